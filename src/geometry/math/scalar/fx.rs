//! [`Fx`]: 16.16 fixed point with saturating arithmetic (the module docs of
//! [`scalar`](super) state its range, resolution and rounding), and its
//! [`Scalar`] implementation for parts without an FPU.

use super::Scalar;
use super::fx_bits::{
    div_round_u64_u32, f32_from_fx_bits, fx_bits_from_f32, fx_bits_from_f32_int, mul_bits_in_range,
    saturating_div_bits, saturating_mul_bits,
};
use core::ops::{Add, Div, Mul, Neg, Sub};
use fixed::types::I16F16;

/// 16.16 fixed point with saturating arithmetic (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Default, Hash)]
pub struct Fx(pub I16F16);

impl Fx {
    /// Largest value, 32768 − 2^-16.
    pub const MAX: Fx = Fx(I16F16::MAX);
    /// Smallest value, −32768.
    pub const MIN: Fx = Fx(I16F16::MIN);
    /// The raw 16.16 bits.
    pub const fn to_bits(self) -> i32 {
        self.0.to_bits()
    }
    /// From raw 16.16 bits.
    pub const fn from_bits(b: i32) -> Self {
        Fx(I16F16::from_bits(b))
    }
    /// [`Scalar::from_f32`] as a `const fn`, bit for bit (the nearest
    /// value, ties to even, saturating, NaN giving 0): for mesh data
    /// converted at compile time ([`Mesh`](crate::mesh::Mesh) in 16.16).
    ///
    /// ```
    /// use microraster::math::{Fx, Scalar};
    /// static HALF: Fx = Fx::const_from_f32(0.5);
    /// assert_eq!(HALF, Fx::from_f32(0.5));
    /// ```
    pub const fn const_from_f32(v: f32) -> Self {
        Fx::from_bits(fx_bits_from_f32_int(v))
    }
    /// The nearest value to `v`, or [`Error::NonFiniteCoordinate`](crate::Error::NonFiniteCoordinate) for NaN and
    /// ±infinity and [`Error::CoordinateOutOfRange`](crate::Error::CoordinateOutOfRange) for `|v| ≥ 32767` (where
    /// [`Scalar::from_f32`] would saturate, or nearly): the checked
    /// conversion for camera and projection parameters.
    pub fn try_from_f32(v: f32) -> Result<Self, crate::Error> {
        if !v.is_finite() {
            Err(crate::Error::NonFiniteCoordinate)
        } else if v.abs() >= 32767.0 {
            Err(crate::Error::CoordinateOutOfRange)
        } else {
            Ok(Fx::from_bits(fx_bits_from_f32(v)))
        }
    }
}

impl Add for Fx {
    type Output = Fx;
    #[inline]
    fn add(self, o: Fx) -> Fx {
        Fx(self.0.saturating_add(o.0))
    }
}
impl Sub for Fx {
    type Output = Fx;
    #[inline]
    fn sub(self, o: Fx) -> Fx {
        Fx(self.0.saturating_sub(o.0))
    }
}
impl Mul for Fx {
    type Output = Fx;
    /// `⌊a·b⌋` in 16.16 (rounded toward −∞, error < 2^-16), saturating:
    /// bit-identical to `I16F16::saturating_mul` (without its 64-bit product
    /// on the Cortex-M0: four 16×16-bit products).
    #[inline]
    fn mul(self, o: Fx) -> Fx {
        Fx::from_bits(saturating_mul_bits(self.to_bits(), o.to_bits()))
    }
}

impl Div for Fx {
    type Output = Fx;
    #[inline]
    fn div(self, o: Fx) -> Fx {
        if o.0 == I16F16::ZERO {
            match self.0.cmp(&I16F16::ZERO) {
                core::cmp::Ordering::Greater => Fx::MAX,
                core::cmp::Ordering::Less => Fx::MIN,
                core::cmp::Ordering::Equal => Fx(I16F16::ZERO),
            }
        } else {
            // Parts with a hardware divide (Thumb-2) divide in 64 bits; the
            // Cortex-M0 has none and uses the shift-subtract form.
            if crate::math::divisor::ARMV6M {
                Fx::from_bits(saturating_div_bits(self.to_bits(), o.to_bits()))
            } else {
                Fx(self.0.saturating_div(o.0))
            }
        }
    }
}
impl Neg for Fx {
    type Output = Fx;
    #[inline]
    fn neg(self) -> Fx {
        Fx(self.0.saturating_neg())
    }
}

