//! The shape ratio table of `cargo bench --bench shapes`, from criterion's
//! medians of its last run (`target/criterion`, read only): each shape and
//! the dashboard frame against embedded-graphics and tiny-skia. Shared
//! (`#[path]`) by `examples/readme_2d.rs` (the README) and
//! `examples/report` (`docs/tradeoffs.md`); the caller includes
//! `benches/common/criterion_median.rs` as `criterion_median`.

use crate::criterion_median::median;

pub const SHAPES: [(&str, &str); 8] = [
    ("rect", "rect"),
    ("rounded", "rounded rect"),
    ("circle", "circle"),
    ("ellipse", "ellipse"),
    ("arc", "arc (stroke 5 px)"),
    ("sector", "sector"),
    ("polygon", "polygon (star)"),
    ("polyline", "polyline (stroke 5 px)"),
];

/// Peer / microraster (> 1: microraster faster).
pub fn ratio(peer: Option<f64>, ours: Option<f64>) -> Option<f64> {
    peer.zip(ours).map(|(p, o)| p / o)
}

/// The ratio table and its verdicts, if every shape was measured;
/// `dashboard` links to the dashboard's description.
pub fn table(dashboard: &str) -> Option<String> {
    let cell = |r: Option<f64>| r.map_or("–".into(), |r| format!("{r:.2}"));
    let mut rows = String::from(
        "| shape | e-g / direct | tiny-skia / bands | tiny-skia AA / AA bands |\n|---|---|---|---|\n",
    );
    let (mut faster, mut total, mut fill_worst) = (0, 0, f64::INFINITY);
    for (name, label) in SHAPES {
        let g = format!("shape_{name}");
        let m = |id: &str| median(&g, id);
        median(&g, "mr_band16")?;
        let r = [
            ratio(m("eg"), m("mr_direct")),
            ratio(m("skia"), m("mr_band16")),
            ratio(m("skia_aa"), m("mr_aa_band16")),
        ];
        for v in r.iter().flatten() {
            total += 1;
            faster += usize::from(*v > 1.0);
            if !matches!(name, "arc" | "polyline") {
                fill_worst = fill_worst.min(*v);
            }
        }
        rows += &format!("| {label} | {} | {} | {} |\n", cell(r[0]), cell(r[1]), cell(r[2]));
    }
    let dash = ratio(median("dashboard", "eg"), median("dashboard", "mr_band16"))?;
    rows += &format!(
        "\nmicroraster is faster in {faster} of {total} comparisons; the slowest filled shape \
         takes {:.1}× its peer's time. The dashboard frame ({dashboard}; microraster in 16-row \
         bands, e-g into a framebuffer): e-g / microraster = {:.2} ({}).\n",
        1.0 / fill_worst,
        dash,
        if dash >= 1.0 { "microraster faster" } else { "e-g faster" }
    );
    Some(rows)
}
