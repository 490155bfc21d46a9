//! Aliased coverage of an edge list: the top-left rule, generalised to any
//! closed contours with a winding-number fill rule.
//!
//! # Rule
//! A pixel is covered when the winding number of the contours around the
//! point `centre + (ε, ε²)` (for an infinitesimal `ε > 0`) passes the fill
//! rule. For a triangle that *is* the top-left rule of [`crate::edge`]: a
//! centre on a left edge moves inside, on a right edge outside, on a top
//! (horizontal) edge inside, on a bottom edge outside — so shapes and
//! triangles that share an edge split its pixels exactly as two triangles
//! do, and every fan of triangles gives the same pixels as its outline
//! (`tests/integration/shapes_seams.rs` checks both against
//! [`TriangleSpans`](crate::edge::TriangleSpans)).
//!
//! # Method
//! Per row, the centre line `y + ½` (plus `ε²`) crosses an edge from `y0` to
//! `y1` when `y0 ≤ y + ½ < y1`. The crossing `x_c` is rational; the centre
//! `x + ½ + ε` lies right of it when `x + ½ ≥ x_c`, so the first such column
//! is `⌈(x_c − ½)⌉`. With `den = y1 − y0`, `dx = x1 − x0` and the centre
//! `yc` (all in subpixels, `ONE` subpixels a pixel) that column is
//! `q = ⌈A / D⌉` for `A = x0·den + (yc − y0)·dx − ½·ONE·den` and
//! `D = ONE·den`.
//!
//! # Walking (no division per row)
//! Each active edge keeps `q` and the remainder `r = q·D − A`, with the
//! invariant `0 ≤ r < D`. Both are computed once, with one division, in the
//! first row the scan meets the edge. From row to row `yc` grows by `ONE`, so
//! `A` grows by `ONE·dx = step·D + rstep` with `step = ⌊dx / den⌋` and
//! `rstep = ONE·(dx mod den)` in `0..D` (a second division, once per edge).
//! Then `A' = (q + step)·D − (r − rstep)`: if `r − rstep ≥ 0` the invariant
//! holds with `q' = q + step`; otherwise `r − rstep` lies in `−D..0`, and
//! `q' = q + step + 1`, `r' = r − rstep + D` restores it. So `q` is exactly
//! `⌈A / D⌉` in every row: the pixels are those of the division per row
//! ([`scan_divided`], kept as the reference and as the fallback for more
//! edges active at once than there are walkers: [`WALKERS`], or
//! [`SMALL_WALKERS`] for lists of at most 32 edges).
//!
//! The crossings stay in a sorted array from row to row (edges rarely swap),
//! so re-sorting is an insertion sort over an almost sorted array: one
//! comparison per edge when nothing crossed.
//!
//! # Overflow
//! Coordinates are at most `2^28` subpixel units, so `|dx|, den ≤ 2^29`,
//! `D ≤ 2^33`, `|A| < 2^59` and every product in the set-up is below `2^58`
//! (`i64`). While walking `r, rstep ∈ [0, D)` so `r − rstep + D < 2^34`,
//! and `q` stays a column of the edge's own span (`|q| ≤ 2^25`), which with
//! `step` (`|step| ≤ 2^29`) stays in `i32`: `|q + step + 1| < 2^31` as the
//! next row's `q` is again a column of the edge. The set-up divides in `i32`
//! (a hardware divide on the Cortex-M3/M4) whenever `A` and `D` fit, which on
//! a display-sized shape is always.

use super::edges::{Active, BITS, Edge, EdgeList};
use super::{FillRule, Runs};
use crate::ClipRect;
use crate::edge::Span;

const ONE: i64 = 1 << BITS;
const HALF: i64 = ONE / 2;

/// Most edges walked at once; a scan that needs more finishes with
/// [`scan_divided`] (same pixels). A shape of at most this many edges never
/// does.
pub(crate) const WALKERS: usize = 64;

/// Walkers for the small edge lists (up to 32 edges, most shapes): the
/// walker array is zeroed once per scan, and a disc or a rounded rectangle
/// has 2 edges across a row, a star 4, so 16 (640 bytes) rather than 32.
pub(crate) const SMALL_WALKERS: usize = 16;

/// `⌈a / b⌉` for `b > 0`.
pub(crate) const fn div_ceil(a: i64, b: i64) -> i64 {
    let q = a.div_euclid(b);
    if q * b == a { q } else { q + 1 }
}

