//! What the firmware benchmark times: one list of configurations per target
//! ([`M4F`], [`M0`]), shared word for word by the firmware (timed under QEMU
//! with instruction counting) and by the host run (which counts triangles
//! and covered pixels and checks that each frame's CRC equals the target's).
//!
//! Adding a configuration is one line in [`M4F`] or [`M0`]: a name (the
//! scene) and a [`Work`] (what runs). 2D scenes are any
//! [`scenes::Scene`] function (`fn(width, height, sink)`); 3D work runs the
//! standard scene ([`Scene3d`]) on a vertex path ([`Vertex`]) with a colour
//! interpolation ([`Interp`]).
//!
//! The buffers are those of the CRC firmware (`examples/firmware/workload.rs`):
//! Cortex-M4F 320 × 240 in 16-row bands with all the frame's triangles
//! binned ([`BINS`]) and room for [`PRIMS`] primitives; Cortex-M0 160 × 128
//! in 4-row bands with one band's triangles ([`BAND_BINS`]) and no primitive
//! storage (2D scenes are generated again for every band). A 2D scene with
//! more primitives than [`PRIMS`] needs [`Work::Streamed2d`] (or a larger
//! [`PRIMS`]: on QEMU's mps2-an386, where the Cortex-M4F is timed, RAM is
//! 4 MB; the table's RAM column shows the buffer's size).

use core::convert::Infallible;
use core::hint::black_box;

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand};
use microraster::render::{Direct3d, PerBand3d, Triangles3d, from_fn};

