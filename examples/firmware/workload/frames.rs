//! The standard scenes rendered band by band into a [`CrcTarget`]: the 2D
//! scene collected or streamed, the 3D scene binned per frame or per band.

use core::convert::Infallible;

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::band::BandView;
use microraster::depth::{Depth16, DepthBand};
use microraster::edge::Cull;
use microraster::math::Scalar;
use microraster::raster3d::{Interpolation, Precision, ScreenTriangle};
use microraster::render::{Direct3d, FromFn, Triangles3d, from_fn};
use microraster::{Band, Error, Primitive, RenderError, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::Scene3d;

use super::{ANGLE, BACKGROUND, CrcTarget, DEPTH_STATE, Out, S};

fn render_error(e: RenderError<Infallible>) -> Error {
    match e {
        RenderError::Input(e) => e,
        RenderError::Target(never) => match never {},
    }
}

/// The standard 2D scene ([`scenes::mixed`]) collected into `prims`, then
/// [`Renderer::render`].
pub fn mixed<const W: usize, const H: usize>(
    name: &'static str,
    height: u32,
    prims: &mut heapless::Vec<Primitive<Rgb565, S>, { scenes::MIXED_LEN }>,
    band: &mut Band<Rgb565, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    prims.clear();
    if scenes::collect(scenes::mixed, W as u32, height, prims)? != 0 {
        return Err(Error::BufferTooSmall);
    }
    let mut target = CrcTarget::new(name, W as u32, height, out);
    Renderer::new(height, BACKGROUND).render(&prims[..], band, &mut target).map_err(render_error)?;
    target.finish();
    Ok(())
}

/// The same scene with no primitive storage: for each band the scene
/// function runs again and the primitives that touch the band are drawn
/// straight into it (the pixels are those of [`mixed`]).
pub fn mixed_streamed<const W: usize, const H: usize>(
    name: &'static str,
    height: u32,
    band: &mut Band<Rgb565, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    let mut target = CrcTarget::new(name, W as u32, height, out);
    let frame = streamed::<W>(scenes::mixed::<Rgb565, S>, height);
    Renderer::new(height, BACKGROUND).render(frame, band, &mut target).map_err(render_error)?;
    target.finish();
    Ok(())
}

/// The pass that runs `scene` again for every band and draws the
/// primitives touching the band straight into it: a 2D frame with no
/// primitive storage. The scene's first error is the frame's.
pub fn streamed<const W: usize>(
    scene: scenes::Scene<Rgb565, S>,
    height: u32,
) -> FromFn<Rgb565, impl FnMut(&mut BandView<'_, Rgb565, W>) -> Result<(), Error>, W> {
    from_fn(move |view| {
        let (y0, y1) = (view.y0(), view.y1());
        scene(W as u32, height, &mut |p| {
            let (lo, hi) = p.rows();
            if lo < y1 && hi >= y0 {
                p.draw(view, Cull::None);
            }
        })
    })
}

/// The standard 3D scene ([`Scene3d`], meshes in flash) with the vertex
/// stage run once per frame in accuracy tier `precision`: every visible
/// triangle binned, then `Triangles3d` with `M` colour interpolation.
#[allow(clippy::too_many_arguments)]
pub fn scene3d<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize>(
    name: &'static str,
    precision: Precision,
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?.with_precision(precision);
    bins.clear();
    Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?;
    let mut target = CrcTarget::new(name, W as u32, height, out);
    Renderer::new(height, BACKGROUND)
        .render(Triangles3d::new(bins, depth, DEPTH_STATE, M::default()), band, &mut target)
        .map_err(render_error)?;
    target.finish();
    Ok(())
}

/// The standard 3D scene with the vertex stage run once per band
/// (a `Direct3d` pass) in accuracy tier `precision`: `bins` holds one
/// band's triangles.
#[allow(clippy::too_many_arguments)]
pub fn scene3d_per_band<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize>(
    name: &'static str,
    precision: Precision,
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?.with_precision(precision);
    let mut target = CrcTarget::new(name, W as u32, height, out);
    let frame = Direct3d::new(depth, DEPTH_STATE, M::default(), |b3| {
        bins.clear();
        pipeline.rows = Some(b3.rows());
        Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?;
        b3.draw_all(bins);
        Ok(())
    });
    Renderer::new(height, BACKGROUND).render(frame, band, &mut target).map_err(render_error)?;
    target.finish();
    Ok(())
}
