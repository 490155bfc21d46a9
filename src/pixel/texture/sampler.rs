//! Samplers: the filter is a type (so a filter a program never uses is not
//! compiled), the addressing mode of each axis a value.
//!
//! # Index arithmetic (per axis, texture size `n`, coordinate `u`)
//! `u` has [`UV_FRAC`](super::UV_FRAC) = 16 fraction bits; the texel-space position
//! `p = u·n` is exact in units of 2^-16 texel, and texel `i` covers
//! `[i, i + 1)` (centre `i + ½`).
//! * Wrap: the period of `u` is 1.0 = 2^16, so `u & 0xFFFF` is
//!   `u.rem_euclid(2^16)` for every `i32`, and
//!   `⌊u·n⌋ mod n = ⌊(u mod 2^16)·n / 2^16⌋` (the product is below 2^28).
//!   Bilinear's `p − ½` is brought back into `[0, n)` by adding one period.
//! * Clamp: `u` is clamped to `[0, 1]` first; every index then clamped to
//!   `[0, n − 1]` is the same as without the first clamp, because the
//!   indices are monotonic in `u` and already at the edge texel there.
//!
//! Power-of-two sizes replace the multiply by `n` with a shift (chosen when
//! the texture is built); no path divides, none can overflow.

use super::format::TexelFormat;
use super::{Texture, UV_ONE};
use core::fmt::Debug;

/// How a coordinate outside `[0, 1)` is brought back onto the texture.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::texture::{Address, Sampler, Texture, UV_ONE};
/// let tex = Texture::<Gray8>::new(&[10, 20, 30, 40], 4, 1)?;
/// // u = 1.125 is a quarter texel into the second period: texel 0 when
/// // repeating, the last texel when the edge extends.
/// let uv = [UV_ONE + UV_ONE / 8, UV_ONE / 2];
/// assert_eq!(tex.sample(Sampler::NEAREST_WRAP, uv), [10; 3]);
/// let clamp = Sampler::NEAREST_WRAP.with_address(Address::Clamp, Address::Clamp);
/// assert_eq!(tex.sample(clamp, uv), [40; 3]);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Address {
    /// Repeat: `u` and `u + 1` sample the same point (bilinear filtering
    /// blends the last texel with the first across the seam).
    #[default]
    Wrap,
    /// Clamp to edge: outside `[0, 1]` the edge texels extend (bilinear
    /// filtering never reads across the border).
    Clamp,
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Nearest {}
    impl Sealed for super::Bilinear {}
}

/// A texture filter: [`Nearest`] or [`Bilinear`]. Sealed; a type parameter of
/// [`Sampler`], so only the filters a program samples with are compiled.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::texture::{Address, Bilinear, Filter, Nearest, Sampler, Texture, UV_ONE};
/// let tex = Texture::<Gray8>::new(&[0, 200], 2, 1)?;
/// // Code generic over the filter; half-way between the two texel centres.
/// fn mid<Fi: Filter>(t: &Texture<Gray8>, filter: Fi) -> u8 {
///     let clamp = Sampler { filter, ..Sampler::default() }.with_address(Address::Clamp, Address::Clamp);
///     t.sample(clamp, [UV_ONE / 2, UV_ONE / 2])[0]
/// }
/// assert_eq!(mid(&tex, Nearest), 200); // the texel containing the point
/// assert_eq!(mid(&tex, Bilinear), 100); // both texels, equally weighted
/// # Ok::<(), microraster::Error>(())
/// ```
pub trait Filter: sealed::Sealed + Copy + Default + Debug {
    /// True for [`Bilinear`].
    ///
    /// ```
    /// use microraster::texture::{Bilinear, Filter, Nearest};
    /// assert!(Bilinear::BILINEAR && !Nearest::BILINEAR);
    /// ```
    const BILINEAR: bool;
}

/// Nearest texel: the texel containing the sample point. Exact.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::texture::{Nearest, Sampler, Texture, UV_ONE};
/// let tex = Texture::<Gray8>::new(&[0, 200], 2, 1)?;
/// // u = 3/8 is in texel 0 (u < 1/2), a quarter texel right of its centre.
/// let nearest = Sampler { filter: Nearest, ..Sampler::NEAREST_CLAMP };
/// assert_eq!(tex.sample(nearest, [3 * UV_ONE / 8, UV_ONE / 2]), [0; 3]);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Nearest;

/// Bilinear: the four texels around the sample point, weighted by distance
/// (texel centres at `(i + ½)/n`).
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::texture::{Bilinear, Sampler, Texture, UV_ONE};
/// let tex = Texture::<Gray8>::new(&[0, 200], 2, 1)?;
/// // u = 3/8: a quarter of the way from texel 0's centre to texel 1's.
/// let bilinear = Sampler { filter: Bilinear, ..Sampler::BILINEAR_CLAMP };
/// assert_eq!(tex.sample(bilinear, [3 * UV_ONE / 8, UV_ONE / 2]), [50; 3]);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Bilinear;

