extern crate std;
use super::reference::*;
use super::*;
use crate::math::Fx;
use crate::math::mat::tests::{F32, FX, Path};
use crate::math::vec::tests::{Exact, Rng, U};
use std::println;

#[test]
fn sin_cos_within_the_bound_the_references_assume() {
    // `Path::sc`: f32 sin/cos (scalar.rs) err by < 2e-7 + 1e-10·|a|; the
    // constructors see |a| ≤ 2π here, so 2.1e-7. Fx: 0.53u (scalar.rs).
    let (mut worst, mut n) = ([0f64; 2], 0);
    for i in -100_000..=100_000 {
        let a = i as f32 * 6.3e-5; // ±6.3 rad
        let (s, c) = a.sin_cos();
        let (es, ec) = f64::from(a).sin_cos();
        worst[1] = worst[1].max((f64::from(s) - es).abs()).max((f64::from(c) - ec).abs());
        let fa = Fx::from_f32(a);
        let (s, c) = fa.sin_cos();
        let (es, ec) = fa.f64().sin_cos();
        worst[0] = worst[0].max((s.f64() - es).abs()).max((c.f64() - ec).abs());
        n += 1;
    }
    println!(
        "sin_cos: {n} angles within ±6.3 rad, worst error Fx {:.2}u, f32 {:.2e}",
        worst[0] / U,
        worst[1]
    );
    assert!(worst[0] <= FX.sc && worst[1] <= F32.sc);
}

#[test]
fn conventions() {
    let near = |a: [f32; 4], b: [f32; 4]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-4);
    let q = core::f32::consts::FRAC_PI_2;
    let (x, y, z) = (Vec3::new(1.0f32, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0));
    // Counter-clockwise about each axis: x → y, y → z, z → x (and the same in Fx).
    assert!(near(rotation_z(q).transform_point(x).to_f32(), [0.0, 1.0, 0.0, 1.0]));
    assert!(near(rotation_x(q).transform_point(y).to_f32(), [0.0, 0.0, 1.0, 1.0]));
    assert!(near(rotation_y(q).transform_point(z).to_f32(), [1.0, 0.0, 0.0, 1.0]));
    assert!(near(
        rotation_y(Fx::from_f32(q)).transform_point(Vec3::from_f32([0.0, 0.0, 1.0])).to_f32(),
        [1.0, 0.0, 0.0, 1.0]
    ));
    assert!(near(
        scaling(Vec3::new(2.0f32, 3.0, 4.0)).transform_point(Vec3::new(1.0, 1.0, 1.0)).to_f32(),
        [2.0, 3.0, 4.0, 1.0]
    ));
    // A camera on +z looking at the origin: right is +x, up +y, ahead −z.
    let v = look_at(z * 5.0, Vec3::ZERO, y).unwrap();
    assert!(near(v.transform_point(x).to_f32(), [1.0, 0.0, -5.0, 1.0]));
    assert!(near(v.transform_point(y).to_f32(), [0.0, 1.0, -5.0, 1.0]));
    // Perspective: w = −z_view; the top of the field of view is NDC y = 1.
    let p = perspective(q, 2.0, 1.0, 10.0).unwrap();
    let c = p.transform_point(Vec3::new(0.0, 3.0, -3.0)); // tan(45°)·3
    assert!(c.w == 3.0 && (c.y / c.w - 1.0).abs() < 1e-6 && c.z > 0.0);
    assert!((p.transform_point(Vec3::new(6.0, 0.0, -3.0)).x - 3.0).abs() < 1e-6); // x scaled by f/aspect
    // Viewport: NDC (−1, 1) is the top-left corner, y grows downwards.
    let vp = Viewport::new(10.0f32, 20.0, 320.0, 240.0);
    assert_eq!(vp.to_screen(Vec3::new(-1.0, 1.0, 0.0)), (10.0, 20.0));
    assert_eq!(vp.to_screen(Vec3::new(1.0, -1.0, 0.0)), (330.0, 260.0));
    assert_eq!(vp.project(Vec4::new(0.5, 0.5, 0.25, 0.5)), Ok(Vec3::new(330.0, 20.0, 0.5)));
    let vf = Viewport::new(Fx::ZERO, Fx::ZERO, Fx::from_f32(320.0), Fx::from_f32(240.0));
    assert_eq!(vf.to_screen(Vec3::from_f32([0.5, -0.5, 0.0])), (Fx::from_f32(240.0), Fx::from_f32(180.0)));
}

