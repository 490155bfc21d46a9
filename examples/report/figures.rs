//! The charts in `docs/charts/`, drawn from this run's rows.

use super::{Peer, Res, cost_rows, find};
use crate::charts::{self, Point2};
use crate::sweep::{Row2d, Row3d};
use crate::{cortex, knot};
use std::path::Path;

pub(crate) fn draw_charts(
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
