//! Textured triangles (affine and perspective-correct) against the f64
//! reference per pixel centre.

use super::{BILINEAR_BOUND, RefTexture};
use crate::ref3d::bary;
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888, RgbColor};
use microraster::depth::{DepthBand, DepthState, NoDepth};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle, ScreenVertex};
use microraster::texture::{Address, Bilinear, Filter, Nearest, Sampler, Texture, UV_ONE, from_rgb8};
use microraster::varyings::{Varyings, draw_fragments};
use microraster::{Band, SubPoint};

// ---------------------------------------------------------------------------
// Textured triangles.

const W: usize = 80;
const H: usize = 64;

/// The `Varyings` bound (src/raster/varyings.rs) on a value with exact value `v`:
/// affine ½ + 2^-7 of the screen-linear value; perspective-correct
/// ½ + (2^10 + |v|/8)/(Q − 1/8) with `Q` the normalised `1/w` of the
/// pixel, at least the smallest normalised vertex value.
fn varying_bound<M: Interpolation>(tri: &ScreenTriangle<4>, v: f64) -> f64 {
    if !M::PERSPECTIVE {
        return 0.5 + 1.0 / 128.0 + 1e-6;
    }
    let qmax = tri.v.iter().map(|v| v.inv_w).max().unwrap();
    let scale = 2f64.powi(30 - (32 - qmax.leading_zeros()) as i32);
    let q_lo = tri.v.iter().map(|v| f64::from(v.inv_w)).fold(f64::MAX, f64::min) * scale;
    0.5 + (1024.0 + v.abs() / 8.0) / (q_lo - 0.125) + 1e-6
}

/// The exact `(u, v)` at the centre of `(x, y)`: perspective-correct, and
/// screen-linear. `None` unless the centre is strictly inside the triangle
/// (edge pixels follow the fill rule, tested elsewhere).
fn reference_uv(tri: &ScreenTriangle<4>, uv: &[[i32; 2]; 3], x: i32, y: i32) -> Option<([f64; 2], [f64; 2])> {
    let (num, det) = bary(tri.v.map(|v| v.pos), x, y)?;
    if num.iter().any(|&n| n == 0 || (n < 0) != (det < 0)) {
        return None;
    }
    let l = num.map(|n| n as f64 / det as f64);
    let q = tri.v.map(|v| f64::from(v.inv_w));
    let den: f64 = (0..3).map(|i| l[i] * q[i]).sum();
    let persp = [0, 1].map(|k| (0..3).map(|i| l[i] * q[i] * f64::from(uv[i][k])).sum::<f64>() / den);
    let lin = [0, 1].map(|k| (0..3).map(|i| l[i] * f64::from(uv[i][k])).sum::<f64>());
    Some((persp, lin))
}

/// Draws `tri` textured with `tex` through `Varyings<2>` (`M`) and
/// `draw_fragments`, into an Rgb888 band (8-bit channels kept exactly).
fn draw_textured<M: Interpolation, Fi: Filter>(
    tri: &ScreenTriangle<4>,
    uv: [[i32; 2]; 3],
    tex: &Texture<'_, Rgb565>,
    sampler: Sampler<Fi>,
) -> Option<Box<Band<Rgb888, W, H>>> {
    let varyings = Varyings::new(tri, uv, M::default()).unwrap()?;
    let mut band = Box::new(Band::<Rgb888, W, H>::new(Rgb888::BLACK));
    let mut depth = DepthBand::<NoDepth, W, H>::new();
    draw_fragments(
        tri,
        &mut band.view(0, H, Rgb888::BLACK),
        &mut depth.rows_mut(H),
        DepthState::DISABLED,
        |x, y| Some(from_rgb8(tex.sample(sampler, varyings.at(x, y)))),
    );
    Some(band)
}

/// Error statistics of one mode over many pixels.
#[derive(Default, Debug)]
struct Stats {
    pixels: usize,
    /// Bilinear: worst |error| per channel and worst error/bound ratio.
    worst: f64,
    worst_ratio: f64,
    /// Nearest: pixels whose reference coordinate was within δ of a texel edge.
    ambiguous: usize,
}

