//! Depth quantization per format through the rasterizer ([`draw_triangle`]).
//!
//! Reference: the f64 plane through the snapped vertices' `(x, y, depth/2^32)`
//! at the pixel centre, times `MAX = 2^b − 1` (`ref3d::depth_code`).
//!
//! Derived bound (from the `raster3d` and `attr` docs, not from the code):
//! the plane's vertex values are `depth·MAX/2^16` truncated to whole units of
//! 2^-16 code (error < 2^-16 code, and at a pixel inside the triangle the
//! plane is a convex combination of them), interpolation adds < 2^13 units =
//! 1/8 code, and the stored code is that rounded to nearest. Hence
//! `|stored − exact| ≤ 1/2 + E` with `E = 1/8 + 2^-16`: the stored code is the
//! correctly rounded one except where `exact` is within `E` of a half-integer,
//! and then it is off by one. Rounding is monotone, so for any two pixels
//! `exact(p) + 2E < exact(q)` implies `stored(p) ≤ stored(q)`.
//!
//! [`draw_triangle`]: microraster::raster3d::draw_triangle

use crate::ref3d::{depth_code, draw_frame};
use crate::reference::{Rng, exact_coverage, random_triangle};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthFormat, DepthState};
use microraster::edge::Cull;
use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
use microraster::{ClipRect, SubPoint};

const W: usize = 64;
const H: usize = 48;
const E: f64 = 0.125 + 1.0 / 65536.0;
/// f64 evaluation error of the reference, in codes (< 2^-20 even for Depth32).
const F64_SLOP: f64 = 1e-6;

fn random_depths(rng: &mut Rng) -> [u32; 3] {
    let u = |rng: &mut Rng| rng.next_u64() as u32;
    match rng.below(8) {
        0 | 1 => [u(rng), u(rng), u(rng)],
        2 => [0, 1, 2].map(|_| rng.below(1 << 20) as u32), // near the near plane
        3 => [0, 1, 2].map(|_| u32::MAX - rng.below(1 << 20) as u32), // near the far plane
        4 => {
            // A narrow range: gradients below one code per pixel in every format.
            let base = rng.below(1 << 31) as u32 + (1 << 30);
            let spread = 1 << rng.range(0, 24);
            [0, 1, 2].map(|_| base + rng.below(spread) as u32)
        }
        5 => [[0, u32::MAX, u(rng)], [u32::MAX, u32::MAX, u(rng)], [0, 0, u(rng)]][rng.below(3) as usize],
        6 => [u(rng); 3], // constant depth
        _ => {
            // Exact codes of a random format at the vertices (sometimes ±1 unit).
            let k = 1u64 << [8, 16, 24][rng.below(3) as usize];
            [0, 1, 2].map(|_| {
                let c = rng.below(k);
                (c * u32::MAX as u64 / (k - 1)) as u32 ^ rng.below(2) as u32
            })
        }
    }
}

fn screen<const S: u32>(pos: [SubPoint<S>; 3], depth: [u32; 3]) -> ScreenTriangle<S> {
    let v = |i: usize| ScreenVertex { pos: pos[i], depth: depth[i], inv_w: 1 << 30, color: [255, 0, 0] };
    ScreenTriangle { v: [v(0), v(1), v(2)], flat: true }
}

/// Worst `|stored − exact|`, pixels checked, pixels off the rounded value.
struct Stats {
    triangles: usize,
    pixels: usize,
    off_by_one: usize,
    worst: f64,
    pairs: Vec<(f64, u32)>,
}

fn check_format<F: DepthFormat, const S: u32>(rng: &mut Rng, triangles: usize) -> Stats {
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let mut st = Stats { triangles: 0, pixels: 0, off_by_one: 0, worst: 0.0, pairs: Vec::new() };
    while st.triangles < triangles {
        let pos = random_triangle::<S>(rng, W as i32, H as i32);
        let tri = screen(pos, random_depths(rng));
        let cov = exact_coverage(pos, clip, Cull::None);
        if cov.is_empty() {
            continue;
        }
        st.triangles += 1;
        let (color, depth) =
            draw_frame::<Gray8, F, Affine, S, W, H>(&[tri], Gray8::new(0), DepthState::ALWAYS_WRITE);
        for y in 0..H as i32 {
            for x in 0..W as i32 {
                let i = y as usize * W + x as usize;
                let covered = color[i] != Gray8::new(0);
                assert_eq!(covered, cov.get(x, y), "coverage at ({x},{y}) of {tri:?}");
                if !covered {
                    assert_eq!(depth[i], F::MAX, "depth written outside the triangle");
                    continue;
                }
                let exact = depth_code::<F, S>(&tri, x, y).unwrap();
                let stored = depth[i];
                let err = (stored as f64 - exact).abs();
                st.worst = st.worst.max(err);
                assert!(
                    err <= 0.5 + E + F64_SLOP,
                    "{}-bit: stored {stored}, exact {exact} at ({x},{y}) of {tri:?}",
                    F::BITS
                );
                if stored as f64 != exact.round() && (exact.fract() - 0.5).abs() > 1e-9 {
                    // Only allowed within E of a rounding boundary.
                    let to_half = ((exact - exact.floor()) - 0.5).abs();
                    assert!(to_half <= E + F64_SLOP, "{}-bit: {stored} for {exact} at ({x},{y})", F::BITS);
                    st.off_by_one += 1;
                }
                st.pixels += 1;
                st.pairs.push((exact, stored));
            }
        }
    }
    st
}

