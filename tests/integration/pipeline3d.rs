//! The vertex stage end to end: the standard 3D scene on the `f32` and `Fx`
//! paths, band-height invariance of `Triangles3d`, and `MeshStats`.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use microraster::depth::{Depth16, Depth24, DepthBand, DepthFormat, DepthState};
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{
    cube, cube_triangle_count, cube_vertex_count, icosphere, icosphere_triangle_count, icosphere_vertex_count,
};
use microraster::pipeline::{MeshStats, Pipeline};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Interpolate, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

const W: usize = 160;
const HEIGHT: usize = 120; // not a multiple of 7 or 16: the last band is short
const BG: Rgb565 = Rgb565::new(2, 4, 6);
type Bins = heapless::Vec<ScreenTriangle<4>, BINS>;

fn bins<T: Scalar>(scene: &mut Scene3d, angle: f32) -> Box<Bins> {
    let p = Scene3d::pipeline::<T, 4>(W as u32, HEIGHT as u32).unwrap();
    let mut bins = Box::new(Bins::new());
    let st = scene.draw::<T, Rgb565, 4, BINS>(&p, angle, &mut bins).unwrap();
    assert_eq!(st.emitted as usize, bins.len());
    bins
}

fn render<F: DepthFormat, M: Interpolation, const H: usize>(bins: &[ScreenTriangle<4>]) -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(W as u32, HEIGHT as u32, Rgb565::new(31, 63, 31));
    let mut band = Box::new(Band::<Rgb565, W, H>::new(BG));
    let mut depth = Box::new(DepthBand::<F, W, H>::new());
    Renderer::new(HEIGHT as u32, BG)
        .render(Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, M::default()), &mut band, &mut fb)
        .unwrap();
    // One fill_contiguous per band, full width, consecutive, the last one short.
    assert_eq!(fb.contiguous.len(), HEIGHT.div_ceil(H), "band count for H = {H}");
    for (i, r) in fb.contiguous.iter().enumerate() {
        assert_eq!(r.top_left, Point::new(0, (i * H) as i32));
        assert_eq!(r.size, Size::new(W as u32, (HEIGHT - i * H).min(H) as u32));
    }
    assert!(fb.writes.iter().all(|&w| w == 1), "each frame pixel sent exactly once");
    fb.pixels
}

fn bands_agree<F: DepthFormat, M: Interpolation>(bins: &[ScreenTriangle<4>]) -> usize {
    let full = render::<F, M, HEIGHT>(bins);
    assert_eq!(render::<F, M, 1>(bins), full, "band height 1");
    assert_eq!(render::<F, M, 7>(bins), full, "band height 7");
    assert_eq!(render::<F, M, 16>(bins), full, "band height 16");
    full.iter().filter(|&&c| c != BG).count()
}

#[test]
fn frame_is_identical_for_band_heights_1_7_16_and_full() {
    let mut scene = Box::new(Scene3d::new());
    let mut frames = 0;
    for angle in [0.0, 0.8, 2.1, 4.0] {
        let b = bins::<f32>(&mut scene, angle);
        let drawn = bands_agree::<Depth16, PerspectiveCorrect>(&b) + bands_agree::<Depth24, Affine>(&b);
        let b = bins::<Fx>(&mut scene, angle);
        let drawn = drawn + bands_agree::<Depth16, Affine>(&b);
        assert!(drawn > 3 * W * HEIGHT / 10, "scene mostly missing at angle {angle}");
        frames += 3;
    }
    println!("3D band invariance: {frames} frames x 4 band heights identical");
    assert_eq!(frames, 12);
}

