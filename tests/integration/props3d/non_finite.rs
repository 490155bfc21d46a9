//! NaN and ±inf in every `f32` input of the pipeline.

use super::{FH, FW, drawn, rare_wild, wild};
use crate::props::{Tally, runner};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::Error;
use microraster::edge::Cull;
use microraster::light::Lighting;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::Pipeline;
use microraster::raster3d::ScreenTriangle;
use proptest::prelude::*;

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
                            Error::InvalidFrameSize
                                | Error::InvalidParameter(_)
                                | Error::CoordinateOutOfRange
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
                | Err(
                    Error::InvalidParameter(_) | Error::NonFiniteCoordinate | Error::CoordinateOutOfRange,
                ) => {}
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
