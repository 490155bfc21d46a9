//! What the firmware benchmark times: one list of configurations per target
//! ([`M4F`], [`M0`]), shared word for word by the firmware (timed under QEMU
//! with instruction counting) and by the host run (which counts triangles
//! and covered pixels and checks that each frame's CRC equals the target's).
//!
//! Adding a configuration is one line in [`M4F`] or [`M0`]: a name (the
//! scene) and a [`Work`] (what runs). 2D scenes are any
//! [`scenes::Scene`] function (`fn(width, height, sink)`); 3D work runs the
//! standard scene ([`Scene3d`](microraster_scenes::scenes3d::Scene3d)) on a vertex path ([`Vertex`]) with a colour
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

use embedded_graphics_core::pixelcolor::Rgb565;

// The shape kit does not fit the micro:bit's flash beside the rest: Cortex-M4F only.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(dead_code)] // the bench uses the microraster version only
#[path = "../common/dashboard.rs"]
pub mod dashboard;
// The drive of `examples/link.rs` (`dashboard-drive`), which names the
// dashboard's module `scene`.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use self::dashboard as scene;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[path = "../common/knot_mesh.rs"]
pub mod knot_mesh;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[path = "../common/dashboard_live.rs"]
pub mod live;
use microraster::raster3d::Precision;
// The knot as `obj2rs`'s default command converts it, at 20k and 5k
// triangles ([`Work::Ways`]); not every static is read.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(dead_code)]
#[path = "../common/knot20k_obj2rs.rs"]
pub mod knot20k;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(dead_code)]
#[path = "../common/knot5k_obj2rs.rs"]
pub mod knot5k;
use microraster_scenes::scenes;

/// The knot's cameras ([`Work::KnotTier`]).
#[path = "../common/knot_eye.rs"]
pub mod knot_eye;
pub use knot_eye::Eye;

pub use crate::sink::{Mode, Sink};
use crate::workload::S;
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
    /// 16.16 fixed point ([`Fx`](microraster::math::Fx)).
    Fx,
}

/// Colour interpolation of the 3D scene.
#[derive(Clone, Copy, Debug)]
pub enum Interp {
    /// Screen-space linear ([`Affine`](microraster::raster3d::Affine)).
    Affine,
    /// Perspective-correct ([`PerspectiveCorrect`](microraster::raster3d::PerspectiveCorrect)).
    Perspective,
}

/// What one configuration runs for one frame.
#[derive(Clone, Copy)]
pub enum Work {
    /// The band loop alone: each band cleared and handed to the display.
    /// Every other row includes this cost.
    Clear,
    /// A 2D scene collected once into the primitive buffer, then
    /// [`Renderer::render`](microraster::Renderer::render). Scene generation is outside the timed frame.
    Frame2d(Scene2d),
    /// A 2D scene generated again for every band and drawn straight into it
    /// (no primitive storage; generation is inside the timed frame).
    Streamed2d(Scene2d),
    /// The standard 3D scene's vertex stage alone, once per frame, into the
    /// frame's bins (nothing rasterized).
    Vertex3d(Vertex),
    /// [`Work::Vertex3d`] with a vertex cache ([`Scene3d::draw_cached`](microraster_scenes::scenes3d::Scene3d::draw_cached):
    /// each vertex transformed, snapped and lit once; `f32` only, Cortex-M4F).
    Vertex3dCached,
    /// [`Work::Vertex3dCached`] with a cache of 64 vertices, one meshlet
    /// cluster's ([`ClusterCache`](microraster::pipeline::ClusterCache)): the meshes in chunks of their
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
    /// The vertex stage once per band into one band's bins, drawn by a
    /// `Direct3d` pass.
    PerBand3d(Vertex, Interp),
    /// The 20k-triangle knot ([`knot_mesh::KNOT`]) through the meshlet stage:
    /// `Direct3d` with [`Pipeline::draw_meshlets`](microraster::pipeline::Pipeline::draw_meshlets) per
    /// band, no bins. Its triangle count is the mesh's (instructions per
    /// mesh triangle).
    Meshlets(Vertex, Interp),
    /// [`Work::Meshlets`] in `f32` with the specular term's viewer at
    /// infinity ([`Viewer::Infinite`](microraster::light::Viewer::Infinite): one half vector per mesh, as
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
    /// rows ([`Pipeline::meshlet_triangles`](microraster::pipeline::Pipeline::meshlet_triangles) per band, triangles only
    /// counted, no band buffer or band loop). 240 rows: one band, the
    /// vertex work of a framebuffer renderer on the same meshlets.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    KnotVertexRows(u16),
    /// The whole `f32` affine frame of [`Work::Meshlets`] with bands of
    /// [`TALL_20`], [`TALL_48`] or [`TALL_240`] rows (`knot20k-rows`): the
    /// speed a user buys with the RAM of taller bands (20: within issue
    /// 12's 32 KB; 240: a whole colour and depth frame, as a framebuffer
    /// renderer holds).
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    KnotTall(u16),
    /// The standard scene through the one-call front
    /// ([`View3d::draw`](microraster::view3d::View3d::draw): `f32`,
    /// perspective-correct, the vertex stage per band straight into each
    /// band, no bins), with the scene's camera, light and shading: the
    /// frame of `Frame3d(F32, Perspective)` (tested equal,
    /// `tests/integration/view3d.rs`). Cortex-M4F only.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    Front3d,
    /// Issue 61: the knot as [`Work::Meshlets`] (local viewer) in an
    /// accuracy tier ([`Precision`]) and seen from an [`Eye`] (Cortex-M4F only).
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    KnotTier(Precision, Eye, Vertex, Interp),
    /// Issue 61's Pareto table: the `f32` affine knot of
    /// [`Work::KnotTier`] (standard eye) in bands of [`TALL_20`],
    /// [`TALL_32`] or [`TALL_48`] rows, in an accuracy tier (Cortex-M4F only).
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    KnotTallTier(Precision, u16),
    /// [`Work::Frame3d`] with the vertex stage's pipeline in an accuracy
    /// tier ([`Precision`]).
    Frame3dTier(Precision, Vertex, Interp),
    /// One of the three documented ways to draw a mesh on a knot converted
    /// by `obj2rs`'s default command ([`ways`]: `f32`, perspective-correct,
    /// exact tier; select them by their scene, `ways`). Cortex-M4F only.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    Ways(ways::Knot, ways::Way),
    /// The 2D kit's dashboard ([`dashboard::dashboard`]: shapes with
    /// gradients, anti-aliasing and translucency, an alpha sprite, text),
    /// built and drawn in every band by `render::from_fn`.
    Dashboard,
    /// The dashboard's drive of `examples/link.rs` with damage regions:
    /// 59 frames, each rendering and sending only what changed
    /// ([`drive`]); counted per frame ([`Work::frames`]).
    DashboardDrive,
}

