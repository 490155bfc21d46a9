//! Against tiny-skia 0.12's non-anti-aliased `fill_path` (`FillRule::Winding`).
//!
//! What tiny-skia does (read from `edge.rs`, `scan/path.rs`, `fixed_point.rs`):
//! - vertices become 26.6 fixed point by `(v * 64.0) as i32`: truncation toward
//!   zero, not rounding. Vertices snapped to `S = 6` (1/64 px) are exact, so
//!   both rasterizers see identical geometry here.
//! - rows: an edge spans rows `round(y0)..round(y1)` (`(n + 32) >> 6`), i.e.
//!   centres with `y0 < cy ≤ y1`; columns: a span is `round(xl)..round(xr)`
//!   (`(x + 0.5) >> 16`), i.e. centres with `xl < cx ≤ xr`. A centre exactly on
//!   an edge is therefore covered on a BOTTOM or RIGHT edge: the mirror image of
//!   microraster's top-left rule. Both are watertight on shared edges; with
//!   exact arithmetic they would differ only on centres lying exactly on an edge.
//! - the first row's `x` is `x0 + (slope·dy >> 16)` in 26.6, i.e. FLOORED to
//!   1/64 px, then stepped by a 16.16 slope truncated toward zero (drift below
//!   48·2^-16 < 1/1024 px here). Edges that cross the pixmap border are chopped
//!   in `f32`/`f64` and the new end point is truncated to 1/64 px again.
//!
//! So an edge as tiny-skia walks it is off the exact one by < 1/64 px
//! (+ 1/64 px when chopped) + 1/1024 px; perpendicular distance is at most the
//! horizontal one. Pixels whose centre lies within `1/32 + 1/1024` px of an edge
//! are masked and all others must match. A second test checks the tie rule on
//! triangles with only vertical, horizontal and 45° edges through half-pixel
//! points, where all of tiny-skia's arithmetic is exact.

use crate::reference::{Coverage, Rng, TieRule, coverage_with, dist_to_edges, spans_coverage};
use microraster::edge::{Cull, TriangleSpans};
use microraster::{ClipRect, SubPoint};
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Transform};

const W: i32 = 64;
const H: i32 = 48;
const MASK_PX: f64 = 1.0 / 32.0 + 1.0 / 1024.0;

fn skia_coverage(pixmap: &mut Pixmap, v: [SubPoint<6>; 3]) -> Coverage {
    let clip = ClipRect::new(0, 0, W, H);
    let mut cov = Coverage::new(clip);
    pixmap.fill(Color::TRANSPARENT);
    let pts = v.map(|p| p.to_f64()).map(|(x, y)| (x as f32, y as f32)); // exact: |v| < 2^18 px
    let mut pb = PathBuilder::new();
    pb.move_to(pts[0].0, pts[0].1);
    pb.line_to(pts[1].0, pts[1].1);
    pb.line_to(pts[2].0, pts[2].1);
    pb.close();
    let Some(path) = pb.finish() else { return cov };
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 255, 255, 255);
    paint.anti_alias = false;
    pixmap.fill_path(&path, &paint, FillRule::Winding, Transform::identity(), None);
    for (i, px) in pixmap.pixels().iter().enumerate() {
        if px.alpha() != 0 {
            cov.set(i as i32 % W, i as i32 / W);
        }
    }
    cov
}

/// Random 1/64 px triangles: free `f32` positions, whole pixels, half pixels
/// (many ties) and vertices far outside the pixmap (tiny-skia clips those).
fn random_triangle(rng: &mut Rng) -> [SubPoint<6>; 3] {
    let kind = rng.below(4);
    let size = if kind == 3 { rng.log_uniform(64.0, 1000.0) } else { rng.log_uniform(0.5, 200.0) };
    let (cx, cy) = (rng.uniform(-8.0, W as f64 + 8.0), rng.uniform(-8.0, H as f64 + 8.0));
    [0, 1, 2].map(|_| {
        let (mut x, mut y) = (cx + rng.uniform(-size, size), cy + rng.uniform(-size, size));
        match kind {
            1 => (x, y) = (x.round(), y.round()),
            2 => (x, y) = ((x * 2.0).round() / 2.0, (y * 2.0).round() / 2.0),
            _ => {}
        }
        SubPoint::<6>::from_f32(x as f32, y as f32).unwrap()
    })
}

