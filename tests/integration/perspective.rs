//! Perspective-correct colour against an f64 reference, and the affine mode's
//! error on a receding floor.
//!
//! Reference: `c = Σ λ_i c_i q_i / Σ λ_i q_i` with `λ` the exact barycentrics
//! of the pixel centre on the snapped vertices and `q_i` the `inv_w` values fed
//! in (`ref3d::bary`).
//!
//! Derived bound (from the `raster3d`/`attr` docs: `q` normalised per
//! triangle to 23 bits, `q` and `c·q` planes in 2^16 units per step, per pixel
//! `c = (c·q)/q` rounded): with `q'_i` the normalised values,
//! * normalisation truncates: `q'_i = s_i − t_i`, `0 ≤ t_i < 1`, `s_i` the exact
//!   scaled `q_i`, `q'_i ≥ m := ⌊2^22·q_min/q_max⌋ − 1` (and ≥ 1). Relative
//!   weight errors `≤ ε = 1/m` move the weighted mean by `≤ 255·ε/(1 − ε)`;
//! * each plane is within 2^13 units (1/8 step) of exact and is floored to a
//!   step: `p = P + δp`, `q = Q + δq`, `δ ∈ (−9/8, 1/8]`, so
//!   `|p/q − P/Q| ≤ 9/8·(1 + c)/q ≤ 288/(m − 9/8)` (`Q ≥ min q'_i ≥ m` inside);
//! * the division `(p + ⌊q/2⌋)/q` rounds to within `1/2 + 1/(2q)`.
//!
//! So `|c − c_ref| ≤ 1/2 + 1/(2(m − 9/8)) + 288/(m − 9/8) + 255ε/(1 − ε)`.

use crate::ref3d::{bary, draw_frame, is_tiny};
use crate::reference::{Rng, exact_coverage};
use embedded_graphics_core::pixelcolor::Rgb888;
use microraster::depth::{DepthState, NoDepth};
use microraster::edge::Cull;
use microraster::raster3d::{Affine, PerspectiveCorrect, ScreenTriangle, ScreenVertex};
use microraster::{ClipRect, Interpolate, SubPoint};

const W: usize = 96;
const H: usize = 72;
const BG: Rgb888 = Rgb888::new(0, 0, 0);

/// The derived bound of the module docs for one triangle.
fn bound(inv_w: [u32; 3]) -> f64 {
    let (lo, hi) = (*inv_w.iter().min().unwrap() as f64, *inv_w.iter().max().unwrap() as f64);
    let m = ((4194304.0 * lo / hi).floor() - 1.0).max(1.0);
    let eps = 1.0 / m;
    assert!(m > 2.0, "bound needs q_max/q_min < 2^21");
    0.5 + 0.5 / (m - 1.125) + 288.0 / (m - 1.125) + 255.0 * eps / (1.0 - eps)
}

/// Perspective-correct and screen-linear references at pixel `(x, y)`, per channel.
fn references(t: &ScreenTriangle<4>, x: i32, y: i32) -> ([f64; 3], [f64; 3]) {
    let (num, det) = bary(t.v.map(|v| v.pos), x, y).unwrap();
    let l = num.map(|n| n as f64 / det as f64);
    let q = t.v.map(|v| v.inv_w as f64);
    let den: f64 = (0..3).map(|i| l[i] * q[i]).sum();
    let pc = [0, 1, 2].map(|k| (0..3).map(|i| l[i] * q[i] * t.v[i].color[k] as f64).sum::<f64>() / den);
    let lin = [0, 1, 2].map(|k| (0..3).map(|i| l[i] * t.v[i].color[k] as f64).sum::<f64>());
    (pc, lin)
}

