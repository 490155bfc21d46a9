//! The pixel walk of an anti-aliased line: the segment set-up ([`Seg`]), the
//! clipped per-column iterator [`LineAaPixels`] and [`line_aa_pixels`], split
//! from `line_aa.rs` so the drawable [`LineAa`](super::LineAa) stays short.

use crate::{ClipRect, SubPoint};
use core::iter::FusedIterator;

// Overflow budget (i64; |coordinate| ≤ 2^28 subpixels, S ≤ 8, clip indices
// 0..=4096):
// * d ≤ 2^29, |e| ≤ d, one = 2^S, den = 2d·one ≤ 2^38, |w| = 2|e|·one ≤ den.
// * base = 2va·d + e·(one − 2ua) − d·one: 2^58 + 2^29·(2^29 + 2^8) + 2^37 < 2^60.
// * n(M) = M·w + base for |M| ≤ 2^12 + 1 (clip range only): < 2^51 + 2^60.
// * t(k) = k·den − base for |k| ≤ 2^12 + 1: < 2^51 + 2^60.
// * Per column: rem ∈ [0, den), hi ∈ [0, A]; the exact quotient keeps
//   r ∈ [0, 2den) and steps by 2A·δ with |δ| ≤ den: < 2^48.
// * End columns: 2·rem·G + den < 2^48.

/// A segment normalised to increasing major coordinate.
struct Seg {
    x_major: bool,
    /// Per-column change of the numerator `n`, `2e·2^S`.
    w: i64,
    /// `n(M) = M·w + base`; `n / den` is `v − ½` in pixels at column centre `M + ½`.
    base: i64,
    den: i64,
    /// First and last column touched (inclusive).
    mf: i64,
    ml: i64,
    /// Their overlaps with the segment, in subpixel units (`1..=2^S`).
    ov_f: i64,
    ov_l: i64,
}

/// `(floor(n / q), n mod q)` for `q > 0`.
fn floor_div(n: i64, q: i64) -> Option<(i64, i64)> {
    Some((n.checked_div_euclid(q)?, n.checked_rem_euclid(q)?))
}

fn ceil_div(n: i64, q: i64) -> Option<i64> {
    floor_div(n.checked_neg()?, q)?.0.checked_neg()
}

impl Seg {
    fn new(a: (i32, i32), b: (i32, i32), s: u32) -> Option<Seg> {
        let (ax, ay, bx, by) = (i64::from(a.0), i64::from(a.1), i64::from(b.0), i64::from(b.1));
        let (dx, dy) = (bx.checked_sub(ax)?, by.checked_sub(ay)?);
        let x_major = dx.checked_abs()? >= dy.checked_abs()?;
        let (mut ua, mut va, mut ub, mut vb) = if x_major { (ax, ay, bx, by) } else { (ay, ax, by, bx) };
        if ua > ub {
            core::mem::swap(&mut ua, &mut ub);
            core::mem::swap(&mut va, &mut vb);
        }
        let d = ub.checked_sub(ua)?;
        if d == 0 {
            return None; // zero length
        }
        let e = vb.checked_sub(va)?;
        let one = 1i64.checked_shl(s)?;
        let den = d.checked_mul(2)?.checked_mul(one)?;
        let w = e.checked_mul(2)?.checked_mul(one)?;
        // n(M) = 2va·d + e·((2M+1)·one − 2ua) − d·one = M·w + base.
        let base = va
            .checked_mul(2)?
            .checked_mul(d)?
            .checked_add(e.checked_mul(one.checked_sub(ua.checked_mul(2)?)?)?)?
            .checked_sub(d.checked_mul(one)?)?;
        let mf = floor_div(ua, one)?.0;
        let ml = ceil_div(ub, one)?.checked_sub(1)?;
        let (ov_f, ov_l) = if mf == ml {
            (d, d)
        } else {
            (mf.checked_add(1)?.checked_mul(one)?.checked_sub(ua)?, ub.checked_sub(ml.checked_mul(one)?)?)
        };
        Some(Seg { x_major, w, base, den, mf, ml, ov_f, ov_l })
    }

