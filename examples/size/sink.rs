//! A target that only checksums what it receives, shared by the two size
//! programs so they differ in nothing but the scene.

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;

/// A target that only checksums what it receives.
pub struct Sink(pub u32);
impl OriginDimensions for Sink {
    fn size(&self) -> Size {
        Size::new(320, 240)
    }
}
impl DrawTarget for Sink {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, it: I) -> Result<(), Self::Error> {
        it.into_iter().for_each(|Pixel(_, c)| self.0 = self.0.rotate_left(5) ^ c.into_storage() as u32);
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        _: &Rectangle,
        c: I,
    ) -> Result<(), Self::Error> {
        c.into_iter().for_each(|c| self.0 = self.0.rotate_left(5) ^ c.into_storage() as u32);
        Ok(())
    }
}
