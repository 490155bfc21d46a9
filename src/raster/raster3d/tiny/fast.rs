//! The colour of a tiny triangle in the fast tier
//! ([`Precision::Fast`](crate::raster3d::Precision)): the same coverage and
//! depth formula as the exact tier's (the parent module), with the colour
//! chosen once per triangle instead of divided out at each pixel.
//!
//! The depth's vertex values come from `depth_steps_approx` (two shifts):
//! within one unit of `2^-8` steps of the exact tier's, so each stored code
//! is within one of the exact tier's.
//!
//! # What is computed, and its error
//! At a covered centre the weights `w_i` (unbiased edge functions, summing
//! to `det < 2^16`) give a channel `V = Σ w_i·c_i / det`, which the exact
//! tier rounds half up exactly; that rounding lies in the vertex values'
//! range `[c_min, c_max]` (a convex combination), as does the exact tier's
//! perspective-correct one.
//!
//! * A triangle whose vertex values lie within 2 of each other in every
//!   channel (most of a lit mesh's tiny triangles) is the middle of each
//!   range at every pixel: within one of the exact tier's channel.
//! * Otherwise each `c_i / det` is prepared once as a whole
//!   `K_i = round(c_i·2^23 / det)`, and a channel is
//!   `(w_1·(K_1 − K_0) + w_2·(K_2 − K_0) + det·K_0 + 2^22) >> 23`
//!   (`w_0 = det − w_1 − w_2`; exact modulo 2^32, and the true sum is below
//!   `2^31`): `Σ w_i·K_i` is `V·2^23` within `Σ w_i/2 = det/2 < 2^15`, so
//!   the result is `V` within `2^-8` rounded half up, within one of the
//!   exact tier's. Two multiply-adds and a shift per channel.
//! * Perspective-correct: where the vertices' `1/w` differ so little that
//!   the screen-linear value is within `Δ ≤ 1/2` of the perspective-correct
//!   one (`perspective`'s bound), the screen-linear weights above (within
//!   `1/2 + 2^-8 < 1` before rounding, so within one); otherwise the exact
//!   tier's own perspective-correct colour.

use super::super::{Interpolation, ScreenTriangle};
use super::perspective::{PerspFactors, shade_perspective};
use crate::Interpolate;

/// Scale of the colour weights: a channel of up to 255 times `2^23`, plus
/// the rounding, stays below `2^31`.
const SHIFT: u32 = 23;

/// A channel of the triangle as `(w_1·a + w_2·b + c) >> SHIFT` at weights
/// `w` (module docs; `c` holds `det·K_0` and the rounding).
#[derive(Clone, Copy)]
pub(super) struct Weighted {
    a: u32,
    b: u32,
    c: u32,
}

impl Weighted {
    /// The weights of vertex channels `v` (each at most 255) for a triangle
    /// of determinant `det` (`0 < det < 2^16`).
    #[inline(always)]
    fn new(v: [u8; 3], det: u32) -> Self {
        // v·2^23 + det/2 < 2^31: one 32-bit division each.
        let k = v.map(|v| ((u32::from(v) << SHIFT) + det / 2) / det);
        let (a, b) = (k[1].wrapping_sub(k[0]), k[2].wrapping_sub(k[0]));
        Weighted { a, b, c: det.wrapping_mul(k[0]).wrapping_add(1 << (SHIFT - 1)) }
    }

    #[inline(always)]
    fn channel(&self, w: [u32; 3]) -> u8 {
        (w[1].wrapping_mul(self.a).wrapping_add(w[2].wrapping_mul(self.b)).wrapping_add(self.c) >> SHIFT)
            as u8
    }
}

/// The fast tier's colour of one tiny triangle (module docs).
pub(super) enum FastShade<C> {
    /// One colour at every pixel: flat, or every channel within 2.
    Const(C),
    /// Screen-linear weights per channel (`None` for a channel the colour
    /// type lacks).
    Linear([Option<Weighted>; 3]),
    /// The exact tier's perspective-correct colour.
    Perspective(PerspFactors),
}

