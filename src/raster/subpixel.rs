//! Subpixel vertex coordinates: snapping from integers, fixed point and `f32`.
//!
//! A [`SubPoint<S>`] holds a position in units of `1/2^S` pixel. Integer pixel
//! coordinates name pixel *corners*: pixel `(x, y)` covers `[x, x+1) × [y, y+1)`
//! and is sampled at its centre `(x + 0.5, y + 0.5)` (the D3D11/Vulkan
//! convention).
//!
//! # Range and resolution
//!
//! | `S` | resolution | coordinate range (each axis) |
//! |-----|------------|------------------------------|
//! | 0   | 1 px       | ±2^28 px |
//! | 4   | 1/16 px    | ±2^24 px |
//! | 8   | 1/256 px   | ±2^20 px |
//!
//! In general the range is `±2^(28-S)` pixels: [`SubPoint::MAX_SUBPIXELS`]
//! subpixel units. Every constructor rejects coordinates beyond it with
//! [`Error::CoordinateOutOfRange`], which is what keeps all later integer
//! arithmetic provably free of overflow (see [`crate::edge`]).

use crate::Error;
#[cfg(feature = "fx")]
use fixed::FixedI32;
#[cfg(feature = "fx")]
use fixed::types::extra::LeEqU32;

/// The largest supported number of fractional (subpixel) bits.
pub const MAX_SUBPIXEL_BITS: u32 = 8;

/// A vertex position snapped to `S` fractional bits (`1/2^S` pixel).
///
/// `S` may be 0 to [`MAX_SUBPIXEL_BITS`]; anything else is a compile error.
///
/// ```
/// use microraster::SubPoint;
/// let p = SubPoint::<8>::from_f32(10.3, 2.5).unwrap();
/// assert_eq!((p.x(), p.y()), (2637, 640)); // 10.3 * 256 = 2636.8 → 2637
/// assert!(SubPoint::<8>::from_f32(f32::NAN, 0.0).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SubPoint<const S: u32> {
    x: i32,
    y: i32,
}

impl<const S: u32> SubPoint<S> {
    const CHECK: () = assert!(S <= MAX_SUBPIXEL_BITS, "subpixel bits must be 0..=8");

    /// Largest accepted magnitude of a coordinate, in subpixel units (2^28).
    pub const MAX_SUBPIXELS: i32 = 1 << 28;
    /// One pixel in subpixel units (`2^S`).
    pub const ONE: i32 = 1 << S;
    /// Number of fractional bits, `S`.
    pub const BITS: u32 = S;
    /// `(0, 0)`, for `const` initialisers (`Default` is not `const`).
    pub(crate) const ORIGIN: Self = SubPoint { x: 0, y: 0 };

    /// A point from raw subpixel units (`x / 2^S` pixels).
    ///
    /// Errors with [`Error::CoordinateOutOfRange`] if `|x|` or `|y|` exceeds
    /// [`Self::MAX_SUBPIXELS`].
    pub const fn new(x: i32, y: i32) -> Result<Self, Error> {
        let () = Self::CHECK;
        if in_range(x as i64) && in_range(y as i64) {
            Ok(SubPoint { x, y })
        } else {
            Err(Error::CoordinateOutOfRange)
        }
    }

    /// A point at integer pixel coordinates (a pixel corner).
    pub const fn from_pixels(x: i32, y: i32) -> Result<Self, Error> {
        let () = Self::CHECK;
        let (sx, sy) = ((x as i64) << S, (y as i64) << S);
        if in_range(sx) && in_range(sy) {
            Ok(SubPoint { x: sx as i32, y: sy as i32 })
        } else {
            Err(Error::CoordinateOutOfRange)
        }
    }

    /// The centre of pixel `(x, y)`, i.e. `(x + 0.5, y + 0.5)`.
    ///
    /// Needs at least one subpixel bit: with `S = 0` this is a compile error.
    pub const fn pixel_center(x: i32, y: i32) -> Result<Self, Error> {
        const { assert!(S >= 1, "pixel centres need at least one subpixel bit") };
        let half = 1i64 << (S.saturating_sub(1));
        let (sx, sy) = (((x as i64) << S) + half, ((y as i64) << S) + half);
        if in_range(sx) && in_range(sy) {
            Ok(SubPoint { x: sx as i32, y: sy as i32 })
        } else {
            Err(Error::CoordinateOutOfRange)
        }
    }

