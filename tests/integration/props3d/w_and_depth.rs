//! `w → 0+` and `w < 0` through the pipeline, and depth at near and far for
//! far/near ratios up to 10^7.

use super::{FH, FW, clip_w, drawn};
use crate::props::{Tally, runner};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::clip3d::ClipPlanes;
use microraster::depth::{Depth16, DepthBand, DepthFormat, DepthState};
use microraster::edge::Cull;
use microraster::math::{Mat4, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::{Band, Error};
use proptest::prelude::*;

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
            prop_assert_eq!(
                transform::perspective(1.0f32, 1.0, n, n).err(),
                Some(Error::InvalidParameter(microraster::Param::NearFar))
            );
            prop_assert_eq!(
                transform::perspective(1.0f32, 1.0, -n, f).err(),
                Some(Error::InvalidParameter(microraster::Param::NearFar))
            );
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
