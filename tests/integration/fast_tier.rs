//! The fast accuracy tier (`Precision::Fast`) against the exact one, whole
//! frames (`frames.rs` states the bounds): the standard scene on both
//! numeric paths, affine and perspective-correct, and random scenes of
//! spheres and tori through the cached mesh call; bad input stays the
//! same typed error in both tiers. The knot's frames are compared in
//! `tests/bench_mesh.rs`, its and the standard scene's watertightness in
//! both tiers in `tests/bench_mesh/closed.rs` and `placed.rs`; vertex-level
//! bounds are unit tests (`src/geometry/pipeline/tier/tests.rs`).

pub(crate) mod frames;

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use frames::{Diff, Frame, check, compare};
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::light::Lighting;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{self, ValidMesh, icosphere, torus};
use microraster::pipeline::{Pipeline, VertexCache};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, Precision, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Error, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

const W: usize = 160;
const H: usize = 120;
const BG: Rgb565 = Rgb565::new(2, 4, 6);
type Bins = heapless::Vec<ScreenTriangle<4>, BINS>;
type BigBins = heapless::Vec<ScreenTriangle<4>, 4096>;

/// `bins` drawn in one band of the whole frame.
fn render<M: Interpolation>(bins: &[ScreenTriangle<4>]) -> Frame {
    let mut fb = Framebuffer::new(W as u32, H as u32, Rgb565::BLACK);
    let mut band = Box::new(Band::<Rgb565, W, H>::new(BG));
    let mut depth = Box::new(DepthBand::<Depth16, W, H>::new());
    Renderer::new(H as u32, BG)
        .render(Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, M::default()), &mut band, &mut fb)
        .unwrap();
    Frame::new(fb.pixels, &depth)
}

/// The depth of an empty pixel.
fn clear() -> u32 {
    render::<Affine>(&[]).depth[0]
}

/// The standard scene's bins in tier `tier`.
fn scene<T: Scalar>(angle: f32, tier: Precision) -> Box<Bins> {
    let p = Scene3d::pipeline::<T, 4>(W as u32, H as u32).unwrap().with_precision(tier);
    let mut bins = Box::new(Bins::new());
    Scene3d.draw::<T, Rgb565, 4, BINS>(&p, angle, &mut bins).unwrap();
    bins
}

fn scene_diff<T: Scalar, M: Interpolation>(angle: f32) -> Diff {
    let [e, f] = [Precision::Exact, Precision::Fast].map(|t| render::<M>(&scene::<T>(angle, t)));
    let d = compare(&e, &f, clear());
    check(&d, &format!("scene at {angle}"));
    d
}

#[test]
fn standard_scene_fast_frames_within_bounds() {
    let mut total = Diff::default();
    for angle in [0.0, 0.7, 1.9, 3.3, 5.1] {
        total += scene_diff::<f32, Affine>(angle);
        total += scene_diff::<f32, PerspectiveCorrect>(angle);
        total += scene_diff::<Fx, Affine>(angle);
        total += scene_diff::<Fx, PerspectiveCorrect>(angle);
    }
    println!("standard scene, fast against exact: {total:?}");
    // Not vacuous: the frames are full (the fast tier's colours seldom
    // differ at all: its lit vertices are within 2^-12 before rounding).
    assert!(total.same > 40_000, "{total:?}");
}

/// Random scenes: a sphere and a torus each at a random place, turn,
/// scale and light, through the cached mesh call (f32 and Fx).
#[test]
fn random_scenes_fast_frames_within_bounds() {
    let (nv, nt) = (mesh::icosphere_vertex_count(3), mesh::icosphere_triangle_count(3));
    let (mut p, mut n, mut i) = (vec![[0.0; 3]; nv], vec![[0.0; 3]; nv], vec![[0u16; 3]; nt]);
    let sphere = icosphere(3, &mut p, &mut n, &mut i).unwrap();
    let (nv, nt) = (mesh::torus_vertex_count(32, 16), mesh::torus_triangle_count(32, 16));
    let (mut tp, mut tn, mut ti) = (vec![[0.0; 3]; nv], vec![[0.0; 3]; nv], vec![[0u16; 3]; nt]);
    let tor = torus(32, 16, 1.0, 0.4, &mut tp, &mut tn, &mut ti).unwrap();
    let meshes = [ValidMesh::new(sphere).unwrap(), ValidMesh::new(tor).unwrap()];
    let mut seed = 0x0FA5_7000_5CE7_0001u64;
    let mut r = |lo: f32, hi: f32| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        lo + (hi - lo) * ((seed >> 40) as f32 / (1u64 << 24) as f32)
    };
    let mut total = Diff::default();
    for case in 0..24 {
        let light =
            Lighting::new(r(0.0, 0.3), Vec3::new(r(-1.0, 1.0), r(-1.0, 1.0), r(0.2, 1.0)), r(0.4, 0.8))
                .with_specular(r(0.1, 0.6), [4, 9, 16, 24, 40][case % 5]);
        let models = [0, 1].map(|_| {
            transform::translation(Vec3::new(r(-1.5, 1.5), r(-1.0, 1.0), r(-7.0, -4.0)))
                * transform::rotation_y(r(0.0, 6.3))
                * transform::rotation_x(r(0.0, 6.3))
        });
        let frame = |tier: Precision, fx: bool| {
            let mut bins = Box::new(BigBins::new());
            if fx {
                draw::<Fx>(&meshes, &models, &light, tier, &mut bins);
            } else {
                draw::<f32>(&meshes, &models, &light, tier, &mut bins);
            }
            render::<PerspectiveCorrect>(&bins)
        };
        let fx = case % 3 == 2;
        let d = compare(&frame(Precision::Exact, fx), &frame(Precision::Fast, fx), clear());
        check(&d, &format!("random scene {case}"));
        total += d;
    }
    println!("random scenes, fast against exact: {total:?}");
    assert!(total.same > 20_000, "{total:?}");
}