impl Scalar for Fx {
    const ZERO: Self = Fx(I16F16::ZERO);
    const ONE: Self = Fx(I16F16::ONE);
    #[inline]
    fn from_f32(v: f32) -> Self {
        Fx::from_bits(fx_bits_from_f32(v))
    }
    /// The nearest `f32`, ties to even (bit-identical to the `fixed`
    /// crate's `to_num::<f32>`, without its 64-bit normalisation).
    #[inline]
    fn to_f32(self) -> f32 {
        f32_from_fx_bits(self.to_bits())
    }
    #[inline(always)]
    fn from_fx(v: Fx) -> Self {
        v
    }
    #[inline(always)]
    fn vec3_to<U: Scalar>(v: [Fx; 3]) -> crate::math::Vec3<U> {
        crate::math::Vec3::new(U::from_fx(v[0]), U::from_fx(v[1]), U::from_fx(v[2]))
    }
    fn sqrt(self) -> Self {
        Fx(self.0.checked_sqrt().unwrap_or(I16F16::ZERO))
    }
    fn sin_cos(self) -> (Self, Self) {
        fixed_sin_cos(self)
    }
    fn abs(self) -> Self {
        Fx(self.0.saturating_abs())
    }
    fn is_finite(self) -> bool {
        true
    }
    fn to_subpixels(self, s: u32) -> Option<i32> {
        let v = crate::subpixel::shift_round_even(self.to_bits() as i64, s as i32 - 16);
        if v.abs() <= 1 << 28 { Some(v as i32) } else { None }
    }
    fn div_scaled(self, den: Self, scale: i64) -> Option<i64> {
        let d = den.to_bits() as i64;
        if d <= 0 || scale.abs() > 1 << 40 {
            return None;
        }
        // |bits · scale| ≤ 2^31 · 2^40: i128 only when i64 would overflow
        // (an i128 division is a slow library call on Cortex-M).
        let q = match (self.to_bits() as i64).checked_mul(scale) {
            Some(n) if n.unsigned_abs() < 1 << 62 => {
                // 0 < d < 2^31; the same rounding as (|n| + d/2)/d.
                let (m, d) = (n.unsigned_abs(), d as u32);
                let q = if crate::math::divisor::ARMV6M {
                    div_round_u64_u32(m, d)
                } else {
                    (m + (d / 2) as u64) / d as u64
                } as i64;
                if n >= 0 { q } else { -q }
            }
            _ => {
                let (n, d) = (self.to_bits() as i128 * scale as i128, d as i128);
                (if n >= 0 { (n + d / 2) / d } else { -((-n + d / 2) / d) }) as i64
            }
        };
        if q.abs() <= 1 << 40 { Some(q) } else { None }
    }
    type Divisor = crate::math::divisor::FxDivisor;
    #[inline]
    fn divisor(self) -> Option<Self::Divisor> {
        crate::math::divisor::FxDivisor::new(self.to_bits())
    }
    #[inline]
    fn div_scaled_by(self, den: Self::Divisor, scale: i64) -> Option<i64> {
        // Scales up to 2^32 (all of snapping's): |bits·scale| < 2^63 in u64.
        if let Ok(sa) = u32::try_from(scale.unsigned_abs()) {
            let m = crate::math::divisor::mul_wide_u32_by(sa, self.to_bits().unsigned_abs());
            if let Some(q) = den.div_round(m) {
                let q = q as i64;
                return Some(if (self.to_bits() < 0) != (scale < 0) { -q } else { q });
            }
        }
        self.div_scaled(Fx::from_bits(den.d as i32), scale)
    }
    #[inline]
    fn divisor_word(den: Self::Divisor) -> u32 {
        den.reciprocal_word()
    }
    #[inline]
    fn divisor_from_word(self, word: u32) -> Option<Self::Divisor> {
        crate::math::divisor::FxDivisor::from_reciprocal(self.to_bits(), word)
    }
    fn unit3(v: crate::math::Vec3<Fx>) -> crate::math::Vec3<Fx> {
        match crate::math::unit::unit_bits([v.x, v.y, v.z].map(Fx::to_bits)) {
            Some([x, y, z]) => crate::math::Vec3::new(Fx::from_bits(x), Fx::from_bits(y), Fx::from_bits(z)),
            None => v,
        }
    }
    /// Each product `⌊a·b/2^16⌋` and each sum in wrapping 32-bit
    /// arithmetic: equal modulo 2^32 to the exact values, so equal to them
    /// (and to the saturating operations, which then do not saturate)
    /// when they fit an `i32`, as the caller guarantees.
    #[inline(always)]
    fn row_in_range(m: [Fx; 3], p: [Fx; 3], d: Fx) -> Fx {
        let mul = |a: Fx, b: Fx| mul_bits_in_range(a.to_bits(), b.to_bits());
        let sum = mul(m[0], p[0]).wrapping_add(mul(m[1], p[1])).wrapping_add(mul(m[2], p[2]));
        Fx::from_bits(sum.wrapping_add(d.to_bits()))
    }
    fn to_channel(self, max: u8) -> u8 {
        let b = self.to_bits().clamp(0, 1 << 16) as u32;
        ((b * max as u32 + (1 << 15)) >> 16) as u8
    }
}

