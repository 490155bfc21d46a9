//! The one-call 3D front (`microraster::view3d`): the same pixels as the
//! explicit API (vertex stage into bins, then `Triangles3d`), for
//! every band height; its defaults (back faces culled, lighting on, winding
//! checked); its errors.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Vec3, transform};
use microraster::mesh::{self, Mesh, Meshlet, ValidMeshletMesh};
use microraster::pipeline::Pipeline;
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::Triangles3d;
use microraster::view3d::{CUBE, Camera, DEFAULT_LIGHTING, Object, View3d};
use microraster::{Band, Error, Param, Region, RenderError, Renderer};

const W: usize = 96;
const H: u32 = 72;
const BG: Rgb565 = Rgb565::BLACK;

/// An icosphere of 2 subdivisions in leaked buffers (162 vertices, 320
/// triangles); also the mesh of `view3d_colors`.
pub(crate) fn sphere() -> Mesh<'static> {
    let (nv, nt) = (mesh::icosphere_vertex_count(2), mesh::icosphere_triangle_count(2));
    let p = Vec::leak(vec![[0.0; 3]; nv]);
    let n = Vec::leak(vec![[0.0; 3]; nv]);
    let i = Vec::leak(vec![[0u16; 3]; nt]);
    mesh::icosphere(2, p, n, i).unwrap()
}

/// The same sphere in clusters.
pub(crate) fn sphere_meshlets() -> &'static ValidMeshletMesh<'static> {
    clusters(sphere())
}

/// `m` in clusters (leaked buffers).
pub(crate) fn clusters(m: Mesh<'static>) -> &'static ValidMeshletMesh<'static> {
    let (nv, nt) = (m.vertex_count(), m.triangle_count());
    let meshlets = Vec::leak(vec![Meshlet::default(); mesh::meshlet_bound(nt)]);
    let vertices = Vec::leak(vec![0u16; mesh::meshlet_vertex_bound(nt)]);
    let triangles = Vec::leak(vec![[0u8; 3]; nt]);
    let scratch = Vec::leak(vec![0u32; mesh::meshlet_scratch_len(nv, nt)]);
    let built = mesh::build_meshlets(m, meshlets, vertices, triangles, scratch).unwrap();
    Box::leak(Box::new(ValidMeshletMesh::new(built).unwrap()))
}

/// The error of a `frame` (width, height) at the origin on a `target` of that size.
fn outside(frame: (u32, u32), target: (u32, u32)) -> Error {
    Error::FrameOutsideTarget {
        frame: Region::new(0, 0, frame.0, frame.1),
        target: Region::new(0, 0, target.0, target.1),
    }
}

fn camera() -> Camera {
    Camera::look_at([2.0, 2.5, 6.0], [0.0, 0.2, 0.0])
}

