//! Issue 13 (integrity): the `Fx` vertex path either makes the f32 path's
//! decision (drawn or not) or returns a typed error; regression tests for
//! each finding, and a property test over every rendering path.

use crate::framebuffer::Framebuffer;
use crate::props::{Tally, runner};
use crate::ref3d::ONE_TRIANGLE;
use crate::reference::{Coverage, spans_coverage};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::blit::Blitter;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::{Cull, Span, TriangleSpans};
use microraster::light::Lighting;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{Mesh, ValidMesh, bounding_sphere};
use microraster::pipeline::{Pipeline, VertexCache};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::render::{PerBand3d, Triangles3d};
use microraster::{Band, ClipRect, Error, RenderError, Renderer};
use proptest::prelude::*;

const W: usize = 64;
const H: usize = 48;

/// The image of `mesh` drawn by `p`: the whole frame's bins at once
/// (`Triangles3d`), and the vertex stage once per 8-row band
/// (`PerBand3d`); `Err` is the first error of either.
fn both_ways<T: Scalar>(
    p: &Pipeline<T, 4>,
    mesh: &Mesh<'_>,
    model: &Mat4<T>,
) -> Result<(Vec<Gray8>, Vec<Gray8>), Error> {
    let bg = Gray8::new(0);
    let mut bins = heapless::Vec::<ScreenTriangle<4>, 64>::new();
    p.draw_mesh(mesh, model, Gray8::new(255), &mut bins)?;
    let mut fb = Framebuffer::new(W as u32, H as u32, bg);
    let mut band = Band::<Gray8, W, 8>::new(bg);
    let mut depth = DepthBand::<Depth16, W, 8>::new();
    Renderer::new(H as u32, bg)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
        .unwrap();
    let whole = fb.pixels;
    let mut fb = Framebuffer::new(W as u32, H as u32, bg);
    let mut pb = *p;
    let mut failed = None;
    let r = Renderer::new(H as u32, bg).render(
        PerBand3d::new(&mut bins, &mut depth, DepthState::LESS_WRITE, Affine, |y0, y1, bins| {
            pb.rows = Some((y0, y1 - 1));
            pb.draw_mesh(mesh, model, Gray8::new(255), bins).map(|_| ()).inspect_err(|e| failed = Some(*e))
        }),
        &mut band,
        &mut fb,
    );
    if let Some(e) = failed {
        return Err(e);
    }
    r.unwrap();
    Ok((whole, fb.pixels))
}

fn lit(img: &[Gray8]) -> usize {
    img.iter().filter(|&&c| c != Gray8::new(0)).count()
}

