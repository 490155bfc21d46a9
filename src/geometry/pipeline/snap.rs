//! Snapping: clip space to the rasterizer's fixed-point screen positions,
//! depth and `1/w`, and the snapped-area tests (zero area, back faces,
//! rows) that decide which triangles go on.

use super::tier::Tier;
use super::{MeshStats, Pipeline};
use crate::SubPoint;
use crate::edge::Cull;
use crate::math::Scalar;
use crate::math::divisor::FastQuotient;
use crate::primitive::center_rows;
use crate::raster3d::ScreenVertex;

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// Snapped positions of a triangle inside the clip volume, if it passes
    /// [`Pipeline::keep`]; a triangle that cannot be snapped counts as
    /// degenerate.
    pub(super) fn snapped_and_kept<R: Tier>(
        &self,
        clip: [[T; 4]; 3],
        stats: &mut MeshStats,
    ) -> Option<[ScreenVertex<S>; 3]> {
        let Some(at) = self.snap_positions::<R>(clip) else {
            stats.degenerate += 1;
            return None;
        };
        self.keep(at.map(|v| v.pos), stats).then_some(at)
    }

    /// Clip space to snapped screen positions, depth and `1/w` (colour left
    /// 0); `None` if a coordinate is out of the rasterizer's range (the guard
    /// band prevents this) or not finite.
    pub(super) fn snap_positions<R: Tier>(&self, clip: [[T; 4]; 3]) -> Option<[ScreenVertex<S>; 3]> {
        let mut out = [ScreenVertex::default(); 3];
        for (o, c) in out.iter_mut().zip(clip) {
            *o = self.snap_vertex::<R>(c)?;
        }
        Some(out)
    }

    /// One vertex of [`Pipeline::snap_positions`].
    /// `w` is prepared once for the four quotients ([`Scalar::divisor`]:
    /// for [`Fx`](crate::math::Fx) one reciprocal, each quotient still exact;
    /// in the fast tier, `tier`'s quotients).
    pub(super) fn snap_vertex<R: Tier>(&self, c: [T; 4]) -> Option<ScreenVertex<S>> {
        let w = c[3].divisor()?;
        let (depth, inv_w) = self.snap_depth::<R>(c, w)?;
        Some(ScreenVertex { pos: self.snap_xy::<R>(c, w)?, depth, inv_w, color: [0; 3] })
    }

    /// The snapped position of [`Pipeline::snap_vertex`] (all that culling
    /// needs).
    #[inline]
    pub(super) fn snap_xy<R: Tier>(&self, [x, y, _, _]: [T; 4], w: T::Divisor) -> Option<SubPoint<S>> {
        let px = self.ndc_to_sub::<R>(x, w, self.size.0, self.origin.0, false)?;
        let py = self.ndc_to_sub::<R>(y, w, self.size.1, self.origin.1, true)?;
        SubPoint::new(i32::try_from(px).ok()?, i32::try_from(py).ok()?).ok()
    }

    /// The depth and `1/w` of [`Pipeline::snap_vertex`]; `None` only for a
    /// `z` that is not finite.
    ///
    /// A depth `z/w` beyond `[0, 1]` is clamped to it. That happens only
    /// with the far plane off (`ClipPlanes::with_far`): a vertex beyond it
    /// gets the farthest depth. The quotient's range ends at `|z/w| = 2^8`
    /// ([`Scalar::div_scaled_by`]); beyond it the depth saturates the same
    /// way instead of failing, which dropped the vertex's triangles (an
    /// orthographic lens with the far plane off lost geometry `2^8` times
    /// its depth range away; found by the `closed` fuzz target).
    #[inline]
    pub(super) fn snap_depth<R: Tier>(&self, [_, _, z, _]: [T; 4], w: T::Divisor) -> Option<(u32, u32)> {
        // The fast tier's quotients where they exist, else the exact ones.
        let fast = |n: T, scale: i64| if R::FAST { w.quotient_fast(n, scale) } else { None };
        let depth = match fast(z, u32::MAX as i64).or_else(|| z.div_scaled_by(w, u32::MAX as i64)) {
            Some(d) => d.clamp(0, u32::MAX as i64) as u32,
            None => saturated_depth(z)?,
        };
        Some((
            depth,
            // Only ratios of 1/w matter; a vertex nearer than w_ref/4 (which
            // the w_ref contract excludes) saturates rather than vanishing.
            if self.with_inv_w {
                fast(self.w_ref, 1 << 30)
                    .or_else(|| self.w_ref.div_scaled_by(w, 1 << 30))
                    .unwrap_or(i64::MAX)
                    .clamp(1, u32::MAX as i64) as u32
            } else {
                1
            },
        ))
    }

    /// The snapped-area tests on a triangle's snapped positions: zero area
    /// and back faces are dropped (and counted), as are triangles outside
    /// [`Pipeline::rows`]. In 32-bit differences (`|coordinate| ≤ 2^28`, so
    /// they cannot overflow) and 64-bit products; the rows as
    /// [`ScreenTriangle::rows`](crate::raster3d::ScreenTriangle::rows) computes them.
    #[inline]
    pub(super) fn keep(&self, p: [SubPoint<S>; 3], stats: &mut MeshStats) -> bool {
        let (e1x, e1y) = (p[1].x() - p[0].x(), p[1].y() - p[0].y());
        let (e2x, e2y) = (p[2].x() - p[0].x(), p[2].y() - p[0].y());
        let det = signed_area2(e1x, e1y, e2x, e2y);
        if det == 0 {
            stats.degenerate += 1;
            return false;
        }
        let culled = match self.cull {
            Cull::None => false,
            Cull::Clockwise => det > 0,
            Cull::CounterClockwise => det < 0,
        };
        if culled {
            stats.back_faces += 1;
            return false;
        }
        let (y0, y1, y2) = (p[0].y(), p[1].y(), p[2].y());
        let (lo, hi) = center_rows::<S>(y0.min(y1).min(y2), y0.max(y1).max(y2));
        self.rows.is_none_or(|(r0, r1)| lo <= r1 && hi >= r0)
    }

    /// `origin + (1 ± ndc)·size/2` in subpixels, `ndc = c/w` (y flipped).
    /// The fast tier takes its quotient ([`FastQuotient`]) where the extent
    /// is even and the quotient within [`FAST_SNAP_MAX`]: within one
    /// subpixel of the exact one, and the same value whichever route snaps
    /// the vertex (`PreSnap` computes it bit for bit).
    pub(super) fn ndc_to_sub<R: Tier>(
        &self,
        c: T,
        w: T::Divisor,
        size: u32,
        origin: i64,
        flip: bool,
    ) -> Option<i64> {
        let full = (size as i64) << S; // viewport extent in subpixels
        let c = if flip { -c } else { c };
        if R::FAST && full % 2 == 0 {
            if let Some(t) = w.quotient_fast(c, full / 2).filter(|t| t.abs() <= FAST_SNAP_MAX) {
                return Some((origin << S) + full / 2 + t);
            }
        }
        // Halve exactly when possible; only S = 0 with an odd size rounds twice.
        let t =
            if full % 2 == 0 { c.div_scaled_by(w, full / 2)? } else { (c.div_scaled_by(w, full)? + 1) >> 1 };
        Some((origin << S) + full / 2 + t)
    }
}

