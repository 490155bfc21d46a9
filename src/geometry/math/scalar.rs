//! The two numeric paths of the vertex stage: `f32` and 16.16 fixed point.
//!
//! [`Scalar`] is sealed: it is implemented for `f32` (for parts with an FPU,
//! maths through `micromath` so host and target give identical bits) and for
//! [`Fx`] (16.16 fixed point from the `fixed` crate, for parts without one).
//!
//! [`Fx`] arithmetic **saturates** instead of overflowing: results beyond
//! ±32768 clamp to [`Fx::MAX`]/[`Fx::MIN`], and division by zero gives the
//! saturated value with the dividend's sign (`0/0 = 0`). Range ±32768,
//! resolution 2^-16 ≈ 1.5·10^-5; `+ − ×` are exact or correctly rounded down
//! (truncation, error < 2^-16), `÷` truncates toward zero (error < 2^-16).

use core::fmt::Debug;
use core::ops::{Add, Div, Mul, Neg, Sub};

#[cfg(feature = "fx")]
mod fx;
#[cfg_attr(not(feature = "fx"), allow(dead_code, unused_imports))]
mod fx_bits;
pub(crate) use fx_bits::HARD_FLOAT;

#[cfg(feature = "fx")]
#[cfg_attr(docsrs, doc(cfg(feature = "fx")))]
pub use fx::Fx;

mod sealed {
    use crate::mesh::Rows;
    pub trait Sealed: Sized {
        /// Mesh rows of this type as the mesh checks read them.
        fn rows(s: &[[Self; 3]]) -> Rows<'_>;
    }
    impl Sealed for f32 {
        fn rows(s: &[[f32; 3]]) -> Rows<'_> {
            Rows::F32(s)
        }
    }
    #[cfg(feature = "fx")]
    impl Sealed for super::Fx {
        fn rows(s: &[[super::Fx; 3]]) -> Rows<'_> {
            Rows::Fx(s)
        }
    }
}

/// A number type of the vertex stage: `f32` or [`Fx`].
pub trait Scalar:
    Copy
    + Debug
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + sealed::Sealed
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// The nearest value to `v` (saturating for [`Fx`]; NaN becomes 0 there).
    fn from_f32(v: f32) -> Self;
    /// The value as `f32` (exact for [`Fx`] values below 2^8 in magnitude,
    /// otherwise rounded to nearest).
    fn to_f32(self) -> f32;
    /// The value of `v`: exact for [`Fx`]; for `f32` as [`Fx::to_f32`]
    /// gives it (exact below 2^8 in magnitude).
    #[cfg(feature = "fx")]
    fn from_fx(v: Fx) -> Self;
    /// [`Vec3::from_data`](super::Vec3::from_data): for `f32` data the
    /// very call [`Vec3::from_f32`](super::Vec3::from_f32) (the vertex
    /// stage's code and its counts as before 16.16 data), for [`Fx`] data
    /// [`Scalar::from_fx`] of each component.
    #[doc(hidden)]
    fn vec3_to<U: Scalar>(v: [Self; 3]) -> super::Vec3<U>;
    /// Square root; negative inputs give 0.
    fn sqrt(self) -> Self;
    /// Sine and cosine of an angle in radians.
    fn sin_cos(self) -> (Self, Self);
    /// Absolute value (saturating for [`Fx`]).
    fn abs(self) -> Self;
    /// False for NaN and infinities (always true for [`Fx`]).
    fn is_finite(self) -> bool;
    /// The value times `2^s`, rounded to nearest (ties to even), or `None` if
    /// it is not finite or its magnitude exceeds 2^28: the snapping step into
    /// [`SubPoint`](crate::SubPoint) units.
    fn to_subpixels(self, s: u32) -> Option<i32>;
    /// `round(self / den · scale)` for `den > 0` and `|scale| ≤ 2^40`, or `None`
    /// if the operands are not finite, `den ≤ 0`, or the result exceeds 2^40:
    /// the perspective divide and viewport scale in one step, so [`Fx`] keeps
    /// its full precision (one `i64` division) instead of rounding `self/den`
    /// to 16 fractional bits first. `f32` rounds to nearest, ties to even.
    fn div_scaled(self, den: Self, scale: i64) -> Option<i64>;
    /// A denominator prepared for several [`Scalar::div_scaled_by`] (and
    /// the fast tier's quotients).
    type Divisor: Copy + Debug + super::divisor::FastQuotient<Self>;
    /// `self` prepared as the denominator of [`Scalar::div_scaled_by`], or
    /// `None` where [`Scalar::div_scaled`] would fail for any numerator (not
    /// finite, or `≤ 0`).
    fn divisor(self) -> Option<Self::Divisor>;
    /// `self.div_scaled(den, scale)` for `den` prepared by
    /// [`Scalar::divisor`]: bit-identical, with the denominator's work done
    /// once ([`divisor`](super::divisor)).
    fn div_scaled_by(self, den: Self::Divisor, scale: i64) -> Option<i64>;
    /// What a vertex cache keeps of prepared divisor `den` while the
    /// vertex's depth waits (`Fx`: its reciprocal; `f32`: nothing), so
    /// [`Scalar::divisor_from_word`] rebuilds it without preparing it again.
    #[doc(hidden)]
    fn divisor_word(den: Self::Divisor) -> u32;
    /// `self.divisor()` from `word`, which [`Scalar::divisor_word`] gave
    /// for `self.divisor()`.
    #[doc(hidden)]
    fn divisor_from_word(self, word: u32) -> Option<Self::Divisor>;
    /// [`Vec3::normalize_fast`](super::Vec3::normalize_fast) (see there).
    #[doc(hidden)]
    fn unit3(v: super::Vec3<Self>) -> super::Vec3<Self>;
    /// The value in `[0, 1]` (clamped; NaN gives 0) times `max`, rounded to
    /// nearest: a colour channel from an intensity.
    fn to_channel(self, max: u8) -> u8;
    /// `((m₀·p₀ + m₁·p₁) + m₂·p₂) + d`, as those operations give it, for
    /// a caller that knows no partial sum (nor product) leaves the range:
    /// a matrix row times a point (the vertex stage, after
    /// `fx_coordinates_fit`). `f32`: the same four operations. [`Fx`]:
    /// without the saturation (module docs of its impl), bit-identical there.
    #[doc(hidden)]
    fn row_in_range(m: [Self; 3], p: [Self; 3], d: Self) -> Self;
}

