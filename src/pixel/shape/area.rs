//! Anti-aliased coverage: the exact area of each pixel inside the contours.
//!
//! # Method
//! For a pixel cell `[c, c+1] × [y, y+1]`, the integral of the winding
//! number over the cell is `Σ_edges dir · ∫ clamp(c + 1 − x(t), 0, 1) dt`
//! over the part of each edge inside the row strip (Green's theorem, one
//! edge at a time). Each edge's part in the strip is cut at the column
//! boundaries it crosses; in column `k` the piece of height `dt` between
//! `x = p` and `x = q` adds `dt · (k + 1 − (p + q)/2)` to cell `k` (the
//! trapezoid right of it) and `dt` to every cell right of `k` (the "cover").
//! Cells left of the clip are never visited: the part of an edge left of
//! the clip is cover, the part right of it nothing.
//!
//! The fill rule is applied to the integral: nonzero takes
//! `min(1, |v|)`, even-odd folds `v` into `[0, 1]`. Where a pixel holds one
//! layer of the shape (winding 0 or ±1 everywhere in it: every shape except
//! self-overlapping polygons and the joins of thick lines) that *is* the
//! exact area of the snapped shape inside the pixel; where contours overlap
//! inside a pixel it can overestimate it (documented in [`super`]).
//!
//! # Arithmetic
//! Integer, over the whole `±2^28`-subpixel range: every crossing (the `x`
//! of an edge at a strip boundary, the `t` at a column boundary) is the
//! exact rational `x0 + (t − y0)·dx/dy` (or its inverse) rounded down to
//! [`FB`] fraction bits of a subpixel, relative to the clip and the strip,
//! so far vertices lose nothing to cancellation. Numerators are below
//! `2^60`; a piece adds below `2^53` to a cell (one pixel is exactly
//! `2^(2·FB + 9)`), so `MAX_EDGES` edges sum below `2^61`. The crossings
//! telescope: a cell right of a piece gets its height exactly. Each edge
//! through a pixel adds at most `3 · 2^-26` px² of error there, so the
//! alpha, `⌊255·v + ½⌋` of the integer integral, is within `½ + 2^-16`
//! levels per such edge of `255 ×` the exact area (`½ + 1/256` with
//! [`MAX_EDGES`](super::MAX_EDGES)): the exact area rounded, except within
//! that margin of a tie (`tests/integration/shapes_ref/far.rs` and
//! `antialiased.rs` compare with the exact area in `f64`).
//!
//! The row is processed in chunks of 32 cells: chunks no edge
//! reaches have one coverage and go out as one run; the others accumulate
//! per cell.

use super::edges::{Active, BITS, Edge, EdgeList};
use super::{FillRule, Runs};
use crate::ClipRect;
use crate::edge::Span;

/// Cells accumulated at once.
pub(crate) const CHUNK: usize = 32;

/// Fraction bits of a subpixel in crossings.
const FB: u32 = 22;
/// One subpixel, a pixel (a column's width, a strip's height) in crossing units.
const SUB: i64 = 1 << FB;
const COL: i64 = SUB << BITS;
/// The integral over one whole pixel: `COL · 2·COL` (areas are kept doubled,
/// so the trapezoid's `(p + q)/2` needs no rounding).
const FULL: i64 = COL * 2 * COL;

/// `n / d` (`d > 0`) rounded down to `FB` fraction bits: `⌊n · 2^FB / d⌋`
/// without forming `n · 2^FB` (`|n| < 2^60`, `d < 2^31`).
#[inline]
fn fixed(n: i64, d: i64) -> i64 {
    let (q, r) = (n.div_euclid(d), n.rem_euclid(d));
    // r < d < 2^31: r · 2^FB < 2^53.
    (q << FB) + (r << FB) / d
}

/// One edge clipped to a row strip: its left and right end, `x` in
/// crossing units from the clip's left side (`i64`: far vertices), `t` from
/// the strip's top (at most `16 · 2^FB`). Both ends lie on a strip boundary
/// or an end point of the edge, whole subpixels, so `|rt − lt|` is the
/// piece's exact height. 32 bytes: with the edge's index, not its copy.
#[derive(Debug, Clone, Copy, Default)]
struct Piece {
    lx: i64,
    rx: i64,
    lt: i32,
    rt: i32,
    edge: u32,
    dir: i32,
}

