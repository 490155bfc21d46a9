//! The standard 3D scene's vertex stage and frames, and the triangles and
//! lines of one frame of each configuration (the host's count).

use core::hint::black_box;

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::math::{Fx, Scalar};
use microraster::pipeline::{MeshStats, VertexCache};
use microraster::raster3d::{Interpolation, ScreenTriangle};
use microraster::render::{Direct3d, Triangles3d};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use microraster::view3d::View3d;
use microraster::{Error, Primitive, Renderer};
use microraster_scenes::scenes3d::Scene3d;

use super::Vertex::{F32, Fx as Fix};
use super::frame::{Buffers, input};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::knot_mesh;
use super::tiers::scene_triangles;
use super::{Scene2d, Sink, Vertex, Work};
use crate::workload::{ANGLE, DEPTH_STATE, S};

pub(super) fn vertex3d<T: Scalar, const W: usize, const N: usize>(
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?;
    bins.clear();
    black_box(Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?);
    Ok(())
}

/// The vertex stage once per band of `H` rows; `each(y0, bins)` sees each
/// band's triangles.
pub(super) fn vertex3d_per_band<T: Scalar, const W: usize, const H: usize, const N: usize>(
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    mut each: impl FnMut(i32, &[ScreenTriangle<S>]),
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?;
    let mut y0 = 0;
    while y0 < height as i32 {
        let y1 = (y0 + H as i32).min(height as i32);
        pipeline.rows = Some((y0, y1 - 1));
        bins.clear();
        black_box(Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?);
        each(y0, bins);
        y0 = y1;
    }
    Ok(())
}

/// The standard scene's `f32` vertex stage into `bins` through a cache of
/// `V` vertices (the whole of each mesh, or chunks of it).
pub(super) fn cached_vertex_stage<const V: usize, const W: usize, const N: usize>(
    height: u32,
    cache: &mut VertexCache<f32, S, V>,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
) -> Result<MeshStats, Error> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, height)?;
    bins.clear();
    Scene3d.draw_cached::<f32, Rgb565, S, V, N>(&pipeline, ANGLE, cache, bins)
}

pub(super) fn frame3d<
    T: Scalar,
    M: Interpolation,
    const W: usize,
    const H: usize,
    const N: usize,
    const P: usize,
>(
    r: Renderer<Rgb565>,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let height = r.height();
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?;
    b.bins.clear();
    Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, b.bins)?;
    r.render(Triangles3d::new(b.bins, b.depth, DEPTH_STATE, M::default()), b.band, sink).map_err(input)
}

pub(super) fn per_band3d<
    T: Scalar,
    M: Interpolation,
    const W: usize,
    const H: usize,
    const N: usize,
    const P: usize,
>(
    r: Renderer<Rgb565>,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, r.height())?;
    let bins = &mut *b.bins;
    // The vertex stage per band into one band's bins (the way the removed
    // `PerBand3d` pass did it).
    let frame = Direct3d::new(b.depth, DEPTH_STATE, M::default(), |b3| {
        bins.clear();
        pipeline.rows = Some(b3.rows());
        Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?;
        b3.draw_all(bins);
        Ok(())
    });
    r.render(frame, b.band, sink).map_err(input)
}

/// The standard scene through the one-call front ([`Work::Front3d`]): the
/// camera, light and shading of [`Scene3d::pipeline`], frames of `height`
/// rows on background `bg`.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
pub(super) fn front3d<const W: usize, const H: usize>(
    view: &mut View3d<Rgb565, W, H>,
    height: u32,
    bg: Rgb565,
    sink: &mut Sink,
) -> Result<(), Error> {
    let p = Scene3d::pipeline::<f32, S>(W as u32, height)?;
    view.set_height(Some(height));
    view.set_background(bg);
    view.set_lighting(p.lighting);
    view.set_cull(p.cull);
    view.set_shade(p.shade);
    view.draw(&Scene3d::camera(), &Scene3d::objects(ANGLE), sink).map_err(input)
}

/// Triangles and lines of one frame of `work` (each triangle counted once,
/// in the band of its top row, when the vertex stage runs per band).
pub fn primitives<const W: usize, const H: usize, const N: usize, const P: usize>(
    work: Work,
    height: u32,
    b: &mut Buffers<'_, W, H, N, P>,
) -> Result<(u32, u32), Error> {
    let mut tris = 0u32;
    let mut count_2d = |scene: Scene2d| -> Result<(u32, u32), Error> {
        let mut lines = 0;
        scene(W as u32, height, &mut |p| match p {
            Primitive::Triangle(_) => tris += 1,
            Primitive::Line(_) => lines += 1,
        })?;
        Ok((tris, lines))
    };
    let mut count_3d = |t: Vertex| {
        let mut tris = 0u32;
        let mut each = |y0: i32, bins: &[ScreenTriangle<S>]| {
            tris += bins.iter().filter(|t| t.rows().0.max(0) / H as i32 == y0 / H as i32).count() as u32;
        };
        match t {
            F32 => vertex3d_per_band::<f32, W, H, N>(height, b.bins, &mut each),
            Fix => vertex3d_per_band::<Fx, W, H, N>(height, b.bins, &mut each),
        }
        .map(|()| (tris, 0))
    };
    match work {
        Work::Clear | Work::Dashboard | Work::DashboardDrive => Ok((0, 0)),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Meshlets(..)
        | Work::MeshletsFar(_)
        | Work::KnotStage(..)
        | Work::KnotVertexRows(_)
        | Work::KnotTall(_)
        | Work::KnotTier(..)
        | Work::KnotTallTier(..) => Ok((knot_mesh::KNOT.triangles.len() as u32, 0)),
        Work::Frame3dTier(p, F32, _) => Ok((scene_triangles::<f32, W, H, N>(p, height, b.bins)?, 0)),
        Work::Frame3dTier(p, Fix, _) => Ok((scene_triangles::<Fx, W, H, N>(p, height, b.bins)?, 0)),
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::Meshlets(..) | Work::MeshletsFar(_) | Work::KnotStage(..) => {
            Err(Error::InvalidParameter(microraster::Param::User))
        }
        Work::Frame2d(scene) | Work::Streamed2d(scene) => count_2d(scene),
        Work::Vertex3dCached | Work::Vertex3dChunked | Work::Frame3dChunked => count_3d(F32),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Front3d => count_3d(F32),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Ways(knot, _) => Ok((knot.triangles(), 0)),
        Work::Vertex3d(t) | Work::VertexPerBand3d(t) | Work::Frame3d(t, _) | Work::PerBand3d(t, _) => {
            count_3d(t)
        }
    }
}
