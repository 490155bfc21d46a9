//! [`FxDivisor`]: a positive 16.16 denominator prepared once for exact
//! quotients by multiplication (Möller–Granlund algorithm 4), and the
//! reciprocal it needs, computed per target.

use super::m0_arith::{ARMV6M, leading_zeros_u32, mul_u16_u32, mul_wide_u32, mul_wide_u32_by};

/// A positive [`Fx`](crate::math::Fx) denominator prepared for exact rounding
/// division of 64-bit numerators (`FxDivisor::div_round`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FxDivisor {
    /// The raw 16.16 bits of the denominator, `0 < d < 2^31`.
    pub(crate) d: u32,
    /// `d << sh` has bit 31 set.
    sh: u32,
    /// `⌊(2^64 − 1)/(d << sh)⌋ − 2^32`, the reciprocal of algorithm 4.
    v: u32,
}

impl FxDivisor {
    /// The divisor `d` (raw bits), `None` unless `0 < d`.
    pub(crate) fn new(d: i32) -> Option<Self> {
        let p = Self::from_reciprocal(d, 0)?;
        Some(FxDivisor { v: reciprocal(p.d << p.sh), ..p })
    }

    /// The raw divisor, its normalising shift and its reciprocal word
    /// (the fast tier's quotient, `divisor::fast`).
    #[inline]
    pub(crate) fn parts(&self) -> (u32, u32, u32) {
        (self.d, self.sh, self.v)
    }

    /// The reciprocal word, all that [`FxDivisor::from_reciprocal`] needs
    /// besides `d` (a vertex cache keeps it in one `u32`).
    #[inline]
    pub(crate) fn reciprocal_word(&self) -> u32 {
        self.v
    }

    /// The divisor `d` whose [`FxDivisor::reciprocal_word`] is `v`, without
    /// computing the reciprocal again (`None` unless `0 < d`). A `v` from
    /// another divisor gives wrong quotients, never a panic or overflow:
    /// the 2-by-1 division's corrections wrap.
    #[inline]
    pub(crate) fn from_reciprocal(d: i32, v: u32) -> Option<Self> {
        let d = u32::try_from(d).ok().filter(|&d| d > 0)?;
        Some(FxDivisor { d, sh: leading_zeros_u32(d), v })
    }

    /// `⌊(m + ⌊d/2⌋) / d⌋` (the rounding of
    /// [`Scalar::div_scaled`](crate::math::Scalar::div_scaled)), exactly, or
    /// `None` if it is `2^32` or more (the caller then divides the slow way).
    #[inline]
    pub(crate) fn div_round(&self, m: u64) -> Option<u32> {
        // m < 2^63 and d/2 < 2^30: no overflow.
        let m = m + (self.d / 2) as u64;
        // The quotient fits 32 bits iff ⌊m / 2^32⌋ < d; then m·2^sh < 2^64.
        if (m >> 32) >= self.d as u64 {
            return None;
        }
        Some(div_2by1(shl_words(m, self.sh), self.d << self.sh, self.v))
    }
}

impl FxDivisor {
    /// `⌊(m + ⌊d/2⌋) / d⌋` for `m < 2^63`, exactly, whatever its size: the
    /// high word by one 32-bit division (one instruction on ARMv7-M), then
    /// the remainder with the low word by the 2-by-1 division (its high
    /// word, the remainder, is below `d`, so it meets its precondition and
    /// `(r·2^32 + lo)·2^sh < 2^64`).
    #[inline]
    pub(crate) fn div_round_u64(&self, m: u64) -> u64 {
        // m < 2^63 and d/2 < 2^30: no overflow.
        let m = m + (self.d / 2) as u64;
        let (hi, lo) = ((m >> 32) as u32, m as u32);
        let q1 = hi / self.d;
        let r = hi - q1 * self.d;
        let q0 = div_2by1(shl_words((r as u64) << 32 | lo as u64, self.sh), self.d << self.sh, self.v);
        (q1 as u64) << 32 | q0 as u64
    }
}

/// `u << sh` as its high and low words, for `sh` in `1..=31` (a
/// normalising shift of a positive `i32`) where the result fits 64 bits:
/// two 32-bit shifts per word, not the Cortex-M0's 64-bit shift call.
#[inline(always)]
fn shl_words(u: u64, sh: u32) -> (u32, u32) {
    debug_assert!((1..32).contains(&sh) && u.leading_zeros() >= sh);
    let (hi, lo) = ((u >> 32) as u32, u as u32);
    ((hi << sh) | (lo >> (32 - sh)), lo << sh)
}

