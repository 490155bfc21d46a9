//! Shapes against references: tiny-skia 0.12's aliased fills and strokes
//! (away from edges, where tie rules and flattening differ), and the
//! anti-aliased coverage against the exact area in `f64`.
//!
//! tiny-skia sees the same vertices (1/16 px is exact in its 26.6 fixed
//! point); its edge walk is off by < 1/64 + 1/1024 px (see
//! `triangles_skia.rs`), so polygon pixels whose centre lies within
//! `MASK_PX` of an edge are not compared. For strokes the true outline is
//! not a polygon; pixels tiny-skia's own anti-aliased stroke covers only
//! partly, and their neighbours, are not compared (our flattening is within
//! 0.17 px of the true outline, far less than the half pixel a fully covered
//! or empty pixel keeps from it).
//!
//! Curves (filled circles, ellipses, rounded rectangles; stroked circles and
//! arcs with every cap) are compared where the pixel centre is farther from
//! the true curve than either side's flattening error: see `SKIA_CURVE`.

mod antialiased;
mod curves;
mod far;
mod group;
mod polygons;

use crate::reference::Rng;
use crate::shapes::grid_point;
use tiny_skia::{Paint, PathBuilder, Pixmap};

const MASK_PX: f64 = 1.0 / 32.0 + 1.0 / 1024.0;

fn path(pts: &[(f32, f32)], close: bool) -> Option<tiny_skia::Path> {
    let mut pb = PathBuilder::new();
    pb.move_to(pts[0].0, pts[0].1);
    for p in &pts[1..] {
        pb.line_to(p.0, p.1);
    }
    if close {
        pb.close();
    }
    pb.finish()
}

fn paint(aa: bool) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(255, 255, 255, 255);
    p.anti_alias = aa;
    p
}

fn alphas(pm: &Pixmap) -> Vec<u8> {
    pm.pixels().iter().map(|p| p.alpha()).collect()
}

/// Random polygons: star-shaped (concave, simple) or free (self-intersecting).
fn random_polygon(rng: &mut Rng) -> Vec<(f32, f32)> {
    let n = rng.range(3, 12) as usize;
    random_polygon_of(rng, n)
}

/// Edges a fill may keep and still be drawn with the small scratch lists
/// (`SMALL_EDGES`, private in `src/pixel/shape/style/styled.rs`).
const SMALL_LIST_EDGES: usize = 32;

/// A random polygon of 24 to 48 vertices, so either side of the small
/// scratch lists, and whether its kept edges (the non-horizontal ones, as
/// an edge list keeps them) fit those lists.
fn polygon_around_small_lists(rng: &mut Rng) -> (Vec<(f32, f32)>, bool) {
    let n = rng.range(24, 48) as usize;
    let pts = random_polygon_of(rng, n);
    let kept = (0..pts.len()).filter(|&i| pts[i].1 != pts[(i + 1) % pts.len()].1).count();
    (pts, kept <= SMALL_LIST_EDGES)
}

/// [`random_polygon`] with `n` vertices.
fn random_polygon_of(rng: &mut Rng, n: usize) -> Vec<(f32, f32)> {
    let c = grid_point(rng, 8.0, 56.0, false);
    let free = rng.chance(0.4);
    let mut angles: Vec<f64> = (0..n).map(|_| rng.uniform(0.0, std::f64::consts::TAU)).collect();
    angles.sort_by(f64::total_cmp);
    angles
        .iter()
        .map(|&a| {
            if free {
                let ties = rng.chance(0.3);
                grid_point(rng, -6.0, 70.0, ties)
            } else {
                let r = rng.uniform(1.0, 40.0);
                let q = (f64::from(c.0) + r * a.cos(), f64::from(c.1) + r * a.sin());
                (((q.0 * 16.0).round() / 16.0) as f32, ((q.1 * 16.0).round() / 16.0) as f32)
            }
        })
        .collect()
}
