//! The raw-bit arithmetic under [`Fx`](super::Fx): products, quotients and
//! the conversion from `f32`, each bit-identical to the `fixed` crate's
//! saturating operation (tested) but without 64-bit library calls where
//! the part has no 32×32→64 multiply or no divide (the Cortex-M0).

/// The 16.16 product of two raw 16.16 values, `⌊a·b / 2^16⌋` clamped to the
/// `i32` range: exact up to the rounding toward −∞ (error in `[0, 2^-16)`),
/// saturating with the sign of the exact product. Bit-identical to
/// `I16F16::saturating_mul` of the `fixed` crate (tested).
///
/// Parts without a 32×32→64 multiply (Cortex-M0: `__aeabi_lmul`, and the
/// `fixed` crate's overflow-checked 64-bit product) use
/// [`saturating_mul_bits_16`]; elsewhere one widening multiply.
#[inline]
pub(crate) fn saturating_mul_bits(a: i32, b: i32) -> i32 {
    if crate::math::divisor::ARMV6M {
        saturating_mul_bits_16(a, b)
    } else {
        let p = (a as i64 * b as i64) >> 16; // |a·b| ≤ 2^62: no overflow
        p.clamp(i32::MIN as i64, i32::MAX as i64) as i32
    }
}

/// [`saturating_mul_bits`] from four 16×16-bit products, each of which fits
/// an `i32`/`u32` (`|ah·bh| ≤ 2^30`, `|ah·bl| < 2^31`, `al·bl < 2^32`); only
/// additions and shifts are 64-bit (inline on every target). With
/// `a = ah·2^16 + al` (`al` unsigned): `⌊a·b/2^16⌋ = ah·bh·2^16 + ah·bl +
/// al·bh + ⌊al·bl/2^16⌋` exactly.
///
/// Operands below 128 in magnitude (`|a|, |b| < 2^23`: unit vectors,
/// colours, lighting factors) take [`mul_bits_in_range_16`]: their product
/// is below `2^30`, so 32-bit wrapping arithmetic is exact and nothing
/// saturates (Cortex-M0 `Fx` knot: this halves a multiply's 64-bit work).
#[inline]
pub(crate) fn saturating_mul_bits_16(a: i32, b: i32) -> i32 {
    // `x >> 23` is −1 or 0 exactly when `|x| < 2^23` (or x = −2^23): then
    // `(x >> 23) + 1` is 0 or 1, and the OR of two such values is too.
    if (((a >> 23) + 1) | ((b >> 23) + 1)) as u32 <= 1 {
        return mul_bits_in_range_16(a, b);
    }
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    let low = ((al as u32 * bl as u32) >> 16) as i64;
    let p = (((ah * bh) as i64) << 16) + (ah * bl) as i64 + (al * bh) as i64 + low;
    p.clamp(i32::MIN as i64, i32::MAX as i64) as i32
}

/// `⌊a·b / 2^16⌋` modulo 2^32: exact whenever it fits an `i32`. Without a
/// 32×32→64-bit multiply (Cortex-M0) from the four 16×16-bit products of
/// [`saturating_mul_bits_16`] in wrapping arithmetic (no 64-bit addition,
/// no clamp); elsewhere the widening product.
#[inline(always)]
pub(crate) fn mul_bits_in_range(a: i32, b: i32) -> i32 {
    if crate::math::divisor::ARMV6M {
        mul_bits_in_range_16(a, b)
    } else {
        ((a as i64 * b as i64) >> 16) as i32
    }
}

/// [`mul_bits_in_range`] from 16-bit halves (tested on every target).
#[inline(always)]
pub(super) fn mul_bits_in_range_16(a: i32, b: i32) -> i32 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    let low = ((al as u32).wrapping_mul(bl as u32) >> 16) as i32;
    (ah.wrapping_mul(bh) << 16).wrapping_add(ah * bl).wrapping_add(al * bh).wrapping_add(low)
}

