//! Coverage of small triangles by testing each candidate pixel centre.
//!
//! A triangle whose vertices span at most [`SMALL_PX`] pixels on each axis
//! covers few centres, so solving each row's span (two divisions per edge and
//! the walker's set-up, in `i64` at first) costs more than testing every
//! centre of its bounding box. Here each centre is tested directly with the
//! same edge functions as [`TriangleSpans`](super::TriangleSpans): centre `c`
//! is covered when `E(c) − bias ≥ 0` for all three edges, `bias = 0` for a top
//! or left edge and `1` otherwise, which is exactly `F ≥ 0` for the reduced
//! `F = ⌊(E − bias)/2^(S+1)⌋` of the module docs (the floor of a division by a
//! positive number is negative exactly when the dividend is). A horizontal
//! edge needs no special case: its `E` is 0 on its own row, so a bottom edge
//! (bias 1) leaves that row out and a top edge takes it, as the row bounds of
//! the walker do. Rows and columns without a covered centre give no span, so
//! the spans are exactly those of the walker.
//!
//! # Range
//! Everything is `i32`. Internal coordinates `2·v` are at most `2^29` in
//! magnitude, so the bounding box's sides (at most `2^30`) fit. When a side is
//! at most `L = SMALL_PX · 2^(S+1) ≤ 2^13`, coordinates are taken relative to
//! the box corner (in `0..=L`): `|A|, |B| ≤ L`, the determinant is below `2L²`
//! and every centre the scan evaluates lies within one pixel (`2^(S+1)`) right
//! of or below the box, so `|E| ≤ L·(L + 2^(S+1)) · 2 + 1 < 2^28`: no overflow.

use super::{Cull, Path, Span, min_max};
use crate::{ClipRect, SubPoint};

/// Largest bounding-box side, in pixels, that takes the per-centre test.
/// Chosen by measurement (Cortex-M4F, QEMU `-icount`, `fw_bench`): the tiny
/// scene (boxes up to 3 px) takes it whatever the value; on the 3D scene
/// (about 42 px per triangle) 2, 4, 8 and 16 all stay within 0.3% of the row
/// solver alone, 8 lowest among them.
pub const SMALL_PX: i32 = 8;

// The range proof of the module docs needs L = SMALL_PX·2^(S+1) ≤ 2^13.
const _: () = assert!(SMALL_PX >= 0 && SMALL_PX << (crate::MAX_SUBPIXEL_BITS + 1) <= 1 << 13);

/// Edge functions of a small triangle at the first candidate column of the
/// current row, minus their bias (covered: all three `≥ 0`), with their steps
/// per column and per row.
#[derive(Debug, Clone)]
pub(crate) struct Small {
    e: [i32; 3],
    a: [i32; 3],
    b: [i32; 3],
    x0: i32,
    cols: i32,
    y: i32,
    y_end: i32,
    /// Twice the area in internal units (`> 0`): the sum of the three
    /// unbiased edge functions at any point.
    det: i32,
    /// Each edge's top-left bias (0 or 1).
    bias: [i32; 3],
}

/// The coverage path of a triangle whose bounding box is at most
/// [`SMALL_PX`] pixels on each side; `None` for a larger one.
#[inline(always)]
pub(super) fn setup<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect, cull: Cull) -> Option<Path> {
    setup_state(v, clip, cull).map(|s| s.map_or(Path::Empty, Path::Small))
}

