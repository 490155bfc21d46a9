//! Read-only textures in `&'static` data (flash), sampled per fragment.
//!
//! A [`Texture<'a, F>`](Texture) is a row-major slice of texels in format
//! `F` ([`Rgb565`](embedded_graphics::pixelcolor::Rgb565): `u16` raw
//! bits; [`Gray8`](embedded_graphics::pixelcolor::Gray8): `u8`; with
//! alpha, [`A8`], [`Argb4444`] and [`Rgb565A8`]; see [`TexelFormat`]) and its size, 1 to [`MAX_TEXTURE_DIM`] texels each way
//! (any size; powers of two index with shifts instead of multiplies).
//! `cargo run -p microraster-tools --bin png2rs` (or
//! `microraster_tools::png::convert` in a build script) converts a PNG to a
//! `static` texture.
//! [`Sprite`] draws a texture at a position, scaled and rotated, in one call.
//!
//! # Coordinates
//! `u` (across) and `v` (down) are `i32` fixed point with [`UV_FRAC`] = 16
//! fraction bits: [`UV_ONE`] (2^16) is one texture width or height. Texel
//! `(i, j)` covers `[i, i + 1)/width × [j, j + 1)/height`, so its centre is
//! at `((i + ½)/width, (j + ½)/height)` (the D3D/GL convention). Every `i32`
//! is accepted (never a panic or overflow); through
//! [`Varyings`](crate::varyings::Varyings), whose values are limited to
//! `|v| ≤ 2^23`, that is up to ±128 texture repeats across a triangle. The
//! coordinate resolution is 2^-16 of the texture, i.e. `size/2^16` texel
//! (1/16 texel at 4096 texels).
//!
//! Interpolate `(u, v)` with `Varyings::<2>` — [`PerspectiveCorrect`] for
//! textures that stay put on slanted surfaces, [`Affine`] as the cheaper
//! option (one division per value and pixel less; textures swim on surfaces
//! that recede) — and sample in the
//! [`draw_fragments`](crate::varyings::draw_fragments) hook.
//!
//! # Accuracy
//! Against the exact value computed in `f64` from the same inputs:
//!
//! | function | inputs | result | error bound |
//! |---|---|---|---|
//! | [`Texture::sample`], [`Nearest`] | any `[i32; 2]` | 8-bit channels | exact: the texel containing `(u, v)` |
//! | [`Texture::sample`], [`Bilinear`] | any `[i32; 2]` | 8-bit channels | ½ + 2^-9 of the exact bilinear blend |
//! | [`TexelFormat::expand`] (Rgb565, [`Rgb565A8`]) | 5/6-bit channel | 8 bits | 0.72 of `c·255/max` (bit replication) |
//! | [`TexelFormat::alpha`] | stored alpha | 8 bits | exact ([`Argb4444`]: `n·17`, exact) |
//! | [`modulate`] | 8-bit channels | 8 bits | exact `round(t·c/255)` |
//! | [`to_rgb8`] | native channels | 8 bits | exact `round(c·255/max)` |
//! | [`from_rgb8`] (RGB) | 8-bit channels | native | exact `round(v·max/255)` |
//! | [`luma`] | 8-bit channels | 8 bits | ½ + 0.003 of Rec. 601 |
//!
//! The bilinear blend is taken over the expanded 8-bit texels with the exact
//! weights: the texel-space position `u·size − ½` is exact in units of 2^-16
//! texel, the row blends are exact and rounded to 2^-8, the column blend
//! rounds once more to 8 bits.
//!
//! # Example: a textured, tinted, perspective-correct triangle
//! ```
//! use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
//! use microraster::depth::{DepthBand, DepthState, NoDepth};
//! use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle, ScreenVertex};
//! use microraster::texture::{from_rgb8, modulate, Sampler, Texture, UV_ONE};
//! use microraster::varyings::{Varyings, draw_fragments};
//! use microraster::{Band, SubPoint};
//!
//! // A 2×2 white/black checker in flash (raw Rgb565 bits).
//! static CHECKER: [[u16; 2]; 2] = [[0xFFFF, 0x0000], [0x0000, 0xFFFF]];
//! static TEX: Texture<'static, Rgb565> = Texture::from_rows(&CHECKER);
//!
//! let v = |x, y, inv_w| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), inv_w, ..Default::default() };
//! // The right vertex is 4× farther away than the others.
//! let tri = ScreenTriangle { v: [v(0, 0, 1 << 30), v(16, 0, 1 << 28), v(0, 16, 1 << 30)], flat: false };
//! let uv = [[0, 0], [4 * UV_ONE, 0], [0, 4 * UV_ONE]]; // 4 repeats
//! let uv = Varyings::new(&tri, uv, PerspectiveCorrect)?.unwrap();
//! let tint = [255, 160, 0]; // orange, at 8 bits
//!
//! let mut band = Band::<Rgb888, 16, 16>::new(Rgb888::BLACK);
//! let mut depth = DepthBand::<NoDepth, 16, 16>::new();
//! let mut view = band.view(0, 16, Rgb888::BLACK);
//! draw_fragments(&tri, &mut view, &mut depth.rows_mut(16), DepthState::DISABLED, |x, y| {
//!     let texel = TEX.sample(Sampler::NEAREST_WRAP, uv.at(x, y));
//!     Some(from_rgb8(modulate(texel, tint)))
//! });
//! assert_eq!(band.rows()[0][0], Rgb888::new(255, 160, 0)); // a white texel, tinted
//! # Ok::<(), microraster::Error>(())
//! ```
//!
//! [`PerspectiveCorrect`]: crate::raster3d::PerspectiveCorrect
//! [`Affine`]: crate::raster3d::Affine

