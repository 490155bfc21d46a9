//! Fragment shaders: [`Textured`] (a texture modulated by the
//! interpolated colour), [`TexturedAlpha`] (the same with alpha, discarding)
//! and [`Phong`] (lighting per pixel from interpolated
//! normals), with the functions that make their varyings in the vertex stage.

use super::{Fragment, FragmentShader};
use crate::Interpolate;
use crate::light::Lighting;
use crate::math::{Scalar, Vec3};
use crate::pipeline::VertexInput;
#[cfg(feature = "textures")]
use crate::texture::{Filter, Sampler, TexelFormat, Texture, UV_ONE, from_rgb8, modulate};

/// Fixed-point unit of [`phong_varyings`]' normals (2^14: components to
/// 6·10^-5).
pub const NORMAL_ONE: i32 = 1 << 14;
/// Fixed-point unit of [`phong_varyings`]' eye-space positions (2^12: to
/// 2.4·10^-4 eye units, up to ±2048 units; farther points are clamped).
pub const POSITION_ONE: i32 = 1 << 12;

fn fixed<T: Scalar>(v: T, one: i32) -> i32 {
    v.div_scaled(T::ONE, one as i64).unwrap_or(0).clamp(-(1 << 23), 1 << 23) as i32
}

/// The varyings of [`Textured`]: texture coordinates `uv` (in texture units,
/// 1.0 = one width/height) and the lit colour as 8-bit channels.
#[cfg(feature = "textures")]
pub fn textured_varyings<T: Scalar>(uv: [f32; 2], input: &VertexInput<T>) -> [i32; 5] {
    let c = input.color.map(|c| c.to_channel(255) as i32);
    let f = |t: f32| (t * UV_ONE as f32).clamp(-8_388_608.0, 8_388_608.0) as i32;
    [f(uv[0]), f(uv[1]), c[0], c[1], c[2]]
}

/// A texture sampled at the fragment's `(u, v)` (varyings 0 and 1, in
/// [`UV_ONE`] units) and modulated by its colour (varyings 2..5, 8-bit
/// channels): [`textured_varyings`] makes them.
#[cfg(feature = "textures")]
#[derive(Debug, Clone, Copy)]
pub struct Textured<'a, F: TexelFormat, Fi: Filter> {
    /// The texture.
    pub texture: &'a Texture<'a, F>,
    /// Filter and addressing.
    pub sampler: Sampler<Fi>,
}

#[cfg(feature = "textures")]
impl<C: Interpolate, F: TexelFormat, Fi: Filter> FragmentShader<C, 5> for Textured<'_, F, Fi> {
    #[inline]
    fn shade(&self, frag: &Fragment<5>) -> C {
        let v = frag.varyings;
        let texel = self.texture.sample(self.sampler, [v[0], v[1]]);
        let tint = [v[2], v[3], v[4]].map(|c| c.clamp(0, 255) as u8);
        from_rgb8(modulate(texel, tint))
    }
}

/// [`Textured`] with the texture's alpha, and a shader that discards: a
/// fragment whose sampled alpha ([`Texture::sample_rgba`]) is below `cutoff`
/// is discarded, the others are blended at that alpha (times the draw's).
/// With [`Replace`](crate::blend::Replace) and `cutoff` 128 it cuts shapes
/// out of a texture with hard edges; with [`Mix`](crate::blend::Mix) and
/// `cutoff` 1 it blends them smoothly. Same varyings as [`Textured`].
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
/// use microraster::fragment::{Fragment, FragmentShader, TexturedAlpha};
/// use microraster::texture::{A8, Sampler, Texture, UV_ONE};
/// static MASK: Texture<'static, A8> = Texture::from_rows(&[[0, 200]]);
/// let shader = TexturedAlpha { texture: &MASK, sampler: Sampler::NEAREST_CLAMP, cutoff: 1 };
/// let at = |u| Fragment { x: 0, y: 0, varyings: [u, 0, 255, 0, 0], color: [0; 3] };
/// assert_eq!(FragmentShader::<Rgb888, 5>::shade_or_discard(&shader, &at(UV_ONE / 4)), None);
/// assert_eq!(shader.shade_or_discard(&at(3 * UV_ONE / 4)), Some((Rgb888::RED, 200)));
/// ```
#[cfg(feature = "textures")]
#[derive(Debug, Clone, Copy)]
pub struct TexturedAlpha<'a, F: TexelFormat, Fi: Filter> {
    /// The texture.
    pub texture: &'a Texture<'a, F>,
    /// Filter and addressing.
    pub sampler: Sampler<Fi>,
    /// Fragments with a lower alpha are discarded.
    pub cutoff: u8,
}

