//! Property tests (proptest) of the 3D path at its extremes: the clipper's
//! output invariants for any input (NaN, ±inf, huge, `w → 0+`, `w < 0`); the
//! pipeline fed NaN and ±inf in every `f32` input (matrices, vertices,
//! lighting colours, near/far/fov, `w_ref`, viewport sizes); nothing from
//! behind the eye; depth exactly at near and far for far/near from 1.0001 to
//! 10^7; viewports from 1×1 to 4096×4096 drawn exactly, with bands of 1 row
//! and of the full frame.

use crate::props::{Tally, runner};
use crate::reference::{Coverage, spans_coverage};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::clip3d::{ClipPlanes, ClipVertex, clip_line, clip_triangle};
use microraster::depth::{Depth16, DepthBand, DepthFormat, DepthState};
use microraster::edge::{Cull, TriangleSpans};
use microraster::light::Lighting;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, PerspectiveCorrect, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, ClipRect, Error, Renderer};
use proptest::prelude::*;

/// An `f32` from the extremes or from a moderate range.
fn wild() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![
        4 => -4.0f32..4.0,
        1 => prop_oneof![Just(f32::NAN), Just(f32::INFINITY), Just(f32::NEG_INFINITY)],
        1 => prop_oneof![Just(0.0f32), Just(-0.0), Just(f32::MIN_POSITIVE), Just(1.0e-30), Just(-1.0e-30)],
        1 => prop_oneof![Just(f32::MAX), Just(f32::MIN), Just(f32::MAX / 16.0), Just(1.8e19), Just(-1.9e19)],
        1 => any::<u32>().prop_map(f32::from_bits),
    ]
}

/// Mostly a moderate value, sometimes an extreme one.
fn rare_wild() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![12 => -4.0f32..4.0, 1 => wild()]
}

/// A clip-space `w`: ordinary, tending to 0 from above, zero, negative.
fn clip_w() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![
        3 => 0.05f32..20.0,
        2 => (-45i32..-1).prop_map(|e| 2f32.powi(e)), // w → 0+
        1 => prop_oneof![Just(0.0f32), Just(-0.0)],
        2 => -20.0f32..-1.0e-6,
        1 => wild(),
    ]
}

fn planes() -> impl Strategy<Value = ClipPlanes> {
    prop_oneof![
        2 => Just(ClipPlanes::DEFAULT),
        1 => Just(ClipPlanes::NO_FAR),
        1 => wild().prop_map(|g| ClipPlanes::DEFAULT.with_guard_band(g)),
        1 => wild().prop_map(|w| ClipPlanes::DEFAULT.with_w_min(w)),
        1 => (1u32..4096, 1u32..4096, 0u32..9).prop_map(|(w, h, s)| ClipPlanes::for_viewport(w, h, s)),
    ]
}

/// The documented guarantees of a clipped vertex, evaluated in `T`.
fn vertex_ok<T: Scalar>(v: &[T; 4], p: ClipPlanes) -> bool {
    let w_min = T::from_f32(p.w_min());
    let w_min = if w_min > T::ZERO { w_min } else { T::from_f32(ClipPlanes::W_MIN) };
    let gw = T::from_f32(p.guard_band()) * v[3];
    v.iter().all(|c| c.is_finite())
        && v[3] >= w_min
        && v[2] >= T::ZERO
        && (!p.far() || v[2] <= v[3])
        && v[0] <= gw
        && -gw <= v[0]
        && v[1] <= gw
        && -gw <= v[1]
}

