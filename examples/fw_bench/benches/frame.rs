//! The buffers a configuration may use, and one frame of it: the preparation
//! outside the timed frame and the frame the firmware times.

use core::convert::Infallible;
use core::hint::black_box;

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand};
use microraster::light::Viewer::{Infinite, Local};
use microraster::math::Fx;
use microraster::mesh::MAX_MESHLET_VERTICES;
use microraster::pipeline::{ClusterCache, VertexCache};
use microraster::raster3d::{Affine, PerspectiveCorrect, ScreenTriangle};
use microraster::render::{Triangles3d, from_fn};
use microraster::view3d::View3d;
use microraster::{Band, Error, Primitive, RenderError, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::CACHE_VERTICES;

use super::Interp::{Affine as Aff, Perspective as Persp};
use super::Vertex::{F32, Fx as Fix};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::dashboard;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::knot::{knot_stage, knot_tall, knot_vertex_rows, meshlets};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::scene3d::front3d;
use super::scene3d::{cached_vertex_stage, frame3d, per_band3d, vertex3d, vertex3d_per_band};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::tiers::{frame3d_tier, knot_tall_tier, knot_tier};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::ways;
use super::{Sink, TALL_20, TALL_32, TALL_48, TALL_240, Work};
use crate::workload::{self, DEPTH_STATE, S};

/// Everything a configuration may use; on the target each buffer is its own
/// `static`. `W`/`H`: band width (= frame width) and rows; `N`: bins;
/// `P`: primitives.
pub struct Buffers<'a, const W: usize, const H: usize, const N: usize, const P: usize> {
    /// 2D primitives ([`Work::Frame2d`]).
    pub prims: &'a mut heapless::Vec<Primitive<Rgb565, S>, P>,
    /// Colour band.
    pub band: &'a mut Band<Rgb565, W, H>,
    /// Depth band.
    pub depth: &'a mut DepthBand<Depth16, W, H>,
    /// Screen triangles (the frame's, or one band's).
    pub bins: &'a mut heapless::Vec<ScreenTriangle<S>, N>,
    /// Vertex cache ([`Work::Vertex3dCached`]; none on the Cortex-M0).
    pub cache: Option<&'a mut Cache>,
    /// One meshlet's vertices and the frame's cluster record
    /// ([`Work::Meshlets`]), per numeric path. None on the Cortex-M0 (its
    /// 16 KB hold no knot row).
    pub cluster: Option<(&'a mut ClusterCache<f32, S>, &'a mut ClusterCache<Fx, S>)>,
    /// A cluster-sized vertex cache ([`Work::Vertex3dChunked`],
    /// [`Work::Frame3dChunked`]); none on the Cortex-M0.
    pub chunk: Option<&'a mut VertexCache<f32, S, MAX_MESHLET_VERTICES>>,
    /// Taller bands ([`Work::KnotTall`]); not on the Cortex-M0, whose
    /// stack has no room for even this field's bytes.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    pub tall: Option<Tall<'a, W>>,
    /// The one-call front with its own bands and cluster cache
    /// ([`Work::Front3d`]); not on the Cortex-M0.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    pub view: Option<&'a mut View<W, H>>,
    /// The 20k and 5k knots' frame bins ([`Work::Ways`] with
    /// [`Way::Bins`](super::ways::Way::Bins)); not on the Cortex-M0.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    pub knot_bins: Option<(&'a mut KnotBins, &'a mut Knot5kBins)>,
}

/// The bins of [`Work::Ways`]' full-frame 20k row (Cortex-M4F only).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
pub type KnotBins = heapless::Vec<ScreenTriangle<S>, { super::ways::KNOT_BINS }>;
/// The bins of [`Work::Ways`]' full-frame 5k row (Cortex-M4F only).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
pub type Knot5kBins = heapless::Vec<ScreenTriangle<S>, { super::ways::KNOT5K_BINS }>;

/// The front of [`Work::Front3d`] (Cortex-M4F only).
pub type View<const W: usize, const H: usize> = View3d<Rgb565, W, H>;

/// The colour and depth bands of [`Work::KnotTall`].
pub struct Tall<'a, const W: usize> {
    /// [`TALL_20`] rows.
    pub band20: &'a mut Band<Rgb565, W, TALL_20>,
    /// Depth rows of `band20`.
    pub depth20: &'a mut DepthBand<Depth16, W, TALL_20>,
    /// [`TALL_32`] rows ([`Work::KnotTallTier`]).
    pub band32: &'a mut Band<Rgb565, W, TALL_32>,
    /// Depth rows of `band32`.
    pub depth32: &'a mut DepthBand<Depth16, W, TALL_32>,
    /// [`TALL_48`] rows.
    pub band48: &'a mut Band<Rgb565, W, TALL_48>,
    /// Depth rows of `band48`.
    pub depth48: &'a mut DepthBand<Depth16, W, TALL_48>,
    /// [`TALL_240`] rows.
    pub band240: &'a mut Band<Rgb565, W, TALL_240>,
    /// Depth rows of `band240`.
    pub depth240: &'a mut DepthBand<Depth16, W, TALL_240>,
}

