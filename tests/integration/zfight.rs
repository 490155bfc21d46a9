//! Z-fighting measured against theory, through the real pipeline
//! ([`Pipeline::perspective`], `f32`) and `Triangles3d`, and
//! through an f64 vertex stage that leaves only the rasterizer's depth
//! arithmetic.
//!
//! Two parallel quads facing the camera, the far one at eye distance `z`, the
//! near one `Δ` closer along the view axis; the far one is drawn first, then
//! the near one with `LESS`. Both overfill the frame, so every pixel sees
//! both. The planes are tilted slightly (the depth changes by about ±4 code
//! steps across the frame, the eye distance by at most ±10 %) so the stored
//! depth sweeps through every rounding phase: the `Δ` a pixel needs is the
//! eye-space distance from its far-plane depth down to the next rounding
//! boundary, between 0 and one code step, and the worst pixel needs about one
//! full step. Measured: the smallest `Δ` from which on the near quad wins
//! every pixel (a downward scan on a 2^(1/8) grid brackets it, bisection
//! refines it).
//!
//! Theory (Marschner & Shirley): `d = f/(f − n)·(1 − n/z)`, so one code step
//! `Δd = 1/2^b` spans `Δz_w ≈ z²·Δd·(f − n)/(f·n) = z²·(f − n)/(2^b·f·n)`.
//! Expected ratio measured/predicted: about 1 (the tilt adds at most
//! `(1 + 4Δz_w/z)²`), asserted within a factor of 2 — except Depth24 through
//! the `f32` pipeline, see [`z_fighting_matches_theory_through_the_pipeline`].

use crate::framebuffer::Framebuffer;
use crate::ref3d::QUAD;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, Depth24, DepthBand, DepthFormat, DepthState};
use microraster::edge::Cull;
use microraster::math::Mat4;
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
use microraster::render::Triangles3d;
use microraster::{Band, Interpolate, Renderer, SubPoint};

const W: usize = 80;
const H: usize = 60;
const FOV: f64 = 0.9;
const FAR: Rgb565 = Rgb565::new(31, 0, 0);
const NEAR: Rgb565 = Rgb565::new(0, 63, 0);
const BG: Rgb565 = Rgb565::new(0, 0, 0);

/// Positions of a quad at eye distance `dist` in the frame's centre, tilted
/// along `(a, b)` so that the eye distance changes by `±tilt·z` at the frame's
/// corners.
fn quad(dist: f64, z: f64, tilt: f64) -> [[f64; 3]; 4] {
    let t = (FOV / 2.0).tan();
    let aspect = W as f64 / H as f64;
    let (a, b) = (0.5f64.cos(), 0.5f64.sin());
    let k = tilt / (t * (a * aspect + b));
    let (xs, ys) = (1.5 * z * t * aspect, 1.5 * z * t);
    [(-xs, -ys), (xs, -ys), (xs, ys), (-xs, ys)].map(|(x, y)| [x, y, -(dist + k * (a * x + b * y))])
}

/// The vertex stage that turns the quads into screen triangles.
enum Stage<'a> {
    /// The library's `f32` pipeline.
    Pipeline(&'a Pipeline<f32, 4>),
    /// An f64 vertex stage: exact projection, depth `round(z/w·2^32)` and
    /// snapping to nearest, so only the rasterizer's depth arithmetic remains.
    Exact { n: f64, f: f64 },
}

fn exact_quad(pos: &[[f64; 3]; 4], n: f64, f: f64, color: Rgb565) -> [ScreenTriangle<4>; 2] {
    let fy = 1.0 / (FOV / 2.0).tan();
    let fx = fy * H as f64 / W as f64;
    let v = pos.map(|p| {
        let (x, y, w) = (p[0], p[1], -p[2]);
        let sx = W as f64 / 2.0 * (1.0 + fx * x / w);
        let sy = H as f64 / 2.0 * (1.0 - fy * y / w);
        let d = f / (f - n) * (1.0 - n / w);
        ScreenVertex {
            pos: SubPoint::new((sx * 16.0).round() as i32, (sy * 16.0).round() as i32).unwrap(),
            depth: (d * 4294967295.0).round().clamp(0.0, u32::MAX as f64) as u32,
            inv_w: (1073741824.0 * n / w).round() as u32,
            color: color.to_channels(),
        }
    });
    QUAD.map(|[a, b, c]| ScreenTriangle { v: [v[a as usize], v[b as usize], v[c as usize]], flat: true })
}

/// Whether the near quad wins every pixel at separation `delta`.
fn near_wins<F: DepthFormat>(stage: &Stage, z: f64, tilt: f64, delta: f64) -> bool {
    let far = quad(z, z, tilt);
    let near = quad(z - delta, z, tilt);
    let mut bins = heapless::Vec::<ScreenTriangle<4>, 16>::new();
    for (pos, color) in [(&far, FAR), (&near, NEAR)] {
        match stage {
            Stage::Pipeline(p) => {
                let pos = pos.map(|v| v.map(|c| c as f32));
                let mesh = Mesh::new(&pos, &[], &QUAD, bounding_sphere(&pos));
                let st = p.draw_mesh(&mesh, &Mat4::IDENTITY, color, &mut bins).unwrap();
                assert_eq!((st.clipped, st.emitted), (0, 2), "quad at {z} clipped or culled: {st:?}");
            }
            Stage::Exact { n, f } => bins.extend(exact_quad(pos, *n, *f, color)),
        }
    }
    let mut fb = Framebuffer::new(W as u32, H as u32, BG);
    let mut band = Box::new(Band::<Rgb565, W, H>::new(BG));
    let mut depth = Box::new(DepthBand::<F, W, H>::new());
    Renderer::new(H as u32, BG)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
        .unwrap();
    assert!(!fb.pixels.contains(&BG), "a pixel is not covered by the quads");
    fb.pixels.iter().all(|&c| c == NEAR)
}