/// The 16.16 quotient of two raw 16.16 values, `a·2^16 / b` truncated
/// toward zero (error < 2^-16), saturating with the sign of the exact
/// quotient; `b ≠ 0`. Bit-identical to `I16F16::saturating_div` of the
/// `fixed` crate (tested), but with at most one 32-bit division (none when
/// `|a| < |b|`, as in normalising) and 16 shift-subtract steps instead of a
/// 64-bit division (a slow library call on Cortex-M).
pub(super) fn saturating_div_bits(a: i32, b: i32) -> i32 {
    let neg = (a < 0) != (b < 0);
    let (ua, ub) = (a.unsigned_abs(), b.unsigned_abs());
    // Integer part and remainder, then 16 fraction bits by restoring division
    // (r < ub ≤ 2^31, so 2r fits a u32).
    let (ip, mut r) = if ua < ub { (0, ua) } else { (ua / ub, ua % ub) };
    // |quotient| > 2^15 · 2^16 = 2^31 saturates.
    if ip > 1 << 15 {
        return if neg { i32::MIN } else { i32::MAX };
    }
    let mut q = ip;
    for _ in 0..16 {
        r <<= 1;
        q <<= 1;
        if r >= ub {
            r -= ub;
            q |= 1;
        }
    }
    // q < (2^15 + 1)·2^16 fits a u32.
    if neg {
        if q > 1 << 31 { i32::MIN } else { (q as i64).wrapping_neg() as i32 }
    } else if q > i32::MAX as u32 {
        i32::MAX
    } else {
        q as i32
    }
}

/// `round(n / d)` (ties away from zero) for `0 ≤ n < 2^63` and
/// `0 < d < 2^31`, exactly, with at most one 32-bit division and 32
/// shift-subtract steps (a 64-bit division is a slow library call on
/// Cortex-M).
pub(super) fn div_round_u64_u32(n: u64, d: u32) -> u64 {
    let n = n + (d / 2) as u64; // < 2^63 + 2^30: no overflow
    let (hi, mut lo) = ((n >> 32) as u32, n as u32);
    let (qh, mut r) = if hi < d { (0, hi) } else { (hi / d, hi % d) };
    let mut ql = 0u32;
    for _ in 0..32 {
        // r < d < 2^31: (r << 1) | bit fits a u32.
        r = (r << 1) | (lo >> 31);
        lo <<= 1;
        ql <<= 1;
        if r >= d {
            r -= d;
            ql |= 1;
        }
    }
    ((qh as u64) << 32) | ql as u64
}

/// The raw 16.16 value nearest to `v` (ties to even), saturating at the
/// `i32` range, NaN giving 0: bit-identical to
/// `I16F16::saturating_from_num(v)` of the `fixed` crate (tested), but with
/// 32-bit integer operations only (the `fixed` crate goes through 128-bit
/// intermediates, slow on Cortex-M).
#[inline]
pub(crate) fn fx_bits_from_f32(v: f32) -> i32 {
    if HARD_FLOAT { fx_bits_from_f32_float(v) } else { fx_bits_from_f32_int(v) }
}

/// True where `f32` arithmetic is in hardware: everywhere but ARM without
/// the hard-float ABI (the Cortex-M0, M3; there a float operation is a
/// library call and the integer form below is cheaper).
pub(crate) const HARD_FLOAT: bool = cfg!(any(not(target_arch = "arm"), target_abi = "eabihf"));

/// [`fx_bits_from_f32`] with floating-point operations (a handful of
/// instructions with an FPU, against about 50 for the integer form):
/// `v·2^16` is exact (a power of two; infinite on overflow, which
/// saturates), below `2^23` in magnitude it is rounded to an integer, ties
/// to even, by adding and subtracting `2^23` (as [`round_even_f32`]), above
/// it is an integer already, and `as i32` saturates and maps NaN to 0, as
/// the fixed crate does (tested against it).
///
/// [`round_even_f32`]: crate::math::divisor::round_even_f32
#[inline]
fn fx_bits_from_f32_float(v: f32) -> i32 {
    use crate::math::divisor::{TWO23, round_even_below_2p23};
    let s = v * 65_536.0;
    let a = if s < 0.0 { -s } else { s };
    if a < TWO23 {
        let r = round_even_below_2p23(a);
        if s < 0.0 { -r } else { r }
    } else {
        s as i32
    }
}

/// The `f32` nearest to `bits / 2^16` (ties to even): bit-identical to the
/// `fixed` crate's `to_num::<f32>` (tested), which normalises through 64
/// bits and the library's leading-zero count (about 90 instructions a
/// conversion on the Cortex-M0, where each lit vertex of a 16.16 mesh
/// converts its normal).
#[inline]
pub(crate) fn f32_from_fx_bits(bits: i32) -> f32 {
    if HARD_FLOAT { f32_from_fx_bits_float(bits) } else { f32_from_fx_bits_int(bits) }
}

/// [`f32_from_fx_bits`] by the hardware conversion (`as` rounds to
/// nearest, ties to even), then divided by 2^16 by lowering the exponent:
/// exact, as a non-zero `i32` has a magnitude of at least 1 and the
/// quotient stays a normal number.
#[inline]
fn f32_from_fx_bits_float(bits: i32) -> f32 {
    if bits == 0 { 0.0 } else { f32::from_bits((bits as f32).to_bits() - (16 << 23)) }
}