// The shape kit does not fit the micro:bit's flash beside the rest: Cortex-M4F only.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(dead_code)] // the bench uses the microraster version only
#[path = "../common/dashboard.rs"]
pub mod dashboard;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[path = "../common/knot_mesh.rs"]
pub mod knot_mesh;
use microraster::edge::Cull;
use microraster::light::Viewer::{self, Infinite, Local};
use microraster::math::{Fx, Scalar};
use microraster::mesh::MAX_MESHLET_VERTICES;
use microraster::pipeline::{ClusterCache, MeshStats, VertexCache};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle};
use microraster::{Band, Error, Primitive, RenderError, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{CACHE_VERTICES, Scene3d};

pub use crate::sink::{Mode, Sink};
use crate::workload::{self, ANGLE, DEPTH_STATE, S};
#[allow(unused_imports)] // each target uses its own
pub use crate::workload::{BACKGROUND, BAND_BINS, M0_BAND, M0_SIZE, M4F_BAND, M4F_SIZE};
#[allow(unused_imports)]
pub use microraster_scenes::scenes3d::BINS;

/// A 2D scene function.
pub type Scene2d = scenes::Scene<Rgb565, S>;

/// The vertex path of the 3D scene.
#[derive(Clone, Copy, Debug)]
pub enum Vertex {
    /// `f32` (hardware floating point on the Cortex-M4F, soft float on the M0).
    F32,
    /// 16.16 fixed point ([`Fx`]).
    Fx,
}

/// Colour interpolation of the 3D scene.
#[derive(Clone, Copy, Debug)]
pub enum Interp {
    /// Screen-space linear ([`Affine`]).
    Affine,
    /// Perspective-correct ([`PerspectiveCorrect`]).
    Perspective,
}

/// What one configuration runs for one frame.
#[derive(Clone, Copy)]
pub enum Work {
    /// The band loop alone: each band cleared and handed to the display.
    /// Every other row includes this cost.
    Clear,
    /// A 2D scene collected once into the primitive buffer, then
    /// [`Renderer::render`]. Scene generation is outside the timed frame.
    Frame2d(Scene2d),
    /// A 2D scene generated again for every band and drawn straight into it
    /// (no primitive storage; generation is inside the timed frame).
    Streamed2d(Scene2d),
    /// The standard 3D scene's vertex stage alone, once per frame, into the
    /// frame's bins (nothing rasterized).
    Vertex3d(Vertex),
    /// [`Work::Vertex3d`] with a vertex cache ([`Scene3d::draw_cached`]:
    /// each vertex transformed, snapped and lit once; `f32` only, Cortex-M4F).
    Vertex3dCached,
    /// [`Work::Vertex3dCached`] with a cache of 64 vertices, one meshlet
    /// cluster's ([`ClusterCache`]): the meshes in chunks of their
    /// triangles, each vertex once per chunk (`f32`, Cortex-M4F).
    Vertex3dChunked,
    /// The whole `f32` affine frame of [`Work::Frame3d`] with the vertex
    /// stage of [`Work::Vertex3dChunked`]: the same bins, so the same frame.
    Frame3dChunked,
    /// The vertex stage once per band, keeping the band's triangles, nothing
    /// rasterized.
    VertexPerBand3d(Vertex),
    /// The vertex stage once per frame, then `Triangles3d`.
    Frame3d(Vertex, Interp),
    /// `PerBand3d`: the vertex stage once per band.
    PerBand3d(Vertex, Interp),
    /// The 20k-triangle knot ([`knot_mesh::KNOT`]) through the meshlet stage:
    /// `Direct3d` with [`Pipeline::draw_meshlets`] per
    /// band, no bins. Its triangle count is the mesh's (instructions per
    /// mesh triangle).
    Meshlets(Vertex, Interp),
    /// [`Work::Meshlets`] in `f32` with the specular term's viewer at
    /// infinity ([`Viewer::Infinite`]: one half vector per mesh, as
    /// OpenGL's default light model and TGX light): the same frame but for
    /// the highlights.
    MeshletsFar(Interp),
    /// The frame of [`Work::Meshlets`] (affine) stopped after one stage, for
    /// the cost breakdown of the report and docs/setup_cost.md: the `f32`
    /// stages are in the default table, the `Fx` ones run on request
    /// (select them by their scene, `knot20k-stages`).
    KnotStage(Vertex, Stage),
    /// What bands of other heights would buy (on request, `knot20k-rows`):
    /// the `f32` vertex stage of [`Work::Meshlets`] for bands of this many
    /// rows ([`Pipeline::meshlet_triangles`] per band, triangles only
    /// counted, no band buffer or band loop). 240 rows: one band, the
    /// vertex work of a framebuffer renderer on the same meshlets.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    KnotVertexRows(u16),
    /// The whole `f32` affine frame of [`Work::Meshlets`] with bands of
    /// [`TALL_48`] or [`TALL_240`] rows (on request, `knot20k-rows`): the
    /// speed a user buys with the RAM of taller bands (240: a whole
    /// colour and depth frame, as a framebuffer renderer holds).
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    KnotTall(u16),
    /// The 2D kit's dashboard ([`dashboard::dashboard`]: shapes with
    /// gradients, anti-aliasing and translucency, an alpha sprite, text),
    /// built and drawn in every band by `render::from_fn`.
    Dashboard,
}

/// How far [`Work::KnotStage`] goes into each band's triangles.
#[derive(Clone, Copy, Debug)]
pub enum Stage {
    /// The band loop and the meshlet vertex stage
    /// ([`Pipeline::meshlet_triangles`]); triangles are only counted.
    Vertex,
    /// [`Stage::Vertex`] and each triangle's coverage in the band
    /// ([`TriangleSpans`]), covered pixels counted.
    Coverage,
    /// The whole frame with a depth test that never passes: coverage,
    /// each covered pixel's depth (per pixel for tiny triangles, from
    /// planes for the others) and the fragment loop, no pixel written.
    NoWrites,
}

/// One timed configuration.
#[derive(Clone, Copy)]
pub struct Bench {
    /// The scene, as the table names it.
    pub scene: &'static str,
    /// What runs.
    pub work: Work,
    /// Run only when selected ([`SELECT_VAR`]), not in the default table.
    pub on_request: bool,
}

const fn bench(scene: &'static str, work: Work) -> Bench {
    Bench { scene, work, on_request: false }
}

/// A configuration run only when selected (the stage breakdown).
const fn probe(scene: &'static str, work: Work) -> Bench {
    Bench { scene, work, on_request: true }
}

/// The environment variable that selects configurations: a comma-separated
/// list of indices and scene names (`8,knot20k`); unset or empty: all. The
/// firmware reads it when it is built, the host when it runs
/// (`bash scripts/firmware.sh table m4f knot20k` sets it for both).
pub const SELECT_VAR: &str = "MICRORASTER_FW_BENCH";

/// Whether configuration `index` of a list is selected by `select` (see
/// [`SELECT_VAR`]).
pub fn selected(select: Option<&str>, index: usize, bench: &Bench) -> bool {
    let Some(select) = select.filter(|s| !s.trim().is_empty()) else { return !bench.on_request };
    select.split(',').map(str::trim).any(|w| w == bench.scene || w.parse() == Ok(index))
}

use Interp::{Affine as Aff, Perspective as Persp};
use Vertex::{F32, Fx as Fix};

/// Cortex-M4F (320 × 240, 16-row bands, frame bins): one line per configuration.
pub const M4F: &[Bench] = &[
    bench("band loop", Work::Clear),
    bench("mixed", Work::Frame2d(scenes::mixed)),
    bench("scene3d", Work::Frame3d(F32, Persp)),
    bench("scene3d", Work::Frame3d(Fix, Persp)),
    bench("scene3d", Work::Frame3d(F32, Aff)),
    bench("scene3d", Work::Vertex3d(F32)),
    bench("scene3d", Work::Vertex3d(Fix)),
    bench("scene3d", Work::Vertex3dCached),
    bench("scene3d", Work::Vertex3dChunked),
    bench("scene3d", Work::Frame3dChunked),
    bench("knot20k", Work::Meshlets(F32, Aff)),
    bench("knot20k", Work::Meshlets(F32, Persp)),
    bench("knot20k", Work::Meshlets(Fix, Aff)),
    bench("knot20k", Work::MeshletsFar(Aff)),
    bench("knot20k", Work::MeshletsFar(Persp)),
    bench("dashboard", Work::Dashboard),
    // The stage breakdown (the report's targets, docs/setup_cost.md); the Fx
    // stages with `table m4f knot20k,knot20k-stages`.
    bench("knot20k-stages", Work::KnotStage(F32, Stage::Vertex)),
    bench("knot20k-stages", Work::KnotStage(F32, Stage::Coverage)),
    bench("knot20k-stages", Work::KnotStage(F32, Stage::NoWrites)),
    probe("knot20k-stages", Work::KnotStage(Fix, Stage::Vertex)),
    probe("knot20k-stages", Work::KnotStage(Fix, Stage::Coverage)),
    probe("knot20k-stages", Work::KnotStage(Fix, Stage::NoWrites)),
    // Taller bands: what more RAM buys (the report's targets,
    // docs/setup_cost.md); the other heights with `table m4f knot20k-rows`.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotVertexRows(240)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTall(TALL_48 as u16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTall(TALL_240 as u16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("knot20k-rows", Work::KnotVertexRows(16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("knot20k-rows", Work::KnotVertexRows(32)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("knot20k-rows", Work::KnotVertexRows(48)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("knot20k-rows", Work::KnotVertexRows(80)),
];

/// Rows of the taller bands of [`Work::KnotTall`] (Cortex-M4F only).
pub const TALL_48: usize = 48;
/// A band as tall as the frame ([`Work::KnotTall`]).
pub const TALL_240: usize = 240;

/// Cortex-M0 (160 × 128, 4-row bands, one band's bins): one line per configuration.
pub const M0: &[Bench] = &[
    bench("band loop", Work::Clear),
    bench("mixed", Work::Streamed2d(scenes::mixed)),
    bench("scene3d", Work::PerBand3d(Fix, Aff)),
    bench("scene3d", Work::PerBand3d(F32, Aff)),
    bench("scene3d", Work::VertexPerBand3d(Fix)),
    bench("scene3d", Work::VertexPerBand3d(F32)),
];

/// Primitives the Cortex-M4F configuration can hold ([`Work::Frame2d`]).
pub const PRIMS: usize = scenes::MIXED_LEN;

impl Work {
    /// How the frame is produced, for the table.
    pub fn describe(&self) -> &'static str {
        match self {
            Work::Clear => "clear + send each band",
            Work::Frame2d(_) => "primitives in RAM",
            Work::Streamed2d(_) => "regenerated per band",
            Work::Vertex3d(F32) => "f32 vertex stage only",
            Work::Vertex3d(Fix) => "Fx vertex stage only",
            Work::Vertex3dCached => "f32 vertex stage only, vertex cache",
            Work::Vertex3dChunked => "f32 vertex stage only, 64-vertex cache (chunks)",
            Work::Frame3dChunked => "f32, affine, 64-vertex cache (chunks)",
            Work::VertexPerBand3d(F32) => "f32 vertex stage only, per band",
            Work::VertexPerBand3d(Fix) => "Fx vertex stage only, per band",
            Work::Frame3d(F32, Persp) => "f32, persp.-correct",
            Work::Frame3d(F32, Aff) => "f32, affine",
            Work::Frame3d(Fix, Persp) => "Fx, persp.-correct",
            Work::Frame3d(Fix, Aff) => "Fx, affine",
            Work::PerBand3d(F32, Persp) => "f32 per band, persp.-correct",
            Work::PerBand3d(F32, Aff) => "f32 per band, affine",
            Work::PerBand3d(Fix, Persp) => "Fx per band, persp.-correct",
            Work::PerBand3d(Fix, Aff) => "Fx per band, affine",
            Work::Meshlets(F32, Aff) => "meshlets per band, f32, affine",
            Work::Meshlets(F32, Persp) => "meshlets per band, f32, persp.-correct",
            Work::Meshlets(Fix, Aff) => "meshlets per band, Fx, affine",
            Work::Meshlets(Fix, Persp) => "meshlets per band, Fx, persp.-correct",
            Work::MeshletsFar(Aff) => "meshlets per band, f32, affine, viewer at infinity",
            Work::MeshletsFar(Persp) => "meshlets per band, f32, persp.-correct, viewer at infinity",
            Work::KnotStage(F32, Stage::Vertex) => "f32 affine: band loop + vertex stage only",
            Work::KnotStage(F32, Stage::Coverage) => "f32 affine: + coverage, no planes",
            Work::KnotStage(F32, Stage::NoWrites) => "f32 affine: all but pixel writes",
            Work::KnotStage(Fix, Stage::Vertex) => "Fx affine: band loop + vertex stage only",
            Work::KnotStage(Fix, Stage::Coverage) => "Fx affine: + coverage, no planes",
            Work::KnotStage(Fix, Stage::NoWrites) => "Fx affine: all but pixel writes",
            Work::Dashboard => "2D kit, drawn per band",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotVertexRows(rows) => match rows {
                16 => "f32 vertex stage only, 16-row bands",
                32 => "f32 vertex stage only, 32-row bands",
                48 => "f32 vertex stage only, 48-row bands",
                80 => "f32 vertex stage only, 80-row bands",
                240 => "f32 vertex stage only, one 240-row band",
                _ => "f32 vertex stage only, other bands",
            },
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTall(rows) => match rows {
                48 => "meshlets, f32, affine, 48-row bands",
                240 => "meshlets, f32, affine, one 240-row band",
                _ => "meshlets, f32, affine, other bands",
            },
        }
    }

    /// The buffers it uses (names of the firmware's statics).
    pub fn buffers(&self) -> &'static str {
        match self {
            Work::Clear | Work::Streamed2d(_) | Work::Dashboard => "BAND",
            Work::Frame2d(_) => "BAND,PRIMS",
            Work::Vertex3d(_) | Work::VertexPerBand3d(_) => "BINS",
            Work::Vertex3dCached => "BINS,CACHE",
            Work::Vertex3dChunked => "BINS,CHUNK",
            Work::Frame3dChunked => "BAND,DEPTH,BINS,CHUNK",
            Work::Frame3d(..) | Work::PerBand3d(..) => "BAND,DEPTH,BINS",
            Work::Meshlets(F32, _) | Work::MeshletsFar(_) | Work::KnotStage(F32, _) => "BAND,DEPTH,CLUSTER",
            Work::Meshlets(Fix, _) | Work::KnotStage(Fix, _) => "BAND,DEPTH,CLUSTER_FX",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotVertexRows(_) => "CLUSTER",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTall(rows) => {
                if *rows == 48 {
                    "BAND48,DEPTH48,CLUSTER"
                } else {
                    "BAND240,DEPTH240,CLUSTER"
                }
            }
        }
    }

    /// Whether it only counts the vertex stage's triangles ([`Work::KnotVertexRows`]).
    fn counts_only(&self) -> bool {
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        if let Work::KnotVertexRows(_) = self {
            return true;
        }
        false
    }

    /// Whether it sends pixels (a frame CRC and covered pixels mean something).
    pub fn draws(&self) -> bool {
        !matches!(
            self,
            Work::Vertex3d(_)
                | Work::Vertex3dCached
                | Work::Vertex3dChunked
                | Work::VertexPerBand3d(_)
                | Work::KnotStage(..)
        ) && !self.counts_only()
    }
}

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
}