/// Where the strip starts: the clip's left side and the strip's top (subpixels).
#[derive(Clone, Copy)]
struct Origin {
    ox: i64,
    s0: i64,
}

impl Origin {
    /// `e` relative to the origin: `(x0, y0, dx, dy)` in subpixels.
    #[inline]
    fn rel(self, e: &Edge) -> (i64, i64, i64, i64) {
        let (x0, y0) = (i64::from(e.x0) - self.ox, i64::from(e.y0) - self.s0);
        (x0, y0, i64::from(e.x1) - i64::from(e.x0), i64::from(e.y1) - i64::from(e.y0))
    }

    /// `e` between rows `t0 < t1` (subpixels, absolute) as a piece.
    fn piece(self, e: &Edge, edge: u32, t0: i64, t1: i64) -> Piece {
        let (x0, y0, dx, dy) = self.rel(e);
        // |x0| < 2^29, dy ≤ 2^29, |t − y0| ≤ 2^29, |dx| ≤ 2^29: below 2^60.
        let at = |t: i64| (fixed(x0 * dy + (t - y0) * dx, dy), (t * SUB) as i32);
        let (a, b) = (at(t0 - self.s0), at(t1 - self.s0));
        let (l, r) = if a.0 <= b.0 { (a, b) } else { (b, a) };
        Piece { lx: l.0, rx: r.0, lt: l.1, rt: r.1, edge, dir: e.dir }
    }

    /// `t` (crossing units from the strip's top) where `e` crosses the
    /// column boundary `x` (subpixels from the clip's left side), for `x`
    /// strictly inside the piece's `x` extent (so `dx ≠ 0`).
    #[inline]
    fn t_at(self, e: &Edge, x: i64) -> i32 {
        let (x0, y0, dx, dy) = self.rel(e);
        let s = dx.signum();
        // |y0 · dx| and |(x − x0) · dy| below 2^59 each; the result lies in
        // the strip, 0 ..= 16 · 2^FB.
        fixed(y0 * dx * s + (x - x0) * dy * s, dx * s) as i32
    }
}

/// Doubled area of height `|b − a|` times a pixel's width, signed by `dir`:
/// what a piece gives every cell right of it.
#[inline]
fn cover(dir: i32, a: i32, b: i32) -> i64 {
    i64::from(dir) * i64::from((b - a).abs()) * 2 * COL
}

fn alpha(v: i64, rule: FillRule) -> u8 {
    let cov = match rule {
        FillRule::NonZero => v.abs().min(FULL),
        FillRule::EvenOdd => {
            let m = v.abs() % (2 * FULL);
            if m > FULL { 2 * FULL - m } else { m }
        }
    };
    // cov ≤ 2^53: 255·cov < 2^61.
    ((cov * 255 + FULL / 2) / FULL) as u8
}

/// Emits `(span, alpha)` runs of the exact coverage of `edges` (sorted by
/// top) inside `clip`.
pub(crate) fn scan<F: FnMut(Span, u8), const N: usize>(
    edges: &EdgeList<N>,
    rule: FillRule,
    clip: ClipRect,
    runs: &mut Runs<F>,
) {
    let (y_min, y_max) = edges.y_range();
    if edges.is_empty() || clip.is_empty() {
        return;
    }
    let one = 1i64 << BITS;
    let lo = (i64::from(y_min).div_euclid(one)).max(i64::from(clip.y0())) as i32;
    let hi = super::scan::div_ceil(i64::from(y_max), one).min(i64::from(clip.y1())) as i32;
    let cols = i64::from(clip.x1() - clip.x0());
    let mut pieces = [Piece::default(); N];
    let mut active = Active::<N>::new();
    let mut cells = Cells { area: [0; CHUNK], start: [0; CHUNK + 1] };
    for y in lo..hi {
        let o = Origin { ox: i64::from(clip.x0()) * one, s0: i64::from(y) * one };
        let s1 = o.s0 + one;
        let (mut n, mut min_x, mut max_x) = (0, i64::MAX, i64::MIN);
        active.advance(edges.edges(), s1, o.s0);
        for (i, e) in active.indexed(edges.edges()) {
            let (t0, t1) = (i64::from(e.y0).max(o.s0), i64::from(e.y1).min(s1));
            if t0 >= t1 {
                continue;
            }
            let p = o.piece(e, i, t0, t1);
            (min_x, max_x) = (min_x.min(p.lx), max_x.max(p.rx));
            pieces[n] = p;
            n += 1;
        }
        if n == 0 {
            continue;
        }
        // Columns (from the clip's left side) the pieces can reach.
        let x_lo = min_x.div_euclid(COL).clamp(0, cols) as i32;
        let x_hi = (max_x.div_euclid(COL) + 1).clamp(0, cols) as i32;
        let strip = Strip { edges: edges.edges(), pieces: &pieces[..n], o, y, cx0: clip.x0() };
        strip.row((x_lo, x_hi), rule, &mut cells, runs);
    }
    runs.flush();
}

