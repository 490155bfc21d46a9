//! Curves (filled and stroked) against tiny-skia away from the true curve.

use super::{MASK_PX, alphas, paint};
use crate::reference::{Rng, dist_to_segment};
use crate::shapes::{CURVE_MARGIN, H, W, draw, fill};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::shape::{Cap, ShapeStyle};
use tiny_skia::{PathBuilder, Pixmap, Stroke, Transform};

// Curves. Both sides flatten, differently, so a pixel is compared only if
// its centre is farther than a stated distance from the *true* curve: then
// each rasteriser puts it on the side the true shape does, so they agree.
// The distance is the larger of the two errors (each is measured against the
// true curve, not against the other), not their sum.
//
// * Ours: `CURVE_MARGIN` (chords within `TOLERANCE`, vertices snapped by
//   √2/32, f32 slack), and no tie band beyond it: the winding number at the
//   nudged centre is exact for the snapped contours.
// * tiny-skia 0.12, from its source, for paths of lines, quads and conics:
//   - conics (its circles and ovals, round caps) become quads within 0.25 px
//     (`AutoConicToQuads::compute`: Floater's bound at tolerance 0.25); the
//     stroker's offset quads are within 0.25 px of the offset curve
//     (`inv_res_scale` = 1/4 at scale 1). One or the other: 0.25;
//   - a quad becomes 2^shift lines within 0.25 px (`diff_to_shift` aims at
//     1/8 px; its bucketing leaves the deviation below 2/8 px for every
//     shift, worked through case by case);
//   - quad points rounded to 1/64 px (FDot6) and the forward differencing:
//     1/64 px;
//   - then the edge walk of the lines: `MASK_PX`, as for polygons.
//
// These are bounds; in practice tiny-skia is much closer. Measured once
// (temporarily changing `curve_mask`): with the mask at `CURVE_MARGIN`
// alone (0.17 px) there are still no mismatches; with no mask at all the
// strokes give 2,515 mismatches (those printed within 0.1 px of the true
// outline).
const SKIA_CURVE: f64 = 0.25 + 0.25 + 1.0 / 64.0;

/// Distance beyond which a pixel centre is compared, for tiny-skia paths
/// within `input` px of the true curve (the error of quads we build
/// ourselves; 0 for its own circles and ovals).
fn curve_mask(input: f64) -> f64 {
    CURVE_MARGIN.max(SKIA_CURVE + input + MASK_PX)
}

/// Appends quads for the arc of `c`, radius `r` from angle `start` sweeping
/// `sweep` (radians, clockwise on screen) in `n` pieces, control points at
/// the tangents' intersection; the current point must be the arc's start.
/// Each quad lies in the triangle of its control points, so within
/// `r·(sec(θ/2) − 1)` of the arc radially, `θ = sweep/n` ([`quad_err`]).
fn arc_quads(pb: &mut PathBuilder, c: (f64, f64), r: f64, start: f64, sweep: f64, n: usize) {
    let t = sweep / n as f64;
    for k in 0..n {
        let (a0, a1) = (start + k as f64 * t, start + (k + 1) as f64 * t);
        let m = r / (t / 2.0).cos();
        let (am, p) = ((a0 + a1) / 2.0, (c.0 + r * a1.cos(), c.1 + r * a1.sin()));
        pb.quad_to((c.0 + m * am.cos()) as f32, (c.1 + m * am.sin()) as f32, p.0 as f32, p.1 as f32);
    }
}

/// Radial error of [`arc_quads`] plus, for a stroke of half width `half`,
/// the offset's error from the quads' tangents: along a quad its tangent
/// turns monotonically between the end tangents, which are the arc's, so it
/// is within `θ` of the arc's tangent at the same angle.
fn quad_err(r: f64, sweep: f64, n: usize, half: f64) -> f64 {
    let t = (sweep / n as f64).abs();
    r * (1.0 / (t / 2.0).cos() - 1.0) + half * t
}