#[test]
fn degenerate_inputs_are_errors_not_panics() {
    use crate::Param;
    let (fov, aspect, near_far) =
        (degenerate(Param::FieldOfView), degenerate(Param::AspectRatio), degenerate(Param::NearFar));
    const NF: Error = Error::NonFiniteCoordinate;
    let nan = f32::NAN;
    for (args, want) in [
        ([1.0, 1.0, 0.0, 10.0], near_far),  // near = 0
        ([1.0, 1.0, -1.0, 10.0], near_far), // near < 0
        ([1.0, 1.0, 2.0, 2.0], near_far),   // far = near
        ([1.0, 1.0, 2.0, 1.0], near_far),   // far < near
        ([1.0, 0.0, 1.0, 10.0], aspect),    // zero aspect
        ([1.0, -1.0, 1.0, 10.0], aspect),   // negative aspect
        ([0.0, 1.0, 1.0, 10.0], fov),       // zero fov
        ([3.2, 1.0, 1.0, 10.0], fov),       // fov ≥ π
        ([nan, 1.0, 1.0, 10.0], NF),        // NaN
        ([1.0, 1.0, 1.0, f32::INFINITY], NF),
    ] {
        assert_eq!(perspective(args[0], args[1], args[2], args[3]), Err(want), "{args:?}");
        let f = args.map(Fx::from_f32);
        if want != NF && args[0] < 3.2 {
            assert_eq!(perspective(f[0], f[1], f[2], f[3]), Err(want), "Fx {args:?}");
        }
    }
    // Fx: a fov of one bit, or a tiny aspect, would saturate f/aspect.
    let fx = Fx::from_f32;
    assert_eq!(perspective(Fx::from_bits(1), fx(1.0), fx(1.0), fx(10.0)), Err(Error::CoordinateOutOfRange));
    assert_eq!(perspective(fx(1.0), Fx::from_bits(1), fx(1.0), fx(10.0)), Err(Error::CoordinateOutOfRange));
    let (o, y) = (Vec3::new(1.0f32, 2.0, 3.0), Vec3::new(0.0, 1.0, 0.0));
    let look = degenerate(Param::LookAt);
    assert_eq!(look_at(o, o, y), Err(look)); // eye == target
    assert_eq!(look_at(o, o + y, y), Err(look)); // up parallel to the view
    assert_eq!(look_at(o, Vec3::ZERO, Vec3::ZERO), Err(look)); // zero up
    assert_eq!(look_at(Vec3::new(nan, 0.0, 0.0), Vec3::ZERO, y), Err(NF));
    let far = Vec3::<Fx>::from_f32([-30000.0, 0.0, 0.0]);
    assert_eq!(look_at(far, -far, Vec3::from_f32([0.0, 1.0, 0.0])), Err(Error::CoordinateOutOfRange));
    let view_box = degenerate(Param::ViewBox);
    assert_eq!(orthographic(1.0f32, 1.0, 0.0, 1.0, 0.0, 1.0), Err(view_box));
    assert_eq!(orthographic(0.0f32, 1.0, 1.0, 0.0, 0.0, 1.0), Err(view_box));
    assert_eq!(orthographic(0.0f32, 1.0, 0.0, 1.0, 1.0, 1.0), Err(near_far));
    assert_eq!(orthographic(0.0f32, 1.0, 0.0, 1.0, 0.0, nan), Err(NF));
    assert_eq!(
        orthographic(fx(-30000.0), fx(30000.0), fx(0.0), fx(1.0), fx(0.0), fx(1.0)),
        Err(Error::CoordinateOutOfRange)
    );
    // Model constructors pass NaN through; the divide reports it.
    let m = rotation_x(nan) * translation(Vec3::new(nan, 0.0, 0.0));
    let vp = Viewport::new(0.0, 0.0, 320.0, 240.0);
    assert_eq!(vp.project(m.transform_point(Vec3::ZERO)), Err(NF));
    assert_eq!(to_ndc(Vec4::new(1.0f32, 1.0, 1.0, 0.0)), Err(Error::CoordinateOutOfRange)); // w = 0
    assert_eq!(to_ndc(Vec4::new(1.0f32, 1.0, 1.0, -2.0)), Err(Error::CoordinateOutOfRange)); // behind
    let vf = Viewport::new(Fx::ZERO, Fx::ZERO, fx(320.0), fx(240.0));
    assert_eq!(
        vf.project(Vec4::new(fx(30000.0), Fx::ZERO, Fx::ZERO, fx(0.5))),
        Err(Error::CoordinateOutOfRange)
    );
    assert_eq!(
        vf.project(Vec4::new(fx(300.0), Fx::ZERO, Fx::ZERO, fx(1.0))),
        Err(Error::CoordinateOutOfRange)
    );
}

