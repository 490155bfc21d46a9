//! Sprites (`texture::Sprite`) and textures with alpha against an `f64`
//! reference: the exact map from a pixel centre to the texture (the sprite
//! module's geometry, in `f64` with `f64` sine and cosine) and the exact
//! nearest texel or bilinear blend there.
//!
//! The random-texture checks run for both colour formats with alpha,
//! `Argb4444` and `Rgb565A8`, their texels widened by the documented rules
//! (`n·17` per nibble; `Rgb565` bit replication and the alpha byte as is).
//!
//! Bounds (from the sprite and texture docs): the sample point handed to the
//! sampler is within `δ = size·2^-16 + size·4·10^-7 + 10^-6` texels of the
//! exact one (2^-16 truncation, the `f32` sine/cosine, `f64` set-up). So
//! * nearest: pixels whose exact point is more than `δ` from every texel
//!   border sample the exact texel; pixels within `δ` of the box's border
//!   may be in or out;
//! * bilinear: within ½ + 2^-9 (the filter) + 2·255·δ (a channel moves at
//!   most 255 per texel along each axis) of the exact blend.

mod case;

use crate::reference::Rng;
use case::{AlphaFormat, Case, Recorder, border, record};
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};
use microraster::blend::Blend;
use microraster::render::from_fn;
use microraster::texture::{A8, Argb4444, Bilinear, Rgb565A8, Sprite, TexelFormat, Texture};
use microraster::{Band, ClipRect, Error, Renderer};
use std::collections::HashMap;

fn check_nearest<F: AlphaFormat>(case: &Case<F>, exact: bool) -> (usize, usize) {
    let tex = case.texture();
    let got = record(&Sprite::new(&tex).at(case.at).scale(case.scale).rotate(case.angle));
    let d = if exact { 0.0 } else { case.delta() };
    let (mut checked, mut skipped) = (0, 0);
    for y in 0..200 {
        for x in 0..200 {
            let (tx, ty) = case.texel_point(x, y);
            if border(tx) <= d || border(ty) <= d {
                // Counted on and around the sprite only (the grid lines go on forever).
                let near = |t: f64, n: u32| (-1.0..=n as f64 + 1.0).contains(&t);
                skipped += (near(tx, case.w) && near(ty, case.h)) as usize;
                continue;
            }
            let inside = (0.0..case.w as f64).contains(&tx) && (0.0..case.h as f64).contains(&ty);
            // Fully transparent pixels are skipped, not blended.
            let want =
                inside.then(|| case.rgba(tx as usize, ty as usize).map(|c| c as u8)).filter(|c| c[3] > 0);
            assert_eq!(got.get(&(x, y)).copied(), want, "pixel ({x}, {y}) at texel ({tx}, {ty})");
            checked += inside as usize;
        }
    }
    (checked, skipped)
}

#[test]
fn nearest_axis_aligned_integer_scale_is_exact() {
    nearest_axis_aligned::<Argb4444>(0x5971);
    nearest_axis_aligned::<Rgb565A8>(0x5a71);
}

fn nearest_axis_aligned<F: AlphaFormat>(seed: u64) {
    let mut rng = Rng::new(seed);
    let mut checked = 0;
    for _ in 0..300 {
        let case = Case::<F>::random(&mut rng, true);
        let (c, skipped) = check_nearest(&case, true);
        assert_eq!(skipped, 0);
        checked += c;
    }
    assert!(checked > 100_000, "{checked} pixels");
}

#[test]
fn nearest_rotated_and_scaled_matches_f64() {
    nearest_rotated::<Argb4444>(0x5972);
    nearest_rotated::<Rgb565A8>(0x5a72);
}

fn nearest_rotated<F: AlphaFormat>(seed: u64) {
    let mut rng = Rng::new(seed);
    let (mut checked, mut skipped) = (0, 0);
    for _ in 0..400 {
        let (c, s) = check_nearest(&Case::<F>::random(&mut rng, false), false);
        checked += c;
        skipped += s;
    }
    println!("nearest sprites: {checked} pixels checked, {skipped} within δ of a texel border skipped");
    assert!(checked > 200_000 && skipped * 100 < checked, "{checked} checked, {skipped} skipped");
}

#[test]
fn bilinear_is_within_the_stated_bound() {
    bilinear_within_bound::<Argb4444>(0x5973);
    bilinear_within_bound::<Rgb565A8>(0x5a73);
}