/// Distance from `p` to the arc of `c`, radius `r` between angles `a0` and
/// `a0 + sweep` (`0 < sweep < 2π`): radial inside the angular range, else to
/// the nearer end (distance to a circle point grows with the angle between).
fn dist_to_arc(p: (f64, f64), c: (f64, f64), r: f64, a0: f64, sweep: f64) -> f64 {
    let (dx, dy) = (p.0 - c.0, p.1 - c.1);
    let d = dx.hypot(dy);
    let rel = (dy.atan2(dx) - a0).rem_euclid(std::f64::consts::TAU);
    if rel <= sweep {
        (d - r).abs()
    } else {
        let end = |a: f64| (p.0 - c.0 - r * a.cos()).hypot(p.1 - c.1 - r * a.sin());
        end(a0).min(end(a0 + sweep))
    }
}

/// A lower bound of a pixel centre's distance to a shape's true outline.
type DistFn = Box<dyn Fn((f64, f64)) -> f64>;

/// Compares `ours` with tiny-skia's aliased `skia` alphas where `dist` (a
/// lower bound of the centre's distance to the true outline) exceeds `mask`.
/// Returns (compared, covered, compared within 1 px beyond the mask,
/// mismatches).
fn compare_away_from(
    ours: &crate::shapes::Grid,
    skia: &[u8],
    mask: f64,
    dist: impl Fn((f64, f64)) -> f64,
    what: &dyn Fn() -> String,
) -> (usize, usize, usize, usize) {
    let (mut compared, mut covered, mut near, mut bad) = (0, 0, 0, 0);
    for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
        let d = dist((x as f64 + 0.5, y as f64 + 0.5));
        assert!(ours.at(x, y) <= 1, "{} pixel ({x}, {y}) written twice", what());
        if d <= mask {
            continue;
        }
        let (a, b) = (ours.at(x, y), u32::from(skia[(y * W + x) as usize] != 0));
        if a != b {
            if bad < 5 {
                println!("mismatch: {} pixel ({x}, {y}) at {d:.3} px: ours {a}, tiny-skia {b}", what());
            }
            bad += 1;
        }
        compared += 1;
        covered += a as usize;
        near += (d <= mask + 1.0) as usize;
    }
    (compared, covered, near, bad)
}