    /// Columns `lo..hi` whose lower pixel index `j` lies in `k0..=k1` (one
    /// interval: `j` is monotonic in the column).
    fn window(&self, k0: i64, k1: i64) -> Option<(i64, i64)> {
        // j(M) ≥ k ⇔ n(M) ≥ k·den ⇔ M·w ≥ t(k) = k·den − base.
        let t = |k: i64| k.checked_mul(self.den)?.checked_sub(self.base);
        if self.w == 0 {
            let (j, _) = floor_div(self.base, self.den)?;
            return Some(if (k0..=k1).contains(&j) { (i64::MIN, i64::MAX) } else { (0, 0) });
        }
        let k2 = k1.checked_add(1)?;
        if self.w > 0 {
            // k0 ≤ j < k1 + 1 ⇔ ceil(t(k0)/w) ≤ M < ceil(t(k1+1)/w).
            Some((ceil_div(t(k0)?, self.w)?, ceil_div(t(k2)?, self.w)?))
        } else {
            // M·w ≥ t ⇔ M ≤ floor(−t / −w).
            let nw = self.w.checked_neg()?;
            let first = floor_div(t(k2)?.checked_neg()?, nw)?.0.checked_add(1)?;
            let last = floor_div(t(k0)?.checked_neg()?, nw)?.0.checked_add(1)?;
            Some((first, last))
        }
    }
}

/// Iterator over the pixels `(x, y, alpha)` of an anti-aliased line, clipped
/// to a [`ClipRect`]; see the [module docs](crate::line_aa) for the rule. Created by
/// [`line_aa_pixels`]. Pixels come column by column along the major axis in
/// increasing order; alphas are never 0.
#[derive(Debug, Clone)]
pub struct LineAaPixels {
    x_major: bool,
    /// Current and end (exclusive) column.
    major: i32,
    end: i32,
    /// Lower pixel of the current column, and the clip's minor range.
    j: i32,
    k0: i32,
    k1: i32,
    /// `n(M) = j·den + rem`, `0 ≤ rem < den`; `rem` steps by `w`.
    rem: i64,
    w: i64,
    den: i64,
    /// Interior columns: `hi = q` with `2·rem·A + den = q·2den + r`.
    q: i64,
    r: i64,
    /// `2A·δ = step·2den + rstep` for δ = w (no minor step) and for the
    /// δ that also moves `j` (w − den forward, w + den backward).
    step: (i64, i64),
    step_wrap: (i64, i64),
    alpha: u8,
    /// First and last column of the segment and their alphas `G`.
    mf: i64,
    ml: i64,
    g_f: i64,
    g_l: i64,
    pending: Option<(i32, i32, u8)>,
}

impl LineAaPixels {
    const EMPTY: LineAaPixels = LineAaPixels {
        x_major: true,
        major: 0,
        end: 0,
        j: 0,
        k0: 0,
        k1: 0,
        rem: 0,
        w: 0,
        den: 1,
        q: 0,
        r: 0,
        step: (0, 0),
        step_wrap: (0, 0),
        alpha: 0,
        mf: 0,
        ml: 0,
        g_f: 0,
        g_l: 0,
        pending: None,
    };

    /// `(lo, hi)` alphas of the current column.
    fn column(&self) -> (u8, u8) {
        let m = i64::from(self.major);
        let (g, hi) = if m == self.mf || m == self.ml {
            let g = if m == self.mf { self.g_f } else { self.g_l };
            // rem < den ≤ 2^38 and g ≤ 255: no overflow (see the budget above).
            (g, (2 * self.rem * g + self.den) / (2 * self.den))
        } else {
            (i64::from(self.alpha), self.q)
        };
        // 0 ≤ hi ≤ g ≤ 255.
        ((g - hi) as u8, hi as u8)
    }

    fn advance(&mut self) {
        self.major += 1;
        self.rem += self.w;
        let (dq, dr) = if self.w >= 0 && self.rem >= self.den {
            self.rem -= self.den;
            self.j += 1;
            self.step_wrap
        } else if self.rem < 0 {
            self.rem += self.den;
            self.j -= 1;
            self.step_wrap
        } else {
            self.step
        };
        self.q += dq;
        self.r += dr;
        if self.r >= 2 * self.den {
            self.r -= 2 * self.den;
            self.q += 1;
        }
    }

