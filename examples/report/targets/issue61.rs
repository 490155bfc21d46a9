//! Issue 61's rows of the targets table: the knot in both accuracy tiers
//! and from both cameras against TGX's fixed counts on the same work
//! (`docs/data/peers-tgx.tsv`), the standard scene's fast frame, the
//! front with a default-converted mesh, the Cortex-M0's fixed point and the
//! host against euc; then where the misses come from, from the same rows.

use super::super::{Peer, knot, ratio};
use super::by;
use crate::cortex::{Counts, FwBench, FwRow};
use std::fmt::Write as _;

/// Every buffer of a knot frame within this (issue 61's condition).
const RAM: u64 = 32 * 1024;

/// A bound on a firmware row: its key, TGX's camera, the largest allowed
/// ratio to TGX's count in tenths (integers: 8 = 0.8×) or hundredths, and
/// what the row is.
struct TgxBound {
    key: &'static str,
    eye: &'static str,
    /// Allowed ratio as `num / den`.
    ratio: (u64, u64),
    label: &'static str,
}

/// The knot rows judged against TGX (`examples/fw_bench`, `docs/data/fw-bench.tsv` keys).
const TGX_BOUNDS: [TgxBound; 5] = [
    TgxBound { key: FAST_AFFINE, eye: "standard", ratio: (8, 10), label: "fast tier, f32, affine" },
    TgxBound {
        key: "knot20k/meshlets-per-band-f32-persp-correct-fast-tier",
        eye: "standard",
        ratio: (9, 10),
        label: "fast tier, f32, perspective-correct",
    },
    TgxBound { key: EXACT_AFFINE, eye: "standard", ratio: (13, 10), label: "exact tier, f32, affine" },
    TgxBound {
        key: CLOSE_FAST,
        eye: "close",
        ratio: (9, 10),
        label: "camera twice as close (eye (0, 0.95, 2.8)), fast tier, f32, affine",
    },
    TgxBound {
        key: CLOSE_EXACT,
        eye: "close",
        ratio: (13, 10),
        label: "camera twice as close, exact tier, f32, affine",
    },
];
const FAST_AFFINE: &str = "knot20k/meshlets-per-band-f32-affine-fast-tier";
const EXACT_AFFINE: &str = "knot20k/meshlets-per-band-f32-affine";
const CLOSE_FAST: &str = "knot20k-close/meshlets-per-band-f32-affine-fast-tier-eye-twice-as-close";
const CLOSE_EXACT: &str = "knot20k-close/meshlets-per-band-f32-affine-eye-twice-as-close";
/// The standard scene's fast perspective-correct frame and its budget:
/// inside a 40 MHz SPI frame at 168 MHz.
const SCENE_FAST: &str = "scene3d/f32-persp-correct-fast-tier";
const SCENE_BUDGET: u64 = 5_160_000;
/// The front with the mesh `obj2rs` writes by default, against the
/// explicit meshlet row of the same interpolation and tier.
const FRONT_RATIO: (u64, u64) = (115, 100);
/// The knot on the host: times faster than euc.
const HOST_EUC: f64 = 2.0;
const PENDING_FW: &str = "pending (`bash scripts/firmware.sh table`)";
const PENDING_TGX: &str = "pending (docs/data/peers-tgx.tsv)";

pub(crate) use crate::digits::group;

/// Issue 61's rows of the targets table and the paragraph on the misses.
pub(super) fn issue61(peers: &[Peer], counts: &Counts, fw: &FwBench) -> (String, String) {
    let (mut rows, mut why) = (String::new(), String::new());
    let t = &mut rows;
    for b in &TGX_BOUNDS {
        let (num, den) = b.ratio;
        let x = num as f64 / den as f64;
        let (bound, measured, v) = match (fw.get("m4f", b.key), fw.tgx(b.eye)) {
            (Some(r), Some(tgx)) => {
                let limit = tgx.instructions * num / den;
                let ok = r.instructions * den <= tgx.instructions * num && r.static_ram <= RAM;
                let over = (r.instructions as f64 / limit as f64).max(r.static_ram as f64 / RAM as f64);
                let m = format!(
                    "{} ({:.0} per mesh triangle, {:.2}× TGX), {} B of buffers",
                    group(r.instructions),
                    r.instructions as f64 / r.triangles as f64,
                    r.instructions as f64 / tgx.instructions as f64,
                    group(r.static_ram)
                );
                (format!("{x:.1}× TGX's {} = {}", group(tgx.instructions), group(limit)), m, by(ok, over))
            }
            (None, Some(tgx)) => {
                let limit = tgx.instructions * num / den;
                (
                    format!("{x:.1}× TGX's {} = {}", group(tgx.instructions), group(limit)),
                    PENDING_FW.into(),
                    "pending".into(),
                )
            }
            (_, None) => (format!("{x:.1}× TGX"), PENDING_TGX.into(), "pending".into()),
        };
        let _ = writeln!(
            t,
            "| issue 61: knot on Cortex-M4F, 16-row bands, {}: ≤ {bound} instructions, ≤ 32 KB of buffers | {measured} | {v} |",
            b.label
        );
    }
    let (measured, v) = match fw.get("m4f", SCENE_FAST) {
        Some(r) => (
            format!(
                "{}{}",
                group(r.instructions),
                fw.get("m4f", "scene3d/f32-persp-correct")
                    .map_or(String::new(), |e| format!(" (exact tier {})", group(e.instructions)))
            ),
            by(r.instructions <= SCENE_BUDGET, r.instructions as f64 / SCENE_BUDGET as f64),
        ),
        None => (PENDING_FW.into(), "pending".into()),
    };
    let _ = writeln!(
        t,
        "| issue 61: standard scene on Cortex-M4F, f32, perspective-correct, fast tier: ≤ {} instructions (a 40 MHz SPI frame at 168 MHz) | {measured} | {v} |",
        group(SCENE_BUDGET)
    );
    let _ = writeln!(t, "{}", front_row(fw));
    // Cortex-M0: Fx against soft-float f32 on the knot (examples/fw_sweep),
    // with the mesh in 16.16 as issue 12's row.
    let m0 = |k: &str| counts.get("m0", k);
    let (measured, v) = match (m0("knot20k/f32/D16/affine/band16/S4"), m0(knot::FX_MESH)) {
        (Some(a), Some(c)) => {
            let x = a as f64 / c as f64;
            (format!("{x:.2}× (f32 {}, Fx {})", group(a), group(c)), by(x >= 3.0, 3.0 / x))
        }
        _ => ("pending (`bash scripts/firmware.sh sweep`)".into(), "pending".into()),
    };
    let _ = writeln!(
        t,
        "| issue 61: Cortex-M0, knot: Fx stays ≥ 3× fewer instructions than soft-float f32 | {measured} | {v} |"
    );
    // Both tiers against euc; the verdict is the fast tier's (the tier a
    // user trades accuracy in for speed), the exact tier's ratio beside it.
    let euc = ratio(peers, knot::EUC, knot::BASE).unwrap_or(f64::NAN);
    let fast = ratio(peers, knot::EUC, knot::FAST).unwrap_or(f64::NAN);
    let fast_affine = ratio(peers, knot::EUC, knot::FAST_AFFINE).unwrap_or(f64::NAN);
    let _ = writeln!(
        t,
        "| issue 61: knot on the host: ≥ {HOST_EUC:.0}× faster than euc 0.5 (same run) | {fast:.2}× (perspective-correct, as euc interpolates, fast tier); {euc:.2}× (exact tier); {fast_affine:.2}× (affine, fast tier) | {} |",
        by(fast >= HOST_EUC, HOST_EUC / fast)
    );
    pixel_why(&mut why, fw);
    (rows, why)
}