#[test]
fn tiny_skia_agrees_away_from_edges() {
    let clip = ClipRect::new(0, 0, W, H);
    let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
    let mut rng = Rng::new(0x5c1a);
    let (mut triangles, mut compared, mut masked, mut masked_differ, mut masked_ties) = (0, 0, 0, 0, 0);
    let (mut covered, mut max_differ_dist) = (0, 0.0f64);
    for _ in 0..10_000 {
        let v = random_triangle(&mut rng);
        let ours = spans_coverage(TriangleSpans::new(v, clip, Cull::None), clip);
        let skia = skia_coverage(&mut pixmap, v);
        let mirrored = coverage_with(v, clip, Cull::None, TieRule::BottomRight);
        let vf = v.map(|p| p.to_f64());
        for y in 0..H {
            for x in 0..W {
                let (a, b) = (ours.get(x, y), skia.get(x, y));
                let d = dist_to_edges(vf, (x as f64 + 0.5, y as f64 + 0.5));
                if d <= MASK_PX {
                    masked += 1;
                    if a != b {
                        max_differ_dist = max_differ_dist.max(d);
                    }
                    masked_differ += (a != b) as usize;
                    masked_ties += (a != b && b == mirrored.get(x, y)) as usize;
                    continue;
                }
                compared += 1;
                covered += a as usize;
                assert_eq!(a, b, "{v:?} pixel ({x}, {y}): microraster={a} tiny-skia={b}");
            }
        }
        triangles += 1;
    }
    println!(
        "tiny-skia: {triangles} triangles, {compared} pixels compared ({covered} covered), {masked} masked \
         near an edge, of which {masked_differ} differ ({masked_ties} explained by the bottom-right \
         tie rule; farthest from an edge: {max_differ_dist:.4} px)"
    );
    assert_eq!(triangles, 10_000);
    assert!(compared >= 10_000 * (W * H) as usize * 9 / 10 && covered >= 1_000_000);
    assert!(masked_ties > 0, "the half-pixel triangles must produce tie differences");
}

/// Vertical, horizontal and 45° edges through half-pixel points: tiny-skia's
/// arithmetic is exact, so it must equal the bottom-right-rule reference on
/// every pixel, and differ from microraster exactly where centres sit on edges.
#[test]
fn tiny_skia_breaks_ties_bottom_right() {
    let clip = ClipRect::new(0, 0, W, H);
    let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
    let mut rng = Rng::new(0x7e5);
    let (mut triangles, mut tie_pixels) = (0, 0);
    for _ in 0..3000 {
        // Right isosceles triangle: legs along the axes, hypotenuse at 45°.
        let half = |rng: &mut Rng, lo: i64, hi: i64| rng.range(2 * lo, 2 * hi) * 32; // half px in 1/64 px
        let (ax, ay) = (half(&mut rng, -4, W as i64 + 4), half(&mut rng, -4, H as i64 + 4));
        let d = half(&mut rng, 1, 40) * if rng.chance(0.5) { 1 } else { -1 };
        let e = if rng.chance(0.5) { d } else { -d };
        let p = |x: i64, y: i64| SubPoint::<6>::new(x as i32, y as i32).unwrap();
        let mut v = [p(ax, ay), p(ax + d, ay), p(ax, ay + e)];
        v.swap(rng.below(3) as usize, rng.below(3) as usize);
        let skia = skia_coverage(&mut pixmap, v);
        let mirrored = coverage_with(v, clip, Cull::None, TieRule::BottomRight);
        if let Some((x, y, s, m)) = skia.first_difference(&mirrored) {
            panic!("{v:?} pixel ({x}, {y}): tiny-skia={s} bottom-right reference={m}");
        }
        let ours = spans_coverage(TriangleSpans::new(v, clip, Cull::None), clip);
        let vf = v.map(|q| q.to_f64());
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            if ours.get(x, y) != skia.get(x, y) {
                // Only centres exactly on an edge may differ (1e-9: f64 rounding).
                let d = dist_to_edges(vf, (x as f64 + 0.5, y as f64 + 0.5));
                assert!(d <= 1e-9, "{v:?} ({x}, {y}) differs {d} px from an edge");
                tie_pixels += 1;
            }
        }
        triangles += 1;
    }
    println!("tiny-skia tie rule: {triangles} axis/45° triangles, {tie_pixels} tie pixels differ");
    assert_eq!(triangles, 3000);
    assert!(tie_pixels > 1000);
}
