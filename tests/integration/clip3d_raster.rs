//! Clipping through the `f32` pipeline against an f64 reference that clips
//! the same way: the same planes in the same order (`w ≥ w_min`, near `z ≥ 0`,
//! far `z ≤ w`, guard band `|x|, |y| ≤ g·w`, Sutherland–Hodgman from the inside
//! end of each edge), then projection and point-in-polygon at pixel centres.
//!
//! Tolerance: if the vertices of the clipped polygon move by at most `δ_i`,
//! the boundary point `(1 − s)·r_i + s·r_{i+1}` moves by at most
//! `(1 − s)·δ_i + s·δ_{i+1}`, and a pixel centre can only change sides where
//! that boundary point can reach it (the boundary sweeps continuously from
//! the reference polygon to the drawn one; `slack` below). Each emitted
//! vertex must lie within its derived bound of a reference vertex, and the
//! coverage check uses `δ_i` = the measured displacement of reference vertex
//! `i` to the nearest emitted vertex, capped by its derived bound (tight,
//! and still conservative). Derived bound per vertex and axis: the snapping
//! error `2^-(S+1)` px plus the `f32` error, to first order with
//! `u = 2^-24` (view = model = identity, so `mvp` is the projection `P`
//! exactly), derived in `clip3d_ref`.

use crate::clip3d_ref::{Ref, inside, slack};
use crate::framebuffer::Framebuffer;
use crate::ref3d::{ONE_TRIANGLE, loose_sphere};
use crate::reference::{Rng, dist_to_segment};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::clip3d::ClipPlanes;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Mat4, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Renderer};

const W: usize = 96;
const H: usize = 72;
const S: u32 = 4;
const BG: Gray8 = Gray8::new(0);
const FG: Gray8 = Gray8::new(255);
const FOV: f32 = 1.0;
const NEAR: f32 = 0.1;
const FAR_D: f32 = 50.0;
/// Snapping error per axis, px.
const SNAP: f64 = 0.5 / (1 << S) as f64;

#[derive(Default, Debug)]
struct Stats {
    cases: usize,
    drawn: usize,
    clipped: usize,
    pixels: usize,
    mismatches: usize,
    worst_distance: f64,
    max_delta: f64,
    worst_vertex: f64,
}

struct Setup {
    p: Pipeline<f32, S>,
    r: Ref,
    /// Whether depth has a near and far plane (a perspective projection).
    depth_planes: bool,
}

/// `w_ref` must be a lower bound of every visible `w` (`Pipeline::new`).
fn setup(projection: Mat4<f32>, w_ref: f32, depth_planes: bool) -> Setup {
    let mut p = Pipeline::<f32, S>::new(Mat4::IDENTITY, projection, w_ref, W as u32, H as u32).unwrap();
    p.cull = Cull::None;
    p.shade = Shade::Flat;
    let cols = projection.to_f32();
    let m = [0, 1, 2, 3].map(|r| [0, 1, 2, 3].map(|c| cols[c][r] as f64));
    let r = Ref { m, g: p.clip.guard_band() as f64, w_min: p.clip.w_min() as f64, far: p.clip.far() };
    Setup { p, r, depth_planes }
}

