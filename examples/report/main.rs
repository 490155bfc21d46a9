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

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth8, Depth16, Depth24, Depth32};
use microraster::math::Fx;
use microraster::raster3d::{Affine, PerspectiveCorrect};
use microraster_scenes::scenes;
use std::path::{Path, PathBuf};

mod charts;
#[path = "../../benches/common/mod.rs"]
mod common;
mod cortex;
#[path = "../../benches/common/criterion_median.rs"]
mod criterion_median;
#[path = "../common/group.rs"]
mod digits;
mod document;
mod figures;
mod frag_report;
mod knot;
mod peer_runs;
mod sections;
#[path = "../common/shapes_ratios.rs"]
mod shapes_ratios;
mod sweep;
mod targets;
mod tiers;
// The knot's two cameras and the tiers' pipelines (issue 61), as fw_bench's.
#[path = "../common/knot_eye.rs"]
mod knot_eye;
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
#[path = "../common/knot_mesh.rs"]
mod knot_mesh;
// The knot's renderers (microraster's meshlet stage and euc), shared with the benchmarks.
#[path = "../../benches/common/knot.rs"]
mod knot_renderers;
mod timing;

use common::*;
use document::document;
use figures::draw_charts;
use peer_runs::{Breakdown, peers2d, peers3d};
use sections::{FragRow, fragment_section, shapes_section};
use sweep::Row3d;
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
    let fw =
        cortex::FwBench::load(&out.join("data/fw-bench.tsv"))?.with_tgx(&out.join("data/peers-tgx.tsv"))?;
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
    let knot_split = knot::peers(&mut peers);

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

    eprintln!("report: accuracy tiers");
    let tier_errors = tiers::measure();
    let tiers_md = tiers::section(&tier_errors, &fw);

    eprintln!("report: charts and tables");
    let (mut doc, targets) = document(
        &cpu,
        memset_ns,
        ceiling,
        &peers,
        &breakdown,
        &knot_split,
        &s2,
        &s3,
        &setups,
        &counts,
        &fw,
        &tiers_md,
    );
    doc.push_str(&fragment_section(&frag, aliased_coverage, &peers, &counts));
    doc.push_str(&shapes_section());
    std::fs::write(out.join("tradeoffs.md"), doc)?;
    // docs/performance.md quotes the targets table; keep it in step when writing docs/.
    let performance = out.join("performance.md");
    if out.ends_with("docs") && performance.exists() {
        update_readme(
            &performance,
            &[
                ("targets", targets),
                ("knot", knot::readme_table(&peers, &counts, &fw)),
                ("tiers", tiers::readme(&tier_errors, &fw, &peers)),
            ],
        )?;
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

fn find<'a>(peers: &'a [Peer], key: &str) -> Option<&'a Peer> {
    peers.iter().find(|p| p.key == key)
}

fn ratio(peers: &[Peer], peer: &str, mine: &str) -> Option<f64> {
    Some(find(peers, peer)?.ns / find(peers, mine)?.ns)
}

fn us(ns: f64) -> String {
    format!("{:.1}", ns / 1000.0)
}

/// Replaces docs/performance.md's generated tables (between its
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