/// The largest snapped offset from the viewport's centre (subpixels) that
/// the fast tier takes from its fast quotient; beyond it (a guard band
/// wider than the default's), the exact quotient
/// (`divisor::fast`: the within-one bound of `f32` holds below `2^21`).
pub(super) const FAST_SNAP_MAX: i64 = 1 << 21;

/// `e1x·e2y − e2x·e1y` exactly, for differences of snapped coordinates
/// (`|e| ≤ 2^29`). On the Cortex-M0, where a 64-bit product is a library
/// call, in 32 bits when every difference is below 2^15 (products below
/// 2^30, their difference below 2^31): a small triangle's, most of a mesh's.
#[inline(always)]
pub(super) fn signed_area2(e1x: i32, e1y: i32, e2x: i32, e2y: i32) -> i64 {
    if crate::math::divisor::ARMV6M {
        if let Some(det) = signed_area2_small(e1x, e1y, e2x, e2y) {
            return det;
        }
    }
    i64::from(e1x) * i64::from(e2y) - i64::from(e2x) * i64::from(e1y)
}

/// [`signed_area2`] in 32 bits where every difference is below 2^15
/// (tested on every target).
#[inline(always)]
pub(super) fn signed_area2_small(e1x: i32, e1y: i32, e2x: i32, e2y: i32) -> Option<i64> {
    let small = |v: i32| v.unsigned_abs() < 1 << 15;
    (small(e1x) && small(e1y) && small(e2x) && small(e2y)).then(|| i64::from(e1x * e2y - e2x * e1y))
}

/// The depth of a vertex whose `z/w` is beyond the quotient's range
/// ([`Pipeline::snap_depth`]): saturated as the clamp to `[0, 1]` would,
/// `None` for a `z` that is not finite. Out of line and cold: only a lens
/// without the far plane gets here.
#[cold]
#[inline(never)]
fn saturated_depth<T: Scalar>(z: T) -> Option<u32> {
    z.is_finite().then_some(if z > T::ZERO { u32::MAX } else { 0 })
}

#[cfg(test)]
mod tests {
    /// The 32-bit area of small differences is the 64-bit one, and larger
    /// differences are left to it.
    #[test]
    fn small_area_is_the_wide_area() {
        let mut rng = crate::math::vec::tests::Rng(0xA2EA);
        let mut small = 0;
        for i in 0..200_000u32 {
            let e = [0; 4].map(|_| (rng.next() as i32) >> (2 + i % 20));
            let wide = i64::from(e[0]) * i64::from(e[3]) - i64::from(e[2]) * i64::from(e[1]);
            match super::signed_area2_small(e[0], e[1], e[2], e[3]) {
                Some(det) => {
                    assert_eq!(det, wide, "{e:?}");
                    small += 1;
                }
                None => assert!(e.iter().any(|v| v.unsigned_abs() >= 1 << 15), "{e:?}"),
            }
            assert_eq!(super::signed_area2(e[0], e[1], e[2], e[3]), wide, "{e:?}");
        }
        assert!(small > 50_000, "{small}");
        let max = (1 << 15) - 1;
        assert_eq!(super::signed_area2_small(max, -max, max, max), Some(2 * max as i64 * max as i64));
    }
}
