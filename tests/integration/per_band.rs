//! The per-band vertex stage (for parts that cannot hold a frame's bins:
//! a `Direct3d` pass whose closure bins one band's triangles and draws
//! them) draws exactly what the per-frame one draws.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::{Fx, Scalar};
use microraster::raster3d::{Affine, PerspectiveCorrect};
use microraster::render::{Direct3d, Triangles3d};
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

const W: usize = 160;
const H: u32 = 120;

fn per_frame<T: Scalar>(angle: f32) -> Vec<Rgb565> {
    let pipeline = Scene3d::pipeline::<T, 4>(W as u32, H).unwrap();
    let mut bins = heapless::Vec::<_, BINS>::new();
    Scene3d.draw::<T, Rgb565, 4, BINS>(&pipeline, angle, &mut bins).unwrap();
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::BLACK);
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(Rgb565::BLACK), DepthBand::<Depth16, W, 8>::new());
    Renderer::new(H, Rgb565::BLACK)
        .render(
            Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.pixels
}

fn per_band<T: Scalar, const N: usize>(angle: f32) -> (Vec<Rgb565>, usize) {
    let mut pipeline = Scene3d::pipeline::<T, 4>(W as u32, H).unwrap();
    let mut bins = heapless::Vec::<_, N>::new();
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::BLACK);
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(Rgb565::BLACK), DepthBand::<Depth16, W, 8>::new());
    let mut most = 0;
    let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |b3| {
        bins.clear();
        pipeline.rows = Some(b3.rows());
        Scene3d.draw::<T, Rgb565, 4, N>(&pipeline, angle, &mut bins)?;
        most = most.max(bins.len());
        b3.draw_all(&bins);
        Ok(())
    });
    Renderer::new(H, Rgb565::BLACK).render(frame, &mut band, &mut fb).unwrap();
    (fb.pixels, most)
}

#[test]
fn per_band_vertex_stage_matches_per_frame() {
    let mut frames = 0;
    for i in 0..6 {
        let angle = i as f32 * 1.1;
        let (img, most) = per_band::<f32, 256>(angle);
        assert_eq!(img, per_frame::<f32>(angle), "f32, angle {angle}");
        let (img, most_fx) = per_band::<Fx, 256>(angle);
        assert_eq!(img, per_frame::<Fx>(angle), "Fx, angle {angle}");
        println!("angle {angle:.1}: at most {most} (f32) / {most_fx} (Fx) triangles in one 8-row band");
        frames += 2;
    }
    assert_eq!(frames, 12);
}

#[test]
fn per_band_reports_full_bins_as_an_error() {
    let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, H).unwrap();
    let mut bins = heapless::Vec::<_, 4>::new();
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::BLACK);
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(Rgb565::BLACK), DepthBand::<Depth16, W, 8>::new());
    let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |b3| {
        bins.clear();
        Scene3d.draw::<f32, Rgb565, 4, 4>(&pipeline, 0.3, &mut bins)?;
        b3.draw_all(&bins);
        Ok(())
    });
    let r = Renderer::new(H, Rgb565::BLACK).render(frame, &mut band, &mut fb);
    let Err(microraster::RenderError::Input(microraster::Error::CapacityExceeded { needed, capacity: 4 })) =
        r
    else {
        panic!("{r:?}")
    };
    assert!(needed > 4, "{needed}");
    // No partial mesh left in the bins.
    assert!(bins.is_empty(), "{} triangles left", bins.len());
}
