//! The three documented ways to draw a mesh (the README's table) on the
//! 5k knot as `obj2rs`'s default command converts it
//! (`examples/common/knot5k_obj2rs.rs`): the front (`View3d` with
//! `Object::new(&NAME, ..)`), meshlets per band (`Direct3d` +
//! `draw_meshlets`) and full-frame bins (`draw_valid_mesh` of `NAME_MESH` +
//! `Triangles3d`) draw the same frame, for several band heights; the
//! front's accuracy tier is the explicit API's `Pipeline::precision`.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::mesh::ValidMesh;
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::{PerspectiveCorrect, Precision};
use microraster::render::{Direct3d, Triangles3d};
use microraster::view3d::{Camera, Geometry, Object, View3d};
use microraster::{Band, Renderer};

#[allow(dead_code)] // the statics a user would not all read
#[path = "../../examples/common/knot5k_obj2rs.rs"]
mod knot5k;

const W: usize = 160;
const H: u32 = 120;
const BG: Rgb565 = Rgb565::BLACK;
const COLOR: Rgb565 = Rgb565::new(27, 46, 12);
const ANGLE: f32 = 0.6;

fn camera() -> Camera {
    Camera::look_at([0.0, 1.9, 5.6], [0.0; 3])
}

/// The front, in `BH`-row bands, in tier `precision`; and its pipeline.
fn front<const BH: usize>(precision: Precision) -> (Vec<Rgb565>, Pipeline<f32, 4>) {
    let mut view = Box::new(View3d::<Rgb565, W, BH>::new(BG));
    view.set_precision(precision);
    let object = Object::new(&knot5k::KNOT5K, COLOR).rotate_y(ANGLE);
    assert!(matches!(object.geometry(), Geometry::Meshlets(_)), "obj2rs's `NAME` is the clusters");
    let mut fb = Framebuffer::new(W as u32, H, BG);
    view.draw(&camera(), &[object], &mut fb).unwrap();
    (fb.pixels, view.pipeline(&camera(), H).unwrap().0)
}

/// The explicit API's meshlet frame with the front's pipeline, 16-row bands.
fn meshlets(pipeline: &Pipeline<f32, 4>) -> Vec<Rgb565> {
    let model = Object::new(&knot5k::KNOT5K, COLOR).rotate_y(ANGLE).model();
    let mut cache = Box::new(ClusterCache::<f32, 4>::new());
    let (mut band, mut depth) = (Band::<Rgb565, W, 16>::new(BG), DepthBand::<Depth16, W, 16>::new());
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |b| {
        pipeline.draw_meshlets(&knot5k::KNOT5K, &model, COLOR, &mut cache, b).map(|_| ())
    });
    Renderer::new(H, BG).render(frame, &mut band, &mut fb).unwrap();
    fb.pixels
}

/// The explicit API's binned frame: `NAME_MESH` into the frame's bins.
fn bins(pipeline: &Pipeline<f32, 4>) -> Vec<Rgb565> {
    let model = Object::new(&knot5k::KNOT5K, COLOR).rotate_y(ANGLE).model();
    let mesh = ValidMesh::new(knot5k::KNOT5K_MESH).unwrap();
    let mut bins = Box::new(heapless::Vec::<_, 4096>::new());
    let stats = pipeline.draw_valid_mesh(&mesh, &model, COLOR, &mut bins).unwrap();
    assert!(stats.emitted > 1000, "{stats:?}");
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(BG), DepthBand::<Depth16, W, 8>::new());
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let frame = Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect);
    Renderer::new(H, BG).render(frame, &mut band, &mut fb).unwrap();
    fb.pixels
}

#[test]
fn three_ways_draw_the_same_frame() {
    let (img, pipeline) = front::<16>(Precision::Exact);
    assert_eq!(pipeline.precision, Precision::Exact, "exact by default");
    let covered = img.iter().filter(|&&c| c != BG).count();
    assert!(covered > 2000, "the knot is drawn: {covered} pixels");
    assert_eq!(img, meshlets(&pipeline), "front and meshlets per band");
    assert_eq!(img, bins(&pipeline), "front and full-frame bins");
    assert_eq!(img, front::<1>(Precision::Exact).0, "1-row bands");
    assert_eq!(img, front::<7>(Precision::Exact).0, "7-row bands");
}

/// `View3d::set_precision` is the explicit API's `Pipeline::precision`: the
/// front draws what `draw_meshlets` draws with that pipeline, in either tier.
#[test]
fn the_front_draws_in_the_chosen_tier() {
    let (img, pipeline) = front::<16>(Precision::Fast);
    assert_eq!(pipeline.precision, Precision::Fast);
    assert_eq!(img, meshlets(&pipeline));
    assert_eq!(img, meshlets(&pipeline.with_precision(Precision::Fast)));
    assert_eq!(img, front::<5>(Precision::Fast).0, "the image does not depend on the band height");
    let view = View3d::<Rgb565, W, 16>::new(BG).with_precision(Precision::Fast);
    assert_eq!(view.precision(), Precision::Fast);
    assert_eq!(View3d::<Rgb565, W, 16>::new(BG).precision(), Precision::Exact);
}
