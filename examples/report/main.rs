//! The speed/accuracy report (issue 5): measures microraster against its
//! peers and sweeps its knobs, then rewrites `docs/tradeoffs.md` and the
//! charts in `docs/charts/`. Every number in that document comes from this
//! program:
//!
//! ```text
//! cargo run --release --example report            # writes docs/ (about 1–2 minutes)
//! cargo run --release --example report -- OUT_DIR # writes OUT_DIR/tradeoffs.md, OUT_DIR/charts/
//! ```
//!
//! Timing: a median of repeated runs ([`timing`]); the criterion benchmarks
//! (`cargo bench --bench peers`) measure the same renderers
//! (`benches/common/mod.rs`, included below) with criterion. Cortex-M
//! instruction counts are read from `docs/data/cortex-m.tsv`, which
//! `bash scripts/firmware.sh sweep` writes (`examples/fw_sweep`, [`cortex`]).
//! The 2D shape ratios are criterion's medians of the last
//! `cargo bench --bench shapes` run, read from `target/criterion` (the
//! report does not run that bench; without its data the section says so).

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::Band;
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthBand};
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::Fx;
use microraster::raster3d::{Affine, PerspectiveCorrect};
use microraster::{ClipRect, Primitive, Renderer};
use microraster_scenes::scenes;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

mod charts;
#[path = "../../benches/common/mod.rs"]
mod common;
mod cortex;
#[path = "../../benches/common/criterion_median.rs"]
mod criterion_median;
mod frag_report;
mod knot;
#[path = "../common/shapes_ratios.rs"]
mod shapes_ratios;
mod sweep;
mod targets;
// The Cortex-M counts' configurations (examples/fw_sweep), timed on the host.
#[allow(dead_code)]
#[path = "../fw_sweep/configs.rs"]
mod configs;
#[allow(dead_code)]
#[path = "../fw_sweep/fragment.rs"]
mod fragment;
#[allow(dead_code)]
#[path = "../fw_sweep/frame.rs"]
mod frame;
// The 20k-triangle knot (issue 12), used by `configs` and `knot_renderers`.
#[allow(dead_code)]
#[path = "../common/knot_mesh.rs"]
mod knot_mesh;
// The knot's renderers (microraster's meshlet stage and euc), shared with the benchmarks.
#[path = "../../benches/common/knot.rs"]
mod knot_renderers;
mod timing;

use charts::Point2;
use common::*;
use sweep::{Row2d, Row3d};
use timing::median_ns;

type Res<T> = Result<T, Box<dyn std::error::Error>>;

/// One renderer on one scene.
struct Peer {
    scene: &'static str,
    renderer: &'static str,
    target: &'static str,
    key: String,
    ns: f64,
    /// Pixels differing from microraster's frame (band renderer, S = 4, flat).
    differs: Option<usize>,
    /// Pixels written by microraster for this scene (fill work).
    covered: u64,
}

