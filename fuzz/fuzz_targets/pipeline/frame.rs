//! Rendering the bins into a checking 64-wide frame, for every depth format
//! and both interpolations: the frame fails on a pixel sent twice or outside it.

use super::FW;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthBand, DepthFormat, DepthState, NoDepth};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Renderer};

pub(super) fn render_any<const S: u32, const H: usize>(
    bins: &[ScreenTriangle<S>],
    fh: usize,
    bg: Rgb565,
    state: DepthState,
    fmt: u8,
    perspective: bool,
) -> Vec<Rgb565> {
    match (fmt, perspective) {
        (0, false) => render::<NoDepth, Affine, S, H>(bins, fh, bg, state),
        (0, true) => render::<NoDepth, PerspectiveCorrect, S, H>(bins, fh, bg, state),
        (1, false) => render::<Depth8, Affine, S, H>(bins, fh, bg, state),
        (1, true) => render::<Depth8, PerspectiveCorrect, S, H>(bins, fh, bg, state),
        (2, false) => render::<Depth16, Affine, S, H>(bins, fh, bg, state),
        (2, true) => render::<Depth16, PerspectiveCorrect, S, H>(bins, fh, bg, state),
        (3, false) => render::<Depth24, Affine, S, H>(bins, fh, bg, state),
        (3, true) => render::<Depth24, PerspectiveCorrect, S, H>(bins, fh, bg, state),
        (_, false) => render::<Depth32, Affine, S, H>(bins, fh, bg, state),
        (_, true) => render::<Depth32, PerspectiveCorrect, S, H>(bins, fh, bg, state),
    }
}

fn render<F: DepthFormat, M: Interpolation, const S: u32, const H: usize>(
    bins: &[ScreenTriangle<S>],
    fh: usize,
    bg: Rgb565,
    state: DepthState,
) -> Vec<Rgb565> {
    let mut band = Box::new(Band::<Rgb565, FW, H>::new(bg));
    let mut depth = Box::new(DepthBand::<F, FW, H>::new());
    let mut fb = Frame { h: fh, px: vec![None; FW * fh] };
    Renderer::new(fh as u32, bg)
        .render(Triangles3d::new(bins, &mut depth, state, M::default()), &mut band, &mut fb)
        .unwrap();
    fb.px.into_iter().map(|p| p.expect("a frame pixel was never sent")).collect()
}

/// A 64-wide frame that fails on a pixel sent twice or outside it.
struct Frame {
    h: usize,
    px: Vec<Option<Rgb565>>,
}

impl OriginDimensions for Frame {
    fn size(&self) -> Size {
        Size::new(FW as u32, self.h as u32)
    }
}

impl DrawTarget for Frame {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            assert!(
                p.x >= 0 && p.y >= 0 && (p.x as usize) < FW && (p.y as usize) < self.h,
                "pixel {p:?} outside the frame"
            );
            let slot = &mut self.px[p.y as usize * FW + p.x as usize];
            assert!(slot.is_none(), "pixel {p:?} sent twice");
            *slot = Some(c);
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)))
    }
}