/// Checks every covered pixel of a textured triangle against the reference
/// at the exact coordinate of mode `M` (perspective-correct or linear).
#[allow(clippy::too_many_arguments)]
fn check_triangle<M: Interpolation>(
    tri: &ScreenTriangle<4>,
    uv: [[i32; 2]; 3],
    tex: &Texture<'_, Rgb565>,
    reference: &RefTexture,
    address: [Address; 2],
    nearest: &mut Stats,
    bilinear: &mut Stats,
) {
    let s = Sampler::NEAREST_WRAP.with_address(address[0], address[1]);
    let (Some(bn), Some(bb)) = (
        draw_textured::<M, Nearest>(tri, uv, tex, s),
        draw_textured::<M, Bilinear>(
            tri,
            uv,
            tex,
            Sampler::BILINEAR_WRAP.with_address(address[0], address[1]),
        ),
    ) else {
        return;
    };
    let size = [tex.width(), tex.height()].map(f64::from);
    for y in 0..H as i32 {
        for x in 0..W as i32 {
            let Some((persp, lin)) = reference_uv(tri, &uv, x, y) else { continue };
            let exact = if M::PERSPECTIVE { persp } else { lin };
            let delta = exact.map(|v| varying_bound::<M>(tri, v));
            let got_b = bb.rows()[y as usize][x as usize];
            let got_n = bn.rows()[y as usize][x as usize];
            // A covered pixel is drawn (the hook returns a colour); the
            // background is black, a possible texel, so coverage is checked
            // by the varyings suite, not here.
            // Bilinear: Lipschitz bound from the coordinate error.
            let want = reference.bilinear(exact, address);
            let bound = BILINEAR_BOUND + 255.0 * (size[0] * delta[0] + size[1] * delta[1]) / 65536.0 + 1e-9;
            let got = [got_b.r(), got_b.g(), got_b.b()];
            for k in 0..3 {
                let e = (f64::from(got[k]) - want[k]).abs();
                assert!(e <= bound, "bilinear {e} > {bound} at ({x},{y}) {tri:?} {uv:?}");
                bilinear.worst = bilinear.worst.max(e);
                bilinear.worst_ratio = bilinear.worst_ratio.max(e / bound);
            }
            bilinear.pixels += 1;
            // Nearest: one of the texels within δ of the exact coordinate.
            let range = |k: usize| {
                let p = |v: f64| RefTexture::pos(v, size[k] as i64).floor() as i64;
                p(exact[k] - delta[k])..=p(exact[k] + delta[k])
            };
            let (ri, rj) = (range(0), range(1));
            if ri.clone().count() > 1 || rj.clone().count() > 1 {
                nearest.ambiguous += 1;
            }
            let got = [got_n.r(), got_n.g(), got_n.b()].map(f64::from);
            let ok = ri.clone().any(|i| rj.clone().any(|j| reference.at(i, j, address) == got));
            assert!(ok, "nearest at ({x},{y}): {got:?} not a texel within δ of {exact:?} {tri:?} {uv:?}");
            nearest.pixels += 1;
        }
    }
}

fn random_textured_triangle(rng: &mut Rng, depth_ratio: f64) -> (ScreenTriangle<4>, [[i32; 2]; 3]) {
    let v = |rng: &mut Rng| ScreenVertex {
        pos: SubPoint::new(
            rng.range(-160, (W as i64 + 10) << 4) as i32,
            rng.range(-160, (H as i64 + 10) << 4) as i32,
        )
        .unwrap(),
        depth: 0,
        inv_w: ((1u64 << 30) as f64 / rng.log_uniform(1.0, depth_ratio)) as u32,
        color: [0; 3],
    };
    let tri = ScreenTriangle { v: [v(rng), v(rng), v(rng)], flat: false };
    // Up to 3 repeats either way (negative coordinates included).
    let uv =
        [0, 1, 2].map(|_| [0, 1].map(|_| rng.range(-3 * i64::from(UV_ONE), 3 * i64::from(UV_ONE)) as i32));
    (tri, uv)
}

fn textured_triangles<M: Interpolation>(seed: u64) -> (Stats, Stats) {
    let mut rng = Rng::new(seed);
    let (mut nearest, mut bilinear) = (Stats::default(), Stats::default());
    for t in 0..600 {
        // Powers of two and not, small and large (16 px of screen per texel
        // down to several texels per pixel).
        let (w, h) = [(8, 8), (5, 12), (64, 32), (3, 100)][t % 4];
        let raw: Vec<u16> = (0..w * h).map(|_| rng.below(1 << 16) as u16).collect();
        let tex = Texture::<Rgb565>::new(&raw, w, h).unwrap();
        let reference = RefTexture::rgb565(&raw, w.into(), h.into());
        let (tri, uv) = random_textured_triangle(&mut rng, 16.0);
        let address = [[Address::Wrap; 2], [Address::Clamp; 2], [Address::Wrap, Address::Clamp]][t % 3];
        check_triangle::<M>(&tri, uv, &tex, &reference, address, &mut nearest, &mut bilinear);
    }
    (nearest, bilinear)
}

#[test]
fn perspective_correct_textured_triangles_within_derived_bounds() {
    let (n, b) = textured_triangles::<PerspectiveCorrect>(0x7e47_0e50);
    println!(
        "textured, perspective-correct: {} px; bilinear worst {:.4} (worst error/bound {:.3}); nearest all within δ, {} px ambiguous",
        b.pixels, b.worst, b.worst_ratio, n.ambiguous
    );
    assert!(b.pixels > 200_000, "{}", b.pixels);
    assert!(n.ambiguous * 50 < n.pixels, "{n:?}");
}

