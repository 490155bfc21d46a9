//! Anti-aliased shape coverage against the exact area: single shapes, shared
//! edges, gauge segments, targets without a background.

use super::{polygon_around_small_lists, random_polygon};
use crate::reference::Rng;
use crate::shapes::{H, W, draw, fill, grid_point};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::shape::{Polygon, ShapeStyle};

/// Area of the simple polygon `pts` inside the unit square at `(x, y)`
/// (Sutherland–Hodgman against the four sides, then the shoelace formula).
pub(super) fn pixel_area(pts: &[(f64, f64)], x: f64, y: f64) -> f64 {
    let mut poly = pts.to_vec();
    let sides: [(usize, f64, bool); 4] =
        [(0, x, true), (0, x + 1.0, false), (1, y, true), (1, y + 1.0, false)];
    for (axis, v, keep_above) in sides {
        let inside = |p: &(f64, f64)| {
            let c = if axis == 0 { p.0 } else { p.1 };
            if keep_above { c >= v } else { c <= v }
        };
        let mut out = Vec::new();
        for i in 0..poly.len() {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            if inside(&a) {
                out.push(a);
            }
            if inside(&a) != inside(&b) {
                let (ca, cb) = if axis == 0 { (a.0, b.0) } else { (a.1, b.1) };
                let t = (v - ca) / (cb - ca);
                out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
        }
        poly = out;
        if poly.is_empty() {
            return 0.0;
        }
    }
    let s: f64 = (0..poly.len())
        .map(|i| poly[i].0 * poly[(i + 1) % poly.len()].1 - poly[(i + 1) % poly.len()].0 * poly[i].1)
        .sum();
    (s / 2.0).abs()
}

#[test]
fn antialiased_coverage_is_the_exact_area() {
    let mut rng = Rng::new(0xa4ea);
    let (mut pixels, mut partial, mut worst) = (0, 0, 0.0f64);
    for _ in 0..1500 {
        let pts = random_polygon(&mut rng);
        // Simple polygons only: winding 0 or ±1, the exact-area domain.
        if !is_simple(&pts) {
            continue;
        }
        let ours = draw(Polygon::new(&pts).unwrap(), fill().antialiased());
        let f: Vec<(f64, f64)> = pts.iter().map(|p| (f64::from(p.0), f64::from(p.1))).collect();
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            let area = pixel_area(&f, x as f64, y as f64);
            let a = f64::from(ours.alpha_at(x, y));
            let err = (a - 255.0 * area).abs();
            assert!(err <= 0.5 + 0.05, "{pts:?} ({x}, {y}): alpha {a} vs area {area}");
            assert!(ours.at(x, y) <= 1, "pixel written twice");
            worst = worst.max(err - (255.0 * area - (255.0 * area).round()).abs());
            pixels += 1;
            partial += (area > 0.0 && area < 1.0) as usize;
        }
    }
    println!(
        "AA vs exact area: {pixels} pixels, {partial} partial; worst error beyond 8-bit rounding {worst:.4} levels"
    );
    assert!(partial > 100_000, "{partial}");
}

/// Polygons of 24 to 48 vertices, on both sides of the 32-edge scratch
/// lists a small shape is drawn with (`Styled::new` chooses): the same
/// exact-area bound as above for each.
#[test]
fn antialiased_coverage_is_the_exact_area_with_small_and_full_edge_lists() {
    let mut rng = Rng::new(0x5ca1e);
    let (mut small, mut full) = (0, 0);
    for _ in 0..400 {
        let (pts, fits) = polygon_around_small_lists(&mut rng);
        if !is_simple(&pts) {
            continue;
        }
        if fits {
            small += 1
        } else {
            full += 1
        }
        let ours = draw(Polygon::new(&pts).unwrap(), fill().antialiased());
        let f: Vec<(f64, f64)> = pts.iter().map(|p| (f64::from(p.0), f64::from(p.1))).collect();
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            let area = pixel_area(&f, x as f64, y as f64);
            let a = f64::from(ours.alpha_at(x, y));
            assert!((a - 255.0 * area).abs() <= 0.5 + 0.05, "{pts:?} ({x}, {y}): alpha {a} vs area {area}");
            assert!(ours.at(x, y) <= 1, "pixel written twice");
        }
    }
    println!("AA vs exact area, 24-48 vertices: {small} polygons in 32-edge lists, {full} in full ones");
    assert!(small > 30 && full > 30, "{small} small, {full} full");
}

