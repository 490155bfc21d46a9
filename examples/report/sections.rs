//! The document's last sections: the fragment stage and the 2D shapes against their peers.

use super::{Peer, find, us};
use crate::common::W;
use crate::{cortex, shapes_ratios};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Band;
use microraster::depth::{Depth16, DepthBand};
use std::fmt::Write as _;

/// One fragment-stage option: its key, host time and accuracy.
pub(crate) struct FragRow {
    pub(crate) key: &'static str,
    pub(crate) ns: f64,
    pub(crate) accuracy: String,
}

/// The fragment-stage section: each option's cost (host and Cortex-M) next
/// to the plain renderer it replaces, and its accuracy.
pub(crate) fn fragment_section(
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

/// The 2D shapes against their peers: criterion's medians of the last
/// `cargo bench --bench shapes` run (read only; not measured here).
pub(crate) fn shapes_section() -> String {
    let mut d = String::from("## 2D shapes against their peers\n\n");
    d += "Each shape (24 instances, 8 to 120 px, 320 × 240 `Rgb565`) against embedded-graphics' and tiny-skia's same \
          shape: criterion's medians of the last `cargo bench --bench shapes` run (`benches/shapes.rs`), read from \
          `target/criterion` when this report was written, not measured by it (> 1: microraster faster).\n\n";
    match shapes_ratios::table("[the 2D kit](shapes.md#the-dashboard)") {
        Some(table) => d += &table,
        None => {
            d += "*Not available: no complete `cargo bench --bench shapes` run in `target/criterion` when this \
                      report was written. Run it, then the report.*\n"
        }
    }
    d
}
