//! Recipe: a car dashboard with the 2D kit, 320 × 240 Rgb565 in 16-row bands
//! (a gradient ring, anti-aliased ticks and needle, a translucent panel, an
//! icon with alpha, text), the README's second recipe.
//!
//! ```text
//! cargo run --example dashboard [-- out.png]   # default docs/img/dashboard.png
//! ```
//!
//! The README shows the code between `recipe:begin` and `recipe:end`
//! verbatim (`tests/readme.rs` checks it, and that [`picture`] still draws
//! the committed `docs/img/dashboard.png`); what lies outside only turns the
//! frame into a PNG on the host.

// recipe:begin
use core::f32::consts::PI;
use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10, ascii::FONT_10X20};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Alignment, Text};
use microraster::{heapless, math::Scalar, prelude::*};

const BG: Rgb565 = Rgb565::new(3, 8, 11);
const C: (f32, f32) = (124.0, 124.0); // the gauge's centre
/// A 6 × 6 fuel-drop icon's alpha (255 opaque), tinted when drawn.
static DROP: Texture<'static, A8> = Texture::from_rows(&[
    [0, 0, 128, 128, 0, 0],
    [0, 128, 255, 255, 128, 0],
    [0, 255, 255, 255, 255, 0],
    [128, 255, 255, 255, 255, 128],
    [128, 255, 255, 255, 255, 128],
    [0, 128, 255, 255, 128, 0],
]);

/// The gauge's angle for `kmh`: 0 at the lower left, 240 at the lower right.
fn angle(kmh: f32) -> f32 {
    0.75 * PI + 1.5 * PI * kmh / 240.0
}

/// The point `r` px from the centre at `kmh`'s angle (the library's sine:
/// the same bits on the host and on Cortex-M).
fn polar(r: f32, kmh: f32) -> (f32, f32) {
    let (s, c) = Scalar::sin_cos(angle(kmh));
    (C.0 + r * c, C.1 + r * s)
}

/// One frame at `kmh`, band by band into `display` (any e-g `DrawTarget`).
pub fn dashboard<D>(display: &mut D, kmh: f32) -> Result<(), RenderError<D::Error>>
where
    D: DrawTarget<Color = Rgb565>,
{
    let mut band = Band::<Rgb565, 320, 16>::new(BG); // 10 KB, not a 150 KB framebuffer
    let (small, big) =
        (MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE), MonoTextStyle::new(&FONT_10X20, Rgb565::WHITE));
    let frame = from_fn(|view| {
        let sky = LinearGradient::new((0.0, 0.0), (0.0, 240.0), [BG, Rgb565::BLACK])?;
        Rect::new(0.0, 0.0, 320.0, 240.0)?.styled(ShapeStyle::fill(sky))?.draw_on(view);
        let zones = LinearGradient::new((40.0, 0.0), (210.0, 0.0), [Rgb565::GREEN, Rgb565::RED])?;
        let ring = ShapeStyle::stroke(zones, 10.0).antialiased();
        Arc::new(C, 100.0, angle(0.0), 1.5 * PI)?.styled(ring)?.draw_on(view);
        let pen = ShapeStyle::stroke(Rgb565::WHITE, 2.0).antialiased();
        for k in 0..=12 {
            let at = 20.0 * k as f32;
            Polyline::new(&[polar(80.0, at), polar(92.0, at)])?.styled(pen)?.draw_on(view);
        }
        let needle =
            [polar(90.0, kmh), polar(6.0, kmh + 80.0), polar(16.0, kmh + 160.0), polar(6.0, kmh - 80.0)];
        Polygon::new(&needle)?.styled(ShapeStyle::fill(Rgb565::YELLOW).antialiased())?.draw_on(view);
        let glass = ShapeStyle::fill(Rgb565::CYAN).with_stroke(Rgb565::WHITE, 1.5).with_opacity(96);
        RoundedRect::new(Rect::new(200.0, 40.0, 108.0, 160.0)?, 10.0)?
            .styled(glass.antialiased())?
            .draw_on(view);
        let drop = Sprite::new(&DROP).at(Point::new(214, 56)).scale(3.0).filter(Bilinear);
        drop.tint([255, 176, 0]).blend_into(view)?;
        view.draw_visible(&Text::new("FUEL 62%", Point::new(238, 68), small))?;
        let mut digits = heapless::String::<8>::new();
        core::fmt::write(&mut digits, format_args!("{kmh:.0}")).ok();
        view.draw_visible(&Text::with_alignment(&digits, Point::new(124, 178), big, Alignment::Center))?;
        Ok(())
    });
    Renderer::new(240, BG).render(frame, &mut band, display)
}
// recipe:end

use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
use embedded_graphics::image::GetPixel;
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};

type Fb = Framebuffer<Rgb565, RawU16, LittleEndian, 320, 240, { buffer_size::<Rgb565>(320, 240) }>;

/// The frame at 88 km/h as 8-bit RGB, row by row (what the PNG holds).
pub fn picture() -> Vec<u8> {
    let mut fb = Box::new(Fb::new());
    dashboard(&mut *fb, 88.0).expect("a framebuffer never fails");
    let mut rgb = Vec::with_capacity(320 * 240 * 3);
    for y in 0..240 {
        for x in 0..320 {
            let c = fb.pixel(Point::new(x, y)).unwrap_or(BG);
            rgb.extend([c.r() << 3 | c.r() >> 2, c.g() << 2 | c.g() >> 4, c.b() << 3 | c.b() >> 2]);
        }
    }
    rgb
}

#[allow(dead_code)] // the test includes this file for `picture` alone
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).unwrap_or_else(|| "docs/img/dashboard.png".into());
    let file = std::io::BufWriter::new(std::fs::File::create(&path)?);
    let mut png = png::Encoder::new(file, 320, 240);
    png.set_color(png::ColorType::Rgb);
    png.set_depth(png::BitDepth::Eight);
    png.write_header()?.write_image_data(&picture())?;
    println!("wrote {path}");
    Ok(())
}
