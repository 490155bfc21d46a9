//! The fast tier's rasterizer against the exact tier's
//! ([`draw_triangle_in`] with [`Precision::Fast`] and [`Precision::Exact`]),
//! on the same [`ScreenTriangle`]s: the same covered pixels; each depth
//! code within one of the exact tier's; each colour channel within one on
//! at least 99.9 % of covered pixels and within two on all. Random
//! triangles, tiny (the per-centre path) and large (the plane path), lit
//! smoothly as a mesh is and with unrelated vertex colours, affine and
//! perspective-correct, for Depth8, Depth16, Depth24 and Depth32, Rgb565 and
//! Rgb888.

use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthBand, DepthFormat, DepthState, DepthTest};
use microraster::raster3d::{
    Affine, Interpolation, PerspectiveCorrect, Precision, ScreenTriangle, ScreenVertex, draw_triangle_in,
};
use microraster::{Band, Interpolate, SubPoint};

const W: usize = 96;
const H: usize = 24;

/// Both tiers' differences over many triangles.
#[derive(Debug, Default)]
struct Tally {
    pixels: u64,
    /// Pixels with a channel differing by more than one.
    beyond_one: u64,
    /// Largest channel and depth differences seen.
    worst_channel: u32,
    worst_depth: u32,
    /// Pixels whose colour or depth differ at all (the tiers must be
    /// different somewhere, or the comparison tests nothing).
    differ: u64,
}

/// One tier's pixels: colour and depth of every pixel of the band.
fn draw<C: Interpolate, F: DepthFormat, M: Interpolation>(
    tri: &ScreenTriangle<4>,
    y0: i32,
    precision: Precision,
) -> (Vec<C>, Vec<u32>) {
    let bg = C::from_channels([0; 3]);
    let mut band = Band::<C, W, H>::new(bg);
    let mut depth = DepthBand::<F, W, H>::new();
    let mut view = band.view(y0, H, bg);
    // Every covered pixel is written (its depth is below the far plane).
    let always = DepthState::new(DepthTest::Always, true);
    draw_triangle_in(tri, &mut view, &mut depth.rows_mut(H), always, M::default(), precision);
    let colors = view.pixels().collect();
    let depths =
        (0..H).flat_map(|r| (0..W).map(move |x| (r, x))).map(|(r, x)| depth.get(r, x).unwrap()).collect();
    (colors, depths)
}

/// Draws `tri` in both tiers and adds their differences to `t`; panics if
/// coverage or depth differ beyond the bounds, or a channel by more than two.
fn compare<C: Interpolate + core::fmt::Debug, F: DepthFormat, M: Interpolation>(
    tri: &ScreenTriangle<4>,
    y0: i32,
    t: &mut Tally,
) {
    let (ce, de) = draw::<C, F, M>(tri, y0, Precision::Exact);
    let (cf, df) = draw::<C, F, M>(tri, y0, Precision::Fast);
    for i in 0..W * H {
        let covered = de[i] != F::MAX;
        assert_eq!(covered, df[i] != F::MAX, "coverage at {i}: {tri:?}");
        if !covered {
            continue;
        }
        let dz = de[i].abs_diff(df[i]);
        let (a, b) = (ce[i].to_channels(), cf[i].to_channels());
        let dc = (0..3).map(|k| a[k].abs_diff(b[k]) as u32).max().unwrap_or(0);
        assert!(dz <= 1, "depth {} vs {} at {i}: {tri:?}", de[i], df[i]);
        assert!(dc <= 2, "colour {a:?} vs {b:?} at {i}: {tri:?}");
        t.pixels += 1;
        t.beyond_one += u64::from(dc > 1);
        t.worst_channel = t.worst_channel.max(dc);
        t.worst_depth = t.worst_depth.max(dz);
        t.differ += u64::from(dz > 0 || dc > 0);
    }
}