impl Scalar for f32 {
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    #[inline]
    fn from_f32(v: f32) -> Self {
        v
    }
    #[inline]
    fn to_f32(self) -> f32 {
        self
    }
    #[cfg(feature = "fx")]
    #[inline]
    fn from_fx(v: Fx) -> Self {
        v.to_f32()
    }
    #[inline(always)]
    fn vec3_to<U: Scalar>(v: [f32; 3]) -> super::Vec3<U> {
        super::Vec3::from_f32(v)
    }
    #[inline]
    fn sqrt(self) -> Self {
        sqrt_f32(self)
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        sin_cos_f32(self)
    }
    #[inline]
    fn abs(self) -> Self {
        micromath::F32Ext::abs(self)
    }
    #[inline]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }
    fn to_subpixels(self, s: u32) -> Option<i32> {
        // Same rounding as SubPoint::from_f32.
        crate::subpixel::snap_f32_bits(self, s).ok()
    }
    fn div_scaled(self, den: Self, scale: i64) -> Option<i64> {
        self.div_scaled_by(den.divisor()?, scale)
    }
    type Divisor = f32;
    #[inline]
    fn divisor(self) -> Option<f32> {
        // False for NaN too.
        (self > 0.0 && self <= f32::MAX).then_some(self)
    }
    fn div_scaled_by(self, den: f32, scale: i64) -> Option<i64> {
        if !self.is_finite() {
            return None;
        }
        // `as f32` of an i32 rounds like that of the same i64 value, without
        // the 64-bit conversion (a library call on 32-bit targets).
        let s = if let Ok(s) = u32::try_from(scale) {
            s as f32
        } else if let Ok(s) = i32::try_from(scale) {
            s as f32
        } else {
            wide_to_f32(scale)
        };
        let v = self / den * s;
        if v.is_nan() || v.abs() > (1u64 << 40) as f32 {
            return None;
        }
        Some(super::divisor::round_even_f32(v))
    }
    #[inline]
    fn divisor_word(_: f32) -> u32 {
        0
    }
    #[inline]
    fn divisor_from_word(self, _: u32) -> Option<f32> {
        self.divisor()
    }
    fn unit3(v: super::Vec3<f32>) -> super::Vec3<f32> {
        super::unit::unit_f32(v)
    }
    #[inline(always)]
    fn row_in_range(m: [f32; 3], p: [f32; 3], d: f32) -> f32 {
        m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + d
    }
    fn to_channel(self, max: u8) -> u8 {
        // `(clamp(c, 0, 1)·max + 0.5)` truncated, with the clamp after the
        // conversion: `as u32` saturates (negative and NaN to 0, +∞ to
        // `u32::MAX`), and for `c` in `[0, 1]` the expression is the same,
        // so only the top needs `min`: one conversion and one integer
        // comparison instead of two floating ones (tested against the
        // clamp-first form).
        ((self * max as f32 + 0.5) as u32).min(u32::from(max)) as u8
    }
}

