//! Host preview: a lit, depth-tested microraster scene drawn by the one-call
//! front ([`View3d`](microraster::view3d::View3d)) band by band into
//! `embedded-graphics-simulator`'s `SimulatorDisplay`, with a HUD (e-g text
//! and a translucent panel) drawn into each band after the meshes
//! ([`View3d::draw_with`](microraster::view3d::View3d::draw_with): every
//! pixel sent once, as on a panel without a framebuffer), and written as a PNG through the simulator's output image
//! (`to_rgb_output_image(..).save_png(..)`). The simulator is a host-only
//! dev-dependency with `default-features = false`: no SDL window, so no
//! system library is needed.
//!
//! ```text
//! cargo run --example simulator                  # writes out/simulator.png
//! cargo run --example simulator -- preview.png   # or the path given
//! ```
//!
//! The display is 320 × 240 Rgb565 (an ST7789 in landscape); the PNG is
//! scaled 2× with the simulator's pixel spacing left at 0.

use std::error::Error;
use std::path::PathBuf;

use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::text::Text;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use microraster::light::Lighting;
use microraster::math::Vec3;
use microraster::mesh::{ValidMesh, icosphere, torus, torus_triangle_count, torus_vertex_count};
use microraster::shape::{Rect, RoundedRect, Shape, ShapeStyle};
use microraster::view3d::{Camera, Object, View320x240};

const BG: Rgb565 = Rgb565::new(2, 6, 8);
const TORUS: (usize, usize) = (32, 12);

fn main() -> Result<(), Box<dyn Error>> {
    let path = std::env::args().nth(1).map_or_else(|| PathBuf::from("out/simulator.png"), PathBuf::from);

    // Meshes: generated into stack arrays here; a firmware keeps them as statics.
    let (mut sp, mut sn, mut si) = ([[0.0; 3]; 162], [[0.0; 3]; 162], [[0; 3]; 320]);
    let sphere = ValidMesh::new(icosphere(2, &mut sp, &mut sn, &mut si)?)?;
    let nv = torus_vertex_count(TORUS.0, TORUS.1);
    let (mut tp, mut tn) = (vec![[0.0; 3]; nv], vec![[0.0; 3]; nv]);
    let mut ti = vec![[0; 3]; torus_triangle_count(TORUS.0, TORUS.1)];
    let ring = ValidMesh::new(torus(TORUS.0, TORUS.1, 1.0, 0.35, &mut tp, &mut tn, &mut ti)?)?;

    // The view (320 × 240 in 16-row bands: the RAM a firmware build would
    // spend), its light, the camera and the two objects.
    let mut view = View320x240::new(BG);
    view.set_lighting(Some(Lighting::try_new(0.25, Vec3::new(-0.5, 0.7, 1.0), 0.75)?));
    let camera = Camera::look_at([0.0, 1.2, 4.5], [0.0; 3]).perspective(0.9, 1.0, 20.0);
    let objects = [
        Object::new(&sphere, Rgb565::new(31, 36, 6)).translate([-1.1, 0.0, 0.0]),
        Object::new(&ring, Rgb565::new(8, 40, 31)).rotate_x(0.35).translate([1.1, 0.0, 0.0]),
    ];

    // The HUD: a half-transparent panel over the meshes, and a label on it.
    let panel = RoundedRect::new(Rect::new(2.0, 2.0, 216.0, 18.0)?, 4.0)?
        .styled(ShapeStyle::fill(Rgb565::new(0, 0, 8)).with_opacity(160))?;
    let label = Text::new(
        "microraster: View3d, 16-row bands",
        Point::new(8, 14),
        MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE),
    );

    // One call: every band, meshes then HUD, into the simulator's display
    // (any e-g `DrawTarget`).
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(320, 240));
    view.draw_with(&camera, &objects, &mut display, |hud| {
        panel.draw_on(hud);
        hud.draw_visible(&label)?;
        Ok(())
    })?;

    // The simulator's own PNG output (2x, no gaps between pixels).
    let settings = OutputSettingsBuilder::new().scale(2).pixel_spacing(0).build();
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    display.to_rgb_output_image(&settings).save_png(&path)?;
    println!("{}: 320 × 240 display, {} objects", path.display(), objects.len());
    Ok(())
}
