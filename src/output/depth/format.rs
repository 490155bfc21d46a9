//! The depth formats ([`DepthFormat`]: [`NoDepth`], [`Depth8`] to [`Depth32`])
//! and the exact quantization of a depth into them ([`quantize_unit`],
//! [`quantize_f32`]), split from `depth.rs` so the band and its test stay short.

use crate::Error;
use core::fmt::Debug;

mod sealed {
    pub trait Sealed {}
}

/// A depth-buffer format: how many bits each depth value keeps. Sealed;
/// implemented by [`NoDepth`], [`Depth8`], [`Depth16`], [`Depth24`] and
/// [`Depth32`].
pub trait DepthFormat: sealed::Sealed {
    /// The stored value (`()` for [`NoDepth`]).
    type Storage: Copy + Ord + Default + Debug;
    /// Bits of depth kept (0 for [`NoDepth`]).
    const BITS: u32;
    /// False only for [`NoDepth`], which has no depth test.
    const ENABLED: bool;
    /// The largest value, `2^BITS − 1` (0 for [`NoDepth`]).
    const MAX: u32;
    /// The value a cleared buffer holds: `MAX`, the far plane.
    const FAR: Self::Storage;
    /// The value 0 (the near plane).
    const ZERO: Self::Storage;
    /// The stored form of `v`, which should be in `0..=MAX`; larger values
    /// clamp to `MAX`.
    fn from_u32(v: u32) -> Self::Storage;
    /// The value of a stored depth, in `0..=MAX`.
    fn to_u32(s: Self::Storage) -> u32;
}

/// No depth buffer: zero bytes, no per-pixel work, every test passes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct NoDepth;

impl sealed::Sealed for NoDepth {}
impl DepthFormat for NoDepth {
    type Storage = ();
    const BITS: u32 = 0;
    const ENABLED: bool = false;
    const MAX: u32 = 0;
    const FAR: () = ();
    const ZERO: () = ();
    #[inline(always)]
    fn from_u32(_: u32) {}
    #[inline(always)]
    fn to_u32(_: ()) -> u32 {
        0
    }
}

macro_rules! formats {
    ($($(#[$doc:meta])* $name:ident: $storage:ty = $bits:literal;)*) => {$(
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        pub struct $name;

        impl sealed::Sealed for $name {}
        impl DepthFormat for $name {
            type Storage = $storage;
            const BITS: u32 = $bits;
            const ENABLED: bool = true;
            const MAX: u32 = u32::MAX >> (32 - $bits);
            const FAR: $storage = Self::MAX as $storage;
            const ZERO: $storage = 0;
            #[inline(always)]
            fn from_u32(v: u32) -> $storage {
                // In range after the clamp, so the cast never truncates.
                v.min(Self::MAX) as $storage
            }
            #[inline(always)]
            fn to_u32(s: $storage) -> u32 {
                u32::from(s)
            }
        }
    )*};
}

formats! {
    /// 8-bit depth in a `u8`.
    Depth8: u8 = 8;
    /// 16-bit depth in a `u16`: 2 bytes a pixel, the usual choice.
    ///
    /// ```
    /// use microraster::depth::{Depth16, DepthBand, DepthFormat};
    /// assert_eq!(Depth16::FAR, 0xFFFF);
    /// let z = DepthBand::<Depth16, 240, 16>::new();
    /// assert_eq!(core::mem::size_of_val(&z), 240 * 16 * 2);
    /// ```
    Depth16: u16 = 16;
    /// 24-bit depth in a `u32` (the top 8 bits are always 0).
    Depth24: u32 = 24;
    /// 32-bit depth in a `u32`.
    Depth32: u32 = 32;
}

/// `1.0` in the 0.32 fixed-point input of [`quantize_unit`]: `2^32`.
pub const UNIT_ONE: u64 = 1 << 32;

/// Quantizes a depth `u = d · 2^32` (`0..=`[`UNIT_ONE`]; larger values clamp)
/// to `round(u · MAX / 2^32)`, exactly, ties up. This is the reference the
/// rasterizer's depth planes are measured against.
#[inline]
pub fn quantize_unit<F: DepthFormat>(u: u64) -> F::Storage {
    F::from_u32(unit_to_code(u, F::MAX))
}

/// Quantizes `d ∈ [0, 1]` to `round(d · MAX)`, exactly, ties up; values
/// outside `[0, 1]` clamp (see the [module docs](crate::depth#quantization-guarantee)).
///
/// # Errors
/// [`Error::NonFiniteCoordinate`] if `d` is NaN or infinite.
#[inline]
pub fn quantize_f32<F: DepthFormat>(d: f32) -> Result<F::Storage, Error> {
    f32_to_code(d, F::MAX).map(F::from_u32)
}

fn unit_to_code(u: u64, max: u32) -> u32 {
    let u = u.min(UNIT_ONE);
    // u · max ≤ 2^32 · (2^32 − 1) = 2^64 − 2^32, so adding 2^31 cannot overflow;
    // the quotient is at most max.
    ((u * max as u64 + (1 << 31)) >> 32) as u32
}

fn f32_to_code(d: f32, max: u32) -> Result<u32, Error> {
    let bits = d.to_bits();
    if bits & 0x7F80_0000 == 0x7F80_0000 {
        return Err(Error::NonFiniteCoordinate);
    }
    if bits >> 31 == 1 {
        return Ok(0); // negative or -0.0
    }
    if bits >= 1.0f32.to_bits() {
        return Ok(max);
    }
    // 0 ≤ d < 1 is exactly m · 2^-s with m < 2^24 and 24 ≤ s ≤ 149.
    let exp = bits >> 23;
    let (m, s) = if exp == 0 { (bits, 149) } else { (bits & 0x7F_FFFF | 0x80_0000, 150 - exp) };
    if s > 56 {
        return Ok(0); // d · max < 2^24 · 2^32 · 2^-57 = 1/2
    }
    // m · max < 2^56 and the half is at most 2^55: no overflow; result ≤ max.
    Ok(((m as u64 * max as u64 + (1 << (s - 1))) >> s) as u32)
}
