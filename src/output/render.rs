//! The band renderer: a frame drawn band by band into a `DrawTarget`.

use crate::band::{Band, BandView, LazyClear};
use crate::depth::{DepthBand, DepthFormat, DepthState};
use crate::edge::Cull;
use crate::raster3d::{Interpolation, ScreenTriangle};

mod band3d;
mod dirty;
pub mod link;
#[cfg(feature = "async")]
mod link_async;
mod overlay;
#[cfg(feature = "async")]
mod spi_panel;
#[cfg(feature = "std")]
mod threads;
use crate::{Error, Interpolate, Primitive, RenderError};
pub use band3d::Band3d;
pub use dirty::{DirtyBands, signature};
use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;
pub use link::{BandSink, Blocking, FrameBands, Lent};
#[cfg(feature = "async")]
pub use link_async::{AsyncBandSink, poll_ready};
#[cfg(feature = "async")]
pub use spi_panel::{SpiPanel, SpiPanelError};

/// Renders scenes of [`Primitive`]s, band by band, to a display.
///
/// For each band of `H` rows (the last may be shorter) the renderer clears the
/// band to the background, rasterizes every primitive whose row range overlaps
/// it (clipped to the band), and sends the band with one
/// [`DrawTarget::fill_contiguous`] over the band's rectangle. The frame is `W`
/// pixels wide (the band's width) and [`Renderer::height`] rows tall, placed at
/// [`Renderer::offset`] on the target. The image does not depend on `H`.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{Band, Primitive, Renderer, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
/// let mut band = Band::<BinaryColor, 4, 2>::new(BinaryColor::Off);
/// let mut display = MockDisplay::new();
/// Renderer::new(4, BinaryColor::Off).render(&scene, &mut band, &mut display).unwrap();
/// display.assert_pattern(&["###.", "##..", "#...", "...."]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Renderer<C> {
    height: u32,
    offset: Point,
    background: C,
    cull: Cull,
}

impl<C: Interpolate> Renderer<C> {
    /// A renderer for frames `height` rows tall, cleared to `background`,
    /// at the target's origin, culling nothing.
    pub const fn new(height: u32, background: C) -> Self {
        Renderer { height, offset: Point::zero(), background, cull: Cull::None }
    }

    /// The same renderer with another cull mode.
    pub const fn with_cull(self, cull: Cull) -> Self {
        Renderer { cull, ..self }
    }

    /// The same renderer drawing the frame at `offset` on the target.
    pub const fn with_offset(self, offset: Point) -> Self {
        Renderer { offset, ..self }
    }

    /// Frame height in rows.
    pub const fn height(&self) -> u32 {
        self.height
    }

    /// The colour every band is cleared to.
    pub const fn background(&self) -> C {
        self.background
    }

    /// Which screen winding is dropped.
    pub const fn cull(&self) -> Cull {
        self.cull
    }

    /// Where the frame's top-left pixel goes on the target.
    pub const fn offset(&self) -> Point {
        self.offset
    }

