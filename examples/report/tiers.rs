//! The accuracy tier as a trade knob (issue 61): the fast tier's frames
//! against the exact tier's, pixel by pixel on the host, beside the
//! Cortex-M4F instructions of both (`docs/data/fw-bench.tsv`); and the
//! README's "which tier" table from the same numbers.
//!
//! Frames are drawn in one 240-row band (a whole colour and depth frame;
//! both tiers are band-invariant, so these are the 16-row frames' pixels)
//! and compared where both tiers cover a pixel: the share of those pixels
//! whose three RGB565 channels are all within ±1 of the exact tier's, the
//! largest channel difference, the largest `Depth16` code difference, and
//! apart the pixels only one tier covers (its own snapped vertices move a
//! silhouette edge by up to one subpixel).

use crate::common::{BG3, Bins, H, SliceFb, W, mr3d};
use crate::cortex::FwBench;
use crate::knot_eye::{self, Eye};
use crate::knot_mesh::VALID_KNOT;
use crate::knot_renderers::mr_knot_of;
use crate::targets::group;
use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::Band;
use microraster::depth::{Depth16, DepthBand};
use microraster::pipeline::ClusterCache;
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, Precision};
use std::fmt::Write as _;

/// The bounds: ±1 per channel on this share of covered pixels…
const WITHIN_ONE: f64 = 0.999;
/// …±2 everywhere, depth within ±1 code.
const MAX_CHANNEL: u8 = 2;
const MAX_DEPTH: u32 = 1;

/// One frame compared across tiers.
pub struct TierError {
    /// What is drawn.
    pub label: &'static str,
    /// `docs/data/fw-bench.tsv` keys of the exact and the fast frame.
    pub keys: [&'static str; 2],
    /// Pixels covered in both tiers.
    pub both: usize,
    /// Of those, pixels whose channels are all within ±1.
    pub within_one: usize,
    /// Largest channel difference (RGB565 steps) where both cover.
    pub max_channel: u8,
    /// Largest depth code difference where both cover.
    pub max_depth: u32,
    /// Pixels covered by one tier only.
    pub coverage_differs: usize,
}

impl TierError {
    /// Whether the bounds hold on this frame.
    pub fn within_bounds(&self) -> bool {
        self.within_one as f64 >= WITHIN_ONE * self.both as f64
            && self.max_channel <= MAX_CHANNEL
            && self.max_depth <= MAX_DEPTH
    }
}

/// One whole frame: colours and depth codes, row by row.
type Frame = (Vec<Rgb565>, Vec<u32>);

/// Draws `eye`'s knot in tier `p` with interpolation `M`.
fn knot<M: Interpolation + Default>(eye: Eye, p: Precision) -> Frame {
    let pipeline = knot_eye::pipeline::<f32, 4>(eye, p, W as u32, H as u32).expect("the knot's pipeline");
    let mut cache = Box::new(ClusterCache::new());
    let mut band = Box::new(Band::<Rgb565, W, H>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, H>::new());
    let mut fb = SliceFb::default();
    mr_knot_of::<f32, M, f32, H>(&VALID_KNOT, &pipeline, &mut cache, &mut band, &mut depth, &mut fb);
    (fb.px, depths(&depth))
}

/// Draws the standard scene in tier `p`, perspective-correct.
fn scene(p: Precision) -> Frame {
    let pipeline =
        knot_eye::pipeline::<f32, 4>(Eye::Standard, p, W as u32, H as u32).expect("the scene's pipeline");
    let mut bins = Box::new(Bins::<4>::new());
    let mut band = Box::new(Band::<Rgb565, W, H>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, H>::new());
    let mut fb = SliceFb::default();
    mr3d::<f32, Depth16, PerspectiveCorrect, 4, H>(&pipeline, &mut bins, &mut band, &mut depth, &mut fb);
    (fb.px, depths(&depth))
}

fn depths(d: &DepthBand<Depth16, W, H>) -> Vec<u32> {
    (0..H).flat_map(|y| (0..W).map(move |x| d.get(y, x).unwrap_or(0))).collect()
}

/// Compares the fast frame with the exact one.
fn compare(label: &'static str, keys: [&'static str; 2], exact: Frame, fast: Frame) -> TierError {
    let mut e =
        TierError { label, keys, both: 0, within_one: 0, max_channel: 0, max_depth: 0, coverage_differs: 0 };
    for i in 0..exact.0.len() {
        let (a, b) = (exact.0[i], fast.0[i]);
        match (a != BG3, b != BG3) {
            (true, true) => {
                let d = [a.r().abs_diff(b.r()), a.g().abs_diff(b.g()), a.b().abs_diff(b.b())];
                let m = d.into_iter().max().unwrap_or(0);
                e.both += 1;
                e.within_one += usize::from(m <= 1);
                e.max_channel = e.max_channel.max(m);
                e.max_depth = e.max_depth.max(exact.1[i].abs_diff(fast.1[i]));
            }
            (false, false) => {}
            _ => e.coverage_differs += 1,
        }
    }
    e
}

