//! The 3D passes: screen triangles depth-tested into each band, binned once
//! per frame ([`Triangles3d`]) or drawn straight into the band
//! ([`Direct3d`]: meshlets, or the vertex stage run per band).

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
/// for each mesh, or collects the band's triangles (set
/// [`Pipeline::rows`](crate::pipeline::Pipeline::rows) to
/// [`Band3d::rows`] and call `draw_valid_mesh` into small bins of your own)
/// and draws them with [`Band3d::draw_all`] (the second example). The RAM a
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
///
/// A plain mesh with the vertex stage run once per band, its triangles in
/// bins that hold one band's (the image is that of [`Triangles3d`] over the
/// frame's bins; vertex work grows with the number of bands):
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::math::{Mat4, Vec3, transform};
/// use microraster::pipeline::Pipeline;
/// use microraster::raster3d::{Affine, ScreenTriangle};
/// use microraster::render::Direct3d;
/// use microraster::view3d::CUBE;
/// use microraster::{Band, Renderer};
/// let eye = transform::look_at(Vec3::new(2.0, 2.0, 3.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
/// let mut pipeline = Pipeline::<f32, 4>::perspective(eye, 1.0, 1.0, 10.0, 16, 16)?;
/// let mut bins = microraster::heapless::Vec::<ScreenTriangle<4>, 12>::new();
/// let mut band = Band::<Rgb565, 16, 4>::new(Rgb565::BLACK);
/// let mut depth = DepthBand::<Depth16, 16, 4>::new();
/// let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |band| {
///     bins.clear();
///     pipeline.rows = Some(band.rows());
///     pipeline.draw_valid_mesh(&CUBE, &Mat4::IDENTITY, Rgb565::RED, &mut bins)?;
///     band.draw_all(&bins);
///     Ok(())
/// });
/// let mut display = MockDisplay::new();
/// Renderer::new(16, Rgb565::BLACK).render(frame, &mut band, &mut display)?;
/// assert_ne!(display.get_pixel(embedded_graphics::prelude::Point::new(8, 8)), Some(Rgb565::BLACK));
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