/// Sine and cosine in 16.16: reduce to `[-π/4, π/4]` by quadrant, then Taylor
/// polynomials to x^9/x^10 evaluated in 2.30 fixed point (truncation error
/// < 2·10^-9 on that interval, far below the 16.16 resolution).
fn fixed_sin_cos(a: Fx) -> (Fx, Fx) {
    use core::f64::consts::FRAC_PI_2;
    const HALF_PI: i64 = (FRAC_PI_2 * 65536.0 * 65536.0) as i64; // 2^32 scale
    // Angle in 32.32, quadrant k = round(a / (π/2)), remainder r in [-π/4, π/4].
    let a32 = (a.to_bits() as i64) << 16;
    let k = (a32 + a32.signum() * HALF_PI / 2) / HALF_PI;
    let r32 = a32 - k * HALF_PI; // |r| ≤ π/4 · 2^32
    let r = r32 >> 2; // 2.30 fixed point
    let mul = |x: i64, y: i64| (x * y) >> 30;
    let r2 = mul(r, r);
    const ONE: i64 = 1 << 30;
    // sin r = r(1 − r²/6(1 − r²/20(1 − r²/42))), cos r = 1 − r²/2(1 − r²/12(1 − r²/30(1 − r²/56)))
    let s = mul(r, ONE - mul(r2, (ONE - mul(r2, (ONE - mul(r2, ONE - r2 / 72) / 42) / 20)) / 6));
    let c =
        ONE - mul(r2, (ONE - mul(r2, (ONE - mul(r2, (ONE - mul(r2, ONE - r2 / 90) / 56) / 30)) / 12)) / 2);
    let (s, c) = match k.rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    };
    let to_fx = |v: i64| Fx::from_bits(((v + (1 << 13)) >> 14) as i32);
    (to_fx(s), to_fx(c))
}

#[cfg(test)]
mod tests {
    use super::super::fx_bits::mul_bits_in_range_16;
    use super::*;

    /// Where the products and partial sums fit, the unsaturated row equals
    /// the saturating operations; the 16-bit-halves product equals the
    /// fixed crate's wherever the result fits.
    #[test]
    fn rows_in_range_equal_the_saturating_rows() {
        let mut rng = crate::math::vec::tests::Rng(0x005E_ED0F_0123);
        let (mut n, mut near) = (0, 0);
        for i in 0..400_000u32 {
            let r = rng.next();
            let (a, b) = (r as i32 >> (i % 17), (r >> 32) as i32 >> (i / 17 % 17));
            let want = I16F16::from_bits(a).saturating_mul(I16F16::from_bits(b)).to_bits();
            let exact = (a as i64 * b as i64) >> 16;
            if exact == want as i64 {
                assert_eq!(mul_bits_in_range_16(a, b), want, "{a} * {b}");
                assert_eq!(mul_bits_in_range(a, b), want, "{a} * {b}");
            }
            // A row whose partial sums fit (or not: then nothing is claimed).
            let mut f = |k: u32| Fx::from_bits(rng.next() as i32 >> (1 + (i + 3 * k) % 24));
            let (m, p, d) = ([f(0), f(1), f(2)], [f(3), f(4), f(5)], f(6));
            let wide = |a: Fx, b: Fx| (a.to_bits() as i64 * b.to_bits() as i64) >> 16;
            let s1 = wide(m[0], p[0]) + wide(m[1], p[1]);
            let s2 = s1 + wide(m[2], p[2]);
            let s3 = s2 + d.to_bits() as i64;
            let fits = [wide(m[0], p[0]), wide(m[1], p[1]), wide(m[2], p[2]), s1, s2, s3]
                .iter()
                .all(|&v| i32::try_from(v).is_ok());
            if fits {
                let want = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + d;
                assert_eq!(Fx::row_in_range(m, p, d), want, "{m:?} {p:?} {d:?}");
                n += 1;
                near += (s3.unsigned_abs() > 1 << 29) as u32;
            }
        }
        // Not vacuous: most rows fit, and some come near the range's end.
        assert!(n > 100_000 && near > 1_000, "{n} {near}");
    }