/// `(⌈a / b⌉, ⌈a / b⌉·b − a)` for `b > 0`: the remainder is in `0..b`. In
/// `i32` when both fit (no library call on a 32-bit target).
#[inline]
fn div_ceil_rem(a: i64, b: i64) -> (i64, i64) {
    let q = match (i32::try_from(a), i32::try_from(b)) {
        (Ok(a32), Ok(b32)) => i64::from(div_ceil32(a32, b32)),
        _ => div_ceil(a, b),
    };
    (q, q * b - a)
}

/// `⌈a / b⌉` for `b > 0`, in `i32` (never overflows: `|⌈a/b⌉| ≤ |a|`, and
/// `a = i32::MIN` only with `b ≥ 1`, where `⌈a / b⌉ ≥ a`).
#[inline]
const fn div_ceil32(a: i32, b: i32) -> i32 {
    // Truncating division rounds towards zero: up for a < 0, so only a
    // positive inexact quotient needs the +1.
    let q = a / b;
    if a > 0 && q * b != a { q + 1 } else { q }
}

/// Rows `lo..hi` whose centres `y + ½` lie in `y_min ≤ · < y_max` (subpixels).
fn center_rows(y_min: i32, y_max: i32, clip: ClipRect) -> (i32, i32) {
    let (lo, hi) = (first_row(y_min).max(i64::from(clip.y0())), first_row(y_max).min(i64::from(clip.y1())));
    // Both now lie within the clip's 0..=MAX_FRAME_DIM.
    (lo as i32, hi.max(lo) as i32)
}

/// The rows both scans visit: [`center_rows`] of the edges' extent, none
/// for no edges or an empty clip.
fn scan_rows<const N: usize>(edges: &EdgeList<N>, clip: ClipRect) -> Option<(i32, i32)> {
    let (y_min, y_max) = edges.y_range();
    (!edges.is_empty() && !clip.is_empty()).then(|| center_rows(y_min, y_max, clip))
}

/// The first row whose centre is at or below `y` (subpixels): `⌈(y − ½)/ONE⌉`,
/// a shift.
#[inline]
pub(crate) fn first_row(y: i32) -> i64 {
    (i64::from(y) - HALF + ONE - 1) >> BITS
}

/// One edge being walked down the rows (see the module docs).
#[derive(Debug, Clone, Copy, Default)]
struct Walker {
    /// First column right of the crossing in the current row, unclamped.
    q: i32,
    dir: i32,
    /// First row the edge no longer crosses.
    end: i32,
    step: i32,
    r: i64,
    rstep: i64,
    d: i64,
}

impl Walker {
    /// The walker of `e` at row `y` (`e` crosses row `y`).
    fn new(e: &Edge, y: i32) -> Self {
        let (x0, y0) = (i64::from(e.x0), i64::from(e.y0));
        let (den, dx) = (e.y1 - e.y0, e.x1 - e.x0);
        let d = ONE * i64::from(den);
        let yc = i64::from(y) * ONE + HALF;
        let (q, r) = div_ceil_rem(x0 * i64::from(den) + (yc - y0) * i64::from(dx) - HALF * i64::from(den), d);
        // i32: den > 0 and both within 2^29 (module docs).
        let (step, rem) = (dx.div_euclid(den), dx.rem_euclid(den));
        // q is a column of the edge: within 2^25 (module docs).
        let end = first_row(e.y1) as i32;
        Walker { q: q as i32, dir: e.dir, end, step, r, rstep: ONE * i64::from(rem), d }
    }

    /// Moves to the next row: exact add and carry.
    #[inline(always)]
    fn next(&mut self) {
        self.q += self.step;
        self.r -= self.rstep;
        if self.r < 0 {
            self.r += self.d;
            self.q += 1;
        }
    }
}

/// Emits the covered spans of `edges` (sorted by top) inside `clip` (alpha 255).
pub(crate) fn scan<F: FnMut(crate::edge::Span, u8), const N: usize>(
    edges: &EdgeList<N>,
    rule: FillRule,
    clip: ClipRect,
    runs: &mut Runs<F>,
) {
    if let Some(chains) = Chains::sorted(edges.edges(), clip) {
        return chains.walk(edges.edges(), clip, runs);
    }
    // The branches are on constants and fold away.
    if N <= SMALL_WALKERS {
        walk::<F, N, N>(edges, rule, clip, runs)
    } else if N <= 2 * SMALL_WALKERS {
        walk::<F, N, SMALL_WALKERS>(edges, rule, clip, runs)
    } else {
        walk::<F, N, WALKERS>(edges, rule, clip, runs)
    }
}

