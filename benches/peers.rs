//! microraster against its peers on the benchmark scenes, in one run:
//!
//! ```text
//! cargo bench --bench peers                 # everything: about 2 minutes of measuring
//! cargo bench --bench peers -- scatter      # one scene (criterion filter)
//! ```
//!
//! Scenes (`microraster_scenes::scenes::benchmarks`, `microraster_scenes::scenes3d`), all at
//! 320 × 240 `Rgb565` (tiny-skia: RGBA8888, its only format): (1) `scatter`,
//! 1,000 triangles of mixed sizes; (2) `large`, 8 large triangles (fill-rate
//! bound); (3) `tiny`, 10,000 tiny triangles (setup bound); (4) `mesh3d`, the
//! standard 3D scene (1,116 triangles, 16-bit depth, Gouraud); (5) `lines`,
//! 1,000 lines; `knot20k`, the 20k-triangle knot (10,240 vertices, Gouraud
//! with specular, 16-bit depth, back faces culled) through the meshlet stage,
//! against the `euc` crate. Renderers and targets: `benches/common/mod.rs`
//! and `benches/common/knot.rs`.
//!
//! After criterion's own output, a table of ratios from this run's estimates
//! (criterion's median per benchmark) is printed: peer time / microraster
//! time, and scene 2's fill rate as a fraction of the slice-fill ceiling. The
//! report (`cargo run --release --example report`) measures the same
//! renderers with its own timing loop and writes `docs/tradeoffs.md`.

use criterion::{BenchmarkGroup, Criterion, measurement::WallTime};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Band;
use microraster::depth::{Depth16, DepthBand};
use microraster::math::Fx;
use microraster::raster3d::{Affine, PerspectiveCorrect, Precision};
use microraster_scenes::scenes;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

#[path = "common/mod.rs"]
mod common;
use common::*;
#[path = "common/knot.rs"]
mod knot;
#[path = "../examples/common/knot_mesh.rs"]
mod knot_mesh;

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(400))
        .measurement_time(Duration::from_millis(1200))
        .sample_size(20)
        .without_plots()
        .configure_from_args()
}

/// Every 2D renderer on one scene; `gouraud` also runs the Gouraud variant.
fn scene2d(
    c: &mut Criterion,
    name: &str,
    scene: scenes::Scene<Rgb565, 4>,
    gouraud: Option<scenes::Scene<Rgb565, 4>>,
) {
    let s4 = Scene2d::<4>::new(scene);
    let s8 = Scene2d::<8>::new(match name {
        "scatter" => scenes::scatter,
        "large" => scenes::large,
        "tiny" => scenes::tiny,
        _ => scenes::lines,
    });
    let mut g = c.benchmark_group(name);
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let mut slice = SliceFb::default();
    let mut egfb = Box::new(EgFb::new());
    let mut pixmap = tiny_skia::Pixmap::new(W as u32, H as u32).unwrap();
    let mut out = vec![BG; W * H];
    run(&mut g, "mr_band16_slice", || mr_band(&s4, &mut band, &mut slice));
    run(&mut g, "mr_band16_slice_s8", || mr_band(&s8, &mut band, &mut slice));
    let mut index = Vec::new();
    run(&mut g, "mr_band16_slice_binned", || mr_binned(&s4, &mut band, &mut index, &mut slice));
    run(&mut g, "mr_band16_egfb", || mr_band(&s4, &mut band, &mut *egfb));
    run(&mut g, "mr_direct_slice", || mr_direct(&s4, &mut slice));
    run(&mut g, "mr_direct_egfb", || mr_direct(&s4, &mut *egfb));
    if let Some(gs) = gouraud {
        let sg = Scene2d::<4>::new(gs);
        run(&mut g, "mr_band16_slice_gouraud", || mr_band(&sg, &mut band, &mut slice));
        run(&mut g, "mr_direct_slice_gouraud", || mr_direct(&sg, &mut slice));
    }
    run(&mut g, "eg_egfb", || eg(&s4, &mut *egfb));
    run(&mut g, "eg_slice", || eg(&s4, &mut slice));
    run(&mut g, "skia", || skia(&s4, &mut pixmap));
    run(&mut g, "reference", || reference(&s4, &mut out));
    g.finish();
}

fn run(g: &mut BenchmarkGroup<'_, WallTime>, id: &str, mut f: impl FnMut()) {
    g.bench_function(id, |b| b.iter(|| black_box(&mut f)()));
}

fn mesh3d(c: &mut Criterion) {
    let mut g = c.benchmark_group("mesh3d");
    let (p32, pfx) = (pipeline3d::<f32, 4>(), pipeline3d::<Fx, 4>());
    let mut bins = Box::new(Bins::<4>::new());
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut slice = SliceFb::default();
    let mut egfb = Box::new(EgFb::new());
    run(&mut g, "mr_f32_persp_band16_slice", || {
        mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    });
    run(&mut g, "mr_fx_persp_band16_slice", || {
        mr3d::<Fx, Depth16, PerspectiveCorrect, 4, 16>(&pfx, &mut bins, &mut band, &mut depth, &mut slice);
    });
    run(&mut g, "mr_f32_affine_band16_slice", || {
        mr3d::<f32, Depth16, Affine, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    });
    run(&mut g, "mr_f32_persp_band16_egfb", || {
        mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut *egfb);
    });
    let mut px = vec![RefPixel { id: 0, depth: 0.0, color: [0.0; 3] }; W * H];
    let mut out = vec![BG3; W * H];
    run(&mut g, "reference", || Ref3d::frame(ANGLE, &mut px, &mut out));
    g.finish();
}

