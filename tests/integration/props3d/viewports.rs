//! Viewports from 1×1 to 4096×4096 drawn exactly.

use super::{FH, FW, drawn};
use crate::props::{Tally, runner};
use crate::reference::{Coverage, spans_coverage};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::ClipRect;
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::{Fx, Mat4, Scalar, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::Pipeline;
use microraster::raster3d::ScreenTriangle;
use proptest::prelude::*;

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