    fn pixel(&self, major: i32, minor: i32, alpha: u8) -> Option<(i32, i32, u8)> {
        if alpha == 0 || minor < self.k0 || minor >= self.k1 {
            return None;
        }
        Some(if self.x_major { (major, minor, alpha) } else { (minor, major, alpha) })
    }
}

impl Iterator for LineAaPixels {
    type Item = (i32, i32, u8);

    fn next(&mut self) -> Option<(i32, i32, u8)> {
        loop {
            if let Some(p) = self.pending.take() {
                return Some(p);
            }
            if self.major >= self.end {
                return None;
            }
            let (lo, hi) = self.column();
            let (m, j) = (self.major, self.j);
            if self.major + 1 < self.end {
                self.advance();
            } else {
                self.major = self.end; // no step past the last visible column
            }
            let upper = j.checked_add(1).and_then(|j1| self.pixel(m, j1, hi));
            match self.pixel(m, j, lo) {
                Some(p) => {
                    self.pending = upper;
                    return Some(p);
                }
                None if upper.is_some() => return upper,
                None => {}
            }
        }
    }
}

impl FusedIterator for LineAaPixels {}

/// The pixels of the anti-aliased segment from `a` to `b` with line alpha
/// `alpha` (255 = opaque), restricted to `clip`, as `(x, y, alpha)`.
///
/// Never panics; a zero-length segment, an empty clip or a zero alpha yields
/// nothing. Cost is proportional to the visible columns.
pub fn line_aa_pixels<const S: u32>(
    a: SubPoint<S>,
    b: SubPoint<S>,
    clip: ClipRect,
    alpha: u8,
) -> LineAaPixels {
    build((a.x(), a.y()), (b.x(), b.y()), S, clip, alpha).unwrap_or(LineAaPixels::EMPTY)
}

/// Non-generic body of [`line_aa_pixels`].
fn build(a: (i32, i32), b: (i32, i32), s: u32, clip: ClipRect, alpha: u8) -> Option<LineAaPixels> {
    if clip.is_empty() || alpha == 0 {
        return None;
    }
    let seg = Seg::new(a, b, s)?;
    let (c0, c1, k0, k1) = if seg.x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    // Pixels j or j + 1 meet k0..k1 ⇔ k0 − 1 ≤ j ≤ k1 − 1.
    let (w0, w1) = seg.window(i64::from(k0) - 1, i64::from(k1) - 1)?;
    let first = seg.mf.max(i64::from(c0)).max(w0);
    let end = seg.ml.checked_add(1)?.min(i64::from(c1)).min(w1);
    if first >= end {
        return None;
    }
    // first..end ⊆ 0..4096 and j ∈ k0 − 1..k1: every index fits an i32.
    let n = first.checked_mul(seg.w)?.checked_add(seg.base)?;
    let (j, rem) = floor_div(n, seg.den)?;
    let a2 = 2 * i64::from(alpha);
    let d2 = seg.den.checked_mul(2)?;
    let (q, r) = floor_div(rem.checked_mul(a2)?.checked_add(seg.den)?, d2)?;
    let wrap = if seg.w >= 0 { seg.w.checked_sub(seg.den)? } else { seg.w.checked_add(seg.den)? };
    let one = 1i64 << s;
    let g = |ov: i64| -> Option<i64> { Some(ov.checked_mul(a2)?.checked_add(one)? / (2 * one)) };
    Some(LineAaPixels {
        x_major: seg.x_major,
        major: i32::try_from(first).ok()?,
        end: i32::try_from(end).ok()?,
        j: i32::try_from(j).ok()?,
        k0,
        k1,
        rem,
        w: seg.w,
        den: seg.den,
        q,
        r,
        step: floor_div(seg.w.checked_mul(a2)?, d2)?,
        step_wrap: floor_div(wrap.checked_mul(a2)?, d2)?,
        alpha,
        mf: seg.mf,
        ml: seg.ml,
        g_f: g(seg.ov_f)?,
        g_l: g(seg.ov_l)?,
        pending: None,
    })
}