#[cfg(feature = "textures")]
impl<C: Interpolate, F: TexelFormat, Fi: Filter> FragmentShader<C, 5> for TexturedAlpha<'_, F, Fi> {
    /// The colour alone, as [`Textured`] (alpha ignored).
    #[inline]
    fn shade(&self, frag: &Fragment<5>) -> C {
        Textured { texture: self.texture, sampler: self.sampler }.shade(frag)
    }

    #[inline]
    fn shade_or_discard(&self, frag: &Fragment<5>) -> Option<(C, u8)> {
        let v = frag.varyings;
        let [r, g, b, a] = self.texture.sample_rgba(self.sampler, [v[0], v[1]]);
        let tint = [v[2], v[3], v[4]].map(|c| c.clamp(0, 255) as u8);
        (a >= self.cutoff).then(|| (from_rgb8(modulate([r, g, b], tint)), a))
    }
}

/// The varyings of [`Phong`]: the unit eye-space normal in [`NORMAL_ONE`]
/// units and the eye-space position in [`POSITION_ONE`] units.
pub fn phong_varyings<T: Scalar>(input: &VertexInput<T>) -> [i32; 6] {
    let (n, p) = (input.normal, input.position);
    [
        fixed(n.x, NORMAL_ONE),
        fixed(n.y, NORMAL_ONE),
        fixed(n.z, NORMAL_ONE),
        fixed(p.x, POSITION_ONE),
        fixed(p.y, POSITION_ONE),
        fixed(p.z, POSITION_ONE),
    ]
}

/// Per-pixel (Phong) shading: the interpolated normal is renormalised and
/// lit at the interpolated eye position with the same [`Lighting`] formula
/// the vertex stage uses per vertex, on the fragment's material colour (draw
/// the mesh with a pipeline *without* lighting, so the vertex colour is the
/// material's). Varyings from [`phong_varyings`].
///
/// Gouraud shading evaluates the highlight at the vertices only and loses it
/// between them; this evaluates it at every pixel, at the cost of a
/// normalisation and a power per pixel in `T` arithmetic.
#[derive(Debug, Clone, Copy)]
pub struct Phong<T> {
    /// The light.
    pub lighting: Lighting<T>,
}

impl<C: Interpolate, T: Scalar> FragmentShader<C, 6> for Phong<T> {
    #[inline]
    fn shade(&self, frag: &Fragment<6>) -> C {
        let v = frag.varyings;
        let f = |x: i32, one: i32| T::from_f32(x as f32 / one as f32);
        let n = Vec3::new(f(v[0], NORMAL_ONE), f(v[1], NORMAL_ONE), f(v[2], NORMAL_ONE)).normalize();
        let p = Vec3::new(f(v[3], POSITION_ONE), f(v[4], POSITION_ONE), f(v[5], POSITION_ONE));
        let max = C::CHANNEL_MAX;
        let base =
            [0, 1, 2].map(|k| if max[k] == 0 { T::ZERO } else { f(frag.color[k] as i32, max[k] as i32) });
        let c = self.lighting.shade(n, p, base);
        C::from_channels([0, 1, 2].map(|k| if c[k].is_finite() { c[k].to_channel(max[k]) } else { 0 }))
    }
}
