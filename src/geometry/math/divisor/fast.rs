//! The fast tier's quotients ([`Precision::Fast`](crate::raster3d::Precision)):
//! `round(n / d · scale)` from one reciprocal and multiplications, within
//! one unit of the exact quotient ([`Scalar::div_scaled_by`](super::super::Scalar::div_scaled_by))
//! where snapping meets them, instead of a correctly rounded result.
//!
//! * `f32`: `(n · fl(1/d)) · scale`, rounded to nearest. Against the exact
//!   tier's `fl(fl(n/d) · scale)` the two products carry five roundings of
//!   `2^-24` relative between them: below `|q| ≤ 2^21` they differ by less
//!   than `5·2^-24·(2^21 + 1/2) < 0.63`, so the rounded integers by at most
//!   one. The reciprocal is shared by a vertex's quotients (the compiler
//!   keeps one `VDIV`).
//! * [`FxDivisor`]: the estimate `⌊M·(2^32 + v)/2^64⌋` of the normalised
//!   numerator `M` with the divisor's reciprocal word `v`, computed from
//!   two 32×32 products without the exact correction steps: never above the
//!   exact quotient, and below it by at most one while it is under `2^30`
//!   (the reciprocal is within one unit of `2^64/D`, so the estimate is
//!   short by less than `(q + 1)/2^32`, plus the dropped low word's
//!   `2^-32`). On the Cortex-M0, whose wide products are library-like
//!   sequences, the exact quotient is cheaper and is used.

use super::FxDivisor;
use super::m0_arith::{ARMV6M, mul_wide_u32, mul_wide_u32_by};

/// A prepared divisor's fast quotient (sealed: `f32` and [`FxDivisor`]).
#[doc(hidden)]
pub trait FastQuotient<N>: Copy {
    /// `round(n / self · scale)` within one unit of the exact tier's quotient
    /// for results below `2^21` in magnitude (module docs; within a few
    /// units, `f32` within `5·2^-24` relative, beyond), or `None` where the
    /// exact quotient is `None` or the caller should take it instead.
    fn quotient_fast(self, n: N, scale: i64) -> Option<i64>;
}

impl FastQuotient<f32> for f32 {
    #[inline]
    fn quotient_fast(self, n: f32, scale: i64) -> Option<i64> {
        // Snapping's and depth's scales are u32; others are the exact path's.
        let s = u32::try_from(scale).ok()? as f32;
        let v = n * (1.0 / self) * s;
        // As the exact quotient: NaN and beyond 2^40 (infinity too) fail.
        if v.is_nan() || v.abs() > (1u64 << 40) as f32 {
            return None;
        }
        Some(super::round_even_f32(v))
    }
}

#[cfg(feature = "fx")]
impl FastQuotient<crate::math::Fx> for FxDivisor {
    #[inline]
    fn quotient_fast(self, n: crate::math::Fx, scale: i64) -> Option<i64> {
        let sa = u32::try_from(scale.unsigned_abs()).ok()?;
        let m = mul_wide_u32_by(sa, n.to_bits().unsigned_abs());
        let q = self.div_round_fast(m)? as i64;
        Some(if (n.to_bits() < 0) != (scale < 0) { -q } else { q })
    }
}

impl FxDivisor {
    /// [`FxDivisor::div_round`] within one below for quotients under
    /// `2^30`, never above (module docs); `None` where that is `None`.
    #[inline]
    pub(crate) fn div_round_fast(&self, m: u64) -> Option<u32> {
        if ARMV6M {
            return self.div_round(m);
        }
        let (d, sh, v) = self.parts();
        let m = m + (d / 2) as u64;
        if (m >> 32) >= d as u64 {
            return None;
        }
        // (u1, u0) = m·2^sh < 2^64 (the quotient fits 32 bits).
        let mm = if sh == 0 { m } else { m << sh };
        let (u1, u0) = ((mm >> 32) as u32, mm as u32);
        // M·(2^32 + v)/2^64 = u1 + (u0 + u1·v + u0·v/2^32)/2^32; the sum
        // below is under 2^64 (u1 < 2^32 − 1, v < 2^32).
        let a = mul_wide_u32(u1, v) + u64::from(u0) + (mul_wide_u32(u0, v) >> 32);
        Some(u1 + (a >> 32) as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Fx, Scalar};

    /// Fast quotients against the exact ones: never more than one apart
    /// below 2^21 (both types), and `Fx` never above; ties included.
    #[test]
    fn fast_quotients_within_one_of_exact() {
        let mut rng = crate::math::vec::tests::Rng(0xFA57_0001);
        let (mut off, mut n) = (0u32, 0u32);
        for i in 0..400_000u32 {
            let w = rng.range(1e-3, 200.0);
            let x = rng.range(-1.0, 1.0) * w * [1.0, 20.0, 4000.0][i as usize % 3];
            let scale = [2560i64, 1920, 1 << 30, u32::MAX as i64, 40960][i as usize % 5];
            if let (Some(e), Some(f)) =
                (x.div_scaled(w, scale), w.divisor().and_then(|d| d.quotient_fast(x, scale)))
            {
                if e.abs() <= 1 << 21 {
                    assert!((e - f).abs() <= 1, "f32 {x}/{w}·{scale}: {e} vs {f}");
                    off += u32::from(e != f);
                    n += 1;
                } else {
                    assert!((e - f).abs() as f64 <= 5.0 * (e.abs() as f64) / 16_777_216.0 + 1.0);
                }
            }
            let (fx, fw) = (Fx::from_f32(x.clamp(-30000.0, 30000.0)), Fx::from_f32(w.max(0.01)));
            let d = fw.divisor().unwrap();
            if let Some(e) = fx.div_scaled_by(d, scale) {
                let f = d.quotient_fast(fx, scale).unwrap_or(e);
                let lim = if e.abs() < 1 << 30 { 1 } else { 2 };
                assert!((e - f).abs() <= lim && f.abs() <= e.abs(), "Fx {fx:?}/{fw:?}·{scale}: {e} vs {f}");
            }
        }
        // Not vacuous: the fast quotients do differ, rarely.
        assert!(n > 100_000 && off > 0 && off < n / 10, "{off} of {n}");
    }

    /// Exact divisions (`n/d` an integer plus a half: the rounding's ties)
    /// are where the `Fx` estimate falls one short.
    #[test]
    fn fx_ties_fall_at_most_one_short() {
        for d in [3i32, 65536, 65537, 99_999, 1 << 20, (1 << 30) + 7] {
            let div = FxDivisor::new(d).unwrap();
            for k in [0u64, 1, 2, 1000, 123_456, (1 << 21) - 1] {
                let m = k * d as u64 + (d as u64) / 2;
                let e = div.div_round(m).unwrap();
                let f = div.div_round_fast(m).unwrap();
                assert!(e - f <= 1, "{d} {k}: {e} {f}");
            }
        }
    }
}
