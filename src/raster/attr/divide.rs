//! Exact rounded division of plane numerators by a triangle's determinant,
//! prepared once per triangle ([`Divisor`]) and used for every quotient.
//!
//! Three ways, chosen by the divisor's size and the target, all giving
//! `⌊n/d⌋` exactly (tests below check each against the 64-bit division on
//! every target):
//! * `d < 2^16` on ARMv7-M (every triangle of a few pixels): 16-bit digits
//!   with the 32-bit hardware divider ([`div_short`]), no reciprocal;
//! * `2^16 ≤ d < 2^31` on ARMv7-M (triangles of up to a quarter of a
//!   320×240 frame): a normalised 32-bit reciprocal made with the hardware
//!   divider and Möller–Granlund's 2-by-1 division
//!   ([`FxDivisor`], shared with the `Fx` vertex divisor), after a 32-bit
//!   division for the quotient's high word;
//! * otherwise the reciprocal `r = ⌊(2^64 − 1)/d⌋` of one 64-bit division.
//!
//! On ARMv7-M a 64-bit division is a bit-by-bit library loop of about 300
//! instructions, which is why the first two exist; the host divides 64 bits
//! in hardware and the Cortex-M0 has no divider at all.

use crate::math::divisor::FxDivisor;
use core::num::NonZeroU32;

/// Division by a fixed `d > 0` (module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct Divisor {
    d: u64,
    how: How,
}

#[derive(Debug, Clone, Copy)]
enum How {
    /// `d < 2^16`: [`div_short`].
    Short(NonZeroU32),
    /// `2^16 ≤ d < 2^31`: [`FxDivisor`].
    Mid(FxDivisor),
    /// `r = ⌊(2^64 − 1)/d⌋`. For `n < 2^64`, `q̂ = ⌊n·r/2^64⌋` satisfies
    /// `n/d − 3 < q̂ ≤ n/d` (as `r > (2^64 − 1)/d − 1`), so at most two
    /// corrections give `⌊n/d⌋` exactly.
    Reciprocal(u64),
}

/// Divisors below this divide by 16-bit digits ([`div_short`]).
const SHORT_LIMIT: u64 = 1 << 16;

/// Divisors below this (and at least [`SHORT_LIMIT`]) divide through
/// [`FxDivisor`], which takes `0 < d < 2^31`.
const MID_LIMIT: u64 = 1 << 31;

/// Whether the hardware-divider ways are taken: where a 32-bit division is
/// one instruction and a 64-bit one a library loop (ARMv7-M).
const HW_DIV: bool = cfg!(all(target_arch = "arm", target_feature = "thumb2"));

impl Divisor {
    #[inline]
    pub(super) fn new(d: u64) -> Divisor {
        Self::with_hw(d, HW_DIV)
    }

    /// [`Divisor::new`], with the hardware-divider ways if `allow`.
    #[inline]
    fn with_hw(d: u64, allow: bool) -> Divisor {
        let how = if allow && d < SHORT_LIMIT {
            NonZeroU32::new(d as u32).map(How::Short)
        } else if allow && d < MID_LIMIT {
            FxDivisor::new(d as i32).map(How::Mid)
        } else {
            None
        };
        Divisor { d, how: how.unwrap_or_else(|| How::Reciprocal(u64::MAX / d)) }
    }

    /// `⌊n/d⌋` by the reciprocal.
    #[inline]
    fn div_floor_reciprocal(&self, n: u64, r: u64) -> u64 {
        let mut q = mul_hi(n, r);
        // q ≤ n/d, so q·d ≤ n: no overflow, and the remainder is below 3d.
        let mut rem = n - q * self.d;
        while rem >= self.d {
            q += 1;
            rem -= self.d;
        }
        q
    }

    /// `⌊(m + ⌊d/2⌋)/d⌋` for `m < 2^63`. The short way inline (a few
    /// instructions, the common case of a dense mesh), the others out of
    /// line, which keeps the plane set-up small.
    #[inline(always)]
    fn div_half_up(&self, m: u64) -> u64 {
        // m + ⌊d/2⌋ < 2^63 + 2^62: no overflow.
        match self.how {
            How::Short(d) => div_short(m + self.d / 2, d),
            _ => self.div_half_up_long(m),
        }
    }

    /// [`Divisor::div_half_up`] for a divisor of 2^16 or more.
    #[inline(never)]
    fn div_half_up_long(&self, m: u64) -> u64 {
        match self.how {
            How::Mid(f) => f.div_round_u64(m),
            How::Reciprocal(r) => self.div_floor_reciprocal(m + self.d / 2, r),
            How::Short(d) => div_short(m + self.d / 2, d),
        }
    }

    /// `(⌊n/d⌋, n − d·⌊n/d⌋)`, the remainder in `0..d`, for `|n| < 2^63`:
    /// from [`Divisor::div_half_up`]'s quotient, which is `⌊|n|/d⌋` or one
    /// more, so no other way of dividing is needed. Out of line: it serves
    /// only the uncommon split set-up, five times a plane.
    #[inline(never)]
    pub(super) fn div_floor_rem(&self, n: i64) -> (i64, i64) {
        let m = n.unsigned_abs();
        let q = self.div_half_up(m);
        // q·d ≤ m + ⌊d/2⌋ < 2^63 + 2^62: no overflow.
        let (q, r) = if q * self.d > m { (q - 1, m + self.d - q * self.d) } else { (q, m - q * self.d) };
        // |n| = q·d + r with 0 ≤ r < d < 2^63.
        match (n < 0, r) {
            (false, _) => (q as i64, r as i64),
            (true, 0) => (-(q as i64), 0),
            (true, _) => (-(q as i64) - 1, (self.d - r) as i64),
        }
    }

