//! Issue 61's rows: the knot and the standard scene in either accuracy tier
//! ([`Precision`]), the knot also with the camera twice as close, and the
//! knot's frame in taller bands per tier (the Pareto table of instructions
//! against RAM).
//!
//! Apart from the older rows' functions (`knot.rs`, `scene3d.rs`) and not
//! inlined into [`frame`](super::frame()): the older rows keep their code
//! generation, so their counts, which the docs quote, do not move.

use embedded_graphics_core::pixelcolor::Rgb565;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use microraster::depth::{Depth16, DepthBand};
use microraster::math::{Fx, Scalar};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use microraster::pipeline::ClusterCache;
use microraster::pipeline::Pipeline;
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, Precision, ScreenTriangle};
use microraster::render::Triangles3d;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use microraster::{Band, render::Direct3d};
use microraster::{Error, Renderer};
use microraster_scenes::scenes3d::Scene3d;

use super::Interp::{Affine as Aff, Perspective as Persp};
use super::Vertex::{F32, Fx as Fix};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::frame::Tall;
use super::frame::{Buffers, input};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::knot::{KNOT_COLOR, knot_model};
use super::{Eye, Interp, Sink, Vertex, knot_eye};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::{TALL_20, TALL_32, TALL_48, knot_mesh};
use crate::workload::{ANGLE, DEPTH_STATE, S};

/// The knot's camera and tier ([`knot_eye::pipeline`]), `S` subpixel bits.
fn pipeline<T: Scalar>(
    eye: Eye,
    precision: Precision,
    width: u32,
    height: u32,
) -> Result<Pipeline<T, S>, Error> {
    knot_eye::pipeline::<T, S>(eye, precision, width, height)
}

#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
/// [`Work::KnotTier`](super::Work::KnotTier): the knot through the meshlet
/// stage, straight into each band, as `Work::Meshlets` but in tier
/// `precision` and seen from `eye`.
#[inline(never)]
pub(super) fn knot_tier<const W: usize, const H: usize, const N: usize, const P: usize>(
    r: Renderer<Rgb565>,
    (precision, eye, vertex, interp): (Precision, Eye, Vertex, Interp),
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let c = b.cluster.as_mut().ok_or(Error::BufferTooSmall)?;
    let (band, depth) = (&mut *b.band, &mut *b.depth);
    match (vertex, interp) {
        (F32, Aff) => knot::<f32, Affine, W, H>(r, band, depth, c.0, eye, precision, sink),
        (F32, Persp) => knot::<f32, PerspectiveCorrect, W, H>(r, band, depth, c.0, eye, precision, sink),
        (Fix, Aff) => knot::<Fx, Affine, W, H>(r, band, depth, c.1, eye, precision, sink),
        (Fix, Persp) => knot::<Fx, PerspectiveCorrect, W, H>(r, band, depth, c.1, eye, precision, sink),
    }
}

#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
/// [`Work::KnotTallTier`](super::Work::KnotTallTier): the `f32` affine knot
/// in bands of `rows` rows, in tier `precision`.
#[inline(never)]
pub(super) fn knot_tall_tier<const W: usize>(
    r: Renderer<Rgb565>,
    (precision, rows): (Precision, u16),
    t: &mut Tall<'_, W>,
    cache: &mut ClusterCache<f32, S>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let (eye, p) = (Eye::Standard, precision);
    match rows as usize {
        TALL_20 => knot::<f32, Affine, W, TALL_20>(r, t.band20, t.depth20, cache, eye, p, sink),
        TALL_32 => knot::<f32, Affine, W, TALL_32>(r, t.band32, t.depth32, cache, eye, p, sink),
        TALL_48 => knot::<f32, Affine, W, TALL_48>(r, t.band48, t.depth48, cache, eye, p, sink),
        _ => Err(Error::InvalidParameter(microraster::Param::User)),
    }
}

/// [`Work::Frame3dTier`](super::Work::Frame3dTier): the standard scene's
/// vertex stage once per frame in tier `precision`, then `Triangles3d`.
#[inline(never)]
pub(super) fn frame3d_tier<const W: usize, const H: usize, const N: usize, const P: usize>(
    r: Renderer<Rgb565>,
    (precision, vertex, interp): (Precision, Vertex, Interp),
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    match (vertex, interp) {
        (F32, Aff) => scene::<f32, Affine, W, H, N, P>(r, precision, b, sink),
        (F32, Persp) => scene::<f32, PerspectiveCorrect, W, H, N, P>(r, precision, b, sink),
        (Fix, Aff) => scene::<Fx, Affine, W, H, N, P>(r, precision, b, sink),
        (Fix, Persp) => scene::<Fx, PerspectiveCorrect, W, H, N, P>(r, precision, b, sink),
    }
}

#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(clippy::too_many_arguments)]
fn knot<T: Scalar, M: Interpolation, const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    cache: &mut ClusterCache<T, S>,
    eye: Eye,
    precision: Precision,
    sink: &mut Sink,
) -> Result<(), Error> {
    let pipeline = pipeline::<T>(eye, precision, W as u32, r.height())?;
    let model = knot_model::<T>();
    r.render(
        Direct3d::new(depth, DEPTH_STATE, M::default(), |band| {
            pipeline.draw_meshlets(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, band).map(|_| ())
        }),
        band,
        sink,
    )
    .map_err(input)
}

fn scene<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize, const P: usize>(
    r: Renderer<Rgb565>,
    precision: Precision,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let pipeline = pipeline::<T>(Eye::Standard, precision, W as u32, r.height())?;
    b.bins.clear();
    Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, b.bins)?;
    r.render(Triangles3d::new(b.bins, b.depth, DEPTH_STATE, M::default()), b.band, sink).map_err(input)
}

/// The standard scene's triangles of a frame in tier `precision`, each
/// counted once, in the band of its top row (the host's count).
pub(super) fn scene_triangles<T: Scalar, const W: usize, const H: usize, const N: usize>(
    precision: Precision,
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
) -> Result<u32, Error> {
    let mut pipeline = pipeline::<T>(Eye::Standard, precision, W as u32, height)?;
    let (mut y0, mut tris) = (0, 0u32);
    while y0 < height as i32 {
        let y1 = (y0 + H as i32).min(height as i32);
        pipeline.rows = Some((y0, y1 - 1));
        bins.clear();
        Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?;
        tris += bins.iter().filter(|t| t.rows().0.max(0) / H as i32 == y0 / H as i32).count() as u32;
        y0 = y1;
    }
    Ok(tris)
}