fn main() -> Res<()> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "docs".into()));
    let charts_dir = out.join("charts");
    std::fs::create_dir_all(&charts_dir)?;
    let counts = cortex::Counts::load(&out.join("data/cortex-m.tsv"))?;
    let fw = cortex::FwBench::load(&out.join("data/fw-bench.tsv"))?;
    let cpu = cpu_name();
    eprintln!("report: {cpu}; writing {}", out.display());

    let mut fb = SliceFb::default();
    let memset_ns = median_ns(|| memset(&mut fb, Rgb565::new(3, 5, 7)));
    let ceiling = (W * H) as f64 / memset_ns; // px per ns

    eprintln!("report: peers");
    let mut peers = Vec::new();
    let mut breakdown = Vec::new();
    peers2d(
        &mut peers,
        &mut breakdown,
        "scatter",
        scenes::scatter,
        scenes::scatter,
        Some(scenes::scatter_gouraud),
    );
    peers2d(&mut peers, &mut breakdown, "large", scenes::large, scenes::large, None);
    peers2d(&mut peers, &mut breakdown, "tiny", scenes::tiny, scenes::tiny, None);
    peers2d(&mut peers, &mut breakdown, "lines", scenes::lines, scenes::lines, None);
    peers3d(&mut peers);
    knot::peers(&mut peers);

    eprintln!("report: sweep (2D)");
    let fine = sweep::fine_scene();
    let ref_ids = sweep::reference_ids(&fine);
    let mut s2 = vec![
        sweep::run2d::<0, 16>(&fine, &ref_ids, "subpixel", "S = 0"),
        sweep::run2d::<2, 16>(&fine, &ref_ids, "subpixel", "S = 2"),
        sweep::run2d::<4, 16>(&fine, &ref_ids, "subpixel", "S = 4"),
        sweep::run2d::<6, 16>(&fine, &ref_ids, "subpixel", "S = 6"),
        sweep::run2d::<8, 16>(&fine, &ref_ids, "subpixel", "S = 8"),
        sweep::run2d::<4, 1>(&fine, &ref_ids, "band", "1 row"),
        sweep::run2d::<4, 8>(&fine, &ref_ids, "band", "8 rows"),
        sweep::run2d::<4, 16>(&fine, &ref_ids, "band", "16 rows"),
        sweep::run2d::<4, 32>(&fine, &ref_ids, "band", "32 rows"),
        sweep::run2d::<4, H>(&fine, &ref_ids, "band", "240 rows (full)"),
    ];
    let keys2 = ["S0", "S2", "S4", "S6", "S8"];
    let bands = ["band1", "band8", "band16", "band32", "band240"];
    for (i, r) in s2.iter_mut().enumerate() {
        r.key = if i < 5 {
            format!("scatter-fine/band16/{}/flat", keys2[i])
        } else {
            format!("scatter-fine/{}/S4/flat", bands[i - 5])
        };
    }
    let base2 = s2[7].frame.clone();
    for r in &mut s2 {
        r.differs_from_baseline = r.frame.iter().zip(&base2).filter(|(a, b)| a != b).count();
    }

    eprintln!("report: sweep (3D)");
    let reference = sweep::Ref3dFrame::new();
    use sweep::run3d;
    type P = PerspectiveCorrect;
    let mut s3 = vec![
        run3d::<f32, Depth16, P, 0, 16>(&reference, "subpixel", "S = 0"),
        run3d::<f32, Depth16, P, 2, 16>(&reference, "subpixel", "S = 2"),
        run3d::<f32, Depth16, P, 4, 16>(&reference, "subpixel", "S = 4"),
        run3d::<f32, Depth16, P, 6, 16>(&reference, "subpixel", "S = 6"),
        run3d::<f32, Depth16, P, 8, 16>(&reference, "subpixel", "S = 8"),
        run3d::<f32, Depth8, P, 4, 16>(&reference, "depth", "8 bits"),
        run3d::<f32, Depth16, P, 4, 16>(&reference, "depth", "16 bits"),
        run3d::<f32, Depth24, P, 4, 16>(&reference, "depth", "24 bits"),
        run3d::<f32, Depth32, P, 4, 16>(&reference, "depth", "32 bits"),
        run3d::<f32, Depth16, P, 4, 1>(&reference, "band", "1 row"),
        run3d::<f32, Depth16, P, 4, 8>(&reference, "band", "8 rows"),
        run3d::<f32, Depth16, P, 4, 16>(&reference, "band", "16 rows"),
        run3d::<f32, Depth16, P, 4, 32>(&reference, "band", "32 rows"),
        run3d::<f32, Depth16, P, 4, H>(&reference, "band", "240 rows (full)"),
        run3d::<f32, Depth16, Affine, 4, 16>(&reference, "interpolation", "affine"),
        run3d::<f32, Depth16, P, 4, 16>(&reference, "interpolation", "perspective-correct"),
        run3d::<f32, Depth16, P, 4, 16>(&reference, "vertex", "f32"),
        run3d::<Fx, Depth16, P, 4, 16>(&reference, "vertex", "Fx (16.16)"),
    ];
    let keys3 = [
        "f32/D16/persp/band16/S0",
        "f32/D16/persp/band16/S2",
        "f32/D16/persp/band16/S4",
        "f32/D16/persp/band16/S6",
        "f32/D16/persp/band16/S8",
        "f32/D8/persp/band16/S4",
        "f32/D16/persp/band16/S4",
        "f32/D24/persp/band16/S4",
        "f32/D32/persp/band16/S4",
        "f32/D16/persp/band1/S4",
        "f32/D16/persp/band8/S4",
        "f32/D16/persp/band16/S4",
        "f32/D16/persp/band32/S4",
        "f32/D16/persp/band240/S4",
        "f32/D16/affine/band16/S4",
        "f32/D16/persp/band16/S4",
        "f32/D16/persp/band16/S4",
        "Fx/D16/persp/band16/S4",
    ];
    for (r, k) in s3.iter_mut().zip(keys3) {
        r.key = format!("mesh3d/{k}");
    }
    let base3 = s3[11].frame.clone();
    for r in &mut s3 {
        r.differs_from_baseline = r.frame.iter().zip(&base3).filter(|(a, b)| a != b).count();
    }
    let setups: Vec<(usize, usize)> = {
        let p = pipeline3d::<f32, 4>();
        let mut bins = Box::new(Bins::<4>::new());
        microraster_scenes::scenes3d::Scene3d
            .draw::<f32, Rgb565, 4, { microraster_scenes::scenes3d::BINS }>(&p, ANGLE, &mut bins)?;
        [1, 8, 16, 32, H].iter().map(|&bh| (bh, sweep::setups_per_frame(&bins, bh))).collect()
    };

    eprintln!("report: fragment stage");
    let frag: Vec<FragRow> = fragment::LIST
        .iter()
        .map(|c| FragRow {
            key: c.key,
            ns: frag_report::config_ns(c),
            accuracy: frag_report::accuracy(c.key),
        })
        .collect();
    let aliased_coverage = frag_report::aliased_coverage();

    eprintln!("report: charts and tables");
    let (mut doc, targets) =
        document(&cpu, memset_ns, ceiling, &peers, &breakdown, &s2, &s3, &setups, &counts, &fw);
    doc.push_str(&fragment_section(&frag, aliased_coverage, &peers, &counts));
    doc.push_str(&shapes_section());
    std::fs::write(out.join("tradeoffs.md"), doc)?;
    // The README quotes the targets table; keep it in step when writing docs/.
    let readme = out.join("../README.md");
    if out.ends_with("docs") && readme.exists() {
        update_readme(&readme, &[("targets", targets), ("knot", knot::readme_table(&peers, &counts, &fw))])?;
    }
    draw_charts(&charts_dir, ceiling, &peers, &s2, &s3, &counts)?;
    eprintln!("report: wrote {} and {}", out.join("tradeoffs.md").display(), charts_dir.display());
    Ok(())
}

fn cpu_name() -> String {
    let info = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let model = info
        .lines()
        .find_map(|l| l.strip_prefix("model name"))
        .map(|l| l.trim_start_matches([' ', '\t', ':']));
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{} ({cores} cores available, one used)", model.unwrap_or("unknown CPU"))
}

/// The slice pass of `Renderer::render` (the primitives whose rows meet the
/// band, each drawn with the renderer's cull) into a blitter that counts the
/// pixels instead of writing them: the frame's set-up and coverage alone.
struct Coverage<'a, const S: u32>(&'a [Primitive<Rgb565, S>]);

impl<const S: u32, const BW: usize, const BH: usize> microraster::render::Pass<Rgb565, BW, BH>
    for Coverage<'_, S>
{
    // Nothing is written, so nothing needs clearing.
    const CLEARS: bool = false;

    fn draw(
        &mut self,
        band: &mut microraster::band::BandView<'_, Rgb565, BW>,
        renderer: &Renderer<Rgb565>,
    ) -> Result<(), microraster::Error> {
        use microraster::blit::Blitter;
        struct Count(ClipRect, u64);
        impl Blitter<Rgb565> for Count {
            fn clip(&self) -> ClipRect {
                self.0
            }
            fn set_pixel(&mut self, _: i32, _: i32, _: Rgb565) {
                self.1 += 1;
            }
            fn fill_span(&mut self, span: microraster::edge::Span, _: Rgb565) {
                self.1 += span.len as u64;
            }
        }
        let (y0, y1) = (band.y0(), band.y1());
        let mut count = Count(band.clip(), 0);
        for prim in self.0 {
            let (lo, hi) = prim.rows();
            if lo < y1 && hi >= y0 {
                prim.draw(&mut count, renderer.cull());
            }
        }
        std::hint::black_box(count.1);
        Ok(())
    }
}