struct Row {
    bits: u32,
    n: f64,
    f: f64,
    z: f64,
    predicted: f64,
    measured: f64,
}

/// The smallest separation from which on the near quad always wins: scan down
/// a geometric grid (ratio 2^(1/8)) from 8× the prediction to the first loss,
/// then bisect between that loss and the win above it.
fn measure<F: DepthFormat>(exact: bool, n: f64, f: f64, z: f64) -> Row {
    let mut p =
        Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, FOV as f32, n as f32, f as f32, W as u32, H as u32)
            .unwrap();
    p.cull = Cull::None;
    p.shade = Shade::Flat;
    let stage = if exact { Stage::Exact { n, f } } else { Stage::Pipeline(&p) };
    let predicted = z * z * (f - n) / ((1u64 << F::BITS) as f64 * f * n);
    // About 8 code steps across the frame (so every rounding phase occurs,
    // yet the depth gradient is far below a code per pixel and snapping the
    // vertices moves the depth by a negligible fraction of a code), at most
    // ±10 % of z.
    let tilt = (4.0 * predicted / z).min(0.1);
    let wins = |d: f64| near_wins::<F>(&stage, z, tilt, d);
    assert!(!wins(0.0), "coincident planes: the second must lose (LESS)");
    let ratio = 2f64.powf(1.0 / 8.0);
    let mut hi = 8.0 * predicted;
    assert!(wins(hi), "{}-bit n={n} f={f} z={z}: near plane loses at 8x the prediction", F::BITS);
    while wins(hi / ratio) {
        hi /= ratio;
    }
    let mut lo = hi / ratio;
    for _ in 0..16 {
        let mid = 0.5 * (lo + hi);
        if wins(mid) { hi = mid } else { lo = mid }
    }
    Row { bits: F::BITS, n, f, z, predicted, measured: hi }
}

fn table(exact: bool, title: &str) -> Vec<Row> {
    let mut rows = Vec::new();
    for bits in [16, 24] {
        for (n, f) in [(0.1, 10.0), (0.1, 100.0), (0.1, 1000.0), (1.0, 10.0), (1.0, 100.0), (1.0, 1000.0)] {
            let zs: &[f64] = match f {
                10.0 => &[2.0, 8.0],
                100.0 => &[5.0, 50.0],
                _ => &[5.0, 50.0, 500.0],
            };
            for &z in zs {
                rows.push(if bits == 16 {
                    measure::<Depth16>(exact, n, f, z)
                } else {
                    measure::<Depth24>(exact, n, f, z)
                });
            }
        }
    }
    // One print, so parallel tests cannot interleave the table.
    let mut t = format!("z-fighting, {title}:\n");
    t += "| bits | n | f | z | predicted Δ | measured Δ | ratio |\n|---:|---:|---:|---:|---:|---:|---:|\n";
    for r in &rows {
        let ratio = r.measured / r.predicted;
        t += &format!(
            "| {} | {} | {} | {} | {:.3e} | {:.3e} | {ratio:.2} |\n",
            r.bits, r.n, r.f, r.z, r.predicted, r.measured
        );
    }
    print!("{t}");
    rows
}

fn assert_within(rows: &[Row], bits: u32, lo: f64, hi: f64) -> usize {
    let mut n = 0;
    for r in rows.iter().filter(|r| r.bits == bits) {
        let ratio = r.measured / r.predicted;
        assert!(
            (lo..=hi).contains(&ratio),
            "{}-bit n={} f={} z={}: measured {:.3e} vs predicted {:.3e} (ratio {ratio:.2})",
            r.bits,
            r.n,
            r.f,
            r.z,
            r.measured,
            r.predicted
        );
        n += 1;
    }
    n
}

/// The rasterizer alone (f64 vertex stage): every row within a factor of 2.
#[test]
fn z_fighting_matches_theory_with_exact_vertices() {
    let rows = table(true, "f64 vertex stage (rasterizer only)");
    let n = assert_within(&rows, 16, 0.5, 2.0) + assert_within(&rows, 24, 0.5, 2.0);
    println!("z-fighting (f64 vertices): {n} configurations bisected");
    assert_eq!(n, 28);
}

/// Through the `f32` pipeline. Depth16: within a factor of 2. Depth24: the
/// `f32` vertex stage computes `d = z/w` as `fl(fl(fl(A·z_v) + B)/w)` (`A`,
/// `B` the projection's depth row; positions are exact `f32` inputs, but
/// `z − Δ` is itself rounded to `f32`), an absolute error of up to
/// `u·(f/(f − n)·(1 + n/z) + 2d)` with `u = 2^-24`, `d ≤ 1`: at most
/// `e = 1.12·(1 + 1/1.8) + 2 ≈ 3.7` Depth24 codes per plane here (0.015
/// Depth16 codes). So the separation needed lies anywhere in `(0, 1 + 2e]`
/// steps, and only that envelope is asserted for Depth24.
#[test]
fn z_fighting_matches_theory_through_the_pipeline() {
    let rows = table(false, "f32 pipeline");
    let n = assert_within(&rows, 16, 0.5, 2.0)
        + assert_within(&rows, 24, 0.0, 1.0 + 2.0 * (1.12 * (1.0 + 1.0 / 1.8) + 2.0));
    println!("z-fighting (pipeline): {n} configurations bisected");
    assert_eq!(n, 28);
}
