//! The shape ratio table of `cargo bench --bench shapes`, from criterion's
//! medians of its last run (`target/criterion`, read only): each shape and
//! the dashboard frame against embedded-graphics and tiny-skia. Shared
//! (`#[path]`) by `examples/readme_2d.rs` (the README) and
//! `examples/report` (`docs/tradeoffs.md`); the caller includes
//! `benches/common/criterion_median.rs` as `criterion_median`.

use crate::criterion_median::median;

pub const SHAPES: [(&str, &str); 10] = [
    ("rect", "rect"),
    ("rounded", "rounded rect"),
    ("circle", "circle"),
    ("ellipse", "ellipse"),
    ("arc", "arc (stroke 5 px)"),
    ("sector", "sector"),
    ("polygon", "polygon (star)"),
    ("polyline", "polyline (stroke 5 px)"),
    ("triangle", "triangle"),
    ("line", "line (stroke 5 px)"),
];

/// Peer / microraster (> 1: microraster faster).
pub fn ratio(peer: Option<f64>, ours: Option<f64>) -> Option<f64> {
    peer.zip(ours).map(|(p, o)| p / o)
}

/// The verdict of one row from its ratios: `met` when each is at least 1.0,
/// else by how much the slowest misses (its peer / microraster ratio's
/// inverse: how many times faster microraster must become).
pub fn verdict(ratios: &[Option<f64>]) -> String {
    let worst = ratios.iter().flatten().fold(f64::INFINITY, |a, &b| a.min(b));
    if worst == f64::INFINITY {
        "–".into()
    } else if worst >= 1.0 {
        "met".into()
    } else {
        format!("missed by {:.2}×", 1.0 / worst)
    }
}

/// The ratio table and its verdicts (ratio ≥ 1.0 wanted in every column),
/// if every shape was measured; `dashboard` links to the dashboard's
/// description.
pub fn table(dashboard: &str) -> Option<String> {
    let cell = |r: Option<f64>| r.map_or("–".into(), |r| format!("{r:.2}"));
    let mut rows = String::from(
        "| shape | e-g / direct | e-g / bands | e-g / prepared bands | tiny-skia / bands | tiny-skia AA / AA bands | verdict (≥ 1.0) |\n\
         |---|--:|--:|--:|--:|--:|---|\n",
    );
    let (mut met, mut total, mut fill_worst) = (0, 0, f64::INFINITY);
    for (name, label) in SHAPES {
        let g = format!("shape_{name}");
        let m = |id: &str| median(&g, id);
        median(&g, "mr_band16")?;
        let r = [
            ratio(m("eg"), m("mr_direct")),
            ratio(m("eg"), m("mr_band16")),
            ratio(m("skia"), m("mr_band16")),
            ratio(m("skia_aa"), m("mr_aa_band16")),
        ];
        // The same bands with each shape's edges built once a frame
        // (`shape::Prepared`, in the timed frame): the verdict takes the
        // faster of the two banded ways, as a user would.
        let prepared = ratio(m("eg"), m("mr_band16_prepared"));
        let banded = r[1].into_iter().chain(prepared).reduce(f64::max);
        for v in r.iter().flatten() {
            total += 1;
            met += usize::from(*v >= 1.0);
        }
        for v in [r[0], banded, r[2], r[3]].iter().flatten() {
            if !matches!(name, "arc" | "polyline" | "line") {
                fill_worst = fill_worst.min(*v);
            }
        }
        rows += &format!(
            "| {label} | {} | {} | {} | {} | {} | {} |\n",
            cell(r[0]),
            cell(r[1]),
            cell(prepared),
            cell(r[2]),
            cell(r[3]),
            verdict(&[r[0], banded, r[2], r[3]])
        );
    }
    let dash = ratio(median("dashboard", "eg"), median("dashboard", "mr_band16"))?;
    rows += &format!(
        "\nmicroraster is at least as fast in {met} of {total} comparisons (the prepared column not \
         counted); the slowest filled shape takes {:.1}× its peer's time (the faster banded way). \
         The e-g verdict takes the faster of the two banded ways: \"bands\" builds each shape's \
         edges in every band it meets, \"prepared bands\" once a frame (`Styled::prepare`, then \
         `Prepared::set` each frame, inside the timed frame), the same pixels. The dashboard frame ({dashboard}; microraster in 16-row \
         bands, e-g into a framebuffer): e-g / microraster = {:.2} ({}).\n",
        1.0 / fill_worst,
        dash,
        if dash >= 1.0 { "microraster faster" } else { "e-g faster" }
    );
    if let Some((e, m)) = median("floor", "eg").zip(median("floor", "mr_band16")) {
        rows += &format!(
            "\nThe empty frame (what every banded row pays before any shape: each band cleared \
             and copied out): {:.1} µs in 16-row bands, against e-g's wipe of the framebuffer, \
             {:.1} µs.\n",
            m / 1e3,
            e / 1e3
        );
    }
    Some(rows)
}