    /// `to_f32` is the `fixed` crate's conversion, bit for bit, in both forms
    /// (hardware and integer): over every
    /// magnitude, both signs, the extremes, and the values with more than
    /// 24 significant bits, where the conversion rounds (ties included).
    #[test]
    fn to_f32_is_the_fixed_crates_conversion() {
        let mut rng = crate::math::vec::tests::Rng(0x70F3_2B17);
        let check = |b: i32| {
            let want = I16F16::from_bits(b).to_num::<f32>().to_bits();
            assert_eq!(Fx::from_bits(b).to_f32().to_bits(), want, "{b}");
            assert_eq!(super::super::fx_bits::f32_from_fx_bits_int(b).to_bits(), want, "{b}");
        };
        for b in
            [0, 1, -1, i32::MIN, i32::MAX, i32::MIN + 1, 1 << 24, (1 << 24) + 1, (1 << 25) + 2, (1 << 25) + 6]
        {
            check(b);
            check(b.wrapping_neg());
        }
        let mut rounded = 0;
        for i in 0..1_000_000u32 {
            let r = rng.next();
            let b = (r as i32) >> (i % 32);
            check(b);
            // Ties: the bit below the kept 24 set, the rest clear.
            let lz = (b.unsigned_abs() | 1).leading_zeros();
            if lz < 8 {
                rounded += 1;
                let k = 8 - lz;
                let tie = ((b >> k) << k) | (1 << (k - 1));
                check(tie);
            }
        }
        assert!(rounded > 100_000, "{rounded}");
    }

    #[test]
    fn fixed_ops_saturate_instead_of_panicking() {
        let big = Fx::from_f32(30000.0);
        assert_eq!(big + big, Fx::MAX);
        assert_eq!(-big - big, Fx::MIN);
        assert_eq!(big * big, Fx::MAX);
        assert_eq!(Fx::ONE / Fx::ZERO, Fx::MAX);
        assert_eq!(-Fx::ONE / Fx::ZERO, Fx::MIN);
        assert_eq!(Fx::ZERO / Fx::ZERO, Fx::ZERO);
        assert_eq!(-Fx::MIN, Fx::MAX);
        assert_eq!(Fx::from_f32(f32::NAN), Fx::ZERO);
        assert_eq!(Fx::from_f32(f32::INFINITY), Fx::MAX);
        assert_eq!(Fx::from_f32(-4.0).sqrt(), Fx::ZERO);
    }

    #[test]
    fn fixed_sin_cos_within_bound_of_f64() {
        // Bound: polynomial error < 2e-9, a few 2^-30 steps of 2.30
        // arithmetic and the final rounding to 16.16 (≤ 2^-17).
        let bound = 2e-9 + 8.0 * 2.0f64.powi(-30) + 2.0f64.powi(-17);
        let mut n = 0;
        for i in -20000..=20000 {
            let a = Fx::from_bits(i * 97); // ±29.6 rad
            let x = f64::from(a.to_bits()) / 65536.0;
            let (s, c) = a.sin_cos();
            let (s, c) = (f64::from(s.to_bits()) / 65536.0, f64::from(c.to_bits()) / 65536.0);
            assert!((s - x.sin()).abs() <= bound, "sin({x}) = {s}");
            assert!((c - x.cos()).abs() <= bound, "cos({x}) = {c}");
            n += 1;
        }
        assert_eq!(n, 40001);
    }
}
