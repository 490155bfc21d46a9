//! One-pixel-wide line segments: midpoint (Pitteway / van Aken–Novak) scan
//! conversion with subpixel end points.
//!
//! # The rule
//!
//! This is a public guarantee; the tests check it against exact rational
//! arithmetic.
//!
//! * The **major axis** is x when `|dx| ≥ |dy|` (in subpixel units), else y.
//!   The other axis is the minor axis.
//! * One pixel is emitted for each major-axis pixel index `M` whose centre
//!   `M + 0.5` lies in the half-open interval from the start point `a` to the
//!   end point `b` along the major axis: **start inclusive, end exclusive**, in
//!   the direction of travel. Pixels come out in that order, from `a` to `b`.
//! * The minor index is `m = floor(v)`, where `v` is the minor coordinate of
//!   the exact line through `a` and `b` at the major centre `M + 0.5`: the
//!   pixel that contains that point of the line. A point exactly on the
//!   boundary between two pixels goes to the **larger index**. The choice
//!   does not depend on direction: `a → b` and `b → a` light the same pixels
//!   apart from the end-point rule.
//! * Exactly one pixel per major index, so a line is 8-connected and has no
//!   gaps. Only pixels inside the [`ClipRect`] are emitted.
//!
//! # Why half-open
//!
//! A polyline `a → b → c` lights the shared vertex's pixel once (it ends the
//! first segment's exclusive end and begins the second), which matters for
//! XOR or blended drawing, and a zero-length segment draws nothing. Closing a
//! polygon outline with `… → a` is therefore seamless too.
//!
//! # Lines and triangle edges
//!
//! The triangle rasterizer works on the same snapped coordinates and fills a
//! pixel when its centre is inside (top-left rule for centres exactly on an
//! edge). In each major column (or row) a line drawn along a triangle edge
//! lights the pixel that *contains* the edge at that column's centre. The
//! pixel centres on the triangle's side of that point are filled and those on
//! the other side are not, so the line's pixel is either the fill's last pixel
//! in that column or its first unfilled neighbour. A wireframe drawn over a
//! filled mesh thus never strays more than one pixel from the fill's boundary.
//!
//! # Arithmetic
//!
//! Integer only. Coordinates are doubled internally so that pixel centres are
//! odd integers even when `S = 0`. The first visible pixel is computed
//! directly by exact floor/ceil division, so the invisible part of a long line
//! is never walked; the minor index is monotonic, so the last visible pixel is
//! computed the same way. Each further pixel costs one add and one compare of
//! the decision variable (plus a minor step when it fires).
//!
//! ```
//! use microraster::line::{line_pixels, line_rows};
//! use microraster::{ClipRect, SubPoint};
//!
//! let a = SubPoint::<4>::pixel_center(0, 0).unwrap();
//! let b = SubPoint::<4>::pixel_center(4, 2).unwrap();
//! let px: Vec<_> = line_pixels(a, b, ClipRect::new(0, 0, 16, 16)).collect();
//! // At x = 1.5 the line is exactly at y = 1.0, a pixel boundary: row 1 wins.
//! // The end pixel (4, 2) is not drawn (half-open).
//! assert_eq!(px, [(0, 0), (1, 1), (2, 1), (3, 2)]);
//! assert_eq!(line_rows(a, b), Some((0, 2)));
//! ```

use crate::{ClipRect, SubPoint};
use core::iter::FusedIterator;

// Overflow budget (all values i64; |coord| ≤ 2^28 subpixels, S ≤ 8, clip
// indices in 0..=4096 = 2^12):
// * d = |du| ≤ 2^29 and |e| = |dv| ≤ d (major-axis choice); den = d·2^(S+1)
//   ≤ 2^38, and the per-pixel increment |w| = |e|·2^(S+1) ≤ den.
// * Major indices of the segment satisfy |M| ≤ 2^28 + 1, and their doubled
//   centres C lie between 2ua and 2ub, so |C - 2ua| ≤ 2d ≤ 2^30.
// * n(M) = 2va·d + e·(C - 2ua): |2va·d| ≤ 2^58, |e·(C - 2ua)| ≤ 2^59, so
//   |n| < 2^60.
// * t(k) = k·den - 2va·d + 2e·ua - e·2^S with |k| ≤ 2^12: 2^50 + 2^58 + 2^58
//   + 2^37 < 2^60.
// * Per pixel: r ∈ [0, den) and |w| ≤ den, so r + w ∈ [-2^38, 2^39); pixel
//   indices move by one per step and stay within -1..=4097.
// All comfortably below 2^63. Setup still uses checked operations so that a
// flaw in this argument would show up as a test mismatch, never as a panic.

