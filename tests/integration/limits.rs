//! The rows of `docs/limits.md`, each tested at the limit, one subpixel (or
//! one unit) beyond it, and far beyond it. Test names match the table.
//!
//! Triangles are compared with the exact `i128` reference of `reference`;
//! lines with the exact rule of `microraster::line`, evaluated here in
//! `i128` ([`line_rule`]).

mod coordinates;
mod frames_and_depth;
mod vertex_stage;

use crate::reference::{exact_coverage, spans_coverage};
use microraster::edge::{Cull, TriangleSpans};
use microraster::{ClipRect, SubPoint};

/// 2^28: the largest coordinate magnitude in subpixels, for every `S`.
pub const LIM: i64 = 1 << 28;

/// The exact line rule (start inclusive, end exclusive, minor index
/// `floor` of the exact line at the major centre), in `i128`.
pub fn line_rule(a: (i32, i32), b: (i32, i32), s: u32, clip: ClipRect) -> Vec<(i32, i32)> {
    let (dx, dy) = (i128::from(b.0) - i128::from(a.0), i128::from(b.1) - i128::from(a.1));
    let x_major = dx.abs() >= dy.abs();
    let (ua, va, ub, du, dv) = if x_major { (a.0, a.1, b.0, dx, dy) } else { (a.1, a.0, b.1, dy, dx) };
    let (ua, va, ub) = (i128::from(ua), i128::from(va), i128::from(ub));
    let (c0, c1, k0, k1) = if x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let mut out = Vec::new();
    if du == 0 {
        return out;
    }
    let majors: Vec<i32> = if du > 0 { (c0..c1).collect() } else { (c0..c1).rev().collect() };
    for m in majors {
        let c = (2 * i128::from(m) + 1) << s;
        let inside = if du > 0 { 2 * ua <= c && c < 2 * ub } else { 2 * ub < c && c <= 2 * ua };
        if !inside {
            continue;
        }
        let (n, q) = (2 * va * du + dv * (c - 2 * ua), (2 * du) << s);
        let minor = if q < 0 { (-n).div_euclid(-q) } else { n.div_euclid(q) };
        if (i128::from(k0)..i128::from(k1)).contains(&minor) {
            out.push(if x_major { (m, minor as i32) } else { (minor as i32, m) });
        }
    }
    out
}

/// `TriangleSpans` against the exact reference on `clip`; returns (pixels, fast path).
pub fn exact_check<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect) -> (usize, bool) {
    let spans = TriangleSpans::new(v, clip, Cull::None);
    let fast = spans.is_fast_path();
    let got = spans_coverage(spans, clip);
    let want = exact_coverage(v, clip, Cull::None);
    if let Some((x, y, g, w)) = got.first_difference(&want) {
        let pts: Vec<_> = v.iter().map(|p| (p.x(), p.y())).collect();
        panic!("S={S} {pts:?} {clip:?}: pixel ({x}, {y}) spans={g} reference={w}");
    }
    (want.count(), fast)
}

/// The exact fast-path threshold: the largest bounding-box side, in
/// subpixels, that takes the `i32` path (`src/raster/edge.rs`: `2·side + 2^(S+1) ≤
/// X` with `X = ⌊√((2^31 − 3)·2^S)⌋`).
pub fn fast_threshold_sub(s: u32) -> i64 {
    let limit = (i128::from(i32::MAX) - 2) << s;
    let x = (limit as f64).sqrt() as i128;
    let x = (x - 2..=x + 2).filter(|v| v * v <= limit).max().unwrap() as i64;
    x / 2 - (1 << s)
}