/// Draws one triangle through the pipeline and checks it against the
/// reference; `expect_empty` additionally demands that nothing is drawn.
fn check(s: &Setup, tri: [[f32; 3]; 3], loose: bool, expect_empty: bool, st: &mut Stats) {
    let sphere = if loose { loose_sphere(&tri) } else { bounding_sphere(&tri) };
    let mesh = Mesh::new(&tri, &[], &ONE_TRIANGLE, sphere);
    let mut bins = heapless::Vec::<ScreenTriangle<S>, 16>::new();
    let ms = s.p.draw_mesh(&mesh, &Mat4::IDENTITY, FG, &mut bins).unwrap();
    let mut fb = Framebuffer::new(W as u32, H as u32, BG);
    let mut band = Box::new(Band::<Gray8, W, 16>::new(BG));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    Renderer::new(H as u32, BG)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
        .unwrap();

    let poly = s.r.clip(tri.map(|p| s.r.vertex(p)));
    let scr: Vec<((f64, f64), (f64, f64))> = poly.iter().map(|v| s.r.screen(v, W, H)).collect();
    let pts: Vec<(f64, f64)> = scr.iter().map(|q| q.0).collect();
    let emitted: Vec<(f64, f64)> =
        bins.iter().flat_map(|t| t.v).map(|v| (v.pos.x() as f64 / 16.0, v.pos.y() as f64 / 16.0)).collect();
    let delta: Vec<f64> = scr
        .iter()
        .map(|(q, (ex, ey))| {
            let measured = emitted.iter().map(|e| (e.0 - q.0).hypot(e.1 - q.1)).fold(f64::INFINITY, f64::min);
            (ex + SNAP).hypot(ey + SNAP).min(measured + 1e-9)
        })
        .collect();
    st.cases += 1;
    st.drawn += usize::from(!bins.is_empty());
    st.clipped += usize::from(ms.clipped > 0);
    if expect_empty {
        assert!(!fb.pixels.contains(&FG), "drew {ms:?} for {tri:?} (loose sphere {loose})");
    }
    if poly.is_empty() {
        assert!(bins.is_empty(), "emitted {ms:?} for {tri:?}, which the reference clips away");
    }
    // Every emitted vertex is within its bound of some reference vertex: per
    // axis, snapping plus the f32 error. Track how much of the f32 bound the
    // excess over snapping uses.
    for v in bins.iter().flat_map(|t| t.v) {
        let (x, y) = (v.pos.x() as f64 / 16.0, v.pos.y() as f64 / 16.0);
        let fits = |(q, (ex, ey)): &((f64, f64), (f64, f64))| {
            let (dx, dy) = ((x - q.0).abs(), (y - q.1).abs());
            (dx <= SNAP + ex && dy <= SNAP + ey).then(|| ((dx - SNAP) / ex).max((dy - SNAP) / ey).max(0.0))
        };
        let used = scr.iter().filter_map(fits).fold(f64::INFINITY, f64::min);
        assert!(used.is_finite(), "vertex ({x}, {y}) off every reference vertex of {scr:?} for {tri:?}");
        st.worst_vertex = st.worst_vertex.max(used);
    }
    for y in 0..H {
        for x in 0..W {
            let c = (x as f64 + 0.5, y as f64 + 0.5);
            let want = pts.len() >= 3 && inside(&pts, c);
            let got = fb.pixels[y * W + x] == FG;
            st.pixels += 1;
            if want != got {
                st.mismatches += 1;
                let n = pts.len();
                let d = (0..n)
                    .map(|i| dist_to_segment(c, pts[i], pts[(i + 1) % n]))
                    .fold(f64::INFINITY, f64::min);
                let (slack, local) = (0..n)
                    .map(|i| slack(c, (pts[i], delta[i]), (pts[(i + 1) % n], delta[(i + 1) % n])))
                    .fold((f64::INFINITY, 0.0), |a, b| if b.0 < a.0 { b } else { a });
                assert!(
                    slack <= 1e-9,
                    "pixel ({x},{y}) drawn={got} is {d} px from the edge (δ {delta:?}) for {tri:?}"
                );
                st.worst_distance = st.worst_distance.max(d);
                st.max_delta = st.max_delta.max(local);
            }
        }
    }
}

/// A view-space point at eye distance `dist` whose projection is NDC `(u, v)`.
fn at_ndc(u: f64, v: f64, dist: f64) -> [f32; 3] {
    let ty = (FOV as f64 / 2.0).tan();
    let tx = ty * W as f64 / H as f64;
    [(u * tx * dist) as f32, (v * ty * dist) as f32, -dist as f32]
}

fn on_screen(rng: &mut Rng, dist: f64) -> [f32; 3] {
    at_ndc(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), dist)
}

fn front(rng: &mut Rng) -> f64 {
    rng.log_uniform(NEAR as f64 * 1.5, FAR_D as f64 * 0.8)
}