/// How far [`Work::KnotStage`] goes into each band's triangles.
#[derive(Clone, Copy, Debug)]
pub enum Stage {
    /// The band loop and the meshlet vertex stage
    /// ([`Pipeline::meshlet_triangles`](microraster::pipeline::Pipeline::meshlet_triangles)); triangles are only counted.
    Vertex,
    /// [`Stage::Vertex`] and each triangle's coverage in the band
    /// ([`TriangleSpans`](microraster::edge::TriangleSpans)), covered pixels counted.
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
use Precision::{Exact, Fast};
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
    // Last, so the rows above keep their indices.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTall(TALL_20 as u16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("scene3d", Work::Front3d),
    // Issue 61, appended so the rows above keep their indices: the fast
    // tier beside the exact rows above, the camera twice as close in both
    // tiers, and the Pareto table's bands (16 rows: the knot20k rows).
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k", Work::KnotTier(Fast, Eye::Standard, F32, Aff)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k", Work::KnotTier(Fast, Eye::Standard, F32, Persp)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k", Work::KnotTier(Fast, Eye::Standard, Fix, Aff)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-close", Work::KnotTier(Exact, Eye::Close, F32, Aff)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-close", Work::KnotTier(Exact, Eye::Close, F32, Persp)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-close", Work::KnotTier(Fast, Eye::Close, F32, Aff)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-close", Work::KnotTier(Fast, Eye::Close, F32, Persp)),
    bench("scene3d", Work::Frame3dTier(Fast, F32, Persp)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTallTier(Exact, TALL_32 as u16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTallTier(Fast, TALL_20 as u16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTallTier(Fast, TALL_32 as u16)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("knot20k-rows", Work::KnotTallTier(Fast, TALL_48 as u16)),
    // Issue 61's three ways to draw a mesh (the README's table; the 20k
    // front and meshlet rows by default, for the report's front verdict,
    // the rest on request: `table m4f ways`).
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("ways", Work::Ways(ways::Knot::K20, ways::Way::Front)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("ways", Work::Ways(ways::Knot::K20, ways::Way::Meshlets)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("ways", Work::Ways(ways::Knot::K20, ways::Way::Bins)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("ways", Work::Ways(ways::Knot::K5, ways::Way::Front)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("ways", Work::Ways(ways::Knot::K5, ways::Way::Meshlets)),
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    probe("ways", Work::Ways(ways::Knot::K5, ways::Way::Bins)),
    // Issue 62, appended so the rows above keep their indices: the drive
    // of examples/link.rs with damage regions, per frame.
    #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
    bench("dashboard-drive", Work::DashboardDrive),
];

/// Rows of a band of [`Work::KnotTall`] whose colour and `Depth16` rows
/// (320 × 20 × 4 B) and cluster cache fit the 32 KB that issue 12 allows
/// the knot's frame (the table's RAM column; 21 rows would fit too, in
/// the same 12 bands). Cortex-M4F only.
pub const TALL_20: usize = 20;
/// Rows of the bands of [`Work::KnotTallTier`]'s middle step (Cortex-M4F only).
pub const TALL_32: usize = 32;
/// Rows of the taller bands of [`Work::KnotTall`] (Cortex-M4F only).
pub const TALL_48: usize = 48;
/// A band as tall as the frame ([`Work::KnotTall`]).
pub const TALL_240: usize = 240;

/// Cortex-M0 (160 × 128, 4-row bands, one band's bins): one line per configuration.
pub const M0: &[Bench] = &[
    bench("band loop", Work::Clear),
    bench("mixed", Work::Streamed2d(scenes::mixed)),
    bench("scene3d", Work::PerBand3d(Fix, Aff)),
    bench("scene3d", Work::VertexPerBand3d(Fix)),
];

/// Primitives the Cortex-M4F configuration can hold ([`Work::Frame2d`]).
pub const PRIMS: usize = scenes::MIXED_LEN;

// The `dashboard-drive` row (Cortex-M4F and host).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
pub mod drive;
mod frame;
// What each configuration is called and which buffers it uses.
mod work;
// Its functions are Cortex-M4F (and host) only: on the Cortex-M0 its imports go unused.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), allow(unused_imports))]
mod knot;
mod scene3d;
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), allow(unused_imports, dead_code))]
pub mod tiers;
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
pub mod ways;

#[allow(unused_imports)] // the firmware uses some, the host's table all
pub use frame::{Buffers, Cache, Tall, View, frame, prepare};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(unused_imports)]
pub use frame::{Knot5kBins, KnotBins};
#[allow(unused_imports)]
pub use scene3d::primitives;