/// The vertex cache of [`Work::Vertex3dCached`].
pub type Cache = VertexCache<f32, S, CACHE_VERTICES>;

pub(super) fn input(e: RenderError<Infallible>) -> Error {
    match e {
        RenderError::Input(e) => e,
        RenderError::Target(never) => match never {},
    }
}

/// Prepares `work` (outside the timed frame: collects a [`Work::Frame2d`]
/// scene into the primitive buffer).
pub fn prepare<const W: usize, const H: usize, const N: usize, const P: usize>(
    work: Work,
    height: u32,
    b: &mut Buffers<'_, W, H, N, P>,
) -> Result<(), Error> {
    if let Work::Frame2d(scene) = work {
        b.prims.clear();
        if scenes::collect(scene, W as u32, height, b.prims)? != 0 {
            return Err(Error::BufferTooSmall);
        }
    }
    Ok(())
}

/// Renders one frame of `work` (after [`prepare`]) into `sink` with background `bg`:
/// what the firmware times.
pub fn frame<const W: usize, const H: usize, const N: usize, const P: usize>(
    work: Work,
    height: u32,
    bg: Rgb565,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    // The taller-band rows apart: in the same function their code changed
    // how the compiler laid out (and how much stack took) every other row.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    match work {
        Work::KnotVertexRows(rows) => {
            let c = b.cluster.as_mut().ok_or(Error::BufferTooSmall)?;
            return knot_vertex_rows::<W>(height, rows, c.0);
        }
        Work::KnotTall(rows) => {
            let c = b.cluster.as_mut().ok_or(Error::BufferTooSmall)?;
            let t = b.tall.as_mut().ok_or(Error::BufferTooSmall)?;
            return knot_tall::<W>(Renderer::new(height, bg), rows, t, c.0, sink);
        }
        Work::Front3d => {
            return front3d(b.view.as_deref_mut().ok_or(Error::BufferTooSmall)?, height, bg, sink);
        }
        Work::KnotTier(p, eye, t, i) => return knot_tier(Renderer::new(height, bg), (p, eye, t, i), b, sink),
        Work::KnotTallTier(p, rows) => {
            let c = b.cluster.as_mut().ok_or(Error::BufferTooSmall)?;
            let t = b.tall.as_mut().ok_or(Error::BufferTooSmall)?;
            return knot_tall_tier::<W>(Renderer::new(height, bg), (p, rows), t, c.0, sink);
        }
        Work::Frame3dTier(p, t, i) => return frame3d_tier(Renderer::new(height, bg), (p, t, i), b, sink),
        Work::Ways(knot, way) => return ways_frame(knot, way, height, bg, b, sink),
        _ => {}
    }
    frame_other(work, height, bg, b, sink)
}

/// [`Work::Ways`] (not inlined, as the taller-band rows).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[inline(never)]
fn ways_frame<const W: usize, const H: usize, const N: usize, const P: usize>(
    knot: ways::Knot,
    way: ways::Way,
    height: u32,
    bg: Rgb565,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let r = Renderer::new(height, bg);
    match way {
        ways::Way::Front => {
            ways::front(b.view.as_deref_mut().ok_or(Error::BufferTooSmall)?, knot, height, bg, sink)
        }
        ways::Way::Meshlets => {
            let c = b.cluster.as_mut().ok_or(Error::BufferTooSmall)?;
            ways::meshlets::<W, H>(r, b.band, b.depth, c.0, knot, sink)
        }
        ways::Way::Bins => match (knot, b.knot_bins.as_mut().ok_or(Error::BufferTooSmall)?) {
            (ways::Knot::K20, (bins, _)) => ways::bins(r, b.band, b.depth, bins, knot, sink),
            (ways::Knot::K5, (_, bins)) => ways::bins(r, b.band, b.depth, bins, knot, sink),
        },
    }
}

