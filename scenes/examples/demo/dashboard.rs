//! The dashboard (`examples/common/dashboard.rs`): microraster's version in
//! 16-row bands to `dashboard.png`, the plain embedded-graphics one into a
//! framebuffer to `dashboard_eg.png`.

use super::{Canvas, Result, save};
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::render::from_fn;
use microraster::{Band, Renderer};
use std::path::Path;

#[allow(dead_code)] // each user takes what it needs
#[path = "../../../examples/common/dashboard.rs"]
pub mod scene;

pub fn run(out: &Path) -> Result<()> {
    let mut canvas = Canvas::new(scene::W as u32, scene::H);
    let mut band = Band::<Rgb565, { scene::W }, 16>::new(scene::NIGHT);
    let r = Renderer::new(scene::H, scene::NIGHT);
    r.render(from_fn(scene::dashboard), &mut band, &mut canvas.color_converted())
        .map_err(|e| e.to_string())?;
    save(&canvas, &out.join("dashboard.png"))?;
    let mut plain = Canvas::new(scene::W as u32, scene::H);
    scene::dashboard_eg(&mut plain.color_converted())?;
    save(&plain, &out.join("dashboard_eg.png"))
}
