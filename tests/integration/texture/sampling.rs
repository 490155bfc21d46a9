//! Texture sampling (nearest, bilinear; wrap, clamp) against the f64 reference.

use super::{BILINEAR_BOUND, RefTexture};
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565};
use microraster::texture::{Address, Sampler, TexelFormat, Texture, UV_ONE};

/// Texture sizes: powers of two (shift path) and others (multiply path).
const SIZES: [(u32, u32); 9] =
    [(1, 1), (2, 4), (3, 5), (16, 16), (7, 64), (64, 1), (100, 3), (37, 41), (4096, 1)];

/// A coordinate: often near a texel boundary or centre of an axis with
/// `n` texels, sometimes anywhere in `i32`, sometimes at the extremes.
fn coordinate(rng: &mut Rng, n: u32) -> i32 {
    let one = i64::from(UV_ONE);
    match rng.below(6) {
        0 => rng.range(i64::from(i32::MIN), i64::from(i32::MAX)) as i32,
        1 => [i32::MIN, i32::MIN + 1, -1, 0, 1, UV_ONE - 1, UV_ONE, i32::MAX - 1, i32::MAX]
            [rng.below(9) as usize],
        2 | 3 => {
            // (k + ½·c)/n repeats away, ± a few units: edges and centres.
            let k = rng.range(-3 * i64::from(n), 4 * i64::from(n));
            let c = rng.range(0, 1);
            let exact = ((2 * k + c) * one) as f64 / (2.0 * f64::from(n));
            (exact.round() as i64 + rng.range(-2, 2)) as i32
        }
        _ => rng.range(-5 * one, 6 * one) as i32,
    }
}

/// Samples `tex` against the reference at random coordinates with every
/// addressing combination; returns (samples, worst bilinear error).
fn sample_against_reference<F: TexelFormat>(
    rng: &mut Rng,
    tex: &Texture<'_, F>,
    reference: &RefTexture,
    samples: usize,
) -> (usize, f64) {
    let (w, h) = (tex.width(), tex.height());
    let mut worst = 0f64;
    for _ in 0..samples {
        let uv = [coordinate(rng, w), coordinate(rng, h)];
        let a = [Address::Wrap, Address::Clamp];
        let address = [a[rng.below(2) as usize], a[rng.below(2) as usize]];
        let ruv = uv.map(f64::from);
        let nearest = tex.sample(Sampler::NEAREST_WRAP.with_address(address[0], address[1]), uv);
        assert_eq!(
            nearest.map(f64::from),
            reference.nearest(ruv, address),
            "nearest {w}×{h} {uv:?} {address:?}"
        );
        let got = tex.sample(Sampler::BILINEAR_WRAP.with_address(address[0], address[1]), uv);
        let want = reference.bilinear(ruv, address);
        for k in 0..3 {
            let e = (f64::from(got[k]) - want[k]).abs();
            assert!(e <= BILINEAR_BOUND + 1e-9, "bilinear {w}×{h} {uv:?} {address:?}: {got:?} vs {want:?}");
            worst = worst.max(e);
        }
    }
    (samples, worst)
}

#[test]
fn nearest_exact_and_bilinear_within_bound_any_size_and_coordinate() {
    let mut rng = Rng::new(0x07e4_70e5);
    let (mut total, mut worst) = (0, 0f64);
    for (w, h) in SIZES {
        let n = (w * h) as usize;
        let raw: Vec<u16> = (0..n).map(|_| rng.below(1 << 16) as u16).collect();
        let tex = Texture::<Rgb565>::new(&raw, w, h).unwrap();
        let (s, e) =
            sample_against_reference(&mut rng, &tex, &RefTexture::rgb565(&raw, w.into(), h.into()), 40_000);
        total += s;
        worst = worst.max(e);
        // Grey: the same positions, the other format (and transposed sizes).
        let raw: Vec<u8> = (0..n).map(|_| rng.below(256) as u8).collect();
        let tex = Texture::<Gray8>::new(&raw, h, w).unwrap();
        let (s, e) =
            sample_against_reference(&mut rng, &tex, &RefTexture::gray8(&raw, h.into(), w.into()), 40_000);
        total += s;
        worst = worst.max(e);
    }
    println!(
        "texture sampling: {total} samples per filter, nearest exact, worst bilinear error {worst:.5} (bound {BILINEAR_BOUND:.5})"
    );
    // Rounding to 8 bits alone costs up to ½; a much smaller worst would mean
    // the test never reached the interesting cases.
    assert!(worst > 0.49, "{worst}");
}

