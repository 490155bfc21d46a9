//! A plain `Rgb565` framebuffer of the report's frame size, as a user with
//! the RAM for one would write it: `fill_solid` and `fill_contiguous` copy
//! contiguous runs (the host report's `SliceFb`, without `std`).

use core::convert::Infallible;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;

use crate::configs::{H, W};

/// `W × H` pixels, row by row.
pub struct FrameBuffer {
    px: [Rgb565; W * H],
}

impl FrameBuffer {
    /// A black frame (all bits zero: a `static` of it lives in `.bss`).
    pub const fn new() -> Self {
        FrameBuffer { px: [Rgb565::BLACK; W * H] }
    }

    /// The pixels, row by row.
    pub fn pixels(&self) -> &[Rgb565] {
        &self.px
    }

    /// Sets every pixel to `color`.
    pub fn wipe(&mut self, color: Rgb565) {
        self.px.fill(color);
    }

    fn screen() -> Rectangle {
        Rectangle::new(Point::zero(), Size::new(W as u32, H as u32))
    }
}

impl OriginDimensions for FrameBuffer {
    fn size(&self) -> Size {
        Size::new(W as u32, H as u32)
    }
}

impl DrawTarget for FrameBuffer {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if (0..W as i32).contains(&p.x) && (0..H as i32).contains(&p.y) {
                self.px[p.y as usize * W + p.x as usize] = c;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        if area.intersection(&Self::screen()) != *area || area.is_zero_sized() {
            return self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)));
        }
        let (x0, w) = (area.top_left.x as usize, area.size.width as usize);
        if w == W || area.size.height == 1 {
            // Whole rows (or a single row): one contiguous run, one pass.
            let start = area.top_left.y as usize * W + x0;
            for (d, c) in self.px[start..][..w * area.size.height as usize].iter_mut().zip(colors) {
                *d = c;
            }
            return Ok(());
        }
        let mut it = colors.into_iter();
        for y in area.rows() {
            let row = &mut self.px[y as usize * W + x0..][..w];
            for (d, c) in row.iter_mut().zip(&mut it) {
                *d = c;
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Infallible> {
        let area = area.intersection(&Self::screen());
        let (x0, w) = (area.top_left.x as usize, area.size.width as usize);
        for y in area.rows() {
            self.px[y as usize * W + x0..][..w].fill(color);
        }
        Ok(())
    }
}