/// Finding 1: with `Pipeline::rows` set, `Band::sphere_touches` evaluated
/// `plane · centre` and `r·|plane|` in `Fx`; for a mesh with a far vertex
/// (here an unused one, 10^4 away) seen through a narrow field of view both
/// saturated and the band test rejected a visible triangle in some bands.
/// The three scenes come from a random search (seed 13) over 20,000 scenes;
/// all three failed before the fix (51 of 57, 1,424 of 2,905 and 656 of 803
/// pixels per band), none fails after.
#[test]
fn fx_per_band_keeps_a_visible_mesh_with_a_far_vertex() {
    type Case = ([f32; 3], [f32; 3], f32, f32, f32, [[f32; 3]; 4]);
    let cases: [Case; 3] = [
        (
            [50.944225, -36.237503, -6.0511355],
            [3.667817, -2.4976797, -1.9806851],
            0.24304354,
            0.7856157,
            106.93934,
            [
                [-0.21659708, -4.4719315, 2.0141978],
                [5.9502826, -2.5078812, 1.3317295],
                [1.4870508, 0.3111515, -0.0958606],
                [10230.566, 10160.271, -3411.054],
            ],
        ),
        (
            [-13.07493, -31.888433, 9.389813],
            [1.7352806, 1.6788731, -0.3412027],
            0.20478038,
            1.8732128,
            390.5836,
            [
                [11.588312, -6.867194, -16.540854],
                [3.0180435, 2.82765, 12.462788],
                [-10.442001, 12.051107, 4.8476725],
                [-3597.534, 7330.6665, 7905.634],
            ],
        ),
        (
            [1.4741801, -20.759027, -45.069576],
            [2.112519, -2.5069482, -2.7914667],
            0.36951548,
            0.07862456,
            4635.2407,
            [
                [52.755833, 34.26031, -25.848091],
                [-70.55307, -20.205688, 78.6634],
                [-60.485542, -39.366463, 57.38846],
                [-7765.2383, 9314.354, -10005.371],
            ],
        ),
    ];
    for (eye, tgt, fov, near, far, pos) in cases {
        let mesh = Mesh::new(&pos, &[], &ONE_TRIANGLE, bounding_sphere(&pos));
        let up = [0.0, 1.0, 0.0];
        let view =
            transform::look_at(Vec3::<Fx>::from_f32(eye), Vec3::from_f32(tgt), Vec3::from_f32(up)).unwrap();
        let f = Fx::from_f32;
        let mut p =
            Pipeline::<Fx, 4>::perspective(view, f(fov), f(near), f(far), W as u32, H as u32).unwrap();
        p.cull = Cull::None;
        let (whole, per_band) = both_ways(&p, &mesh, &Mat4::IDENTITY).unwrap();
        // The f32 path's decision: drawn.
        let view =
            transform::look_at(Vec3::<f32>::from_f32(eye), Vec3::from_f32(tgt), Vec3::from_f32(up)).unwrap();
        let mut q = Pipeline::<f32, 4>::perspective(view, fov, near, far, W as u32, H as u32).unwrap();
        q.cull = Cull::None;
        let (reference, _) = both_ways(&q, &mesh, &Mat4::IDENTITY).unwrap();
        assert!(lit(&reference) > 0 && lit(&whole) > 0, "eye {eye:?}: the triangle is visible");
        assert_eq!(lit(&per_band), lit(&whole), "eye {eye:?}: pixels drawn per band / per frame");
        assert!(per_band == whole, "eye {eye:?}: per band differs from per frame");
    }
}

/// Finding 2: mesh coordinates and matrix entries beyond ±32768 saturated
/// silently in `Fx`, and a saturated `z` equal to a saturated `w` sits on
/// the far plane: geometry far beyond it was drawn with `Ok`. Now the `Fx`
/// path returns `CoordinateOutOfRange` (the f32 path draws nothing).
#[test]
fn fx_geometry_beyond_its_range_is_an_error_not_a_saturated_image() {
    let f = Fx::from_f32;
    let mut p =
        Pipeline::<Fx, 4>::perspective(Mat4::IDENTITY, f(1.0), f(0.5), f(20.0), W as u32, H as u32).unwrap();
    p.cull = Cull::None;
    let mut q = Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, 1.0, 0.5, 20.0, W as u32, H as u32).unwrap();
    q.cull = Cull::None;
    // A quad seen at a constant angle from z = −4·10^4 to −10^18, far = 20.
    let quad = [
        [-2.0e4f32, -2.0e4, -4.0e4],
        [2.0e4, -2.0e4, -4.0e4],
        [5.0e17, 5.0e17, -1.0e18],
        [-5.0e17, 5.0e17, -1.0e18],
    ];
    let idx = [[0u16, 1, 2], [0, 2, 3]];
    let mesh = Mesh::new(&quad, &[], &idx, bounding_sphere(&quad));
    let (a, b) = both_ways(&q, &mesh, &Mat4::IDENTITY).unwrap();
    assert_eq!((lit(&a), lit(&b)), (0, 0), "f32: beyond the far plane");
    assert_eq!(both_ways(&p, &mesh, &Mat4::IDENTITY).err(), Some(Error::CoordinateOutOfRange), "Fx quad");
    // A triangle in view, scaled by 10^30 (f32: far beyond the far plane).
    let tri = [[-1.0f32, -1.0, -3.0], [1.0, -1.0, -3.0], [0.0, 1.0, -3.0]];
    let mesh = Mesh::new(&tri, &[], &ONE_TRIANGLE, bounding_sphere(&tri));
    let big = [[1e30, 0.0, 0.0, 0.0], [0.0, 1e30, 0.0, 0.0], [0.0, 0.0, 1e30, 0.0], [0.0, 0.0, 0.0, 1.0]];
    let (a, b) = both_ways(&q, &mesh, &Mat4::from_f32(big)).unwrap();
    assert_eq!((lit(&a), lit(&b)), (0, 0), "f32: scaled beyond the far plane");
    assert_eq!(
        both_ways(&p, &mesh, &Mat4::from_f32(big)).err(),
        Some(Error::CoordinateOutOfRange),
        "Fx model × 10^30"
    );
    // Just inside the range: drawn, the same way per band.
    let near_limit = [[-1.0f32, -1.0, -3.0], [1.0, -1.0, -3.0], [0.0, 1.0, -3.0], [0.0, 0.0, -19000.0]];
    let mesh = Mesh::new(&near_limit, &[], &ONE_TRIANGLE, bounding_sphere(&near_limit));
    let (a, b) = both_ways(&p, &mesh, &Mat4::IDENTITY).unwrap();
    assert!(lit(&a) > 100 && a == b, "a far unused vertex inside the range");
}

