//! The knot's frames in the fast accuracy tier against the exact tier
//! (`tests/integration/fast_tier/frames.rs` states the bounds), `f32` and
//! `Fx`, affine and perspective-correct, at the benchmark's camera and at
//! half its distance; and the fast tier's frame is the same in bands of 16
//! rows as in one band.

use super::frames::{Diff, Frame, check, compare};
use super::knot_mesh::{VALID_KNOT, VALID_KNOT_FX};
use crate::framebuffer::Framebuffer;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::{Scalar, Vec3, transform};
use microraster::mesh::ValidMeshletMesh;
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, Precision};
use microraster::render::Direct3d;
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::Scene3d;

const W: usize = 320;
const H: usize = 240;
const BG: Rgb565 = Rgb565::BLACK;
const KNOT_COLOR: Rgb565 = Rgb565::new(27, 46, 12);

/// The knot at `angle` from `eye`, in bands of `B` rows: its colours and
/// (with `B = H`, one band) its depth.
fn knot<T: Scalar, P: Scalar, M: Interpolation, const B: usize>(
    mesh: &ValidMeshletMesh<'_, P>,
    eye: [f32; 3],
    angle: f32,
    tier: Precision,
) -> (Vec<Rgb565>, Box<DepthBand<Depth16, W, B>>) {
    let f = T::from_f32;
    let v = |p: [f32; 3]| Vec3::new(f(p[0]), f(p[1]), f(p[2]));
    // The benchmark's lens and light (`Scene3d`), from `eye`.
    let view = transform::look_at(v(eye), v([0.0; 3]), v([0.0, 1.0, 0.0])).unwrap();
    let pipeline = Pipeline::perspective(view, f(0.9), f(1.0), f(20.0), W as u32, H as u32)
        .unwrap()
        .with_lighting(Scene3d::lighting::<T>())
        .with_precision(tier);
    let model = transform::rotation_y(f(angle));
    let mut cache = Box::new(ClusterCache::<T, 4>::new());
    let mut band = Box::new(Band::<Rgb565, W, B>::new(BG));
    let mut depth = Box::new(DepthBand::<Depth16, W, B>::new());
    let mut out = Framebuffer::new(W as u32, H as u32, BG);
    Renderer::new(H as u32, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, M::default(), |band| {
                pipeline.draw_meshlets(mesh, &model, KNOT_COLOR, &mut cache, band).map(|_| ())
            }),
            &mut band,
            &mut out,
        )
        .unwrap();
    (out.pixels, depth)
}

fn diff<T: Scalar, P: Scalar, M: Interpolation>(
    mesh: &ValidMeshletMesh<'_, P>,
    eye: [f32; 3],
    angle: f32,
) -> Diff {
    let frame = |tier| {
        let (c, d) = knot::<T, P, M, H>(mesh, eye, angle, tier);
        Frame::new(c, &d)
    };
    let clear = DepthBand::<Depth16, 1, 1>::new().get(0, 0).unwrap();
    let d = compare(&frame(Precision::Exact), &frame(Precision::Fast), clear);
    check(&d, &format!("knot eye {eye:?} angle {angle}"));
    d
}

#[test]
fn the_knot_fast_frames_within_bounds() {
    let mut total = Diff::default();
    for (eye, angle) in [([0.0, 1.9, 5.6], 0.6), ([0.0, 0.95, 2.8], 0.6), ([0.0, 1.9, 5.6], 2.2)] {
        total += diff::<f32, f32, Affine>(&VALID_KNOT, eye, angle);
        total += diff::<f32, f32, PerspectiveCorrect>(&VALID_KNOT, eye, angle);
        total += diff::<microraster::math::Fx, microraster::math::Fx, Affine>(&VALID_KNOT_FX, eye, angle);
    }
    println!("knot, fast against exact: {total:?}");
    assert!(total.same > 100_000, "{total:?}");
}

#[test]
fn the_knot_fast_frame_is_the_same_in_any_band_height() {
    let eye = [0.0, 1.9, 5.6];
    let one = knot::<f32, f32, PerspectiveCorrect, H>(&VALID_KNOT, eye, 0.6, Precision::Fast).0;
    assert_eq!(knot::<f32, f32, PerspectiveCorrect, 16>(&VALID_KNOT, eye, 0.6, Precision::Fast).0, one);
    assert_eq!(knot::<f32, f32, PerspectiveCorrect, 7>(&VALID_KNOT, eye, 0.6, Precision::Fast).0, one);
    assert!(one.iter().filter(|&&c| c != BG).count() > 10_000);
}