fn scenario(rng: &mut Rng, kind: usize, depth_planes: bool) -> ([[f32; 3]; 3], bool) {
    let mut t = match kind {
        // Crossing the near plane: 1 or 2 vertices in front, the rest behind
        // the eye or between the eye and the near plane.
        0 => {
            let k = 1 + rng.below(2) as usize;
            [0, 1, 2].map(|i| {
                if i < k {
                    let d = front(rng);
                    on_screen(rng, d)
                } else if rng.chance(0.5) {
                    [
                        rng.uniform(-5.0, 5.0) as f32,
                        rng.uniform(-5.0, 5.0) as f32,
                        rng.log_uniform(1e-3, 20.0) as f32,
                    ]
                } else {
                    let d = rng.uniform(0.0, NEAR as f64);
                    on_screen(rng, d)
                }
            })
        }
        // Entirely behind the eye, placed where the naive projection (x/w
        // with w < 0) lands on screen.
        1 => [0, 1, 2].map(|_| {
            let d = rng.log_uniform(0.05, 40.0);
            let p = on_screen(rng, d);
            [p[0], p[1], -p[2]]
        }),
        // w → 0+: vertices a hair in front of the eye (far inside the near
        // plane), far off axis, with the others visible.
        2 => {
            let k = 1 + rng.below(2) as usize;
            [0, 1, 2].map(|i| {
                if i < k {
                    let d = rng.log_uniform(1e-7, NEAR as f64);
                    [rng.uniform(-3.0, 3.0) as f32, rng.uniform(-3.0, 3.0) as f32, -d as f32]
                } else {
                    let d = front(rng);
                    on_screen(rng, d)
                }
            })
        }
        // Entirely outside one plane of the view volume.
        3 => {
            let side = rng.below(if depth_planes { 6 } else { 4 });
            [0, 1, 2].map(|_| {
                let (a, b) = (rng.uniform(1.05, 30.0), rng.uniform(-30.0, 30.0));
                match side {
                    0 => at_ndc(-a, b, front(rng)),
                    1 => at_ndc(a, b, front(rng)),
                    2 => at_ndc(b, -a, front(rng)),
                    3 => at_ndc(b, a, front(rng)),
                    4 => at_ndc(b / 20.0, b / 25.0, FAR_D as f64 * rng.uniform(1.05, 20.0)),
                    _ => at_ndc(b, a, NEAR as f64 * rng.uniform(0.0, 0.95)),
                }
            })
        }
        // Far larger than the guard band: NDC up to ±10^5, edges crossing the frame.
        _ => {
            let th = rng.uniform(0.0, std::f64::consts::TAU);
            let (m1, m2) = (rng.log_uniform(10.0, 1e5), rng.log_uniform(10.0, 1e5));
            let a = at_ndc(m1 * th.cos(), m1 * th.sin(), front(rng));
            let th2 = th + std::f64::consts::PI + rng.uniform(-0.3, 0.3);
            let b = at_ndc(m2 * th2.cos(), m2 * th2.sin(), front(rng));
            let d = front(rng);
            let c =
                if rng.chance(0.5) { on_screen(rng, d) } else { at_ndc(-m1 * th.sin(), m2 * th.cos(), d) };
            [a, b, c]
        }
    };
    if rng.chance(0.5) {
        t.swap(1, 2);
    }
    (t, kind == 1 || kind == 3)
}

const NAMES: [&str; 5] = ["crossing near", "behind the eye", "w -> 0+", "outside", "beyond guard band"];

