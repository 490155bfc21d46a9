//! The fragment stage: per-pixel shading programs ([`FragmentShader`]) fed
//! with interpolated per-vertex values ([`Varyings`]), depth-tested, and
//! blended into the band ([`Blend`]).
//!
//! [`raster3d::draw_triangle`](crate::raster3d::draw_triangle) covers flat and
//! Gouraud colour at the least cost; this stage is for what it cannot do —
//! textures ([`Textured`]), per-pixel lighting ([`Phong`]), translucency — and
//! is compiled only into programs that use it. The vertex stage produces its
//! input, [`FragTriangle`]s, with
//! [`Pipeline::draw_mesh_varying`](crate::pipeline::Pipeline::draw_mesh_varying).
//!
//! # Order of operations, per covered pixel
//! 1. depth test against the band's z-buffer (`state.test`); a failing
//!    fragment stops here;
//! 2. the shader computes the source colour from the pixel's varyings, or
//!    discards the fragment, which stops here;
//! 3. the blend mode combines it with the band's colour at `alpha`
//!    ([`Replace`](crate::blend::Replace) writes it);
//! 4. depth write (if `state.write`: off for translucent geometry, see
//!    [`DepthState::READ_ONLY`]).
//!
//! Translucent meshes go after opaque ones, farthest first
//! ([`back_to_front`](crate::blend::back_to_front)); where translucent
//! surfaces overlap, the result still depends on their order.

mod shaders;

pub use shaders::{NORMAL_ONE, POSITION_ONE, Phong, phong_varyings};
#[cfg(feature = "textures")]
#[cfg_attr(docsrs, doc(cfg(feature = "textures")))]
pub use shaders::{Textured, TexturedAlpha, textured_varyings};

use crate::blend::div255_round;

use crate::band::BandView;
use crate::blend::Blend;
use crate::depth::{DepthFormat, DepthRows, DepthState};
use crate::raster3d::{Interpolation, ScreenTriangle};
use crate::varyings::Varyings;
use crate::{Error, Interpolate};

/// A screen triangle with `A` values per vertex for the fragment shader.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FragTriangle<const S: u32, const A: usize> {
    /// Position, depth, `1/w` and colour of each vertex.
    pub tri: ScreenTriangle<S>,
    /// The values at each vertex (`|v| ≤` [`MAX_VARYING`](crate::varyings::MAX_VARYING)).
    pub varyings: [[i32; A]; 3],
}

impl<const S: u32, const A: usize> FragTriangle<S, A> {
    /// First and last frame row the triangle can touch.
    pub fn rows(&self) -> (i32, i32) {
        self.tri.rows()
    }
}

/// What the shader sees of one fragment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fragment<const A: usize> {
    /// Pixel column.
    pub x: i32,
    /// Pixel row.
    pub y: i32,
    /// The varyings at the pixel centre, rounded (affine or perspective-correct
    /// as the draw call's `interp` says; error bounds in [`Varyings`]).
    pub varyings: [i32; A],
    /// Vertex 0's colour channels (the mesh's material colour when the
    /// pipeline has no lighting).
    pub color: [u8; 3],
}

/// A per-pixel shading program: the colour of a fragment from its varyings.
pub trait FragmentShader<C, const A: usize> {
    /// The source colour of `frag`, before blending.
    fn shade(&self, frag: &Fragment<A>) -> C;

