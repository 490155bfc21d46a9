//! The 3D passes: screen triangles depth-tested into each band, binned once
//! per frame ([`Triangles3d`]), once per band ([`PerBand3d`]) or drawn
//! straight into the band ([`Direct3d`]).

use core::marker::PhantomData;

use super::Pass;
use crate::band::BandView;
use crate::depth::{DepthBand, DepthFormat, DepthState};
use crate::raster3d::{Interpolation, ScreenTriangle};
use crate::render::{Band3d, Renderer};
use crate::{Error, Interpolate};

/// Screen triangles from the vertex stage ([`Pipeline::draw_mesh`](crate::pipeline::Pipeline::draw_mesh)),
/// tested against `depth` (cleared to far in each band) as `state` says,
/// colour interpolated as `interp` says ([`Affine`](crate::raster3d::Affine)
/// or [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect); a value, so
/// the call needs no turbofish). The renderer's cull mode does not apply: the
/// vertex stage culls.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
/// use microraster::render::Triangles3d;
/// use microraster::{Band, Renderer};
/// let tris: [ScreenTriangle<4>; 0] = []; // from Pipeline::draw_mesh
/// let mut band = Band::<Gray8, 8, 4>::new(Gray8::new(0));
/// let mut depth = DepthBand::<Depth16, 8, 4>::new();
/// let mut display = MockDisplay::new();
/// let frame = Triangles3d::new(&tris, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect);
/// Renderer::new(8, Gray8::new(0)).render(frame, &mut band, &mut display).unwrap();
/// assert_eq!(display.get_pixel(embedded_graphics::prelude::Point::new(3, 3)), Some(Gray8::new(0)));
/// ```
pub struct Triangles3d<'a, F: DepthFormat, M, const S: u32, const W: usize, const H: usize> {
    triangles: &'a [ScreenTriangle<S>],
    depth: &'a mut DepthBand<F, W, H>,
    state: DepthState,
    _m: PhantomData<M>,
}

impl<'a, F: DepthFormat, M: Interpolation, const S: u32, const W: usize, const H: usize>
    Triangles3d<'a, F, M, S, W, H>
{
    /// `triangles` drawn with `depth` as `state` says, colour interpolated as `interp` says.
    pub fn new(
        triangles: &'a [ScreenTriangle<S>],
        depth: &'a mut DepthBand<F, W, H>,
        state: DepthState,
        interp: M,
    ) -> Self {
        let _ = interp; // a value, so the call needs no turbofish
        Triangles3d { triangles, depth, state, _m: PhantomData }
    }
}

impl<C, F, M, const S: u32, const W: usize, const H: usize> Pass<C, W, H> for Triangles3d<'_, F, M, S, W, H>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    fn draw(&mut self, band: &mut BandView<'_, C, W>, _: &Renderer<C>) -> Result<(), Error> {
        band3d::<C, F, M, W, H>(band, self.depth, self.state).draw_all(self.triangles);
        Ok(())
    }
}

/// A vertex stage that draws straight into each band, with no bins:
/// `draw` gets the band as a [`Band3d`] (its depth cleared to far) and
/// draws into it, typically with
/// [`Pipeline::draw_meshlets`](crate::pipeline::Pipeline::draw_meshlets)
/// for each mesh, or collects the band's triangles (rows
/// [`Band3d::rows`]) and draws them with [`Band3d::draw_all`]. The RAM a
/// frame needs is the band, its depth rows and what `draw` keeps, whatever
/// the scene's size. Colour is interpolated as `interp` says.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::raster3d::Affine;
/// use microraster::render::Direct3d;
/// use microraster::{Band, Renderer};
/// let mut band = Band::<Gray8, 8, 4>::new(Gray8::new(0));
/// let mut depth = DepthBand::<Depth16, 8, 4>::new();
/// let mut bands = 0;
/// let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |band| {
///     bands += 1; // pipeline.draw_meshlets(&mesh, band)? for each mesh
///     Ok(())
/// });
/// Renderer::new(10, Gray8::new(0)).render(frame, &mut band, &mut MockDisplay::new())?;
/// assert_eq!(bands, 3);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub struct Direct3d<'a, F: DepthFormat, M, G, const W: usize, const H: usize> {
    depth: &'a mut DepthBand<F, W, H>,
    state: DepthState,
    draw: G,
    _m: PhantomData<M>,
}

