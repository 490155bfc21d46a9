//! The README's first recipe: a lit, spinning mesh (the 5,120-triangle
//! knot as `obj2rs` converts it by default) with a HUD, a translucent panel
//! and text drawn into each band after the mesh, so every pixel is sent
//! once. The code between `recipe:begin` and `recipe:end` is the README's
//! block, word for word; the rest runs it on the host and writes the third
//! frame to `docs/img/recipe_mesh_hud.png` (or the path given).
//!
//! ```text
//! cargo run --release --example mesh_hud [-- out.png]
//! ```

use std::path::PathBuf;

use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
use embedded_graphics::image::GetPixel;
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};

/// `KNOT5K`, as `obj2rs knot5k.obj KNOT5K > knot5k.rs` writes it.
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

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path =
        std::env::args().nth(1).map_or_else(|| PathBuf::from("docs/img/recipe_mesh_hud.png"), PathBuf::from);
    let mut display =
        Framebuffer::<Rgb565, RawU16, LittleEndian, 240, 240, { buffer_size::<Rgb565>(240, 240) }>::new();
    let mut view = Box::new(View240x240::new(Rgb565::new(2, 4, 8)));
    for n in 0..3 {
        draw_frame(&mut view, n, &mut display)?;
    }
    // The framebuffer as an 8-bit RGB PNG.
    let mut data = Vec::with_capacity(240 * 240 * 3);
    for y in 0..240 {
        for x in 0..240 {
            let c = display.pixel(Point::new(x, y)).unwrap_or(Rgb565::BLACK);
            let (r, g, b) = (u32::from(c.r()), u32::from(c.g()), u32::from(c.b()));
            data.extend([r * 255 / 31, g * 255 / 63, b * 255 / 31].map(|v| v as u8));
        }
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    let mut enc = png::Encoder::new(std::io::BufWriter::new(std::fs::File::create(&path)?), 240, 240);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header()?;
    writer.write_image_data(&data)?;
    writer.finish()?;
    println!("wrote {}", path.display());
    Ok(())
}