#[test]
fn affine_textured_triangles_within_derived_bounds() {
    let (n, b) = textured_triangles::<Affine>(0x7e47_0e51);
    println!(
        "textured, affine (vs screen-linear uv): {} px; bilinear worst {:.4} (worst error/bound {:.3}); nearest {} px ambiguous",
        b.pixels, b.worst, b.worst_ratio, n.ambiguous
    );
    assert!(b.pixels > 200_000, "{}", b.pixels);
    assert!(n.ambiguous * 50 < n.pixels, "{n:?}");
}

/// A floor receding from w = 1 to w = 20 (as in `perspective.rs`), textured
/// with 4 × 20 repeats of an 8 × 8 texture: affine texture coordinates drift
/// by texels, perspective-correct ones stay within their bound.
#[test]
fn affine_swims_on_a_receding_floor_perspective_correct_does_not() {
    let fy = 1.0 / 0.5f64.tan();
    let fx = fy * H as f64 / W as f64;
    let corner = |x: f64, w: f64| {
        let sx = W as f64 / 2.0 * (1.0 + fx * x / w);
        let sy = H as f64 / 2.0 * (1.0 + fy / w);
        let pos = SubPoint::new((sx * 16.0).round() as i32, (sy * 16.0).round() as i32).unwrap();
        ScreenVertex { pos, depth: 0, inv_w: (1073741824.0 / w).round() as u32, color: [0; 3] }
    };
    let v = [corner(-3.0, 1.0), corner(3.0, 1.0), corner(3.0, 20.0), corner(-3.0, 20.0)];
    let uvs = [[0, 0], [4 * UV_ONE, 0], [4 * UV_ONE, 20 * UV_ONE], [0, 20 * UV_ONE]];
    let mut rng = Rng::new(5);
    let raw: Vec<u16> = (0..64).map(|_| rng.below(1 << 16) as u16).collect();
    let tex = Texture::<Rgb565>::new(&raw, 8, 8).unwrap();
    let reference = RefTexture::rgb565(&raw, 8, 8);
    // Worst texture-coordinate error in texels, and worst colour error,
    // against the perspective-correct reference.
    let mut worst = [(0f64, 0f64); 2];
    let mut pixels = 0;
    for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
        let tri = ScreenTriangle { v: [v[a], v[b], v[c]], flat: false };
        let uv = [uvs[a], uvs[b], uvs[c]];
        let p = Varyings::new(&tri, uv, PerspectiveCorrect).unwrap().unwrap();
        let l = Varyings::new(&tri, uv, Affine).unwrap().unwrap();
        let bands = [
            draw_textured::<PerspectiveCorrect, Bilinear>(&tri, uv, &tex, Sampler::BILINEAR_WRAP).unwrap(),
            draw_textured::<Affine, Bilinear>(&tri, uv, &tex, Sampler::BILINEAR_WRAP).unwrap(),
        ];
        let mut p_nearest = Stats::default();
        let mut p_bilinear = Stats::default();
        // The perspective-correct image passes the general check.
        check_triangle::<PerspectiveCorrect>(
            &tri,
            uv,
            &tex,
            &reference,
            [Address::Wrap; 2],
            &mut p_nearest,
            &mut p_bilinear,
        );
        for y in 0..H as i32 {
            for x in 0..W as i32 {
                let Some((exact, _)) = reference_uv(&tri, &uv, x, y) else { continue };
                let want = reference.bilinear(exact, [Address::Wrap; 2]);
                // The perspective-correct coordinates stay within the
                // `Varyings` bound.
                let pc = p.at(x, y);
                for k in 0..2 {
                    let bound = varying_bound::<PerspectiveCorrect>(&tri, exact[k]);
                    assert!((f64::from(pc[k]) - exact[k]).abs() <= bound, "({x},{y}) {pc:?} {exact:?}");
                }
                for (m, got_uv) in [pc, l.at(x, y)].into_iter().enumerate() {
                    let du = (0..2)
                        .map(|k| (f64::from(got_uv[k]) - exact[k]).abs() * 8.0 / 65536.0)
                        .fold(0f64, f64::max);
                    let c = bands[m].rows()[y as usize][x as usize];
                    let e = [c.r(), c.g(), c.b()]
                        .iter()
                        .zip(want)
                        .map(|(&g, w)| (f64::from(g) - w).abs())
                        .fold(0f64, f64::max);
                    worst[m] = (worst[m].0.max(du), worst[m].1.max(e));
                }
                pixels += 1;
            }
        }
    }
    println!(
        "floor, {pixels} px: perspective-correct worst uv error {:.5} texel, colour {:.2}; affine {:.2} texels, colour {:.1}",
        worst[0].0, worst[0].1, worst[1].0, worst[1].1
    );
    assert!(pixels > 1500, "{pixels}");
    assert!(worst[1].0 > 100.0 * worst[0].0 && worst[1].0 > 1.0, "affine not clearly worse: {worst:?}");
    assert!(worst[1].1 > 20.0 * worst[0].1, "affine colour not clearly worse: {worst:?}");
}