    /// Renders `scene` through `band` into `target`.
    ///
    /// Errors: [`Error::InvalidFrameSize`] if the height is 0 or above
    /// [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM); [`Error::CoordinateOutOfRange`] if the offset puts
    /// the frame beyond `i32` coordinates; [`Error::FrameOutsideTarget`] if the
    /// frame (`W` × height at the offset) does not fit in `target`'s
    /// bounding box; [`RenderError::Target`] if the
    /// target fails (the remaining bands are not sent).
    pub fn render<D, const S: u32, const W: usize, const H: usize>(
        &self,
        scene: &[Primitive<C, S>],
        band: &mut Band<C, W, H>,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
    {
        self.bands(band, target, false, |view, y0, y1| self.draw_scene::<S, W, H>(scene, view, y0, y1))
    }

    /// [`Renderer::render`]'s pass over one band: the primitives that touch
    /// rows `y0..y1`, on an uncleared view.
    fn draw_scene<const S: u32, const W: usize, const H: usize>(
        &self,
        scene: &[Primitive<C, S>],
        view: &mut BandView<'_, C, W>,
        y0: i32,
        y1: i32,
    ) {
        // Rows are cleared as they are first written (`LazyClear`): most
        // rows' first span then costs one pass over the row, not two.
        let mut view = LazyClear::<C, W, H>::new(view, self.background);
        for prim in scene {
            let (lo, hi) = prim.rows();
            if lo < y1 && hi >= y0 {
                match prim {
                    Primitive::Triangle(t) => t.draw(&mut view, self.cull),
                    // Pixel by pixel: clear the line's rows once, then no checks.
                    Primitive::Line(l) => {
                        view.clear_rows(lo, hi);
                        l.draw(view.view());
                    }
                }
            }
        }
        view.finish();
    }

    /// Renders screen-space triangles from the vertex stage
    /// ([`pipeline`](crate::pipeline)) with the depth buffer `depth`, cleared to far at
    /// each band, and colour interpolated as `interp` says
    /// ([`Affine`](crate::raster3d::Affine) or
    /// [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect); a value,
    /// so the call needs no turbofish).
    /// The renderer's cull mode does not apply: the vertex stage culls.
    ///
    /// Errors as for [`Renderer::render`].
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::depth::{Depth16, DepthBand, DepthState};
    /// use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
    /// use microraster::{Band, Renderer};
    /// let tris: [ScreenTriangle<4>; 0] = []; // from Pipeline::draw_mesh
    /// let mut band = Band::<Gray8, 8, 4>::new(Gray8::new(0));
    /// let mut depth = DepthBand::<Depth16, 8, 4>::new();
    /// let mut display = MockDisplay::new();
    /// Renderer::new(8, Gray8::new(0))
    ///     .render_3d(&tris, &mut band, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, &mut display)
    ///     .unwrap();
    /// assert_eq!(display.get_pixel(embedded_graphics::prelude::Point::new(3, 3)), Some(Gray8::new(0)));
    /// ```
    pub fn render_3d<D, F, M, const S: u32, const W: usize, const H: usize>(
        &self,
        triangles: &[ScreenTriangle<S>],
        band: &mut Band<C, W, H>,
        depth: &mut DepthBand<F, W, H>,
        state: DepthState,
        interp: M,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        F: DepthFormat,
        M: Interpolation,
    {
        let _ = interp; // a value, so the call needs no turbofish
        self.render_with(band, target, |view, y0, y1| {
            band3d::<C, F, M, W, H>(view, depth, state, y0, y1).draw_all(triangles)
        })
    }

    /// Like [`Renderer::render_3d`], but runs the vertex stage once per band
    /// instead of once per frame, for parts whose RAM cannot hold a whole
    /// frame's bins: for each band `geometry(y0, y1, bins)` must append the
    /// triangles touching rows `y0..y1` (set [`Pipeline::rows`](crate::pipeline::Pipeline::rows)
    /// to `Some((y0, y1 − 1))` and call `draw_mesh`); `bins` is cleared before
    /// each band. Vertex work grows with the number of bands; the image is the
    /// same as [`Renderer::render_3d`]'s. `interp` is the colour
    /// interpolation, as there.
    ///
    /// Errors as for [`Renderer::render`], plus [`RenderError::Input`] with the
    /// first error `geometry` returns (the remaining bands are not drawn).
    #[allow(clippy::too_many_arguments)]
    pub fn render_3d_per_band<D, F, M, G, const S: u32, const W: usize, const H: usize, const N: usize>(
        &self,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
        mut geometry: G,
        band: &mut Band<C, W, H>,
        depth: &mut DepthBand<F, W, H>,
        state: DepthState,
        interp: M,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        F: DepthFormat,
        M: Interpolation,
        G: FnMut(i32, i32, &mut heapless::Vec<ScreenTriangle<S>, N>) -> Result<(), Error>,
    {
        let _ = interp; // a value, so the call needs no turbofish
        let mut failed = None;
        self.render_with(band, target, |view, y0, y1| {
            if failed.is_some() {
                return;
            }
            bins.clear();
            if let Err(e) = geometry(y0, y1, bins) {
                failed = Some(e);
                return;
            }
            band3d::<C, F, M, W, H>(view, depth, state, y0, y1).draw_all(bins);
        })?;
        failed.map_or(Ok(()), |e| Err(RenderError::Input(e)))
    }

    /// Renders a frame whose vertex stage draws straight into each band, with
    /// no bins at all: for each band, `draw` gets the band as a [`Band3d`]
    /// (its depth cleared to far) and draws into it, typically with
    /// [`Pipeline::draw_meshlets`](crate::pipeline::Pipeline::draw_meshlets)
    /// for each mesh. The RAM a frame needs is the band, its depth rows and
    /// what `draw` keeps (a meshlet's vertices), whatever the scene's size.
    /// Colour is interpolated as `interp` says ([`Affine`](crate::raster3d::Affine)
    /// or [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect)).
    ///
    /// Errors as for [`Renderer::render`], plus [`RenderError::Input`] with the
    /// first error `draw` returns (the remaining bands are not drawn).
    pub fn render_3d_direct<D, F, M, G, const W: usize, const H: usize>(
        &self,
        band: &mut Band<C, W, H>,
        depth: &mut DepthBand<F, W, H>,
        state: DepthState,
        interp: M,
        target: &mut D,
        mut draw: G,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        F: DepthFormat,
        M: Interpolation,
        G: FnMut(&mut Band3d<'_, '_, C, F, M, W>) -> Result<(), Error>,
    {
        let _ = interp; // a value, so the call needs no turbofish
        let mut failed = None;
        self.render_with(band, target, |view, y0, y1| {
            if failed.is_none() {
                let mut b = band3d::<C, F, M, W, H>(view, depth, state, y0, y1);
                failed = draw(&mut b).err();
            }
        })?;
        failed.map_or(Ok(()), |e| Err(RenderError::Input(e)))
    }

    /// The band loop itself, for custom passes: for each band, clear it to the
    /// background, call `draw(view, y0, y1)` to fill frame rows `y0..y1`
    /// (mix 2D [`Primitive`]s, [`draw_triangle`](crate::raster3d::draw_triangle) calls with your own
    /// [`DepthBand`], or anything that writes through the
    /// [`Blitter`](crate::blit::Blitter) trait), then send the band with one
    /// `fill_contiguous`. [`Renderer::render`] and [`Renderer::render_3d`] are
    /// built on it.
    ///
    /// Errors as for [`Renderer::render`].
    pub fn render_with<D, const W: usize, const H: usize>(
        &self,
        band: &mut Band<C, W, H>,
        target: &mut D,
        draw: impl FnMut(&mut BandView<'_, C, W>, i32, i32),
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
    {
        self.bands(band, target, true, draw)
    }

    /// [`Error::FrameOutsideTarget`] unless the frame lies within `display`
    /// (a target's `bounding_box`). Checked before the first band, so a
    /// 320-wide band on a 240-wide display fails instead of drawing a
    /// clipped frame. Call after `frame_bands`, which keeps the frame's
    /// corners within `i32`.
    fn fits<const W: usize>(&self, display: Rectangle) -> Result<(), Error> {
        let frame = Rectangle::new(self.offset, Size::new(W as u32, self.height));
        // The frame is not empty, so both corners inside means contained.
        let inside = |p: Option<Point>| p.is_some_and(|p| display.contains(p));
        if inside(Some(frame.top_left)) && inside(frame.bottom_right()) {
            Ok(())
        } else {
            Err(Error::FrameOutsideTarget)
        }
    }

    /// The band loop; with `clear` false the views are not cleared and `draw`
    /// must write every pixel of them.
    fn bands<D, const W: usize, const H: usize>(
        &self,
        band: &mut Band<C, W, H>,
        target: &mut D,
        clear: bool,
        draw: impl FnMut(&mut BandView<'_, C, W>, i32, i32),
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
    {
        // Size and offset first (`fits` needs them in range), then the target.
        self.frame_bands::<W, H>()?;
        self.fits::<W>(target.bounding_box())?;
        // The linked loop with one band and a sink that sends before it
        // returns: the plain render-then-send loop.
        link::run(self, core::slice::from_mut(band), &mut link::Blocking(target), clear, draw)
    }
}

/// Clears the band's depth to far: the [`Band3d`] of rows `y0..y1`.
fn band3d<'a, 'v, C, F, M, const W: usize, const H: usize>(
    view: &'a mut BandView<'v, C, W>,
    depth: &'a mut DepthBand<F, W, H>,
    state: DepthState,
    y0: i32,
    y1: i32,
) -> Band3d<'a, 'v, C, F, M, W>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    let mut rows = depth.rows_mut((y1 - y0) as usize);
    for r in rows.iter_mut() {
        r.fill(F::FAR);
    }
    Band3d::new(view, rows, state, (y0, y1))
}