fn run(s: &Setup, seed: u64, what: &str, per_kind: usize) {
    let mut rng = Rng::new(seed);
    for (kind, name) in NAMES.iter().enumerate() {
        let mut st = Stats::default();
        for i in 0..per_kind {
            let (tri, empty) = scenario(&mut rng, kind, s.depth_planes);
            check(s, tri, i % 2 == 0, empty, &mut st);
        }
        println!(
            "clip {what}, {name:18}: {} cases ({} drawn, {} clipped), {} pixels, {} mismatches, all within \
             the local δ (farthest {:.3} px from the reference edge, largest local δ {:.3} px); vertex error \
             beyond snapping uses at most {:.0}% of its f32 bound",
            st.cases,
            st.drawn,
            st.clipped,
            st.pixels,
            st.mismatches,
            st.worst_distance,
            st.max_delta,
            100.0 * st.worst_vertex
        );
        assert_eq!(st.cases, per_kind);
        if kind != 1 && kind != 3 {
            let enough = st.drawn >= per_kind * 2 / 3 && st.clipped >= per_kind / 2;
            assert!(enough, "{name}: too few drawn/clipped cases: {st:?}");
        }
    }
}

#[test]
fn clipped_coverage_matches_f64_reference() {
    let s = setup(transform::perspective(FOV, W as f32 / H as f32, NEAR, FAR_D).unwrap(), NEAR, true);
    run(&s, 0xc11b_3d00, "perspective", 3000);
}

/// A projection with constant depth `z = w/2`: the near plane `z ≥ 0` is then
/// `w ≥ 0`, so the `w ≥ w_min` plane is what stops `w → 0+`, and the guard
/// band what bounds `x/w` at `w = 2^-16`.
#[test]
fn w_min_plane_clips_like_the_reference() {
    run(&setup(half_depth(), ClipPlanes::W_MIN, false), 0xc11b_3d01, "z = w/2", 1200);
}

fn half_depth() -> Mat4<f32> {
    let p = transform::perspective(FOV, W as f32 / H as f32, NEAR, FAR_D).unwrap().to_f32();
    let (fx, fy, z) = (p[0][0], p[1][1], 0.0);
    Mat4::from_rows([[fx, z, z, z], [z, fy, z, z], [z, z, -0.5, z], [z, z, -1.0, z]])
}

/// Regression: with `w_ref` above some visible `w` (a contract violation the
/// pipeline cannot detect), `inv_w` saturates instead of the clipped polygon
/// being dropped.
#[test]
fn small_w_below_w_ref_is_not_dropped() {
    let s = setup(half_depth(), NEAR, false);
    let tri = [
        [5.7411404, 2.4312007, -7.1131735],
        [-0.0044636447, 0.0020454323, -0.0119935265],
        [-0.21629038, -4.1409335, 12.345458],
    ];
    let mut bins = heapless::Vec::<ScreenTriangle<S>, 16>::new();
    let mesh = Mesh::new(&tri, &[], &ONE_TRIANGLE, loose_sphere(&tri));
    let ms = s.p.draw_mesh(&mesh, &Mat4::IDENTITY, FG, &mut bins).unwrap();
    // The polygon covers (23.5, 24.8)–(101.2, 13.5) on screen; all 4 fan
    // triangles come back as `degenerate`.
    assert!(ms.emitted > 0 && ms.degenerate == 0, "{ms:?}");
    check(&s, tri, true, false, &mut Stats::default());
}

#[test]
fn nothing_behind_the_eye_is_drawn() {
    let s = setup(transform::perspective(FOV, W as f32 / H as f32, NEAR, FAR_D).unwrap(), NEAR, true);
    // Behind the camera (z_view > 0); the naive projection x/w with w = −z_view
    // mirrors it onto the middle of the screen, covering most of it.
    let tri =
        [at_ndc(-0.9, -0.9, 2.0), at_ndc(0.9, -0.9, 2.0), at_ndc(0.0, 0.9, 2.0)].map(|p| [p[0], p[1], -p[2]]);
    let naive = s.r.vertex(tri[0]);
    assert!(
        naive.c[3] < 0.0 && (naive.c[0] / naive.c[3]).abs() < 1.0,
        "naive projection must land on screen"
    );
    let mut st = Stats::default();
    for loose in [false, true] {
        check(&s, tri, loose, true, &mut st);
    }
    // The same triangle in front of the camera is drawn.
    let front = tri.map(|p| [p[0], p[1], -p[2]]);
    check(&s, front, true, false, &mut st);
    assert_eq!(st.drawn, 1);
}