#[test]
fn curve_fills_match_tiny_skia_away_from_the_true_curve() {
    use microraster::shape::{Circle, Ellipse, Rect, RoundedRect};
    use std::f64::consts::{FRAC_PI_2, PI};
    let mut rng = Rng::new(0xc1c1e);
    let mut pm = Pixmap::new(W as u32, H as u32).unwrap();
    let mut totals = [0usize; 4];
    let mut per_kind = [0usize; 3];
    for i in 0..450 {
        let kind = i % 3;
        let c = (rng.uniform(8.0, 56.0), rng.uniform(6.0, 42.0));
        let cf = (c.0 as f32, c.1 as f32);
        let (ours, path, input, dist): (_, _, f64, DistFn) = match kind {
            0 => {
                let r = rng.uniform(0.5, 24.0);
                let ours = draw(Circle::new(cf, r as f32).unwrap(), fill());
                let path = PathBuilder::from_circle(cf.0, cf.1, r as f32).unwrap();
                let r = f64::from(r as f32);
                (ours, path, 0.0, Box::new(move |p: (f64, f64)| ((p.0 - c.0).hypot(p.1 - c.1) - r).abs()))
            }
            1 => {
                let (rx, ry) = (rng.uniform(0.5, 28.0) as f32, rng.uniform(0.5, 28.0) as f32);
                let ours = draw(Ellipse::new(cf, rx, ry).unwrap(), fill());
                let oval = tiny_skia::Rect::from_xywh(cf.0 - rx, cf.1 - ry, 2.0 * rx, 2.0 * ry).unwrap();
                let path = PathBuilder::from_oval(oval).unwrap();
                let (rx, ry) = (f64::from(rx), f64::from(ry));
                // The ellipse is the unit circle scaled by (rx, ry): a point at
                // "radius" g in the circle's space is at least min(rx, ry)·|g − 1|
                // from it (a lower bound of the distance, which suffices).
                let dist = move |p: (f64, f64)| {
                    let g = ((p.0 - c.0) / rx).hypot((p.1 - c.1) / ry);
                    rx.min(ry) * (g - 1.0).abs()
                };
                (ours, path, 0.0, Box::new(dist))
            }
            _ => {
                let (w, h) = (rng.uniform(1.0, 50.0) as f32, rng.uniform(1.0, 40.0) as f32);
                let (x0, y0) = (cf.0 - w / 2.0, cf.1 - h / 2.0);
                let rr = RoundedRect::new(Rect::new(x0, y0, w, h).unwrap(), rng.uniform(0.0, 20.0) as f32)
                    .unwrap();
                let ours = draw(rr, fill());
                let r = f64::from(rr.radius());
                let (x0, y0, x1, y1) = (f64::from(x0), f64::from(y0), f64::from(x0 + w), f64::from(y0 + h));
                let n = 8;
                let mut pb = PathBuilder::new();
                pb.move_to((x1 - r) as f32, y0 as f32);
                for (cc, a) in [
                    ((x1 - r, y0 + r), -FRAC_PI_2),
                    ((x1 - r, y1 - r), 0.0),
                    ((x0 + r, y1 - r), FRAC_PI_2),
                    ((x0 + r, y0 + r), PI),
                ] {
                    let start = (cc.0 + r * a.cos(), cc.1 + r * a.sin());
                    pb.line_to(start.0 as f32, start.1 as f32);
                    arc_quads(&mut pb, cc, r, a, FRAC_PI_2, n);
                }
                pb.close();
                // Exact distance to the rounded box's outline.
                let (hx, hy, mx, my) =
                    ((x1 - x0) / 2.0 - r, (y1 - y0) / 2.0 - r, (x0 + x1) / 2.0, (y0 + y1) / 2.0);
                let dist = move |p: (f64, f64)| {
                    let (qx, qy) = ((p.0 - mx).abs() - hx, (p.1 - my).abs() - hy);
                    (qx.max(0.0).hypot(qy.max(0.0)) + qx.max(qy).min(0.0) - r).abs()
                };
                (ours, pb.finish().unwrap(), quad_err(r, FRAC_PI_2, n, 0.0), Box::new(dist))
            }
        };
        pm.fill(tiny_skia::Color::TRANSPARENT);
        pm.fill_path(&path, &paint(false), tiny_skia::FillRule::Winding, Transform::identity(), None);
        let what = || format!("shape {i} (kind {kind})");
        let r = compare_away_from(&ours, &alphas(&pm), curve_mask(input), dist, &what);
        for (t, v) in totals.iter_mut().zip([r.0, r.1, r.2, r.3]) {
            *t += v;
        }
        per_kind[kind] += r.2;
    }
    let [compared, covered, near, mismatches] = totals;
    println!(
        "curve fills vs tiny-skia (mask {:.3} px): {compared} compared, {covered} covered, {near} within 1 px beyond the mask {per_kind:?}, {mismatches} mismatches",
        curve_mask(0.0)
    );
    assert_eq!(mismatches, 0);
    assert!(
        compared > 1_000_000 && covered > 200_000 && per_kind.iter().all(|&n| n > 10_000),
        "{totals:?} {per_kind:?}"
    );
}