/// [`scan`] with at most `K` edges walked at once.
fn walk<F: FnMut(crate::edge::Span, u8), const N: usize, const K: usize>(
    edges: &EdgeList<N>,
    rule: FillRule,
    clip: ClipRect,
    runs: &mut Runs<F>,
) {
    let Some((lo, hi)) = scan_rows(edges, clip) else { return };
    let list = edges.edges();
    let mut w = [Walker::default(); K];
    let (mut n, mut next) = (0, 0);
    for y in lo..hi {
        let yc = i64::from(y) * ONE + HALF;
        // Enter the edges whose top is at or above this centre, sorted into
        // place; those that already ended above it never cross a row here.
        while let Some(e) = list.get(next).filter(|e| i64::from(e.y0) <= yc) {
            next += 1;
            if i64::from(e.y1) <= yc {
                continue;
            }
            if n == K {
                // More edges cross this row than walkers: the rest by division.
                let rest = ClipRect::new(clip.x0(), y, clip.x1(), clip.y1());
                return scan_divided(edges, rule, rest, runs);
            }
            w[n] = Walker::new(e, y);
            n += 1;
        }
        sort(&mut w[..n]);
        // The row's covered columns, runs that touch joined here (what
        // `Runs::push` would join) and handed on whole.
        let mut winding = 0i32;
        let mut run: Option<(i32, i32)> = None;
        for i in 0..n {
            winding += w[i].dir;
            if rule.inside(winding) {
                let x = w[i].q.clamp(clip.x0(), clip.x1());
                let next = if i + 1 < n { w[i + 1].q.clamp(clip.x0(), clip.x1()) } else { clip.x1() };
                if next > x {
                    run = match run {
                        Some((a, b)) if b == x => Some((a, next)),
                        Some((a, b)) => {
                            runs.emit(Span { y, x: a, len: (b - a) as u32 });
                            Some((x, next))
                        }
                        None => Some((x, next)),
                    };
                }
            }
        }
        if let Some((a, b)) = run {
            runs.emit(Span { y, x: a, len: (b - a) as u32 });
        }
        // Step to the next row, dropping the edges that end here.
        // (Moved only past a dropped one: a walker is 40 bytes.)
        let mut k = 0;
        for i in 0..n {
            if w[i].end > y + 1 {
                if k != i {
                    w[k] = w[i];
                }
                w[k].next();
                k += 1;
            }
        }
        n = k;
    }
    runs.flush();
}

/// Insertion sort by column: after one row's steps the walkers are almost
/// always still in order, which costs one comparison each.
#[inline]
fn sort(w: &mut [Walker]) {
    for i in 1..w.len() {
        if w[i - 1].q <= w[i].q {
            continue;
        }
        let v = w[i];
        let mut j = i;
        while j > 0 && w[j - 1].q > v.q {
            w[j] = w[j - 1];
            j -= 1;
        }
        w[j] = v;
    }
}

/// The reference scan: each crossing by one division per row and edge.
/// Used when more than [`WALKERS`] edges cross one row (the divisions run in
/// `i32` whenever the values fit), and by the tests.
fn scan_divided<F: FnMut(crate::edge::Span, u8), const N: usize>(
    edges: &EdgeList<N>,
    rule: FillRule,
    clip: ClipRect,
    runs: &mut Runs<F>,
) {
    let Some((lo, hi)) = scan_rows(edges, clip) else { return };
    let (cx0, cx1) = (i64::from(clip.x0()), i64::from(clip.x1()));
    let mut xs = [(0i32, 0i32); N];
    let mut active = Active::<N>::new();
    for y in lo..hi {
        let yc = i64::from(y) * ONE + HALF;
        let mut n = 0;
        active.advance(edges.edges(), yc + 1, yc);
        for e in active.edges(edges.edges()) {
            let (y0, y1) = (i64::from(e.y0), i64::from(e.y1));
            if y0 > yc || yc >= y1 {
                continue;
            }
            let den = y1 - y0;
            let num = i64::from(e.x0) * den + (yc - y0) * (i64::from(e.x1) - i64::from(e.x0));
            let x = div_ceil_rem(num - HALF * den, ONE * den).0.clamp(cx0, cx1) as i32;
            // Insertion into the sorted prefix; n < N as there are N edges.
            let mut i = n;
            while i > 0 && xs[i - 1].0 > x {
                xs[i] = xs[i - 1];
                i -= 1;
            }
            xs[i] = (x, e.dir);
            n += 1;
        }
        let mut winding = 0i32;
        for i in 0..n {
            winding += xs[i].1;
            let (x, next) = (xs[i].0, if i + 1 < n { xs[i + 1].0 } else { clip.x1() });
            if next > x && rule.inside(winding) {
                runs.push(y, x, (next - x) as u32, 255);
            }
        }
    }
    runs.flush();
}

mod chains;
pub(crate) use chains::Chains;

#[cfg(test)]
mod tests;