/// `⌊u / d⌋` for `u = (u1, u0)` (high and low words), `d ≥ 2^31` and
/// `u1 < d`, with `v` from [`reciprocal`] (Möller–Granlund algorithm 4: the
/// estimate is at most one too large or two too small, fixed by the
/// remainder tests).
#[inline]
fn div_2by1((u1, u0): (u32, u32), d: u32, v: u32) -> u32 {
    // (q1, q0) = v·u1 + (u1 + 1, u0) mod 2^64; u1 + 1 ≤ d fits a u32.
    // u1 is mostly small (a snapped coordinate's numerator over w).
    let q = mul_wide_u32_by(u1, v).wrapping_add((((u1 + 1) as u64) << 32) | u0 as u64);
    let (mut q1, q0) = ((q >> 32) as u32, q as u32);
    let mut r = u0.wrapping_sub(q1.wrapping_mul(d));
    if r > q0 {
        q1 = q1.wrapping_sub(1);
        r = r.wrapping_add(d);
    }
    if r >= d {
        q1 = q1.wrapping_add(1);
    }
    q1
}

/// True on ARMv7-M (Cortex-M3/M4/M7): a 32-bit division is one
/// instruction, a 64-bit one a bit-by-bit library loop (about 300).
const ARMV7M: bool = cfg!(all(target_arch = "arm", target_feature = "thumb2"));

/// `⌊(2^64 − 1)/d⌋ − 2^32` for `d ≥ 2^31` (in `[0, 2^32)`): the quotient
/// of `(2^32 − 1 − d, 2^32 − 1)` by `d`. On ARMv7-M by 16-bit halves with
/// the hardware divider, on the Cortex-M0 (no divider: the library's two
/// 32-bit divisions cost about 160 instructions) by Newton's iteration,
/// one 64-bit division elsewhere.
fn reciprocal(d: u32) -> u32 {
    if ARMV6M {
        reciprocal_by_newton(d)
    } else if ARMV7M {
        reciprocal_by_halves(d)
    } else {
        (u64::MAX / d as u64 - (1 << 32)) as u32
    }
}

/// `⌊2^25 / (2·t + 1)⌋` for `t = 256 + i`: `2^63/d` to about 9 bits
/// (`2^40/(t + 1/2)`, in units of `2^16`) for the divisors `d` whose top
/// nine bits are `t` (512 bytes).
const RECIPROCAL_SEED: [u16; 256] = {
    let mut table = [0u16; 256];
    let mut i = 0;
    while i < 256 {
        // Between 2^25/1023 > 2^15 and 2^25/513 < 2^16.
        table[i] = ((1u32 << 25) / (2 * (256 + i as u32) + 1)) as u16;
        i += 1;
    }
    table
};

/// [`reciprocal`] with multiplications only (tested on every target).
///
/// `y ≈ 2^63/d` (in `(2^31, 2^32]`; the last value is kept below `2^32`)
/// starts from [`RECIPROCAL_SEED`], relative error `ε₀ < 2^-9`, and takes
/// two Newton steps `y + y·(2^63 − y·d)/2^63`: each squares the relative
/// error (`2^-18`, then `2^-36`, so within a few units of `2^63/d`) and
/// truncates a little (the first step keeps the top 15 bits of its
/// residual, the second 50, adding below `2^-22` and one unit). Then
/// `2y − 2^32` is within about six of the result, which the remainder
/// `(2^64 − 1) − (2^32 + v)·d` (exact, in 64 bits; it must lie in
/// `[0, d)`) corrects one step at a time: exact whatever the estimate.
fn reciprocal_by_newton(d: u32) -> u32 {
    // The first step in 32 bits: y₀ = t·2^16, its residual
    // 2^63 − y₀·d = 2^16·e with e = 2^47 − t·d (|e| < 2^38.1, from ε₀).
    let t = RECIPROCAL_SEED[((d >> 23) & 0xFF) as usize] as u32;
    let e = (1i64 << 47) - mul_u16_u32(t, d) as i64;
    // y₀·(2^16·e)/2^63 = t·e/2^31, with e's top bits: |e >> 23| ≤ 2^15.1,
    // so t·|e >> 23| < 2^31.1 fits a u32.
    let (neg, e) = (e < 0, (e.unsigned_abs() >> 23) as u32);
    let step = (t * e) >> 8;
    let y = t << 16;
    let y = if neg { y - step } else { y.saturating_add(step) };
    // The second step with exact 64-bit products: r = 2^63 − y·d, |r| <
    // 2^45.6 (ε₁ < 2^-17.4); y·|r|/2^63 from |r| >> 15 (below 2^31).
    let yd = mul_wide_u32(y, d);
    let (neg, r) = if yd > 1 << 63 { (true, yd - (1 << 63)) } else { (false, (1 << 63) - yd) };
    let step = (mul_wide_u32(y, (r >> 15) as u32) >> 48) as u32;
    // Each step leaves y at or below 2^63/d ≤ 2^32 in exact arithmetic;
    // saturating keeps d = 2^31 (whose 2^63/d is 2^32) in range.
    let y = if neg { y - step } else { y.saturating_add(step) };
    // v ≈ 2y − 2^32, then the remainder u − v·d with u = (2^64 − 1) −
    // 2^32·d: above it (u < v·d) v is too large, at d or more too small.
    let mut v = y.wrapping_mul(2);
    let u = ((!d as u64) << 32) | u32::MAX as u64;
    let mut vd = mul_wide_u32(v, d);
    while vd > u {
        v -= 1;
        vd -= d as u64;
    }
    while u - vd >= d as u64 {
        v += 1;
        vd += d as u64;
    }
    v
}

