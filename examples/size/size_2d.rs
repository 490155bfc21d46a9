//! A 2D-only firmware-shaped program: flat/Gouraud triangles and lines into a
//! band, no depth buffer, no clipper, no vertex stage. Built by
//! `scripts/code-size.sh` to show that a 2D scene pays for none of the 3D code.

use core::hint::black_box;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::{Band, Primitive, Renderer};
use microraster_scenes::scenes;

#[path = "sink.rs"]
mod sink;
use sink::Sink;

fn main() {
    let mut prims = heapless::Vec::<Primitive<Rgb565, 4>, { scenes::MIXED_LEN }>::new();
    let _ = scenes::mixed::<Rgb565, 4>(320, 240, &mut |p| {
        let _ = prims.push(p);
    });
    let mut band = Band::<Rgb565, 320, 16>::new(Rgb565::BLACK);
    let mut sink = Sink(0);
    let _ = Renderer::new(240, Rgb565::BLACK).render(black_box(&prims), &mut band, &mut sink);
    println!("{:08x}", black_box(sink.0));
}