fn check_clip<T: Scalar>(
    pos: [[f32; 4]; 3],
    attr: [f32; 3],
    p: ClipPlanes,
    tally: &Tally,
) -> Result<(), TestCaseError> {
    let v: [ClipVertex<T, 1>; 3] =
        core::array::from_fn(|i| ClipVertex { pos: pos[i].map(T::from_f32), attr: [T::from_f32(attr[i])] });
    let invalid = pos.iter().flatten().chain(&attr).any(|c| !c.is_finite() || c.abs() > 1.8446744e19);
    let poly = clip_triangle(v, p);
    let n = poly.vertices().len();
    prop_assert!(n == 0 || (3..=10).contains(&n), "{} vertices", n);
    if invalid && T::from_f32(f32::NAN).to_f32().is_nan() {
        prop_assert!(poly.is_empty(), "invalid input not discarded");
        tally.add("invalid → empty");
    }
    for x in poly.vertices() {
        prop_assert!(vertex_ok(&x.pos, p), "vertex {:?} breaks the guarantees of {:?}", x.pos, p);
        prop_assert!(x.attr.iter().all(|a| a.is_finite()));
    }
    if pos.iter().all(|q| q[3] < 0.0) {
        prop_assert!(poly.is_empty(), "a triangle behind the eye survived");
        tally.add("behind → empty");
    }
    tally.add(if poly.is_empty() {
        "empty"
    } else if n == 3 {
        "3 vertices"
    } else {
        "clipped"
    });
    prop_assert_eq!(poly.triangles().count(), n.saturating_sub(2));
    // clip_line on the first edge: same guarantees.
    if let Some((a, b)) = clip_line(v[0], v[1], p) {
        prop_assert!(vertex_ok(&a.pos, p) && vertex_ok(&b.pos, p), "clip_line {:?} {:?}", a.pos, b.pos);
    }
    Ok(())
}

#[test]
fn prop_clipper_output_invariants() {
    let mild = (-4.0f32..4.0, -4.0f32..4.0, -0.5f32..1.5, clip_w())
        .prop_map(|(x, y, z, w)| [x * w.abs().max(1.0), y * w.abs().max(1.0), z * w, w]);
    let vert =
        prop_oneof![8 => mild, 1 => (wild(), wild(), wild(), clip_w()).prop_map(|(x, y, z, w)| [x, y, z, w])];
    let strat = ([vert.clone(), vert.clone(), vert], [rare_wild(), rare_wild(), rare_wild()], planes());
    for (name, fx) in [("f32", false), ("Fx", true)] {
        let tally = Tally::default();
        runner(6000)
            .run(&strat, |(pos, attr, p)| {
                if fx {
                    check_clip::<Fx>(pos, attr, p, &tally)
                } else {
                    check_clip::<f32>(pos, attr, p, &tally)
                }
            })
            .unwrap();
        tally.report(&format!("props3d: clipper invariants, {name}"));
        assert!(
            tally.get("clipped") >= 600
                && tally.get("behind → empty") >= 100
                && tally.get("3 vertices") >= 300,
            "{name}"
        );
        assert!(fx || tally.get("invalid → empty") >= 300, "{name}");
    }
}

const FW: usize = 48;
const FH: usize = 40;

