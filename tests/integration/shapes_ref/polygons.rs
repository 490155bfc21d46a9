//! Aliased polygons and thick polylines against tiny-skia, away from edges.

use super::{MASK_PX, alphas, paint, path, polygon_around_small_lists, random_polygon};
use crate::reference::{Rng, dist_to_segment};
use crate::shapes::{H, W, draw, fill, grid_point};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::shape::{Cap, FillRule, Join, Polygon, Polyline, ShapeStyle};
use tiny_skia::{Pixmap, Stroke, Transform};

fn near_edge(pts: &[(f32, f32)], p: (f64, f64)) -> bool {
    let f = |q: (f32, f32)| (f64::from(q.0), f64::from(q.1));
    (0..pts.len()).any(|i| dist_to_segment(p, f(pts[i]), f(pts[(i + 1) % pts.len()])) <= MASK_PX)
}

/// Fills `pts` with both renderers under the same fill rule and asserts
/// every pixel centre away from the edges equal: (pixels compared, covered).
fn match_tiny_skia(
    pm: &mut Pixmap,
    pts: &[(f32, f32)],
    (ours_rule, skia_rule): (FillRule, tiny_skia::FillRule),
) -> (usize, usize) {
    let ours = draw(Polygon::new(pts).unwrap(), fill().with_fill_rule(ours_rule));
    pm.fill(tiny_skia::Color::TRANSPARENT);
    if let Some(p) = path(pts, true) {
        pm.fill_path(&p, &paint(false), skia_rule, Transform::identity(), None);
    }
    let skia = alphas(pm);
    let (mut compared, mut covered) = (0, 0);
    for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
        if near_edge(pts, (x as f64 + 0.5, y as f64 + 0.5)) {
            continue;
        }
        let (a, b) = (ours.at(x, y), u32::from(skia[(y * W + x) as usize] != 0));
        assert_eq!(a, b, "{pts:?} {ours_rule:?} pixel ({x}, {y})");
        compared += 1;
        covered += a as usize;
    }
    (compared, covered)
}

#[test]
fn polygons_match_tiny_skia_away_from_edges() {
    let mut rng = Rng::new(0xfa11);
    let mut pm = Pixmap::new(W as u32, H as u32).unwrap();
    let (mut compared, mut covered) = (0, 0);
    for i in 0..2000 {
        let pts = random_polygon(&mut rng);
        let (ours_rule, skia_rule) = if i % 2 == 0 {
            (FillRule::NonZero, tiny_skia::FillRule::Winding)
        } else {
            (FillRule::EvenOdd, tiny_skia::FillRule::EvenOdd)
        };
        let (c, v) = match_tiny_skia(&mut pm, &pts, (ours_rule, skia_rule));
        compared += c;
        covered += v;
    }
    println!("polygons vs tiny-skia: {compared} pixels compared, {covered} covered");
    assert!(compared > 5_000_000 && covered > 1_000_000);
}

/// Polygons of 24 to 48 vertices, on both sides of the 32-edge scratch
/// lists a small shape is drawn with (`Styled::new` chooses).
#[test]
fn polygons_with_small_and_full_edge_lists_match_tiny_skia() {
    let mut rng = Rng::new(0x32ed);
    let mut pm = Pixmap::new(W as u32, H as u32).unwrap();
    let (mut small, mut full, mut covered) = (0, 0, 0);
    for _ in 0..300 {
        let (pts, fits) = polygon_around_small_lists(&mut rng);
        if fits {
            small += 1
        } else {
            full += 1
        }
        covered += match_tiny_skia(&mut pm, &pts, (FillRule::NonZero, tiny_skia::FillRule::Winding)).1;
    }
    println!("polygons of 24-48 vertices vs tiny-skia: {small} in 32-edge lists, {full} in full ones");
    assert!(small > 30 && full > 30 && covered > 100_000, "{small} small, {full} full, {covered} covered");
}

#[test]
fn thick_polylines_match_tiny_skia_away_from_the_outline() {
    let mut rng = Rng::new(0x57e0);
    let mut pm = Pixmap::new(W as u32, H as u32).unwrap();
    let (mut compared, mut covered, mut hit_twice) = (0, 0, 0);
    for i in 0..1500 {
        let n = rng.range(2, 6) as usize;
        let pts: Vec<(f32, f32)> = (0..n).map(|_| grid_point(&mut rng, 4.0, 60.0, false)).collect();
        let width = rng.log_uniform(1.0, 12.0) as f32;
        let join = [Join::Miter, Join::Round, Join::Bevel][i % 3];
        let cap = [Cap::Butt, Cap::Round, Cap::Square][(i / 3) % 3];
        let closed = i % 7 == 0;
        let style = ShapeStyle::stroke(Gray8::WHITE, width).with_join(join).with_cap(cap);
        let ours = if closed {
            draw(Polygon::new(&pts).unwrap(), style)
        } else {
            draw(Polyline::new(&pts).unwrap(), style)
        };
        hit_twice += ours.hits.iter().filter(|&&h| h > 1).count();
        let stroke = Stroke {
            width,
            miter_limit: 4.0,
            line_cap: [tiny_skia::LineCap::Butt, tiny_skia::LineCap::Round, tiny_skia::LineCap::Square]
                [(i / 3) % 3],
            line_join: [tiny_skia::LineJoin::Miter, tiny_skia::LineJoin::Round, tiny_skia::LineJoin::Bevel]
                [i % 3],
            dash: None,
        };
        let Some(p) = path(&pts, closed) else { continue };
        pm.fill(tiny_skia::Color::TRANSPARENT);
        pm.stroke_path(&p, &paint(true), &stroke, Transform::identity(), None);
        let soft = alphas(&pm);
        pm.fill(tiny_skia::Color::TRANSPARENT);
        pm.stroke_path(&p, &paint(false), &stroke, Transform::identity(), None);
        let hard = alphas(&pm);
        let partial = |x: i32, y: i32| {
            (x - 1..=x + 1).any(|u| {
                (y - 1..=y + 1).any(|v| {
                    (0..W).contains(&u)
                        && (0..H).contains(&v)
                        && !matches!(soft[(v * W + u) as usize], 0 | 255)
                })
            })
        };
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            if partial(x, y) {
                continue;
            }
            let (a, b) = (ours.at(x, y).min(1), u32::from(hard[(y * W + x) as usize] != 0));
            assert_eq!(a, b, "{pts:?} w {width} {join:?} {cap:?} closed {closed} pixel ({x}, {y})");
            compared += 1;
            covered += a as usize;
        }
    }
    println!("strokes vs tiny-skia: {compared} pixels compared, {covered} covered");
    assert_eq!(hit_twice, 0, "a stroke is one fill: no pixel twice");
    assert!(compared > 2_000_000 && covered > 100_000);
}