    /// The source colour and alpha of `frag`, or `None` to discard it (the
    /// pixel keeps its colour). The draw calls this, not
    /// [`FragmentShader::shade`]; the alpha multiplies the draw's
    /// [`Output::alpha`] (exactly `round(a·b/255)`; 255 leaves it as it is).
    /// The default is `shade` at alpha 255. A discarded fragment writes no
    /// depth (see the [module docs](self)): it does not occlude.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::depth::{Depth16, DepthBand};
    /// use microraster::fragment::{FragTriangle, Fragment, FragmentShader, Output, draw_fragment_triangle};
    /// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
    /// use microraster::{Band, SubPoint};
    /// /// White on columns 4 and beyond; the others discarded.
    /// struct RightHalf;
    /// impl FragmentShader<Gray8, 1> for RightHalf {
    ///     fn shade(&self, _: &Fragment<1>) -> Gray8 {
    ///         Gray8::WHITE
    ///     }
    ///     fn shade_or_discard(&self, f: &Fragment<1>) -> Option<(Gray8, u8)> {
    ///         (f.x >= 4).then_some((Gray8::WHITE, 255))
    ///     }
    /// }
    /// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), inv_w: 1 << 30, ..Default::default() };
    /// // Covers the whole row: its hypotenuse crosses y = ½ at x = 12.
    /// let t = FragTriangle { tri: ScreenTriangle { v: [v(0, 0), v(16, 0), v(0, 2)], flat: false }, varyings: [[0]; 3] };
    /// let mut band = Band::<Gray8, 8, 1>::new(Gray8::BLACK);
    /// let mut depth = DepthBand::<Depth16, 8, 1>::new();
    /// let g = Gray8::new(9);
    /// let mut view = band.view(0, 1, g);
    /// draw_fragment_triangle(&t, &mut view, &mut depth.rows_mut(1), &RightHalf, Output::OPAQUE, Affine)?;
    /// // Discarded pixels keep the clear colour.
    /// let w = Gray8::WHITE;
    /// assert_eq!(view.pixels().collect::<Vec<_>>(), [g, g, g, g, w, w, w, w]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    #[inline]
    fn shade_or_discard(&self, frag: &Fragment<A>) -> Option<(C, u8)> {
        Some((self.shade(frag), 255))
    }
}

impl<C, const A: usize, F: Fn(&Fragment<A>) -> C> FragmentShader<C, A> for F {
    #[inline]
    fn shade(&self, frag: &Fragment<A>) -> C {
        self(frag)
    }
}

/// How fragments are written: depth test and write, blend mode and alpha.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Output<B> {
    /// Depth test and write.
    pub depth: DepthState,
    /// Blend mode.
    pub blend: B,
    /// Alpha handed to the blend mode (0..=255).
    pub alpha: u8,
}

impl Output<crate::blend::Replace> {
    /// Opaque geometry: depth test `<`, depth written, colour replaced.
    pub const OPAQUE: Self =
        Output { depth: DepthState::LESS_WRITE, blend: crate::blend::Replace, alpha: 255 };
}

impl Output<crate::blend::Mix> {
    /// Translucent geometry at `alpha`: depth tested but not written, colour
    /// mixed over the band's.
    pub const fn translucent(alpha: u8) -> Self {
        Output { depth: DepthState::READ_ONLY, blend: crate::blend::Mix, alpha }
    }
}

