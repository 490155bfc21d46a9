//! Anti-aliased coverage: the exact area of each pixel inside the contours.
//!
//! # Method
//! For a pixel cell `[c, c+1] × [y, y+1]`, the integral of the winding
//! number over the cell is `Σ_edges dir · ∫ clamp(c + 1 − x(t), 0, 1) dt`
//! over the part of each edge inside the row strip (Green's theorem, one
//! edge at a time). Along a straight edge `x` is linear in `t`, so `x` is
//! uniformly distributed over `[a, b]`, the edge's x-extent in the strip,
//! and the inner integral is the strip height times the mean of
//! `clamp(c + 1 − x, 0, 1)` over `[a, b]`: a closed form with no subdivision.
//! Cells wholly right of an edge get its full signed height (the "cover");
//! cells left of it nothing.
//!
//! The fill rule is applied to the integral: nonzero takes
//! `min(1, |v|)`, even-odd folds `v` into `[0, 1]`. Where a pixel holds one
//! layer of the shape (winding 0 or ±1 everywhere in it: every shape except
//! self-overlapping polygons and the joins of thick lines) that *is* the
//! exact area of the snapped shape inside the pixel; where contours overlap
//! inside a pixel it can overestimate it (documented in [`super`]).
//!
//! The row is processed in chunks of 32 cells: chunks no edge
//! reaches have one coverage and go out as one run; the others accumulate
//! per cell. The arithmetic is `f32` on coordinates already snapped; the
//! tests compare against an `f64` evaluation of the same formula and against
//! polygon clipping in `f64` (`tests/integration/shapes_aa.rs`).

use super::edges::{Active, BITS, EdgeList};
use super::{FillRule, Runs};
use crate::ClipRect;
use crate::edge::Span;
use crate::math::Scalar;
use crate::math::scalar::floor_i32;

/// `⌊v⌋` for finite `v`, saturating beyond `i32` (far outside the frame,
/// where only the clamp to the clip matters), widened for the `i64`
/// arithmetic around it.
fn floor(v: f32) -> i64 {
    i64::from(floor_i32(v))
}

/// Cells accumulated at once.
pub(crate) const CHUNK: usize = 32;

const ONE: i64 = 1 << BITS;
const INV_ONE: f32 = 1.0 / ONE as f32;

/// One edge clipped to a row strip: x-extent `a ≤ b` (px) and signed height.
#[derive(Debug, Clone, Copy, Default)]
struct Piece {
    a: f32,
    b: f32,
    h: f32,
}

/// Mean of `clamp(c + 1 − x, 0, 1)` for `x` uniform on `[a, b]`.
#[inline]
pub(crate) fn cell_share(c: f32, a: f32, b: f32) -> f32 {
    let w = b - a;
    if w <= 1e-6 {
        return (c + 1.0 - 0.5 * (a + b)).clamp(0.0, 1.0);
    }
    let full = (b.min(c) - a).max(0.0);
    let (lo, hi) = (a.max(c), b.min(c + 1.0));
    let ramp = if lo < hi {
        let (u, v) = (c + 1.0 - lo, c + 1.0 - hi);
        0.5 * (u - v) * (u + v)
    } else {
        0.0
    };
    ((full + ramp) / w).clamp(0.0, 1.0)
}

/// `x` (px) of edge `e` at `t` subpixels, `e.y0 ≤ t ≤ e.y1`.
#[inline]
fn x_at(x0: i32, y0: i32, x1: i32, y1: i32, t: i64) -> f32 {
    // Snapped coordinates are within ±2^28: the differences fit `i32`.
    let den = y1 - y0;
    let off = (t - i64::from(y0)) * i64::from(x1 - x0);
    // An `i64` converts to `f32` by a library call on 32-bit cores; through
    // `i32` where it fits (nearly always: a shape's size squared in
    // subpixels), by one instruction with an FPU, rounded the same.
    let off = match i32::try_from(off) {
        Ok(o) => o as f32,
        Err(_) => off as f32,
    };
    // x0 + off/den in subpixels; the division is exact to f32 rounding.
    (x0 as f32 + off / den as f32) * INV_ONE
}

