//! A host framebuffer `DrawTarget` that also records how it was drawn to.

use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;

/// Full-frame pixel store; counts writes per pixel and records every
/// `fill_contiguous` rectangle.
pub struct Framebuffer<C> {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<C>,
    pub writes: Vec<u32>,
    pub contiguous: Vec<Rectangle>,
}

impl<C: PixelColor> Framebuffer<C> {
    pub fn new(width: u32, height: u32, fill: C) -> Self {
        let n = (width * height) as usize;
        Framebuffer { width, height, pixels: vec![fill; n], writes: vec![0; n], contiguous: Vec::new() }
    }

    fn put(&mut self, p: Point, c: C) {
        assert!(
            p.x >= 0 && p.y >= 0 && (p.x as u32) < self.width && (p.y as u32) < self.height,
            "pixel {p:?} outside the {}x{} frame",
            self.width,
            self.height
        );
        let i = (p.y as u32 * self.width + p.x as u32) as usize;
        self.pixels[i] = c;
        self.writes[i] += 1;
    }
}

impl<C: PixelColor> OriginDimensions for Framebuffer<C> {
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }
}

impl<C: PixelColor> DrawTarget for Framebuffer<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            self.put(p, c);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.contiguous.push(*area);
        let mut n = 0u32;
        for (p, c) in area.points().zip(colors) {
            self.put(p, c);
            n += 1;
        }
        assert_eq!(n, area.size.width * area.size.height, "fill_contiguous got too few colours");
        Ok(())
    }
}