/// Max and mean per-channel error of a frame against the perspective-correct
/// reference, over the pixels the triangles cover; `check` sees every error.
fn errors(
    tris: &[ScreenTriangle<4>],
    frame: &[Rgb888],
    mut check: impl FnMut(usize, f64, f64),
) -> (f64, f64, usize) {
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let (mut max, mut sum, mut n) = (0f64, 0f64, 0usize);
    for (ti, t) in tris.iter().enumerate() {
        let cov = exact_coverage(t.v.map(|v| v.pos), clip, Cull::None);
        for (x, y) in cov.pixels() {
            let got = frame[y as usize * W + x as usize].to_channels();
            let (pc, lin) = references(t, x, y);
            for k in 0..3 {
                let e = (got[k] as f64 - pc[k]).abs();
                check(ti, e, (got[k] as f64 - lin[k]).abs());
                (max, sum, n) = (max.max(e), sum + e, n + 1);
            }
        }
    }
    (max, sum / n.max(1) as f64, n)
}

#[test]
fn perspective_correct_colour_within_derived_bound() {
    let mut rng = Rng::new(0x9e3779b97f4a7c15);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    // Per w-ratio class: max error, smallest margin (bound − error), error sum, samples.
    let mut stats = [(0f64, f64::INFINITY, 0f64, 0usize); 3];
    let (mut triangles, mut samples) = (0usize, 0usize);
    while triangles < 4500 {
        // Vertices within twice the frame; 1/16 px.
        let mut pt = || {
            let x = rng.range(-(W as i64) * 8, W as i64 * 24) as i32;
            let y = rng.range(-(H as i64) * 8, H as i64 * 24) as i32;
            SubPoint::<4>::new(x, y).unwrap()
        };
        let pos = [pt(), pt(), pt()];
        if exact_coverage(pos, clip, Cull::None).is_empty() {
            continue;
        }
        // inv_w = 2^30·n/w with w/n log-uniform in [1, R]: the pipeline's range.
        let class = triangles % 3;
        let r = [2.0, 100.0, 10000.0][class];
        let inv_w = [0, 1, 2].map(|_| (1073741824.0 / rng.log_uniform(1.0, r)).round() as u32);
        let colors: [[u8; 3]; 3] = [0, 1, 2].map(|_| [0, 1, 2].map(|_| rng.below(256) as u8));
        let v = |i: usize| ScreenVertex { pos: pos[i], depth: 0, inv_w: inv_w[i], color: colors[i] };
        let tri = ScreenTriangle { v: [v(0), v(1), v(2)], flat: false };
        let (frame, _) =
            draw_frame::<Rgb888, NoDepth, PerspectiveCorrect, 4, W, H>(&[tri], BG, DepthState::DISABLED);
        let b = bound(inv_w);
        let (max, mean, n) = errors(&[tri], &frame, |_, e, _| {
            assert!(e <= b + 1e-9, "error {e} > bound {b} for {tri:?}");
        });
        let s = &mut stats[class];
        *s = (s.0.max(max), s.1.min(b - max), s.2 + mean * n as f64, s.3 + n);
        samples += n;
        triangles += 1;
    }
    for (r, (max, margin, sum, n)) in ["<= 2", "<= 100", "<= 10^4"].iter().zip(stats) {
        let mean = sum / n as f64;
        println!(
            "perspective-correct, w ratio {r}: {n} samples, max error {max:.4}, mean {mean:.4}, \
             smallest margin to the bound {margin:.4}"
        );
    }
    println!("perspective-correct: {triangles} triangles, {samples} channel samples");
    assert!(samples >= 6_000_000, "only {samples} samples");
}

/// A floor receding from w = 1 to w = 20 under a camera at height 1, with a
/// colour ramp along depth (red) and across (green), projected in f64 and
/// snapped to nearest; `inv_w = 2^30/w` as the pipeline computes it (n = 1).
fn floor() -> [ScreenTriangle<4>; 2] {
    let fy = 1.0 / 0.5f64.tan(); // fov_y = 1 rad
    let fx = fy * H as f64 / W as f64;
    let corner = |x: f64, w: f64, c: [u8; 3]| {
        let sx = W as f64 / 2.0 * (1.0 + fx * x / w);
        let sy = H as f64 / 2.0 * (1.0 + fy * 1.0 / w); // floor at y = −1
        let pos = SubPoint::new((sx * 16.0).round() as i32, (sy * 16.0).round() as i32).unwrap();
        ScreenVertex { pos, depth: 0, inv_w: (1073741824.0 / w).round() as u32, color: c }
    };
    let v = [
        corner(-3.0, 1.0, [0, 0, 128]),
        corner(3.0, 1.0, [0, 255, 128]),
        corner(3.0, 20.0, [255, 255, 128]),
        corner(-3.0, 20.0, [255, 0, 128]),
    ];
    [[0, 1, 2], [0, 2, 3]].map(|[a, b, c]| ScreenTriangle { v: [v[a], v[b], v[c]], flat: false })
}