/// A segment in major/minor terms, normalised so that the major delta is
/// positive (`v = va + e/d · (u - ua)` is the same line either way).
#[derive(Debug, Clone, Copy)]
struct Seg {
    x_major: bool,
    /// True if travel is towards increasing major index.
    forward: bool,
    /// Start point (major, minor) in subpixel units.
    ua: i64,
    va: i64,
    /// |major delta| > 0, and the minor delta times the sign of the major delta.
    d: i64,
    e: i64,
    /// 2^S: half a pixel in doubled units.
    half: i64,
    /// d·2^(S+1): the denominator of the doubled minor coordinate.
    den: i64,
    /// e·2^(S+1): change of its numerator per major index.
    w: i64,
    /// The segment's major indices are `lo..hi` (increasing).
    lo: i64,
    hi: i64,
}

/// `floor(n / q)` and the remainder in `0..q`, for `q > 0`.
fn floor_div(n: i64, q: i64) -> Option<(i64, i64)> {
    Some((n.checked_div_euclid(q)?, n.checked_rem_euclid(q)?))
}

/// `ceil(n / q)` for `q > 0`.
fn ceil_div(n: i64, q: i64) -> Option<i64> {
    floor_div(n.checked_neg()?, q)?.0.checked_neg()
}

impl Seg {
    fn new(ax: i32, ay: i32, bx: i32, by: i32, s: u32) -> Option<Seg> {
        let (ax, ay, bx, by) = (i64::from(ax), i64::from(ay), i64::from(bx), i64::from(by));
        let (dx, dy) = (bx.checked_sub(ax)?, by.checked_sub(ay)?);
        let x_major = dx.checked_abs()? >= dy.checked_abs()?;
        let (ua, va, ub, du, dv) = if x_major { (ax, ay, bx, dx, dy) } else { (ay, ax, by, dy, dx) };
        if du == 0 {
            return None; // zero length (|dv| ≤ |du| = 0)
        }
        let forward = du > 0;
        let (d, e) = if forward { (du, dv) } else { (du.checked_neg()?, dv.checked_neg()?) };
        // Doubled units: the centre of index M is (2M+1)·2^S and a pixel is 2^(S+1).
        // Forward: 2ua ≤ (2M+1)·2^S < 2ub ⇔ ceil((2ua-2^S)/2^(S+1)) ≤ M < ceil((2ub-2^S)/2^(S+1)).
        // Backward: 2ub < (2M+1)·2^S ≤ 2ua ⇔ floor((2ub-2^S)/2^(S+1)) < M ≤ floor((2ua-2^S)/2^(S+1)).
        let half = 1i64.checked_shl(s)?;
        let pix = half.checked_mul(2)?;
        let ka = ua.checked_mul(2)?.checked_sub(half)?;
        let kb = ub.checked_mul(2)?.checked_sub(half)?;
        let (lo, hi) = if forward {
            (ceil_div(ka, pix)?, ceil_div(kb, pix)?)
        } else {
            (floor_div(kb, pix)?.0.checked_add(1)?, floor_div(ka, pix)?.0.checked_add(1)?)
        };
        let (den, w) = (d.checked_mul(pix)?, e.checked_mul(pix)?);
        Some(Seg { x_major, forward, ua, va, d, e, half, den, w, lo, hi })
    }

    /// Minor index at major index `major`, and the remainder of its floor
    /// division: the doubled minor coordinate is n / den with
    /// n = 2va·d + e·((2M+1)·2^S - 2ua).
    fn minor_at(&self, major: i64) -> Option<(i64, i64)> {
        let c = major.checked_mul(2)?.checked_add(1)?.checked_mul(self.half)?;
        let dc = c.checked_sub(self.ua.checked_mul(2)?)?;
        let n = self.va.checked_mul(2)?.checked_mul(self.d)?.checked_add(self.e.checked_mul(dc)?)?;
        floor_div(n, self.den)
    }

    /// The major indices `lo..hi` whose minor index lies in `k0..k1` (a single
    /// interval, because the minor index is monotonic in M).
    fn minor_window(&self, k0: i64, k1: i64) -> Option<(i64, i64)> {
        if self.w == 0 {
            // Constant minor index: everything or nothing.
            let (m, _) = self.minor_at(self.lo)?;
            return Some(if (k0..k1).contains(&m) { (i64::MIN, i64::MAX) } else { (0, 0) });
        }
        // minor(M) ≥ k ⇔ n(M) ≥ k·den ⇔ M·w ≥ t(k) = k·den - 2va·d + 2e·ua - e·2^S.
        // Exact integer division, so no fix-up step is needed.
        let base = (self.e.checked_mul(2)?.checked_mul(self.ua)?)
            .checked_sub(self.va.checked_mul(2)?.checked_mul(self.d)?)?
            .checked_sub(self.e.checked_mul(self.half)?)?;
        let t = |k: i64| k.checked_mul(self.den)?.checked_add(base);
        if self.w > 0 {
            // Minor increases with M: k0 ≤ minor < k1 ⇔ ceil(t(k0)/w) ≤ M < ceil(t(k1)/w).
            Some((ceil_div(t(k0)?, self.w)?, ceil_div(t(k1)?, self.w)?))
        } else {
            // Minor decreases: M·w ≥ t ⇔ M ≤ floor(-t / -w).
            let nw = self.w.checked_neg()?;
            let first = floor_div(t(k1)?.checked_neg()?, nw)?.0.checked_add(1)?;
            let last = floor_div(t(k0)?.checked_neg()?, nw)?.0.checked_add(1)?;
            Some((first, last))
        }
    }
}