/// [`reciprocal`] as two 16-bit quotient digits, each estimated with a
/// 32-bit division by the divisor's high half and corrected at most twice
/// (Knuth's algorithm D for two digits, as `divlu` in Warren's *Hacker's
/// Delight*, §9-4). Tested on every target.
fn reciprocal_by_halves(d: u32) -> u32 {
    const B: u32 = 1 << 16;
    let (dh, dl) = (d >> 16, d & 0xFFFF); // dh ≥ 2^15: d is normalised
    // The dividend (u1, u0) = (2^32 − 1 − d, 2^32 − 1), u1 < d; digits of u0.
    let (u1, un1, un0) = (!d, 0xFFFF, 0xFFFF);
    // One digit of (r, digit) / d for r < d: the estimate r / dh is at most
    // two too large; while it is (checked on the next divisor digit), lower it.
    let digit = |r: u32, un: u32| {
        let (mut q, mut rhat) = (r / dh, r % dh);
        // rhat < B whenever the product test runs, so nothing overflows.
        while q >= B || q * dl > (rhat << 16 | un) {
            q -= 1;
            rhat += dh;
            if rhat >= B {
                break;
            }
        }
        q
    };
    let q1 = digit(u1, un1);
    // (u1, un1) − q1·d lies in [0, d): exact modulo 2^32.
    let r = (u1 << 16 | un1).wrapping_sub(q1.wrapping_mul(d));
    q1 << 16 | digit(r, un0)
}

#[cfg(test)]
mod tests {
    use super::super::m0_arith::mul_wide_u32_16;
    use super::*;
    use crate::math::vec::tests::Rng;
    use crate::math::{Fx, Scalar};

    /// A divisor rebuilt from its reciprocal word (what a vertex cache
    /// keeps while a depth waits) is the prepared divisor; a word from
    /// another divisor gives some quotient, never a panic.
    #[test]
    fn divisor_from_its_reciprocal_word_is_the_divisor() {
        let mut rng = Rng(0x5EC1_9E0D);
        for i in 0..100_000u32 {
            let d = [(rng.next() >> 33) as i32, 1, i32::MAX, 1 << 16, (rng.next() >> 50) as i32]
                [(i % 5) as usize];
            let Some(p) = FxDivisor::new(d) else { continue };
            assert_eq!(FxDivisor::from_reciprocal(d, p.reciprocal_word()), Some(p), "{d}");
            let m = rng.next() >> 1;
            let other = FxDivisor::from_reciprocal(d, rng.next() as u32).map(|q| q.div_round(m));
            assert!(other.is_some());
        }
        assert_eq!(FxDivisor::from_reciprocal(0, 7), None);
        assert_eq!(FxDivisor::from_reciprocal(-5, 7), None);
    }