/// Finding 3: `Pipeline::perspective` with a zero width returned
/// `InvalidParameter` (from the aspect ratio); `Pipeline::new` and
/// docs/limits.md say `InvalidFrameSize`.
#[test]
fn perspective_with_a_bad_viewport_is_invalid_frame_size() {
    for (w, h) in [(0, 48), (64, 0), (0, 0), (4097, 48), (64, 4097), (u32::MAX, 1)] {
        let r = Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, 1.0, 0.5, 20.0, w, h);
        assert_eq!(r.err(), Some(Error::InvalidFrameSize), "f32 {w}×{h}");
        let f = Fx::from_f32;
        let r = Pipeline::<Fx, 4>::perspective(Mat4::IDENTITY, f(1.0), f(0.5), f(20.0), w, h);
        assert_eq!(r.err(), Some(Error::InvalidFrameSize), "Fx {w}×{h}");
    }
}

/// A blitter that keeps the default span methods and records its pixels.
struct Recorder(Vec<(i32, i32)>);
impl Blitter<Gray8> for Recorder {
    fn clip(&self) -> ClipRect {
        ClipRect::new(0, 0, 4096, 4096)
    }
    fn set_pixel(&mut self, x: i32, y: i32, _: Gray8) {
        self.0.push((x, y));
    }
}

/// Finding 4: the default `fill_span`/`shade_span` added `span.x + i`
/// unchecked: a panic in debug builds, `set_pixel(i32::MIN, …)` in release.
#[test]
fn default_span_methods_stop_at_i32_max() {
    for len in [1u32, 2, 1000, u32::MAX] {
        let span = Span { y: 3, x: i32::MAX, len };
        let r = std::panic::catch_unwind(|| {
            let mut b = Recorder(Vec::new());
            b.fill_span(span, Gray8::new(1));
            let mut c = Recorder(Vec::new());
            c.shade_span(span, std::iter::repeat(Gray8::new(2)));
            (b.0, c.0)
        });
        let (a, b) = r.unwrap_or_else(|_| panic!("default span methods panicked, len {len}"));
        assert_eq!(a, [(i32::MAX, 3)], "fill_span, len {len}");
        assert_eq!(b, [(i32::MAX, 3)], "shade_span, len {len}");
    }
    // Ordinary spans are unchanged; an empty one writes nothing.
    let mut b = Recorder(Vec::new());
    b.fill_span(Span { y: 0, x: -2, len: 3 }, Gray8::new(1));
    b.fill_span(Span { y: 1, x: i32::MIN, len: 0 }, Gray8::new(1));
    assert_eq!(b.0, [(-2, 0), (-1, 0), (0, 0)]);
}

