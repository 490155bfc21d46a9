//! Texel formats with alpha, and sampling colour and alpha together.
//!
//! * [`A8`]: an 8-bit alpha mask (a `u8` per texel), white in colour: tinted
//!   by the sprite's or shader's colour, it draws anti-aliased glyphs,
//!   icons and soft shapes in any colour.
//! * [`Argb4444`]: 16-bit colour + alpha (a `u16`: alpha in bits 15–12,
//!   red 11–8, green 7–4, blue 3–0), each nibble expanded to 8 bits as
//!   `n·17` (exact: 15 ↦ 255).
//! * [`Rgb565A8`]: `Rgb565` colour and 8-bit alpha in 3 bytes (`[u8; 3]`:
//!   the colour's raw bits big-endian, then alpha), for icons whose alpha
//!   gradients would band at 16 levels. Colour expands as
//!   `Rgb565`'s does (bit
//!   replication), alpha is exact.
//!
//! `Rgb565A8` interleaves colour and alpha rather than storing two planes:
//! a texel is one read from one place (flash prefetch and caches see one
//! stream, not two), `Texture` stays one slice for every format, and 3
//! bytes cost 25 % less flash than padding to a `u32`. Big-endian colour
//! reads as `0xRRGG…` in the generated hex and is the byte order SPI panels
//! take.
//!
//! Alpha is *straight* (not premultiplied), and bilinear filtering blends
//! each channel and alpha independently with the same weights and bounds
//! as colour (½ + 2^-9 of the exact blend). A transparent texel's colour
//! still enters its neighbours' blends, so give transparent texels the
//! colour of the opaque texels next to them (or black for an additive
//! look); `png2rs` keeps what the PNG stores.

use super::Texture;
use super::format::TexelFormat;
use super::sampler::{Filter, Sampler, bilerp};
use embedded_graphics_core::pixelcolor::Rgb565;

/// An 8-bit alpha mask: `u8` coverage per texel, colour white.
///
/// ```
/// use microraster::texture::{A8, Sampler, TexelFormat, Texture, UV_ONE};
/// assert_eq!((A8::expand(77), A8::alpha(77)), ([255; 3], 77));
/// static MASK: [[u8; 2]; 1] = [[0, 255]];
/// static TEX: Texture<'static, A8> = Texture::from_rows(&MASK);
/// // Half-way between the two texel centres: half covered.
/// assert_eq!(TEX.sample_rgba(Sampler::BILINEAR_CLAMP, [UV_ONE / 2, UV_ONE / 2]), [255, 255, 255, 128]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct A8;

/// 16-bit colour and alpha, 4 bits each: `0xARGB` in a `u16`.
///
/// ```
/// use microraster::texture::{Argb4444, TexelFormat};
/// assert_eq!(Argb4444::expand(0x8F40), [255, 68, 0]);
/// assert_eq!(Argb4444::alpha(0x8F40), 136);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Argb4444;

/// `Rgb565` colour with 8-bit alpha: `[colour bits 15–8, colour bits 7–0,
/// alpha]` per texel (3 interleaved bytes: one read per texel, one slice
/// per texture, a quarter less flash than a `u32`). Build texels with [`Rgb565A8::texel`].
///
/// ```
/// use microraster::texture::{Rgb565A8, Sampler, TexelFormat, Texture, UV_ONE};
/// let orange = Rgb565A8::texel(0xFC00, 200); // red 31, green 32, blue 0; alpha 200
/// assert_eq!(orange, [0xFC, 0x00, 200]);
/// assert_eq!((Rgb565A8::expand(orange), Rgb565A8::alpha(orange)), ([255, 130, 0], 200));
/// static ICON: [[[u8; 3]; 2]; 1] = [[Rgb565A8::texel(0xFFFF, 0), Rgb565A8::texel(0xFFFF, 255)]];
/// static TEX: Texture<'static, Rgb565A8> = Texture::from_rows(&ICON);
/// // Half-way between the texel centres: alpha 127.5, rounded half up; no 16-level steps.
/// assert_eq!(TEX.sample_rgba(Sampler::BILINEAR_CLAMP, [UV_ONE / 2, 0]), [255, 255, 255, 128]);
/// assert_eq!(TEX.sample_rgba(Sampler::BILINEAR_CLAMP, [UV_ONE * 3 / 8, 0]), [255, 255, 255, 64]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Rgb565A8;

impl Rgb565A8 {
    /// The texel of raw `Rgb565` bits `rgb565` (red 15–11, green 10–5, blue
    /// 4–0, as [`Texture<Rgb565>`](Texture) stores them) and alpha `alpha`
    /// (straight, 255 opaque). A `const fn`, for `static` texel arrays.
    ///
    /// ```
    /// use microraster::texture::Rgb565A8;
    /// assert_eq!(Rgb565A8::texel(0x07E0, 128), [0x07, 0xE0, 128]); // green, half covered
    /// ```
    pub const fn texel(rgb565: u16, alpha: u8) -> [u8; 3] {
        let [hi, lo] = rgb565.to_be_bytes();
        [hi, lo, alpha]
    }
}

