//! The frame targets the renderers draw into: embedded-graphics' own
//! `Framebuffer` ([`EgFb`]) and a slice-speed `Vec<Rgb565>` ([`SliceFb`]).

use super::{BG, H, W};
use core::convert::Infallible;
use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::primitives::Rectangle;

/// embedded-graphics' framebuffer of the same colour type.
pub type EgFb = Framebuffer<Rgb565, RawU16, LittleEndian, W, H, { buffer_size::<Rgb565>(W, H) }>;

/// A target that can be reset to the background by its fastest means.
pub trait Frame: DrawTarget<Color = Rgb565, Error = Infallible> {
    /// Sets every pixel to [`BG`].
    fn wipe(&mut self);
}

impl Frame for EgFb {
    fn wipe(&mut self) {
        self.data_mut().fill(0);
    }
}

/// A plain framebuffer with slice-speed `fill_solid` and `fill_contiguous`.
pub struct SliceFb {
    /// Pixels, row by row.
    pub px: Vec<Rgb565>,
}

impl Default for SliceFb {
    fn default() -> Self {
        SliceFb { px: vec![BG; W * H] }
    }
}

impl Frame for SliceFb {
    fn wipe(&mut self) {
        self.px.fill(BG);
    }
}

impl OriginDimensions for SliceFb {
    fn size(&self) -> Size {
        Size::new(W as u32, H as u32)
    }
}

fn inside(area: &Rectangle) -> bool {
    let b = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    area.intersection(&b) == *area && !area.is_zero_sized()
}

impl DrawTarget for SliceFb {
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
        if !inside(area) {
            return self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)));
        }
        let (x0, w) = (area.top_left.x as usize, area.size.width as usize);
        if w == W || area.size.height == 1 {
            // Whole rows (or a single row): one contiguous run of the buffer,
            // copied in one pass.
            let start = area.top_left.y as usize * W + x0;
            let run = &mut self.px[start..][..w * area.size.height as usize];
            for (d, c) in run.iter_mut().zip(colors) {
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
        let area = area.intersection(&Rectangle::new(Point::zero(), Size::new(W as u32, H as u32)));
        let (x0, w) = (area.top_left.x as usize, area.size.width as usize);
        for y in area.rows() {
            self.px[y as usize * W + x0..][..w].fill(color);
        }
        Ok(())
    }
}

/// The physical ceiling: every pixel of the frame written by a slice fill.
pub fn memset(fb: &mut SliceFb, color: Rgb565) {
    fb.px.fill(color);
}