fn alpha(v: f32, rule: FillRule) -> u8 {
    let cov = match rule {
        FillRule::NonZero => Scalar::abs(v).min(1.0),
        FillRule::EvenOdd => {
            let m = Scalar::abs(v) % 2.0;
            if m > 1.0 { 2.0 - m } else { m }
        }
    };
    (cov * 255.0 + 0.5) as u8
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
    let lo = (i64::from(y_min).div_euclid(ONE)).max(i64::from(clip.y0())) as i32;
    let hi = super::scan::div_ceil(i64::from(y_max), ONE).min(i64::from(clip.y1())) as i32;
    let mut pieces = [Piece::default(); N];
    let mut active = Active::<N>::new();
    let mut cells = Cells { area: [0.0; CHUNK], start: [0.0; CHUNK + 1] };
    for y in lo..hi {
        let (s0, s1) = (i64::from(y) * ONE, i64::from(y + 1) * ONE);
        let (mut n, mut min_x, mut max_x) = (0, f32::INFINITY, f32::NEG_INFINITY);
        active.advance(edges.edges(), s1, s0);
        for e in active.edges(edges.edges()) {
            let (t0, t1) = (i64::from(e.y0).max(s0), i64::from(e.y1).min(s1));
            if t0 >= t1 {
                continue;
            }
            let (xa, xb) = (x_at(e.x0, e.y0, e.x1, e.y1, t0), x_at(e.x0, e.y0, e.x1, e.y1, t1));
            let (a, b) = if xa <= xb { (xa, xb) } else { (xb, xa) };
            // 0 < t1 - t0 ≤ ONE: converted through `i32`, exactly.
            pieces[n] = Piece { a, b, h: e.dir as f32 * ((t1 - t0) as i32 as f32 * INV_ONE) };
            n += 1;
            min_x = min_x.min(a);
            max_x = max_x.max(b);
        }
        if n == 0 {
            continue;
        }
        let x_lo = floor(min_x).clamp(i64::from(clip.x0()), i64::from(clip.x1())) as i32;
        let x_hi = (floor(max_x) + 1).clamp(i64::from(clip.x0()), i64::from(clip.x1())) as i32;
        row(&pieces[..n], y, (x_lo, x_hi), rule, &mut cells, runs);
    }
    runs.flush();
}

/// One chunk's accumulators: each cell's partial area, and the winding
/// change entering at each cell. Kept by the caller and zeroed only for a
/// chunk an edge touches: most chunks of a large shape (its inside, or
/// the hole of a ring) are one coverage and need neither.
struct Cells {
    area: [f32; CHUNK],
    start: [f32; CHUNK + 1],
}

/// Columns `x_lo..x_hi` of row `y`, chunk by chunk.
fn row<F: FnMut(Span, u8)>(
    pieces: &[Piece],
    y: i32,
    (x_lo, x_hi): (i32, i32),
    rule: FillRule,
    Cells { area, start }: &mut Cells,
    runs: &mut Runs<F>,
) {
    let mut c0 = x_lo;
    while c0 < x_hi {
        let len = (x_hi - c0).min(CHUNK as i32);
        let (f0, f1) = (c0 as f32, (c0 + len) as f32);
        let mut base = 0.0f32;
        let mut touched = false;
        for p in pieces {
            if p.b <= f0 {
                base += p.h;
            } else if p.a < f1 {
                if !touched {
                    // The cells this chunk reads: area[..len], start[..=len].
                    area[..len as usize].fill(0.0);
                    start[..=len as usize].fill(0.0);
                }
                touched = true;
                // Cells floor(a)..=floor(b) can be partial; those after it are covered.
                let k_lo = (floor(p.a).max(i64::from(c0)) - i64::from(c0)) as usize;
                let k_hi = ((floor(p.b) + 1).min(i64::from(c0 + len)) - i64::from(c0)) as usize;
                for (k, cell) in area.iter_mut().enumerate().take(k_hi).skip(k_lo) {
                    *cell += p.h * cell_share(f0 + k as f32, p.a, p.b);
                }
                start[k_hi] += p.h;
            }
        }
        if !touched {
            runs.push(y, c0, len as u32, alpha(base, rule));
        } else {
            let mut cover = base;
            for k in 0..len as usize {
                cover += start[k];
                runs.push(y, c0 + k as i32, 1, alpha(cover + area[k], rule));
            }
        }
        c0 += len;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cell_share_of_vertical_and_slanted_edges() {
        assert_eq!(cell_share(3.0, 3.25, 3.25), 0.75);
        assert_eq!(cell_share(3.0, 5.0, 5.0), 0.0);
        assert_eq!(cell_share(3.0, 1.0, 2.0), 1.0);
        // x uniform on [3, 4]: mean of 4 − x is ½.
        assert!((cell_share(3.0, 3.0, 4.0) - 0.5).abs() < 1e-6);
        // x uniform on [2, 4]: half the time left of the cell (1), half ramp (½).
        assert!((cell_share(3.0, 2.0, 4.0) - 0.75).abs() < 1e-6);
    }

    #[test]
    fn even_odd_folds_the_winding_integral() {
        assert_eq!(alpha(1.0, FillRule::EvenOdd), 255);
        assert_eq!(alpha(2.0, FillRule::EvenOdd), 0);
        assert_eq!(alpha(1.5, FillRule::EvenOdd), 128);
        assert_eq!(alpha(-2.0, FillRule::NonZero), 255);
    }
}
