//! Which pixels shapes cover: the triangle core's, exact partitions, curves
//! within tolerance, zero-length thick lines, fill rules.

use super::{CURVE_MARGIN, Grid, H, W, draw, fill, grid_point};
use crate::reference::{Rng, spans_coverage};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::edge::{Cull, TriangleSpans};
use microraster::shape::{
    Arc, Canvas, Cap, Circle, Ellipse, FillRule, Polygon, Polyline, Rect, RoundedRect, Sector, ShapeStyle,
};
use microraster::{ClipRect, SubPoint};

#[test]
fn a_triangle_shape_covers_what_the_triangle_core_covers() {
    let mut rng = Rng::new(0x5a9e);
    let clip = ClipRect::new(0, 0, W, H);
    let mut covered = 0;
    for i in 0..3000 {
        let v = [0, 1, 2].map(|_| grid_point(&mut rng, -10.0, W as f64 + 10.0, i % 2 == 0));
        let g = draw(Polygon::new(&v).unwrap(), fill());
        let core = spans_coverage(
            TriangleSpans::new(v.map(|(x, y)| SubPoint::<4>::from_f32(x, y).unwrap()), clip, Cull::None),
            clip,
        );
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            assert_eq!(g.at(x, y), core.get(x, y) as u32, "{v:?} pixel ({x}, {y})");
        }
        covered += core.count();
    }
    assert!(covered > 300_000, "{covered}");
}

/// Fills `pieces` into one grid; every pixel must be hit as often as `whole` hits it.
fn assert_partition(pieces: &[Grid], whole: &Grid, what: &str) {
    for i in 0..(W * H) as usize {
        let sum: u32 = pieces.iter().map(|g| g.hits[i]).sum();
        assert_eq!(sum, whole.hits[i], "{what}: pixel ({}, {})", i as i32 % W, i as i32 / W);
    }
}

#[test]
fn shapes_sharing_edges_partition_exactly() {
    let mut rng = Rng::new(0x5ea3);
    for _ in 0..500 {
        // A rectangle cut by random 1/16 px lines into a grid of rectangles.
        let (x0, y0) = grid_point(&mut rng, -4.0, 20.0, false);
        let (xs, ys) = ([x0, x0 + 7.3125, x0 + 13.5, x0 + 40.0625], [y0, y0 + 0.5, y0 + 11.0625, y0 + 30.0]);
        let mut cells = Vec::new();
        for i in 0..3 {
            for j in 0..3 {
                cells.push(draw(
                    Rect::new(xs[i], ys[j], xs[i + 1] - xs[i], ys[j + 1] - ys[j]).unwrap(),
                    fill(),
                ));
            }
        }
        let whole = draw(Rect::new(x0, y0, 40.0625, 30.0).unwrap(), fill());
        assert!(whole.hits.iter().all(|&h| h <= 1));
        assert_partition(&cells, &whole, "rect grid");

        // A convex polygon cut along a chord, one part drawn as a triangle of the core.
        let c = grid_point(&mut rng, 10.0, 50.0, false);
        let r = rng.uniform(3.0, 30.0);
        let mut ring: Vec<(f32, f32)> = (0..7)
            .map(|k| {
                let a = k as f64 / 7.0 * std::f64::consts::TAU + rng.uniform(0.0, 0.5);
                (
                    ((c.0 as f64 + r * a.cos()) * 16.0).round() as f32 / 16.0,
                    ((c.1 as f64 + r * a.sin()) * 16.0).round() as f32 / 16.0,
                )
            })
            .collect();
        if rng.chance(0.5) {
            ring.reverse();
        }
        let whole = draw(Polygon::new(&ring).unwrap(), fill());
        let rest =
            draw(Polygon::new(&[ring[0], ring[2], ring[3], ring[4], ring[5], ring[6]]).unwrap(), fill());
        let mut tri = Grid::new();
        let t = [ring[0], ring[1], ring[2]].map(|(x, y)| SubPoint::<4>::from_f32(x, y).unwrap());
        for s in TriangleSpans::new(t, tri.clip, Cull::None) {
            tri.fill(s, Gray8::WHITE, 255);
        }
        assert_partition(&[rest, tri], &whole, "polygon + core triangle");
    }
}

