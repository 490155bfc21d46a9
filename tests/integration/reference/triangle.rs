//! Reference triangle coverage: exact `i128` under a tie rule; `f64`
//! point-in-triangle and distances.

use super::Coverage;
use microraster::edge::Cull;
use microraster::{ClipRect, SubPoint};

/// Which samples lying exactly on an edge count as covered.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum TieRule {
    /// D3D11.3: on a top or left edge.
    TopLeft,
    /// The mirror image: on a bottom or right edge (what tiny-skia does).
    BottomRight,
}

#[derive(Clone, Copy, Debug)]
struct RefEdge {
    /// The edge function `ex·cx + ey·cy + k` at `(cx, cy)`: a cross product
    /// with the edge, sign chosen so that it is positive inside.
    ex: i128,
    ey: i128,
    k: i128,
    top_left: bool,
    bottom_right: bool,
}

impl RefEdge {
    fn tie(&self, rule: TieRule) -> bool {
        match rule {
            TieRule::TopLeft => self.top_left,
            TieRule::BottomRight => self.bottom_right,
        }
    }
}

/// One non-degenerate snapped triangle, in units of `2^-(S+1)` px so that pixel
/// centres `(2X+1)·2^S` are integers for every `S`, including 0.
#[derive(Clone, Debug)]
pub struct ExactTriangle {
    edges: [RefEdge; 3],
    /// Screen-clockwise (y down): `cross(v1 − v0, v2 − v0) > 0`.
    pub clockwise: bool,
    half: i128,
    bbox: [i128; 4],
}

fn cross(u: (i128, i128), v: (i128, i128)) -> i128 {
    u.0 * v.1 - u.1 * v.0
}