/// True if no two non-adjacent edges of the closed polygon intersect.
fn is_simple(p: &[(f32, f32)]) -> bool {
    let n = p.len();
    let f = |q: (f32, f32)| (f64::from(q.0), f64::from(q.1));
    let cross =
        |o: (f64, f64), a: (f64, f64), b: (f64, f64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    for i in 0..n {
        for j in i + 1..n {
            if j == i + 1 || (i == 0 && j == n - 1) {
                continue;
            }
            let (a, b, c, d) = (f(p[i]), f(p[(i + 1) % n]), f(p[j]), f(p[(j + 1) % n]));
            let (d1, d2, d3, d4) = (cross(a, b, c), cross(a, b, d), cross(c, d, a), cross(c, d, b));
            if d1 * d2 <= 0.0 && d3 * d4 <= 0.0 {
                return false;
            }
        }
    }
    true
}

#[test]
fn antialiased_shapes_sharing_an_edge_sum_to_the_whole() {
    let mut rng = Rng::new(0x5ea5);
    let mut shared = 0;
    for _ in 0..500 {
        let q = [0, 1, 2, 3].map(|_| grid_point(&mut rng, 0.0, 64.0, false));
        // Quad split along its diagonal q0–q2 (both halves, and the whole if convex).
        let (a, b) = (
            draw(Polygon::new(&[q[0], q[1], q[2]]).unwrap(), fill().antialiased()),
            draw(Polygon::new(&[q[0], q[2], q[3]]).unwrap(), fill().antialiased()),
        );
        let whole = draw(Polygon::new(&q).unwrap(), fill().antialiased());
        if !is_simple(&q) {
            continue;
        }
        let cross = |o: (f32, f32), p: (f32, f32), r: (f32, f32)| {
            (p.0 - o.0) * (r.1 - o.1) - (p.1 - o.1) * (r.0 - o.0)
        };
        if cross(q[0], q[2], q[1]) * cross(q[0], q[2], q[3]) >= 0.0 {
            continue; // q1 and q3 on the same side: the halves overlap
        }
        for i in 0..(W * H) as usize {
            let (sa, sb, sw) = (a.alpha[i] as i32, b.alpha[i] as i32, whole.alpha[i] as i32);
            // Each is the area rounded to 8 bits (± 0.55): the sum within 1 level (plus slack).
            assert!((sa + sb - sw).abs() <= 1, "{q:?} pixel {i}: {sa} + {sb} vs {sw}");
            shared += (sa > 0 && sb > 0) as usize;
        }
    }
    assert!(shared > 3000, "{shared}");
}

#[test]
fn antialiased_gauge_segments_sum_to_one_ring() {
    use microraster::shape::Arc;
    let mut rng = Rng::new(0x6a06e);
    let mut shared = 0;
    for _ in 0..200 {
        let c = grid_point(&mut rng, 20.0, 44.0, false);
        let (r, w) = (rng.uniform(6.0, 20.0) as f32, rng.uniform(1.0, 6.0) as f32);
        let (start, a) = (rng.uniform(-3.0, 3.0) as f32, rng.uniform(0.3, 2.5) as f32);
        let b = rng.uniform(0.3, 2.5) as f32;
        let ring = |s: f32, sweep: f32| {
            draw(Arc::new(c, r, s, sweep).unwrap(), ShapeStyle::stroke(Gray8::WHITE, w).antialiased())
        };
        let (first, second) = (ring(start, a), ring(start + a, b));
        // The shared cap line is the same snapped segment in both: along it the
        // two coverages are the areas on either side, summing to one pixel.
        let (s, co) = ((start + a) as f64).sin_cos();
        for k in 0..=8 {
            let rad = f64::from(r) + f64::from(w) * (k as f64 / 8.0 - 0.5) * 0.8;
            let (px, py) = (f64::from(c.0) + rad * co, f64::from(c.1) + rad * s);
            let (x, y) = (px.floor() as i32, py.floor() as i32);
            if !(0..W).contains(&x) || !(0..H).contains(&y) {
                continue;
            }
            let (fa, fb) = (first.alpha_at(x, y) as i32, second.alpha_at(x, y) as i32);
            if fa > 0 && fb > 0 && fa + fb >= 250 {
                shared += 1;
            }
            assert!(fa + fb <= 256, "({x}, {y}): {fa} + {fb} overlap");
        }
    }
    assert!(shared > 300, "{shared}");
}

#[test]
fn a_draw_target_without_background_gets_pixels_at_least_half_covered() {
    use crate::framebuffer::Framebuffer;
    use embedded_graphics_core::Drawable;
    use microraster::shape::{Circle, Shape};
    let style = ShapeStyle::fill(Gray8::WHITE).antialiased();
    let disc = Circle::new((31.3, 20.6), 12.7).unwrap();
    let mut fb = Framebuffer::new(W as u32, H as u32, Gray8::BLACK);
    disc.styled(style).unwrap().draw(&mut fb).unwrap();
    let exact = draw(disc, style);
    let mut partial = 0;
    for i in 0..(W * H) as usize {
        let drawn = fb.pixels[i] == Gray8::WHITE;
        assert_eq!(drawn, exact.alpha[i] >= 128, "pixel {i}: alpha {}", exact.alpha[i]);
        assert!(fb.writes[i] <= 1);
        partial += (exact.alpha[i] > 0 && exact.alpha[i] < 255) as usize;
    }
    assert!(partial > 50);
}