/// Renders `bins` into an `FW × FH` frame with bands of `H` rows; every frame
/// pixel must be sent exactly once.
fn render<const S: u32, const H: usize>(
    bins: &[ScreenTriangle<S>],
    bg: Gray8,
    perspective: bool,
) -> Vec<Gray8> {
    let mut fb = crate::framebuffer::Framebuffer::new(FW as u32, FH as u32, Gray8::new(7));
    let mut band = Box::new(Band::<Gray8, FW, H>::new(bg));
    let mut depth = Box::new(DepthBand::<Depth16, FW, H>::new());
    let r = Renderer::new(FH as u32, bg);
    if perspective {
        r.render(
            Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            &mut fb,
        )
    } else {
        r.render(Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
    }
    .unwrap();
    assert!(fb.writes.iter().all(|&w| w == 1), "a frame pixel sent {:?} times", fb.writes.iter().max());
    fb.pixels
}

/// Drawn pixels: equal under two backgrounds (band height 1 vs full, too).
fn drawn<const S: u32>(bins: &[ScreenTriangle<S>], perspective: bool) -> Vec<bool> {
    let a = render::<S, 1>(bins, Gray8::new(3), perspective);
    let b = render::<S, FH>(bins, Gray8::new(250), perspective);
    let c = render::<S, FH>(bins, Gray8::new(3), perspective);
    assert!(a == c, "the image depends on the band height");
    a.iter().zip(&b).map(|(a, b)| a == b).collect()
}

#[derive(Debug, Clone)]
struct Scene {
    proj: [f32; 3], // fov, near, far
    raw_proj: Option<[[f32; 4]; 4]>,
    w_ref: f32,
    view: [f32; 9], // eye, target, up
    model: [[f32; 4]; 4],
    pos: [[f32; 3]; 4],
    light: Option<[f32; 5]>,
    size: (u32, u32),
}

fn scene() -> impl Strategy<Value = Scene> {
    let r = rare_wild;
    let m4 = [[r(), r(), r(), r()], [r(), r(), r(), r()], [r(), r(), r(), r()], [r(), r(), r(), r()]];
    let ident =
        Just([[1.0f32, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]);
    let sizes = prop_oneof![4 => Just((FW as u32, FH as u32)), 1 => (0u32..5000, 0u32..5000), 1 => Just((0, 0)), 1 => Just((4097, 1))];
    (
        (
            prop_oneof![8 => Just(1.0f32), 1 => wild()],
            prop_oneof![8 => Just(0.1f32), 1 => wild()],
            prop_oneof![8 => Just(50.0f32), 1 => wild()],
        ),
        prop_oneof![6 => Just(None), 1 => m4.clone().prop_map(Some)],
        prop_oneof![3 => Just(0.1f32), 1 => wild()],
        (
            prop_oneof![8 => Just([0.0f32, 0.0, 0.0]), 1 => [r(), r(), r()]],
            prop_oneof![8 => Just([0.0f32, 0.0, -1.0]), 1 => [r(), r(), r()]],
            prop_oneof![8 => Just([0.0f32, 1.0, 0.0]), 1 => [r(), r(), r()]],
        ),
        prop_oneof![4 => ident, 1 => m4],
        [[r(), r(), r()], [r(), r(), r()], [r(), r(), r()], [r(), r(), r()]],
        prop_oneof![1 => Just(None), 1 => [r(), r(), r(), r(), r()].prop_map(Some)],
        sizes,
    )
        .prop_map(|(proj, raw_proj, w_ref, (e, t, u), model, pos, light, size)| {
            // Vertices mostly in front of the camera.
            let pos = pos.map(|p| {
                [p[0], p[1], if p[2].is_finite() && p[2].abs() < 4.0 { -2.0 - p[2].abs() } else { p[2] }]
            });
            Scene {
                proj: proj.into(),
                raw_proj,
                w_ref,
                view: [e, t, u].concat().try_into().unwrap(),
                model,
                pos,
                light,
                size,
            }
        })
}

/// NaN and ±inf in every f32 input: typed errors where documented, never a
/// panic, never a pixel outside the viewport (= the frame here), and a
/// non-finite matrix or vertex discards what it touches.
#[test]
fn prop_pipeline_survives_nan_and_inf_everywhere() {
    // The strategy's value tree is deep: run on a thread with a larger stack.
    std::thread::Builder::new().stack_size(64 << 20).spawn(nan_and_inf_everywhere).unwrap().join().unwrap();
}

fn nan_and_inf_everywhere() {
    let tally = Tally::default();
    runner(1500)
        .run(&scene(), |sc| {
            let v = |k: usize| Vec3::<f32>::from_f32([sc.view[k], sc.view[k + 1], sc.view[k + 2]]);
            let view = match transform::look_at(v(0), v(3), v(6)) {
                Ok(m) => m,
                Err(e) => {
                    if sc.view.iter().any(|c| !c.is_finite()) {
                        prop_assert_eq!(e, Error::NonFiniteCoordinate);
                    }
                    tally.add("look_at error");
                    return Ok(());
                }
            };
            let (w, h) = sc.size;
            let p = match sc.raw_proj {
                None => Pipeline::<f32, 4>::perspective(view, sc.proj[0], sc.proj[1], sc.proj[2], w, h),
                Some(m) => Pipeline::new(view, Mat4::from_f32(m), sc.w_ref, w, h),
            };
            let mut p = match p {
                Ok(p) => p,
                Err(e) => {
                    let bad_size = !(1..=4096).contains(&w) || !(1..=4096).contains(&h);
                    if sc.raw_proj.is_none() && sc.proj.iter().any(|c| !c.is_finite()) {
                        prop_assert_eq!(e, Error::NonFiniteCoordinate);
                    } else if bad_size {
                        prop_assert!(matches!(
                            e,
                            Error::InvalidFrameSize | Error::InvalidParameter | Error::CoordinateOutOfRange
                        ));
                    }
                    tally.add("constructor error");
                    return Ok(());
                }
            };
            prop_assert!((1..=4096).contains(&w) && (1..=4096).contains(&h), "viewport {}×{} accepted", w, h);
            p.cull = Cull::None;
            if let Some(l) = sc.light {
                p = p.with_lighting(Lighting::new(l[0], Vec3::new(l[1], l[2], l[3]), l[4]));
            }
            let model = Mat4::from_f32(sc.model);
            let sphere = bounding_sphere(&sc.pos);
            let mesh = Mesh::new(&sc.pos, &[], &crate::ref3d::QUAD, sphere);
            let mut bins = heapless::Vec::<ScreenTriangle<4>, 32>::new();
            match p.draw_mesh(&mesh, &model, Gray8::new(200), &mut bins) {
                // A non-finite or unrepresentable mesh is rejected by validate.
                Ok(_)
                | Err(Error::InvalidParameter | Error::NonFiniteCoordinate | Error::CoordinateOutOfRange) => {
                }
                Err(e) => prop_assert!(false, "undocumented error {:?}", e),
            }
            let nan_matrix = sc
                .model
                .iter()
                .flatten()
                .chain(sc.raw_proj.iter().flatten().flatten())
                .any(|c| !c.is_finite());
            if nan_matrix {
                prop_assert!(bins.is_empty(), "a non-finite matrix produced triangles");
                tally.add("non-finite matrix → nothing");
            }
            if sc.pos.iter().flatten().any(|c| !c.is_finite())
                && sc.pos[0].iter().chain(&sc.pos[2]).any(|c| !c.is_finite())
            {
                // Vertices 0 and 2 are in both triangles of the quad.
                prop_assert!(bins.is_empty(), "a non-finite vertex produced triangles");
                tally.add("non-finite vertex → nothing");
            }
            if (w, h) == (FW as u32, FH as u32) {
                let d = drawn(&bins, false);
                tally.add(if d.contains(&true) { "drawn" } else { "nothing drawn" });
            } else {
                tally.add("other viewport");
            }
            Ok(())
        })
        .unwrap();
    tally.report("props3d: NaN/inf everywhere");
    for k in [
        "drawn",
        "non-finite matrix → nothing",
        "non-finite vertex → nothing",
        "constructor error",
        "look_at error",
    ] {
        assert!(tally.get(k) >= 20, "too few '{k}' cases");
    }
}

/// `w → 0+` and `w < 0` through the pipeline: a projection whose `z/w` is
/// 1/2 everywhere, so only the `w ≥ w_min` plane stops `w → 0+`. Triangles
/// entirely behind the eye draw nothing; the others draw only in front.
#[test]
fn prop_w_to_zero_and_negative() {
    let half = Mat4::from_rows([
        [1.0f32, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, -0.5, 0.0],
        [0.0, 0.0, -1.0, 0.0],
    ]);
    let vert = (-3.0f32..3.0, -3.0f32..3.0, clip_w()).prop_map(|(x, y, w)| [x, y, -w]); // w = −z_view
    let tally = Tally::default();
    let worst = std::cell::Cell::new(0.0f64);
    runner(1500)
        .run(&([vert.clone(), vert.clone(), vert], any::<bool>()), |(tri, persp)| {
            let mut p =
                Pipeline::<f32, 4>::new(Mat4::IDENTITY, half, ClipPlanes::W_MIN, FW as u32, FH as u32)
                    .unwrap();
            p.cull = Cull::None;
            p.shade = Shade::Gouraud;
            let mesh = Mesh::new(&tri, &[], &crate::ref3d::ONE_TRIANGLE, crate::ref3d::loose_sphere(&tri));
            let mut bins = heapless::Vec::<ScreenTriangle<4>, 16>::new();
            match p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(200), &mut bins) {
                Ok(_) => {}
                // `draw_mesh` validates the mesh: a bounding sphere too large
                // for f32 (|w| near f32::MAX) is a typed error, nothing drawn.
                Err(Error::NonFiniteCoordinate | Error::CoordinateOutOfRange) => {
                    tally.add("mesh rejected by validate");
                    return Ok(());
                }
                Err(e) => prop_assert!(false, "undocumented error {:?}", e),
            }
            // z/w = 1/2 exactly in the input. A vertex the clipper puts on
            // w = w_min keeps its interpolated z: d errs by up to about
            // 3·2^-24·(|z_a| + |z_b| + |w_a| + |w_b|)/w_min (the lerp's rounding
            // relative to w_min); elsewhere by a few ulp.
            let mag: f32 = tri.iter().map(|q| 1.5 * q[2].abs()).sum();
            let bound = 3.0 * f64::from(mag) / 16_777_216.0 / f64::from(ClipPlanes::W_MIN) + 1.0e-6;
            for t in &bins {
                for v in t.v {
                    let e = (f64::from(v.depth) / 4294967296.0 - 0.5).abs();
                    prop_assert!(e <= bound, "depth {} off by {} (bound {})", v.depth, e, bound);
                    worst.set(worst.get().max(e));
                }
            }
            let d = drawn(&bins, persp);
            let behind = tri.iter().all(|q| -q[2] <= 0.0);
            if behind {
                prop_assert!(!d.contains(&true) && bins.is_empty(), "drawn from behind the eye");
                tally.add("behind");
            } else if tri.iter().any(|q| -q[2] <= 0.0) {
                tally.add("crossing w = 0");
            }
            if tri.iter().any(|q| (0.0..1.0e-6).contains(&-q[2])) {
                tally.add("w → 0+");
            }
            tally.add(if d.contains(&true) { "drawn" } else { "empty" });
            Ok(())
        })
        .unwrap();
    tally.report("props3d: w → 0+ and w < 0");
    println!("props3d: w → 0+: worst depth error {:.2e}", worst.get());
    for k in ["behind", "crossing w = 0", "w → 0+", "drawn"] {
        assert!(tally.get(k) >= 30, "too few '{k}' cases");
    }
}

/// Depth exactly at near (code 0) and far (code MAX) and in between (the
/// f64 formula `d = f/(f − n)·(1 − n/z)` within the f32 vertex path's error,
/// about `4·2^-24·f/(f − n)` in `d`), for far/near from 1.0001 to 10^7; near
/// = far and near ≤ 0 are typed errors.
#[test]
fn prop_depth_near_far_ratios() {
    const W: usize = 8;
    const H: usize = 6;
    let strat = (-3.0f64..1.0, 1.0001f64.ln()..1.0e7f64.ln(), 0.0f64..=1.0);
    let worst = std::cell::Cell::new(0.0f64);
    runner(800)
        .run(&strat, |(ln_near, ln_ratio, t)| {
            let n = 10f64.powf(ln_near) as f32;
            let f = (f64::from(n) * ln_ratio.exp()) as f32;
            prop_assume!(f > n);
            prop_assert_eq!(transform::perspective(1.0f32, 1.0, n, n).err(), Some(Error::InvalidParameter));
            prop_assert_eq!(transform::perspective(1.0f32, 1.0, -n, f).err(), Some(Error::InvalidParameter));
            let mut p =
                Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, 1.0, n, f, W as u32, H as u32).unwrap();
            p.cull = Cull::None;
            p.shade = Shade::Flat;
            // z: exactly near, exactly far, or in between (log-spaced).
            let z = if t == 0.0 {
                n
            } else if t == 1.0 {
                f
            } else {
                (f64::from(n) * (f64::from(f) / f64::from(n)).powf(t)) as f32
            };
            let s = z * 2.0;
            let pos = [[-s, -s, -z], [s, -s, -z], [s, s, -z], [-s, s, -z]];
            let mesh = Mesh::new(&pos, &[], &crate::ref3d::QUAD, bounding_sphere(&pos));
            let mut bins = heapless::Vec::<ScreenTriangle<4>, 16>::new();
            p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(200), &mut bins).unwrap();
            let mut band = Band::<Gray8, W, H>::new(Gray8::new(0));
            let mut depth = DepthBand::<Depth16, W, H>::new();
            {
                let mut view = band.view(0, H, Gray8::new(0));
                for tri in &bins {
                    microraster::raster3d::draw_triangle(
                        tri,
                        &mut view,
                        &mut depth.rows_mut(H),
                        DepthState::LESS_EQUAL_WRITE,
                        Affine,
                    );
                }
            }
            let (nf, ff, zf) = (f64::from(n), f64::from(f), f64::from(z));
            let d = ff / (ff - nf) * (1.0 - nf / zf);
            let max = f64::from(Depth16::MAX);
            let bound = 1.0 + 4.0 * ff / (ff - nf) / 16_777_216.0 * max;
            for y in 0..H {
                for x in 0..W {
                    prop_assert!(
                        band.rows()[y][x] == Gray8::new(200),
                        "pixel ({}, {}) not drawn at z = {} ({}..{})",
                        x,
                        y,
                        z,
                        n,
                        f
                    );
                    let code = f64::from(depth.get(y, x).unwrap());
                    if z == n {
                        prop_assert_eq!(code, 0.0);
                    } else if z == f {
                        prop_assert_eq!(code, max);
                    }
                    let e = (code - d * max).abs();
                    prop_assert!(
                        e <= bound,
                        "code {} vs exact {} (bound {}) at z = {} in {}..{}",
                        code,
                        d * max,
                        bound,
                        z,
                        n,
                        f
                    );
                    worst.set(worst.get().max(e / bound));
                }
            }
            Ok(())
        })
        .unwrap();
    println!("props3d: depth at near/far, far/near 1.0001..1e7: worst error {:.2} of the bound", worst.get());
}