#[test]
fn model_and_view_matrices_against_f64() {
    // Each entry against the f64 matrix of the same f32 parameters, within the
    // bound carried through the construction (see `Tr`, `look_at_ref`).
    let mut rng = Rng(11);
    let (mut wm, mut wv, mut n) = ([0f64; 2], [0f64; 2], 0);
    while n < 20_000 {
        let m = Model::random(&mut rng, 256.0, 0.25, 64.0);
        wm[0] = wm[0].max(worst(m.build::<Fx>(), &m.reference([0.0; 3], &FX)));
        wm[1] = wm[1].max(worst(m.build::<f32>(), &m.reference([0.0; 3], &F32)));
        let (eye, target, up) = (rng.vec3(256.0), rng.vec3(64.0), rng.vec3(1.0));
        if !in_envelope(eye, target, up) {
            continue;
        }
        wv[0] = wv[0].max(worst(la::<Fx>(eye, target, up).unwrap(), &look_at_ref(eye, target, up, &FX)));
        wv[1] = wv[1].max(worst(la::<f32>(eye, target, up).unwrap(), &look_at_ref(eye, target, up, &F32)));
        n += 1;
    }
    println!(
        "{n} model (T·Ry·Rx·Rz·S) and look_at matrices, worst error / derived bound: \
         model Fx {:.3} f32 {:.3}, view Fx {:.3} f32 {:.3}",
        wm[0], wm[1], wv[0], wv[1]
    );
}

#[test]
fn projections_against_f64() {
    let (mut wp, mut n) = ([0f64; 2], 0);
    let q = Fx::from_f32;
    for fov in [20.0f32, 45.0, 60.0, 90.0, 120.0].map(f32::to_radians) {
        for aspect in [0.5, 4.0 / 3.0, 2.0] {
            for (near, far) in [(0.0625, 4096.0), (0.1, 100.0), (1.0, 2.0), (1.0, 1000.0), (10.0, 4000.0)] {
                let mf = perspective(q(fov), q(aspect), q(near), q(far)).unwrap();
                wp[0] = wp[0].max(worst(mf, &perspective_ref(fov, aspect, near, far, &FX)));
                let me = perspective(fov, aspect, near, far).unwrap();
                wp[1] = wp[1].max(worst(me, &perspective_ref(fov, aspect, near, far, &F32)));
                // Depth is exactly 0 on the near plane, 1 on the far plane to 1 ulp (f32).
                let a = me.transform_point(Vec3::new(0.0, 0.0, -near));
                let b = me.transform_point(Vec3::new(0.0, 0.0, -far));
                assert!(a.z == 0.0 && a.w == near && (b.z / b.w - 1.0).abs() <= 1.2e-7 && b.w == far);
                n += 1;
            }
        }
    }
    println!("{n} perspective matrices, worst error / derived bound: Fx {:.3}, f32 {:.3}", wp[0], wp[1]);
    // Orthographic: the box corners map to the NDC cube's, within a few u for Fx.
    for [l, r, b, t, nr, fr] in [[-2.0f32, 2.0, -1.5, 1.5, -1.0, 10.0], [0.0, 16.0, 0.0, 12.0, 0.5, 8.0]] {
        let of = orthographic(q(l), q(r), q(b), q(t), q(nr), q(fr)).unwrap();
        let oe = orthographic(l, r, b, t, nr, fr).unwrap();
        for (x, y, z, want) in [(l, b, -nr, [-1.0, -1.0, 0.0]), (r, t, -fr, [1.0, 1.0, 1.0])] {
            let pe = oe.transform_point(Vec3::new(x, y, z)).to_f32();
            let pf = of.transform_point(Vec3::from_f32([x, y, z])).to_f32();
            for i in 0..3 {
                assert!((pe[i] - want[i]).abs() < 1e-6 && (pf[i] - want[i]).abs() < 32.0 * U as f32);
            }
        }
    }
}