mod alpha;
mod format;
mod sampler;
mod shade;
mod sprite;
#[cfg(test)]
mod tests;

pub use alpha::{A8, Argb4444, Rgb565A8};
pub use format::TexelFormat;
pub use sampler::{Address, Bilinear, Filter, Nearest, Sampler};
pub use shade::{from_rgb8, luma, modulate, to_rgb8};
pub use sprite::{SPRITE_SCALE_RANGE, Sprite};

use crate::{Error, Param};
use sampler::Axis;

/// Fraction bits of texture coordinates: [`UV_ONE`] = 2^16 is one texture
/// width (for `u`) or height (for `v`).
pub const UV_FRAC: u32 = 16;

/// 1.0 in texture coordinates (2^[`UV_FRAC`]).
pub const UV_ONE: i32 = 1 << UV_FRAC;

/// The largest texture width or height (4096): keeps `u·size` in `u32`
/// arithmetic, and leaves 1/16 texel of coordinate resolution.
pub const MAX_TEXTURE_DIM: u32 = 4096;

/// A read-only texture: `width × height` texels of format `F`, row by row
/// from the top left, borrowed (typically `&'static`, from flash).
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::texture::{Sampler, Texture, UV_ONE};
/// let ramp = [0u8, 85, 170, 255, 10, 20, 30, 40]; // 4 × 2 (not a power of two in area: fine)
/// let tex = Texture::<Gray8>::new(&ramp, 4, 2)?;
/// // The centre of texel (1, 0) is at u = 1.5/4, v = 0.5/2.
/// let centre = [3 * UV_ONE / 8, UV_ONE / 4];
/// assert_eq!(tex.sample(Sampler::NEAREST_CLAMP, centre), [85; 3]);
/// assert_eq!(tex.sample(Sampler::BILINEAR_CLAMP, centre), [85; 3]);
/// // Half-way between the centres of texels (1, 0) and (2, 0):
/// assert_eq!(tex.sample(Sampler::BILINEAR_CLAMP, [UV_ONE / 2, UV_ONE / 4]), [128; 3]); // 127.5 rounds up
/// assert_eq!(Texture::<Gray8>::new(&ramp, 3, 3).err(), Some(microraster::Error::BufferTooSmall));
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Texture<'a, F: TexelFormat> {
    data: &'a [F::Storage],
    u: Axis,
    v: Axis,
}