fn knot20k(c: &mut Criterion) {
    use knot::{EucKnot, mr_knot};
    use microraster::pipeline::ClusterCache;
    let mut g = c.benchmark_group("knot20k");
    let (p32, pfx) = (pipeline3d::<f32, 4>(), pipeline3d::<Fx, 4>());
    let (mut c32, mut cfx) = (Box::new(ClusterCache::new()), Box::new(ClusterCache::new()));
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut slice = SliceFb::default();
    run(&mut g, "mr_f32_persp_band16_slice", || {
        mr_knot::<f32, PerspectiveCorrect>(&p32, &mut c32, &mut band, &mut depth, &mut slice);
    });
    run(&mut g, "mr_f32_affine_band16_slice", || {
        mr_knot::<f32, Affine>(&p32, &mut c32, &mut band, &mut depth, &mut slice);
    });
    run(&mut g, "mr_fx_affine_band16_slice", || {
        mr_knot::<Fx, Affine>(&pfx, &mut cfx, &mut band, &mut depth, &mut slice);
    });
    let fast = p32.with_precision(Precision::Fast);
    run(&mut g, "mr_f32_persp_band16_slice_fast", || {
        mr_knot::<f32, PerspectiveCorrect>(&fast, &mut c32, &mut band, &mut depth, &mut slice);
    });
    run(&mut g, "mr_f32_affine_band16_slice_fast", || {
        mr_knot::<f32, Affine>(&fast, &mut c32, &mut band, &mut depth, &mut slice);
    });
    let mut euc = EucKnot::new();
    run(&mut g, "euc", || euc.frame());
    g.finish();
}

fn ceiling(c: &mut Criterion) {
    let mut g = c.benchmark_group("ceiling");
    let mut slice = SliceFb::default();
    let mut k = 0u16;
    run(&mut g, "memset", || {
        k = k.wrapping_add(1);
        memset(&mut slice, Rgb565::new((k & 31) as u8, 0, 0));
    });
    g.finish();
}

fn main() {
    let mut c = config();
    ceiling(&mut c);
    scene2d(&mut c, "scatter", scenes::scatter, Some(scenes::scatter_gouraud));
    scene2d(&mut c, "large", scenes::large, None);
    scene2d(&mut c, "tiny", scenes::tiny, None);
    scene2d(&mut c, "lines", scenes::lines, None);
    mesh3d(&mut c);
    knot20k(&mut c);
    c.final_summary();
    ratios();
}

/// Criterion's median estimate (ns) of `group/id` from this run, if any.
fn median(group: &str, id: &str) -> Option<f64> {
    let base = std::env::var_os("CRITERION_HOME").map(PathBuf::from).unwrap_or_else(|| {
        let target =
            std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| PathBuf::from("target"), PathBuf::from);
        target.join("criterion")
    });
    let text = std::fs::read_to_string(base.join(group).join(id).join("new/estimates.json")).ok()?;
    let at = text.find("\"median\"")?;
    let rest = &text[at..];
    let v = rest[rest.find("\"point_estimate\":")? + 17..].split([',', '}']).next()?;
    v.trim().parse().ok()
}

/// Peer / microraster time ratios from this run's estimates.
fn ratios() {
    println!("\nRatios from this run (criterion medians; > 1: microraster is faster)");
    println!(
        "{:<8} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "scene", "eg/mr egfb", "eg/mr slice", "skia/mr", "ref/mr", "mr µs"
    );
    for scene in ["scatter", "large", "tiny", "lines", "mesh3d"] {
        let mr_id = if scene == "mesh3d" { "mr_f32_persp_band16_slice" } else { "mr_band16_slice" };
        let Some(mr) = median(scene, mr_id) else { continue };
        let r = |id: &str, base: Option<f64>| {
            median(scene, id).zip(base).map_or("-".to_string(), |(t, b)| format!("{:.2}", t / b))
        };
        println!(
            "{:<8} {:>12} {:>12} {:>12} {:>12} {:>12.1}",
            scene,
            r("eg_egfb", median(scene, "mr_band16_egfb")),
            r("eg_slice", Some(mr)),
            r("skia", Some(mr)),
            r("reference", Some(mr)),
            mr / 1000.0
        );
    }
    let knot = |id: &str| median("knot20k", id);
    if let (Some(euc), Some(persp), Some(affine)) =
        (knot("euc"), knot("mr_f32_persp_band16_slice"), knot("mr_f32_affine_band16_slice"))
    {
        println!(
            "knot20k: euc / microraster {:.2} (f32, perspective-correct, as euc interpolates), {:.2} (f32, affine); \
             microraster {:.1} µs, euc {:.1} µs",
            euc / persp,
            euc / affine,
            persp / 1000.0,
            euc / 1000.0
        );
    }
    if let (Some(euc), Some(persp), Some(affine)) =
        (knot("euc"), knot("mr_f32_persp_band16_slice_fast"), knot("mr_f32_affine_band16_slice_fast"))
    {
        println!(
            "knot20k, fast tier: euc / microraster {:.2} (perspective-correct), {:.2} (affine); microraster {:.1} µs",
            euc / persp,
            euc / affine,
            persp / 1000.0
        );
    }
    let large = Scene2d::<4>::new(scenes::large);
    if let (Some(mem), Some(band), Some(direct)) =
        (median("ceiling", "memset"), median("large", "mr_band16_slice"), median("large", "mr_direct_slice"))
    {
        let ceiling = (W * H) as f64 / mem;
        let rate = |t: f64| large.covered as f64 / t / ceiling * 100.0;
        println!(
            "scene 2 flat fill rate: band renderer {:.0}% and direct {:.0}% of the slice-fill ceiling ({:.2} px/ns)",
            rate(band),
            rate(direct),
            ceiling
        );
    }
}
