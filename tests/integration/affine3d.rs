//! Affine Gouraud colour of the 3D fragment loop against an f64 reference,
//! and band invariance of small depth-tested triangles.
//!
//! Reference: the screen-linear colour `Σ λ_i c_i` with `λ` the exact
//! barycentrics of the pixel centre on the snapped vertices
//! (`ref3d::bary`). Derived bound (from the `raster3d` docs, not the code):
//! a channel is within `1/2 + 2^-7` of it. Triangles of every size are drawn,
//! so both ways the loop colours a triangle are held to it: planes, and the
//! per-pixel barycentric division of tiny triangles (twice the area below
//! 2^16 internal units, `raster3d::tiny`), which the test counts.

use crate::ref3d::{bary, draw_frame, is_tiny};
use crate::reference::{Rng, exact_coverage};
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888};
use microraster::band::Band;
use microraster::depth::{Depth16, DepthFormat, DepthRows, DepthState, NoDepth};
use microraster::edge::Cull;
use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex, draw_triangle};
use microraster::{ClipRect, Interpolate, SubPoint};

const W: usize = 64;
const H: usize = 48;
const BOUND: f64 = 0.5 + 1.0 / 128.0;

/// A random triangle inside (or reaching into) the frame, `size` pixels
/// across at most, 1/16 px resolution.
fn triangle<C: Interpolate>(rng: &mut Rng, size: i64) -> ScreenTriangle<4> {
    let (cx, cy) = (rng.range(-4, W as i64 + 4) * 16, rng.range(-4, H as i64 + 4) * 16);
    let m = C::CHANNEL_MAX;
    let mut v = || {
        let (x, y) = (cx + rng.range(0, size * 16), cy + rng.range(0, size * 16));
        ScreenVertex {
            pos: SubPoint::<4>::new(x as i32, y as i32).unwrap(),
            depth: rng.below(1 << 32) as u32,
            inv_w: 1 << 30,
            color: [0, 1, 2].map(|k| rng.below(m[k] as u64 + 1) as u8),
        }
    };
    ScreenTriangle { v: [v(), v(), v()], flat: false }
}

/// Every covered channel of `C` within the bound, drawn with depth format
/// `F` and `state` (one that every pixel passes); (samples, tiny samples,
/// max error).
fn check<C: Interpolate, F: DepthFormat>(
    seed: u64,
    triangles: usize,
    state: DepthState,
) -> (usize, usize, f64) {
    let mut rng = Rng::new(seed);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let (mut n, mut tiny, mut worst) = (0, 0, 0f64);
    for i in 0..triangles {
        let size = [1, 2, 3, 6, 12, 40][i % 6];
        let t = triangle::<C>(&mut rng, size);
        let (frame, _) = draw_frame::<C, F, Affine, 4, W, H>(&[t], C::from_channels([0; 3]), state);
        let small = is_tiny(t.v.map(|v| v.pos));
        for (x, y) in exact_coverage(t.v.map(|v| v.pos), clip, Cull::None).pixels() {
            let (num, d) = bary(t.v.map(|v| v.pos), x, y).unwrap();
            let got = frame[y as usize * W + x as usize].to_channels();
            for (k, &got) in got.iter().enumerate() {
                if C::CHANNEL_MAX[k] == 0 {
                    continue;
                }
                let want: f64 = (0..3).map(|i| num[i] as f64 / d as f64 * t.v[i].color[k] as f64).sum();
                let e = (got as f64 - want).abs();
                assert!(e <= BOUND + 1e-9, "channel {k} at ({x}, {y}): {got} vs {want} for {t:?}");
                worst = worst.max(e);
                n += 1;
                tiny += small as usize;
            }
        }
    }
    (n, tiny, worst)
}

#[test]
fn affine_colour_within_derived_bound_for_tiny_and_larger_triangles() {
    // With a depth buffer the loop tests depth first and colours the
    // pixels that pass from their index in the span (spans of up to 40
    // pixels here, beyond its 32-pixel chunks); without, it steps the colour.
    let (always, none) = (DepthState::LESS_EQUAL_WRITE, DepthState::DISABLED);
    for (name, (n, tiny, worst)) in [
        ("Rgb888", check::<Rgb888, NoDepth>(0x5EED_0001, 6000, none)),
        ("Rgb565", check::<Rgb565, NoDepth>(0x5EED_0002, 6000, none)),
        ("Gray8", check::<Gray8, NoDepth>(0x5EED_0003, 6000, none)),
        ("Rgb888, Depth16", check::<Rgb888, Depth16>(0x5EED_0004, 6000, always)),
        ("Rgb565, Depth16", check::<Rgb565, Depth16>(0x5EED_0005, 6000, always)),
    ] {
        println!(
            "affine colour, {name}: {n} channel samples ({tiny} of tiny triangles), max error {worst:.4}"
        );
        // Both paths exercised, each on many samples.
        assert!(tiny > 5_000 && n - tiny > 30_000, "{name}: {tiny} tiny of {n}");
    }
}