/// One chunk's accumulators (doubled areas): each cell's partial area, and
/// the winding change entering at each cell. Kept by the caller and zeroed
/// only for a chunk an edge touches: most chunks of a large shape (its
/// inside, or the hole of a ring) are one coverage and need neither.
struct Cells {
    area: [i64; CHUNK],
    start: [i64; CHUNK + 1],
}

/// One row strip's pieces.
struct Strip<'a> {
    edges: &'a [Edge],
    pieces: &'a [Piece],
    o: Origin,
    y: i32,
    cx0: i32,
}

impl Strip<'_> {
    /// Columns `x_lo..x_hi` (from the clip's left side), chunk by chunk.
    fn row<F: FnMut(Span, u8)>(
        &self,
        (x_lo, x_hi): (i32, i32),
        rule: FillRule,
        Cells { area, start }: &mut Cells,
        runs: &mut Runs<F>,
    ) {
        let mut c0 = x_lo;
        while c0 < x_hi {
            let len = (x_hi - c0).min(CHUNK as i32);
            let (f0, f1) = (i64::from(c0) * COL, i64::from(c0 + len) * COL);
            let mut base = 0i64;
            let mut touched = false;
            for p in self.pieces {
                if p.rx <= f0 {
                    base += cover(p.dir, p.lt, p.rt);
                } else if p.lx < f1 {
                    if !touched {
                        // The cells this chunk reads: area[..len], start[..=len].
                        area[..len as usize].fill(0);
                        start[..=len as usize].fill(0);
                    }
                    touched = true;
                    let e = &self.edges[p.edge as usize];
                    // The part left of the chunk is cover for all of it.
                    let (mut ax, mut at) = (p.lx, p.lt);
                    if ax < f0 {
                        let t = self.o.t_at(e, f0 >> FB);
                        base += cover(p.dir, at, t);
                        (ax, at) = (f0, t);
                    }
                    // Column by column, to the right end or the chunk's side.
                    let mut k = (ax - f0).div_euclid(COL);
                    while k < i64::from(len) {
                        let side = f0 + (k + 1) * COL;
                        let end = p.rx <= side;
                        let (bx, bt) = if end { (p.rx, p.rt) } else { (side, self.o.t_at(e, side >> FB)) };
                        // The trapezoid right of the piece in column k, and
                        // its height as cover for the columns after it.
                        let dt = i64::from(p.dir) * i64::from((bt - at).abs());
                        area[k as usize] += dt * (2 * side - ax - bx);
                        start[k as usize + 1] += dt * 2 * COL;
                        if end {
                            break;
                        }
                        (ax, at, k) = (bx, bt, k + 1);
                    }
                }
            }
            let x = self.cx0 + c0;
            if !touched {
                runs.push(self.y, x, len as u32, alpha(base, rule));
            } else {
                let mut cover = base;
                for k in 0..len as usize {
                    cover += start[k];
                    runs.push(self.y, x + k as i32, 1, alpha(cover + area[k], rule));
                }
            }
            c0 += len;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_rounds_down_for_both_signs() {
        assert_eq!(fixed(3, 2), 3 * SUB / 2);
        assert_eq!(fixed(-3, 2), -3 * SUB / 2);
        assert_eq!(fixed(1, 3), SUB / 3);
        assert_eq!(fixed(-1, 3), -(SUB / 3) - 1);
    }

    #[test]
    fn even_odd_folds_the_winding_integral() {
        assert_eq!(alpha(FULL, FillRule::EvenOdd), 255);
        assert_eq!(alpha(2 * FULL, FillRule::EvenOdd), 0);
        assert_eq!(alpha(3 * FULL / 2, FillRule::EvenOdd), 128);
        assert_eq!(alpha(-2 * FULL, FillRule::NonZero), 255);
    }
}
