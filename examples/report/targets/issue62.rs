//! Issue 62's Cortex-M4F rows of the targets table: the 2D frames against
//! the wire (a 320 × 240 `Rgb565` frame over a 40 MHz SPI link is 30.7 ms,
//! 5.16 M cycles of a 168 MHz Cortex-M4F), the mixed 2D scene, and the
//! dashboard's 60-frame drive with damage regions against its full frame.
//! Every row from `docs/data/fw-bench.tsv` (`bash scripts/firmware.sh
//! table`); the shape ratios against embedded-graphics and tiny-skia are
//! the README's table (`cargo bench --bench shapes`, then `cargo run
//! --example readme_2d`), which computes their verdicts the same way.

use super::by;
use super::issue61::group;
use crate::cortex::{FwBench, FwRow};
use std::fmt::Write as _;

/// Bits of one 320 × 240 `Rgb565` frame.
const FRAME_BITS: u64 = 320 * 240 * 16;
/// The link and the core the budget is set for.
const SPI_HZ: u64 = 40_000_000;
const CORE_HZ: u64 = 168_000_000;
/// The mixed 2D scene's bound.
const MIXED: u64 = 2_500_000;
/// The damaged drive's average frame against the full frame, as `num / den`.
const DRIVE: (u64, u64) = (25, 100);
const PENDING: &str = "pending (`bash scripts/firmware.sh table`)";

/// Cycles of the core while the link carries one frame (5,160,960).
pub(crate) const fn wire_cycles() -> u64 {
    FRAME_BITS * CORE_HZ / SPI_HZ
}

/// A verdict whose factor needs three decimals (a miss by under 1 %).
fn by3(ok: bool, factor: f64) -> String {
    if ok { by(true, factor) } else { format!("**missed** by {factor:.3}×") }
}

/// The first Cortex-M4F row of `scene` (its key up to the `/`).
fn scene(fw: &FwBench, scene: &str) -> Option<(String, FwRow)> {
    fw.find("m4f", &format!("{scene}/"), &[])
}

/// Issue 62's rows of the targets table and the sentence on its misses.
pub(super) fn issue62(fw: &FwBench) -> (String, String) {
    let (mut rows, mut why) = (String::new(), String::new());
    let wire = wire_cycles();
    let dash = scene(fw, "dashboard");
    let (m, v) = match &dash {
        Some((_, r)) => (
            format!("{} ({:.3}× the wire)", group(r.instructions), r.instructions as f64 / wire as f64),
            by3(r.instructions <= wire, r.instructions as f64 / wire as f64),
        ),
        None => (PENDING.into(), "pending".into()),
    };
    let _ = writeln!(
        rows,
        "| issue 62: dashboard on Cortex-M4F, 16-row bands: ≤ {} instructions (one 320 × 240 Rgb565 frame on a 40 MHz SPI link at 168 MHz) | {m} | {v} |",
        group(wire)
    );
    let (m, v) = match scene(fw, "mixed") {
        Some((_, r)) => {
            (group(r.instructions), by(r.instructions <= MIXED, r.instructions as f64 / MIXED as f64))
        }
        None => (PENDING.into(), "pending".into()),
    };
    let _ = writeln!(
        rows,
        "| issue 62: mixed 2D scene on Cortex-M4F: ≤ {} instructions | {m} | {v} |",
        group(MIXED)
    );
    let (num, den) = DRIVE;
    let (m, v) = match (scene(fw, "dashboard-drive"), &dash) {
        (Some((_, d)), Some((_, f))) => {
            let x = d.instructions as f64 / f.instructions as f64;
            (
                format!(
                    "{} a frame on average, {:.1}% of the full frame's {}",
                    group(d.instructions),
                    100.0 * x,
                    group(f.instructions)
                ),
                by(d.instructions * den <= f.instructions * num, x * den as f64 / num as f64),
            )
        }
        _ => (PENDING.into(), "pending".into()),
    };
    let _ = writeln!(
        rows,
        "| issue 62: the dashboard's 60-frame drive with damage regions: ≤ {num}% of a full frame's instructions on average | {m} | {v} |"
    );
    if let Some((key, r)) = &dash {
        if r.instructions > wire {
            let _ = writeln!(
                why,
                "Issue 62: the dashboard (`{key}`) is compute-bound at {:.3}× the wire: `bash scripts/firmware.sh profile dashboard 40` shows where its instructions go.\n",
                r.instructions as f64 / wire as f64
            );
        }
    }
    (rows, why)
}

// 1,228,800 bits at 40 MHz is 30.72 ms; at 168 MHz, 5,160,960 cycles (the issue's 5.16 M).
const _: () = assert!(wire_cycles() == 5_160_960);