/// A random triangle of at most `size` pixels a side inside the band's
/// columns, rows around `y0..y0 + H`; vertex depths below the far plane
/// (so a covered pixel's depth is never the cleared value); colours
/// within `C`'s channels, either a smooth lit gradient (`spread` steps at
/// most across the triangle) or unrelated; `1/w` within `ratio` of each
/// other.
fn triangle<C: Interpolate>(rng: &mut Rng, y0: i32, size: f64, spread: u8, ratio: f64) -> ScreenTriangle<4> {
    let (cx, cy) = (rng.uniform(0.0, W as f64), rng.uniform(y0 as f64 - 4.0, (y0 + H as i32) as f64 + 4.0));
    let max = C::CHANNEL_MAX;
    let base = [0, 1, 2].map(|k| rng.below(u64::from(max[k]) + 1) as i64);
    let inv_w0 = rng.range(1 << 20, 1 << 31) as f64;
    let v = |rng: &mut Rng| {
        let (x, y) = (cx + rng.uniform(-size, size) / 2.0, cy + rng.uniform(-size, size) / 2.0);
        let pos = SubPoint::<4>::new((x * 16.0).round() as i32, (y * 16.0).round() as i32).unwrap();
        let color = [0, 1, 2].map(|k| {
            let c = if spread == u8::MAX {
                rng.below(u64::from(max[k]) + 1) as i64
            } else {
                base[k] + rng.range(-i64::from(spread), i64::from(spread))
            };
            c.clamp(0, i64::from(max[k])) as u8
        });
        let depth = rng.range(0, (u32::MAX / 100 * 99) as i64) as u32;
        let inv_w = (inv_w0 * rng.uniform(1.0, ratio)).min(u32::MAX as f64) as u32;
        ScreenVertex { pos, depth, inv_w, color }
    };
    let mut tri = ScreenTriangle { v: [v(rng), v(rng), v(rng)], flat: rng.chance(0.05) };
    if rng.chance(0.5) {
        // Depths near each other, as on a mesh's small triangles.
        let d = tri.v[0].depth;
        for v in &mut tri.v[1..] {
            v.depth = d.saturating_add(rng.below(1 << 24) as u32).min(u32::MAX / 100 * 99);
        }
    }
    tri
}

/// Many triangles of each kind in both tiers; the bounds hold for each
/// pixel (`compare`) and over all of them.
fn check<C: Interpolate + core::fmt::Debug, F: DepthFormat, M: Interpolation>(
    seed: u64,
    cases: u32,
) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    for i in 0..cases {
        let y0 = rng.range(0, 40) as i32;
        // Tiny (most of a mesh's), small, and up to the band's width.
        let size = [1.5, 3.0, 8.0, 30.0, 90.0][(i % 5) as usize];
        let spread = [1u8, 2, 4, 12, u8::MAX][(i / 5 % 5) as usize];
        let ratio = [1.0001, 1.01, 1.3, 4.0][(i / 25 % 4) as usize];
        let tri = triangle::<C>(&mut rng, y0, size, spread, ratio);
        compare::<C, F, M>(&tri, y0, &mut t);
    }
    assert!(t.pixels > u64::from(cases) * 5, "{t:?}");
    assert!(t.differ > 0, "the tiers never differ: {t:?}");
    assert!(t.beyond_one * 1000 <= t.pixels, "more than 0.1 % of pixels beyond ±1: {t:?}");
    assert!(t.worst_channel <= 2 && t.worst_depth <= 1, "{t:?}");
    t
}

#[test]
fn fast_tier_rgb565_depth16_affine() {
    check::<Rgb565, Depth16, Affine>(0xFA57_0001, 6_000);
}

#[test]
fn fast_tier_rgb565_depth16_perspective() {
    check::<Rgb565, Depth16, PerspectiveCorrect>(0xFA57_0002, 6_000);
}

#[test]
fn fast_tier_rgb888_depth16_both() {
    check::<Rgb888, Depth16, Affine>(0xFA57_0003, 3_000);
    check::<Rgb888, Depth16, PerspectiveCorrect>(0xFA57_0004, 3_000);
}

#[test]
fn fast_tier_other_depth_formats() {
    check::<Rgb565, Depth8, Affine>(0xFA57_0005, 2_000);
    check::<Rgb565, Depth24, PerspectiveCorrect>(0xFA57_0006, 2_000);
    check::<Rgb565, Depth32, Affine>(0xFA57_0007, 2_000);
}
