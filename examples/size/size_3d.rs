//! The same program with the standard 3D scene: vertex stage, clipping,
//! 16-bit depth, perspective-correct colour. Built by `scripts/code-size.sh`.

use core::hint::black_box;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::Triangles3d;
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

#[path = "sink.rs"]
mod sink;
use sink::Sink;

fn main() {
    let scene = Scene3d::new();
    let Ok(pipeline) = Scene3d::pipeline::<f32, 4>(320, 240) else { return };
    let mut bins = Box::new(heapless::Vec::<_, BINS>::new());
    let _ = scene.draw::<f32, Rgb565, 4, BINS>(&pipeline, black_box(0.6), &mut bins);
    let mut band = Band::<Rgb565, 320, 16>::new(Rgb565::BLACK);
    let mut depth = DepthBand::<Depth16, 320, 16>::new();
    let mut sink = Sink(0);
    let _ = Renderer::new(240, Rgb565::BLACK).render(
        Triangles3d::new(black_box(&bins), &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
        &mut band,
        &mut sink,
    );
    println!("{:08x}", black_box(sink.0));
}