/// Square root to within about an ulp: `micromath`'s estimate (≈5 % error)
/// refined by Newton steps, in plain `f32` arithmetic so host and target agree
/// bit for bit. Non-positive inputs (and NaN) give 0, infinity gives infinity.
pub(crate) fn sqrt_f32(x: f32) -> f32 {
    if x.is_nan() || x <= 0.0 {
        return 0.0;
    }
    if x == f32::INFINITY {
        return x;
    }
    if x < f32::MIN_POSITIVE {
        // Subnormal: the bit-trick estimate is poor there; scale by 2^48.
        return sqrt_f32(x * 281_474_976_710_656.0) / 16_777_216.0;
    }
    let mut y = micromath::F32Ext::sqrt(x);
    // Quadratic convergence: 6e-2 → 2e-3 → 2e-6 → rounding.
    for _ in 0..4 {
        y = 0.5 * (y + x / y);
    }
    y
}

/// `⌊v⌋` for finite `v` (no `std`): truncation, one lower for a negative
/// value with a fraction. Exact for `|v| < 2^31`; beyond `i32` it saturates
/// (NaN gives 0). Both conversions are one instruction on an FPU, where an
/// `i64` floor would call the runtime library on a 32-bit core.
pub(crate) fn floor_i32(v: f32) -> i32 {
    let t = v as i32;
    if (t as f32) > v { t.saturating_sub(1) } else { t }
}

/// `⌈v⌉` for finite `v`, as [`floor_i32`].
pub(crate) fn ceil_i32(v: f32) -> i32 {
    let t = v as i32;
    if (t as f32) < v { t.saturating_add(1) } else { t }
}