impl Filter for Nearest {
    const BILINEAR: bool = false;
}
impl Filter for Bilinear {
    const BILINEAR: bool = true;
}

/// Sampling settings: a filter (a type: [`Nearest`] or [`Bilinear`]) and the
/// addressing mode of each axis (a value: [`Address`]).
///
/// ```
/// use microraster::texture::{Address, Bilinear, Sampler};
/// let s = Sampler::BILINEAR_WRAP;
/// assert_eq!((s.address_u, s.address_v), (Address::Wrap, Address::Wrap));
/// // A texture repeating across u but not v (a road, a fence):
/// let road = Sampler { filter: Bilinear, address_u: Address::Wrap, address_v: Address::Clamp };
/// assert_eq!(road, Sampler::BILINEAR_WRAP.with_address(Address::Wrap, Address::Clamp));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Sampler<Fi: Filter = Nearest> {
    /// The filter (a zero-sized marker).
    pub filter: Fi,
    /// Addressing of `u` (across the width).
    pub address_u: Address,
    /// Addressing of `v` (down the height).
    pub address_v: Address,
}

impl Sampler<Nearest> {
    /// Nearest texel, repeating.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::{Sampler, Texture, UV_ONE};
    /// let tex = Texture::<Gray8>::new(&[10, 20], 2, 1)?;
    /// // u = 5/4 wraps to 1/4: texel 0.
    /// assert_eq!(tex.sample(Sampler::NEAREST_WRAP, [5 * UV_ONE / 4, 0]), [10; 3]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const NEAREST_WRAP: Self =
        Sampler { filter: Nearest, address_u: Address::Wrap, address_v: Address::Wrap };
    /// Nearest texel, edges extended.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::{Sampler, Texture, UV_ONE};
    /// let tex = Texture::<Gray8>::new(&[10, 20], 2, 1)?;
    /// // u = 5/4 is past the right edge: the last texel.
    /// assert_eq!(tex.sample(Sampler::NEAREST_CLAMP, [5 * UV_ONE / 4, 0]), [20; 3]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const NEAREST_CLAMP: Self =
        Sampler { filter: Nearest, address_u: Address::Clamp, address_v: Address::Clamp };
}

impl Sampler<Bilinear> {
    /// Bilinear, repeating.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::{Sampler, Texture, UV_ONE};
    /// let tex = Texture::<Gray8>::new(&[10, 20], 2, 1)?;
    /// // u = 0 is half-way between texel 1's centre (wrapped left) and texel 0's.
    /// assert_eq!(tex.sample(Sampler::BILINEAR_WRAP, [0, UV_ONE / 2]), [15; 3]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const BILINEAR_WRAP: Self =
        Sampler { filter: Bilinear, address_u: Address::Wrap, address_v: Address::Wrap };
    /// Bilinear, edges extended.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::{Sampler, Texture, UV_ONE};
    /// let tex = Texture::<Gray8>::new(&[10, 20], 2, 1)?;
    /// // Left of texel 0's centre there is only texel 0.
    /// assert_eq!(tex.sample(Sampler::BILINEAR_CLAMP, [0, UV_ONE / 2]), [10; 3]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const BILINEAR_CLAMP: Self =
        Sampler { filter: Bilinear, address_u: Address::Clamp, address_v: Address::Clamp };
}

impl<Fi: Filter> Sampler<Fi> {
    /// The same filter with addressing `u` across and `v` down.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::texture::{Address, Sampler, Texture, UV_ONE};
    /// let tex = Texture::<Gray8>::new(&[10, 20, 30, 40], 4, 1)?;
    /// let uv = [-UV_ONE / 8, UV_ONE / 2]; // left of the texture
    /// assert_eq!(tex.sample(Sampler::NEAREST_WRAP, uv), [40; 3]); // from the right end
    /// let clamped = Sampler::NEAREST_WRAP.with_address(Address::Clamp, Address::Wrap);
    /// assert_eq!(tex.sample(clamped, uv), [10; 3]); // the left edge extended
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const fn with_address(self, u: Address, v: Address) -> Self {
        Sampler { filter: self.filter, address_u: u, address_v: v }
    }
}

/// One axis of a texture: its size and, for a power of two, its `log2`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Axis {
    /// Texels along the axis, `1..=MAX_TEXTURE_DIM`.
    pub size: u32,
    /// `log2(size)` when `size` is a power of two.
    pub pow2: Option<u32>,
}

const HALF: u32 = 1 << 15;