/// The front with the knot as `obj2rs`'s default command converts it (the
/// `ways` rows of `examples/fw_bench`: `View3d`, perspective-correct, exact
/// tier) against the explicit meshlet row on the same converted knot.
fn front_row(fw: &FwBench) -> String {
    let label = "issue 61: `View3d` with the knot as `obj2rs` converts it by default: ≤ 1.15× the explicit meshlet row";
    let front = fw.find("m4f", "ways", &["20k", "view3d"]);
    let explicit = fw.find("m4f", "ways", &["20k", "meshlets"]);
    match (front, explicit) {
        (Some((_, r)), Some((key, e))) => {
            let (num, den) = FRONT_RATIO;
            let x = r.instructions as f64 / e.instructions as f64;
            let ok = r.instructions * den <= e.instructions * num;
            format!(
                "| {label} | {x:.2}× ({} against `{key}` {}) | {} |",
                group(r.instructions),
                group(e.instructions),
                by(ok, x * den as f64 / num as f64)
            )
        }
        _ => format!("| {label} | {PENDING_FW} (no `ways` rows of the 20k knot) | pending |"),
    }
}

/// Where the knot's instructions go against TGX's, per tier: the extra
/// cost of each extra covered pixel (the close camera against the
/// standard one) and what is left per mesh triangle.
fn pixel_why(w: &mut String, fw: &FwBench) {
    let (Some(ts), Some(tc)) = (fw.tgx("standard"), fw.tgx("close")) else { return };
    let per_px = |s: FwRow, c: FwRow| {
        let px = c.covered.saturating_sub(s.covered).max(1);
        c.instructions.saturating_sub(s.instructions) as f64 / px as f64
    };
    let tgx_px = per_px(ts, tc);
    let mut parts = Vec::new();
    for (tier, std_key, close_key) in
        [("exact", EXACT_AFFINE, CLOSE_EXACT), ("fast", FAST_AFFINE, CLOSE_FAST)]
    {
        let (Some(s), Some(c)) = (fw.get("m4f", std_key), fw.get("m4f", close_key)) else { continue };
        let px = per_px(s, c);
        // What the frame costs beside its pixels, against TGX's the same way.
        let rest = |r: FwRow, p: f64, tris: u64| (r.instructions as f64 - p * r.covered as f64) / tris as f64;
        parts.push(format!(
            "the {tier} tier spends {px:.0} instructions per extra covered pixel ({:.1}× TGX's {tgx_px:.0}; \
             {} covered pixels close, {} from the standard eye) and {:.0} per mesh triangle beside its pixels \
             (TGX {:.0}): {}",
            px / tgx_px,
            group(c.covered),
            group(s.covered),
            rest(s, px, s.triangles),
            rest(ts, tgx_px, ts.triangles),
            if s.instructions as f64 > 0.8 * ts.instructions as f64 {
                format!(
                    "at TGX's per-pixel cost the standard frame would still be {:.2}× TGX's",
                    (s.instructions as f64 - (px - tgx_px) * s.covered as f64) / ts.instructions as f64
                )
            } else {
                "within the fast bound".to_string()
            }
        ));
    }
    if !parts.is_empty() {
        let _ = writeln!(
            w,
            "Issue 61, from the knot rows of both cameras (affine, Cortex-M4F): {}.\n",
            parts.join("; ")
        );
    }
}