/// Draws `t` into one band: coverage, the depth test of `out`, the shader
/// per passing pixel, then blending. The varyings are interpolated as
/// `interp` says ([`Affine`](crate::raster3d::Affine) or
/// [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect)); `depth`
/// as for [`draw_triangle`](crate::raster3d::draw_triangle). Every parameter
/// is inferred from the arguments.
///
/// Errors: [`Error::CoordinateOutOfRange`] for a varying beyond
/// [`MAX_VARYING`](crate::varyings::MAX_VARYING) (nothing is drawn).
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::depth::{Depth16, DepthBand};
/// use microraster::fragment::{FragTriangle, Fragment, Output, draw_fragment_triangle};
/// use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle, ScreenVertex};
/// use microraster::{Band, SubPoint};
/// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), inv_w: 1 << 30, ..Default::default() };
/// let tri = ScreenTriangle { v: [v(0, 0), v(8, 0), v(0, 4)], flat: false };
/// // One varying: 0 at the left vertices, 160 at the right one.
/// let t = FragTriangle { tri, varyings: [[0], [160], [0]] };
/// let mut band = Band::<Gray8, 8, 4>::new(Gray8::BLACK);
/// let mut depth = DepthBand::<Depth16, 8, 4>::new();
/// let mut view = band.view(0, 4, Gray8::BLACK);
/// let shader = |f: &Fragment<1>| Gray8::new(f.varyings[0] as u8);
/// draw_fragment_triangle(&t, &mut view, &mut depth.rows_mut(4), &shader, Output::OPAQUE, PerspectiveCorrect)?;
/// // Pixel (1, 0), centre x = 1.5: 160 · 1.5 / 8 = 30 (equal 1/w: exact).
/// assert_eq!(view.pixels().nth(1), Some(Gray8::new(30)));
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn draw_fragment_triangle<C, F, M, B, Sh, const S: u32, const W: usize, const A: usize>(
    t: &FragTriangle<S, A>,
    color: &mut BandView<'_, C, W>,
    depth: &mut DepthRows<'_, F, W>,
    shader: &Sh,
    out: Output<B>,
    interp: M,
) -> Result<(), Error>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    B: Blend,
    Sh: FragmentShader<C, A> + ?Sized,
{
    let _ = interp; // a value, so the call needs no turbofish
    let Some(vary) = Varyings::new(&t.tri, t.varyings, interp)? else { return Ok(()) };
    let base = t.tri.v[0].color;
    crate::varyings::for_each_fragment::<C, F, S, W>(&t.tri, color, &mut *depth, out.depth, |x, y, dst| {
        let frag = Fragment { x, y, varyings: vary.at(x, y), color: base };
        let Some((src, a)) = shader.shade_or_discard(&frag) else { return false };
        // The default's 255 folds away: the same code as without discard.
        let alpha =
            if a == 255 { out.alpha } else { div255_round(u32::from(out.alpha) * u32::from(a)) as u8 };
        *dst = out.blend.blend(src, *dst, alpha);
        true
    });
    Ok(())
}

/// Draws every triangle of `tris` that touches the band (rows `y0..y1` of
/// `color`), in order: the body of a
/// [`from_fn`](crate::render::from_fn) pass. Arguments
/// as for [`draw_fragment_triangle`].
///
/// Errors: as [`draw_fragment_triangle`]; the first error stops the pass.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::depth::{Depth16, DepthBand};
/// use microraster::fragment::{FragTriangle, Fragment, Output, draw_fragment_band};
/// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
/// use microraster::render::from_fn;
/// use microraster::{Band, Renderer, SubPoint};
/// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), inv_w: 1 << 30, ..Default::default() };
/// let tris = [FragTriangle { tri: ScreenTriangle { v: [v(0, 0), v(8, 0), v(0, 8)], flat: false }, varyings: [[90]; 3] }];
/// let shader = |f: &Fragment<1>| Gray8::new(f.varyings[0] as u8);
/// let (mut band, mut depth) = (Band::<Gray8, 8, 4>::new(Gray8::BLACK), DepthBand::<Depth16, 8, 4>::new());
/// let mut display = MockDisplay::new();
/// let frame = from_fn(|view| {
///     depth.clear(view.height()); // far, each band
///     let mut rows = depth.rows_mut(view.height());
///     draw_fragment_band(&tris, view, &mut rows, &shader, Output::OPAQUE, Affine)
/// });
/// Renderer::new(8, Gray8::BLACK).render(frame, &mut band, &mut display)?;
/// assert_eq!(display.get_pixel(embedded_graphics::prelude::Point::new(0, 6)), Some(Gray8::new(90)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[allow(clippy::too_many_arguments)]
pub fn draw_fragment_band<C, F, M, B, Sh, const S: u32, const W: usize, const A: usize>(
    tris: &[FragTriangle<S, A>],
    color: &mut BandView<'_, C, W>,
    depth: &mut DepthRows<'_, F, W>,
    shader: &Sh,
    out: Output<B>,
    interp: M,
) -> Result<(), Error>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    B: Blend,
    Sh: FragmentShader<C, A> + ?Sized,
{
    let (y0, y1) = (color.y0(), color.y1());
    for t in tris {
        let (lo, hi) = t.rows();
        if lo < y1 && hi >= y0 {
            draw_fragment_triangle(t, color, depth, shader, out, interp)?;
        }
    }
    Ok(())
}