/// Where the band renderer's time goes on one scene.
struct Breakdown {
    scene: &'static str,
    full: f64,
    empty: f64,
    spans: f64,
}

#[allow(clippy::too_many_arguments)]
fn peers2d(
    peers: &mut Vec<Peer>,
    breakdown: &mut Vec<Breakdown>,
    scene: &'static str,
    f4: scenes::Scene<Rgb565, 4>,
    f8: scenes::Scene<Rgb565, 8>,
    gouraud: Option<scenes::Scene<Rgb565, 4>>,
) {
    let s4 = Scene2d::<4>::new(f4);
    let s8 = Scene2d::<8>::new(f8);
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let mut slice = SliceFb::default();
    let mut egfb = Box::new(EgFb::new());
    let mut pixmap = tiny_skia::Pixmap::new(W as u32, H as u32).unwrap();
    let mut out = vec![BG; W * H];
    let covered = s4.covered;
    let mut add = |renderer, target, key: String, ns, differs| {
        peers.push(Peer { scene, renderer, target, key, ns, differs, covered });
    };
    let k = |rest: &str| format!("{scene}/{rest}");
    add(
        "microraster, 16-row bands",
        "slice",
        k("band16/S4/flat"),
        median_ns(|| mr_band(&s4, &mut band, &mut slice)),
        Some(0),
    );
    let mine = slice.px.clone();
    let diff = |px: &[Rgb565]| Some(px.iter().zip(&mine).filter(|(a, b)| a != b).count());
    let mut index = Vec::new();
    let t = median_ns(|| mr_binned(&s4, &mut band, &mut index, &mut slice));
    add(
        "microraster, 16-row bands, binned (Binned2d)",
        "slice",
        k("band16/S4/flat/binned"),
        t,
        diff(&slice.px),
    );
    let t = median_ns(|| mr_band(&s8, &mut band, &mut slice));
    add("microraster, 16-row bands, S = 8", "slice", k("band16/S8/flat"), t, diff(&slice.px));
    let t = median_ns(|| mr_direct(&s4, &mut slice));
    add("microraster, direct (TargetBlitter)", "slice", k("direct/S4/flat"), t, diff(&slice.px));
    if let Some(g) = gouraud {
        let sg = Scene2d::<4>::new(g);
        let t = median_ns(|| mr_band(&sg, &mut band, &mut slice));
        add("microraster, 16-row bands, Gouraud", "slice", k("band16/S4/gouraud"), t, None);
        let t = median_ns(|| mr_direct(&sg, &mut slice));
        add("microraster, direct, Gouraud", "slice", k("direct/S4/gouraud"), t, None);
    }
    let t = median_ns(|| mr_band(&s4, &mut band, &mut *egfb));
    add("microraster, 16-row bands", "e-g Framebuffer", k("band16/S4/flat/egfb"), t, None);
    let t = median_ns(|| mr_direct(&s4, &mut *egfb));
    add("microraster, direct (TargetBlitter)", "e-g Framebuffer", k("direct/S4/flat/egfb"), t, None);
    let t = median_ns(|| eg(&s4, &mut slice));
    add("embedded-graphics 0.8", "slice", k("eg/slice"), t, diff(&slice.px));
    let t = median_ns(|| eg(&s4, &mut *egfb));
    add("embedded-graphics 0.8", "e-g Framebuffer", k("eg/egfb"), t, None);
    let t = median_ns(|| skia(&s4, &mut pixmap));
    let sk: Vec<[u8; 3]> = pixmap.pixels().iter().map(|p| [p.red(), p.green(), p.blue()]).collect();
    let d = sk.iter().zip(&mine).filter(|(a, b)| **a != rgb8(**b)).count();
    add("tiny-skia 0.12 (no AA)", "Pixmap RGBA8", k("skia"), t, Some(d));
    let t = median_ns(|| reference(&s4, &mut out));
    add("f64 reference", "slice", k("reference"), t, diff(&out));

    // Where the band renderer's time goes: the empty frame (clear + send),
    // and the same band loop with the frame's coverage but nothing written
    // (`Coverage`: each primitive drawn as the frame draws it, into a
    // blitter that only counts pixels), less the empty frame.
    let empty: [Primitive<Rgb565, 4>; 0] = [];
    let e = median_ns(|| Renderer::new(H as u32, BG).render(&empty, &mut band, &mut slice).unwrap());
    let covering =
        median_ns(|| Renderer::new(H as u32, BG).render(Coverage(&s4.prims), &mut band, &mut slice).unwrap());
    let spans = (covering - e).max(0.0);
    let full = peers.iter().find(|p| p.scene == scene).map_or(0.0, |p| p.ns);
    breakdown.push(Breakdown { scene, full, empty: e, spans });
}