/// The colour and depth bands of [`Work::KnotTall`].
pub struct Tall<'a, const W: usize> {
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

fn input(e: RenderError<Infallible>) -> Error {
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
        _ => {}
    }
    frame_other(work, height, bg, b, sink)
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
        Work::Dashboard => Err(Error::InvalidParameter),
        Work::Streamed2d(scene) => {
            r.render(workload::streamed::<W>(scene, height), b.band, sink).map_err(input)
        }
        Work::Vertex3d(F32) => vertex3d::<f32, W, N>(height, b.bins),
        Work::Vertex3d(Fix) => vertex3d::<Fx, W, N>(height, b.bins),
        Work::Vertex3dCached => {
            let cache = b.cache.as_deref_mut().ok_or(Error::BufferTooSmall)?;
            black_box(cached_vertex_stage::<CACHE_VERTICES, W, N>(height, cache, b.bins)?);
            Ok(())
        }
        Work::Vertex3dChunked => {
            let cache = b.chunk.as_deref_mut().ok_or(Error::BufferTooSmall)?;
            black_box(cached_vertex_stage::<MAX_MESHLET_VERTICES, W, N>(height, cache, b.bins)?);
            Ok(())
        }
        Work::Frame3dChunked => {
            let cache = b.chunk.as_deref_mut().ok_or(Error::BufferTooSmall)?;
            cached_vertex_stage::<MAX_MESHLET_VERTICES, W, N>(height, cache, b.bins)?;
            r.render(Triangles3d::new(b.bins, b.depth, DEPTH_STATE, Affine), b.band, sink).map_err(input)
        }
        Work::VertexPerBand3d(F32) => vertex3d_per_band::<f32, W, H, N>(height, b.bins, |_, _| ()),
        Work::VertexPerBand3d(Fix) => vertex3d_per_band::<Fx, W, H, N>(height, b.bins, |_, _| ()),
        Work::Frame3d(F32, Persp) => frame3d::<f32, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        Work::Frame3d(F32, Aff) => frame3d::<f32, Affine, W, H, N, P>(r, b, sink),
        Work::Frame3d(Fix, Persp) => frame3d::<Fx, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        Work::Frame3d(Fix, Aff) => frame3d::<Fx, Affine, W, H, N, P>(r, b, sink),
        Work::PerBand3d(F32, Persp) => per_band3d::<f32, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        Work::PerBand3d(F32, Aff) => per_band3d::<f32, Affine, W, H, N, P>(r, b, sink),
        Work::PerBand3d(Fix, Persp) => per_band3d::<Fx, PerspectiveCorrect, W, H, N, P>(r, b, sink),
        Work::PerBand3d(Fix, Aff) => per_band3d::<Fx, Affine, W, H, N, P>(r, b, sink),
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
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::KnotVertexRows(_) | Work::KnotTall(_) => Err(Error::InvalidParameter), // in `frame`
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::Meshlets(..) | Work::MeshletsFar(_) | Work::KnotStage(..) => Err(Error::InvalidParameter),
    }
}

