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
use fixed::types::I16F16;

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for super::Fx {}
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
    /// A denominator prepared for several [`Scalar::div_scaled_by`].
    type Divisor: Copy + Debug;
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
        // (An `if` chain, since LLVM hoists a `match` on both conversions'
        // results above the branch, library call included.)
        let s = if let Ok(s) = u32::try_from(scale) {
            s as f32
        } else if let Ok(s) = i32::try_from(scale) {
            s as f32
        } else {
            scale as f32
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
    if super::divisor::ARMV6M {
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
    if super::divisor::ARMV6M { mul_bits_in_range_16(a, b) } else { ((a as i64 * b as i64) >> 16) as i32 }
}

/// [`mul_bits_in_range`] from 16-bit halves (tested on every target).
#[inline(always)]
fn mul_bits_in_range_16(a: i32, b: i32) -> i32 {
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
fn saturating_div_bits(a: i32, b: i32) -> i32 {
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
fn div_round_u64_u32(n: u64, d: u32) -> u64 {
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
const HARD_FLOAT: bool = cfg!(any(not(target_arch = "arm"), target_abi = "eabihf"));

/// [`fx_bits_from_f32`] with floating-point operations (a handful of
/// instructions with an FPU, against about 50 for the integer form):
/// `v·2^16` is exact (a power of two; infinite on overflow, which
/// saturates), below `2^23` in magnitude it is rounded to an integer, ties
/// to even, by adding and subtracting `2^23` (as [`round_even_f32`]), above
/// it is an integer already, and `as i32` saturates and maps NaN to 0, as
/// the fixed crate does (tested against it).
///
/// [`round_even_f32`]: super::divisor::round_even_f32
#[inline]
fn fx_bits_from_f32_float(v: f32) -> i32 {
    use super::divisor::{TWO23, round_even_below_2p23};
    let s = v * 65_536.0;
    let a = if s < 0.0 { -s } else { s };
    if a < TWO23 {
        let r = round_even_below_2p23(a);
        if s < 0.0 { -r } else { r }
    } else {
        s as i32
    }
}

/// `m / 2^k` rounded to nearest, ties to even, for `m < 2^24` and `k` in
/// `1..=25`, without a branch: adding half − 1, plus 1 where the quotient
/// is odd, carries into it exactly when the remainder exceeds half, or
/// equals it with an odd quotient (`m + 2^(k−1) < 2^25`: no overflow).
#[inline(always)]
fn shr_round_even(m: u32, k: u32) -> u32 {
    (m + (1u32 << (k - 1)) - 1 + ((m >> k) & 1)) >> k
}

/// [`fx_bits_from_f32`] with 32-bit integer operations only.
#[inline]
fn fx_bits_from_f32_int(v: f32) -> i32 {
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
            if super::divisor::ARMV6M {
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
    fn to_f32(self) -> f32 {
        self.0.to_num::<f32>()
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
                let q = if super::divisor::ARMV6M {
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
    type Divisor = super::divisor::FxDivisor;
    #[inline]
    fn divisor(self) -> Option<Self::Divisor> {
        super::divisor::FxDivisor::new(self.to_bits())
    }
    #[inline]
    fn div_scaled_by(self, den: Self::Divisor, scale: i64) -> Option<i64> {
        // Scales up to 2^32 (all of snapping's): |bits·scale| < 2^63 in u64.
        if let Ok(sa) = u32::try_from(scale.unsigned_abs()) {
            let m = super::divisor::mul_wide_u32_by(sa, self.to_bits().unsigned_abs());
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
        super::divisor::FxDivisor::from_reciprocal(self.to_bits(), word)
    }
    fn unit3(v: super::Vec3<Fx>) -> super::Vec3<Fx> {
        match super::unit::unit_bits([v.x, v.y, v.z].map(Fx::to_bits)) {
            Some([x, y, z]) => super::Vec3::new(Fx::from_bits(x), Fx::from_bits(y), Fx::from_bits(z)),
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