#[test]
fn f32_and_fx_paths_draw_nearly_the_same_frame() {
    let mut scene = Box::new(Scene3d::new());
    let (mut px, mut differ, mut far_off, mut coverage) = (0usize, 0usize, 0usize, 0usize);
    for angle in [0.0, 0.5, 1.3, 2.2, 3.1, 4.4, 5.6] {
        let a = render::<Depth16, PerspectiveCorrect, 16>(&bins::<f32>(&mut scene, angle));
        let b = render::<Depth16, PerspectiveCorrect, 16>(&bins::<Fx>(&mut scene, angle));
        for (p, q) in a.iter().zip(&b) {
            if *p == BG && *q == BG {
                continue;
            }
            px += 1;
            coverage += usize::from((*p == BG) != (*q == BG));
            let (p, q) = (p.to_channels(), q.to_channels());
            let d = (0..3).map(|k| p[k].abs_diff(q[k])).max().unwrap();
            differ += usize::from(d > 0);
            far_off += usize::from(d > 1);
        }
    }
    let (f1, f2) = (differ as f64 / px as f64, far_off as f64 / px as f64);
    println!(
        "f32 vs Fx, standard scene {W}x{HEIGHT}, 7 angles: {px} drawn pixels, {differ} differ ({:.2}%), \
         {far_off} by more than one channel level ({:.3}%), {coverage} covered in one frame only",
        100.0 * f1,
        100.0 * f2
    );
    assert!(px > 7 * W * HEIGHT / 5, "scene mostly missing");
    // One-level differences are vertex colours rounding the other way (Fx
    // lighting differs by ~2^-16); larger ones need moved edges.
    assert!(f1 < 0.15 && f2 < 0.005, "f32 and Fx frames differ too much");
}

/// Viewport of the `MeshStats` checks (larger triangles, fewer ambiguous).
const SW: u32 = 640;
const SH: u32 = 480;

/// Screen position (y down) of `p` under `view` and `proj`, in f64 from the
/// `f32` matrices.
fn project(view: Mat4<f32>, proj: Mat4<f32>, p: [f32; 3]) -> (f64, f64) {
    let (v, pr) = (view.to_f32(), proj.to_f32());
    let mul = |m: &[[f32; 4]; 4], x: [f64; 4]| {
        [0, 1, 2, 3].map(|r| (0..4).map(|c| m[c][r] as f64 * x[c]).sum::<f64>())
    };
    let c = mul(&pr, mul(&v, [p[0] as f64, p[1] as f64, p[2] as f64, 1.0]));
    (SW as f64 / 2.0 * (1.0 + c[0] / c[3]), SH as f64 / 2.0 * (1.0 - c[1] / c[3]))
}

/// Sure front faces, sure back faces and ambiguous ones of `indices`: the
/// sign of twice the projected area in y-down pixel coordinates. A front
/// face is counter-clockwise seen from outside, and the projection keeps the
/// picture's orientation (screen up is view up), so it is counter-clockwise
/// on screen too: negative `area2` with y down. Ambiguous when moving each
/// vertex by `delta` px could flip the sign (`|Δ area2| ≤ 2δ·perimeter + 12δ²`).
fn classify(view: Mat4<f32>, proj: Mat4<f32>, pos: &[[f32; 3]], idx: &[[u16; 3]], delta: f64) -> [usize; 3] {
    let mut n = [0; 3];
    for t in idx {
        let p = t.map(|i| project(view, proj, pos[i as usize]));
        let area2 = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
        let perimeter: f64 =
            (0..3).map(|i| (p[i].0 - p[(i + 1) % 3].0).hypot(p[i].1 - p[(i + 1) % 3].1)).sum();
        let margin = 2.0 * delta * perimeter + 12.0 * delta * delta;
        n[if area2 < -margin {
            0
        } else if area2 > margin {
            1
        } else {
            2
        }] += 1;
    }
    n
}

fn stats<T: Scalar>(
    eye: [f32; 3],
    pos: &[[f32; 3]],
    nrm: &[[f32; 3]],
    idx: &[[u16; 3]],
    model: Mat4<T>,
) -> MeshStats {
    let f = |v: [f32; 3]| Vec3::new(T::from_f32(v[0]), T::from_f32(v[1]), T::from_f32(v[2]));
    let view = transform::look_at(f(eye), f([0.0; 3]), f([0.0, 1.0, 0.0])).unwrap();
    let p =
        Pipeline::<T, 4>::perspective(view, T::from_f32(0.9), T::from_f32(0.5), T::from_f32(50.0), SW, SH)
            .unwrap();
    let mesh = microraster::mesh::Mesh::new(pos, nrm, idx, microraster::mesh::bounding_sphere(pos));
    let mut bins = Box::new(Bins::new());
    p.draw_mesh(&mesh, &model, Rgb565::new(31, 0, 0), &mut bins).unwrap()
}