fn peers3d(peers: &mut Vec<Peer>) {
    let (p32, pfx) = (pipeline3d::<f32, 4>(), pipeline3d::<Fx, 4>());
    let mut bins = Box::new(Bins::<4>::new());
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut slice = SliceFb::default();
    let mut egfb = Box::new(EgFb::new());
    mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let covered = bins
        .iter()
        .map(|t| TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None).map(|s| s.len as u64).sum::<u64>())
        .sum();
    let mine = slice.px.clone();
    // 3D frames differ by colour rounding: count pixels more than one step off.
    let far = |a: Rgb565, b: Rgb565| {
        let d = |x: u8, y: u8| x.abs_diff(y) > 1;
        d(a.r(), b.r()) || d(a.g(), b.g()) || d(a.b(), b.b())
    };
    let diff = |px: &[Rgb565]| Some(px.iter().zip(&mine).filter(|(a, b)| far(**a, **b)).count());
    let mut add = |renderer, target, key: &str, ns, differs| {
        peers.push(Peer {
            scene: "mesh3d",
            renderer,
            target,
            key: format!("mesh3d/{key}"),
            ns,
            differs,
            covered,
        });
    };
    let t = median_ns(|| {
        mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    });
    add("microraster, f32, perspective-correct", "slice", "f32/D16/persp/band16/S4", t, Some(0));
    let t = median_ns(|| {
        mr3d::<Fx, Depth16, PerspectiveCorrect, 4, 16>(&pfx, &mut bins, &mut band, &mut depth, &mut slice);
    });
    add("microraster, Fx, perspective-correct", "slice", "Fx/D16/persp/band16/S4", t, diff(&slice.px));
    let t = median_ns(|| {
        mr3d::<f32, Depth16, Affine, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    });
    add("microraster, f32, affine", "slice", "f32/D16/affine/band16/S4", t, diff(&slice.px));
    let t = median_ns(|| {
        mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut *egfb);
    });
    add("microraster, f32, perspective-correct", "e-g Framebuffer", "f32/D16/persp/band16/S4/egfb", t, None);
    let mut px = vec![RefPixel { id: 0, depth: 0.0, color: [0.0; 3] }; W * H];
    let mut out = vec![BG3; W * H];
    let t = median_ns(|| Ref3d::frame(ANGLE, &mut px, &mut out));
    add("f64 reference pipeline", "slice", "reference", t, diff(&out));
}

fn find<'a>(peers: &'a [Peer], key: &str) -> Option<&'a Peer> {
    peers.iter().find(|p| p.key == key)
}

fn ratio(peers: &[Peer], peer: &str, mine: &str) -> Option<f64> {
    Some(find(peers, peer)?.ns / find(peers, mine)?.ns)
}

fn us(ns: f64) -> String {
    format!("{:.1}", ns / 1000.0)
}