/// Iterator over the pixels (x, y) of a line segment, clipped to a
/// [`ClipRect`]; see the [module docs](self) for which pixels.
///
/// Created by [`line_pixels`]. Pixels come in the direction of travel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LinePixels {
    x_major: bool,
    major: i32,
    minor: i32,
    /// +1 or -1 per pixel along the major axis.
    step: i32,
    remaining: u32,
    /// Midpoint decision variable: the implicit line function (scaled by
    /// `den`) at the current pixel's lower boundary, kept in `0..den`. The
    /// boundaries are the midpoints between candidate pixel centres, so the
    /// sign of `r` or `r - den` after a step says which pixel holds the line.
    r: i64,
    /// Change of `r` per major step (`|inc| ≤ den`, so one minor step suffices).
    inc: i64,
    den: i64,
}

impl LinePixels {
    const EMPTY: LinePixels =
        LinePixels { x_major: true, major: 0, minor: 0, step: 1, remaining: 0, r: 0, inc: 0, den: 1 };
}

impl Iterator for LinePixels {
    type Item = (i32, i32);

    fn next(&mut self) -> Option<(i32, i32)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let out = if self.x_major { (self.major, self.minor) } else { (self.minor, self.major) };
        self.major += self.step;
        self.r += self.inc;
        if self.inc >= 0 {
            if self.r >= self.den {
                self.r -= self.den;
                self.minor += 1;
            }
        } else if self.r < 0 {
            self.r += self.den;
            self.minor -= 1;
        }
        Some(out)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.remaining as usize;
        (n, Some(n))
    }
}

impl ExactSizeIterator for LinePixels {}
impl FusedIterator for LinePixels {}

/// Pixels of the segment from `a` to `b`, restricted to `clip`.
///
/// Never panics; an empty clip rectangle, a zero-length segment or a segment
/// that misses `clip` yields nothing. Cost is proportional to the number of
/// visible pixels, however long the segment is.
pub fn line_pixels<const S: u32>(a: SubPoint<S>, b: SubPoint<S>, clip: ClipRect) -> LinePixels {
    build(a.x(), a.y(), b.x(), b.y(), S, clip).unwrap_or(LinePixels::EMPTY)
}

/// Non-generic body of [`line_pixels`] (keeps one copy in the binary).
fn build(ax: i32, ay: i32, bx: i32, by: i32, s: u32, clip: ClipRect) -> Option<LinePixels> {
    if clip.is_empty() {
        return None;
    }
    let seg = Seg::new(ax, ay, bx, by, s)?;
    let (c0, c1, k0, k1) = if seg.x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let (w0, w1) = seg.minor_window(i64::from(k0), i64::from(k1))?;
    let first = seg.lo.max(i64::from(c0)).max(w0);
    let end = seg.hi.min(i64::from(c1)).min(w1);
    if first >= end {
        return None;
    }
    // first..end ⊆ 0..4096, so every index below fits an i32.
    let start = if seg.forward { first } else { end.checked_sub(1)? };
    let (minor, r) = seg.minor_at(start)?;
    let inc = if seg.forward { seg.w } else { seg.w.checked_neg()? };
    Some(LinePixels {
        x_major: seg.x_major,
        major: i32::try_from(start).ok()?,
        minor: i32::try_from(minor).ok()?,
        step: if seg.forward { 1 } else { -1 },
        remaining: u32::try_from(end.checked_sub(first)?).ok()?,
        r,
        inc,
        den: seg.den,
    })
}

/// Inclusive range of pixel rows the segment can touch (`None` if it draws
/// nothing); used by the band renderer to reject a line cheaply.
///
/// The range is exact: it is the smallest and largest row of the unclipped
/// [`line_pixels`] output.
pub fn line_rows<const S: u32>(a: SubPoint<S>, b: SubPoint<S>) -> Option<(i32, i32)> {
    let seg = Seg::new(a.x(), a.y(), b.x(), b.y(), S)?;
    if seg.lo >= seg.hi {
        return None;
    }
    let last = seg.hi.checked_sub(1)?;
    let (r0, r1) = if seg.x_major {
        // Rows are the minor indices, monotonic in M: look at both ends.
        let (m0, _) = seg.minor_at(seg.lo)?;
        let (m1, _) = seg.minor_at(last)?;
        (m0.min(m1), m0.max(m1))
    } else {
        (seg.lo, last)
    };
    Some((i32::try_from(r0).ok()?, i32::try_from(r1).ok()?))
}

#[cfg(test)]
mod tests;