/// Finding 5: ambient = diffuse = `f32::MAX` overflowed to infinity and was
/// clamped to black (Fx saturates to full intensity); zero, NaN and infinite
/// light directions were accepted silently. Now: full intensity, and typed
/// errors from `draw_mesh`.
#[test]
fn lighting_overflow_is_full_intensity_and_bad_directions_are_errors() {
    let tri = [[-1.0f32, -1.0, -3.0], [1.0, -1.0, -3.0], [0.0, 1.0, -3.0]];
    let mesh = Mesh::new(&tri, &[], &ONE_TRIANGLE, bounding_sphere(&tri));
    let towards = Vec3::new(0.0f32, 0.0, 1.0);
    let p = Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, 1.0, 0.5, 20.0, W as u32, H as u32).unwrap();
    let f = Fx::from_f32;
    let pf =
        Pipeline::<Fx, 4>::perspective(Mat4::IDENTITY, f(1.0), f(0.5), f(20.0), W as u32, H as u32).unwrap();
    let colour = |img: &[Gray8]| img.iter().copied().filter(|&c| c != Gray8::new(0)).max();
    let (a, _) =
        both_ways(&p.with_lighting(Lighting::new(f32::MAX, towards, f32::MAX)), &mesh, &Mat4::IDENTITY)
            .unwrap();
    let l = Lighting::new(f(f32::MAX), Vec3::from_f32([0.0, 0.0, 1.0]), f(f32::MAX));
    let (b, _) = both_ways(&pf.with_lighting(l), &mesh, &Mat4::IDENTITY).unwrap();
    assert_eq!(colour(&b), Some(Gray8::new(255)), "Fx saturates to full intensity");
    assert_eq!(colour(&a), Some(Gray8::new(255)), "f32 overflow to infinity: full intensity, as Fx");
    for (dir, err) in [
        ([0.0f32, 0.0, 0.0], Error::InvalidParameter),
        ([f32::NAN, 0.0, 1.0], Error::NonFiniteCoordinate),
        ([0.0, f32::INFINITY, 1.0], Error::NonFiniteCoordinate),
    ] {
        let q = p.with_lighting(Lighting::new(0.2, Vec3::from_f32(dir), 0.8));
        assert_eq!(both_ways(&q, &mesh, &Mat4::IDENTITY).err(), Some(err), "f32 direction {dir:?}");
    }
    let q = pf.with_lighting(Lighting::new(f(0.2), Vec3::from_f32([0.0; 3]), f(0.8)));
    assert_eq!(
        both_ways(&q, &mesh, &Mat4::IDENTITY).err(),
        Some(Error::InvalidParameter),
        "Fx zero direction"
    );
    for bad in [f32::NAN, f32::INFINITY] {
        let q = p.with_lighting(Lighting::new(bad, towards, 0.5));
        assert_eq!(
            both_ways(&q, &mesh, &Mat4::IDENTITY).err(),
            Some(Error::NonFiniteCoordinate),
            "ambient {bad}"
        );
    }
}