#[allow(clippy::too_many_arguments)]
fn document(
    cpu: &str,
    memset_ns: f64,
    ceiling: f64,
    peers: &[Peer],
    breakdown: &[Breakdown],
    s2: &[Row2d],
    s3: &[Row3d],
    setups: &[(usize, usize)],
    counts: &cortex::Counts,
    fw: &cortex::FwBench,
) -> (String, String) {
    let mut d = String::new();
    let w = &mut d;
    let _ = writeln!(w, "# Speed and accuracy: measurements\n");
    let _ = writeln!(
        w,
        "Generated by `cargo run --release --example report` (`examples/report/`); do not edit by hand: \
         every number below comes from that run. Host: {cpu}. Frames are {W} × {H} `Rgb565`. Times are \
         medians of {} timed batches of about 15 ms of thread CPU time each, single thread. The criterion benchmarks \
         (`cargo bench --bench peers`) measure the same renderers (`benches/common/mod.rs`).\n",
        timing::RUNS
    );
    let _ = writeln!(w, "![microraster against its peers](charts/peers.png)\n");

    // --- Targets
    let targets = targets::section(w, memset_ns, ceiling, peers, breakdown, s3, counts, fw);

    // --- Peers
    let _ = writeln!(w, "## microraster against its peers\n");
    let _ = writeln!(
        w,
        "Same scene, same resolution, same run. Scenes (`microraster_scenes::scenes::benchmarks`, \
         `microraster_scenes::scenes3d`): **scatter** = (1) 1,000 triangles of mixed sizes; **large** = (2) 8 large \
         triangles, fill-rate bound; **tiny** = (3) 10,000 tiny triangles, setup bound; **mesh3d** = (4) the \
         standard 3D scene (1,116 triangles, 16-bit depth, Gouraud, vertex stage included); **lines** = (5) \
         1,000 lines; **knot20k** = the 20,480-triangle knot (10,240 vertices, Gouraud with specular, 16-bit \
         depth, back faces culled; microraster's meshlet stage per band, `benches/common/knot.rs`) against the \
         `euc` crate 0.5 (whole `f32` depth buffer and framebuffer; it interpolates perspective-correct only, so \
         \"× mr\" compares with microraster's perspective-correct frame). Every vertex is a pixel centre, so every renderer gets the same geometry (see \
         `scenes::benchmarks`). Targets: *slice* = a `Vec<Rgb565>` with slice-speed `fill_solid` / \
         `fill_contiguous`; *e-g Framebuffer* = `embedded_graphics::framebuffer::Framebuffer<Rgb565, …>`, whose \
         only drawing primitive is a per-pixel `draw_iter`; tiny-skia only draws RGBA8888. \"× mr\" = this \
         renderer's time ÷ microraster's (16-row bands, S = 4, flat, same target kind where both exist; above 1 \
         microraster is faster). \"differs\" = pixels of the frame that differ from microraster's (for 2D: any \
         difference; for mesh3d: a channel more than one step off).\n"
    );
    let _ = writeln!(
        w,
        "| scene | renderer | target | µs / frame | × mr | ns / pixel written | fill % of ceiling | differs | key |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|");
    for p in peers {
        let base = if p.scene == knot::SCENE {
            knot::BASE
        } else if p.scene == "mesh3d" {
            if p.target == "e-g Framebuffer" {
                "mesh3d/f32/D16/persp/band16/S4/egfb"
            } else {
                "mesh3d/f32/D16/persp/band16/S4"
            }
        } else if p.target == "e-g Framebuffer" {
            &format!("{}/band16/S4/flat/egfb", p.scene)
        } else {
            &format!("{}/band16/S4/flat", p.scene)
        };
        let x = find(peers, base).map_or(f64::NAN, |b| p.ns / b.ns);
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {:.2} | {:.2} | {:.0}% | {} | `{}` |",
            p.scene,
            p.renderer,
            p.target,
            us(p.ns),
            x,
            p.ns / p.covered as f64,
            p.covered as f64 / p.ns / ceiling * 100.0,
            p.differs.map_or("–".into(), |n| n.to_string()),
            p.key
        );
    }
    let _ = writeln!(
        w,
        "\n\"ns / pixel written\" divides by microraster's pixel count for the scene (including overdraw), for \
         every renderer, so it compares like with like. Pixels written per scene: {}.\n",
        ["scatter", "large", "tiny", "lines", "mesh3d", knot::SCENE]
            .iter()
            .filter_map(|s| peers.iter().find(|p| p.scene == *s).map(|p| format!("{s} {}", p.covered)))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let _ = writeln!(
        w,
        "Why the frames differ: embedded-graphics fills every pixel its scanline intersections touch, edges \
         included (so it draws more pixels along every edge) and includes the end pixel of lines; tiny-skia \
         breaks ties toward bottom-right where microraster uses the top-left rule, and its hairlines follow its \
         own stepping; the f64 reference excludes centres exactly on an edge; `S = 8` changes nothing because \
         every vertex is a pixel centre at any S ≥ 1.\n"
    );

    let _ = writeln!(w, "### The real-mesh benchmark: the 20k-triangle knot\n");
    let _ = writeln!(
        w,
        "The knot (20,480 triangles, 10,240 vertices, 320 × 240, Gouraud with specular, 16-bit depth, back faces \
         culled, 16-row bands) on the host against euc, and the same configurations counted on the Cortex-M4F \
         (`examples/fw_bench`, the README's firmware table; static RAM = the buffers it uses) and on the Cortex-M0 \
         (`examples/fw_sweep`, 320 × 240 on QEMU's mps2-an386).\n"
    );
    w.push_str(&knot::readme_table(peers, counts, fw));
    w.push('\n');
    let _ = writeln!(w, "### Where microraster's time goes (16-row bands, slice target)\n");
    let _ = writeln!(
        w,
        "*empty frame* = the band loop with no primitive (clear each band, send it with `fill_contiguous`); \
         *coverage only* = the same band loop with each primitive drawn as the frame draws it (triangle set-up \
         per band, then per-centre tests for a small triangle or the exact per-row span solve for a larger one, \
         or the line walk) into a blitter that counts pixels instead of writing them, less the empty frame; \
         *writing pixels* = the rest.\n"
    );
    let _ = writeln!(
        w,
        "| scene | whole frame µs | empty frame µs | coverage only µs | writing pixels µs (rest) |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|");
    let mut apart = Vec::new();
    for b in breakdown {
        let rest = b.full - b.empty - b.spans;
        let pct = |v: f64| format!("{} ({:.0}%)", us(v), v / b.full * 100.0);
        // Measured apart, the parts need not add up; where they overshoot,
        // the split says nothing and is not printed as one.
        let rest = if rest >= 0.0 {
            pct(rest)
        } else {
            apart.push(b.scene);
            "– (parts exceed the frame)".into()
        };
        let _ =
            writeln!(w, "| {} | {} | {} | {} | {rest} |", b.scene, us(b.full), pct(b.empty), pct(b.spans));
    }
    if !apart.is_empty() {
        let _ = writeln!(
            w,
            "\n{}: counting the pixels instead of writing them took longer than writing them: the counting \
             loop is other machine code than the frame's, so here these parts are not a split of the frame's \
             time.",
            apart.join(", ")
        );
    }
    let _ = writeln!(w);

    // --- Sweep
    let _ = writeln!(w, "## The trade sweep\n");
    let _ = writeln!(
        w,
        "Each knob varied alone from the baseline: S = 4 subpixel bits, 16-bit depth, 16-row bands, \
         perspective-correct colour, f32 vertex math. Cost is host time per frame; the Cortex-M columns are \
         instructions per frame of the same configuration built for the Cortex-M4F (`thumbv7em-none-eabihf`, \
         hardware f32) and the Cortex-M0 (`thumbv6m-none-eabi`: soft float, no divider), counted under QEMU with \
         `-icount shift=0` by `bash scripts/firmware.sh sweep` (`examples/fw_sweep`, frames checked identical to the \
         host's, written to `docs/data/cortex-m.tsv`), \"pending\" until it has run. Instructions, not cycles: no \
         wait states, no bus. Errors:\n\n\
         * **2D mismatches**: pixels of scene 1 whose top triangle differs from an f64 rasterizer on the \
         unsnapped vertices (scene 1 before snapping, `scenes::scatter_fine`, vertices at 1/65536 px; rate = \
         mismatches ÷ pixels the reference covers);\n\
         * **visibility**: pixels of the standard 3D scene whose visible source triangle (or background) \
         differs from an f64 pipeline's (f64 transform, lighting and per-pixel f64 depth test on unsnapped \
         vertices, `benches/common/mod.rs` `Ref3d`); *objects* counts only pixels where the visible mesh differs;\n\
         * **depth error**: stored depth code against the f64 pipeline's `z/w · (2^b − 1)` where both show the \
         same triangle, in LSB of the format (max, mean);\n\
         * **colour error**: 8-bit channel against the exact perspective-correct value on the same screen \
         triangle (f64 barycentrics on the snapped vertices), max and mean over channels and pixels.\n"
    );
    let pc = |x: usize| format!("{x} ({:.2}%)", x as f64 / (W * H) as f64 * 100.0);
    let cm = |key: &str| format!("{} | {}", counts.cell("m4f", key), counts.cell("m0", key));
    let _ = writeln!(w, "### Subpixel bits\n");
    let _ = writeln!(
        w,
        "| S | scene 1 µs | 2D mismatches | rate | 3D frame µs | visibility: triangles | objects | Cortex-M4F | Cortex-M0 | key (2D) |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|");
    for (a, b) in s2.iter().filter(|r| r.knob == "subpixel").zip(s3.iter().filter(|r| r.knob == "subpixel")) {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {:.2e} | {} | {} | {} | {} | `{}` |",
            a.setting,
            us(a.frame_ns),
            a.mismatches,
            a.mismatches as f64 / a.ref_covered as f64,
            us(b.frame_ns),
            pc(b.vis_tri),
            pc(b.vis_obj),
            cm(&a.key),
            a.key
        );
    }
    let _ = writeln!(w, "\n![subpixel bits](charts/pareto_subpixel.png)\n");

    let _ = writeln!(w, "### Depth bits\n");
    let _ = writeln!(
        w,
        "Two depth errors: *rasterizer* = stored code against the exact plane through the same screen \
         triangle's vertex depths (the rasterizer's own rounding; bound 0.5 + 1/8 LSB); *pipeline* = against the \
         f64 pipeline's depth at the same pixel, which adds the f32 vertex stage and vertex snapping (a vertex \
         moves by up to 1/32 px at S = 4, and on steep triangles the depth changes fast across a pixel). The \
         last column puts the pipeline's mean error in units of 2^-16 of the depth range, comparable across \
         formats.\n"
    );
    let _ = writeln!(
        w,
        "| depth | frame µs | depth band bytes | visibility: triangles | objects | rasterizer max (LSB) | mean | pipeline max (LSB) | mean | pipeline mean (2^-16 range) | Cortex-M4F | Cortex-M0 | key |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for r in s3.iter().filter(|r| r.knob == "depth") {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {:.1} | {:.3} | {:.3} | {} | `{}` |",
            r.setting,
            us(r.frame_ns),
            r.band_bytes - Band::<Rgb565, W, 16>::BYTES,
            pc(r.vis_tri),
            pc(r.vis_obj),
            r.raster_depth_max,
            r.raster_depth_mean,
            r.depth_max,
            r.depth_mean,
            r.depth_mean_range,
            cm(&r.key),
            r.key
        );
    }
    let _ = writeln!(w, "\n![depth bits](charts/pareto_depth.png)\n");

    let _ = writeln!(w, "### Band height\n");
    let _ = writeln!(
        w,
        "The image does not depend on the band height (checked here: \"differs\" counts pixels that differ \
         from the 16-row frame); the trade is memory against time. Each band re-runs the set-up of every \
         triangle that touches it: *set-ups* = (triangle, band) pairs of the 3D frame.\n"
    );
    let _ = writeln!(
        w,
        "| band | scene 1 µs | differs | 3D frame µs | differs | band bytes (colour + 16-bit depth) | 3D set-ups | Cortex-M4F | Cortex-M0 | key (3D) |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|");
    for ((a, b), (_, n)) in
        s2.iter().filter(|r| r.knob == "band").zip(s3.iter().filter(|r| r.knob == "band")).zip(setups)
    {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} | {} | {} | `{}` |",
            a.setting,
            us(a.frame_ns),
            a.differs_from_baseline,
            us(b.frame_ns),
            b.differs_from_baseline,
            b.band_bytes,
            n,
            cm(&b.key),
            b.key
        );
    }
    let _ = writeln!(w, "\n![band height](charts/pareto_band.png)\n");

    let _ = writeln!(w, "### Colour interpolation\n");
    let _ =
        writeln!(w, "| interpolation | frame µs | colour error max | mean | Cortex-M4F | Cortex-M0 | key |");
    let _ = writeln!(w, "|---|---|---|---|---|---|---|");
    for r in s3.iter().filter(|r| r.knob == "interpolation") {
        let _ = writeln!(
            w,
            "| {} | {} | {:.2} | {:.3} | {} | `{}` |",
            r.setting,
            us(r.frame_ns),
            r.color_max,
            r.color_mean,
            cm(&r.key),
            r.key
        );
    }
    let _ = writeln!(w, "\n![colour interpolation](charts/pareto_interpolation.png)\n");

    let _ = writeln!(w, "### Vertex math\n");
    let _ = writeln!(
        w,
        "| vertex path | frame µs | vertex stage µs | visibility: triangles | objects | depth error max (LSB) | mean | differs from f32 frame | Cortex-M4F | Cortex-M0 | key |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|---|");
    for r in s3.iter().filter(|r| r.knob == "vertex") {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {} | {} | `{}` |",
            r.setting,
            us(r.frame_ns),
            us(r.vertex_ns),
            pc(r.vis_tri),
            pc(r.vis_obj),
            r.depth_max,
            r.depth_mean,
            r.differs_from_baseline,
            cm(&r.key),
            r.key
        );
    }
    let _ = writeln!(w, "\n![vertex math](charts/pareto_vertex.png)\n");
    let _ = writeln!(
        w,
        "The Cortex-M0 target compares the vertex stage alone: keys `mesh3d/vertex/f32` and \
         `mesh3d/vertex/Fx` in `docs/data/cortex-m.tsv` (host vertex stage: f32 {} µs, Fx {} µs).\n",
        s3.iter().find(|r| r.key == "mesh3d/f32/D16/persp/band16/S4").map_or("?".into(), |r| us(r.vertex_ns)),
        s3.iter().find(|r| r.key == "mesh3d/Fx/D16/persp/band16/S4").map_or("?".into(), |r| us(r.vertex_ns)),
    );

    // --- Cost per pixel
    let _ = writeln!(w, "## Cost per pixel by configuration\n");
    let _ = writeln!(
        w,
        "Host ns per pixel written (2D: the scene's pixels with overdraw; 3D: fragments, every pixel of every \
         screen triangle before the depth test) and, once measured, Cortex-M instructions per pixel and per \
         triangle.\n"
    );
    let _ = writeln!(
        w,
        "| configuration | pixels | triangles | host ns / pixel | M4F instr. / pixel | M4F instr. / triangle | M0 instr. / pixel | key |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|");
    for row in cost_rows(peers, s3) {
        let per = |core: &str, n: f64| {
            counts.get(core, &row.key).map_or("pending".into(), |c| format!("{:.1}", c as f64 / n))
        };
        let _ = writeln!(
            w,
            "| {} | {} | {} | {:.2} | {} | {} | {} | `{}` |",
            row.label,
            row.pixels,
            row.tris,
            row.ns / row.pixels as f64,
            per("m4f", row.pixels as f64),
            per("m4f", row.tris as f64),
            per("m0", row.pixels as f64),
            row.key
        );
    }
    let _ = writeln!(w, "\n![cost per pixel](charts/cost_per_pixel.png)\n");
    if counts.any() {
        let _ = writeln!(
            w,
            "![Cortex-M4F instructions per pixel](charts/instructions_per_pixel_m4f.png)\n\n\
             ![Cortex-M0 instructions per pixel](charts/instructions_per_pixel_m0.png)\n"
        );
    }
    if !counts.any() {
        let _ = writeln!(
            w,
            "Cortex-M instruction counts: **pending**. `bash scripts/firmware.sh sweep` writes \
             `docs/data/cortex-m.tsv` (format in `examples/report/cortex.rs`); rerun this command to fill the \
             columns above.\n"
        );
    }
    (d, targets)
}

