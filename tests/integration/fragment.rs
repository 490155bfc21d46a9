//! The fragment stage end to end: per-pixel (Phong) lighting against an f64
//! evaluation and against Gouraud, translucent geometry with the depth test
//! on and depth writes off, and varyings carried through the clipper.

use crate::ref3d::bary;
use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
use microraster::blend::{Blend, Mix};
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::fragment::{
    FragTriangle, Fragment, NORMAL_ONE, Output, POSITION_ONE, Phong, draw_fragment_band,
    draw_fragment_triangle, phong_varyings,
};
use microraster::light::Lighting;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, ValidMesh, icosphere, icosphere_triangle_count, icosphere_vertex_count};
use microraster::pipeline::{Pipeline, Shade, VertexInput};
use microraster::raster3d::{Affine, PerspectiveCorrect, ScreenTriangle, ScreenVertex, draw_triangle};
use microraster::{Band, SubPoint};

const W: usize = 160;
const H: usize = 120;
const BG: Rgb888 = Rgb888::BLACK;

fn light() -> Lighting<f32> {
    Lighting::new(0.15, Vec3::new(-0.3, 0.5, 0.8), 0.6).with_specular(0.6, 24)
}

fn camera() -> Mat4<f32> {
    transform::look_at(Vec3::new(0.0, 0.0, 3.2), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap()
}

/// A coarse sphere (subdivision 1: 80 faces, large enough for highlights to
/// fall between vertices).
fn sphere<R>(f: impl FnOnce(ValidMesh<'_>) -> R) -> R {
    const V: usize = icosphere_vertex_count(1);
    const T: usize = icosphere_triangle_count(1);
    let (mut p, mut n, mut i) = ([[0.0; 3]; V], [[0.0; 3]; V], [[0u16; 3]; T]);
    let mesh: Mesh<'_> = icosphere(1, &mut p, &mut n, &mut i).unwrap();
    f(ValidMesh::new(mesh).unwrap())
}

/// `Σ λ_k q_k v_k / Σ λ_k q_k` at pixel `(x, y)`: perspective-correct, f64.
fn persp<const A: usize>(t: &FragTriangle<4, A>, x: i32, y: i32) -> Option<[f64; A]> {
    let (l, det) = bary(t.tri.v.map(|v| v.pos), x, y)?;
    let wq: [f64; 3] = [0, 1, 2].map(|k| l[k] as f64 / det as f64 * t.tri.v[k].inv_w as f64);
    let sum: f64 = wq.iter().sum();
    Some(core::array::from_fn(|j| (0..3).map(|k| wq[k] * t.varyings[k][j] as f64).sum::<f64>() / sum))
}

#[test]
fn phong_matches_an_f64_evaluation_and_keeps_highlights_gouraud_loses() {
    let (bins, gouraud) = sphere(|mesh| {
        let p = Pipeline::<f32, 4>::perspective(camera(), 0.9, 1.0, 10.0, W as u32, H as u32).unwrap();
        let mut bins = Box::new(heapless::Vec::<FragTriangle<4, 6>, 128>::new());
        let model = transform::rotation_y(0.3);
        let white = Rgb888::new(110, 110, 110);
        p.draw_mesh_varying(&mesh, &model, white, phong_varyings::<f32>, &mut bins).unwrap();
        let lit = p.with_lighting(light());
        let mut g = Box::new(heapless::Vec::<ScreenTriangle<4>, 128>::new());
        lit.draw_valid_mesh(&mesh, &model, white, &mut g).unwrap();
        (bins, g)
    });
    assert!(bins.len() > 20, "{} front triangles", bins.len());
    let shader = Phong { lighting: light() };
    let mut band = Box::new(Band::<Rgb888, W, H>::new(BG));
    let mut depth = Box::new(DepthBand::<Depth16, W, H>::new());
    let mut view = band.view(0, H, BG);
    draw_fragment_band(&bins, &mut view, &mut depth.rows_mut(H), &shader, Output::OPAQUE, PerspectiveCorrect)
        .unwrap();
    // The f64 evaluation at every pixel each front triangle covers (the
    // sphere is convex: every covered pixel shows its only front triangle).
    let l = light();
    let (mut worst, mut n) = (0f64, 0usize);
    let rows = band.rows();
    for t in bins.iter() {
        for y in 0..H as i32 {
            for x in 0..W as i32 {
                let Some(v) = persp(t, x, y) else { continue };
                let (lam, det) = bary(t.tri.v.map(|v| v.pos), x, y).unwrap();
                let inside = lam.iter().all(|&a| if det > 0 { a > 0 } else { a < 0 });
                if !inside {
                    continue; // edges belong to one neighbour: skip them
                }
                let nn = [v[0], v[1], v[2]].map(|c| c / NORMAL_ONE as f64);
                let len = (nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]).sqrt();
                let nn = nn.map(|c| c / len);
                let p = [v[3], v[4], v[5]].map(|c| c / POSITION_ONE as f64);
                let d = [l.direction.x, l.direction.y, l.direction.z].map(f64::from);
                let lam_d = (nn[0] * d[0] + nn[1] * d[1] + nn[2] * d[2]).max(0.0);
                let pl = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
                let h = [0, 1, 2].map(|k| d[k] - p[k] / pl);
                let hl = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
                let nh = (0..3).map(|k| nn[k] * h[k] / hl).sum::<f64>().max(0.0);
                let spec = if lam_d > 0.0 { 0.6 * nh.powi(24) } else { 0.0 };
                let base = t.tri.v[0].color[0] as f64 / 255.0;
                let want = ((base * (0.15 + 0.6 * lam_d) + spec).clamp(0.0, 1.0) * 255.0).min(255.0);
                let got = rows[y as usize][x as usize].r() as f64;
                worst = worst.max((got - want).abs());
                n += 1;
            }
        }
    }
    println!("Phong vs f64: {n} pixels, worst {worst:.3} (8-bit steps)");
    // ½ for rounding; the normals' 2^-14 quantisation through the power 24
    // adds at most 24·2^-14·0.6·255 ≈ 0.22; f32 arithmetic is far below.
    assert!(n > 3000 && worst <= 0.75, "{n} pixels, worst {worst}");

    // Gouraud on the same sphere: its brightest pixel is darker, since the
    // highlight peaks between vertices.
    let mut gband = Box::new(Band::<Rgb888, W, H>::new(BG));
    let mut gdepth = Box::new(DepthBand::<Depth16, W, H>::new());
    let mut gview = gband.view(0, H, BG);
    for t in gouraud.iter() {
        draw_triangle(t, &mut gview, &mut gdepth.rows_mut(H), DepthState::LESS_WRITE, PerspectiveCorrect);
    }
    let peak = |b: &Band<Rgb888, W, H>| b.rows().iter().flatten().map(|c| u16::from(c.r())).max().unwrap();
    let (phong_peak, gouraud_peak) = (peak(&band), peak(&gband));
    println!("highlight peak: Phong {phong_peak}, Gouraud {gouraud_peak}");
    assert!(phong_peak >= gouraud_peak + 20, "Phong {phong_peak}, Gouraud {gouraud_peak}");
}

/// Two triangles covering columns `x0..x1`, rows 10..50, flat at `depth`.
pub(crate) fn rect(x0: i32, x1: i32, depth: u32, color: [u8; 3]) -> [FragTriangle<4, 0>; 2] {
    let v = |x: i32, y: i32| ScreenVertex {
        pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
        depth,
        inv_w: 1 << 30,
        color,
    };
    let (a, b, c, d) = (v(x0, 10), v(x1, 10), v(x1, 50), v(x0, 50));
    [
        FragTriangle { tri: ScreenTriangle { v: [a, c, b], flat: true }, varyings: [[]; 3] },
        FragTriangle { tri: ScreenTriangle { v: [a, d, c], flat: true }, varyings: [[]; 3] },
    ]
}

#[test]
fn translucent_geometry_blends_depth_tested_without_writing_depth() {
    let (blue, red, green) = ([0, 0, 255], [255, 0, 0], [0, 255, 0]);
    let mut band = Box::new(Band::<Rgb888, 100, 60>::new(BG));
    let mut depth = Box::new(DepthBand::<Depth16, 100, 60>::new());
    let mut view = band.view(0, 60, BG);
    let z = |f: f64| (f * u32::MAX as f64) as u32;
    // Opaque blue at depth 0.5 (x 0..40), translucent red nearer (x 20..60),
    // translucent red farther than the blue (x 10..50, hidden where blue is).
    fn draw<B: Blend>(
        t: &[FragTriangle<4, 0>],
        out: Output<B>,
        view: &mut microraster::band::BandView<'_, Rgb888, 100>,
        depth: &mut DepthBand<Depth16, 100, 60>,
    ) {
        let flat = |f: &Fragment<0>| Rgb888::new(f.color[0], f.color[1], f.color[2]);
        for t in t {
            draw_fragment_triangle(t, view, &mut depth.rows_mut(60), &flat, out, Affine).unwrap();
        }
    }
    draw(&rect(0, 40, z(0.5), blue), Output::OPAQUE, &mut view, &mut depth);
    draw(&rect(20, 60, z(0.3), red), Output::translucent(100), &mut view, &mut depth);
    // Depth was not written by the translucent rectangle: an opaque green one
    // at 0.4 (behind the red, in front of the blue) still replaces x 20..30.
    draw(&rect(20, 30, z(0.4), green), Output::OPAQUE, &mut view, &mut depth);
    // A translucent red one behind the blue: hidden there, blended elsewhere.
    draw(&rect(10, 50, z(0.7), red), Output::translucent(100), &mut view, &mut depth);
    let px = |x: usize| band.rows()[30][x];
    let c = |v: [u8; 3]| Rgb888::new(v[0], v[1], v[2]);
    assert_eq!(px(5), c(blue), "opaque only");
    assert_eq!(px(25), c(green), "green drawn after: depth 0.3 was never written");
    assert_eq!(
        px(45),
        Mix.blend(c(red), Mix.blend(c(red), BG, 100), 100),
        "two translucent reds over the background"
    );
    assert_eq!(px(55), Mix.blend(c(red), BG, 100), "near red over background");
    assert_eq!(px(15), c(blue), "the far red is hidden behind the blue");
}

#[test]
fn varyings_are_carried_exactly_through_the_near_plane() {
    // A large triangle crossing the near plane: each vertex's varyings are
    // its corner's weight · 2^20; after clipping the weights must put the
    // new vertex where it is on screen.
    let pos = [[-2.0, -1.0, 2.5], [2.0, -1.0, 2.5], [0.0, 1.5, -6.0]];
    let mesh = Mesh::new(&pos, &[], &[[0, 1, 2]], ([0.0, 0.0, -1.0], 6.0));
    let mesh = ValidMesh::new(mesh).unwrap();
    let eye =
        transform::look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))
            .unwrap();
    let mut p = Pipeline::<f32, 4>::perspective(eye, 0.9, 1.0, 20.0, W as u32, H as u32).unwrap();
    p.cull = microraster::edge::Cull::None;
    p.shade = Shade::Gouraud;
    let mut bins = heapless::Vec::<FragTriangle<4, 3>, 8>::new();
    let one = 1 << 20;
    let weights = |v: &VertexInput<f32>| {
        let mut w = [0; 3];
        w[v.index as usize] = one;
        w
    };
    let stats = p.draw_mesh_varying(&mesh, &Mat4::IDENTITY, Rgb888::WHITE, weights, &mut bins).unwrap();
    assert!(stats.clipped == 1 && !bins.is_empty(), "{stats:?}");
    let mvp = transform::perspective(0.9f32, W as f32 / H as f32, 1.0, 20.0).unwrap() * eye;
    let mut checked = 0;
    for t in &bins {
        for (v, w) in t.tri.v.iter().zip(t.varyings) {
            let total: i32 = w.iter().sum();
            assert!((total - one).abs() <= 2 && w.iter().all(|&x| (-1..=one + 1).contains(&x)), "{w:?}");
            // Σ w_k · clip_k, projected, in f64.
            let mut c = [0f64; 4];
            for (k, q) in pos.iter().enumerate() {
                let cl = mvp.transform_point(Vec3::new(q[0], q[1], q[2]));
                for (ci, v) in c.iter_mut().zip([cl.x, cl.y, cl.z, cl.w]) {
                    *ci += w[k] as f64 / one as f64 * v as f64;
                }
            }
            let sx = (c[0] / c[3] + 1.0) * W as f64 / 2.0;
            let sy = (1.0 - c[1] / c[3]) * H as f64 / 2.0;
            let (gx, gy) = (v.pos.x() as f64 / 16.0, v.pos.y() as f64 / 16.0);
            assert!((gx - sx).abs() < 0.05 && (gy - sy).abs() < 0.05, "({gx}, {gy}) vs ({sx}, {sy})");
            checked += 1;
        }
    }
    assert!(checked >= 3);
}