/// Sine and cosine in `f32`: Cody–Waite reduction by π/2 (a two-part
/// constant), then the same Taylor polynomials as the fixed-point path on
/// `[-π/4, π/4]`. Absolute error below 2·10^-7 (plus 10^-10·|a|) for
/// `|a| ≤ 2^13` rad; beyond
/// 2^20 rad the reduction is meaningless and `(0, 1)` is returned (a
/// documented clamp, not a panic). micromath's own sin/cos err by up to 2·10^-3,
/// too much for rotation matrices.
fn sin_cos_f32(a: f32) -> (f32, f32) {
    if !a.is_finite() {
        return (f32::NAN, f32::NAN);
    }
    if micromath::F32Ext::abs(a) > 1_048_576.0 {
        return (0.0, 1.0);
    }
    // π/2 = A + B + C with A (8 bits) and B (11 bits) short enough that k·A and
    // k·B are exact for |k| < 2^13: the reduction loses nothing there.
    const A: f32 = 1.570_312_5;
    const B: f32 = 4.837_513e-4;
    const C: f32 = 7.549_79e-8;
    let k = a * core::f32::consts::FRAC_2_PI;
    let k = if k >= 0.0 { (k + 0.5) as i32 } else { (k - 0.5) as i32 };
    let kf = k as f32;
    let r = ((a - kf * A) - kf * B) - kf * C;
    let r2 = r * r;
    // Taylor to r^9 / r^10: truncation below 2·10^-9 on [-π/4, π/4].
    let s = r * (1.0 - r2 / 6.0 * (1.0 - r2 / 20.0 * (1.0 - r2 / 42.0 * (1.0 - r2 / 72.0))));
    let c = 1.0 - r2 / 2.0 * (1.0 - r2 / 12.0 * (1.0 - r2 / 30.0 * (1.0 - r2 / 56.0 * (1.0 - r2 / 90.0))));
    match k.rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// `x as f32`, out of line: inlined, LLVM computed this library call
/// (`__aeabi_l2f`/`__aeabi_ul2f` on 32-bit targets) before testing whether
/// the one-instruction `u32`/`i32` conversion applies, and kept the 64-bit
/// one for the rare scale that needs it; a call it cannot hoist. (Each
/// snapped vertex of the standard 3D scene paid two: 3 % of its
/// Cortex-M4F frame.)
#[cold]
#[inline(never)]
fn wide_to_f32(x: i64) -> f32 {
    x as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn div_scaled_and_to_channel_agree_between_paths() {
        let mut n = 0;
        for i in -300..300 {
            for w in [0.25f32, 1.0, 3.7, 100.0] {
                let x = i as f32 * 0.731;
                let exact = f64::from(x) / f64::from(w) * 40960.0;
                let a = x.div_scaled(w, 40960).unwrap();
                assert!((a as f64 - exact).abs() <= 0.5 + exact.abs() * 2.4e-7, "f32 {x}/{w}");
                let (fx, fw) = (Fx::from_f32(x), Fx::from_f32(w));
                let ex = f64::from(fx.to_bits()) / f64::from(fw.to_bits()) * 40960.0;
                let b = fx.div_scaled(fw, 40960).unwrap();
                assert!((b as f64 - ex).abs() <= 0.5, "Fx {x}/{w}");
                n += 1;
            }
        }
        assert_eq!(n, 2400);
        assert_eq!(1.0f32.div_scaled(0.0, 10), None);
        assert_eq!(f32::NAN.div_scaled(1.0, 10), None);
        assert_eq!(Fx::ONE.div_scaled(Fx::ZERO, 10), None);
        assert_eq!(Fx::ONE.div_scaled(-Fx::ONE, 10), None);
        // Scales through each conversion (u32, negative i32, the out-of-line
        // 64-bit one): the quotient of the scale's own `as f32`, and within
        // rounding of the exact product.
        for scale in [1i64, 40960, (1 << 31) + 1, u32::MAX as i64, -7, -(1 << 31), 1 << 33, -(1 << 35) - 3] {
            for (x, w) in [(0.731f32, 3.7f32), (-2.5, 0.25), (100.0, 1.0)] {
                let v = x / w * scale as f32;
                let exact = f64::from(x) / f64::from(w) * scale as f64;
                if v.abs() > (1u64 << 40) as f32 {
                    assert_eq!(x.div_scaled(w, scale), None, "{x}/{w}·{scale}: beyond 2^40");
                    continue;
                }
                let want = crate::math::divisor::round_even_f32(v);
                assert_eq!(x.div_scaled(w, scale), Some(want), "{x}/{w}·{scale}");
                assert!((want as f64 - exact).abs() <= 0.5 + exact.abs() * 2.4e-7, "{x}/{w}·{scale}");
            }
        }
        for (v, max, want) in [(0.5f32, 255u8, 128u8), (1.5, 31, 31), (-1.0, 63, 0), (f32::NAN, 255, 0)] {
            assert_eq!(v.to_channel(max), want);
            assert_eq!(Fx::from_f32(v).to_channel(max), want);
        }
    }

    /// `to_channel` equals the clamp-first form `(clamp(c, 0, 1)·max + 0.5)
    /// as u8` for every channel size, on values in, around and far outside
    /// `[0, 1]`, rounding ties, NaN and infinities.
    #[test]
    fn to_channel_is_the_clamp_first_form() {
        let clamp_first = |c: f32, max: u8| {
            let c = if c > 1.0 {
                1.0
            } else if c > 0.0 {
                c
            } else {
                0.0
            };
            (c * max as f32 + 0.5) as u8
        };
        let mut rng = crate::math::vec::tests::Rng(0xC4A7_0001);
        let mut n = 0;
        for max in [0u8, 1, 3, 15, 31, 63, 255] {
            let special =
                [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -0.0, 0.0, 1.0, f32::MAX, -f32::MAX, 1e-30];
            let ties = (0..=u32::from(max)).map(|k| (k as f32 + 0.5) / f32::from(max.max(1)));
            let random = (0..20_000).map(|_| (rng.next() >> 40) as f32 / (1u64 << 24) as f32 * 3.0 - 1.0);
            for c in special.into_iter().chain(ties).chain(random) {
                assert_eq!(c.to_channel(max), clamp_first(c, max), "{c} {max}");
                n += 1;
            }
        }
        assert!(n > 140_000);
    }

    #[test]
    fn f32_sqrt_and_sin_cos_within_bound_of_f64() {
        let mut n = 0;
        for i in 1..200_000 {
            let x = i as f32 * 0.013_7;
            let r = f64::from(sqrt_f32(x));
            assert!((r - f64::from(x).sqrt()).abs() <= f64::from(x).sqrt() * 2.4e-7, "sqrt({x})");
            let a = (i as f32 - 100_000.0) * 0.041; // ±4100 rad
            let (s, c) = sin_cos_f32(a);
            let a64 = f64::from(a);
            assert!(
                (f64::from(s) - a64.sin()).abs() <= 2e-7 + a64.abs() * 1e-10,
                "sin({a}) = {s} vs {}",
                a64.sin()
            );
            assert!((f64::from(c) - a64.cos()).abs() <= 2e-7 + a64.abs() * 1e-10, "cos({a})");
            n += 1;
        }
        assert_eq!(n, 199_999);
        assert_eq!(sqrt_f32(-1.0), 0.0);
        assert!(sin_cos_f32(f32::NAN).0.is_nan());
    }
}