/// [`f32_from_fx_bits`] with 32-bit integer operations only: the leading
/// bit found by table ([`leading_zeros_u32`]), the magnitude rounded to 24
/// significant bits (a carry out of the 24 bits raises the exponent, as
/// the sum below does), exponent and sign put in place.
///
/// [`leading_zeros_u32`]: crate::math::divisor::leading_zeros_u32
#[inline(never)]
pub(super) fn f32_from_fx_bits_int(bits: i32) -> f32 {
    if bits == 0 {
        return 0.0;
    }
    let m = bits.unsigned_abs();
    let top = 31 - crate::math::divisor::leading_zeros_u32(m);
    let mant = if top <= 23 {
        m << (23 - top)
    } else {
        // Rounded by its remainder, not by `shr_round_even`: `m` reaches
        // 2^31, beyond that helper's no-overflow range (below 2^24).
        let k = top - 23; // 1..=8
        let (q, r, half) = (m >> k, m & ((1 << k) - 1), 1 << (k - 1));
        q + u32::from(r > half || (r == half && q & 1 == 1))
    };
    // Value m·2^-16 with its leading bit at `top`: exponent top − 16, biased
    // top + 111; `mant` holds the leading bit at 2^23 (or 2^24 after a carry).
    let sign = bits as u32 & 0x8000_0000;
    f32::from_bits(sign | (((top + 111) << 23) + (mant - (1 << 23))))
}

/// `m / 2^k` rounded to nearest, ties to even, for `m < 2^24` and `k` in
/// `1..=25`, without a branch: adding half − 1, plus 1 where the quotient
/// is odd, carries into it exactly when the remainder exceeds half, or
/// equals it with an odd quotient (`m + 2^(k−1) < 2^25`: no overflow).
#[inline(always)]
const fn shr_round_even(m: u32, k: u32) -> u32 {
    (m + (1u32 << (k - 1)) - 1 + ((m >> k) & 1)) >> k
}

