//! Varyings (per-vertex value vectors) against f64 references, and the
//! fragment hook against the colour rasterizer's coverage.

use crate::ref3d::bary;
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState, NoDepth};
use microraster::raster3d::{Affine, PerspectiveCorrect, ScreenTriangle, ScreenVertex, draw_triangle};
use microraster::varyings::{MAX_VARYING, Varyings, draw_fragments};
use microraster::{Band, SubPoint};

const W: usize = 96;
const H: usize = 64;

fn random_triangle(rng: &mut Rng, depth_ratio: f64) -> ScreenTriangle<4> {
    let v = |rng: &mut Rng| ScreenVertex {
        pos: SubPoint::new(
            rng.range(-200, (W as i64 + 12) << 4) as i32,
            rng.range(-200, (H as i64 + 12) << 4) as i32,
        )
        .unwrap(),
        depth: rng.below(1 << 32) as u32,
        inv_w: ((1u64 << 30) as f64 / rng.uniform(1.0, depth_ratio)) as u32,
        color: [0; 3],
    };
    ScreenTriangle { v: [v(rng), v(rng), v(rng)], flat: false }
}

#[test]
fn affine_and_perspective_varyings_within_derived_bounds() {
    let mut rng = Rng::new(0x5eed_0a77);
    let (mut tris, mut samples, mut worst_a, mut worst_p) = (0, 0u64, 0f64, 0f64);
    for _ in 0..3000 {
        let tri = random_triangle(&mut rng, 16.0);
        let vals: [[i32; 3]; 3] = [0, 1, 2].map(|_| {
            let big = rng.chance(0.5);
            [0, 1, 2].map(|_| if big { rng.range(-(MAX_VARYING as i64), MAX_VARYING as i64) } else { rng.range(-4000, 4000) } as i32)
        });
        let (Some(a), Some(p)) = (
            Varyings::new(&tri, vals, Affine).unwrap(),
            Varyings::new(&tri, vals, PerspectiveCorrect).unwrap(),
        ) else {
            continue;
        };
        tris += 1;
        let inv: Vec<f64> = tri.v.iter().map(|v| f64::from(v.inv_w)).collect();
        // The normalisation of src/raster/varyings.rs: the largest 1/w gets 30 bits.
        let qmax = tri.v.iter().map(|v| v.inv_w).max().unwrap();
        let scale = 2f64.powi(30 - (32 - qmax.leading_zeros()) as i32);
        let q_lo = inv.iter().cloned().fold(f64::MAX, f64::min) * scale;
        for y in 0..H as i32 {
            for x in 0..W as i32 {
                let Some((num, det)) = bary(tri.v.map(|v| v.pos), x, y) else { continue };
                let l = num.map(|n| n as f64 / det as f64);
                if l.iter().any(|&l| l < 0.0) {
                    continue; // outside: the planes are only bounded inside
                }
                let (got_a, got_p) = (a.at(x, y), p.at(x, y));
                let den: f64 = (0..3).map(|i| l[i] * inv[i]).sum();
                for k in 0..3 {
                    let v = |i: usize| f64::from(vals[i][k]);
                    let lin: f64 = (0..3).map(|i| l[i] * v(i)).sum();
                    let persp: f64 = (0..3).map(|i| l[i] * inv[i] * v(i)).sum::<f64>() / den;
                    let ea = (f64::from(got_a[k]) - lin).abs();
                    let ep = (f64::from(got_p[k]) - persp).abs();
                    // Bounds from src/raster/varyings.rs (plus f64 evaluation slack).
                    assert!(ea <= 0.5 + 1.0 / 128.0 + 1e-6, "affine {ea} at ({x},{y}) {tri:?} {vals:?}");
                    let bound = 0.5 + (1024.0 + persp.abs() / 8.0) / (q_lo - 0.125) + 1e-6;
                    assert!(ep <= bound, "perspective {ep} > {bound} at ({x},{y})");
                    worst_a = worst_a.max(ea);
                    worst_p = worst_p.max(ep);
                    samples += 1;
                }
            }
        }
    }
    println!(
        "varyings: {tris} triangles, {samples} samples; worst affine {worst_a:.4}, perspective {worst_p:.4}"
    );
    assert!(tris > 2000 && samples > 1_000_000);
    assert_eq!(
        Varyings::new(&random_triangle(&mut rng, 2.0), [[MAX_VARYING + 1], [0], [0]], Affine).err(),
        Some(microraster::Error::CoordinateOutOfRange)
    );
}

#[test]
fn fragment_hook_covers_what_the_colour_rasterizer_covers() {
    let mut rng = Rng::new(77);
    let mut fragments = 0;
    for _ in 0..500 {
        let mut tri = random_triangle(&mut rng, 4.0);
        tri.flat = true;
        tri.v[0].color = [31, 0, 0];
        let mut a = Band::<Rgb565, W, H>::new(Rgb565::BLACK);
        let mut za = DepthBand::<Depth16, W, H>::new();
        draw_triangle(
            &tri,
            &mut a.view(0, H, Rgb565::BLACK),
            &mut za.rows_mut(H),
            DepthState::LESS_WRITE,
            Affine,
        );
        let mut b = Band::<Rgb565, W, H>::new(Rgb565::BLACK);
        let mut zb = DepthBand::<Depth16, W, H>::new();
        let mut view = b.view(0, H, Rgb565::BLACK);
        draw_fragments(&tri, &mut view, &mut zb.rows_mut(H), DepthState::LESS_WRITE, |_, _| {
            fragments += 1;
            Some(Rgb565::RED)
        });
        assert_eq!(a.rows(), b.rows());
        assert_eq!(za.rows(), zb.rows());
        // Without depth: every covered pixel, once.
        let mut seen = std::collections::HashSet::new();
        let mut c = Band::<Rgb565, W, H>::new(Rgb565::BLACK);
        let mut zn = DepthBand::<NoDepth, W, H>::new();
        draw_fragments(
            &tri,
            &mut c.view(0, H, Rgb565::BLACK),
            &mut zn.rows_mut(H),
            DepthState::LESS_WRITE,
            |x, y| {
                assert!(seen.insert((x, y)), "fragment ({x},{y}) twice");
                None
            },
        );
        let covered = a.rows().iter().flatten().filter(|&&p| p == Rgb565::RED).count();
        assert_eq!(seen.len(), covered);
    }
    println!("fragment hook: {fragments} fragments over 500 triangles");
    assert!(fragments > 10_000);
}
