//! Colour channels for interpolation.
//!
//! Gouraud shading interpolates each channel in the colour's *native* depth
//! (5/6/5 bits for [`Rgb565`], 8 bits for [`Gray8`], 1 bit for
//! [`BinaryColor`]), so no precision is invented and none is lost converting.

use embedded_graphics_core::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, GrayColor, Rgb555, Rgb565, Rgb666,
    Rgb888, RgbColor,
};
use embedded_graphics_core::prelude::PixelColor;

/// A colour whose channels can be read and written as small integers.
///
/// Implemented for every `embedded-graphics` RGB, BGR and grey colour type and
/// for [`BinaryColor`]. Unused channels are 0 with a maximum of 0.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::Interpolate;
/// let c = Rgb565::new(31, 10, 3);
/// assert_eq!(c.to_channels(), [31, 10, 3]);
/// assert_eq!(Rgb565::CHANNEL_MAX, [31, 63, 31]);
/// assert_eq!(Rgb565::from_channels([31, 10, 3]), c);
/// ```
pub trait Interpolate: PixelColor {
    /// The largest value of each channel (0 for channels the type lacks).
    const CHANNEL_MAX: [u8; 3];

    /// The channel values, each in `0..=CHANNEL_MAX[i]`.
    fn to_channels(self) -> [u8; 3];

    /// The colour with these channel values; values above the maximum are
    /// clamped to it.
    fn from_channels(c: [u8; 3]) -> Self;
}

macro_rules! rgb {
    ($($t:ty),*) => {$(
        impl Interpolate for $t {
            const CHANNEL_MAX: [u8; 3] = [<$t>::MAX_R, <$t>::MAX_G, <$t>::MAX_B];
            #[inline]
            fn to_channels(self) -> [u8; 3] {
                [self.r(), self.g(), self.b()]
            }
            #[inline]
            fn from_channels(c: [u8; 3]) -> Self {
                let m = Self::CHANNEL_MAX;
                <$t>::new(c[0].min(m[0]), c[1].min(m[1]), c[2].min(m[2]))
            }
        }
    )*};
}
rgb!(Rgb555, Bgr555, Rgb565, Bgr565, Rgb666, Bgr666, Rgb888, Bgr888);

macro_rules! gray {
    ($($t:ty = $max:expr),*) => {$(
        impl Interpolate for $t {
            const CHANNEL_MAX: [u8; 3] = [$max, 0, 0];
            #[inline]
            fn to_channels(self) -> [u8; 3] {
                [self.luma(), 0, 0]
            }
            #[inline]
            fn from_channels(c: [u8; 3]) -> Self {
                <$t>::new(c[0].min($max))
            }
        }
    )*};
}
gray!(Gray2 = 3, Gray4 = 15, Gray8 = 255);

impl Interpolate for BinaryColor {
    const CHANNEL_MAX: [u8; 3] = [1, 0, 0];
    #[inline]
    fn to_channels(self) -> [u8; 3] {
        [self.is_on() as u8, 0, 0]
    }
    #[inline]
    fn from_channels(c: [u8; 3]) -> Self {
        BinaryColor::from(c[0] != 0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip<C: Interpolate + core::fmt::Debug>() -> usize {
        let m = C::CHANNEL_MAX;
        let mut n = 0;
        for r in 0..=m[0] {
            for g in (0..=m[1]).step_by(3) {
                for b in (0..=m[2]).step_by(5) {
                    assert_eq!(C::from_channels([r, g, b]).to_channels(), [r, g, b]);
                    n += 1;
                }
            }
        }
        assert_eq!(C::from_channels([255, 255, 255]).to_channels(), m, "clamped to max");
        n
    }

    #[test]
    fn channels_round_trip_and_clamp() {
        let n = round_trip::<Rgb565>()
            + round_trip::<Bgr565>()
            + round_trip::<Rgb888>()
            + round_trip::<Rgb666>()
            + round_trip::<Rgb555>()
            + round_trip::<Gray8>()
            + round_trip::<Gray4>()
            + round_trip::<Gray2>()
            + round_trip::<BinaryColor>();
        assert!(n > 1000);
    }
}