impl<'a, F, M, G, const W: usize, const H: usize> Direct3d<'a, F, M, G, W, H>
where
    F: DepthFormat,
    M: Interpolation,
{
    /// `draw` called for each band with `depth` as `state` says, colour
    /// interpolated as `interp` says.
    pub fn new<C>(depth: &'a mut DepthBand<F, W, H>, state: DepthState, interp: M, draw: G) -> Self
    where
        C: Interpolate,
        G: FnMut(&mut Band3d<'_, '_, C, F, M, W>) -> Result<(), Error>,
    {
        let _ = interp; // a value, so the call needs no turbofish
        Direct3d { depth, state, draw, _m: PhantomData }
    }
}

impl<C, F, M, G, const W: usize, const H: usize> Pass<C, W, H> for Direct3d<'_, F, M, G, W, H>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    G: FnMut(&mut Band3d<'_, '_, C, F, M, W>) -> Result<(), Error>,
{
    fn draw(&mut self, band: &mut BandView<'_, C, W>, _: &Renderer<C>) -> Result<(), Error> {
        (self.draw)(&mut band3d::<C, F, M, W, H>(band, self.depth, self.state))
    }
}

/// The vertex stage run once per band instead of once per frame, for parts
/// whose RAM cannot hold a whole frame's bins: for each band
/// `geometry(y0, y1, bins)` appends the triangles touching rows `y0..y1`
/// (set [`Pipeline::rows`](crate::pipeline::Pipeline::rows) to
/// `Some((y0, y1 − 1))` and call `draw_mesh`) to `bins`, cleared before each
/// band; they are drawn as [`Triangles3d`] draws them. Vertex work grows
/// with the number of bands; the image is the same as with [`Triangles3d`].
/// The first error `geometry` returns is the frame's
/// ([`RenderError::Input`](crate::RenderError::Input)).
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::raster3d::{Affine, ScreenTriangle};
/// use microraster::render::PerBand3d;
/// use microraster::{Band, Renderer};
/// let mut bins = heapless::Vec::<ScreenTriangle<4>, 64>::new();
/// let mut band = Band::<Gray8, 8, 4>::new(Gray8::new(0));
/// let mut depth = DepthBand::<Depth16, 8, 4>::new();
/// let mut rows = Vec::new();
/// let frame = PerBand3d::new(&mut bins, &mut depth, DepthState::LESS_WRITE, Affine, |y0, y1, _bins| {
///     rows.push((y0, y1)); // pipeline.rows = Some((y0, y1 - 1)); pipeline.draw_mesh(.., bins)
///     Ok(())
/// });
/// Renderer::new(10, Gray8::new(0)).render(frame, &mut band, &mut MockDisplay::new())?;
/// assert_eq!(rows, [(0, 4), (4, 8), (8, 10)]);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub struct PerBand3d<'a, F: DepthFormat, M, G, const S: u32, const N: usize, const W: usize, const H: usize> {
    bins: &'a mut heapless::Vec<ScreenTriangle<S>, N>,
    depth: &'a mut DepthBand<F, W, H>,
    state: DepthState,
    geometry: G,
    _m: PhantomData<M>,
}

impl<'a, F, M, G, const S: u32, const N: usize, const W: usize, const H: usize>
    PerBand3d<'a, F, M, G, S, N, W, H>
where
    F: DepthFormat,
    M: Interpolation,
    G: FnMut(i32, i32, &mut heapless::Vec<ScreenTriangle<S>, N>) -> Result<(), Error>,
{
    /// `geometry` run for each band into `bins`, drawn with `depth` as
    /// `state` says, colour interpolated as `interp` says.
    pub fn new(
        bins: &'a mut heapless::Vec<ScreenTriangle<S>, N>,
        depth: &'a mut DepthBand<F, W, H>,
        state: DepthState,
        interp: M,
        geometry: G,
    ) -> Self {
        let _ = interp; // a value, so the call needs no turbofish
        PerBand3d { bins, depth, state, geometry, _m: PhantomData }
    }
}

impl<C, F, M, G, const S: u32, const N: usize, const W: usize, const H: usize> Pass<C, W, H>
    for PerBand3d<'_, F, M, G, S, N, W, H>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    G: FnMut(i32, i32, &mut heapless::Vec<ScreenTriangle<S>, N>) -> Result<(), Error>,
{
    fn draw(&mut self, band: &mut BandView<'_, C, W>, _: &Renderer<C>) -> Result<(), Error> {
        let (y0, y1) = (band.y0(), band.y1());
        self.bins.clear();
        (self.geometry)(y0, y1, self.bins)?;
        band3d::<C, F, M, W, H>(band, self.depth, self.state).draw_all(self.bins);
        Ok(())
    }
}

/// The band's [`Band3d`], its depth rows cleared to far.
fn band3d<'a, 'v, C, F, M, const W: usize, const H: usize>(
    view: &'a mut BandView<'v, C, W>,
    depth: &'a mut DepthBand<F, W, H>,
    state: DepthState,
) -> Band3d<'a, 'v, C, F, M, W>
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    depth.clear(view.height());
    Band3d::new(view, depth.rows_mut(view.height()), state)
}
