//! The real-mesh benchmark in the report (issue 12): the 20k-triangle knot
//! on the host, microraster's meshlet stage against `euc`, same frame
//! (renderers in `benches/common/knot.rs`, `crate::knot_renderers`). Its targets are in
//! [`super::targets`].

use super::Peer;
use crate::common::*;
use crate::cortex::{Counts, FwBench};
use crate::knot_mesh::VALID_KNOT_FX;
use crate::knot_renderers::{self as knot, EucKnot, mr_knot, mr_knot_of, mr_knot_vertex_only};
use crate::timing::median_ns;
use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::Band;
use microraster::depth::{Depth16, DepthBand};
use microraster::math::Fx;
use microraster::pipeline::ClusterCache;
use microraster::raster3d::{Affine, PerspectiveCorrect, Precision};
use std::fmt::Write as _;

/// The knot's scene name in the tables.
pub const SCENE: &str = "knot20k";
/// The microraster configuration peers are compared with: perspective-correct
/// colour, as euc interpolates.
pub const BASE: &str = "knot20k/f32/D16/persp/band16/S4";
pub const AFFINE: &str = "knot20k/f32/D16/affine/band16/S4";
pub const EUC: &str = "knot20k/euc";
/// The fast accuracy tier (`Precision::Fast`), perspective-correct and affine.
pub const FAST: &str = "knot20k/f32/D16/persp/band16/S4/fast";
pub const FAST_AFFINE: &str = "knot20k/f32/D16/affine/band16/S4/fast";
/// The fixed-point path reading the knot's data in 16.16 (`KNOT_FX`).
pub const FX_MESH: &str = "knot20k/Fx/D16/affine/band16/S4/fx-mesh";

/// Where the knot's host time goes (the report's reason for its host
/// verdict), measured in the same run as [`peers`]' frames.
pub struct Split {
    /// The band loop and the vertex stage alone, 16-row bands, `f32`:
    /// every band's triangles only counted ([`mr_knot_vertex_only`]).
    pub vertex_ns: f64,
    /// The `f32` perspective-correct frame in one 240-row band: a whole
    /// colour and depth frame, as euc holds.
    pub one_band_ns: f64,
    /// Pixels of that frame that differ from the 16-row bands' frame
    /// (band invariance: 0).
    pub one_band_differs: usize,
}