/// [`Work::KnotTall`]. Not inlined: its frames' locals would enlarge
/// [`frame`]'s stack frame, and so every row's stack figure.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[inline(never)]
fn knot_tall<const W: usize>(
    r: Renderer<Rgb565>,
    rows: u16,
    t: &mut Tall<'_, W>,
    cache: &mut ClusterCache<f32, S>,
    sink: &mut Sink,
) -> Result<(), Error> {
    match rows as usize {
        TALL_48 => meshlets::<f32, _, W, TALL_48>(r, t.band48, t.depth48, cache, Affine, Local, sink),
        TALL_240 => meshlets::<f32, _, W, TALL_240>(r, t.band240, t.depth240, cache, Affine, Local, sink),
        _ => Err(Error::InvalidParameter),
    }
}

/// [`Work::KnotVertexRows`]: the knot's `f32` vertex stage for bands of
/// `rows` rows, each band's triangles only counted (not inlined, as
/// [`knot_tall`]).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[inline(never)]
fn knot_vertex_rows<const W: usize>(
    height: u32,
    rows: u16,
    cache: &mut ClusterCache<f32, S>,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, height)?;
    let model = knot_model::<f32>();
    let (mut y0, height) = (0, height as i32);
    while y0 < height {
        let y1 = (y0 + i32::from(rows.max(1))).min(height);
        let mut n = 0u32;
        pipeline.meshlet_triangles(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, (y0, y1 - 1), |t| {
            n += black_box(t).v[0].depth >> 16
        })?;
        black_box(n);
        y0 = y1;
    }
    Ok(())
}