    /// `n / d` rounded to nearest, ties away from zero (as
    /// `div_round_i128`); `|n| < 2^63`.
    #[inline(always)]
    pub(super) fn div_round(&self, n: i64) -> i64 {
        // The quotient is below 2^63.
        let q = self.div_half_up(n.unsigned_abs()) as i64;
        if n < 0 { -q } else { q }
    }
}

/// `⌊n/d⌋` for `d < 2^16` by schoolbook division in 32-bit words: the high
/// word, then two 16-bit digits, each remainder below `d` so that
/// `remainder·2^16 + digit` fits a `u32` and each digit's quotient is below
/// 2^16. Three 32-bit divisions (one instruction each on ARMv7-M).
#[inline]
fn div_short(n: u64, d: NonZeroU32) -> u64 {
    let (hi, lo) = ((n >> 32) as u32, n as u32);
    let dv = d.get();
    let q2 = hi / d;
    let t = (hi - q2 * dv) << 16 | lo >> 16;
    let q1 = t / d;
    let t = (t - q1 * dv) << 16 | (lo & 0xFFFF);
    let q0 = t / d;
    (q2 as u64) << 32 | (q1 << 16 | q0) as u64
}

/// The high 64 bits of `a·b`, from 32-bit halves (a `u128` product would be
/// a library call on Cortex-M).
#[inline]
fn mul_hi(a: u64, b: u64) -> u64 {
    let (a0, a1, b0, b1) = (a & 0xFFFF_FFFF, a >> 32, b & 0xFFFF_FFFF, b >> 32);
    let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
    // Each term below 2^32: the sum fits.
    let mid = (p00 >> 32) + (p01 & 0xFFFF_FFFF) + (p10 & 0xFFFF_FFFF);
    p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift64 as a closure.
    fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        }
    }

    fn check(n: i64, d: u64) -> [bool; 2] {
        let (a, b) = (Divisor::with_hw(d, true), Divisor::with_hw(d, false));
        assert!(matches!(b.how, How::Reciprocal(_)));
        let want = super::super::div_round_i128(n as i128, d as i128) as i64;
        assert_eq!(a.div_round(n), want, "{n} / {d}");
        assert_eq!(b.div_round(n), want, "{n} / {d}");
        [matches!(a.how, How::Short(_)), matches!(a.how, How::Mid(_))]
    }

    /// `⌊n/d⌋` and its remainder in `i128` (the reference).
    fn floor_rem_i128(n: i64, d: u64) -> (i64, i64) {
        let (n, d) = (n as i128, d as i128);
        (n.div_euclid(d) as i64, n.rem_euclid(d) as i64)
    }

    /// `div_floor_rem` in every way against the `i128` floor division.
    #[test]
    fn floor_and_remainder_are_exact() {
        let mut next = xorshift(0x2545_F491_4F6C_DD1Du64);
        for i in 0..300_000u32 {
            let d = (next() >> (2 + i % 62)).max(1);
            let n = (next() >> (1 + i % 63)) as i64 * if i % 2 == 0 { -1 } else { 1 };
            let want = floor_rem_i128(n, d);
            for allow in [true, false] {
                assert_eq!(Divisor::with_hw(d, allow).div_floor_rem(n), want, "{n} / {d}");
            }
        }
        for d in [1u64, 2, 3, 0xFFFF, 1 << 16, (1 << 31) - 1, 1 << 31, u64::MAX >> 2] {
            for n in
                [0, 1, -1, d as i64, -(d as i64), i64::MAX - (d / 2) as i64, -(i64::MAX - (d / 2) as i64)]
            {
                let want = floor_rem_i128(n, d);
                assert_eq!(Divisor::new(d).div_floor_rem(n), want, "{n} / {d}");
            }
        }
    }

    /// Every way gives the `i128` division's rounded quotients, on random
    /// divisors of every size and numerators of every size and sign.
    #[test]
    fn every_way_is_exact() {
        let mut next = xorshift(0x9E37_79B9_7F4A_7C15u64);
        let (mut short, mut mid) = (0, 0);
        for i in 0..600_000u32 {
            let d = (next() >> (2 + i % 62)).max(1);
            let n = (next() >> (1 + i % 63)) as i64 * if i % 3 == 0 { -1 } else { 1 };
            let [s, m] = check(n, d);
            (short, mid) = (short + s as u32, mid + m as u32);
        }
        assert!(short > 100_000 && mid > 100_000, "{short} {mid}");
    }

    /// Extremes: the limits between the ways, the largest numerators, ties,
    /// and quotients just below and above 2^32 (the 2-by-1 division's range).
    #[test]
    fn edges_are_exact() {
        let ds = [
            1,
            2,
            3,
            0xFFFF,
            1 << 16,
            (1 << 16) + 1,
            (1 << 31) - 1,
            1 << 31,
            (1 << 31) + 1,
            1 << 40,
            u64::MAX >> 2,
        ];
        for d in ds {
            let big = i64::MAX - (d / 2) as i64;
            let q32 = ((d as u128) << 32).min(big as u128) as i64;
            for n in [0, 1, d as i64 / 2, d as i64 / 2 + 1, d as i64, q32 - 1, q32, q32 + 1, big, big - 1] {
                check(n, d);
                check(-n, d);
            }
        }
        for (n, d) in [(u64::MAX >> 1, 1), (u64::MAX >> 1, 0xFFFF), (0xFFFF_FFFF, 0xFFFF), (0, 1)] {
            assert_eq!(div_short(n, NonZeroU32::new(d).unwrap()), n / d as u64);
        }
    }
}