/// One fragment-stage option: its key, host time and accuracy.
struct FragRow {
    key: &'static str,
    ns: f64,
    accuracy: String,
}

/// The fragment-stage section: each option's cost (host and Cortex-M) next
/// to the plain renderer it replaces, and its accuracy.
fn fragment_section(
    rows: &[FragRow],
    aliased: (f64, f64),
    peers: &[Peer],
    counts: &cortex::Counts,
) -> String {
    let mut d = String::new();
    let w = &mut d;
    let _ = writeln!(w, "## The fragment stage\n");
    let _ = writeln!(
        w,
        "Each option on the standard 3D scene (`mesh3d`: every mesh drawn through it, vertex stage included, \
         16-row bands, 320 × 240 `Rgb565`, 16-bit depth) or on scene 5 (`lines`), against the plain renderer it \
         replaces: `draw_triangle` with Gouraud colour (`mesh3d/f32/D16/persp/band16/S4`) and midpoint lines \
         (`lines/band16/S4/flat`). The configurations are those of the Cortex-M counts (`examples/fw_sweep/fragment.rs`), \
         timed on the host between the same brackets. Textures: the demo's 64 × 64 bricks (`assets/bricks.png`), \
         planar coordinates, several repeats per mesh. Accuracy: texture error on a receding textured floor \
         against f64 sampling (nearest or bilinear) of exactly perspective-correct coordinates, interior pixels, \
         8-bit channel steps (affine coordinates are wrong by design: the error is the swim; nearest sampling picks the neighbouring \
         texel where the coordinate lies within its error bound of a texel edge, hence a rare large maximum); coverage error over \
         the pixels an edge crosses of 400 random triangles (2–40 px) drawn alone white on black, resolved value \
         against the exact area of the snapped triangle in the pixel (the aliased renderer: max {:.3}, mean {:.4}).\n",
        aliased.0, aliased.1
    );
    let base_ns = |k: &str| find(peers, k).map_or(f64::NAN, |p| p.ns);
    let _ = writeln!(
        w,
        "| option | host µs / frame | × plain (host) | Cortex-M4F instr. | × plain (M4F) | Cortex-M0 instr. | accuracy | key |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|");
    for r in rows {
        let plain = if r.key.starts_with("lines") {
            "lines/band16/S4/flat"
        } else {
            "mesh3d/f32/D16/persp/band16/S4"
        };
        let m4 = counts.get("m4f", r.key);
        let ratio_m4 = match (m4, counts.get("m4f", plain)) {
            (Some(a), Some(b)) => format!("{:.2}", a as f64 / b as f64),
            _ => "pending".into(),
        };
        let _ = writeln!(
            w,
            "| {} | {} | {:.2} | {} | {} | {} | {} | `{}` |",
            r.key.split_once('/').map_or(r.key, |(_, rest)| rest),
            us(r.ns),
            r.ns / base_ns(plain),
            counts.cell("m4f", r.key),
            ratio_m4,
            counts.cell("m0", r.key),
            r.accuracy,
            r.key
        );
    }
    let aliased_b = Band::<Rgb565, W, 16>::BYTES + DepthBand::<Depth16, W, 16>::BYTES;
    let grid2 = Band::<Rgb565, { 2 * W }, 32>::BYTES
        + DepthBand::<Depth16, { 2 * W }, 32>::BYTES
        + Band::<Rgb565, W, 16>::BYTES;
    let sparse4 =
        Band::<Rgb565, W, 64>::BYTES + DepthBand::<Depth16, W, 64>::BYTES + Band::<Rgb565, W, 16>::BYTES;
    let _ = writeln!(
        w,
        "\nMemory per 16-row band (320 px, `Rgb565` + 16-bit depth): aliased {aliased_b} B; 2 × 2 samples \
         (`Ssaa<2>`, `Msaa<2>`) {grid2} B, 4 sparse samples (`MsaaSparse<4>`) {sparse4} B (sample colour and depth \
         bands plus the output band). Code a scene does not use is not linked: `bash scripts/code-size.sh`.\n"
    );
    d
}