fn bilinear_within_bound<F: AlphaFormat>(seed: u64) {
    let mut rng = Rng::new(seed);
    let (mut checked, mut worst) = (0usize, 0f64);
    for _ in 0..300 {
        let aligned = rng.chance(0.2);
        let case = Case::<F>::random(&mut rng, aligned);
        let tex = case.texture();
        let got =
            record(&Sprite::new(&tex).at(case.at).scale(case.scale).rotate(case.angle).filter(Bilinear));
        let (d, bound) = (case.delta(), 0.5 + 1.0 / 512.0 + 2.0 * 255.0 * case.delta());
        for y in 0..200 {
            for x in 0..200 {
                let (tx, ty) = case.texel_point(x, y);
                let near_edge = |t: f64, n: u32| t.abs() <= d || (t - n as f64).abs() <= d;
                if near_edge(tx, case.w) || near_edge(ty, case.h) {
                    continue;
                }
                let inside = (0.0..case.w as f64).contains(&tx) && (0.0..case.h as f64).contains(&ty);
                assert!(inside || !got.contains_key(&(x, y)), "pixel ({x}, {y}) at ({tx}, {ty})");
                if inside {
                    // Fully transparent pixels are skipped, not blended: alpha 0.
                    let g = got.get(&(x, y)).copied().unwrap_or([0; 4]);
                    let want = case.bilinear(tx, ty);
                    let channels: &[usize] = if got.contains_key(&(x, y)) { &[0, 1, 2, 3] } else { &[3] };
                    for &k in channels {
                        let e = (g[k] as f64 - want[k]).abs();
                        assert!(e <= bound, "pixel ({x}, {y}) channel {k}: {} vs {}", g[k], want[k]);
                        worst = worst.max(e);
                    }
                    checked += 1;
                }
            }
        }
    }
    println!("bilinear sprites: {checked} pixels, worst channel error {worst:.3}");
    assert!(checked > 100_000);
}

#[test]
fn a8_mask_is_tinted_and_opacity_scales_alpha() {
    let mask: Vec<u8> = (0..=255).collect();
    let tex = Texture::<A8>::new(&mask, 16, 16).unwrap();
    let got = record(&Sprite::new(&tex).at(Point::new(3, 4)).tint([200, 100, 0]).opacity(128));
    assert_eq!(got.len(), 255, "all but the transparent texel");
    for (i, &a) in mask.iter().enumerate().skip(1) {
        let (x, y) = (3 + (i % 16) as i32, 4 + (i / 16) as i32);
        let want_a = (a as f64 * 128.0 / 255.0).round() as u8;
        assert_eq!(got[&(x, y)], [200, 100, 0, want_a], "texel {i}");
    }
}

#[test]
fn sprites_are_band_invariant() {
    fn frame<F: TexelFormat, const H: usize>(tex: &Texture<'_, F>) -> Vec<Rgb565> {
        let mut band = Band::<Rgb565, 64, H>::new(Rgb565::BLACK);
        let mut fb = crate::framebuffer::Framebuffer::new(64, 48, Rgb565::BLACK);
        Renderer::new(48, Rgb565::new(5, 10, 20))
            .render(
                from_fn(|view| {
                    Sprite::new(tex).at(Point::new(-5, 3)).scale(3.3).rotate(0.4).blend_into(view)?;
                    Sprite::new(tex)
                        .at(Point::new(30, 10))
                        .scale(2.0)
                        .filter(Bilinear)
                        .opacity(200)
                        .blend_into(view)?;
                    Sprite::new(tex).at(Point::new(20, 30)).scale(1.5).rotate(-2.0).draw(view)??; // cut-out
                    Ok(())
                }),
                &mut band,
                &mut fb,
            )
            .unwrap();
        fb.pixels
    }
    let mut rng = Rng::new(0x5974);
    let texels: Vec<u16> = (0..12 * 9).map(|_| rng.next_u64() as u16).collect();
    let tex = Texture::<Argb4444>::new(&texels, 12, 9).unwrap();
    let full = frame::<_, 48>(&tex);
    assert!(full.iter().filter(|&&c| c != Rgb565::new(5, 10, 20)).count() > 500);
    assert_eq!(frame::<_, 1>(&tex), full);
    assert_eq!(frame::<_, 3>(&tex), full);
    assert_eq!(frame::<_, 16>(&tex), full);
    // The same for 8-bit alpha.
    let texels: Vec<[u8; 3]> = (0..12 * 9).map(|_| Rgb565A8::random(rng.next_u64())).collect();
    let tex = Texture::<Rgb565A8>::new(&texels, 12, 9).unwrap();
    let full = frame::<_, 48>(&tex);
    assert!(full.iter().filter(|&&c| c != Rgb565::new(5, 10, 20)).count() > 500);
    assert_eq!(frame::<_, 1>(&tex), full);
    assert_eq!(frame::<_, 3>(&tex), full);
    assert_eq!(frame::<_, 16>(&tex), full);
}

