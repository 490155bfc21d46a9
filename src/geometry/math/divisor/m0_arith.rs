//! Integer arithmetic the Cortex-M0 (ARMv6-M) lacks in hardware: the
//! 32×32→64-bit multiply, leading zeros and division, built from what it
//! has (each one instruction or a plain operator elsewhere).

/// True on the Cortex-M0 (ARMv6-M): no 32×32→64-bit multiply, no divider.
pub(crate) const ARMV6M: bool = cfg!(all(target_arch = "arm", not(target_feature = "thumb2")));

/// `a·b` exactly. On the Cortex-M0 from four 16×16-bit products (each fits
/// a `u32`), elsewhere one widening multiply (`__aeabi_lmul` would handle
/// 64×64 bits on the Cortex-M0).
#[inline]
pub(crate) fn mul_wide_u32(a: u32, b: u32) -> u64 {
    if ARMV6M { mul_wide_u32_16(a, b) } else { a as u64 * b as u64 }
}

/// `a·b` exactly for `a < 2^16`: on the Cortex-M0 from two 32-bit products
/// (`a·b_hi` and `a·b_lo`, each below `2^32`), elsewhere as
/// [`mul_wide_u32`].
#[inline]
pub(crate) fn mul_u16_u32(a: u32, b: u32) -> u64 {
    debug_assert!(a < 1 << 16);
    if ARMV6M { mul_u16_u32_halves(a, b) } else { a as u64 * b as u64 }
}

/// `x.leading_zeros()`; on the Cortex-M0 (no `CLZ` instruction; the
/// library's loop costs about 35 instructions) two comparisons and a byte
/// table ([`leading_zeros_by_table`]).
#[inline(always)]
pub(crate) fn leading_zeros_u32(x: u32) -> u32 {
    if ARMV6M { leading_zeros_by_table(x) } else { x.leading_zeros() }
}

/// Leading zeros of each byte value (8 for 0).
const CLZ8: [u8; 256] = {
    let mut t = [0u8; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = (i as u8).leading_zeros() as u8;
        i += 1;
    }
    t
};

/// [`leading_zeros_u32`] by the top non-zero byte's table entry (tested on
/// every target).
#[inline(always)]
fn leading_zeros_by_table(x: u32) -> u32 {
    let (top, base) = if x >= 1 << 16 {
        if x >= 1 << 24 { (x >> 24, 0) } else { (x >> 16, 8) }
    } else if x >= 1 << 8 {
        (x >> 8, 16)
    } else {
        (x, 24)
    };
    base + CLZ8[top as usize & 0xFF] as u32
}

/// `a·b` exactly, as [`mul_wide_u32`]; on the Cortex-M0 cheaper for the
/// factors snapping and division meet most ([`mul_wide_u32_cases`]).
#[inline(always)]
pub(crate) fn mul_wide_u32_by(a: u32, b: u32) -> u64 {
    if ARMV6M { mul_wide_u32_cases(a, b) } else { a as u64 * b as u64 }
}

/// [`mul_wide_u32_by`] on the Cortex-M0 (tested on every target): two
/// 32-bit products for `a < 2^16` (half the viewport in subpixels; a
/// quotient's high word), none for `a = 2^32 − 1` (the depth range), else
/// the four of [`mul_wide_u32_16`].
#[inline(always)]
fn mul_wide_u32_cases(a: u32, b: u32) -> u64 {
    if a < 1 << 16 {
        mul_u16_u32_halves(a, b)
    } else if a == u32::MAX {
        // b·2^32 − b by words: written as that difference, LLVM folds it
        // back into a product (the library's 64-bit multiply).
        let hi = b - (b != 0) as u32;
        ((hi as u64) << 32) | b.wrapping_neg() as u64
    } else {
        mul_wide_u32_16(a, b)
    }
}

/// `(⌊x / d⌋, x mod d)` for a quotient below `2^BITS`: `0 < d`,
/// `x < d·2^BITS` and `d·2^(BITS − 1) < 2^32`. On the Cortex-M0, which has
/// no divider (the library's 32-bit division loop costs about 127
/// instructions), by `BITS` restoring steps; elsewhere one division.
#[inline(always)]
pub(crate) fn divrem_small_quotient<const BITS: u32>(x: u32, d: u32) -> (u32, u32) {
    if ARMV6M { divrem_by_steps::<BITS>(x, d) } else { (x / d, x % d) }
}