/// Draws and compares every frame of the table (a few frames: seconds).
pub fn measure() -> Vec<TierError> {
    use Precision::{Exact, Fast};
    vec![
        compare(
            "knot, f32, affine",
            ["knot20k/meshlets-per-band-f32-affine", "knot20k/meshlets-per-band-f32-affine-fast-tier"],
            knot::<Affine>(Eye::Standard, Exact),
            knot::<Affine>(Eye::Standard, Fast),
        ),
        compare(
            "knot, f32, perspective-correct",
            [
                "knot20k/meshlets-per-band-f32-persp-correct",
                "knot20k/meshlets-per-band-f32-persp-correct-fast-tier",
            ],
            knot::<PerspectiveCorrect>(Eye::Standard, Exact),
            knot::<PerspectiveCorrect>(Eye::Standard, Fast),
        ),
        compare(
            "knot, eye twice as close, f32, affine",
            [
                "knot20k-close/meshlets-per-band-f32-affine-eye-twice-as-close",
                "knot20k-close/meshlets-per-band-f32-affine-fast-tier-eye-twice-as-close",
            ],
            knot::<Affine>(Eye::Close, Exact),
            knot::<Affine>(Eye::Close, Fast),
        ),
        compare(
            "standard scene, f32, perspective-correct",
            ["scene3d/f32-persp-correct", "scene3d/f32-persp-correct-fast-tier"],
            scene(Exact),
            scene(Fast),
        ),
    ]
}

/// Instructions of a row, grouped, or "pending".
fn instr(fw: &FwBench, key: &str) -> String {
    fw.get("m4f", key).map_or("pending".into(), |r| group(r.instructions))
}

/// The fast tier's speed-up on a frame (exact ÷ fast instructions).
fn speedup(fw: &FwBench, e: &TierError) -> String {
    match (fw.get("m4f", e.keys[0]), fw.get("m4f", e.keys[1])) {
        (Some(a), Some(b)) => format!("{:.2}×", a.instructions as f64 / b.instructions as f64),
        _ => "pending".into(),
    }
}

fn share(e: &TierError) -> String {
    format!("{:.3} %", 100.0 * e.within_one as f64 / e.both.max(1) as f64)
}

/// The "Accuracy tier" part of the trade sweep (`docs/tradeoffs.md`).
pub fn section(errors: &[TierError], fw: &FwBench) -> String {
    let mut w = String::new();
    let _ = writeln!(w, "### Accuracy tier (`Precision::Exact` / `Precision::Fast`)\n");
    let _ = writeln!(
        w,
        "The fast tier (`Pipeline::with_precision(Precision::Fast)`) against the exact tier, the library's \
         reference pixels: each frame drawn in both tiers on the host and compared pixel by pixel where both \
         cover it; Cortex-M4F instructions per frame from `docs/data/fw-bench.tsv` (`bash scripts/firmware.sh \
         table`, QEMU icount). Bounds (issue 61): every channel within ±1 on ≥ {:.1} % of the pixels, ±{MAX_CHANNEL} \
         everywhere, depth within ±{MAX_DEPTH} code. \"edge pixels\": covered by one tier only (its own snapped \
         vertices, within one subpixel of the exact tier's, move silhouette edges).\n",
        WITHIN_ONE * 100.0
    );
    let _ = writeln!(
        w,
        "| frame | exact: instructions | fast: instructions | speed-up | pixels compared | within ±1 | max channel error | max depth error (codes) | edge pixels | bounds |"
    );
    let _ = writeln!(w, "|---|--:|--:|--:|--:|--:|--:|--:|--:|---|");
    for e in errors {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            e.label,
            instr(fw, e.keys[0]),
            instr(fw, e.keys[1]),
            speedup(fw, e),
            group(e.both as u64),
            share(e),
            e.max_channel,
            e.max_depth,
            group(e.coverage_differs as u64),
            if e.within_bounds() { "held" } else { "**broken**" }
        );
    }
    let _ = writeln!(w);
    let _ = writeln!(w, "{}", pareto(fw));
    w
}