#[test]
fn drawable_is_the_cut_out_of_the_blend() {
    cut_out_of_the_blend::<Argb4444>(0x5975);
    cut_out_of_the_blend::<Rgb565A8>(0x5a75);
}

fn cut_out_of_the_blend<F: AlphaFormat>(seed: u64) {
    let mut rng = Rng::new(seed);
    for _ in 0..50 {
        let case = Case::<F>::random(&mut rng, false);
        let tex = case.texture();
        let sprite = Sprite::new(&tex).at(case.at).scale(case.scale).rotate(case.angle);
        let blended = record(&sprite);
        let mut fb = crate::framebuffer::Framebuffer::new(200, 200, Rgb888::BLACK);
        sprite.draw(&mut fb).unwrap().unwrap();
        for y in 0..200 {
            for x in 0..200 {
                let i = (y * 200 + x) as usize;
                match blended.get(&(x, y)) {
                    Some(&[r, g, b, a]) if a >= 128 => {
                        assert_eq!((fb.writes[i], fb.pixels[i]), (1, Rgb888::new(r, g, b)), "({x}, {y})")
                    }
                    _ => assert_eq!(fb.writes[i], 0, "({x}, {y})"),
                }
            }
        }
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let texels = [0xFFFFu16; 6];
    assert_eq!(Texture::<Argb4444>::new(&texels[..5], 3, 2).err(), Some(Error::BufferTooSmall));
    assert_eq!(Texture::<A8>::new(&[0; 5], 3, 2).err(), Some(Error::BufferTooSmall));
    assert_eq!(
        Texture::<A8>::new(&[0; 0], 0, 2).err(),
        Some(Error::InvalidParameter(microraster::Param::TextureSize))
    );
    let tex = Texture::<Argb4444>::new(&texels, 3, 2).unwrap();
    let cases: [(f32, f32, Error); 7] = [
        (f32::NAN, 0.0, Error::NonFiniteCoordinate),
        (f32::INFINITY, 0.0, Error::NonFiniteCoordinate),
        (1.0, f32::NAN, Error::NonFiniteCoordinate),
        (1.0, f32::NEG_INFINITY, Error::NonFiniteCoordinate),
        (0.0, 0.0, Error::InvalidParameter(microraster::Param::SpriteScale)),
        (-2.0, 0.0, Error::InvalidParameter(microraster::Param::SpriteScale)),
        (1e9, 0.0, Error::InvalidParameter(microraster::Param::SpriteScale)),
    ];
    for (scale, angle, e) in cases {
        let s = Sprite::new(&tex).at(Point::new(1, 1)).scale(scale).rotate(angle);
        let mut r = Recorder { clip: ClipRect::new(0, 0, 50, 50), seen: HashMap::new() };
        assert_eq!(s.blend_into(&mut r), Err(e), "scale {scale}, angle {angle}");
        assert!(r.seen.is_empty());
        let mut fb = crate::framebuffer::Framebuffer::new(50, 50, Rgb888::BLACK);
        assert_eq!(s.draw(&mut fb), Ok(Err(e)));
        assert!(fb.writes.iter().all(|&n| n == 0));
    }
    // Far off-frame, huge and tiny but valid: clipped, no panic.
    for (at, scale) in [(Point::new(i32::MIN, i32::MAX), 256.0), (Point::new(-1000, 10), 1.0 / 256.0)] {
        let mut r = Recorder { clip: ClipRect::new(0, 0, 50, 50), seen: HashMap::new() };
        Sprite::new(&tex).at(at).scale(scale).rotate(1e7).filter(Bilinear).blend_into(&mut r).unwrap();
        assert!(r.seen.is_empty());
    }
}

#[test]
fn discarding_shader_skips_and_blends_by_texel_alpha() {
    use microraster::SubPoint;
    use microraster::blend::{Mix, Replace};
    use microraster::depth::{DepthBand, DepthState, NoDepth};
    use microraster::fragment::{FragTriangle, Output, TexturedAlpha, draw_fragment_triangle};
    use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
    use microraster::texture::{Sampler, UV_ONE, from_rgb8};

    let mut rng = Rng::new(0x5976);
    let texels: Vec<u16> = (0..8 * 8).map(|_| rng.next_u64() as u16).collect();
    let tex = Texture::<Argb4444>::new(&texels, 8, 8).unwrap();
    let bg = Rgb888::new(20, 40, 60);
    let v = |x, y| ScreenVertex {
        pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
        inv_w: 1 << 30,
        ..Default::default()
    };
    let tri = FragTriangle {
        tri: ScreenTriangle { v: [v(0, 0), v(32, 0), v(0, 32)], flat: false },
        varyings: [[0, 0, 255, 200, 100], [UV_ONE, 0, 255, 200, 100], [0, UV_ONE, 255, 200, 100]],
    };
    for (cutoff, draw_alpha) in [(1u8, 255u8), (128, 255), (100, 90)] {
        let shader = TexturedAlpha { texture: &tex, sampler: Sampler::BILINEAR_CLAMP, cutoff };
        let mut band = Band::<Rgb888, 32, 32>::new(bg);
        let mut depth = DepthBand::<NoDepth, 32, 32>::new();
        let out = Output { depth: DepthState::DISABLED, blend: Mix, alpha: draw_alpha };
        let mut view = band.view(0, 32, bg);
        draw_fragment_triangle(&tri, &mut view, &mut depth.rows_mut(32), &shader, out, Affine).unwrap();
        // Reference: the same coverage and varyings, discard and alpha done by hand.
        let mut want = Band::<Rgb888, 32, 32>::new(bg);
        let mut view = want.view(0, 32, bg);
        let by_hand = |f: &microraster::fragment::Fragment<5>| {
            let [r, g, b, a] = tex.sample_rgba(Sampler::BILINEAR_CLAMP, [f.varyings[0], f.varyings[1]]);
            let c = from_rgb8::<Rgb888>(microraster::texture::modulate([r, g, b], [255, 200, 100]));
            let alpha = (a as f64 * draw_alpha as f64 / 255.0).round() as u8;
            if a < cutoff { bg } else { Mix.blend(c, bg, alpha) }
        };
        let replace = Output { depth: DepthState::DISABLED, blend: Replace, alpha: 255 };
        draw_fragment_triangle(&tri, &mut view, &mut depth.rows_mut(32), &by_hand, replace, Affine).unwrap();
        assert_eq!(band.rows(), want.rows(), "cutoff {cutoff}, alpha {draw_alpha}");
        let kept = band.rows().iter().flatten().filter(|&&c| c == bg).count();
        assert!(kept > 0 && kept < 32 * 32, "some pixels discarded, some drawn");
    }
}

/// Found by the `sprite` fuzz target: a small sprite far off-frame (its
/// centre ~2^31 px away at scale 1/256) put texture coordinates beyond the
/// 2^-32 fixed-point map and overflowed in `floor_i64` (a panic in debug).
/// It covers no pixel: `Ok` and nothing drawn, by either path.
#[test]
fn far_off_frame_tiny_sprite_draws_nothing() {
    let tex = Texture::<A8>::new(&[255; 2], 1, 2).unwrap();
    for at in [Point::new(i32::MIN, 0), Point::new(0, i32::MAX), Point::new(i32::MAX, i32::MIN)] {
        let s = Sprite::new(&tex).at(at).scale(1.0 / 256.0).rotate(0.3);
        let mut r = Recorder { clip: ClipRect::new(0, 0, 50, 50), seen: HashMap::new() };
        s.blend_into(&mut r).unwrap();
        assert!(r.seen.is_empty());
        let mut fb = crate::framebuffer::Framebuffer::new(50, 50, Rgb888::BLACK);
        assert_eq!(s.draw(&mut fb), Ok(Ok(())));
        assert!(fb.writes.iter().all(|&n| n == 0));
    }
}