impl ExactTriangle {
    /// `None` for zero area.
    pub fn new<const S: u32>(v: [SubPoint<S>; 3]) -> Option<Self> {
        let p = v.map(|q| (2 * q.x() as i128, 2 * q.y() as i128));
        let sub = |u: (i128, i128), w: (i128, i128)| (u.0 - w.0, u.1 - w.1);
        let area2 = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        if area2 == 0 {
            return None;
        }
        let edges = [0, 1, 2].map(|i| {
            let (a, b, c) = (p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
            let d = sub(b, a);
            let horizontal = d.1 == 0;
            // Horizontal: top if the third vertex is below it (y grows downwards).
            let (top, bottom) = (horizontal && c.1 > a.1, horizontal && c.1 < a.1);
            // Otherwise `dd / d.y` is how far right of the edge line the third vertex
            // lies at its own height; the edge is a left edge if that is positive.
            let dd = (c.0 - a.0) * d.1 - d.0 * (c.1 - a.1);
            let left = !horizontal && (dd > 0) == (d.1 > 0);
            let right = !horizontal && !left;
            // inside · cross(d, q − a), expanded in q.
            let inside = cross(d, sub(c, a)).signum();
            RefEdge {
                ex: -inside * d.1,
                ey: inside * d.0,
                k: inside * (d.1 * a.0 - d.0 * a.1),
                top_left: top || left,
                bottom_right: bottom || right,
            }
        });
        let xs = p.map(|q| q.0);
        let ys = p.map(|q| q.1);
        let min = |a: [i128; 3]| a[0].min(a[1]).min(a[2]);
        let max = |a: [i128; 3]| a[0].max(a[1]).max(a[2]);
        Some(ExactTriangle {
            edges,
            clockwise: area2 > 0,
            half: 1i128 << S,
            bbox: [min(xs), max(xs), min(ys), max(ys)],
        })
    }

    fn centre(&self, x: i32) -> i128 {
        (2 * x as i128 + 1) * self.half
    }

    /// Whether the centre of pixel `(x, y)` is covered.
    pub fn covers(&self, x: i32, y: i32, rule: TieRule) -> bool {
        let (cx, cy) = (self.centre(x), self.centre(y));
        self.edges.iter().all(|e| {
            let v = e.ex * cx + e.ey * cy + e.k;
            v > 0 || (v == 0 && e.tie(rule))
        })
    }

    /// A pixel rectangle `(x0, x1, y0, y1)`, inclusive, holding every pixel
    /// whose centre can be inside (padded by one pixel: it need not be tight).
    pub fn pixel_bounds(&self) -> (i32, i32, i32, i32) {
        let one = 2 * self.half; // one pixel is 2^(S+1) units
        let f = |v: i128| (v.div_euclid(one)).clamp(-(1 << 30), 1 << 30) as i32;
        let [x0, x1, y0, y1] = self.bbox;
        (f(x0) - 1, f(x1) + 1, f(y0) - 1, f(y1) + 1)
    }
}

/// True if `cull` drops a triangle of this winding (y pointing down).
pub fn culled(cull: Cull, clockwise: bool) -> bool {
    match cull {
        Cull::None => false,
        Cull::Clockwise => clockwise,
        Cull::CounterClockwise => !clockwise,
    }
}

/// Brute-force coverage of one triangle inside `clip` under `rule`, and the
/// number of pixels the tie rule decided (centre on an edge, inside the others).
pub fn coverage_and_ties<const S: u32>(
    v: [SubPoint<S>; 3],
    clip: ClipRect,
    cull: Cull,
    rule: TieRule,
) -> (Coverage, usize) {
    let (mut cov, mut ties) = (Coverage::new(clip), 0);
    let Some(t) = ExactTriangle::new(v) else { return (cov, 0) };
    if culled(cull, t.clockwise) || clip.is_empty() {
        return (cov, 0);
    }
    let (bx0, bx1, by0, by1) = t.pixel_bounds();
    let tie = t.edges.map(|e| e.tie(rule));
    for y in by0.max(clip.y0())..=by1.min(clip.y1() - 1) {
        // Same evaluation as `covers`, with the row's terms computed once.
        let cy = t.centre(y);
        let row = t.edges.map(|e| e.ey * cy + e.k);
        for x in bx0.max(clip.x0())..=bx1.min(clip.x1() - 1) {
            let cx = t.centre(x);
            let v = [0, 1, 2].map(|i| t.edges[i].ex * cx + row[i]);
            if v.iter().all(|&e| e >= 0) && v.contains(&0) {
                ties += 1;
            }
            if (0..3).all(|i| v[i] > 0 || (v[i] == 0 && tie[i])) {
                cov.set(x, y);
            }
        }
    }
    (cov, ties)
}

/// [`coverage_and_ties`] without the tie count.
pub fn coverage_with<const S: u32>(
    v: [SubPoint<S>; 3],
    clip: ClipRect,
    cull: Cull,
    rule: TieRule,
) -> Coverage {
    coverage_and_ties(v, clip, cull, rule).0
}

/// The exact reference for [`microraster::edge::TriangleSpans`].
pub fn exact_coverage<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect, cull: Cull) -> Coverage {
    coverage_with(v, clip, cull, TieRule::TopLeft)
}

/// Point-in-triangle on unsnapped `f64` vertices, either winding, boundary excluded.
pub fn float_inside(v: [(f64, f64); 3], px: f64, py: f64) -> bool {
    let e = |a: (f64, f64), b: (f64, f64)| (b.0 - a.0) * (py - a.1) - (b.1 - a.1) * (px - a.0);
    let (e0, e1, e2) = (e(v[0], v[1]), e(v[1], v[2]), e(v[2], v[0]));
    (e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0)
}

/// Euclidean distance from `p` to the segment `ab`.
pub fn dist_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Smallest distance from `p` to the three edges of `v`.
pub fn dist_to_edges(v: [(f64, f64); 3], p: (f64, f64)) -> f64 {
    (0..3).map(|i| dist_to_segment(p, v[i], v[(i + 1) % 3])).fold(f64::INFINITY, f64::min)
}