#[test]
fn normal_matrix_against_f64() {
    // N = (V·M)⁻ᵀ for non-uniform scales in [1/4, 16], against the bound of
    // `inverse_transpose_ref`.
    let mut rng = Rng(21);
    let (mut ratio, mut angle, mut n) = ([0f64; 2], [0f64; 2], 0);
    while n < 10_000 {
        let m = Model::random(&mut rng, 64.0, 0.25, 16.0);
        let (eye, target, up) = (rng.vec3(256.0), rng.vec3(64.0), rng.vec3(1.0));
        if !in_envelope(eye, target, up) {
            continue;
        }
        let dir = rng.vec3(1.0);
        for (k, p) in [&FX, &F32].into_iter().enumerate() {
            let a = model_view_ref(eye, target, up, &m, p);
            let got: [[f64; 3]; 3] = match k {
                0 => (la::<Fx>(eye, target, up).unwrap() * m.build())
                    .normal_matrix()
                    .unwrap()
                    .cols
                    .map(|c| c.map(Fx::f64)),
                _ => (la::<f32>(eye, target, up).unwrap() * m.build())
                    .normal_matrix()
                    .unwrap()
                    .cols
                    .map(|c| c.map(f64::from)),
            };
            let (x, bound) = inverse_transpose_ref(&a, p);
            for c in 0..3 {
                for r in 0..3 {
                    let e = (got[c][r] - x[c][r]).abs();
                    let b = bound[c][r];
                    assert!(e <= b, "path {k}: N[{c}][{r}] = {} vs {}: {e:e} > {b:e}", got[c][r], x[c][r]);
                    ratio[k] = ratio[k].max(e / b);
                }
            }
            // The transformed normal's direction, which is what shading uses.
            let d = dir.map(f64::from);
            let apply =
                |m: &[[f64; 3]; 3]| unit([0, 1, 2].map(|r| (0..3).map(|c| m[c][r] * d[c]).sum::<f64>()));
            let (g, w) = (apply(&got), apply(&x));
            angle[k] = angle[k].max(norm([g[0] - w[0], g[1] - w[1], g[2] - w[2]]));
        }
        n += 1;
    }
    println!(
        "{n} normal matrices (scales 1/4..16): worst error / derived bound Fx {:.3}, f32 {:.3}; \
         worst normal direction error Fx {:.1e} rad, f32 {:.1e} rad",
        ratio[0], ratio[1], angle[0], angle[1]
    );
    assert!(angle[0] < 2e-3 && angle[1] < 1e-5);
}