/// The scene through the front, in `BH`-row bands.
fn front<const BH: usize>(camera: &Camera, objects: &[Object<'_, Rgb565>]) -> Vec<Rgb565> {
    let mut view = Box::new(View3d::<Rgb565, W, BH>::new(BG));
    let mut fb = Framebuffer::new(W as u32, H, BG);
    view.draw(camera, objects, &mut fb).unwrap();
    fb.pixels
}

/// The same scene through the explicit API, written out step by step:
/// `look_at` + `Pipeline::perspective` with the lighting, every mesh into
/// one frame's bins, then `Triangles3d` with 16-bit depth.
fn explicit(
    eye: [f32; 3],
    target: [f32; 3],
    meshes: &[(Mesh<'_>, transform_steps::Model, Rgb565)],
) -> Vec<Rgb565> {
    let v = |a: [f32; 3]| Vec3::new(a[0], a[1], a[2]);
    let view = transform::look_at(v(eye), v(target), v([0.0, 1.0, 0.0])).unwrap();
    let fov = 50f32.to_radians();
    let pipeline = Pipeline::<f32, 4>::perspective(view, fov, 0.25, 64.0, W as u32, H)
        .unwrap()
        .with_lighting(DEFAULT_LIGHTING);
    let mut bins = heapless::Vec::<_, 1024>::new();
    for (m, model, color) in meshes {
        pipeline.draw_mesh(m, &model.matrix(), *color, &mut bins).unwrap();
    }
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(BG), DepthBand::<Depth16, W, 8>::new());
    Renderer::new(H, BG)
        .render(
            Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.pixels
}

/// Model matrices composed by hand: translation · (rotation · scale), the
/// order `Object`'s steps multiply in (float products are not associative).
mod transform_steps {
    use microraster::math::{Mat4, Vec3, transform};
    pub struct Model {
        pub scale: f32,
        pub yaw: f32,
        pub at: [f32; 3],
    }
    impl Model {
        pub fn matrix(&self) -> Mat4<f32> {
            let t = transform::translation(Vec3::new(self.at[0], self.at[1], self.at[2]));
            t * (transform::rotation_y(self.yaw)
                * transform::scaling(Vec3::new(self.scale, self.scale, self.scale)))
        }
    }
}
use transform_steps::Model;

/// Distinct colours covering more than `min` pixels, background excluded.
fn colours(img: &[Rgb565], min: usize) -> usize {
    let mut counts = std::collections::HashMap::new();
    for &c in img.iter().filter(|&&c| c != BG) {
        *counts.entry(c).or_insert(0usize) += 1;
    }
    counts.values().filter(|&&n| n > min).count()
}

#[test]
fn front_draws_what_the_explicit_api_draws() {
    let ball = sphere();
    for (i, yaw) in [0.0f32, 0.7, 2.1, 4.0].into_iter().enumerate() {
        let objects = [
            Object::new(&CUBE, Rgb565::CYAN).scale(0.8).rotate_y(yaw).translate([-1.0, 0.0, 0.0]),
            Object::new(&ball, Rgb565::new(31, 40, 4)).rotate_y(-yaw).translate([1.2, 0.3, -0.5]),
        ];
        let img = front::<16>(&camera(), &objects);
        let reference = explicit(
            camera().eye(),
            camera().target(),
            &[
                (*CUBE.mesh(), Model { scale: 0.8, yaw, at: [-1.0, 0.0, 0.0] }, Rgb565::CYAN),
                (ball, Model { scale: 1.0, yaw: -yaw, at: [1.2, 0.3, -0.5] }, Rgb565::new(31, 40, 4)),
            ],
        );
        let differ = img.iter().zip(&reference).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "view {i}: {differ} pixels differ");
        // Not vacuous: both meshes drawn, in many shades.
        let covered = img.iter().filter(|&&c| c != BG).count();
        assert!(covered > 800, "view {i}: {covered} pixels drawn");
        assert!(colours(&img, 0) > 20, "view {i}");
    }
}

/// The standard scene (`Scene3d`, the benchmarks' scene) through the front
/// at full size (320 × 240, 16-row bands: its vertex stage per band through
/// the stack cache) draws the binned path's frame exactly
/// (`Scene3d::draw` into one frame's bins, then `Triangles3d`), over a turn
/// of its animation; the `fw_bench` row of the front times this frame.
#[test]
fn front_draws_the_standard_scene_as_the_binned_path() {
    use microraster_scenes::scenes3d::{BINS, Scene3d};
    const SW: usize = 320;
    const SH: u32 = 240;
    let mut view = Box::new(View3d::<Rgb565, SW, 16>::new(BG));
    let p = Scene3d::pipeline::<f32, 4>(SW as u32, SH).unwrap();
    view.set_lighting(p.lighting);
    view.set_cull(p.cull);
    view.set_shade(p.shade);
    let mut bins = Box::new(heapless::Vec::<_, BINS>::new());
    let (mut band, mut depth) =
        (Box::new(Band::<Rgb565, SW, 16>::new(BG)), Box::new(DepthBand::<Depth16, SW, 16>::new()));
    for angle in [0.0f32, 0.6, 1.7, 2.9, 4.4, 5.8] {
        let mut front = Framebuffer::new(SW as u32, SH, BG);
        view.draw(&Scene3d::camera(), &Scene3d::objects(angle), &mut front).unwrap();
        bins.clear();
        Scene3d.draw::<f32, Rgb565, 4, BINS>(&p, angle, &mut bins).unwrap();
        let mut binned = Framebuffer::new(SW as u32, SH, BG);
        let frame = Triangles3d::new(&bins, &mut *depth, DepthState::LESS_WRITE, PerspectiveCorrect);
        Renderer::new(SH, BG).render(frame, &mut *band, &mut binned).unwrap();
        let differ = front.pixels.iter().zip(&binned.pixels).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "angle {angle}: {differ} pixels differ");
        let covered = front.pixels.iter().filter(|&&c| c != BG).count();
        assert!(covered > 15_000 && colours(&front.pixels, 0) > 100, "angle {angle}: {covered} pixels drawn");
    }
}

#[test]
fn image_does_not_depend_on_the_band_height() {
    let ball = sphere();
    let clusters = sphere_meshlets();
    let objects = [
        Object::new(&CUBE, Rgb565::YELLOW).rotate_x(0.4).rotate_y(0.9),
        Object::new(&ball, Rgb565::GREEN).scale(0.7).translate([1.6, 0.0, 0.4]),
        Object::new(clusters, Rgb565::MAGENTA).scale(0.6).translate([-1.7, 0.5, 0.0]),
    ];
    for cam in [camera(), camera().orthographic(5.0, 0.5, 30.0), Camera::orbit([0.0; 3], 5.0, 2.5, -0.4)] {
        let full = front::<{ H as usize }>(&cam, &objects);
        assert_eq!(front::<1>(&cam, &objects), full, "{cam:?}");
        assert_eq!(front::<16>(&cam, &objects), full, "{cam:?}");
        assert!(colours(&full, 0) > 20);
    }
}

/// A meshlet object draws what the plain mesh draws through the bins (a
/// convex mesh: no cluster order effects).
#[test]
fn meshlet_objects_match_the_binned_mesh() {
    let clusters = sphere_meshlets();
    let m = Model { scale: 1.5, yaw: 0.3, at: [0.0, 0.0, 0.0] };
    let img = front::<16>(&camera(), &[Object::new(clusters, Rgb565::RED).scale(1.5).rotate_y(0.3)]);
    assert_eq!(img, explicit(camera().eye(), camera().target(), &[(sphere(), m, Rgb565::RED)]));
}

/// Back faces are culled by default: from inside the cube only back faces
/// face the camera, so nothing is drawn; with culling off, every pixel is.
#[test]
fn back_faces_are_culled_by_default() {
    let inside = Camera::look_at([0.0, 0.0, 0.2], [0.0, 0.0, -1.0]);
    let cube = [Object::new(&CUBE, Rgb565::WHITE)];
    assert!(front::<16>(&inside, &cube).iter().all(|&c| c == BG));
    let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
    view.set_cull(Cull::None);
    let mut fb = Framebuffer::new(W as u32, H, BG);
    view.draw(&inside, &cube, &mut fb).unwrap();
    assert!(fb.pixels.iter().all(|&c| c != BG));
}

/// Lighting is on by default: the three faces of a cube seen from a corner
/// come out in three shades; unlit, in the material colour alone.
#[test]
fn lighting_is_on_by_default() {
    let corner = Camera::look_at([3.0, 2.2, 4.0], [0.0; 3]);
    let cube = [Object::new(&CUBE, Rgb565::new(20, 40, 20))];
    let lit = front::<16>(&corner, &cube);
    assert_eq!(colours(&lit, 100), 3);
    let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
    view.set_lighting(None);
    let mut fb = Framebuffer::new(W as u32, H, BG);
    view.draw(&corner, &cube, &mut fb).unwrap();
    assert_eq!(colours(&fb.pixels, 0), 1);
    assert!(fb.pixels.contains(&Rgb565::new(20, 40, 20)));
}

/// Every wrong input is a typed error; the early ones send nothing.
#[test]
fn wrong_inputs_are_errors() {
    let cube = [Object::new(&CUBE, Rgb565::RED)];
    let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
    let run =
        |view: &mut View3d<Rgb565, W, 16>, cam: &Camera, objects: &[Object<'_, Rgb565>], w: u32, h: u32| {
            let mut fb = Framebuffer::new(w, h, Rgb565::BLUE);
            let r = view.draw(cam, objects, &mut fb);
            (r, fb.contiguous.len())
        };
    let nan = Camera::look_at([f32::NAN, 0.0, 3.0], [0.0; 3]);
    assert_eq!(
        run(&mut view, &nan, &cube, W as u32, H),
        (Err(RenderError::Input(Error::NonFiniteCoordinate)), 0)
    );
    let on_target = Camera::look_at([0.0; 3], [0.0; 3]);
    assert_eq!(
        run(&mut view, &on_target, &cube, W as u32, H),
        (Err(RenderError::Input(Error::InvalidParameter(Param::LookAt))), 0)
    );
    // A zero-size display; one narrower than the band; one shorter than the frame.
    assert_eq!(run(&mut view, &camera(), &cube, 0, 0), (Err(RenderError::Input(Error::InvalidFrameSize)), 0));
    assert_eq!(
        run(&mut view, &camera(), &cube, W as u32 - 1, H),
        (Err(RenderError::Input(outside((W as u32, H), (W as u32 - 1, H)))), 0)
    );
    view.set_height(Some(H + 1));
    assert_eq!(
        run(&mut view, &camera(), &cube, W as u32, H),
        (Err(RenderError::Input(outside((W as u32, H + 1), (W as u32, H)))), 0)
    );
    view.set_height(None);
    // A mesh wound against its normals.
    let reversed: Vec<[u16; 3]> = CUBE.mesh().indices.iter().map(|&[a, b, c]| [a, c, b]).collect();
    let inside_out = Mesh { indices: &reversed, ..*CUBE.mesh() };
    let bad = [Object::new(&inside_out, Rgb565::RED)];
    assert_eq!(
        run(&mut view, &camera(), &bad, W as u32, H),
        (Err(RenderError::Input(Error::WindingMismatch)), 0)
    );
    // The same mesh validated beforehand: its winding, found by
    // `ValidMesh::new`, still fails every frame.
    let valid = microraster::mesh::ValidMesh::new(inside_out).unwrap();
    assert!(!valid.winding_agrees() && CUBE.winding_agrees());
    let bad = [Object::new(&valid, Rgb565::RED)];
    for _ in 0..2 {
        assert_eq!(
            run(&mut view, &camera(), &bad, W as u32, H),
            (Err(RenderError::Input(Error::WindingMismatch)), 0)
        );
    }
    // A singular model fails before the first band (issue 60).
    let flat = [Object::new(&CUBE, Rgb565::RED).scale(0.0)];
    assert_eq!(
        run(&mut view, &camera(), &flat, W as u32, H),
        (Err(RenderError::Input(Error::InvalidParameter(Param::Model))), 0)
    );
    // A bad light fails the frame before any band, with no objects too.
    for direction in [Vec3::new(0.0, 0.0, f32::INFINITY), Vec3::new(0.0, 0.0, 2.0)] {
        view.set_lighting(Some(microraster::light::Lighting { direction, ..DEFAULT_LIGHTING }));
        let want = if direction.z.is_finite() {
            Error::InvalidParameter(Param::LightDirection)
        } else {
            Error::NonFiniteCoordinate
        };
        for objects in [&cube[..], &[]] {
            assert_eq!(run(&mut view, &camera(), objects, W as u32, H), (Err(RenderError::Input(want)), 0));
        }
        // The light's error comes before the camera's.
        assert_eq!(run(&mut view, &nan, &cube, W as u32, H), (Err(RenderError::Input(want)), 0));
    }
    view.set_lighting(Some(DEFAULT_LIGHTING));
    // And the view still works afterwards, on a display taller than the band is wide.
    assert_eq!(run(&mut view, &camera(), &cube, W as u32, H).0, Ok(()));
    view.set_height(Some(40));
    assert_eq!(run(&mut view, &camera(), &cube, W as u32, 200), (Ok(()), 3));
}

/// A model that overflows its normal matrix (scales of 10^30), on a mesh
/// whose bounding sphere reaches behind the eye, is the same error for
/// every band height: the singular check comes before the band test (the
/// band tests of such a sphere are not nested; the fuzz target `view3d`
/// found 1-row bands failing where one band passed).
#[test]
fn a_singular_model_fails_for_every_band_height() {
    use microraster::math::Mat4;
    let model = Mat4::from_rows([
        [5.366036e29, 0.0, -8.559218e30, -5.625],
        [0.0, -5.75, 0.0, -8.125],
        [-2.6198564, 0.0, -0.16424683, 9.452896],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    let cube = [Object::new(&CUBE, Rgb565::RED).then(model)];
    let cam = Camera::look_at([0.0, 0.0, 6.0], [0.0; 3]);
    let run = |bands: u32| {
        let mut fb = Framebuffer::new(W as u32, 2, BG);
        match bands {
            1 => View3d::<Rgb565, W, 1>::new(BG).draw(&cam, &cube, &mut fb),
            _ => View3d::<Rgb565, W, 3>::new(BG).draw(&cam, &cube, &mut fb),
        }
    };
    let want = Err(RenderError::Input(Error::InvalidParameter(Param::Model)));
    assert_eq!((run(1), run(3)), (want, want));
}

/// A singular model is an error whether or not its mesh is in view: a cube
/// scaled by 0 behind the eye fails the front in every band height and the
/// binned path, as one in view does (`Object::scale`'s docs), rather than
/// passing silently where the view cull drops it first.
#[test]
fn a_singular_model_out_of_view_is_an_error() {
    let want = Err(RenderError::Input(Error::InvalidParameter(Param::Model)));
    let cam = camera();
    for at in [[0.0, 0.2, 0.0], [0.0, 0.0, 40.0], [300.0, 0.0, 0.0]] {
        let cube = [Object::new(&CUBE, Rgb565::RED).scale(0.0).translate(at)];
        let mut fb = Framebuffer::new(W as u32, H, BG);
        let one = View3d::<Rgb565, W, 1>::new(BG).draw(&cam, &cube, &mut fb);
        let tall = View3d::<Rgb565, W, 48>::new(BG).draw(&cam, &cube, &mut fb);
        assert_eq!((one, tall), (want, want), "cube at {at:?}");
        assert!(fb.pixels.iter().all(|&c| c == BG), "cube at {at:?}: nothing drawn");
        let (pipeline, _) = View3d::<Rgb565, W, 1>::new(BG).pipeline(&cam, H).unwrap();
        let model = transform::translation(Vec3::new(at[0], at[1], at[2]))
            * transform::scaling(Vec3::new(0.0, 0.0, 0.0));
        let mut bins = heapless::Vec::<_, 64>::new();
        assert_eq!(
            pipeline.draw_mesh(CUBE.mesh(), &model, Rgb565::RED, &mut bins).err(),
            Some(Error::InvalidParameter(Param::Model))
        );
    }
}
