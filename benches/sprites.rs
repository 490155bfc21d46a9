//! Sprites against embedded-graphics' `Image` and tiny-skia's `draw_pixmap`,
//! in one run:
//!
//! ```text
//! cargo bench --bench sprites
//! ```
//!
//! Each benchmark draws the same 24 instances of a 32 × 32 alpha-masked ring
//! (an `A8` texture, tinted) over a 320 × 240 `Rgb565` frame:
//! - `mr_nearest` — microraster, unscaled, nearest texel, blended into
//!   16-row bands; `eg` — e-g's `Image` of the same ring as opaque
//!   `Rgb565` pixels (e-g has no alpha, scaling or rotation): the closest
//!   thing e-g draws;
//! - `mr_bilinear` — microraster scaled 1.5×, rotated 0.3 rad, bilinear,
//!   blended into 16-row bands; `skia` — tiny-skia's `draw_pixmap` of the
//!   same ring (premultiplied RGBA) with the same transform and bilinear
//!   filtering into its RGBA pixmap.
//!
//! After criterion's output the ratios from this run's medians are printed
//! (> 1: microraster is faster).

use criterion::Criterion;
use embedded_graphics::image::{Image, ImageRaw};
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::pixelcolor::raw::RawU16;
use microraster::render::from_fn;
use microraster::texture::{A8, Bilinear, Sprite, Texture};
use microraster::{Band, Renderer};
use std::hint::black_box;
use std::time::Duration;

#[path = "common/mod.rs"]
pub mod common;
use common::{BG, Frame, H, SliceFb, W};
#[path = "common/criterion_median.rs"]
mod criterion_median;
use criterion_median::median;

const SIDE: usize = 32;
const TINT: [u8; 3] = [255, 160, 64];
const SCALE: f32 = 1.5;
const ANGLE: f32 = 0.3;

/// A ring's alpha: 255 between radii 8 and 12 texels, fading to 0 within
/// one texel outside them.
fn ring() -> Vec<u8> {
    let c = SIDE as f32 / 2.0;
    (0..SIDE * SIDE)
        .map(|i| {
            let (x, y) = ((i % SIDE) as f32 + 0.5 - c, (i / SIDE) as f32 + 0.5 - c);
            let d = (x * x + y * y).sqrt();
            let outside = (8.0 - d).max(d - 12.0).clamp(0.0, 1.0);
            (255.0 * (1.0 - outside)) as u8
        })
        .collect()
}

/// Instance `k`'s top-left corner, spread over the frame.
fn place(k: usize) -> Point {
    Point::new(((k * 53) % (W - SIDE)) as i32, ((k * 37) % (H - SIDE)) as i32)
}

fn main() {
    let mut c = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(15)
        .without_plots()
        .configure_from_args();
    let alpha = ring();
    let tex: Texture<'_, A8> = Texture::new(&alpha, SIDE as u32, SIDE as u32).unwrap();
    let mut fb = SliceFb::default();
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let renderer = Renderer::new(H as u32, BG);

    // e-g: the ring as opaque Rgb565 pixels (tint where alpha >= 128).
    let tint = microraster::texture::from_rgb8::<Rgb565>(TINT);
    let raw: Vec<u8> = alpha
        .iter()
        .flat_map(|&a| RawU16::from(if a >= 128 { tint } else { BG }).into_inner().to_be_bytes())
        .collect();
    let eg_image = ImageRaw::<Rgb565>::new(&raw, SIDE as u32);

    // tiny-skia: the ring as premultiplied RGBA.
    let mut src = tiny_skia::Pixmap::new(SIDE as u32, SIDE as u32).unwrap();
    for (px, &a) in src.pixels_mut().iter_mut().zip(&alpha) {
        let p = |v: u8| (v as u16 * a as u16 / 255) as u8;
        *px = tiny_skia::PremultipliedColorU8::from_rgba(p(TINT[0]), p(TINT[1]), p(TINT[2]), a).unwrap();
    }
    let mut pixmap = tiny_skia::Pixmap::new(W as u32, H as u32).unwrap();
    let half = SIDE as f32 / 2.0;

    let mut g = c.benchmark_group("sprite");
    g.bench_function("mr_nearest", |b| {
        b.iter(|| {
            renderer
                .render(
                    from_fn(|v| {
                        (0..24).try_for_each(|k| Sprite::new(&tex).at(place(k)).tint(TINT).blend_into(v))
                    }),
                    &mut band,
                    &mut fb,
                )
                .unwrap();
            black_box(&fb.px);
        })
    });
    g.bench_function("eg", |b| {
        b.iter(|| {
            fb.wipe();
            (0..24).for_each(|k| Image::new(&eg_image, place(k)).draw(&mut fb).unwrap());
            black_box(&fb.px);
        })
    });
    g.bench_function("mr_bilinear", |b| {
        b.iter(|| {
            renderer
                .render(
                    from_fn(|v| {
                        (0..24).try_for_each(|k| {
                            let s = Sprite::new(&tex).at(place(k)).scale(SCALE).rotate(ANGLE);
                            s.filter(Bilinear).tint(TINT).blend_into(v)
                        })
                    }),
                    &mut band,
                    &mut fb,
                )
                .unwrap();
            black_box(&fb.px);
        })
    });
    let paint = tiny_skia::PixmapPaint { quality: tiny_skia::FilterQuality::Bilinear, ..Default::default() };
    g.bench_function("skia", |b| {
        b.iter(|| {
            pixmap.fill(tiny_skia::Color::BLACK);
            for k in 0..24 {
                // Scaled about the box's top-left, rotated about its centre, as the sprite.
                let p = place(k);
                let (cx, cy) = (p.x as f32 + half * SCALE, p.y as f32 + half * SCALE);
                let t = tiny_skia::Transform::from_translate(-half, -half)
                    .post_scale(SCALE, SCALE)
                    .post_rotate(ANGLE.to_degrees())
                    .post_translate(cx, cy);
                pixmap.draw_pixmap(0, 0, src.as_ref(), &paint, t, None);
            }
            black_box(pixmap.data());
        })
    });
    g.finish();
    c.final_summary();

    println!("\nRatios from this run (criterion medians; > 1: microraster is faster)");
    let m = |id: &str| median("sprite", id);
    for (peer, ours, what) in [
        ("eg", "mr_nearest", "e-g Image (opaque, unscaled) / microraster nearest, blended, bands"),
        ("skia", "mr_bilinear", "tiny-skia draw_pixmap / microraster bilinear, scaled + rotated, bands"),
    ] {
        match m(peer).zip(m(ours)) {
            Some((p, o)) => println!("{what}: {:.2} ({:.1} µs vs {:.1} µs)", p / o, p / 1e3, o / 1e3),
            None => println!("{what}: not measured (criterion filter)"),
        }
    }
}