#[test]
fn pie_slices_and_gauge_segments_never_overlap() {
    let mut rng = Rng::new(0x91e);
    let mut checked = 0;
    for _ in 0..300 {
        let ties = rng.chance(0.3);
        let c = grid_point(&mut rng, 16.0, 48.0, ties);
        let r = rng.uniform(2.0, 30.0) as f32;
        let n = rng.range(2, 9) as usize;
        let mut start = rng.uniform(-4.0, 4.0) as f32;
        let mut slices = Vec::new();
        let mut segments = Vec::new();
        let mut angles = Vec::new();
        let step = std::f32::consts::TAU / n as f32;
        for _ in 0..n {
            let sweep = step * rng.uniform(0.5, 1.0) as f32;
            slices.push(draw(Sector::new(c, r, start, sweep).unwrap(), fill()));
            let stroke = ShapeStyle::stroke(Gray8::WHITE, 3.0);
            segments.push(draw(Arc::new(c, r, start, sweep).unwrap(), stroke));
            angles.push((f64::from(start), f64::from(sweep)));
            start += sweep; // the next piece starts exactly where this one ends
        }
        for pieces in [&slices, &segments] {
            for i in 0..(W * H) as usize {
                assert!(pieces.iter().map(|g| g.hits[i]).sum::<u32>() <= 1, "pixel {i} hit twice");
            }
        }
        // Centres clearly inside a slice (away from its arc and both radii) are hit.
        let (cx, cy) = (f64::from(c.0), f64::from(c.1));
        for (k, &(a, sw)) in angles.iter().enumerate() {
            for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
                let (px, py) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
                let d = (px * px + py * py).sqrt();
                let rel = (py.atan2(px) - a).rem_euclid(std::f64::consts::TAU);
                let radius = |t: f64| {
                    crate::reference::dist_to_segment(
                        (px, py),
                        (0.0, 0.0),
                        (f64::from(r) * t.cos(), f64::from(r) * t.sin()),
                    )
                };
                let m = CURVE_MARGIN;
                if d < f64::from(r) - m && rel < sw && radius(a) > m && radius(a + sw) > m {
                    assert_eq!(slices[k].at(x, y), 1, "slice {k} pixel ({x}, {y})");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 50_000, "{checked}");
}

/// `inside`: `None` near the curve (not compared), else whether the centre is inside.
fn inside_margin_ok(inside: Option<bool>, covered: bool) -> bool {
    inside.is_none_or(|i| i == covered)
}

#[test]
fn curves_are_within_the_stated_tolerance_of_the_true_curve() {
    let mut rng = Rng::new(0xc0c1);
    let m = CURVE_MARGIN;
    let mut compared = 0;
    for _ in 0..600 {
        let c = grid_point(&mut rng, 0.0, 64.0, false);
        let (cx, cy) = (f64::from(c.0), f64::from(c.1));
        let (rx, ry) = (rng.log_uniform(0.3, 60.0), rng.log_uniform(0.3, 60.0));
        let circle = draw(Circle::new(c, rx as f32).unwrap(), fill());
        let ellipse = draw(Ellipse::new(c, rx as f32, ry as f32).unwrap(), fill());
        let (w, h) = (rx * 1.5, ry * 1.5);
        let rr = rng.uniform(0.0, w.min(h) / 2.0);
        let rounded = draw(
            RoundedRect::new(Rect::new(c.0, c.1, w as f32, h as f32).unwrap(), rr as f32).unwrap(),
            fill(),
        );
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let d = ((px - cx).powi(2) + (py - cy).powi(2)).sqrt() - f64::from(rx as f32);
            let circ = (d.abs() > m).then_some(d < 0.0);
            assert!(inside_margin_ok(circ, circle.at(x, y) == 1), "circle {c:?} r {rx} at ({x}, {y}): d {d}");
            // Norm of the ellipse: Lipschitz 1/min(rx, ry), so |g − 1| > m/min is m px from the curve.
            let g = (((px - cx) / f64::from(rx as f32)).powi(2) + ((py - cy) / f64::from(ry as f32)).powi(2))
                .sqrt();
            let ell = ((g - 1.0).abs() > m / rx.min(ry)).then_some(g < 1.0);
            assert!(inside_margin_ok(ell, ellipse.at(x, y) == 1), "ellipse {c:?} {rx} {ry} at ({x}, {y})");
            // Rounded rectangle: exact signed distance.
            let (hw, hh) = (f64::from(w as f32) / 2.0, f64::from(h as f32) / 2.0);
            let r = f64::from(rr as f32).min(hw.min(hh));
            let q = ((px - cx - hw).abs() - (hw - r), (py - cy - hh).abs() - (hh - r));
            let sd = (q.0.max(0.0).powi(2) + q.1.max(0.0).powi(2)).sqrt() + q.0.max(q.1).min(0.0) - r;
            let rrect = (sd.abs() > m).then_some(sd < 0.0);
            assert!(inside_margin_ok(rrect, rounded.at(x, y) == 1), "rounded rect at ({x}, {y}): {sd}");
            compared += circ.is_some() as usize;
        }
    }
    assert!(compared > 1_500_000, "{compared}");
}

#[test]
fn a_zero_length_thick_line_is_a_dot_square_or_nothing() {
    let p = [(20.25, 17.5), (20.25, 17.5), (20.25, 17.5)];
    let line = Polyline::new(&p).unwrap();
    let stroke = |cap| ShapeStyle::stroke(Gray8::WHITE, 6.5).with_cap(cap);
    assert!(draw(line, stroke(Cap::Butt)).hits.iter().all(|&h| h == 0));
    let disc = draw(Circle::new(p[0], 3.25).unwrap(), fill());
    assert_eq!(draw(line, stroke(Cap::Round)).hits, disc.hits);
    assert!(disc.hits.iter().sum::<u32>() > 25);
    let square = draw(Rect::new(17.0, 14.25, 6.5, 6.5).unwrap(), fill());
    assert_eq!(draw(line, stroke(Cap::Square)).hits, square.hits);
}

#[test]
fn even_odd_cuts_holes_where_nonzero_unites() {
    let star = [(32.0, 2.0), (44.0, 40.0), (12.0, 16.0), (52.0, 16.0), (20.0, 40.0)];
    let nz = draw(Polygon::new(&star).unwrap(), fill());
    let eo = draw(Polygon::new(&star).unwrap(), fill().with_fill_rule(FillRule::EvenOdd));
    // The pentagon in the middle (winding 2) is in for nonzero, out for even-odd.
    assert_eq!((nz.at(32, 22), eo.at(32, 22)), (1, 0));
    assert_eq!((nz.at(32, 5), eo.at(32, 5)), (1, 1));
    assert!(eo.hits.iter().zip(&nz.hits).all(|(e, n)| e <= n));
}