/// [`Work::KnotStage`]: the knot's frame up to `stage`.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
fn knot_stage<T: Scalar, const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    cache: &mut ClusterCache<T, S>,
    stage: Stage,
    sink: &mut Sink,
) -> Result<(), Error> {
    use microraster::depth::{DepthState, DepthTest};
    use microraster::{ClipRect, edge::TriangleSpans};
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, r.height())?;
    let model = knot_model::<T>();
    let never = DepthState::new(DepthTest::Never, false);
    let coverage = matches!(stage, Stage::Coverage);
    let mut result = Ok(());
    match stage {
        Stage::Vertex | Stage::Coverage => r.render(
            from_fn(|view| {
                let (y0, y1) = (view.y0(), view.y1());
                let clip = ClipRect::new(0, y0, W as i32, y1);
                let mut n = 0u32;
                let s = pipeline.meshlet_triangles(
                    &knot_mesh::VALID_KNOT,
                    &model,
                    KNOT_COLOR,
                    cache,
                    (y0, y1 - 1),
                    |t| {
                        n += if coverage {
                            TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None)
                                .map(|s| s.len)
                                .sum::<u32>()
                        } else {
                            black_box(t).v[0].depth >> 16
                        };
                    },
                );
                black_box(n);
                if result.is_ok() {
                    result = s.map(|_| ());
                };
                Ok(())
            }),
            band,
            sink,
        ),
        Stage::NoWrites => r.render(
            Direct3d::new(depth, never, Affine, |band| {
                pipeline.draw_meshlets(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, band).map(|_| ())
            }),
            band,
            sink,
        ),
    }
    .map_err(input)?;
    result
}