#[test]
fn affine_skews_a_receding_floor_perspective_correct_does_not() {
    let tris = floor();
    let b = bound(tris[0].v.map(|v| v.inv_w)).max(bound(tris[1].v.map(|v| v.inv_w)));
    let (pc, _) = draw_frame::<Rgb888, NoDepth, PerspectiveCorrect, 4, W, H>(&tris, BG, DepthState::DISABLED);
    let (af, _) = draw_frame::<Rgb888, NoDepth, Affine, 4, W, H>(&tris, BG, DepthState::DISABLED);
    let (pc_max, pc_mean, n) = errors(&tris, &pc, |_, e, _| assert!(e <= b + 1e-9, "{e} > {b}"));
    // Affine mode is exactly screen-linear Gouraud: within 0.5 + 2^-7 of the
    // screen-linear reference (the 2D Gouraud bound), far from the correct one.
    let (af_max, af_mean, _) = errors(&tris, &af, |_, _, lin| assert!(lin <= 0.5 + 1.0 / 128.0 + 1e-9));
    println!(
        "floor, {n} channel samples: perspective-correct max {pc_max:.3} mean {pc_mean:.3} (bound {b:.3})"
    );
    println!("floor, {n} channel samples: affine              max {af_max:.3} mean {af_mean:.3}");
    assert!(n >= 3 * 2000, "floor covers too few pixels: {n}");
    assert!(af_max >= 20.0 * pc_max && af_mean >= 20.0 * pc_mean, "affine error not clearly larger");
}

/// Triangles of up to twelve pixels, most of them tiny (twice the area below
/// 2^16 internal units: colour from per-pixel barycentric sums, no planes,
/// `raster3d::tiny`), held to the same derived bound.
#[test]
fn perspective_correct_colour_of_small_triangles_within_derived_bound() {
    let mut rng = Rng::new(0x7715_7EE5);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let (mut samples, mut tiny, mut worst) = (0usize, 0usize, 0f64);
    for i in 0..20_000 {
        let size = [1, 2, 3, 12][i % 4];
        let (cx, cy) = (rng.range(-2, W as i64) * 16, rng.range(-2, H as i64) * 16);
        let mut pt = || {
            SubPoint::<4>::new((cx + rng.range(0, size * 16)) as i32, (cy + rng.range(0, size * 16)) as i32)
        };
        let pos = [pt().unwrap(), pt().unwrap(), pt().unwrap()];
        let r = [2.0, 100.0, 10000.0][i % 3];
        let inv_w = [0, 1, 2].map(|_| (1073741824.0 / rng.log_uniform(1.0, r)).round() as u32);
        let colors: [[u8; 3]; 3] = [0, 1, 2].map(|_| [0, 1, 2].map(|_| rng.below(256) as u8));
        let v = |i: usize| ScreenVertex { pos: pos[i], depth: 0, inv_w: inv_w[i], color: colors[i] };
        let tri = ScreenTriangle { v: [v(0), v(1), v(2)], flat: false };
        if exact_coverage(pos, clip, Cull::None).is_empty() {
            continue;
        }
        let (frame, _) =
            draw_frame::<Rgb888, NoDepth, PerspectiveCorrect, 4, W, H>(&[tri], BG, DepthState::DISABLED);
        let b = bound(inv_w);
        let (max, _, n) = errors(&[tri], &frame, |_, e, _| {
            assert!(e <= b + 1e-9, "error {e} > bound {b} for {tri:?}");
        });
        (samples, worst) = (samples + n, worst.max(max));
        tiny += if is_tiny(pos) { n } else { 0 };
    }
    println!(
        "perspective-correct, small triangles: {samples} channel samples ({tiny} of tiny ones), max error {worst:.4}"
    );
    assert!(tiny > 50_000 && samples > tiny, "{tiny} tiny of {samples}");
}