    /// Snaps `f32` pixel coordinates to the subpixel grid, rounding to nearest
    /// (ties to even). NaN or infinity gives [`Error::NonFiniteCoordinate`].
    pub fn from_f32(x: f32, y: f32) -> Result<Self, Error> {
        let () = Self::CHECK;
        Ok(SubPoint { x: snap_f32::<S>(x)?, y: snap_f32::<S>(y)? })
    }

    /// Snaps fixed-point pixel coordinates with `F` fractional bits to `S`
    /// bits, rounding to nearest (ties to even).
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use microraster::SubPoint;
    /// let p = SubPoint::<4>::from_fixed(I16F16::from_num(1.53125), I16F16::ZERO).unwrap();
    /// assert_eq!(p.x(), 24); // 1.53125 * 16 = 24.5 → 24 (tie to even)
    /// ```
    #[cfg(feature = "fx")]
    #[cfg_attr(docsrs, doc(cfg(feature = "fx")))]
    pub fn from_fixed<F: LeEqU32>(x: FixedI32<F>, y: FixedI32<F>) -> Result<Self, Error> {
        let () = Self::CHECK;
        let frac = FixedI32::<F>::FRAC_NBITS;
        let sx = shift_round_even(x.to_bits() as i64, S as i32 - frac as i32);
        let sy = shift_round_even(y.to_bits() as i64, S as i32 - frac as i32);
        if in_range(sx) && in_range(sy) {
            Ok(SubPoint { x: sx as i32, y: sy as i32 })
        } else {
            Err(Error::CoordinateOutOfRange)
        }
    }

    /// X in subpixel units.
    pub const fn x(self) -> i32 {
        self.x
    }

    /// Y in subpixel units.
    pub const fn y(self) -> i32 {
        self.y
    }

    /// The position in pixels as `f64` (exact).
    pub fn to_f64(self) -> (f64, f64) {
        let one = f64::from(Self::ONE);
        (f64::from(self.x) / one, f64::from(self.y) / one)
    }
}

impl<const S: u32> Default for SubPoint<S> {
    /// The origin. Written out (not derived) so `S > 8` is rejected here too.
    fn default() -> Self {
        let () = Self::CHECK;
        SubPoint { x: 0, y: 0 }
    }
}

const fn in_range(v: i64) -> bool {
    v >= -(1 << 28) && v <= (1 << 28)
}

/// `v * 2^shift`, rounded to nearest with ties to even when `shift < 0`.
#[cfg_attr(not(feature = "fx"), allow(dead_code))]
pub(crate) const fn shift_round_even(v: i64, shift: i32) -> i64 {
    if shift >= 0 {
        return v << shift;
    }
    let k = (-shift) as u32;
    let q = v >> k; // floor
    let rem = v - (q << k);
    let half = 1i64 << (k - 1);
    if rem > half || (rem == half && q & 1 == 1) { q + 1 } else { q }
}

/// Rounds `v * 2^S` to the nearest integer, ties to even, checking the range.
fn snap_f32<const S: u32>(v: f32) -> Result<i32, Error> {
    snap_f32_bits(v, S)
}