/// [`setup`] without the [`Path`]: `Some(None)` for a small triangle with no
/// covered centre (or culled, or of zero area), `Some(Some(state))` for
/// one to walk, `None` for a larger one. The 3D fragment loop keeps the
/// state in its own frame instead of storing it into a `Path`.
#[inline(always)]
pub(crate) fn setup_state<const S: u32>(
    v: [SubPoint<S>; 3],
    clip: ClipRect,
    cull: Cull,
) -> Option<Option<Small>> {
    let shift = S + 1;
    let (one, half) = (1i32 << shift, 1i32 << S);
    let limit = SMALL_PX << shift;
    // |2·v| ≤ 2^29 (SubPoint), so sums of two and the box sides fit i32.
    let p = v.map(|p| (2 * p.x(), 2 * p.y()));
    let (min_x, max_x) = min_max(p[0].0, p[1].0, p[2].0);
    let (min_y, max_y) = min_max(p[0].1, p[1].1, p[2].1);
    if max_x - min_x > limit || max_y - min_y > limit {
        return None;
    }
    // Relative to the box corner: in 0..=limit (module docs).
    let q = p.map(|(x, y)| (x - min_x, y - min_y));
    let det = (q[1].0 - q[0].0) * (q[2].1 - q[0].1) - (q[2].0 - q[0].0) * (q[1].1 - q[0].1);
    let clockwise = det > 0;
    let culled = match cull {
        Cull::None => false,
        Cull::Clockwise => clockwise,
        Cull::CounterClockwise => !clockwise,
    };
    if det == 0 || culled || clip.is_empty() {
        return Some(None);
    }
    // Pixels whose centre can lie inside the box (clip in 0..=4096).
    let col0 = ((min_x - half + one - 1) >> shift).max(clip.x0());
    let col1 = ((max_x - half) >> shift).min(clip.x1() - 1);
    let row0 = ((min_y - half + one - 1) >> shift).max(clip.y0());
    let row1 = ((max_y - half) >> shift).min(clip.y1() - 1);
    if col0 > col1 || row0 > row1 {
        return Some(None);
    }
    // The first centre, relative to the corner: inside the box, in 0..=limit.
    let (cx, cy) = (col0 * one + half - min_x, row0 * one + half - min_y);
    let mut s = Small {
        e: [0; 3],
        a: [0; 3],
        b: [0; 3],
        x0: col0,
        cols: col1 - col0 + 1,
        y: row0,
        y_end: row1 + 1,
        det: det.abs(),
        bias: [0; 3],
    };
    // Edge i is the one opposite vertex i, directed so that the inside is
    // on its non-negative side (the vertices clockwise).
    // Reversing an edge negates its function, so the points need no swap.
    let sign = if clockwise { 1 } else { -1 };
    for i in 0..3 {
        let (st, en) = (q[(i + 1) % 3], q[(i + 2) % 3]);
        let (a, b) = (sign * (st.1 - en.1), sign * (en.0 - st.0));
        s.bias[i] = bias(a, b);
        s.e[i] = a * (cx - st.0) + b * (cy - st.1) - s.bias[i];
        (s.a[i], s.b[i]) = (a << shift, b << shift);
    }
    Some(Some(s))
}

/// The top-left rule's bias of an edge with function steps `a` per column
/// and `b` per row, not both 0: 0 for a top or left edge (`a > 0`, or
/// `a = 0 < b`), else 1. With `|a|, |b| ≤ L ≤ 2^13` (module docs),
/// `a·2^14 + b` has the sign of `a`, or of `b` where `a = 0`: one compare.
#[inline(always)]
fn bias(a: i32, b: i32) -> i32 {
    ((a << 14) + b <= 0) as i32
}

impl Small {
    /// The covered columns `lo..=hi` (relative to `x0`) of the row whose
    /// edge functions at its first column are `e`. Covered centres of a row
    /// are contiguous (a convex triangle), so the scan stops after them.
    #[inline(always)]
    fn row(&self, mut e: [i32; 3]) -> Option<(i32, i32)> {
        let inside = |e: &[i32; 3]| (e[0] | e[1] | e[2]) >= 0;
        let mut c = 0;
        while !inside(&e) {
            c += 1;
            if c == self.cols {
                return None;
            }
            e = [e[0] + self.a[0], e[1] + self.a[1], e[2] + self.a[2]];
        }
        let lo = c;
        loop {
            c += 1;
            if c == self.cols {
                break;
            }
            e = [e[0] + self.a[0], e[1] + self.a[1], e[2] + self.a[2]];
            if !inside(&e) {
                break;
            }
        }
        Some((lo, c - 1))
    }

    #[inline(always)]
    fn span(&self, y: i32, (lo, hi): (i32, i32)) -> Span {
        Span { y, x: self.x0 + lo, len: (hi - lo + 1) as u32 }
    }

    #[inline(always)]
    fn next_row(&self, e: [i32; 3]) -> [i32; 3] {
        [e[0] + self.b[0], e[1] + self.b[1], e[2] + self.b[2]]
    }

    #[inline(always)]
    pub(crate) fn next_span(&mut self) -> Option<Span> {
        while self.y < self.y_end {
            let (y, row) = (self.y, self.row(self.e));
            self.y += 1;
            if self.y < self.y_end {
                self.e = self.next_row(self.e);
            }
            if let Some(r) = row {
                return Some(self.span(y, r));
            }
        }
        None
    }

    /// Twice the triangle's area in internal units (`0 < det < 2L²`, module
    /// docs): the sum of the three unbiased edge functions at any point.
    #[inline(always)]
    pub(crate) fn det(&self) -> i32 {
        self.det
    }

    /// The edges' biases: edge `i` lies opposite vertex `i`, and at a point
    /// its biased function (as [`Small::for_each_centre`] gives it) plus its
    /// bias is [`Small::det`] times the barycentric coordinate of vertex `i`.
    #[inline(always)]
    pub(crate) fn biases(&self) -> [i32; 3] {
        self.bias
    }