/// Times the knot through microraster (both paths, both interpolations) and
/// through euc, same frame, and adds them to `peers`. "covered" is the
/// frame's fragments (pixels of every front-facing screen triangle, before
/// the depth test), as for the standard 3D scene. Returns the host [`Split`].
pub fn peers(peers: &mut Vec<Peer>) -> Split {
    let (p32, pfx) = (pipeline3d::<f32, 4>(), pipeline3d::<Fx, 4>());
    let (mut c32, mut cfx) = (Box::new(ClusterCache::new()), Box::new(ClusterCache::new()));
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut slice = SliceFb::default();
    let covered = knot::fragments();
    let mut add = |renderer, key: &str, ns, differs| {
        let key = key.to_string();
        peers.push(Peer { scene: SCENE, renderer, target: "slice", key, ns, differs, covered });
    };
    let t =
        median_ns(|| mr_knot::<f32, PerspectiveCorrect>(&p32, &mut c32, &mut band, &mut depth, &mut slice));
    add("microraster, f32, perspective-correct", BASE, t, Some(0));
    let mine = slice.px.clone();
    // The split's frames each right after the frame they are compared
    // with, so that drifts of the host's speed during the run touch both.
    let mut tall = Box::new(Band::<Rgb565, W, H>::new(BG3));
    let mut tall_depth = Box::new(DepthBand::<Depth16, W, H>::new());
    let one_band_ns = median_ns(|| {
        mr_knot_of::<f32, PerspectiveCorrect, f32, H>(
            &crate::knot_mesh::VALID_KNOT,
            &p32,
            &mut c32,
            &mut tall,
            &mut tall_depth,
            &mut slice,
        )
    });
    let one_band_differs = slice.px.iter().zip(&mine).filter(|(a, b)| a != b).count();
    // Colour rounding differs between renderers: count channels more than one step off.
    let far = |a: &Rgb565, b: &Rgb565| {
        let d = |x: u8, y: u8| x.abs_diff(y) > 1;
        d(a.r(), b.r()) || d(a.g(), b.g()) || d(a.b(), b.b())
    };
    let diff = |px: &[Rgb565]| Some(px.iter().zip(&mine).filter(|(a, b)| far(a, b)).count());
    let t = median_ns(|| mr_knot::<f32, Affine>(&p32, &mut c32, &mut band, &mut depth, &mut slice));
    add("microraster, f32, affine", AFFINE, t, diff(&slice.px));
    let fast = p32.with_precision(Precision::Fast);
    let t =
        median_ns(|| mr_knot::<f32, PerspectiveCorrect>(&fast, &mut c32, &mut band, &mut depth, &mut slice));
    add("microraster, f32, perspective-correct, fast tier", FAST, t, diff(&slice.px));
    let t = median_ns(|| mr_knot::<f32, Affine>(&fast, &mut c32, &mut band, &mut depth, &mut slice));
    add("microraster, f32, affine, fast tier", FAST_AFFINE, t, diff(&slice.px));
    let vertex_ns = median_ns(|| mr_knot_vertex_only(&p32, &mut c32, &mut band, &mut slice));
    let t = median_ns(|| mr_knot::<Fx, Affine>(&pfx, &mut cfx, &mut band, &mut depth, &mut slice));
    add("microraster, Fx, affine", "knot20k/Fx/D16/affine/band16/S4", t, diff(&slice.px));
    let t = median_ns(|| {
        mr_knot_of::<Fx, Affine, Fx, 16>(&VALID_KNOT_FX, &pfx, &mut cfx, &mut band, &mut depth, &mut slice)
    });
    add("microraster, Fx, affine, mesh in 16.16", FX_MESH, t, diff(&slice.px));
    let mut euc = EucKnot::new();
    let t = median_ns(|| euc.frame());
    add("euc 0.5 (f32 depth, framebuffer)", EUC, t, diff(euc.pixels()));

    Split { vertex_ns, one_band_ns, one_band_differs }
}

/// The README's summary of the knot (between its `knot:begin/end`
/// markers): each configuration's host time against euc, and its Cortex-M
/// counts (Cortex-M4F: `examples/fw_bench`, the README's firmware table;
/// Cortex-M0: `examples/fw_sweep`, 320 × 240 on the mps2-an386).
pub fn readme_table(peers: &[Peer], counts: &Counts, fw: &FwBench) -> String {
    let mut t = String::from(
        "| renderer | host µs / frame | euc's time ÷ this | Cortex-M4F instr. / frame | instr. / mesh triangle | static RAM (B) | Cortex-M0 instr. / frame |\n\
         |---|--:|--:|--:|--:|--:|--:|\n",
    );
    let euc = super::find(peers, EUC).map_or(f64::NAN, |p| p.ns);
    // (peer key, fw_bench row, counted on the Cortex-M0 by fw_sweep)
    let rows = [
        (BASE, Some("knot20k/meshlets-per-band-f32-persp-correct"), true),
        (AFFINE, Some("knot20k/meshlets-per-band-f32-affine"), true),
        (FAST, Some("knot20k/meshlets-per-band-f32-persp-correct-fast-tier"), false),
        (FAST_AFFINE, Some("knot20k/meshlets-per-band-f32-affine-fast-tier"), false),
        ("knot20k/Fx/D16/affine/band16/S4", Some("knot20k/meshlets-per-band-fx-affine"), true),
        (FX_MESH, None, true),
        (EUC, None, false),
    ];
    for (key, fw_key, m0) in rows {
        let Some(p) = super::find(peers, key) else { continue };
        let m4 = fw_key.and_then(|k| fw.get("m4f", k));
        let n = |v: Option<u64>| v.map_or("–".into(), |v| v.to_string());
        let _ = writeln!(
            t,
            "| {} | {} | {:.2} | {} | {} | {} | {} |",
            p.renderer,
            super::us(p.ns),
            euc / p.ns,
            n(m4.map(|r| r.instructions)),
            m4.map_or("–".into(), |r| format!("{:.0}", r.instructions as f64 / r.triangles as f64)),
            n(m4.map(|r| r.static_ram)),
            n(if m0 { counts.get("m0", key) } else { None }),
        );
    }
    t
}