#[test]
fn curve_strokes_match_tiny_skia_away_from_the_true_outline() {
    use microraster::shape::{Arc, Circle};
    use std::f64::consts::TAU;
    let mut rng = Rng::new(0x5a4c);
    let mut pm = Pixmap::new(W as u32, H as u32).unwrap();
    let mut totals = [0usize; 4];
    let caps = [
        (Cap::Butt, tiny_skia::LineCap::Butt),
        (Cap::Round, tiny_skia::LineCap::Round),
        (Cap::Square, tiny_skia::LineCap::Square),
    ];
    let mut per_kind = [0usize; 4];
    for i in 0..400 {
        let c = (rng.uniform(12.0, 52.0), rng.uniform(10.0, 38.0));
        let cf = (c.0 as f32, c.1 as f32);
        let r = rng.uniform(3.0, 24.0) as f32;
        // w ≤ r: the inner offset stays a circle of positive radius (w/2 ≤ r/2).
        let w = rng.uniform(1.0, f64::from(r).min(10.0)) as f32;
        let (r64, half) = (f64::from(r), f64::from(w) / 2.0);
        let kind = i % 4; // 0: circle, 1..=3: arc with butt, round, square caps
        let (cap, skia_cap) = caps[kind.max(1) - 1];
        let style = ShapeStyle::stroke(Gray8::WHITE, w).with_cap(cap);
        let n_per_turn = 512;
        let mut pb = PathBuilder::new();
        let (ours, input, dist): (_, f64, DistFn) = if kind == 0 {
            let ours = draw(Circle::new(cf, r).unwrap(), style);
            pb.move_to((c.0 + r64) as f32, c.1 as f32);
            arc_quads(&mut pb, c, r64, 0.0, TAU, n_per_turn);
            pb.close();
            let dist = move |p: (f64, f64)| (((p.0 - c.0).hypot(p.1 - c.1) - r64).abs() - half).abs();
            (ours, quad_err(r64 + half, TAU, n_per_turn, half), Box::new(dist))
        } else {
            let (start, sweep) = (rng.uniform(-3.2, 3.2) as f32, rng.uniform(0.2, 5.5) as f32);
            let ours = draw(Arc::new(cf, r, start, sweep).unwrap(), style);
            let (a0, s) = (f64::from(start), f64::from(sweep));
            let n = ((s / TAU * n_per_turn as f64).ceil() as usize).max(1);
            pb.move_to((c.0 + r64 * a0.cos()) as f32, (c.1 + r64 * a0.sin()) as f32);
            arc_quads(&mut pb, c, r64, a0, s, n);
            // The true outline lies on the annular sector's boundary (two arcs,
            // two cap lines) and the caps' (a circle of radius w/2 or a square
            // at each end): the distance to all of them bounds the distance to
            // the outline from below.
            let dist = move |p: (f64, f64)| {
                let mut d = dist_to_arc(p, c, r64 + half, a0, s).min(dist_to_arc(p, c, r64 - half, a0, s));
                for (a, out) in [(a0, -1.0), (a0 + s, 1.0)] {
                    let u = (a.cos(), a.sin());
                    let t = (-u.1 * out, u.0 * out); // tangent, pointing away from the arc
                    let at =
                        |k: f64, j: f64| (c.0 + (r64 + k) * u.0 + j * t.0, c.1 + (r64 + k) * u.1 + j * t.1);
                    d = d.min(dist_to_segment(p, at(-half, 0.0), at(half, 0.0)));
                    match cap {
                        Cap::Butt => {}
                        Cap::Round => {
                            d = d.min(((p.0 - at(0.0, 0.0).0).hypot(p.1 - at(0.0, 0.0).1) - half).abs())
                        }
                        Cap::Square => {
                            let q = [at(-half, 0.0), at(-half, half), at(half, half), at(half, 0.0)];
                            d = d.min(
                                (0..3).map(|k| dist_to_segment(p, q[k], q[k + 1])).fold(f64::MAX, f64::min),
                            );
                        }
                    }
                }
                d
            };
            (ours, quad_err(r64 + half, s, n, half), Box::new(dist))
        };
        let stroke = Stroke {
            width: w,
            line_cap: skia_cap,
            line_join: tiny_skia::LineJoin::Round,
            ..Stroke::default()
        };
        pm.fill(tiny_skia::Color::TRANSPARENT);
        pm.stroke_path(&pb.finish().unwrap(), &paint(false), &stroke, Transform::identity(), None);
        let what = || format!("stroke {i} (kind {kind}, r {r}, w {w})");
        let res = compare_away_from(&ours, &alphas(&pm), curve_mask(input), dist, &what);
        for (t, v) in totals.iter_mut().zip([res.0, res.1, res.2, res.3]) {
            *t += v;
        }
        per_kind[kind] += res.2;
    }
    let [compared, covered, near, mismatches] = totals;
    println!(
        "curve strokes vs tiny-skia: {compared} compared, {covered} covered, {near} within 1 px beyond the mask {per_kind:?}, {mismatches} mismatches"
    );
    assert_eq!(mismatches, 0);
    assert!(
        compared > 1_000_000 && covered > 50_000 && per_kind.iter().all(|&n| n > 10_000),
        "{totals:?} {per_kind:?}"
    );
}
