//! The band renderer on one benchmark scene, for profiling: deterministic
//! instruction counts under callgrind, or a quick timing.
//!
//! ```text
//! cargo build --release --example fill_profile
//! valgrind --tool=callgrind target/release/examples/fill_profile large 10
//! target/release/examples/fill_profile large time
//! target/release/examples/fill_profile large time spans
//! ```
//!
//! Arguments: the scene (`scatter`, `large`, `tiny`, `lines`, or `empty`, a
//! frame with no primitive; or `scene3d` / `scene3d_persp`, the standard 3D
//! scene through the `f32` vertex stage and `Triangles3d` with 16-bit depth,
//! affine or perspective-correct colour, vertex stage included); a frame count (default 10), or `time` to print
//! the median thread CPU time per frame and the scene's fill rate against the
//! slice-fill ceiling (the report's timing loop, `examples/report/timing.rs`);
//! and what to run: `render` (default: `Renderer::render` with 16-row bands
//! into the benchmarks' `SliceFb`, `benches/common/mod.rs`) or `spans` (the
//! triangles' per-band set-up and row walk only, summing span lengths,
//! nothing written), or `reference` (the f64 bounding-box reference rasterizer of
//! `benches/common`, the report's baseline). Under callgrind, subtract a run with 0 frames to leave
//! out the scene's preparation.

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::edge::{Cull, TriangleSpans};
use microraster::{Band, ClipRect, Primitive};
use microraster_scenes::scenes;
use std::hint::black_box;

#[path = "../benches/common/mod.rs"]
pub mod common;
#[path = "report/timing.rs"]
mod timing;
use common::*;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let arg = |i: usize, default: &'static str| args.get(i).map_or(default, String::as_str);
    let (scene, frames, mode) = (arg(1, "large"), arg(2, "10"), arg(3, "render"));
    if let Some(persp) = match scene {
        "scene3d" => Some(false),
        "scene3d_persp" => Some(true),
        _ => None,
    } {
        return scene3d(persp, frames.parse().expect("frame count"));
    }
    let s = match scene {
        "scatter" => Scene2d::<4>::new(scenes::scatter),
        "large" => Scene2d::<4>::new(scenes::large),
        "tiny" => Scene2d::<4>::new(scenes::tiny),
        "lines" => Scene2d::<4>::new(scenes::lines),
        "empty" => Scene2d::<4>::from_prims(Vec::new()),
        _ => panic!("unknown scene {scene}"),
    };
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let mut fb = SliceFb::default();
    let mut frame: Box<dyn FnMut()> = match mode {
        "render" => Box::new(|| mr_band(black_box(&s), &mut band, &mut fb)),
        "spans" => Box::new(|| {
            black_box(spans(black_box(&s)));
        }),
        "reference" => {
            let s = &s;
            let mut out = vec![BG; W * H];
            Box::new(move || reference(black_box(s), &mut out))
        }
        _ => panic!("unknown mode {mode}"),
    };
    if frames == "time" {
        let t = timing::median_ns(&mut frame);
        drop(frame);
        let mut fb = SliceFb::default();
        let m = timing::median_ns(|| memset(&mut fb, Rgb565::new(3, 5, 7)));
        let ceiling = (W * H) as f64 / m;
        let fill = s.covered as f64 / t / ceiling * 100.0;
        let fill = if mode == "render" { format!("; fill {fill:.1}% of the ceiling") } else { String::new() };
        println!("{scene} {mode}: {:.2} µs/frame; memset {:.2} µs{fill}", t / 1e3, m / 1e3);
    } else {
        for _ in 0..frames.parse::<usize>().expect("frame count") {
            frame();
        }
    }
}

/// The spans of every triangle band by band (16 rows), as the renderer
/// walks them, without writing: the sum of their lengths.
fn spans(s: &Scene2d<4>) -> u64 {
    let mut n = 0;
    for y0 in (0..H as i32).step_by(16) {
        let clip = ClipRect::new(0, y0, W as i32, (y0 + 16).min(H as i32));
        for p in &s.prims {
            let (lo, hi) = p.rows();
            if let (Primitive::Triangle(t), true) = (p, lo < clip.y1() && hi >= y0) {
                n += TriangleSpans::new(t.vertices(), clip, Cull::None).map(|s| s.len as u64).sum::<u64>();
            }
        }
    }
    n
}

/// `frames` frames of the standard 3D scene (see the header).
fn scene3d(persp: bool, frames: usize) {
    use microraster::depth::{Depth16, DepthBand};
    use microraster::raster3d::{Affine, PerspectiveCorrect};
    let pipeline = pipeline3d::<f32, 4>();
    let mut bins = Box::new(Bins::<4>::new());
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut fb = SliceFb::default();
    for _ in 0..frames {
        if persp {
            mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(
                &pipeline, &mut bins, &mut band, &mut depth, &mut fb,
            );
        } else {
            mr3d::<f32, Depth16, Affine, 4, 16>(&pipeline, &mut bins, &mut band, &mut depth, &mut fb);
        }
    }
    black_box(&fb);
}