/// [`fx_bits_from_f32`] with 32-bit integer operations only.
#[inline]
pub(super) const fn fx_bits_from_f32_int(v: f32) -> i32 {
    let bits = v.to_bits();
    // The common case first (a model's coordinates and normals; Cortex-M0
    // knot, Fx: 106.6 M -> 103.9 M instructions): a normal number from
    // 2^-18 to below 2^7, whose 16.16 value is its 24-bit significand
    // shifted right by k = 134 − exponent in 1..=25, rounded to nearest,
    // ties to even (as below), and below 2^23: no saturation, no special
    // values.
    let k = 134u32.wrapping_sub((bits >> 23) & 0xFF);
    if k.wrapping_sub(1) < 25 {
        let mag = shr_round_even((bits & 0x7F_FFFF) | 1 << 23, k) as i32;
        return if bits >> 31 != 0 { -mag } else { mag };
    }
    let neg = bits >> 31 != 0;
    let exp = ((bits >> 23) & 0xFF) as i32;
    let man = bits & 0x7F_FFFF;
    let sat = if neg { i32::MIN } else { i32::MAX };
    if exp == 0xFF {
        return if man != 0 { 0 } else { sat };
    }
    // |v| = m · 2^e exactly; the 16.16 value is m · 2^(e + 16).
    let (m, e) = if exp == 0 { (man, -149) } else { (man | 1 << 23, exp - 150) };
    let sh = e + 16;
    let mag: u32 = if sh >= 0 {
        // m < 2^24: anything shifted by more than 8 is at least 2^31 (or m = 0).
        if sh > 8 {
            if m == 0 {
                return 0;
            }
            return sat;
        }
        let wide = (m as u64) << sh;
        if wide > 1 << 31 {
            return sat;
        }
        wide as u32 // ≤ 2^31
    } else {
        let k = -sh;
        if k > 25 {
            return 0; // below half of 2^-16 (m < 2^24 ≤ 2^(k−2))
        }
        shr_round_even(m, k as u32) // k in 1..=25
    };
    if neg {
        // mag ≤ 2^31: −2^31 is representable.
        (mag as i64).wrapping_neg() as i32
    } else if mag > i32::MAX as u32 {
        i32::MAX
    } else {
        mag as i32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixed::types::I16F16;

    #[test]
    fn mul_div_and_from_f32_are_bit_identical_to_the_fixed_crate() {
        let mut rng = crate::math::vec::tests::Rng(0x5eed_1234_abcd_ef01);
        let edge = [
            0,
            1,
            -1,
            2,
            0xFFFF,
            0x1_0000,
            -0x1_0000,
            0x7FFF_FFFF,
            i32::MIN,
            i32::MIN + 1,
            0x8000,
            46341 << 8,
            // Either side of the 32-bit path's bound (2^23).
            0x7F_FFFF,
            0x80_0000,
            -0x80_0000,
            -0x80_0001,
        ];
        let mut n = 0;
        for i in 0..400_000u32 {
            let r = rng.next();
            let (mut a, mut b) = (r as i32, (r >> 32) as i32);
            // Mix in small operands and edge values (most products of random
            // 32-bit values saturate).
            match i % 4 {
                0 => (a, b) = (a >> (i % 31), b >> (i / 4 % 31)),
                1 => a = edge[(i / 4) as usize % edge.len()],
                _ => {}
            }
            let want = I16F16::from_bits(a).saturating_mul(I16F16::from_bits(b)).to_bits();
            assert_eq!(saturating_mul_bits_16(a, b), want, "{a} * {b}");
            assert_eq!(saturating_mul_bits(a, b), want, "{a} * {b}");
            let f = f32::from_bits(r as u32);
            let f = if i % 2 == 0 { f } else { (a as f32) * 2f32.powi(-((i % 40) as i32)) };
            let want = if f.is_nan() { 0 } else { I16F16::saturating_from_num(f).to_bits() };
            assert_eq!(fx_bits_from_f32_int(f), want, "{f:e}");
            assert_eq!(fx_bits_from_f32_float(f), want, "{f:e}");
            n += 1;
        }
        for i in 0..400_000u32 {
            let r = rng.next();
            let (mut a, mut b) = (r as i32, (r >> 32) as i32);
            match i % 4 {
                0 => b >>= i % 31,
                1 => a = edge[(i / 4) as usize % edge.len()],
                2 => b = edge[(i / 4) as usize % edge.len()],
                _ => (a, b) = (a >> (i % 17), b.max(a.saturating_abs())), // |a| ≤ |b| (normalising)
            }
            if b == 0 {
                continue;
            }
            let want = I16F16::from_bits(a).saturating_div(I16F16::from_bits(b)).to_bits();
            assert_eq!(saturating_div_bits(a, b), want, "{a} / {b}");
            let n = rng.next() >> (1 + i % 40);
            let d = (((r >> 33) as u32) >> (i % 31)).max(1);
            let want = (u128::from(n) + u128::from(d / 2)) / u128::from(d);
            assert_eq!(u128::from(div_round_u64_u32(n, d)), want, "{n} / {d}");
        }
        for (a, b) in
            [(i32::MIN, 1 << 16), (i32::MIN, -(1 << 16)), (1 << 15, 1), (-(1 << 15), 1), (i32::MAX, i32::MIN)]
        {
            let want = I16F16::from_bits(a).saturating_div(I16F16::from_bits(b)).to_bits();
            assert_eq!(saturating_div_bits(a, b), want, "{a} / {b}");
        }
        for f in [
            0.0f32,
            -0.0,
            0.5 / 65536.0,
            1.5 / 65536.0,
            -0.5 / 65536.0,
            32767.99999,
            32768.0,
            -32768.0,
            -32768.5,
            f32::MIN_POSITIVE,
            1e-45,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MAX,
            f32::MIN,
        ] {
            let want = I16F16::saturating_from_num(f).to_bits();
            assert_eq!((fx_bits_from_f32_int(f), fx_bits_from_f32_float(f)), (want, want), "{f:e}");
        }
        assert_eq!(n, 400_000);
        // Ties and their neighbours for every right shift the conversion
        // rounds by: mantissas whose dropped bits are half a step, or one
        // unit either side, with even and odd quotients, both signs.
        for k in 1..=26u32 {
            for j in 0..64u32 {
                let top = (1u32 << 23) | (j.wrapping_mul(0x9E37_79B9) >> 9 & 0x7F_FFFF);
                let half = 1u32 << (k - 1).min(23);
                for m in [top & !((half << 1) - 1) | half, top & !((half << 1) - 1) | half ^ 1, top] {
                    let m = m.clamp(1, (1 << 24) - 1);
                    for sign in [1.0f32, -1.0] {
                        // m < 2^24 and a power of two: exact in f32.
                        let f = sign * m as f32 * 2f32.powi(-(16 + k as i32));
                        let want = I16F16::saturating_from_num(f).to_bits();
                        assert_eq!(fx_bits_from_f32_int(f), want, "{f:e} (m {m}, k {k})");
                    }
                }
            }
        }
    }
}