/// Finding 6, measured (documented in the README's guarantees and
/// docs/limits.md; no behaviour change): a flat grid, clipped, seen at
/// random angles. Snapping can invert a near-degenerate sliver; with
/// culling off the inverted sliver and its neighbours then cover a few
/// pixels twice. Counts pixels covered more than once, culling off and on.
#[test]
fn flat_grid_double_coverage_rate() {
    const N: usize = 12; // cells per side
    let mut pos = Vec::new();
    for j in 0..=N {
        for i in 0..=N {
            let (u, v) = (i as f32 / N as f32 - 0.5, j as f32 / N as f32 - 0.5);
            pos.push([u * 40.0, 0.0, v * 40.0]);
        }
    }
    let mut idx = Vec::new();
    for j in 0..N {
        for i in 0..N {
            let k = (j * (N + 1) + i) as u16;
            let n = (N + 1) as u16;
            idx.push([k, k + n, k + 1]);
            idx.push([k + 1, k + n, k + n + 1]);
        }
    }
    let mesh = Mesh::new(&pos, &[], &idx, bounding_sphere(&pos));
    let frame = ClipRect::new(0, 0, W as i32, H as i32);
    let mut rng = crate::reference::Rng::new(6);
    let (mut scenes, mut pixels, mut twice_off, mut twice_on, mut scenes_off) = (0, 0, 0, 0, 0);
    while scenes < 1500 {
        let eye = [
            rng.uniform(-30.0, 30.0) as f32,
            rng.log_uniform(0.05, 40.0) as f32,
            rng.uniform(-30.0, 30.0) as f32,
        ];
        let tgt = [rng.uniform(-20.0, 20.0) as f32, 0.0, rng.uniform(-20.0, 20.0) as f32];
        let Ok(view) =
            transform::look_at(Vec3::from_f32(eye), Vec3::from_f32(tgt), Vec3::from_f32([0.0, 1.0, 0.0]))
        else {
            continue;
        };
        let mut p = Pipeline::<f32, 4>::perspective(view, 1.2, 0.1, 100.0, W as u32, H as u32).unwrap();
        let mut counts = [0usize; 2];
        for (c, cull) in [Cull::None, Cull::Clockwise].into_iter().enumerate() {
            // Seen from above the plane's front faces are counter-clockwise.
            p.cull = if eye[1] > 0.0 { cull } else { Cull::None };
            let mut bins = heapless::Vec::<ScreenTriangle<4>, 2048>::new();
            p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(255), &mut bins).unwrap();
            let mut once = Coverage::new(frame);
            for t in &bins {
                for (x, y) in
                    spans_coverage(TriangleSpans::new(t.v.map(|v| v.pos), frame, Cull::None), frame).pixels()
                {
                    if once.set(x, y) {
                        counts[c] += 1;
                    } else if c == 0 {
                        pixels += 1;
                    }
                }
            }
        }
        twice_off += counts[0];
        twice_on += counts[1];
        scenes_off += usize::from(counts[0] > 0);
        scenes += 1;
    }
    println!(
        "flat grid: {scenes} scenes, {pixels} pixels covered; culling off: {twice_off} covered twice \
         ({scenes_off} scenes); culling on: {twice_on}"
    );
    assert!(pixels > 1_000_000, "the grid covers most of the view");
    // The documented rate: at most 1 in 10^4 pixels, culling off.
    assert!(twice_off * 10_000 <= pixels, "{twice_off} of {pixels} pixels covered twice");
}

// ---------------------------------------------------------------------------
// Property: every rendering path draws the same scene.

const PW: usize = 48;
const PH: usize = 40;
const PBINS: usize = 256;

/// A random clipped scene: a camera anywhere within ±10^4, far/near up to
/// 10^5, a few triangles around the target, and sometimes vertices 10^3 to
/// 10^6 away (beyond the `Fx` range), used or unused.
#[derive(Debug, Clone)]
struct PScene {
    eye: [f32; 3],
    target: [f32; 3],
    fov: f32,
    near: f32,
    far: f32,
    pos: Vec<[f32; 3]>,
    idx: Vec<[u16; 3]>,
    model: Option<(f32, [f32; 3])>, // rotation about y, translation
    cull: Cull,
}

fn pscene() -> impl Strategy<Value = PScene> {
    let mag = |lo: f64, hi: f64| (lo.ln()..hi.ln()).prop_map(|l| l.exp() as f32);
    let signed =
        move |lo: f64, hi: f64| (mag(lo, hi), any::<bool>()).prop_map(|(m, s)| if s { -m } else { m });
    let v3 = move |lo: f64, hi: f64| [signed(lo, hi), signed(lo, hi), signed(lo, hi)];
    let far_vertex = prop_oneof![
        3 => v3(1.0e3, 1.0e4),
        1 => v3(3.3e4, 1.0e6),
    ];
    (
        (prop_oneof![2 => v3(0.5, 64.0), 1 => v3(64.0, 1.0e4)], [-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0]),
        (0.2f32..2.8, mag(0.01, 10.0), mag(2.0, 1.0e5)),
        (mag(0.02, 5.0), prop::collection::vec([-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0], 3..6)),
        prop_oneof![2 => Just(None), 1 => far_vertex.prop_map(Some)],
        prop::collection::vec([0u16..8, 0u16..8, 0u16..8], 1..5),
        0u8..3,
        prop_oneof![2 => Just(None), 1 => (-4.0f32..4.0, [-5.0f32..5.0, -5.0f32..5.0, -5.0f32..5.0]).prop_map(Some)],
        prop_oneof![Just(Cull::None), Just(Cull::Clockwise), Just(Cull::CounterClockwise)],
    )
        .prop_map(|((eye, target), (fov, near, ratio), (size, local), far_v, idx, far_use, model, cull)| {
            // Sized relative to the distance from the eye, so that most scenes
            // draw something.
            let dist = (0..3).map(|k| (eye[k] - target[k]).powi(2)).sum::<f32>().sqrt();
            let size = size * dist.max(0.5);
            let mut pos: Vec<[f32; 3]> =
                local.iter().map(|p| [0, 1, 2].map(|k| target[k] + p[k] * size)).collect();
            let n = pos.len() as u16;
            let mut idx: Vec<[u16; 3]> = idx.iter().map(|t| t.map(|i| i % n)).collect();
            if let Some(v) = far_v {
                pos.push(v);
                // 0: unused; 1: one triangle reaches it; 2: two do.
                for k in 0..far_use.min(2) {
                    idx.push([k as u16, n, (k as u16 + 1) % n]);
                }
            }
            PScene { eye, target, fov, near, far: near * ratio, pos, idx, model, cull }
        })
}