/// [`divrem_small_quotient`] by restoring steps (tested on every target):
/// bit `b` of the quotient, from the top, is set where what is left of `x`
/// reaches `d·2^b`; with the quotient below `2^BITS` what is left at the
/// end is the remainder.
#[inline(always)]
fn divrem_by_steps<const BITS: u32>(mut x: u32, d: u32) -> (u32, u32) {
    let (mut q, mut t) = (0, d << (BITS - 1));
    for _ in 0..BITS {
        // The quotient's bits from the top, shifted in (few registers on
        // the Cortex-M0: no per-bit constants).
        let ge = x >= t;
        x -= if ge { t } else { 0 };
        q = (q << 1) | ge as u32;
        t >>= 1;
    }
    (q, x)
}

/// [`mul_u16_u32`] by halves of `b` (tested on every target).
#[inline]
fn mul_u16_u32_halves(a: u32, b: u32) -> u64 {
    (((a * (b >> 16)) as u64) << 16) + (a * (b & 0xFFFF)) as u64
}

/// [`mul_wide_u32`] from four 16×16-bit products (tested on every target).
#[inline]
pub(super) fn mul_wide_u32_16(a: u32, b: u32) -> u64 {
    let (ah, al, bh, bl) = (a >> 16, a & 0xFFFF, b >> 16, b & 0xFFFF);
    let mid = (ah * bl) as u64 + (al * bh) as u64; // < 2^33
    (((ah * bh) as u64) << 32) + (mid << 16) + (al * bl) as u64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::vec::tests::Rng;

    /// The restoring steps against `/` and `%`, over the preconditions'
    /// whole range: quotients at and next to their bound, divisors from 1 to
    /// the largest the bound allows.
    #[test]
    fn divrem_by_steps_is_the_division() {
        fn check<const BITS: u32>(rng: &mut Rng, cases: u32) {
            let d_max = (u32::MAX >> (BITS - 1)) as u64; // d·2^(BITS−1) < 2^32
            for i in 0..cases {
                let r = rng.next();
                let d = match i % 4 {
                    0 => 1 + (r % d_max) as u32,
                    1 => 1 + ((r >> 20) % 300) as u32,
                    2 => d_max as u32,
                    _ => 1 << (r % (33 - BITS as u64)),
                };
                let bound = (d as u64) << BITS; // x < d·2^BITS
                let x = match i % 3 {
                    0 => (r >> 7) % bound.min(1 << 32),
                    1 => bound.min(1 << 32) - 1,
                    _ => (d as u64 * ((r >> 40) % (1 << BITS))).min(u32::MAX as u64),
                } as u32;
                assert_eq!(divrem_by_steps::<BITS>(x, d), (x / d, x % d), "{x} / {d}");
                assert_eq!(divrem_small_quotient::<BITS>(x, d), (x / d, x % d));
            }
        }
        let mut rng = Rng(0xD1_71DE);
        check::<8>(&mut rng, 200_000);
        check::<16>(&mut rng, 200_000);
        check::<1>(&mut rng, 20_000);
        // The tiny raster's channel widths (5 and 6 bits for RGB565).
        check::<5>(&mut rng, 100_000);
        check::<6>(&mut rng, 100_000);
    }

    #[test]
    fn leading_zeros_by_table_is_leading_zeros() {
        let mut rng = Rng(0xC12_0C12);
        for i in 0..200_000u32 {
            let r = rng.next() as u32;
            // Every bit length, and the powers of two and their neighbours.
            let x = [r >> (i % 32), 1 << (i % 32), (1u32 << (i % 32)).wrapping_sub(1), 0, u32::MAX]
                [(i % 5) as usize];
            assert_eq!(leading_zeros_by_table(x), x.leading_zeros(), "{x:#x}");
            assert_eq!(leading_zeros_u32(x), x.leading_zeros());
        }
    }

    #[test]
    fn mul_wide_u32_cases_is_the_product() {
        let mut rng = Rng(0x3232_6464);
        for i in 0..300_000u32 {
            let r = rng.next();
            let a = [(r >> 48) as u32, r as u32, u32::MAX, 0xFFFF, 0x1_0000, u32::MAX - 1][(i % 6) as usize];
            let b = [(r >> 32) as u32, u32::MAX, 0, 1][(i / 6 % 4) as usize];
            assert_eq!(mul_wide_u32_cases(a, b), a as u64 * b as u64, "{a} {b}");
            assert_eq!(mul_wide_u32_by(a, b), a as u64 * b as u64);
        }
    }

    #[test]
    fn mul_u16_u32_halves_is_the_product() {
        let mut rng = Rng(0x16_3216);
        for i in 0..200_000u32 {
            let r = rng.next();
            let a = [(r >> 48) as u32, 0, 0xFFFF, 1][(i % 4) as usize];
            let b = [r as u32, u32::MAX, 0, 1 << 31][(i / 4 % 4) as usize];
            assert_eq!(mul_u16_u32_halves(a, b), a as u64 * b as u64, "{a} {b}");
            assert_eq!(mul_u16_u32(a, b), a as u64 * b as u64);
        }
    }
}