    #[test]
    fn prepared_division_is_exact() {
        let mut rng = Rng(0xD1_5EED);
        let mut n = 0;
        for i in 0..1_000_000u32 {
            let r = rng.next();
            let d = ((r as u32) >> (1 + i % 31)).max(1);
            let Some(p) = FxDivisor::new(d as i32) else { panic!("{d}") };
            let m = rng.next() >> (1 + (r >> 40) % 63);
            let want = (u128::from(m) + u128::from(d / 2)) / u128::from(d);
            match p.div_round(m) {
                Some(q) => assert_eq!(u128::from(q), want, "{m} / {d}"),
                None => assert!(want >= 1 << 32, "{m} / {d}: {want}"),
            }
            n += 1;
        }
        assert_eq!(n, 1_000_000);
        // Extremes of the normalised form and of the quotient.
        for d in [1u32, 2, 3, 0x7FFF_FFFF, 0x4000_0000, 0x4000_0001, 65536] {
            let p = FxDivisor::new(d as i32).unwrap();
            for m in
                [0u64, 1, d as u64 - 1, d as u64, (d as u64) << 31, ((d as u64) << 32) - 1 - d as u64 / 2]
            {
                let want = (u128::from(m) + u128::from(d / 2)) / u128::from(d);
                assert_eq!(p.div_round(m).map(u128::from), Some(want), "{m} / {d}");
            }
            assert_eq!(p.div_round(((d as u64) << 32) - d as u64 / 2), None);
        }
        // Quotients of any size.
        for i in 0..300_000u32 {
            let r = rng.next();
            let d = ((r as u32) >> (1 + i % 31)).max(1);
            let p = FxDivisor::new(d as i32).unwrap();
            let m = [rng.next() >> (1 + (r >> 40) % 63), (1 << 63) - 1, 0, (d as u64) << 32]
                [(i % 7).min(3) as usize];
            let want = (u128::from(m) + u128::from(d / 2)) / u128::from(d);
            assert_eq!(u128::from(p.div_round_u64(m)), want, "{m} / {d}");
        }
        assert_eq!(FxDivisor::new(0), None);
        assert_eq!(FxDivisor::new(-5), None);
    }

    #[test]
    fn wide_product_and_reciprocal_are_exact() {
        let mut rng = Rng(99);
        for _ in 0..200_000 {
            let r = rng.next();
            let (a, b) = (r as u32, (r >> 32) as u32);
            assert_eq!(mul_wide_u32(a, b), u64::from(a) * u64::from(b));
            assert_eq!(mul_wide_u32_16(a, b), u64::from(a) * u64::from(b));
            let d = a | 1 << 31;
            let want = u64::MAX / u64::from(d) - (1 << 32);
            assert_eq!(u64::from(reciprocal_by_halves(d)), want, "{d}");
            assert_eq!(u64::from(reciprocal_by_newton(d)), want, "{d}");
            // Divisors with a low half of all ones or zeros (the corrections).
            for d in [d | 0xFFFF, d & !0xFFFF, d | 0x7FFF_FFFF] {
                assert_eq!(u64::from(reciprocal_by_halves(d)), u64::MAX / u64::from(d) - (1 << 32), "{d}");
                assert_eq!(u64::from(reciprocal_by_newton(d)), u64::MAX / u64::from(d) - (1 << 32), "{d}");
            }
        }
        for d in [1u32 << 31, u32::MAX, (1 << 31) + 1] {
            assert_eq!(u64::from(reciprocal_by_halves(d)), u64::MAX / u64::from(d) - (1 << 32), "{d}");
            assert_eq!(u64::from(reciprocal_by_newton(d)), u64::MAX / u64::from(d) - (1 << 32), "{d}");
        }
        assert_eq!(mul_wide_u32(u32::MAX, u32::MAX), u64::from(u32::MAX) * u64::from(u32::MAX));
    }

    /// The prepared forms against `div_scaled` itself (whose rounding the
    /// tests in `scalar.rs` check against f64), for the scales snapping uses.
    #[test]
    fn div_scaled_by_equals_div_scaled() {
        let mut rng = Rng(17);
        let scales = [2560i64, 1280, 5120 * 16, 1 << 30, u32::MAX as i64, 1, 3, -7, 1 << 40];
        let mut n = 0;
        for i in 0..300_000u32 {
            let r = rng.next();
            let (c, w) = (r as i32 >> (i % 29), ((r >> 32) as i32 >> (i / 29 % 31)).wrapping_abs());
            let (c, w) = (Fx::from_bits(c), Fx::from_bits(if i % 7 == 0 { -w } else { w }));
            let s = scales[i as usize % scales.len()];
            let want = c.div_scaled(w, s);
            let got = w.divisor().and_then(|d| c.div_scaled_by(d, s));
            assert_eq!(got, want, "{c:?} / {w:?} · {s}");
            let (cf, wf) = (rng.range(-3000.0, 3000.0), rng.range(-1.0, 200.0));
            let wf = if i % 11 == 0 { f32::NAN } else { wf };
            let cf = if i % 13 == 0 { f32::INFINITY } else { cf };
            let want = cf.div_scaled(wf, s);
            assert_eq!(wf.divisor().and_then(|d| cf.div_scaled_by(d, s)), want, "{cf} / {wf} · {s}");
            n += usize::from(want.is_some());
        }
        assert!(n > 200_000, "{n}");
    }
}
