//! The band test of the vertex stage: which vertices and triangles lie
//! certainly above or below the rows being drawn, in clip space.

use super::{Pipeline, row_f32};
use crate::math::{Mat4, Scalar, Vec4};

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// The clip-space test of [`Pipeline::rows`] ([`Band`]).
    pub(super) fn band_bounds(&self) -> Band<T> {
        let Some((y0, y1)) = self.rows else { return Band::all() };
        let (h, oy) = (self.size.1 as f32, self.origin.1);
        // Pixel row `r` lies at NDC y = 1 − 2·(r − oy)/h (y flipped). The
        // bounds are used only where they are small, so their Fx rounding
        // (2^-17) stays far below the margin.
        let k = |row: i64| {
            let k = 1.0 - 2.0 * ((row - oy) as f32) / h;
            if k.abs() <= 4.0 { Some(T::from_f32(k)) } else { None }
        };
        Band::new(k(y0 as i64 - 1), k(y1 as i64 + 2), T::from_f32(0.125))
    }
}

/// The rows of [`Pipeline::rows`] as a division-free test in clip space,
/// with a margin of a pixel above and two below the band (so the snapping
/// of the exact test cannot disagree).
///
/// A vertex with `w > 0` lies above pixel row `y0 − 1` when `y > above·w`
/// and below row `y1 + 2` when `y < below·w`. A triangle is dropped early
/// only if all three vertices have `w ≥ w_min` (1/8) and all lie on the same
/// side. Error: `above`/`below` are within 2^-17 of the exact NDC bound
/// (Fx rounding; f32 within 2^-21) and `k·w` is within 2^-16 (Fx truncation;
/// f32 relative 2^-24), so the test is off by at most `2^-17 + 2^-16/w ≤
/// 2^-12.9` in NDC, that is below 0.06 px for any viewport height up to
/// [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM), against a margin of a pixel; the snapped position
/// rounds by at most half a subpixel. So a triangle dropped here has no row
/// in the band, exactly as the test after snapping would find. (With `y`
/// and `w` as evaluated: clipping only moves vertices along the triangle, a
/// convex combination that stays on the same side.)
#[derive(Clone, Copy)]
pub(crate) struct Band<T> {
    pub(super) above: Option<T>,
    pub(super) below: Option<T>,
    pub(super) w_min: T,
    /// `above` and `below` as `f32` bounds that a missing side turns into
    /// ±∞, which no `y` passes (not read for `Fx`, which has no infinity).
    bounds: (T, T),
}

impl<T: Scalar> Band<T> {
    /// No band: every triangle passes.
    pub(super) fn all() -> Self {
        Band::new(None, None, T::ZERO)
    }

    pub(super) fn new(above: Option<T>, below: Option<T>, w_min: T) -> Self {
        let bounds =
            (above.unwrap_or(T::from_f32(f32::INFINITY)), below.unwrap_or(T::from_f32(f32::NEG_INFINITY)));
        Band { above, below, w_min, bounds }
    }

    /// [`Band::excludes`] per vertex: `ABOVE` or `BELOW` if the vertex has
    /// `w ≥ w_min` and lies on that side; a triangle whose three vertices
    /// share a bit is excluded.
    pub(super) const ABOVE: u8 = 1 << 6;
    pub(super) const BELOW: u8 = 1 << 7;

    #[inline]
    pub(super) fn side(&self, (y, w): (T, T)) -> u8 {
        if w < self.w_min {
            return 0;
        }
        let (above, below) = if crate::math::vec::is_float::<T>() {
            // With `w ≥ w_min ≥ 0`, ±∞·w is ±∞, or NaN where `w` is 0 or
            // NaN: no `y` passes either, so a missing side needs no branch
            // (the `y`/`w` pass runs this for every vertex of every cluster
            // visit; tested against the `Option` form).
            (y > self.bounds.0 * w, y < self.bounds.1 * w)
        } else {
            (self.above.is_some_and(|k| y > k * w), self.below.is_some_and(|k| y < k * w))
        };
        (if above { Self::ABOVE } else { 0 }) | (if below { Self::BELOW } else { 0 })
    }

    /// True if the triangle (clip `(y, w)` of its vertices) is certainly
    /// outside the band.
    #[inline]
    pub(super) fn excludes(&self, yw: [(T, T); 3]) -> bool {
        if self.above.is_none() && self.below.is_none() {
            return false;
        }
        if !yw.iter().all(|&(_, w)| w >= self.w_min) {
            return false;
        }
        let above = self.above.is_some_and(|k| yw.iter().all(|&(y, w)| y > k * w));
        above || self.below.is_some_and(|k| yw.iter().all(|&(y, w)| y < k * w))
    }

    /// False if the mesh's bounding sphere lies entirely above or below the
    /// band (planes `above·w − y ≥ 0` and `y − below·w ≥ 0`), with a slack of
    /// `2^-8·(1 + r·|plane|)` in clip units for the rounding of the test.
    ///
    /// Evaluated in `f32` on both paths (bit-identical for `f32`): in `Fx`
    /// `plane · centre` and `r·|plane|` both saturate for a large sphere
    /// (a far vertex, a narrow field of view), and the saturated test
    /// rejected visible meshes (issue 13). `f32` rounding (relative 2^-22
    /// here) is far inside the slack.
    pub(super) fn sphere_touches(&self, mvp: &Mat4<T>, (c, r): ([f32; 3], f32)) -> bool {
        let (y, w) = (row_f32(mvp, 1), row_f32(mvp, 3));
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        let slack = 1.0f32 / 256.0;
        let outside = |p: Vec4<f32>| {
            let reach = r * p.xyz().length();
            p.dot(centre) < -(reach + reach * slack + slack)
        };
        let k = |k: T| k.to_f32();
        !(self.above.is_some_and(|a| outside(w * k(a) - y))
            || self.below.is_some_and(|b| outside(y - w * k(b))))
    }
}

#[cfg(test)]
mod tests {
    use super::Band;

    /// `Band::side` in `f32`, where a missing side is an infinite bound, is
    /// the test of the type's docs (a side that is `None` never holds), at
    /// zero, infinite and NaN `y` and `w` too, for every set of sides.
    #[test]
    fn band_side_with_infinite_bounds_is_the_option_test() {
        let reference = |b: &Band<f32>, (y, w): (f32, f32)| -> u8 {
            if w < b.w_min {
                return 0;
            }
            let above = b.above.is_some_and(|k| y > k * w);
            let below = b.below.is_some_and(|k| y < k * w);
            (if above { Band::<f32>::ABOVE } else { 0 }) | (if below { Band::<f32>::BELOW } else { 0 })
        };
        let values = [
            f32::NEG_INFINITY,
            -1e30,
            -3.0,
            -0.5,
            -0.0,
            0.0,
            1e-30,
            0.125,
            0.3,
            0.5,
            1.0,
            2.0,
            1e30,
            f32::INFINITY,
            f32::NAN,
        ];
        let bands = [
            Band::all(),
            Band::new(None, None, 0.125),
            Band::new(Some(0.5), None, 0.125),
            Band::new(None, Some(-0.25), 0.125),
            Band::new(Some(0.5), Some(-0.25), 0.125),
            Band::new(Some(-4.0), Some(4.0), 0.125),
        ];
        let mut sides = 0;
        for b in &bands {
            for &y in &values {
                for &w in &values {
                    let got = b.side((y, w));
                    assert_eq!(got, reference(b, (y, w)), "y {y}, w {w}");
                    sides += (got != 0) as u32;
                }
            }
        }
        // Both sides and neither occur.
        assert!(sides > 100, "{sides}");
    }
}