/// Replaces the README's generated tables (between its
/// `<!-- NAME:begin -->` and `<!-- NAME:end -->` markers) with this run's:
/// the targets table and the knot's summary.
fn update_readme(path: &Path, tables: &[(&str, String)]) -> Res<()> {
    let mut text = std::fs::read_to_string(path)?;
    for (name, body) in tables {
        let (begin, end) = (format!("<!-- {name}:begin -->"), format!("<!-- {name}:end -->"));
        let (Some(a), Some(b)) = (text.find(&begin), text.find(&end)) else {
            return Err(format!("{}: no {begin} … {end} markers", path.display()).into());
        };
        let table = format!(
            "{begin}\nFrom `docs/tradeoffs.md` (written with this table by `cargo run --release --example report`):\n\n{body}"
        );
        text = format!("{}{table}{}", &text[..a], &text[b..]);
    }
    std::fs::write(path, text)?;
    Ok(())
}

struct CostRow {
    label: String,
    key: String,
    pixels: u64,
    tris: usize,
    ns: f64,
}

fn cost_rows(peers: &[Peer], s3: &[Row3d]) -> Vec<CostRow> {
    let mut rows = Vec::new();
    for p in peers.iter().filter(|p| p.renderer.starts_with("microraster") && p.scene != "mesh3d") {
        let tris = match p.scene {
            "scatter" => scenes::SCATTER_LEN,
            "large" => scenes::LARGE_LEN,
            "tiny" => scenes::TINY_LEN,
            knot::SCENE => knot_renderers::triangles(),
            _ => scenes::LINES_LEN,
        };
        let label =
            format!("{}: {} -> {}", p.scene, p.renderer.trim_start_matches("microraster, "), p.target);
        rows.push(CostRow { label, key: p.key.clone(), pixels: p.covered, tris, ns: p.ns });
    }
    let mut seen = std::collections::HashSet::new();
    for r in s3 {
        if seen.insert(r.key.clone()) {
            let label = format!("mesh3d: {} {}", r.knob, r.setting);
            rows.push(CostRow {
                label,
                key: r.key.clone(),
                pixels: r.fragments,
                tris: r.tris,
                ns: r.frame_ns,
            });
        }
    }
    rows
}

