//! Recipe: a lit, spinning mesh (the 5,120-triangle knot as `obj2rs`
//! converts it by default) with a HUD, a translucent panel and text drawn
//! into each band after the mesh, so every pixel is sent once; the README's
//! first recipe.
//!
//! ```text
//! cargo run --example mesh_hud [-- out.png]   # default docs/img/mesh_hud.png
//! ```
//!
//! The README shows the code between `recipe:begin` and `recipe:end`
//! verbatim (`tests/readme.rs` checks it, and that [`picture`] still draws
//! the committed `docs/img/mesh_hud.png`); what lies outside only turns the
//! third frame into a PNG on the host.

use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
use embedded_graphics::image::GetPixel;
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};

/// `KNOT5K`, as `obj2rs knot5k.obj --name KNOT5K --out knot5k.rs` writes it.
#[path = "../common/knot5k_obj2rs.rs"]
#[allow(dead_code)]
mod knot5k;
use knot5k::KNOT5K;

// recipe:begin
use core::fmt::Write;
use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, text::Text};
use microraster::RenderError;
use microraster::shape::{Rect, Shape, ShapeStyle};
use microraster::view3d::{Camera, Object, View240x240};

/// Frame `n` of the knot, turning, with a HUD, into any 240 × 240 display.
fn draw_frame<D: DrawTarget<Color = Rgb565>>(
    view: &mut View240x240,
    n: u32,
    display: &mut D,
) -> Result<(), RenderError<D::Error>> {
    let camera = Camera::look_at([0.0, 1.5, 6.0], [0.0, 0.0, 0.0]);
    let knot = Object::new(&KNOT5K, Rgb565::new(31, 36, 6)).rotate_y(0.3 * n as f32);
    let panel = Rect::new(8.0, 196.0, 224.0, 36.0)?;
    let glass = panel.styled(ShapeStyle::fill(Rgb565::new(0, 8, 12)).with_opacity(160))?;
    let text = MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE);
    let mut line = microraster::heapless::String::<32>::new();
    let _ = write!(line, "frame {n}: 5,120 triangles");
    view.draw_with(&camera, &[knot], display, |hud| {
        glass.draw_on(hud); // blends over the knot
        hud.draw_visible(&Text::new("microraster", Point::new(16, 210), text))?;
        hud.draw_visible(&Text::new(&line, Point::new(16, 224), text))?;
        Ok(())
    })
}

// In firmware: a `static` view (its bands: 240 × 16 × 4 bytes) and the loop.
// let mut view = View240x240::new(Rgb565::new(2, 4, 8));
// for n in 0.. { draw_frame(&mut view, n, &mut display)?; }
// recipe:end

type Fb = Framebuffer<Rgb565, RawU16, LittleEndian, 240, 240, { buffer_size::<Rgb565>(240, 240) }>;

/// The third frame (the knot turned by 0.6 rad) as 8-bit RGB, row by row
/// (what the PNG holds).
pub fn picture() -> Vec<u8> {
    let mut fb = Box::new(Fb::new());
    let mut view = Box::new(View240x240::new(Rgb565::new(2, 4, 8)));
    for n in 0..3 {
        draw_frame(&mut view, n, &mut *fb).expect("a framebuffer never fails");
    }
    let mut rgb = Vec::with_capacity(240 * 240 * 3);
    for y in 0..240 {
        for x in 0..240 {
            let c = fb.pixel(Point::new(x, y)).unwrap_or(Rgb565::BLACK);
            rgb.extend([c.r() << 3 | c.r() >> 2, c.g() << 2 | c.g() >> 4, c.b() << 3 | c.b() >> 2]);
        }
    }
    rgb
}

#[allow(dead_code)] // the test includes this file for `picture` alone
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).unwrap_or_else(|| "docs/img/mesh_hud.png".into());
    let file = std::io::BufWriter::new(std::fs::File::create(&path)?);
    let mut png = png::Encoder::new(file, 240, 240);
    png.set_color(png::ColorType::Rgb);
    png.set_depth(png::BitDepth::Eight);
    png.write_header()?.write_image_data(&picture())?;
    println!("wrote {path}");
    Ok(())
}