#[test]
fn pipeline_to_screen() {
    // Scenes in the documented envelope: eye within ±256, target within ±64
    // (every third scene: within 2 of the eye, for points near the near
    // plane), fov 20°..120°, model coordinates ±4, scales 1/4..64. Composed
    // as P·(V·M). Every point in the view frustum is checked against its own
    // derived bound: the entry bounds carried through P·(V·M), the point
    // (quantised in Fx) and the divide.
    let mut rng = Rng(12);
    let (mut scenes, mut pts, mut close) = (0, 0, 0);
    // worst[path][w bin]: bins w < 1, 1 ≤ w < 4, 4 ≤ w < 16, w ≥ 16.
    let (mut worst, mut ratio) = ([[0f64; 4]; 2], [0f64; 2]);
    while scenes < 3000 {
        let eye = rng.vec3(256.0);
        let o = rng.vec3(if scenes % 3 == 2 { 2.0 } else { 64.0 });
        let target = if scenes % 3 == 2 { [0, 1, 2].map(|i| eye[i] + o[i]) } else { o };
        let up = if scenes % 2 == 0 { [0.0, 1.0, 0.0] } else { rng.vec3(1.0) };
        if !in_envelope(eye, target, up) {
            continue;
        }
        let dist = norm([0, 1, 2].map(|i| f64::from(target[i] - eye[i])));
        let fov = rng.range(20f64.to_radians(), 120f64.to_radians());
        let near = [0.0625f32, 0.25, 1.0, 4.0][scenes % 4];
        let far = (f64::from(near) + 2.0 * dist + 64.0).min(4096.0) as f32;
        let mut model = Model::random(&mut rng, dist / 4.0, 0.25, 64.0);
        model.t = [0, 1, 2].map(|i| target[i] + model.t[i]);
        model.s = model.s.map(|v| v.min((dist / 4.0) as f32).max(0.25)); // keep it in view
        let aspect = 4.0f32 / 3.0;
        let reference = |p: &Path| {
            perspective_ref(fov, aspect, near, far, p).mul(&model_view_ref(eye, target, up, &model, p), p)
        };
        let refs = [reference(&FX), reference(&F32)];
        let q = Fx::from_f32;
        let mf = perspective(q(fov), q(aspect), q(near), q(far)).unwrap()
            * (la(eye, target, up).unwrap() * model.build());
        let me =
            perspective(fov, aspect, near, far).unwrap() * (la(eye, target, up).unwrap() * model.build());
        let (vf, ve) =
            (Viewport::new(Fx::ZERO, Fx::ZERO, q(320.0), q(240.0)), Viewport::new(0.0, 0.0, 320.0, 240.0));
        for _ in 0..64 {
            let v = rng.vec3(4.0);
            let x = [f64::from(v[0]), f64::from(v[1]), f64::from(v[2]), 1.0];
            let c = crate::math::mat::tests::apply64(&refs[1].v, x);
            if !(c[0].abs() <= c[3] && c[1].abs() <= c[3] && c[2] >= 0.0 && c[2] <= c[3]) {
                continue; // outside the view frustum
            }
            let sf = vf.project(mf.transform_point(Vec3::from_f32(v))).unwrap();
            let se = ve.project(me.transform_point(Vec3::from_f32(v))).unwrap();
            let bin = [1.0, 4.0, 16.0].iter().filter(|&&t| c[3] >= t).count();
            (pts, close) = (pts + 1, close + usize::from(bin == 0));
            for (k, got) in [[sf.x.f64(), sf.y.f64()], [se.x.f64(), se.y.f64()]].into_iter().enumerate() {
                let p = [&FX, &F32][k];
                let (c, ec) = refs[k].apply(x, [p.q, p.q, p.q, 0.0], p);
                let (want, bound) = screen_ref(c, ec, (320.0, 240.0), p);
                for i in 0..2 {
                    let e = (got[i] - want[i]).abs();
                    assert!(e <= bound[i], "path {k}: error {e} px > bound {} at w = {}", bound[i], c[3]);
                    worst[k][bin] = worst[k][bin].max(e);
                    ratio[k] = ratio[k].max(e / bound[i]);
                }
            }
        }
        scenes += 1;
    }
    println!(
        "pipeline 320×240: {scenes} scenes, {pts} points in the frustum ({close} at w < 1); worst px error by w < 1, [1,4), [4,16), ≥ 16:"
    );
    for (k, name) in ["Fx ", "f32"].into_iter().enumerate() {
        let [a, b, c, d] = worst[k];
        println!("  {name}: {a:.2e} {b:.2e} {c:.2e} {d:.2e}; worst error / derived bound {:.3}", ratio[k]);
    }
    let f32_far = worst[1][2].max(worst[1][3]);
    assert!(close > 500 && worst[1][0] < 0.1 && worst[1][1] < 0.03 && f32_far < 0.01);
    assert!(worst[0][0] < 1.0 && worst[0][1].max(worst[0][2]).max(worst[0][3]) < 0.25);
}

/// Finite `f32` input whose matrix overflows is `CoordinateOutOfRange`
/// (the `f32` case of the constructors' docs), and a slightly milder input
/// of each kind is accepted.
#[test]
fn f32_overflow_is_coordinate_out_of_range() {
    let out = Err(Error::CoordinateOutOfRange);
    let v = |x: f32, y: f32, z: f32| Vec3::new(x, y, z);
    let up = v(0.0, 1.0, 0.0);
    assert_eq!(look_at(v(f32::MAX, 0.0, 0.0), v(0.0, 0.0, 0.0), up).map(|_| ()), out);
    assert_eq!(look_at(v(f32::MAX, 0.0, 0.0), v(-f32::MAX, 0.0, 0.0), up).map(|_| ()), out);
    assert!(look_at(v(1e30, 0.0, 0.0), v(0.0, 0.0, 0.0), up).is_ok());
    // A fov or aspect near 0 (1/tan overflows); near and far huge and close.
    assert_eq!(perspective(1e-40f32, 1.0, 0.5, 10.0).map(|_| ()), out);
    assert_eq!(perspective(1.0f32, 1e-40, 0.5, 10.0).map(|_| ()), out);
    let near = 1e37f32;
    assert_eq!(perspective(1.0f32, 1.0, near, f32::from_bits(near.to_bits() + 1)).map(|_| ()), out);
    assert!(perspective(1e-30f32, 1e-6, 1e30, 2e30).is_ok());
    assert_eq!(orthographic(-f32::MAX, f32::MAX, -1.0, 1.0, 0.5, 10.0).map(|_| ()), out);
    assert!(orthographic(-1e30f32, 1e30, -1.0, 1.0, 0.5, 10.0).is_ok());
}