fn draw_charts(
    dir: &Path,
    ceiling: f64,
    peers: &[Peer],
    s2: &[Row2d],
    s3: &[Row3d],
    counts: &cortex::Counts,
) -> Res<()> {
    // Peers: how many times longer each peer takes than microraster.
    let mut bars = Vec::new();
    for p in peers {
        let base = match (p.scene, p.target) {
            ("mesh3d", _) => "mesh3d/f32/D16/persp/band16/S4".to_string(),
            (knot::SCENE, _) => knot::BASE.to_string(),
            (s, "e-g Framebuffer") => format!("{s}/band16/S4/flat/egfb"),
            (s, _) => format!("{s}/band16/S4/flat"),
        };
        let peer = !p.renderer.starts_with("microraster");
        if let (true, Some(b)) = (peer, find(peers, &base)) {
            let short_target = if p.target == "e-g Framebuffer" { " (e-g fb)" } else { "" };
            let name = p.renderer.split(' ').next().unwrap_or(p.renderer);
            bars.push((format!("{}: {name}{short_target}", p.scene), p.ns / b.ns));
        }
    }
    charts::bar_chart(
        &dir.join("peers.png"),
        "Peer frame time / microraster frame time (>1: microraster faster)",
        "times microraster's frame time (log)",
        &bars,
        true,
        Some(1.0),
    )?;

    let cost: Vec<(String, f64)> =
        cost_rows(peers, s3).into_iter().map(|r| (r.label, r.ns / r.pixels as f64)).collect();
    let mut cost = cost;
    cost.push(("slice fill (ceiling)".into(), 1.0 / ceiling));
    charts::bar_chart(
        &dir.join("cost_per_pixel.png"),
        "Host cost per pixel written",
        "ns per pixel (log)",
        &cost,
        true,
        None,
    )?;

    // Cortex-M instructions per pixel written, where counted.
    for (core, name) in [("m4f", "Cortex-M4F"), ("m0", "Cortex-M0")] {
        let bars: Vec<(String, f64)> = cost_rows(peers, s3)
            .into_iter()
            .filter_map(|r| counts.get(core, &r.key).map(|n| (r.label, n as f64 / r.pixels as f64)))
            .collect();
        if !bars.is_empty() {
            charts::bar_chart(
                &dir.join(format!("instructions_per_pixel_{core}.png")),
                &format!("{name} instructions per pixel written (QEMU count)"),
                "instructions per pixel (log)",
                &bars,
                true,
                None,
            )?;
        }
    }

    let pts = |rows: Vec<(String, f64, f64)>| -> Vec<Point2> {
        rows.into_iter().map(|(label, x, y)| Point2 { label, x, y }).collect()
    };
    let p = pts(s2
        .iter()
        .filter(|r| r.knob == "subpixel")
        .map(|r| (r.setting.clone(), r.frame_ns / 1000.0, r.mismatches as f64 / r.ref_covered as f64 * 100.0))
        .collect());
    charts::pareto_chart(
        &dir.join("pareto_subpixel.png"),
        "Subpixel bits: scene 1 time vs pixels unlike f64",
        "µs per frame (16-row bands)",
        "% of covered pixels differing",
        &p,
        true,
    )?;
    let p = pts(s3
        .iter()
        .filter(|r| r.knob == "depth")
        .map(|r| (r.setting.clone(), r.frame_ns / 1000.0, r.vis_tri as f64))
        .collect());
    charts::pareto_chart(
        &dir.join("pareto_depth.png"),
        "Depth bits: 3D frame time vs visibility errors",
        "µs per frame",
        "pixels whose visible triangle differs",
        &p,
        false,
    )?;
    let p = pts(s3
        .iter()
        .filter(|r| r.knob == "band")
        .map(|r| (r.setting.clone(), r.frame_ns / 1000.0, r.band_bytes as f64 / 1024.0))
        .collect());
    charts::pareto_chart(
        &dir.join("pareto_band.png"),
        "Band height: 3D frame time vs band memory (image identical)",
        "µs per frame",
        "KiB of colour + depth band",
        &p,
        false,
    )?;
    let p = pts(s3
        .iter()
        .filter(|r| r.knob == "interpolation")
        .map(|r| (r.setting.clone(), r.frame_ns / 1000.0, r.color_mean))
        .collect());
    charts::pareto_chart(
        &dir.join("pareto_interpolation.png"),
        "Colour interpolation: 3D frame time vs colour error",
        "µs per frame",
        "mean error (8-bit steps)",
        &p,
        false,
    )?;
    let p = pts(s3
        .iter()
        .filter(|r| r.knob == "vertex")
        .map(|r| (r.setting.clone(), r.frame_ns / 1000.0, r.vis_tri as f64))
        .collect());
    charts::pareto_chart(
        &dir.join("pareto_vertex.png"),
        "Vertex math: 3D frame time vs visibility errors",
        "µs per frame",
        "pixels whose visible triangle differs",
        &p,
        false,
    )?;
    Ok(())
}

/// The 2D shapes against their peers: criterion's medians of the last
/// `cargo bench --bench shapes` run (read only; not measured here).
fn shapes_section() -> String {
    let mut d = String::from("## 2D shapes against their peers\n\n");
    d += "Each shape (24 instances, 8 to 120 px, 320 × 240 `Rgb565`) against embedded-graphics' and tiny-skia's same \
          shape: criterion's medians of the last `cargo bench --bench shapes` run (`benches/shapes.rs`), read from \
          `target/criterion` when this report was written, not measured by it (> 1: microraster faster).\n\n";
    match shapes_ratios::table("[README](../README.md#the-dashboard)") {
        Some(table) => d += &table,
        None => {
            d += "*Not available: no complete `cargo bench --bench shapes` run in `target/criterion` when this \
                      report was written. Run it, then the report.*\n"
        }
    }
    d
}