/// The image of one path (`Err`: its error), with the frame's pixels sent
/// exactly once.
type Img = Result<Vec<Gray8>, Error>;

fn frame_of(f: impl FnOnce(&mut Framebuffer<Gray8>) -> Result<(), Error>) -> Img {
    let mut fb = Framebuffer::new(PW as u32, PH as u32, Gray8::new(0));
    f(&mut fb)?;
    assert!(fb.writes.iter().all(|&w| w == 1), "a frame pixel sent {:?} times", fb.writes.iter().max());
    Ok(fb.pixels)
}

fn binned<const BH: usize>(bins: &[ScreenTriangle<4>]) -> Img {
    frame_of(|fb| {
        let mut band = Box::new(Band::<Gray8, PW, BH>::new(Gray8::new(0)));
        let mut depth = Box::new(DepthBand::<Depth16, PW, BH>::new());
        Renderer::new(PH as u32, Gray8::new(0))
            .render(Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, fb)
            .map_err(|_| Error::InvalidParameter)
    })
}

fn per_band<T: Scalar, const BH: usize>(
    p: &Pipeline<T, 4>,
    mesh: &ValidMesh<'_>,
    model: &Mat4<T>,
    cached: bool,
) -> Img {
    frame_of(|fb| {
        let mut band = Box::new(Band::<Gray8, PW, BH>::new(Gray8::new(0)));
        let mut depth = Box::new(DepthBand::<Depth16, PW, BH>::new());
        let mut bins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
        let mut cache = Box::new(VertexCache::<T, 4, 8>::new());
        let mut pb = *p;
        let r = Renderer::new(PH as u32, Gray8::new(0)).render(
            PerBand3d::new(&mut bins, &mut depth, DepthState::LESS_WRITE, Affine, |y0, y1, bins| {
                pb.rows = Some((y0, y1 - 1));
                if cached {
                    pb.draw_valid_mesh_cached(mesh, model, Gray8::new(200), &mut cache, bins).map(|_| ())
                } else {
                    pb.draw_valid_mesh(mesh, model, Gray8::new(200), bins).map(|_| ())
                }
            }),
            &mut band,
            fb,
        );
        match r {
            Ok(()) => Ok(()),
            Err(RenderError::Input(e)) => Err(e),
            Err(RenderError::Target(_)) => unreachable!(),
        }
    })
}