    /// `f(x, y, e)` for each covered centre not yet walked, row by row, left
    /// to right, with the biased edge functions `e` there (each `≥ 0`).
    /// It scans a row itself rather than through [`Small::row`]: finding
    /// the span first and stepping to its start again made the knot frame
    /// 10 % dearer (Cortex-M4F, `fw_bench`).
    #[inline(always)]
    pub(crate) fn for_each_centre(&self, mut f: impl FnMut(i32, i32, [i32; 3])) {
        let mut e = self.e;
        for y in self.y..self.y_end {
            let (mut ec, mut seen) = (e, false);
            for c in 0..self.cols {
                if (ec[0] | ec[1] | ec[2]) >= 0 {
                    f(self.x0 + c, y, ec);
                    seen = true;
                } else if seen {
                    // Covered centres of a row are contiguous.
                    break;
                }
                ec = [ec[0] + self.a[0], ec[1] + self.a[1], ec[2] + self.a[2]];
            }
            e = self.next_row(e);
        }
    }

    /// All remaining spans, in one loop over local state.
    #[inline(always)]
    pub(super) fn fold<B, G: FnMut(B, Span) -> B>(&self, init: B, mut g: G) -> B {
        let mut e = self.e;
        let mut acc = init;
        for y in self.y..self.y_end {
            if let Some(r) = self.row(e) {
                acc = g(acc, self.span(y, r));
            }
            e = self.next_row(e);
        }
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::super::TriangleSpans;
    use super::*;

    /// A fingerprint of the spans through internal iteration (`fold`).
    fn folded(t: &TriangleSpans) -> (u64, u32) {
        t.clone().fold((0u64, 0u32), |(h, n), s| {
            let v = (s.y as u64) << 40 ^ (s.x as u64) << 20 ^ s.len as u64;
            (h.wrapping_mul(0x100_0000_01b3) ^ v, n + 1)
        })
    }

    /// Random triangles up to a few pixels past [`SMALL_PX`], their
    /// coordinates mostly on the half-pixel grid (so centres fall on edges
    /// and vertices: ties), each through the per-centre test and through the
    /// row solver; the spans must be the same, by `next` and by `fold`.
    fn check<const S: u32>(cases: u32) -> (u32, u32) {
        let mut seed = 0x9E37_79B9_7F4A_7C15u64 ^ S as u64;
        let mut next = |n: u32| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            ((seed >> 33) % n as u64) as i32
        };
        let (px, half_px) = (1i32 << S, (1i32 << S) / 2);
        let (mut small, mut ties) = (0, 0);
        for _ in 0..cases {
            let size = 1 + next(SMALL_PX as u32 + 3);
            let (ox, oy) = (next(30) * px - 2 * px, next(30) * px - 2 * px);
            let mut coord = |o: i32| match next(4) {
                // A pixel corner or centre (S = 0 has no centres: corners).
                0 | 1 => o + next(2 * size as u32 + 1) * px / 2,
                2 => o + next(size as u32 + 1) * px + half_px,
                _ => o + next((size * px) as u32 + 1),
            };
            let v = [0; 3].map(|_| SubPoint::<S>::new(coord(ox), coord(oy)).unwrap());
            let clip = match next(3) {
                0 => ClipRect::new(0, 0, 32, 32),
                1 => ClipRect::new(next(16), next(16), 16 + next(20), 16 + next(20)),
                _ => ClipRect::new(0, next(30), 4096, 4 + next(32)),
            };
            let cull = [Cull::None, Cull::None, Cull::Clockwise, Cull::CounterClockwise][next(4) as usize];
            let got = TriangleSpans::new(v, clip, cull);
            let want = TriangleSpans::solved(v, clip, cull);
            // Small triangles with spans (the rest: empty, or solved rows).
            small += (matches!(got.path, Path::Small(_)) && got.clone().next().is_some()) as u32;
            assert!(got.clone().eq(want.clone()), "{v:?} {clip:?} {cull:?}");
            assert_eq!(folded(&got), folded(&want), "{v:?} {clip:?} {cull:?}");
            // Ties: a vertex on a pixel centre, or an edge through one.
            let c = |p: SubPoint<S>| 2 * p.x() - px;
            ties += v.iter().any(|p| c(*p) % (2 * px) == 0 && (2 * p.y() - px) % (2 * px) == 0) as u32;
        }
        (small, ties)
    }

    macro_rules! small_matches_solver {
        ($($name:ident: $s:literal),*) => {$(
            #[test]
            fn $name() {
                let cases = 60_000;
                let (small, ties) = check::<$s>(cases);
                // Both paths must have been exercised, and ties must occur.
                assert!(small > cases / 4 && small < cases, "{small} of {cases} small");
                assert!($s == 0 || ties > cases / 20, "{ties} of {cases} with a vertex on a centre");
            }
        )*};
    }
    small_matches_solver!(s0: 0, s1: 1, s2: 2, s3: 3, s4: 4, s5: 5, s6: 6, s7: 7, s8: 8);
}
