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
//! is `⌈(x_c − ½)⌉`, computed exactly with one `i64` division. The crossings
//! are sorted (insertion sort, at most `N`) and swept left to right summing
//! the edges' directions. Overflow: coordinates are at most `2^28` subpixel
//! units, so every product is below `2^58` and every sum below `2^60`.

use super::edges::{Active, BITS, EdgeList};
use super::{FillRule, Runs};
use crate::ClipRect;

const ONE: i64 = 1 << BITS;
const HALF: i64 = ONE / 2;

/// `⌈a / b⌉` for `b > 0`.
pub(crate) const fn div_ceil(a: i64, b: i64) -> i64 {
    let q = a.div_euclid(b);
    if q * b == a { q } else { q + 1 }
}

/// Rows `lo..hi` whose centres `y + ½` lie in `y_min ≤ · < y_max` (subpixels).
fn center_rows(y_min: i32, y_max: i32, clip: ClipRect) -> (i32, i32) {
    let lo = div_ceil(i64::from(y_min) - HALF, ONE).max(i64::from(clip.y0()));
    let hi = div_ceil(i64::from(y_max) - HALF, ONE).min(i64::from(clip.y1()));
    // Both now lie within the clip's 0..=MAX_FRAME_DIM.
    (lo as i32, hi.max(lo) as i32)
}

/// Emits the covered spans of `edges` (sorted by top) inside `clip` (alpha 255).
pub(crate) fn scan<F: FnMut(crate::edge::Span, u8), const N: usize>(
    edges: &EdgeList<N>,
    rule: FillRule,
    clip: ClipRect,
    runs: &mut Runs<F>,
) {
    let (y_min, y_max) = edges.y_range();
    if edges.is_empty() || clip.is_empty() {
        return;
    }
    let (lo, hi) = center_rows(y_min, y_max, clip);
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
            let x = div_ceil(num - HALF * den, ONE * den).clamp(cx0, cx1) as i32;
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn div_ceil_rounds_up_for_both_signs() {
        assert_eq!([div_ceil(7, 2), div_ceil(-7, 2), div_ceil(6, 2), div_ceil(-6, 2)], [4, -3, 3, -3]);
    }

    #[test]
    fn rows_are_the_centres_inside_half_open() {
        let clip = ClipRect::new(0, 0, 100, 100);
        // Edge from y = 1.5 to 3.5 px: centres 1.5 and 2.5 (3.5 is excluded).
        assert_eq!(center_rows(24, 56, clip), (1, 3));
        assert_eq!(center_rows(25, 56, clip), (2, 3));
        assert_eq!(center_rows(-1000, 5000, ClipRect::new(0, 2, 9, 4)), (2, 4));
    }
}