/// Every path of one numeric type: the images (or errors) must all be equal.
/// Returns the image and, for comparing f32 with `Fx`, the image without
/// the far plane and without depth test (see `prop_every_path_…`).
fn every_path<T: Scalar>(
    sc: &PScene,
    conv: impl Fn(f32) -> Result<T, Error>,
) -> Result<(Vec<Gray8>, Vec<Gray8>), Error> {
    let v = |a: [f32; 3]| -> Result<Vec3<T>, Error> { Ok(Vec3::new(conv(a[0])?, conv(a[1])?, conv(a[2])?)) };
    let view = transform::look_at(v(sc.eye)?, v(sc.target)?, v([0.0, 1.0, 0.0])?)?;
    let mut p = Pipeline::<T, 4>::perspective(
        view,
        conv(sc.fov)?,
        conv(sc.near)?,
        conv(sc.far)?,
        PW as u32,
        PH as u32,
    )?;
    p.cull = sc.cull;
    let model = match sc.model {
        None => Mat4::IDENTITY,
        Some((a, t)) => transform::translation(v(t)?) * transform::rotation_y(conv(a)?),
    };
    let mesh = ValidMesh::new(Mesh::new(&sc.pos, &[], &sc.idx, bounding_sphere(&sc.pos)))?;
    let mut bins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
    let whole = p.draw_valid_mesh(&mesh, &model, Gray8::new(200), &mut bins).map(|_| ());
    let mut cbins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
    let mut cache = Box::new(VertexCache::<T, 4, 8>::new());
    let cached = p.draw_valid_mesh_cached(&mesh, &model, Gray8::new(200), &mut cache, &mut cbins).map(|_| ());
    assert_eq!(whole, cached, "cached vertex stage: another result");
    let images = [
        whole.and_then(|_| binned::<PH>(&bins)),
        whole.and_then(|_| binned::<1>(&bins)),
        whole.and_then(|_| binned::<3>(&bins)),
        whole.and_then(|_| binned::<16>(&bins)),
        cached.and_then(|_| binned::<PH>(&cbins)),
        cached.and_then(|_| binned::<1>(&cbins)),
        cached.and_then(|_| binned::<3>(&cbins)),
        cached.and_then(|_| binned::<16>(&cbins)),
        per_band::<T, 1>(&p, &mesh, &model, false),
        per_band::<T, 3>(&p, &mesh, &model, false),
        per_band::<T, 16>(&p, &mesh, &model, false),
        per_band::<T, PH>(&p, &mesh, &model, false),
        per_band::<T, 1>(&p, &mesh, &model, true),
        per_band::<T, 3>(&p, &mesh, &model, true),
        per_band::<T, 16>(&p, &mesh, &model, true),
        per_band::<T, PH>(&p, &mesh, &model, true),
    ];
    const NAMES: [&str; 16] = [
        "binned, full-frame band",
        "binned, 1-row bands",
        "binned, 3-row bands",
        "binned, 16-row bands",
        "cached, full-frame band",
        "cached, 1-row bands",
        "cached, 3-row bands",
        "cached, 16-row bands",
        "per band, 1 row",
        "per band, 3 rows",
        "per band, 16 rows",
        "per band, full frame",
        "per band (cached), 1 row",
        "per band (cached), 3 rows",
        "per band (cached), 16 rows",
        "per band (cached), full frame",
    ];
    for (img, name) in images.iter().zip(NAMES).skip(1) {
        if img != &images[0] {
            let n = |i: &Img| i.as_ref().map(|i| lit(i)).map_err(|e| *e);
            panic!("{name}: {:?} pixels, binned full frame: {:?}", n(img), n(&images[0]));
        }
    }
    let mut open = p;
    open.clip = open.clip.with_far(false);
    let mut bins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
    open.draw_valid_mesh(&mesh, &model, Gray8::new(200), &mut bins)?;
    let cross = frame_of(|fb| {
        let mut band = Box::new(Band::<Gray8, PW, 16>::new(Gray8::new(0)));
        let mut depth = Box::new(DepthBand::<Depth16, PW, 16>::new());
        Renderer::new(PH as u32, Gray8::new(0))
            .render(Triangles3d::new(&bins, &mut depth, DepthState::DISABLED, Affine), &mut band, fb)
            .map_err(|_| Error::InvalidParameter)
    })?;
    Ok((images[0].clone()?, cross))
}