/// Instructions against RAM for taller bands, both tiers (the knot, f32,
/// affine): what more RAM buys.
pub fn pareto(fw: &FwBench) -> String {
    let mut w = String::new();
    let rows: [(u32, [&str; 2]); 4] = [
        (16, ["knot20k/meshlets-per-band-f32-affine", "knot20k/meshlets-per-band-f32-affine-fast-tier"]),
        (
            20,
            [
                "knot20k-rows/meshlets-f32-affine-20-row-bands",
                "knot20k-rows/meshlets-f32-affine-20-row-bands-fast-tier",
            ],
        ),
        (
            32,
            [
                "knot20k-rows/meshlets-f32-affine-32-row-bands",
                "knot20k-rows/meshlets-f32-affine-32-row-bands-fast-tier",
            ],
        ),
        (
            48,
            [
                "knot20k-rows/meshlets-f32-affine-48-row-bands",
                "knot20k-rows/meshlets-f32-affine-48-row-bands-fast-tier",
            ],
        ),
    ];
    let tgx = fw.tgx("standard");
    let x =
        |n: u64| tgx.map_or(String::new(), |t| format!(" ({:.2}× TGX)", n as f64 / t.instructions as f64));
    let _ = writeln!(
        w,
        "Instructions against RAM (the knot, f32, affine, Cortex-M4F; RAM: the colour and `Depth16` bands and the \
         cluster cache):\n"
    );
    let _ = writeln!(w, "| bands | RAM (B) | exact tier | fast tier |\n|---|--:|--:|--:|");
    for (h, [e, f]) in rows {
        let (re, rf) = (fw.get("m4f", e), fw.get("m4f", f));
        let ram = re.or(rf).map_or("pending".into(), |r| group(r.static_ram));
        let cell = |r: Option<crate::cortex::FwRow>| {
            r.map_or("pending".into(), |r| format!("{}{}", group(r.instructions), x(r.instructions)))
        };
        let _ = writeln!(w, "| {h} rows | {ram} | {} | {} |", cell(re), cell(rf));
    }
    if let Some(t) = tgx {
        let _ = writeln!(
            w,
            "| TGX: full framebuffer and z-buffer | {} | {} | – |",
            group(t.static_ram),
            group(t.instructions)
        );
    }
    w
}

/// The README's "which tier" table (between its `tiers:begin/end` markers).
pub fn readme(errors: &[TierError], fw: &FwBench, peers: &[crate::Peer]) -> String {
    let mut w = String::new();
    let _ = writeln!(
        w,
        "| frame (Cortex-M4F, 320 × 240, 16-row bands) | exact tier | fast tier | fast: within ±1 | max channel / depth error |"
    );
    let _ = writeln!(w, "|---|--:|--:|--:|--:|");
    for e in errors {
        let tgx = if e.keys[0].starts_with("knot20k-close") { fw.tgx("close") } else { fw.tgx("standard") };
        let cell = |k: &str| {
            let n = instr(fw, k);
            match (fw.get("m4f", k), tgx.filter(|_| k.starts_with("knot"))) {
                (Some(r), Some(t)) => {
                    format!("{n} ({:.2}× TGX)", r.instructions as f64 / t.instructions as f64)
                }
                _ => n,
            }
        };
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} / {} |",
            e.label,
            cell(e.keys[0]),
            cell(e.keys[1]),
            share(e),
            e.max_channel,
            e.max_depth
        );
    }
    // The same knot frames timed on the host by `knot::peers`: there a
    // division costs several multiplies, which QEMU's icount (one count per
    // `VDIV.F32`) does not show.
    let t = |k: &str| crate::find(peers, k).map(|p| p.ns);
    let pairs = [(crate::knot::BASE, crate::knot::FAST), (crate::knot::AFFINE, crate::knot::FAST_AFFINE)];
    if let [(Some(a), Some(b)), (Some(c), Some(d))] = pairs.map(|(e, f)| (t(e), t(f))) {
        let _ = writeln!(
            w,
            "\nOn the host (this run of the report, 16-row bands), where a division costs several multiplies, \
             the knot's frame takes {} µs in the fast tier against {} µs in the exact tier perspective-correct \
             (exact ÷ fast: {:.2}) and {} µs against {} µs affine ({:.2}); one run on a shared host, which moves \
             such times by up to ±20 %. The Cortex-M4F columns are QEMU's icount, which counts a `VDIV.F32` as \
             one instruction however many cycles it takes on silicon (14 on a Cortex-M4F).",
            crate::us(b),
            crate::us(a),
            a / b,
            crate::us(d),
            crate::us(c),
            c / d
        );
    }
    w
}