impl<'a, F: TexelFormat> Texture<'a, F> {
    /// A texture over `data`, `width × height` texels row by row.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] if `width` or `height` is 0 or above
    /// [`MAX_TEXTURE_DIM`], or `data` is longer than `width · height` (a
    /// likely wrong width); [`Error::BufferTooSmall`] if it is shorter.
    pub fn new(data: &'a [F::Storage], width: u32, height: u32) -> Result<Self, Error> {
        let ok = |d: u32| (1..=MAX_TEXTURE_DIM).contains(&d);
        if !ok(width) || !ok(height) {
            return Err(Error::InvalidParameter(Param::TextureSize));
        }
        // ≤ 2^24 texels: fits usize on every target with ≥ 32-bit pointers;
        // on smaller ones it could not be addressed anyway.
        let n = usize::try_from(width * height).map_err(|_| Error::InvalidParameter(Param::TextureSize))?;
        match data.len().cmp(&n) {
            core::cmp::Ordering::Less => Err(Error::BufferTooSmall),
            core::cmp::Ordering::Greater => Err(Error::InvalidParameter(Param::TextureSize)),
            core::cmp::Ordering::Equal => Ok(Texture { data, u: Axis::new(width), v: Axis::new(height) }),
        }
    }

    /// A texture over `rows`, `W × H` texels, for `static` and `const`
    /// items: the size is checked when the program is compiled (`W` and `H`
    /// in `1..=`[`MAX_TEXTURE_DIM`]), so this cannot fail at run time.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::Texture;
    /// static TEXELS: [[u8; 3]; 2] = [[0, 128, 255], [255, 128, 0]];
    /// static TEX: Texture<'static, Gray8> = Texture::from_rows(&TEXELS);
    /// assert_eq!((TEX.width(), TEX.height()), (3, 2));
    /// ```
    ///
    /// A zero-sized texture does not compile:
    /// ```compile_fail
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::Texture;
    /// static EMPTY: Texture<'static, Gray8> = Texture::from_rows(&[[0u8; 0]; 2]);
    /// ```
    pub const fn from_rows<const W: usize, const H: usize>(rows: &'a [[F::Storage; W]; H]) -> Self {
        const {
            assert!(W >= 1 && W <= MAX_TEXTURE_DIM as usize, "texture width must be 1..=4096");
            assert!(H >= 1 && H <= MAX_TEXTURE_DIM as usize, "texture height must be 1..=4096");
        }
        // W, H ≤ 4096: the casts are exact.
        Texture { data: rows.as_flattened(), u: Axis::new(W as u32), v: Axis::new(H as u32) }
    }

    /// Width in texels.
    pub const fn width(&self) -> u32 {
        self.u.size
    }

    /// Height in texels.
    pub const fn height(&self) -> u32 {
        self.v.size
    }

    /// The texels, row by row (`width · height` of them).
    pub const fn data(&self) -> &'a [F::Storage] {
        self.data
    }

    /// The texel at column `x`, row `y`, expanded to 8-bit channels
    /// ([`TexelFormat::expand`]); `None` outside the texture.
    pub fn texel(&self, x: u32, y: u32) -> Option<[u8; 3]> {
        (x < self.u.size && y < self.v.size).then(|| self.fetch(x, y))
    }

    /// The texture at `uv = [u, v]` ([`UV_FRAC`] fraction bits), filtered and
    /// addressed as `sampler` says, as 8-bit channels (grey textures give the
    /// level in all three). Any `uv` is accepted; see the
    /// [module docs](self#accuracy) for the error bounds.
    #[inline]
    pub fn sample<Fi: Filter>(&self, sampler: Sampler<Fi>, uv: [i32; 2]) -> [u8; 3] {
        let address = [sampler.address_u, sampler.address_v];
        // A constant per filter type: the other branch is not compiled.
        if Fi::BILINEAR { self.sample_bilinear(address, uv) } else { self.sample_nearest(address, uv) }
    }
}