/// Draws `tris` band by band (`bh` rows each, depth cleared per band) and
/// returns the colours and depth codes of the frame, row-major.
fn banded<F: DepthFormat>(tris: &[ScreenTriangle<4>], bh: usize) -> (Vec<Rgb565>, Vec<u32>) {
    let bg = Rgb565::new(1, 2, 3);
    let mut band = Box::new(Band::<Rgb565, W, H>::new(bg));
    let (mut color, mut depth) = (Vec::new(), Vec::new());
    for y0 in (0..H).step_by(bh) {
        let rows = bh.min(H - y0);
        let mut d = vec![[F::FAR; W]; rows];
        {
            let mut view = band.view(y0 as i32, rows, bg);
            let mut drows = DepthRows::<F, W>::new(&mut d);
            for t in tris {
                draw_triangle(t, &mut view, &mut drows, DepthState::LESS_WRITE, Affine);
            }
        }
        color.extend(band.rows()[..rows].iter().flatten().copied());
        depth.extend(d.iter().flatten().map(|&s| F::to_u32(s)));
    }
    (color, depth)
}

#[test]
fn small_depth_tested_triangles_are_band_invariant() {
    let mut rng = Rng::new(0x0BAD_5EED);
    // Overlapping triangles of up to a few pixels (most tiny), some larger,
    // flat and Gouraud, depths random: the depth test decides many pixels.
    let tris: Vec<_> = (0..3000)
        .map(|i| {
            let mut t = triangle::<Rgb565>(&mut rng, [1, 2, 3, 5, 9][i % 5]);
            t.flat = i % 7 == 0;
            t
        })
        .collect();
    let tiny = tris.iter().filter(|t| is_tiny(t.v.map(|v| v.pos))).count();
    assert!(tiny > 1500, "{tiny} tiny triangles");
    let full = banded::<Depth16>(&tris, H);
    for bh in [1, 3, 7, 16] {
        assert!(banded::<Depth16>(&tris, bh) == full, "{bh}-row bands differ from one band");
    }
    // Something was drawn and tested.
    let bg = Rgb565::new(1, 2, 3);
    let drawn = full.0.iter().filter(|&&c| c != bg).count();
    assert!(drawn > W * H / 2, "{drawn} pixels drawn");
}

/// Vertex channels above the colour's maximum (a hand-made triangle; the
/// pipeline never makes one) are clamped per pixel, on both of the loop's
/// ways (planes, tiny triangles), and a triangle whose channels are in range
/// takes the loop without the clamp: the same channel values as a colour
/// type wide enough for them, here `Rgb888`, then capped at `Rgb565`'s
/// maximum (same planes, same sums, so exact).
#[test]
fn out_of_range_vertex_channels_are_clamped_per_pixel() {
    let mut rng = Rng::new(0x000C_1A4B);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let max = Rgb565::CHANNEL_MAX;
    let (mut clamped, mut below, mut samples) = (0, 0, 0);
    for i in 0..3000 {
        let mut t = triangle::<Rgb888>(&mut rng, [2, 6, 12, 40][i % 4]);
        if i % 2 == 0 {
            // In range for Rgb565: the loop without the clamp.
            for v in &mut t.v {
                v.color = [0, 1, 2].map(|k| v.color[k] % (max[k] + 1));
            }
        }
        let (wide, _) =
            draw_frame::<Rgb888, NoDepth, Affine, 4, W, H>(&[t], Rgb888::new(0, 0, 0), DepthState::DISABLED);
        let (narrow, _) =
            draw_frame::<Rgb565, NoDepth, Affine, 4, W, H>(&[t], Rgb565::new(0, 0, 0), DepthState::DISABLED);
        for (x, y) in exact_coverage(t.v.map(|v| v.pos), clip, Cull::None).pixels() {
            let p = y as usize * W + x as usize;
            let (w, n) = (wide[p].to_channels(), narrow[p].to_channels());
            for k in 0..3 {
                assert_eq!(n[k], w[k].min(max[k]), "channel {k} at ({x}, {y}) of {t:?}");
                clamped += (w[k] > max[k]) as usize;
                below += (w[k] < max[k]) as usize;
                samples += 1;
            }
        }
    }
    // Clamped and unclamped channels both occur, in numbers.
    assert!(clamped > samples / 10 && below > samples / 10, "{clamped} clamped, {below} below, of {samples}");
}