/// [`frame`] for every row but the taller-band ones.
#[inline(never)]
fn frame_other<const W: usize, const H: usize, const N: usize, const P: usize>(
    work: Work,
    height: u32,
    bg: Rgb565,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let r = Renderer::new(height, bg);
    match work {
        Work::Clear => r.render((), b.band, sink).map_err(input),
        Work::Frame2d(_) => r.render(&b.prims[..], b.band, sink).map_err(input),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Dashboard => r.render(from_fn(dashboard::dashboard), b.band, sink).map_err(input),
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::Dashboard => Err(Error::InvalidParameter(microraster::Param::User)),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::DashboardDrive => super::drive::drive(r, b.band, sink),
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::DashboardDrive => Err(Error::InvalidParameter(microraster::Param::User)),
        Work::Streamed2d(scene) => {
            r.render(workload::streamed::<W>(scene, height), b.band, sink).map_err(input)
        }
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Vertex3d(F32) => vertex3d::<f32, W, N>(height, b.bins),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Vertex3d(Fix) => vertex3d::<Fx, W, N>(height, b.bins),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Vertex3dCached => {
            let cache = b.cache.as_deref_mut().ok_or(Error::BufferTooSmall)?;
            black_box(cached_vertex_stage::<CACHE_VERTICES, W, N>(height, cache, b.bins)?);
            Ok(())
        }
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Vertex3dChunked => {
            let cache = b.chunk.as_deref_mut().ok_or(Error::BufferTooSmall)?;
            black_box(cached_vertex_stage::<MAX_MESHLET_VERTICES, W, N>(height, cache, b.bins)?);
            Ok(())
        }
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Frame3dChunked => {
            let cache = b.chunk.as_deref_mut().ok_or(Error::BufferTooSmall)?;
            cached_vertex_stage::<MAX_MESHLET_VERTICES, W, N>(height, cache, b.bins)?;
            r.render(Triangles3d::new(b.bins, b.depth, DEPTH_STATE, Affine), b.band, sink).map_err(input)
        }
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::VertexPerBand3d(F32) => vertex3d_per_band::<f32, W, H, N>(height, b.bins, |_, _| ()),
        Work::VertexPerBand3d(Fix) => vertex3d_per_band::<Fx, W, H, N>(height, b.bins, |_, _| ()),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Frame3d(F32, Persp) => frame3d::<f32, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Frame3d(F32, Aff) => frame3d::<f32, Affine, W, H, N, P>(r, b, sink),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Frame3d(Fix, Persp) => frame3d::<Fx, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Frame3d(Fix, Aff) => frame3d::<Fx, Affine, W, H, N, P>(r, b, sink),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::PerBand3d(F32, Persp) => per_band3d::<f32, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::PerBand3d(F32, Aff) => per_band3d::<f32, Affine, W, H, N, P>(r, b, sink),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::PerBand3d(Fix, Persp) => per_band3d::<Fx, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        Work::PerBand3d(Fix, Aff) => per_band3d::<Fx, Affine, W, H, N, P>(r, b, sink),
        // Rows not on the Cortex-M0's list, left out of its build: with both
        // accuracy tiers' code the benchmark would not fit the micro:bit's
        // 256 KB of flash (soft float's f32 against Fx: `firmware.sh sweep`).
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::Vertex3d(_)
        | Work::Frame3d(..)
        | Work::PerBand3d(_, Persp)
        | Work::PerBand3d(F32, _)
        | Work::VertexPerBand3d(F32)
        | Work::Vertex3dCached
        | Work::Vertex3dChunked
        | Work::Frame3dChunked => Err(Error::InvalidParameter(microraster::Param::User)),
        // The knot's 460 KB of flash data do not fit the micro:bit: Cortex-M4F only.
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Meshlets(t, i) => match (t, i, b.cluster.as_mut().ok_or(Error::BufferTooSmall)?) {
            (F32, Aff, c) => meshlets::<f32, _, W, H>(r, b.band, b.depth, c.0, Affine, Local, sink),
            (F32, Persp, c) => {
                meshlets::<f32, _, W, H>(r, b.band, b.depth, c.0, PerspectiveCorrect, Local, sink)
            }
            (Fix, Aff, c) => meshlets::<Fx, _, W, H>(r, b.band, b.depth, c.1, Affine, Local, sink),
            (Fix, Persp, c) => {
                meshlets::<Fx, _, W, H>(r, b.band, b.depth, c.1, PerspectiveCorrect, Local, sink)
            }
        },
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::MeshletsFar(i) => match (i, b.cluster.as_mut().ok_or(Error::BufferTooSmall)?) {
            (Aff, c) => meshlets::<f32, _, W, H>(r, b.band, b.depth, c.0, Affine, Infinite, sink),
            (Persp, c) => {
                meshlets::<f32, _, W, H>(r, b.band, b.depth, c.0, PerspectiveCorrect, Infinite, sink)
            }
        },
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::KnotStage(t, stage) => match (t, b.cluster.as_mut().ok_or(Error::BufferTooSmall)?) {
            (F32, c) => knot_stage::<f32, W, H>(r, b.band, b.depth, c.0, stage, sink),
            (Fix, c) => knot_stage::<Fx, W, H>(r, b.band, b.depth, c.1, stage, sink),
        },
        // In `frame`.
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::KnotVertexRows(_)
        | Work::KnotTall(_)
        | Work::Front3d
        | Work::KnotTier(..)
        | Work::KnotTallTier(..)
        | Work::Ways(..) => Err(Error::InvalidParameter(microraster::Param::User)),
        // Cortex-M4F rows only (in `frame` there).
        Work::Frame3dTier(..) => Err(Error::InvalidParameter(microraster::Param::User)),
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::Meshlets(..) | Work::MeshletsFar(_) | Work::KnotStage(..) => {
            Err(Error::InvalidParameter(microraster::Param::User))
        }
    }
}
