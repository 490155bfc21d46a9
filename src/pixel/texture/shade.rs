//! Texel colour meets vertex colour: modulation, and conversion between
//! 8-bit channels and any [`Interpolate`] colour.
//!
//! Every function here is exact up to one stated rounding; each uses only
//! `u32` multiplies, adds and shifts (no division, so the Cortex-M0 pays no
//! library call).

use crate::Interpolate;

/// `round(x / 255)` for `x ≤ 255·255`, exactly (255 is odd: no ties). The
/// classic identity `⌊(y + ⌊y/256⌋)/256⌋ = ⌊(x + 127)/255⌋` with `y = x + 128`
/// holds over that range (checked exhaustively by a unit test).
#[inline(always)]
pub(crate) const fn div255_round(x: u32) -> u32 {
    let y = x + 128;
    (y + (y >> 8)) >> 8
}

/// The texel `texel` modulated (multiplied) by `color`, channel by channel,
/// both at 8 bits: exactly `round(t·c/255)`, so white (255) leaves the
/// texel unchanged and black gives black.
///
/// ```
/// use microraster::texture::modulate;
/// assert_eq!(modulate([200, 100, 255], [255, 128, 0]), [200, 50, 0]); // 100·128/255 = 50.2
/// ```
#[inline]
pub fn modulate(texel: [u8; 3], color: [u8; 3]) -> [u8; 3] {
    // t·c ≤ 255², so the result is ≤ 255 and the cast exact.
    [0, 1, 2].map(|k| div255_round(u32::from(texel[k]) * u32::from(color[k])) as u8)
}

/// Rec. 601 luma `0.299 r + 0.587 g + 0.114 b` of 8-bit channels, rounded:
/// weights in 2^-16 (19595, 38470, 7471, summing to 2^16, so grey stays
/// exactly grey). Within ½ + 0.003 of the exact value (the weights are within
/// 6·10^-6 of Rec. 601's; tested on all 2^24 inputs).
///
/// ```
/// use microraster::texture::luma;
/// assert_eq!(luma([255, 255, 255]), 255);
/// assert_eq!(luma([255, 0, 0]), 76); // 76.245
/// ```
#[inline]
pub fn luma(rgb: [u8; 3]) -> u8 {
    let [r, g, b] = rgb.map(u32::from);
    // ≤ 255·2^16 + 2^15 < 2^24; the shifted sum is ≤ 255.
    ((19595 * r + 38470 * g + 7471 * b + (1 << 15)) >> 16) as u8
}

/// `round(c·255/max)` for `c ≤ max` (larger `c` count as `max`; 0 for
/// `max = 0`).
#[inline(always)]
pub(crate) fn channel_to_8bit(c: u8, max: u8) -> u8 {
    let (c, max) = (u32::from(c.min(max)), u32::from(max));
    if max == 0 {
        return 0;
    }
    // `max` is a constant of the colour type, so is this reciprocal, rounded
    // up; with it `round(c·255/max)` is exact for every max in 1..=255
    // (checked exhaustively by a unit test), and
    // c·255·r + 2^23 ≤ 255·2^24 + 255² + 2^23 < 2^32.
    let r = (1u32 << 24).div_ceil(max);
    ((c * 255 * r + (1 << 23)) >> 24) as u8
}

const fn is_grey<C: Interpolate>() -> bool {
    C::CHANNEL_MAX[1] == 0 && C::CHANNEL_MAX[2] == 0
}

/// Channels of colour type `C` in its native depth (as
/// [`Interpolate::to_channels`] and
/// [`ScreenVertex::color`](crate::raster3d::ScreenVertex::color) hold them)
/// at 8 bits: each `round(c·255/max)`, exact (every `max` is `2^b − 1`, odd:
/// no ties); values above `max` count as `max`. Grey and binary colours
/// (`CHANNEL_MAX = [max, 0, 0]`) give their level in all three channels, so
/// they modulate colour texels as a light intensity.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray4, Rgb565};
/// use microraster::texture::to_rgb8;
/// assert_eq!(to_rgb8::<Rgb565>([31, 32, 0]), [255, 130, 0]); // 32·255/63 = 129.5…
/// assert_eq!(to_rgb8::<Gray4>([5, 0, 0]), [85; 3]);
/// ```
#[inline]
pub fn to_rgb8<C: Interpolate>(native: [u8; 3]) -> [u8; 3] {
    let one = channel_to_8bit;
    let m = C::CHANNEL_MAX;
    if is_grey::<C>() { [one(native[0], m[0]); 3] } else { [0, 1, 2].map(|k| one(native[k], m[k])) }
}

/// The colour of type `C` nearest to 8-bit channels `rgb`: each channel
/// `round(v·max/255)`, exact. Grey and binary colours take the [`luma`] of
/// `rgb` first (for a grey input, exactly that grey), then round it the same
/// way: within ½ + (½ + 0.003)·max/255 of the exact Rec. 601 value in
/// native units.
///
/// ```
/// use embedded_graphics::pixelcolor::{BinaryColor, Gray8, Rgb565};
/// use microraster::texture::from_rgb8;
/// assert_eq!(from_rgb8::<Rgb565>([255, 130, 4]), Rgb565::new(31, 32, 0));
/// assert_eq!(from_rgb8::<Gray8>([90, 90, 90]), Gray8::new(90));
/// assert_eq!(from_rgb8::<BinaryColor>([200, 200, 200]), BinaryColor::On);
/// ```
#[inline]
pub fn from_rgb8<C: Interpolate>(rgb: [u8; 3]) -> C {
    let m = C::CHANNEL_MAX;
    // v·max ≤ 255², so the rounded quotient is ≤ max and the cast exact.
    let one = |v: u8, max: u8| div255_round(u32::from(v) * u32::from(max)) as u8;
    if is_grey::<C>() {
        C::from_channels([one(luma(rgb), m[0]), 0, 0])
    } else {
        C::from_channels([0, 1, 2].map(|k| one(rgb[k], m[k])))
    }
}
