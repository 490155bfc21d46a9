//! One divisor, several quotients: the perspective divide of a vertex
//! ([`Scalar::divisor`](super::Scalar::divisor) and
//! [`Scalar::div_scaled_by`](super::Scalar::div_scaled_by)).
//!
//! A snapped vertex needs `x/w`, `y/w`, `z/w` and `w_ref/w`, each scaled and
//! rounded to an integer. [`Fx`](super::Fx) prepares `w` once (normalised,
//! with a 32-bit reciprocal) and then divides each numerator by one
//! 32×32→64-bit multiply, one 32-bit multiply and at most two corrections
//! (Möller and Granlund, "Improved division by invariant integers", 2011,
//! algorithm 4): the quotient is *exact*, bit-identical to
//! [`Scalar::div_scaled`](super::Scalar::div_scaled), with no 64-bit division
//! (a library call on Cortex-M, and a 32-step loop on the Cortex-M0).
//!
//! `f32` keeps one correctly rounded division per numerator (one instruction
//! with an FPU; a reciprocal shared by the four would change the rounding of
//! `x/w` and so the snapped positions) and rounds to an integer with the
//! `2^23` trick instead of branches on the fraction: the same result.

mod fast;
mod fx_divisor;
mod m0_arith;
mod small;

#[doc(hidden)]
pub use fast::FastQuotient;
pub use fx_divisor::FxDivisor;
pub(crate) use m0_arith::{
    ARMV6M, divrem_small_quotient, leading_zeros_u32, mul_u16_u32, mul_wide_u32, mul_wide_u32_by,
};
pub(crate) use small::SmallDivisor;

/// `2^23`: from here on every `f32` is an integer.
pub(crate) const TWO23: f32 = 8_388_608.0;

/// `a` rounded to the nearest integer, ties to even, for `0 ≤ a < 2^23`
/// (else unspecified): `a + 2^23` lies in `[2^23, 2^24)`, where `f32` steps
/// by 1, so the addition rounds `a` (IEEE, to nearest even, on every
/// target) and the subtraction is exact. Two additions and a conversion.
#[inline(always)]
pub(crate) fn round_even_below_2p23(a: f32) -> i32 {
    ((a + TWO23) - TWO23) as i32
}

/// `v` rounded to the nearest integer, ties to even, for `|v| ≤ 2^22`
/// (else unspecified), with no branch on its sign: `v + 1.5·2^23` lies in
/// `[2^23, 2^24]`, where `f32` steps by 1 (`1.5·2^23` is even, so ties
/// still go to even), and the subtraction is exact.
#[inline(always)]
pub(crate) fn round_even_signed_below_2p22(v: f32) -> i32 {
    const MAGIC: f32 = 12_582_912.0; // 1.5·2^23
    ((v + MAGIC) - MAGIC) as i32
}

/// `v` rounded to the nearest integer, ties to even, for `|v| ≤ 2^40`
/// (finite): adding and subtracting `2^23` rounds exactly (IEEE addition
/// rounds to nearest even on every target), and from `2^23` on every `f32`
/// is an integer.
#[inline]
pub(crate) fn round_even_f32(v: f32) -> i64 {
    let a = if v < 0.0 { -v } else { v };
    let r = if a < TWO23 {
        round_even_below_2p23(a) as i64
    } else if a < 4_294_967_296.0 {
        // A u32 conversion (one instruction with an FPU), not the 64-bit
        // library call: depths `z/w·(2^32 − 1)` land here.
        a as u32 as i64
    } else {
        a as i64
    };
    if v < 0.0 { -r } else { r }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::vec::tests::Rng;

    /// Nearest integer, ties to even, in f64 (exact for every f32).
    fn nearest_even(v: f32) -> f64 {
        let x = f64::from(v);
        let f = x.floor();
        let frac = x - f;
        if frac > 0.5 || (frac == 0.5 && f.rem_euclid(2.0) == 1.0) { f + 1.0 } else { f }
    }

    /// The two rounding helpers over their whole stated ranges: random
    /// values, ties, and the range ends.
    #[test]
    fn small_roundings_match_the_definition() {
        let mut rng = Rng(0x2_3523);
        for i in 0..400_000u32 {
            let (a, v) = match i % 3 {
                0 => (rng.range(0.0, 8_388_607.9), rng.range(-4_194_304.0, 4_194_304.0)),
                1 => {
                    // Ties: odd multiples of 1/2.
                    let t = (rng.next() as u32 >> (9 + i % 22)) as f32 + 0.5;
                    (t.min(8_388_607.5), if i % 2 == 0 { t } else { -t }.clamp(-4_194_303.5, 4_194_303.5))
                }
                _ => (rng.range(0.0, 4.0), rng.range(-4.0, 4.0)),
            };
            assert_eq!(round_even_below_2p23(a) as f64, nearest_even(a), "{a}");
            assert_eq!(round_even_signed_below_2p22(v) as f64, nearest_even(v), "{v}");
        }
        for a in [0.0f32, 0.5, 1.5, 8_388_607.0, 8_388_607.5, 8_388_606.5] {
            assert_eq!(round_even_below_2p23(a) as f64, nearest_even(a), "{a}");
        }
        for v in [4_194_304.0f32, -4_194_304.0, 4_194_303.5, -4_194_303.5, -0.5, 0.5, -1.5, 2.5] {
            assert_eq!(round_even_signed_below_2p22(v) as f64, nearest_even(v), "{v}");
        }
    }

    #[test]
    fn round_even_matches_the_definition() {
        let mut rng = Rng(5);
        for i in 0..400_000u32 {
            let v = match i % 4 {
                0 => rng.range(-2e7, 2e7),
                1 => (rng.next() as i32 >> (i % 24)) as f32 * 0.5, // ties
                2 => rng.range(-4.3e9, 4.3e9),                     // the u32 conversion's range and its ends
                _ => rng.range(-1.0995e12, 1.0995e12),
            };
            let x = f64::from(v);
            let want = {
                let f = x.floor();
                let frac = x - f;
                if frac > 0.5 || (frac == 0.5 && f.rem_euclid(2.0) == 1.0) { f + 1.0 } else { f }
            };
            assert_eq!(round_even_f32(v) as f64, want, "{v}");
        }
        for v in [2_147_483_648.0f32, 4_294_967_040.0, 4_294_967_296.0, 8_388_608.0] {
            assert_eq!((round_even_f32(v), round_even_f32(-v)), (v as i64, -(v as i64)));
        }
        assert_eq!(round_even_f32(8_388_607.5), 8_388_608); // a tie, to even
        assert_eq!(round_even_f32(-8_388_606.5), -8_388_606);
    }
}