impl<C: Interpolate> FastShade<C> {
    /// The colour of `tri` (twice its area `det`), interpolated as `M` says.
    /// Out of line: made once per drawn triangle.
    #[inline(never)]
    pub(super) fn new<M: Interpolation, const S: u32>(tri: &ScreenTriangle<S>, det: u32) -> Self {
        if tri.flat {
            return FastShade::Const(C::from_channels(tri.v[0].color));
        }
        let max = C::CHANNEL_MAX;
        let (mut mid, mut spread) = ([0u8; 3], 0u8);
        for k in 0..3 {
            let c = tri.v.map(|v| v.color[k]);
            let (lo, hi) = (c[0].min(c[1]).min(c[2]), c[0].max(c[1]).max(c[2]));
            mid[k] = lo + (hi - lo) / 2;
            if max[k] > 0 {
                spread = spread.max(hi - lo);
            }
        }
        if spread <= 2 {
            return FastShade::Const(C::from_channels(mid));
        }
        if M::PERSPECTIVE {
            // Δ = spread/2 · (a_max − a_min)/a_min ≤ 1/2 on the 1/w as
            // given (only their ratios enter; `perspective`'s bound).
            let a = tri.v.map(|v| u64::from(v.inv_w));
            let (a_min, a_max) = (a[0].min(a[1]).min(a[2]), a[0].max(a[1]).max(a[2]));
            if u64::from(spread) * (a_max - a_min) > a_min {
                return FastShade::Perspective(PerspFactors::new::<C, S>(tri, det));
            }
        }
        let weights = |k: usize| (max[k] > 0).then(|| Weighted::new(tri.v.map(|v| v.color[k]), det));
        FastShade::Linear([weights(0), weights(1), weights(2)])
    }

    /// The colour at weights `w` (summing to `det`).
    #[inline(always)]
    pub(super) fn at<const S: u32>(&self, tri: &ScreenTriangle<S>, w: [u32; 3], det: u32) -> C {
        match self {
            FastShade::Const(c) => *c,
            FastShade::Linear(k) => {
                C::from_channels([0, 1, 2].map(|i| k[i].as_ref().map_or(0, |k| k.channel(w))))
            }
            FastShade::Perspective(f) => shade_perspective::<C, S>(tri, f, w, det),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::next;
    use super::Weighted;

    /// A channel from the weights is the exact value `Σ w_i·c_i / det`
    /// within `2^-8`, rounded half up (module docs): for determinants up to
    /// the tiny path's limit, every split of the weights and channels up to
    /// 255, it lies between the roundings of `V − 2^-8` and `V + 2^-8`,
    /// and equals the exact rounding away from those near a tie.
    #[test]
    fn weighted_channel_is_the_value_within_its_bound() {
        let mut seed = 0x00FA_5700_C010_u64;
        let (mut off_tie, mut near_tie) = (0u32, 0u32);
        for i in 0..1_000_000u32 {
            let det = [(next(&mut seed) >> 48) as u32 % 0xFFFF + 1, 1 + i % 40, 0xFFFF][(i % 3) as usize];
            let a = (next(&mut seed) >> 40) as u32 % (det + 1);
            let b = (next(&mut seed) >> 40) as u32 % (det - a + 1);
            let w = [[det - a - b, a, b], [det, 0, 0], [0, det - a, a]][(i / 3 % 3) as usize];
            let r = next(&mut seed);
            let c = [0u32, 1, 2].map(|k| {
                [(r >> (8 * k)) as u8, 255, 0, (r >> (8 * k + 24)) as u8][((r >> (50 + 2 * k)) % 4) as usize]
            });
            let got = u64::from(Weighted::new(c, det).channel(w));
            // X = 2^8·2·det·V, so V ∓ 2^-8 is X ∓ 2·det, each rounded half up.
            let v = 2 * (0..3).map(|k| u64::from(w[k]) * u64::from(c[k])).sum::<u64>();
            let (d2, x) = (2 * u64::from(det), v << 8);
            let round = |x: u64| (x + (d2 << 7)) / (d2 << 8);
            let (lo, hi) = (round(x.saturating_sub(d2)), round(x + d2));
            assert!(lo <= got && got <= hi, "{c:?} {w:?} det {det}: {got} not in {lo}..={hi}");
            if lo == hi {
                assert_eq!(got, (v + u64::from(det)) / d2, "{c:?} {w:?} det {det}");
                off_tie += 1;
            } else {
                near_tie += 1;
            }
        }
        assert!(off_tie > 900_000 && near_tie > 0, "{off_tie} {near_tie}");
    }
}