/// A quad exactly on the viewport (orthographic, NDC ±1) for viewports from
/// 1×1 to 4096×4096, anywhere on the frame: the drawn pixels are exactly
/// viewport ∩ frame, each covered by exactly one of the two triangles, for
/// bands of 1 row and of the full frame.
#[test]
fn prop_viewport_sizes_are_exact() {
    let dim = prop_oneof![4 => 1u32..=FW as u32, 1 => Just(4096u32), 1 => 1u32..=4096, 1 => Just(1u32)];
    let strat = (dim.clone(), dim, -20i32..FW as i32, -20i32..FH as i32, any::<bool>());
    let tally = Tally::default();
    runner(600)
        .run(&strat, |(w, h, ox, oy, fx)| {
            let frame = ClipRect::new(0, 0, FW as i32, FH as i32);
            let pos = [[-1.0f32, -1.0, -0.5], [1.0, -1.0, -0.5], [1.0, 1.0, -0.5], [-1.0, 1.0, -0.5]];
            let mesh = Mesh::new(&pos, &[], &crate::ref3d::QUAD, bounding_sphere(&pos));
            let mut bins = heapless::Vec::<ScreenTriangle<4>, 16>::new();
            if fx {
                let o = transform::orthographic(
                    -Fx::ONE,
                    Fx::ONE,
                    -Fx::ONE,
                    Fx::ONE,
                    Fx::from_f32(0.25),
                    Fx::ONE,
                )
                .unwrap();
                let mut p =
                    Pipeline::<Fx, 4>::new(Mat4::IDENTITY, o, Fx::ONE, w, h).unwrap().with_origin(ox, oy);
                p.cull = Cull::None;
                p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(200), &mut bins).unwrap();
            } else {
                let o = transform::orthographic(-1.0f32, 1.0, -1.0, 1.0, 0.25, 1.0).unwrap();
                let mut p =
                    Pipeline::<f32, 4>::new(Mat4::IDENTITY, o, 1.0, w, h).unwrap().with_origin(ox, oy);
                p.cull = Cull::None;
                p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(200), &mut bins).unwrap();
            }
            let vp = ClipRect::new(
                ox.max(0),
                oy.max(0),
                (ox + w.min(8192) as i32).min(FW as i32),
                (oy + h.min(8192) as i32).min(FH as i32),
            );
            // Exactly once, per triangle, against the exact spans.
            let mut once = Coverage::new(frame);
            for t in &bins {
                let c = spans_coverage(TriangleSpans::new(t.v.map(|v| v.pos), frame, Cull::None), frame);
                for (x, y) in c.pixels() {
                    prop_assert!(!once.set(x, y), "pixel ({}, {}) covered twice", x, y);
                }
            }
            let d = drawn(&bins, false);
            for y in 0..FH as i32 {
                for x in 0..FW as i32 {
                    let want = vp.contains(x, y);
                    prop_assert_eq!(
                        d[(y * FW as i32 + x) as usize],
                        want,
                        "pixel ({}, {}), viewport {}×{} at ({}, {})",
                        x,
                        y,
                        w,
                        h,
                        ox,
                        oy
                    );
                    prop_assert_eq!(once.get(x, y), want);
                }
            }
            tally.add(if vp.is_empty() {
                "off frame"
            } else if w == 4096 || h == 4096 {
                "4096"
            } else {
                "on frame"
            });
            tally.add(if w == 1 || h == 1 { "1 px" } else { "wider" });
            Ok(())
        })
        .unwrap();
    tally.report("props3d: viewport sizes");
    assert!(tally.get("on frame") >= 200 && tally.get("4096") >= 50 && tally.get("1 px") >= 20);
}
