//! The 3D program with the whole fragment stage on: the fragment scene
//! (`examples/common/fragment_scene.rs`: textures, per-pixel lighting,
//! translucency) supersampled 2 × 2. Built by `scripts/code-size.sh`, which
//! shows what these features add and that the other programs link none of it.

use core::hint::black_box;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::aa::Ssaa;
use microraster::aa::Supersampled;
use microraster::depth::{Depth16, DepthBand};
use microraster::raster3d::PerspectiveCorrect;
use microraster::{Band, Renderer};

#[path = "sink.rs"]
mod sink;
use sink::Sink;

#[allow(dead_code)]
#[path = "../common/fragment_scene.rs"]
mod fragment_scene;
use fragment_scene::{FragBins, FragmentScene, draw_passes};

type Bins = FragBins<4, 1024, 1024, 64, 2048>;

fn main() {
    let Ok(scene) = FragmentScene::<4>::new(320, 240) else { return };
    let mut bins = Box::new(Bins::new());
    if scene.draw(&mut bins).is_err() {
        return;
    }
    // On the 2 × 2 sample grid.
    let mut b2 = Box::new((*bins).clone());
    if b2.scale(2).is_err() {
        return;
    }
    let mut samples = Box::new(Band::<Rgb565, 640, 32>::new(Rgb565::BLACK));
    let mut depth = Box::new(DepthBand::<Depth16, 640, 32>::new());
    let mut out = Box::new(Band::<Rgb565, 320, 16>::new(Rgb565::BLACK));
    let mut sink = Sink(0);
    let _ = Renderer::new(240, Rgb565::BLACK).render(
        Supersampled::new(Ssaa::<2>, &mut samples, |view| {
            let (sy0, sy1) = (view.y0(), view.y1());
            let _ = draw_passes::<_, Depth16, PerspectiveCorrect, 4, 640, 32, 1024, 1024, 64, 2048>(
                black_box(&b2),
                view,
                &mut depth,
                sy0,
                sy1,
            );
            Ok(())
        }),
        &mut out,
        &mut sink,
    );
    println!("{:08x}", black_box(sink.0));
}
