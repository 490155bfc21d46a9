//! Texel formats: how a texel is stored in flash and expanded to 8-bit
//! channels.

use core::fmt::Debug;
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565};

mod sealed {
    pub trait Sealed {}
    impl Sealed for embedded_graphics_core::pixelcolor::Rgb565 {}
    impl Sealed for embedded_graphics_core::pixelcolor::Gray8 {}
    impl Sealed for crate::texture::A8 {}
    impl Sealed for crate::texture::Argb4444 {}
    impl Sealed for crate::texture::Rgb565A8 {}
}

/// A texel format. Sealed: implemented by the `embedded-graphics` colour
/// types [`Rgb565`] (a `u16` per texel) and [`Gray8`] (a `u8`), so a texture
/// reads as `Texture<'static, Rgb565>`, and by the formats with alpha
/// [`A8`](crate::texture::A8), [`Argb4444`](crate::texture::Argb4444) and
/// [`Rgb565A8`](crate::texture::Rgb565A8).
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, Rgb565};
/// use microraster::texture::TexelFormat;
/// // 5/6/5 bits expanded to 8 by bit replication: full scale stays full scale.
/// assert_eq!(Rgb565::expand(0xFFFF), [255, 255, 255]);
/// assert_eq!(Rgb565::expand(0b10000_100000_00001), [132, 130, 8]);
/// assert_eq!(Gray8::expand(77), [77, 77, 77]);
/// ```
pub trait TexelFormat: sealed::Sealed {
    /// One stored texel: `u16` raw bits for [`Rgb565`] (red in bits 15–11,
    /// green 10–5, blue 4–0: `embedded-graphics`' `RawU16`), `u8` for
    /// [`Gray8`], `[u8; 3]` for [`Rgb565A8`](crate::texture::Rgb565A8).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, Rgb565};
    /// use microraster::texture::{A8, Argb4444, Rgb565A8, TexelFormat};
    /// let sizes = [size_of::<<Rgb565 as TexelFormat>::Storage>(), size_of::<<Gray8 as TexelFormat>::Storage>()];
    /// assert_eq!(sizes, [2, 1]);
    /// assert_eq!([size_of::<<A8 as TexelFormat>::Storage>(), size_of::<<Argb4444 as TexelFormat>::Storage>()], [1, 2]);
    /// assert_eq!(size_of::<<Rgb565A8 as TexelFormat>::Storage>(), 3); // no padding: 3 bytes a texel
    /// ```
    type Storage: Copy + Default + Debug + PartialEq + 'static;

    /// Channels that carry information (3 for [`Rgb565`], 1 for [`Gray8`]);
    /// filters only compute these and copy channel 0 to the others.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, Rgb565};
    /// use microraster::texture::{A8, Argb4444, Rgb565A8, TexelFormat};
    /// assert_eq!([Rgb565::CHANNELS, Gray8::CHANNELS, A8::CHANNELS, Argb4444::CHANNELS], [3, 1, 1, 3]);
    /// assert_eq!(Rgb565A8::CHANNELS, 3);
    /// ```
    const CHANNELS: usize;

    /// The texel's channels at 8 bits. [`Rgb565`]: each channel by bit
    /// replication (`r8 = r5·2^3 + r5/2^2`, `g8 = g6·2^2 + g6/2^4`), which maps
    /// 0 to 0 and the maximum to 255 and is within 0.72 of the exact
    /// `c·255/max` (0.68 for the 5-bit channels; it is the rounded value for
    /// all but 4 of 32 and 10 of 64 inputs). [`Gray8`]: the grey level in all
    /// three channels.
    fn expand(texel: Self::Storage) -> [u8; 3];

    /// True for formats with an alpha channel ([`A8`](crate::texture::A8),
    /// [`Argb4444`](crate::texture::Argb4444),
    /// [`Rgb565A8`](crate::texture::Rgb565A8)).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, Rgb565};
    /// use microraster::texture::{A8, Argb4444, Rgb565A8, TexelFormat};
    /// assert!(!Rgb565::ALPHA && !Gray8::ALPHA);
    /// assert!(A8::ALPHA && Argb4444::ALPHA && Rgb565A8::ALPHA);
    /// ```
    const ALPHA: bool = false;

    /// The texel's alpha at 8 bits (255, opaque, for formats without one).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use microraster::texture::{A8, Argb4444, TexelFormat};
    /// assert_eq!(Rgb565::alpha(0x1234), 255); // no alpha channel: opaque
    /// assert_eq!(A8::alpha(77), 77);
    /// // The top nibble, 4 bits to 8 by replication (×17): 8 → 136, 15 → 255.
    /// assert_eq!(Argb4444::alpha(0x80F0), 136);
    /// assert_eq!(Argb4444::alpha(0xF000), 255);
    /// assert_eq!(microraster::texture::Rgb565A8::alpha([0xFF, 0xFF, 77]), 77); // 8 bits, as stored
    /// ```
    #[inline]
    fn alpha(texel: Self::Storage) -> u8 {
        let _ = texel;
        255
    }
}

impl TexelFormat for Rgb565 {
    type Storage = u16;
    const CHANNELS: usize = 3;

    #[inline]
    fn expand(t: u16) -> [u8; 3] {
        // Fields are at most 6 bits wide, so the casts cannot truncate.
        let (r, g, b) = ((t >> 11) as u8, ((t >> 5) & 0x3F) as u8, (t & 0x1F) as u8);
        [(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2)]
    }
}

impl TexelFormat for Gray8 {
    type Storage = u8;
    const CHANNELS: usize = 1;

    #[inline]
    fn expand(t: u8) -> [u8; 3] {
        [t; 3]
    }
}
