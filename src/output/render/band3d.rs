//! A band as a 3D draw target: its colour rows, its depth rows and the depth
//! state, for vertex stages that draw triangles straight into the band
//! ([`Pipeline::draw_meshlets`](crate::pipeline::Pipeline::draw_meshlets))
//! instead of collecting a frame's bins first.

use core::convert::Infallible;
use core::marker::PhantomData;

use embedded_graphics_core::Pixel;
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::Dimensions;
use embedded_graphics_core::primitives::Rectangle;

use crate::ClipRect;
use crate::Interpolate;
use crate::band::BandView;
use crate::blit::Blitter;
use crate::depth::{DepthFormat, DepthRows, DepthState};
use crate::raster3d::{Interpolation, Precision, ScreenTriangle, draw_clipped};

/// The band being drawn, handed to the closure of
/// [`Direct3d`](crate::render::Direct3d): frame
/// rows [`Band3d::rows`], colour interpolation `M`, depth format `F`. Its
/// depth rows were cleared to far by the renderer.
pub struct Band3d<'a, 'v, C, F: DepthFormat, M, const W: usize> {
    view: &'a mut BandView<'v, C, W>,
    depth: DepthRows<'a, F, W>,
    state: DepthState,
    /// The view's clip rectangle, made once for the band's triangles.
    clip: ClipRect,
    y0: i32,
    y1: i32,
    _m: PhantomData<M>,
}

impl<'a, 'v, C, F, M, const W: usize> Band3d<'a, 'v, C, F, M, W>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    /// The band of `view`'s frame rows with its depth rows. The rows are
    /// kept beside the view: the per-triangle row test reads them.
    pub(crate) fn new(
        view: &'a mut BandView<'v, C, W>,
        depth: DepthRows<'a, F, W>,
        state: DepthState,
    ) -> Self {
        let (y0, y1) = (view.y0(), view.y1());
        let clip = Blitter::clip(&*view);
        Band3d { view, depth, state, clip, y0, y1, _m: PhantomData }
    }

    /// The frame rows of the band, first and last (inclusive).
    pub fn rows(&self) -> (i32, i32) {
        (self.y0, self.y1 - 1)
    }

    /// The band's colour rows alone, for writers that need the
    /// [`BandView`] itself rather than a `DrawTarget` (blending: a
    /// [`Sprite`](crate::texture::Sprite)'s `blend_into`,
    /// [`BlendBlitter`](crate::blend::BlendBlitter)). Depth is untouched.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::depth::{Depth16, DepthBand, DepthState};
    /// use microraster::raster3d::Affine;
    /// use microraster::{Band, Renderer};
    /// use microraster::render::Direct3d;
    /// let mut band = Band::<Rgb565, 8, 4>::new(Rgb565::BLACK);
    /// let mut depth = DepthBand::<Depth16, 8, 4>::new();
    /// # let mut display = embedded_graphics::mock_display::MockDisplay::new();
    /// Renderer::new(8, Rgb565::BLACK).render(Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |b| {
    ///     let (first, _) = b.rows();
    ///     assert_eq!(b.color_view().y0(), first);
    ///     Ok(())
    /// }), &mut band, &mut display)?;
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn color_view(&mut self) -> &mut BandView<'v, C, W> {
        self.view
    }

    /// Draws one triangle (clipped to the band; rows outside it cost only the
    /// coverage set-up).
    #[inline]
    pub fn draw<const S: u32>(&mut self, tri: &ScreenTriangle<S>) {
        self.draw_in(tri, Precision::Exact);
    }

    /// [`Band3d::draw`] in accuracy tier `precision` (the vertex stage's:
    /// [`Pipeline::precision`](crate::pipeline::Pipeline)).
    #[inline]
    pub(crate) fn draw_in<const S: u32>(&mut self, tri: &ScreenTriangle<S>, precision: Precision) {
        draw_clipped(tri, self.view, self.clip, &mut self.depth, self.state, M::default(), precision);
    }

    /// Draws the triangles that touch the band, in order.
    pub fn draw_all<const S: u32>(&mut self, triangles: &[ScreenTriangle<S>]) {
        // `tri.rows()` overlaps `y0..y1` exactly when the centre of row `y1 − 1`
        // is not above the top vertex and that of row `y0` not below the bottom
        // one; compared in doubled subpixels (|2y| ≤ 2^29, the centres below
        // 2^22: all in i32), this skips the per-triangle row computation.
        let centre = |row: i32| (2 * row + 1) << S;
        let (top_limit, bottom_limit) = (centre(self.y1 - 1), centre(self.y0));
        for tri in triangles {
            let ys = tri.v.map(|v| 2 * v.pos.y());
            let (ymin, ymax) = (ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]));
            if ymin <= top_limit && ymax >= bottom_limit {
                self.draw(tri);
            }
        }
    }
}

/// The band's colour rows as an `embedded-graphics` target, for 2D drawn in
/// the same pass as the meshes (a HUD drawn after them, a backdrop before):
/// frame coordinates, clipped to the band. It writes colour only: the depth
/// rows are neither tested nor written, so 2D drawn *before* meshes is
/// covered by them wherever they are, and 2D drawn after them covers them.
///
/// ```
/// use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
/// use embedded_graphics::text::Text;
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::primitives::Rectangle;
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use microraster::depth::{DepthBand, DepthState, Depth16};
/// use microraster::raster3d::Affine;
/// use microraster::render::Direct3d;
/// use microraster::{Band, Renderer};
/// let mut display = MockDisplay::new();
/// let mut band = Band::<Rgb565, 48, 8>::new(Rgb565::BLACK);
/// let mut depth = DepthBand::<Depth16, 48, 8>::new();
/// let hud = MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE);
/// let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |b| {
///     // … the meshes first (`pipeline.draw_meshlets(b, …)`), then the HUD:
///     Text::new("42", Point::new(1, 9), hud).draw(b)?;
///     Ok(())
/// });
/// Renderer::new(16, Rgb565::BLACK).render(frame, &mut band, &mut display)?;
/// // The same as the text drawn by e-g over the (empty) 3D frame:
/// let mut expected = MockDisplay::new();
/// expected.set_allow_overdraw(true);
/// expected.fill_solid(&Rectangle::new(Point::zero(), Size::new(48, 16)), Rgb565::BLACK).unwrap();
/// Text::new("42", Point::new(1, 9), hud).draw(&mut expected).unwrap();
/// display.assert_eq(&expected);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
impl<C, F, M, const W: usize> Dimensions for Band3d<'_, '_, C, F, M, W>
where
    C: Interpolate,
    F: DepthFormat,
{
    fn bounding_box(&self) -> Rectangle {
        self.view.bounding_box()
    }
}

impl<C, F, M, const W: usize> DrawTarget for Band3d<'_, '_, C, F, M, W>
where
    C: Interpolate,
    F: DepthFormat,
{
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        self.view.draw_iter(pixels)
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        self.view.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Infallible> {
        self.view.fill_solid(area, color)
    }
}