/// [`snap_f32`] with the bit count as a value (`s ≤ 8`).
pub(crate) fn snap_f32_bits(v: f32, s: u32) -> Result<i32, Error> {
    if !v.is_finite() {
        return Err(Error::NonFiniteCoordinate);
    }
    // Scaling by a power of two is exact; the range test below keeps the cast exact too.
    let scaled = v * (1u32 << s.min(MAX_SUBPIXEL_BITS)) as f32;
    // Below 2^22 in magnitude (every on-screen coordinate), the adder rounds:
    // `scaled + 1.5·2^23` lies in (2^23, 2^24), where the spacing of `f32`
    // is 1, so the sum is `scaled` rounded to the nearest integer, ties to
    // even (Rust's only rounding mode; 1.5·2^23 is even), plus 1.5·2^23; the
    // subtraction is exact. The result is within ±2^22: in range.
    if scaled.abs() < (1u32 << 22) as f32 {
        const ROUNDER: f32 = (3u32 << 22) as f32;
        return Ok(((scaled + ROUNDER) - ROUNDER) as i32);
    }
    if scaled.abs() > (1u32 << 28) as f32 + 0.5 {
        return Err(Error::CoordinateOutOfRange);
    }
    // Toward zero, exact: |scaled| < 2^31 (a hardware conversion on an FPU;
    // an `i64` one is a library call on 32-bit cores).
    let truncated = scaled as i32;
    let frac = scaled - truncated as f32; // exact: both within 2^29
    let step = if scaled < 0.0 { -1 } else { 1 };
    let rounded = if frac.abs() > 0.5 || (frac.abs() == 0.5 && truncated & 1 == 1) {
        truncated + step
    } else {
        truncated
    };
    // |rounded| ≤ 2^28 + 1: the step cannot overflow.
    if in_range(i64::from(rounded)) { Ok(rounded) } else { Err(Error::CoordinateOutOfRange) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_snapping_rounds_half_to_even() {
        // 0.5/256 px ties: 1.5 subpixel → 2, 2.5 → 2, -1.5 → -2.
        let p = SubPoint::<8>::from_f32(1.5 / 256.0, 2.5 / 256.0).unwrap();
        assert_eq!((p.x(), p.y()), (2, 2));
        let p = SubPoint::<8>::from_f32(-1.5 / 256.0, -2.6 / 256.0).unwrap();
        assert_eq!((p.x(), p.y()), (-2, -3));
    }

    #[test]
    fn f32_snapping_matches_an_f64_rounding_on_both_sides_of_2_pow_22() {
        // The reference: f64 holds `v · 2^s` exactly; round half to even by hand.
        let reference = |v: f32, s: u32| -> i64 {
            let x = f64::from(v) * f64::from(1u32 << s);
            let f = x.floor();
            let d = x - f;
            let r = if d > 0.5 || (d == 0.5 && f % 2.0 != 0.0) { f + 1.0 } else { f };
            r as i64
        };
        let mut rng = crate::test_rng::Rng(0x9e37_79b9_7f4a_7c15);
        for i in 0..200_000u32 {
            let s = i % (MAX_SUBPIXEL_BITS + 1);
            let r = rng.next();
            // Magnitudes up to 2^(10..26) subpixels; a quarter exact ties
            // (k + ½ subpixels), a few right at the fast path's 2^22 bound.
            let mag = (r >> 40) as f32 / (1u64 << 24) as f32 * (1u64 << (10 + (r % 17))) as f32;
            let mut scaled = if r & 3 == 0 { mag.floor() + 0.5 } else { mag };
            if r.is_multiple_of(101) {
                scaled = (1u32 << 22) as f32 + [-1.5f32, -0.5, 0.0, 0.5, 1.0][(r % 5) as usize];
            }
            let scaled = if r & 4 == 0 { -scaled } else { scaled };
            let v = scaled / (1u32 << s) as f32;
            let got = snap_f32_bits(v, s).map(i64::from);
            let want = reference(v, s);
            if want.abs() <= 1 << 28 {
                assert_eq!(got, Ok(want), "{v:e} at {s} bits");
            } else {
                assert_eq!(got, Err(Error::CoordinateOutOfRange), "{v:e} at {s} bits");
            }
        }
    }

    #[test]
    fn non_finite_and_out_of_range_are_errors() {
        for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            assert_eq!(SubPoint::<4>::from_f32(bad, 0.0), Err(Error::NonFiniteCoordinate));
            assert_eq!(SubPoint::<4>::from_f32(0.0, bad), Err(Error::NonFiniteCoordinate));
        }
        let limit = (1 << 24) as f32; // 2^28 subpixels at S = 4
        assert!(SubPoint::<4>::from_f32(limit, -limit).is_ok());
        assert_eq!(SubPoint::<4>::from_f32(limit * 2.0, 0.0), Err(Error::CoordinateOutOfRange));
        assert_eq!(SubPoint::<4>::from_f32(f32::MAX, 0.0), Err(Error::CoordinateOutOfRange));
        assert_eq!(SubPoint::<8>::from_pixels(1 << 20, 0).map(|p| p.x()), Ok(1 << 28));
        assert_eq!(SubPoint::<8>::from_pixels((1 << 20) + 1, 0), Err(Error::CoordinateOutOfRange));
        assert_eq!(SubPoint::<0>::new(i32::MIN, 0), Err(Error::CoordinateOutOfRange));
    }

    #[test]
    fn fixed_and_pixel_centre_agree_with_f32() {
        use fixed::types::I24F8;
        for i in -50..50 {
            let v = i as f32 * 0.37;
            let a = SubPoint::<6>::from_f32(v, -v).unwrap();
            let b = SubPoint::<6>::from_fixed(I24F8::from_num(v), I24F8::from_num(-v)).unwrap();
            // The I24F8 conversion itself rounds, so allow the one double-rounding step.
            assert!((a.x() - b.x()).abs() <= 1 && (a.y() - b.y()).abs() <= 1);
        }
        let c = SubPoint::<3>::pixel_center(2, -1).unwrap();
        assert_eq!(c.to_f64(), (2.5, -0.5));
    }
}