fn draw<T: Scalar>(
    meshes: &[ValidMesh<'_>; 2],
    models: &[Mat4<f32>; 2],
    light: &Lighting<f32>,
    tier: Precision,
    bins: &mut BigBins,
) {
    let f = T::from_f32;
    let mut p = Pipeline::<T, 4>::perspective(Mat4::IDENTITY, f(0.9), f(1.0), f(20.0), W as u32, H as u32)
        .unwrap()
        .with_precision(tier);
    let d = light.direction;
    let mut l = Lighting::new(f(light.ambient), Vec3::new(f(d.x), f(d.y), f(d.z)), f(light.diffuse));
    l.specular = light.specular.map(|(s, e)| (f(s), e));
    p = p.with_lighting(l);
    let mut cache = Box::new(VertexCache::<T, 4, 64>::new());
    for (mesh, m) in meshes.iter().zip(models) {
        let model = Mat4 { cols: m.cols.map(|c| c.map(f)) };
        p.draw_valid_mesh_cached(mesh, &model, Rgb565::new(20, 40, 12), &mut cache, bins).unwrap();
    }
}

/// Bad input is the same typed error in both tiers.
#[test]
fn bad_input_is_the_same_error_in_both_tiers() {
    let (mut p, mut n, mut i) = ([[0.0; 3]; 42], [[0.0; 3]; 42], [[0u16; 3]; 80]);
    let mesh = ValidMesh::new(icosphere(1, &mut p, &mut n, &mut i).unwrap()).unwrap();
    let errors = |tier: Precision| -> [Result<usize, Error>; 4] {
        let base = Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, 0.9, 1.0, 20.0, 64, 64)
            .unwrap()
            .with_precision(tier);
        let at = transform::translation(Vec3::new(0.0, 0.0, -4.0));
        let run = |p: &Pipeline<f32, 4>, m: &Mat4<f32>| {
            let mut bins = heapless::Vec::<ScreenTriangle<4>, 128>::new();
            p.draw_valid_mesh(&mesh, m, Rgb565::RED, &mut bins).map(|_| bins.len())
        };
        let mut nan = at;
        nan.cols[0][0] = f32::NAN;
        let singular = at * transform::scaling(Vec3::new(0.0, 1.0, 1.0));
        let bad_light = base.with_lighting(Lighting {
            direction: Vec3::new(0.0, 0.0, 0.0),
            ..Lighting::new(0.2, Vec3::new(0.0, 0.0, 1.0), 0.8)
        });
        // Fx: a model far beyond 16.16's range.
        let fx = Pipeline::<Fx, 4>::perspective(
            Mat4::IDENTITY,
            Fx::from_f32(0.9),
            Fx::ONE,
            Fx::from_f32(20.0),
            64,
            64,
        )
        .unwrap()
        .with_precision(tier);
        let far = transform::translation(Vec3::new(Fx::ZERO, Fx::ZERO, Fx::from_f32(-4.0)))
            * transform::scaling(Vec3::new(
                Fx::from_f32(30000.0),
                Fx::from_f32(30000.0),
                Fx::from_f32(30000.0),
            ));
        let mut bins = heapless::Vec::<ScreenTriangle<4>, 128>::new();
        let fx = fx.draw_valid_mesh(&mesh, &far, Rgb565::RED, &mut bins).map(|_| bins.len());
        [run(&base, &nan), run(&base, &singular), run(&bad_light, &at), fx]
    };
    let (exact, fast) = (errors(Precision::Exact), errors(Precision::Fast));
    assert_eq!(exact, fast);
    assert!(exact.iter().all(Result::is_err), "{exact:?}");
    assert_eq!(exact[1], Err(Error::InvalidParameter(microraster::Param::Model)));
    assert_eq!(exact[3], Err(Error::CoordinateOutOfRange));
}