fn check_convex<T: Scalar>(
    name: &str,
    eye: [f32; 3],
    pos: &[[f32; 3]],
    nrm: &[[f32; 3]],
    idx: &[[u16; 3]],
    vertex_err: f64,
) -> MeshStats {
    let st = stats::<T>(eye, pos, nrm, idx, Mat4::IDENTITY);
    let view = transform::look_at(Vec3::from_f32(eye), Vec3::ZERO, Vec3::new(0.0, 1.0, 0.0)).unwrap();
    let proj = transform::perspective(0.9f32, SW as f32 / SH as f32, 0.5, 50.0).unwrap();
    let delta = std::f64::consts::SQRT_2 / 32.0 + vertex_err;
    let [front, back, amb] = classify(view, proj, pos, idx, delta);
    let total = idx.len() as u32;
    println!("{name}: {st:?}; reference: {front} front, {back} back, {amb} ambiguous");
    assert!(!st.mesh_culled && st.clipped == 0, "{name}: {st:?}");
    assert_eq!(st.emitted + st.back_faces + st.degenerate, total, "{name}: every triangle accounted for");
    assert!((back..=back + amb).contains(&(st.back_faces as usize)), "{name}: back faces {st:?}");
    assert!((front..=front + amb).contains(&(st.emitted as usize)), "{name}: front faces {st:?}");
    st
}

#[test]
fn mesh_stats_back_faces_of_convex_meshes() {
    let mut pos = vec![[0.0; 3]; icosphere_vertex_count(3)];
    let mut nrm = pos.clone();
    let mut idx = vec![[0u16; 3]; icosphere_triangle_count(3)];
    icosphere(3, &mut pos, &mut nrm, &mut idx).unwrap();
    let eye = [0.0, 1.5, 4.77]; // distance D = 5.0 from the unit sphere's centre
    let d = (eye[1] as f64).hypot(eye[2] as f64);
    // A sphere hides the fraction (1 + r/D)/2 of its area from a point at distance D.
    let expect = (1.0 + 1.0 / d) / 2.0;
    // Vertex error allowances: the envelope measured at 320×240 in
    // `math::transform`'s docs for w ≥ 4 (0.0045 px f32, 0.15 px Fx), doubled
    // for 640×480 and rounded up.
    let (ef, ex) = (0.01, 0.35);
    for (name, st) in [
        ("icosphere f32", check_convex::<f32>("icosphere f32", eye, &pos, &nrm, &idx, ef)),
        ("icosphere Fx", check_convex::<Fx>("icosphere Fx", eye, &pos, &nrm, &idx, ex)),
    ] {
        let frac = st.back_faces as f64 / idx.len() as f64;
        println!("{name}: {:.3} of {} triangles are back faces (sphere: {expect:.3})", frac, idx.len());
        assert!((frac - expect).abs() < 0.03, "{name}: back-face fraction {frac}");
    }
    let mut cp = [[0.0; 3]; cube_vertex_count()];
    let mut cn = cp;
    let mut ci = [[0u16; 3]; cube_triangle_count()];
    cube(&mut cp, &mut cn, &mut ci).unwrap();
    // Three faces seen from a generic corner direction: exactly half.
    for st in [
        check_convex::<f32>("cube f32", [3.0, 2.5, 4.0], &cp, &cn, &ci, ef),
        check_convex::<Fx>("cube Fx", [3.0, 2.5, 4.0], &cp, &cn, &ci, ex),
    ] {
        assert_eq!((st.emitted, st.back_faces), (6, 6));
    }
    // Behind the camera: culled by its bounding sphere before any vertex work.
    let behind = transform::translation(Vec3::new(0.0, 3.0, 9.54));
    let st = stats::<f32>(eye, &pos, &nrm, &idx, behind);
    assert_eq!(st, MeshStats { mesh_culled: true, ..MeshStats::default() });
}