impl TexelFormat for A8 {
    type Storage = u8;
    const CHANNELS: usize = 1;
    const ALPHA: bool = true;

    #[inline]
    fn expand(_: u8) -> [u8; 3] {
        [255; 3]
    }

    #[inline]
    fn alpha(t: u8) -> u8 {
        t
    }
}

impl TexelFormat for Argb4444 {
    type Storage = u16;
    const CHANNELS: usize = 3;
    const ALPHA: bool = true;

    #[inline]
    fn expand(t: u16) -> [u8; 3] {
        // Each nibble ≤ 15, times 17 ≤ 255: the casts are exact.
        [8, 4, 0].map(|s| ((t >> s) & 0xF) as u8 * 17)
    }

    #[inline]
    fn alpha(t: u16) -> u8 {
        (t >> 12) as u8 * 17
    }
}

impl TexelFormat for Rgb565A8 {
    type Storage = [u8; 3];
    const CHANNELS: usize = 3;
    const ALPHA: bool = true;

    #[inline]
    fn expand(t: [u8; 3]) -> [u8; 3] {
        Rgb565::expand(u16::from_be_bytes([t[0], t[1]]))
    }

    #[inline]
    fn alpha(t: [u8; 3]) -> u8 {
        t[2]
    }
}

impl<F: TexelFormat> Texture<'_, F> {
    /// The texel at column `x`, row `y` as 8-bit red, green, blue and alpha
    /// (alpha 255 for formats without one); `None` outside the texture.
    ///
    /// ```
    /// use microraster::texture::{Argb4444, Texture};
    /// let tex = Texture::<Argb4444>::new(&[0x0000, 0xF0F0], 2, 1)?;
    /// assert_eq!(tex.texel_rgba(1, 0), Some([0, 255, 0, 255]));
    /// assert_eq!(tex.texel_rgba(2, 0), None);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn texel_rgba(&self, x: u32, y: u32) -> Option<[u8; 4]> {
        (x < self.width() && y < self.height()).then(|| self.fetch_rgba(x, y))
    }

    /// [`Texture::sample`] with alpha: red, green, blue and alpha at 8 bits,
    /// filtered alike (exact for [`Nearest`](super::Nearest), ½ + 2^-9 of
    /// the exact blend for [`Bilinear`](super::Bilinear)).
    ///
    /// ```
    /// use microraster::texture::{Argb4444, Sampler, Texture, UV_ONE};
    /// static TEXELS: [[u16; 2]; 1] = [[0x0F00, 0xFF00]]; // clear red, opaque red
    /// static TEX: Texture<'static, Argb4444> = Texture::from_rows(&TEXELS);
    /// assert_eq!(TEX.sample_rgba(Sampler::NEAREST_CLAMP, [UV_ONE / 4, 0]), [255, 0, 0, 0]);
    /// assert_eq!(TEX.sample_rgba(Sampler::BILINEAR_CLAMP, [UV_ONE / 2, 0]), [255, 0, 0, 128]);
    /// ```
    #[inline]
    pub fn sample_rgba<Fi: Filter>(&self, sampler: Sampler<Fi>, uv: [i32; 2]) -> [u8; 4] {
        let s = [sampler.address_u, sampler.address_v];
        if !Fi::BILINEAR {
            let (x, y) = (self.u.nearest(uv[0], s[0]), self.v.nearest(uv[1], s[1]));
            return self.fetch_rgba(x, y);
        }
        let (x0, x1, fx) = self.u.linear(uv[0], s[0]);
        let (y0, y1, fy) = self.v.linear(uv[1], s[1]);
        let t = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].map(|(x, y)| self.fetch_rgba(x, y));
        let mut out = [0u8; 4];
        for k in 0..F::CHANNELS {
            out[k] = bilerp(t.map(|c| c[k]), fx, fy);
        }
        if F::CHANNELS == 1 {
            out = [out[0], out[0], out[0], 0];
        }
        out[3] = if F::ALPHA { bilerp(t.map(|c| c[3]), fx, fy) } else { 255 };
        out
    }

    /// The texel at `(x, y)` (inside the texture, guaranteed by the callers;
    /// a miss reads the default texel, never panics) with its alpha.
    #[inline(always)]
    fn fetch_rgba(&self, x: u32, y: u32) -> [u8; 4] {
        let t = self.data.get(self.u.offset(y) + x as usize).copied().unwrap_or_default();
        let [r, g, b] = F::expand(t);
        [r, g, b, F::alpha(t)]
    }
}
