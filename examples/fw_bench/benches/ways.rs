//! The three documented ways to draw a mesh (issue 61; the README's table),
//! each on the knot as `obj2rs`'s default command converts it, at 20,480
//! and 5,120 triangles: the front ([`View3d`] with `Object::new(&NAME, ..)`),
//! meshlets per band ([`Direct3d`] + [`Pipeline::draw_meshlets`]) and
//! full-frame bins ([`Pipeline::draw_valid_mesh`] of `NAME_MESH` +
//! [`Triangles3d`]). All `f32`, perspective-correct (the front's only
//! interpolation, so like is compared with like), exact tier, with the
//! knot rows' camera, light, colour and turn (Cortex-M4F only).
//!
//! [`Pipeline::draw_meshlets`]: microraster::pipeline::Pipeline::draw_meshlets
//! [`Pipeline::draw_valid_mesh`]: microraster::pipeline::Pipeline::draw_valid_mesh

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand};
use microraster::mesh::{Mesh, ValidMesh, ValidMeshletMesh};
use microraster::pipeline::ClusterCache;
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
use microraster::render::{Direct3d, Triangles3d};
use microraster::view3d::{Object, View3d};
use microraster::{Band, Error, Renderer};
use microraster_scenes::scenes3d::Scene3d;

use super::frame::input;
use super::knot::{KNOT_COLOR, knot_model};
use super::{Sink, knot5k, knot20k};
use crate::workload::{ANGLE, DEPTH_STATE, S};

/// Which converted knot: `cargo run --example gen_bench_mesh -- --obj 320 32`
/// (or `160 16`) piped through `obj2rs` with no options.
#[derive(Clone, Copy, Debug)]
pub enum Knot {
    /// 5,120 triangles (160 × 16 samples).
    K5,
    /// 20,480 triangles (320 × 32 samples, the knot of the `knot20k` rows).
    K20,
}

/// How the frame is drawn.
#[derive(Clone, Copy, Debug)]
pub enum Way {
    /// `View3d::draw` of `Object::new(&NAME, colour)`.
    Front,
    /// `Direct3d` + `Pipeline::draw_meshlets(&NAME, ..)` per band.
    Meshlets,
    /// `Pipeline::draw_valid_mesh` of `NAME_MESH` into the frame's bins,
    /// then `Triangles3d`.
    Bins,
}

/// Bins for the 20k knot's frame: exactly the triangles its vertex stage
/// emits with this camera (a smaller buffer fails the row with
/// `CapacityExceeded`, which names the need).
pub const KNOT_BINS: usize = 9_841;
/// Bins for the 5k knot's frame, likewise.
pub const KNOT5K_BINS: usize = 2_478;

/// `NAME_MESH` of the 20k knot, checked once (at compile time).
static VALID20: ValidMesh<'static> = valid(knot20k::KNOT20K_MESH);
/// `NAME_MESH` of the 5k knot, checked once.
static VALID5: ValidMesh<'static> = valid(knot5k::KNOT5K_MESH);

#[allow(long_running_const_eval)]
const fn valid(mesh: Mesh<'static>) -> ValidMesh<'static> {
    match ValidMesh::new(mesh) {
        Ok(m) => m,
        Err(_) => panic!("invalid knot mesh"),
    }
}

impl Knot {
    /// `NAME`: the clusters.
    pub fn clusters(self) -> &'static ValidMeshletMesh<'static> {
        match self {
            Knot::K5 => &knot5k::KNOT5K,
            Knot::K20 => &knot20k::KNOT20K,
        }
    }

    /// `NAME_MESH`, validated.
    fn mesh(self) -> &'static ValidMesh<'static> {
        match self {
            Knot::K5 => &VALID5,
            Knot::K20 => &VALID20,
        }
    }

    /// Its triangles (the table's per-triangle figures).
    pub fn triangles(self) -> u32 {
        self.clusters().get().triangles.len() as u32
    }
}

/// [`Way::Front`]: the view set up as the knot rows' pipeline
/// ([`Scene3d::pipeline`]: light, culling, shading), frames of `height` rows.
pub(super) fn front<const W: usize, const H: usize>(
    view: &mut View3d<Rgb565, W, H>,
    knot: Knot,
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
    let object = Object::new(knot.clusters(), KNOT_COLOR).rotate_y(ANGLE);
    view.draw(&Scene3d::camera(), &[object], sink).map_err(input)
}

/// [`Way::Meshlets`]: the knot rows' `Direct3d` frame.
pub(super) fn meshlets<const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    cache: &mut ClusterCache<f32, S>,
    knot: Knot,
    sink: &mut Sink,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, r.height())?;
    let model = knot_model::<f32>();
    let frame = Direct3d::new(depth, DEPTH_STATE, PerspectiveCorrect, |band| {
        pipeline.draw_meshlets(knot.clusters(), &model, KNOT_COLOR, cache, band).map(|_| ())
    });
    r.render(frame, band, sink).map_err(input)
}

/// [`Way::Bins`]: the vertex stage once per frame into `bins`, then the
/// bands.
pub(super) fn bins<const W: usize, const H: usize, const N: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    knot: Knot,
    sink: &mut Sink,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, r.height())?;
    bins.clear();
    pipeline.draw_valid_mesh(knot.mesh(), &knot_model::<f32>(), KNOT_COLOR, bins)?;
    r.render(Triangles3d::new(bins, depth, DEPTH_STATE, PerspectiveCorrect), band, sink).map_err(input)
}