/// The knot through the meshlet stage, drawn straight into each band, with
/// the specular term's viewer at `viewer`.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(clippy::too_many_arguments)]
fn meshlets<T: Scalar, M: Interpolation, const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    cache: &mut ClusterCache<T, S>,
    interp: M,
    viewer: Viewer,
    sink: &mut Sink,
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, r.height())?;
    pipeline.lighting = pipeline.lighting.map(|l| l.with_viewer(viewer));
    let model = knot_model::<T>();
    r.render(
        Direct3d::new(depth, DEPTH_STATE, interp, |band| {
            pipeline.draw_meshlets(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, band).map(|_| ())
        }),
        band,
        sink,
    )
    .map_err(input)
}

/// The knot's colour and placement in the standard scene's camera.
pub const KNOT_COLOR: Rgb565 = Rgb565::new(27, 46, 12);

/// The knot's model matrix: turned by the scene's angle about y.
pub fn knot_model<T: Scalar>() -> microraster::math::Mat4<T> {
    microraster::math::transform::rotation_y(T::from_f32(ANGLE))
}

fn vertex3d<T: Scalar, const W: usize, const N: usize>(
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
fn vertex3d_per_band<T: Scalar, const W: usize, const H: usize, const N: usize>(
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
fn cached_vertex_stage<const V: usize, const W: usize, const N: usize>(
    height: u32,
    cache: &mut VertexCache<f32, S, V>,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
) -> Result<MeshStats, Error> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, height)?;
    bins.clear();
    Scene3d.draw_cached::<f32, Rgb565, S, V, N>(&pipeline, ANGLE, cache, bins)
}

fn frame3d<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize, const P: usize>(
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

fn per_band3d<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize, const P: usize>(
    r: Renderer<Rgb565>,
    b: &mut Buffers<'_, W, H, N, P>,
    sink: &mut Sink,
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, r.height())?;
    let geometry = |y0: i32, y1: i32, bins: &mut heapless::Vec<ScreenTriangle<S>, N>| {
        pipeline.rows = Some((y0, y1 - 1));
        Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins).map(|_| ())
    };
    r.render(PerBand3d::new(b.bins, b.depth, DEPTH_STATE, M::default(), geometry), b.band, sink)
        .map_err(input)
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
        Work::Clear | Work::Dashboard => Ok((0, 0)),
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        Work::Meshlets(..)
        | Work::MeshletsFar(_)
        | Work::KnotStage(..)
        | Work::KnotVertexRows(_)
        | Work::KnotTall(_) => Ok((knot_mesh::KNOT.triangles.len() as u32, 0)),
        #[cfg(not(any(not(target_os = "none"), target_abi = "eabihf")))]
        Work::Meshlets(..) | Work::MeshletsFar(_) | Work::KnotStage(..) => Err(Error::InvalidParameter),
        Work::Frame2d(scene) | Work::Streamed2d(scene) => count_2d(scene),
        Work::Vertex3dCached | Work::Vertex3dChunked | Work::Frame3dChunked => count_3d(F32),
        Work::Vertex3d(t) | Work::VertexPerBand3d(t) | Work::Frame3d(t, _) | Work::PerBand3d(t, _) => {
            count_3d(t)
        }
    }
}