/// Every pair `(p, q)` with `exact(p) + 2E < exact(q)` has `stored(p) ≤
/// stored(q)`: after sorting by exact depth, each entry's stored value must not
/// exceed the smallest stored value among entries more than 2E deeper.
fn check_monotonic(mut pairs: Vec<(f64, u32)>, name: &str) -> usize {
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let n = pairs.len();
    let mut suffix_min = vec![u32::MAX; n + 1];
    for i in (0..n).rev() {
        suffix_min[i] = suffix_min[i + 1].min(pairs[i].1);
    }
    let mut j = 0;
    for i in 0..n {
        while j < n && pairs[j].0 <= pairs[i].0 + 2.0 * E + F64_SLOP {
            j += 1;
        }
        assert!(
            pairs[i].1 <= suffix_min[j],
            "{name}: depth {} stored {} but a pixel deeper by > 2E stored {}",
            pairs[i].0,
            pairs[i].1,
            suffix_min[j]
        );
    }
    n
}

#[test]
fn depth_is_rounded_plane_within_derived_bound_for_every_format() {
    let mut rng = Rng::new(0xde97_0001);
    let n = 4000;
    let runs = [
        ("8-bit, S = 4", check_format::<Depth8, 4>(&mut rng, n)),
        ("16-bit, S = 4", check_format::<Depth16, 4>(&mut rng, n)),
        ("24-bit, S = 4", check_format::<Depth24, 4>(&mut rng, n)),
        ("32-bit, S = 4", check_format::<Depth32, 4>(&mut rng, n)),
        ("16-bit, S = 0", check_format::<Depth16, 0>(&mut rng, n)),
        ("24-bit, S = 8", check_format::<Depth24, 8>(&mut rng, n)),
    ];
    for (name, st) in runs {
        let pairs = check_monotonic(st.pairs, name);
        println!(
            "depth {name}: {} triangles, {} pixels, worst |stored - exact| {:.4} LSB (bound {:.4}), \
             {} pixels off the rounded value (all within E of a tie), monotonic over {pairs} sorted pixels",
            st.triangles,
            st.pixels,
            st.worst,
            0.5 + E,
            st.off_by_one
        );
        assert_eq!(st.triangles, n);
        assert!(st.pixels >= 2_000_000, "{name}: only {} pixels checked", st.pixels);
        assert_eq!(pairs, st.pixels);
    }
}

/// A constant-depth triangle: `depth` at every vertex.
fn constant<F: DepthFormat>(depth: u32) -> Vec<u32> {
    let p = |x, y| SubPoint::<4>::new(x, y).unwrap();
    // Covers most of the frame; vertices far outside exercise the wide setup.
    let tri = screen([p(-200, -300), p(W as i32 * 40, 20), p(30, H as i32 * 40)], [depth; 3]);
    let (color, depth) =
        draw_frame::<Gray8, F, Affine, 4, W, H>(&[tri], Gray8::new(0), DepthState::ALWAYS_WRITE);
    color.iter().zip(depth).filter(|(c, _)| **c != Gray8::new(0)).map(|(_, d)| d).collect()
}

fn ends<F: DepthFormat>() -> (usize, usize) {
    let zero = constant::<F>(0);
    assert!(zero.len() > W * H / 2);
    assert!(zero.iter().all(|&d| d == 0), "{}-bit: depth 0 not stored as 0", F::BITS);
    // u32::MAX is depth 1.0 (`ScreenVertex::depth`): the far plane.
    let one = constant::<F>(u32::MAX);
    let wrong: Vec<u32> = one.iter().copied().filter(|&d| d != F::MAX).take(3).collect();
    assert!(wrong.is_empty(), "{}-bit: depth 1.0 stored as {wrong:?}, expected MAX = {}", F::BITS, F::MAX);
    (zero.len(), one.len())
}

#[test]
fn depth_zero_and_one_map_to_zero_and_max() {
    let runs =
        [(8, ends::<Depth8>()), (16, ends::<Depth16>()), (24, ends::<Depth24>()), (32, ends::<Depth32>())];
    for (bits, (a, b)) in runs {
        println!("depth {bits}-bit ends: {a} pixels at 0 -> 0, {b} pixels at 1.0 -> MAX");
        assert!(a > 0 && b > 0);
    }
}