/// A pixel where the two images differ must lie within one pixel of an edge
/// of both: a neighbour where `reference` has the value `other` has there,
/// or where `other` itself changes (a sliver a pixel wide may appear or
/// vanish: the `Fx` vertex error is below half a pixel, docs/limits.md). A
/// triangle dropped or added whole fails this.
fn within_a_pixel(reference: &[Gray8], other: &[Gray8]) -> Option<(usize, usize)> {
    let on = |img: &[Gray8], x: i32, y: i32| {
        (0..PW as i32).contains(&x)
            && (0..PH as i32).contains(&y)
            && img[y as usize * PW + x as usize] != Gray8::new(0)
    };
    for y in 0..PH as i32 {
        for x in 0..PW as i32 {
            let want = on(other, x, y);
            if on(reference, x, y) != want
                && !(-1..=1).any(|dy| {
                    (-1..=1).any(|dx| {
                        let (qx, qy) = (x + dx, y + dy);
                        (0..PW as i32).contains(&qx)
                            && (0..PH as i32).contains(&qy)
                            && (on(reference, qx, qy) == want || on(other, qx, qy) != want)
                    })
                })
            {
                return Some((x as usize, y as usize));
            }
        }
    }
    None
}

/// 5,000 random clipped scenes (cameras within ±10^4, far/near up to 10^5,
/// coordinates up to 10^4 and beyond the `Fx` range) through every path:
/// binned and cached, each with bands of 1, 3, 16 and 40 rows, and per band
/// (1, 3, 16 and 40 rows), with and without the vertex cache, in f32 and in
/// `Fx`. Within a numeric type every path
/// gives the same image or the same error; `Fx` fails only with
/// `CoordinateOutOfRange` (16.16 cannot hold a value) or where f32 fails, and
/// otherwise draws what f32 draws to within a pixel. That comparison is made
/// without the far plane and depth test: `Fx` holds the projection's
/// `far/(near − far)` to 2^-16, which moves its far plane by a relative
/// `2^-16·far/near` (docs/limits.md), so near the far plane the two paths
/// may decide differently (counted, not failed).
#[test]
fn prop_every_path_draws_the_same_scene() {
    std::thread::Builder::new().stack_size(64 << 20).spawn(every_path_prop).unwrap().join().unwrap();
}

fn every_path_prop() {
    let tally = Tally::default();
    runner(5000)
        .run(&pscene(), |sc| {
            let a = every_path::<f32>(&sc, Ok);
            let b = every_path::<Fx>(&sc, Fx::try_from_f32);
            match (&a, &b) {
                (Ok((ia, a)), Ok((ib, b))) => {
                    if lit(ia) != lit(ib) {
                        tally.add("depth or far plane decides differently");
                    }
                    tally.add(if lit(a) > 0 {
                        "both drawn"
                    } else if lit(b) > 0 {
                        "Fx only"
                    } else {
                        "neither"
                    });
                    if a != b {
                        tally.add("Fx ≠ f32 (edge pixels)");
                    }
                    if let Some(at) = within_a_pixel(a, b) {
                        prop_assert!(
                            false,
                            "Fx differs from f32 by more than a pixel at {:?} ({} vs {} pixels)",
                            at,
                            lit(b),
                            lit(a)
                        );
                    }
                    if let Some(at) = within_a_pixel(b, a) {
                        prop_assert!(
                            false,
                            "f32 differs from Fx by more than a pixel at {:?} ({} vs {} pixels)",
                            at,
                            lit(a),
                            lit(b)
                        );
                    }
                }
                (Ok(_), Err(Error::CoordinateOutOfRange)) => tally.add("Fx out of range"),
                (Err(e), Err(f)) => {
                    prop_assert!(e == f || *f == Error::CoordinateOutOfRange, "f32 {:?}, Fx {:?}", e, f);
                    tally.add("both errors");
                }
                _ => prop_assert!(
                    false,
                    "f32 {:?} but Fx {:?}",
                    a.as_ref().map(|i| lit(&i.1)),
                    b.as_ref().map(|i| lit(&i.1))
                ),
            }
            Ok(())
        })
        .unwrap();
    tally.report("integrity: every path");
    for k in ["both drawn", "neither", "Fx out of range"] {
        assert!(tally.get(k) >= 30, "too few '{k}' cases");
    }
}