#[test]
fn bilinear_reproduces_texels_at_their_centres_and_blends_across_the_wrap_seam() {
    let raw: Vec<u8> = (0..5 * 3).map(|i| (i * 17) as u8).collect();
    let tex = Texture::<Gray8>::new(&raw, 5, 3).unwrap();
    let r = RefTexture::gray8(&raw, 5, 3);
    for j in 0..3i64 {
        for i in 0..5i64 {
            // Texel centres are not representable for n = 5 (2^16/10 is not
            // an integer): the nearest coordinate is within ½ unit.
            let uv = [((2 * i + 1) * 65536) as f64 / 10.0, ((2 * j + 1) * 65536) as f64 / 6.0];
            let got = tex.sample(Sampler::BILINEAR_CLAMP, uv.map(|c| c.round() as i32));
            let t = r.at(i, j, [Address::Clamp; 2])[0];
            assert!((f64::from(got[0]) - t).abs() <= 1.0, "{i},{j}: {got:?} vs {t}");
        }
    }
    // Power of two: centres are exact, so is the texel.
    let raw: Vec<u8> = (0..16).map(|i| (i * 13) as u8).collect();
    let tex = Texture::<Gray8>::new(&raw, 4, 4).unwrap();
    for j in 0..4 {
        for i in 0..4 {
            let uv = [(2 * i + 1) * UV_ONE / 8, (2 * j + 1) * UV_ONE / 8];
            for s in [Sampler::BILINEAR_CLAMP, Sampler::BILINEAR_WRAP] {
                assert_eq!(tex.sample(s, uv), [raw[(j * 4 + i) as usize]; 3]);
            }
        }
    }
    // u = 0: half-way between the last and the first texel when wrapping,
    // the first texel alone when clamping.
    let row = [0u8, 0, 0, 200];
    let tex = Texture::<Gray8>::new(&row, 4, 1).unwrap();
    assert_eq!(tex.sample(Sampler::BILINEAR_WRAP, [0, 0]), [100; 3]);
    assert_eq!(tex.sample(Sampler::BILINEAR_WRAP, [UV_ONE * 7, 0]), [100; 3]);
    assert_eq!(tex.sample(Sampler::BILINEAR_CLAMP, [0, 0]), [0; 3]);
    assert_eq!(tex.sample(Sampler::BILINEAR_CLAMP, [i32::MAX, i32::MIN]), [200; 3]);
}

/// `sample_rgba` of the formats with colour and alpha: colour against the
/// reference as `sample` is, alpha against the reference of the alpha plane
/// alone (a grey texture of the stored alphas widened by the documented
/// rule: 8 bits as is for `Rgb565A8`, `n·17` for `Argb4444`), nearest exact,
/// bilinear within the same bound on all four channels.
#[test]
fn rgba_sampling_of_the_alpha_formats_against_reference() {
    use microraster::texture::{Argb4444, Rgb565A8};
    let mut rng = Rng::new(0x07e4_a1fa);
    let mut worst = 0f64;
    for (w, h) in SIZES {
        let n = (w * h) as usize;
        let (wi, hi) = (i64::from(w), i64::from(h));
        let raw: Vec<u32> = (0..n).map(|_| rng.below(1 << 24) as u32).collect();
        let r565: Vec<[u8; 3]> = raw.iter().map(|&t| Rgb565A8::texel((t >> 8) as u16, t as u8)).collect();
        let tex565 = Texture::<Rgb565A8>::new(&r565, w, h).unwrap();
        let colour565 = RefTexture::rgb565(&raw.iter().map(|&t| (t >> 8) as u16).collect::<Vec<_>>(), wi, hi);
        let alpha565 = RefTexture::gray8(&raw.iter().map(|&t| t as u8).collect::<Vec<_>>(), wi, hi);
        let r4444: Vec<u16> = raw.iter().map(|&t| t as u16).collect();
        let tex4444 = Texture::<Argb4444>::new(&r4444, w, h).unwrap();
        let nibbles = |s: u32| r4444.iter().map(move |&t| f64::from((t >> s) & 15) * 17.0);
        let colour4444 = RefTexture {
            w: wi,
            h: hi,
            texels: nibbles(8).zip(nibbles(4)).zip(nibbles(0)).map(|((r, g), b)| [r, g, b]).collect(),
        };
        let alpha4444 = RefTexture { w: wi, h: hi, texels: nibbles(12).map(|a| [a; 3]).collect() };
        for _ in 0..20_000 {
            let uv = [coordinate(&mut rng, w), coordinate(&mut rng, h)];
            let a = [Address::Wrap, Address::Clamp];
            let address = [a[rng.below(2) as usize], a[rng.below(2) as usize]];
            let ruv = uv.map(f64::from);
            let cases = [
                (
                    tex565.sample_rgba(Sampler::NEAREST_WRAP.with_address(address[0], address[1]), uv),
                    tex565.sample_rgba(Sampler::BILINEAR_WRAP.with_address(address[0], address[1]), uv),
                    &colour565,
                    &alpha565,
                ),
                (
                    tex4444.sample_rgba(Sampler::NEAREST_WRAP.with_address(address[0], address[1]), uv),
                    tex4444.sample_rgba(Sampler::BILINEAR_WRAP.with_address(address[0], address[1]), uv),
                    &colour4444,
                    &alpha4444,
                ),
            ];
            for (nearest, bilinear, colour, alpha) in cases {
                let want = |r: [f64; 3], a: [f64; 3]| [r[0], r[1], r[2], a[0]];
                let exact = want(colour.nearest(ruv, address), alpha.nearest(ruv, address));
                assert_eq!(nearest.map(f64::from), exact, "nearest {w}×{h} {uv:?} {address:?}");
                let blend = want(colour.bilinear(ruv, address), alpha.bilinear(ruv, address));
                for k in 0..4 {
                    let e = (f64::from(bilinear[k]) - blend[k]).abs();
                    assert!(e <= BILINEAR_BOUND + 1e-9, "bilinear {w}×{h} {uv:?}: {bilinear:?} vs {blend:?}");
                    worst = worst.max(e);
                }
            }
        }
    }
    println!("rgba sampling: worst bilinear error {worst:.5} (bound {BILINEAR_BOUND:.5})");
    assert!(worst > 0.49, "{worst}");
}