impl Axis {
    pub const fn new(size: u32) -> Axis {
        let pow2 = if size.is_power_of_two() { Some(size.trailing_zeros()) } else { None };
        Axis { size, pow2 }
    }

    /// `r · size` for `r ≤ 2^16` (so at most 2^28: no overflow).
    #[inline(always)]
    fn scale(self, r: u32) -> u32 {
        match self.pow2 {
            Some(k) => r << k,
            None => r * self.size,
        }
    }

    /// `i · size` for `i ≤ 2^16` (for the width axis, the offset of row `i`).
    #[inline(always)]
    pub fn offset(self, i: u32) -> usize {
        self.scale(i) as usize
    }

    /// The index of the texel containing `u`: `⌊u·n⌋` wrapped or clamped.
    #[inline(always)]
    pub fn nearest(self, u: i32, a: Address) -> u32 {
        match a {
            Address::Wrap => self.scale(u as u32 & 0xFFFF) >> 16,
            // `clamp` keeps u in 0..=2^16, so the cast is exact.
            Address::Clamp => (self.scale(u.clamp(0, UV_ONE) as u32) >> 16).min(self.size - 1),
        }
    }

    /// The two texels around `u` and the weight of the second in 2^-16
    /// (`p − ½ = i0 + frac/2^16`), wrapped or clamped.
    #[inline(always)]
    pub fn linear(self, u: i32, a: Address) -> (u32, u32, u32) {
        match a {
            Address::Wrap => {
                let p = self.scale(u as u32 & 0xFFFF);
                // p − ½ < 0 only left of the first centre: one period on.
                let q = if p >= HALF { p - HALF } else { p + (self.size << 16) - HALF };
                let i0 = q >> 16;
                let i1 = if i0 + 1 == self.size { 0 } else { i0 + 1 };
                (i0, i1, q & 0xFFFF)
            }
            Address::Clamp => {
                let p = self.scale(u.clamp(0, UV_ONE) as u32);
                if p < HALF {
                    (0, 0, 0) // left of the first centre: the edge texel only
                } else {
                    let q = p - HALF;
                    let i0 = q >> 16; // ≤ size − 1 since p ≤ size·2^16
                    (i0, (i0 + 1).min(self.size - 1), q & 0xFFFF)
                }
            }
        }
    }
}

impl<F: TexelFormat> Texture<'_, F> {
    /// The texel at `(x, y)`, `x < width`, `y < height` (guaranteed by the
    /// callers; a miss would read the default texel, never panic).
    #[inline(always)]
    pub(crate) fn fetch(&self, x: u32, y: u32) -> [u8; 3] {
        // Row y starts y·width texels in (the u axis is the width).
        let i = self.u.offset(y) + x as usize;
        F::expand(self.data.get(i).copied().unwrap_or_default())
    }

    #[inline(always)]
    pub(crate) fn sample_nearest(&self, s: [Address; 2], uv: [i32; 2]) -> [u8; 3] {
        self.fetch(self.u.nearest(uv[0], s[0]), self.v.nearest(uv[1], s[1]))
    }

    #[inline(always)]
    pub(crate) fn sample_bilinear(&self, s: [Address; 2], uv: [i32; 2]) -> [u8; 3] {
        let (x0, x1, fx) = self.u.linear(uv[0], s[0]);
        let (y0, y1, fy) = self.v.linear(uv[1], s[1]);
        let [t00, t10, t01, t11] = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].map(|(x, y)| self.fetch(x, y));
        let mut out = [0u8; 3];
        for k in 0..F::CHANNELS {
            out[k] = bilerp([t00[k], t10[k], t01[k], t11[k]], fx, fy);
        }
        if F::CHANNELS == 1 {
            out = [out[0]; 3];
        }
        out
    }
}

/// The bilinear blend of the corner values `[c00, c10, c01, c11]` with
/// weights `fx`, `fy` (of the second column and row) in 2^-16.
#[inline(always)]
pub(crate) fn bilerp(c: [u8; 4], fx: u32, fy: u32) -> u8 {
    // Each row lerp is exact (< 255·2^16 < 2^24), then rounded to
    // 2^-8 (error ≤ 2^-9) so the column lerp fits u32:
    // 255·2^8·2^16 + 2^23 < 2^32.
    let lerp16 = |a: u8, b: u8, f: u32| u32::from(a) * ((1 << 16) - f) + u32::from(b) * f;
    let top = (lerp16(c[0], c[1], fx) + (1 << 7)) >> 8;
    let bottom = (lerp16(c[2], c[3], fx) + (1 << 7)) >> 8;
    let v = (top * ((1 << 16) - fy) + bottom * fy + (1 << 23)) >> 24;
    v as u8 // ≤ 255: a convex combination of ≤ 255·2^24, rounded
}
