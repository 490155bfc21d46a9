//! The display of the firmware benchmarks (`fw_bench`, `fw_sweep`; shared
//! with `#[path]`): it receives each band through `fill_contiguous` and does
//! the least a display driver must do with it.

use core::convert::Infallible;
use core::hint::black_box;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;

use crate::workload::Crc32;

/// The display of the benchmark: it receives each band and does the least a
/// display driver must do with it, reading every pixel once
/// ([`Mode::Consume`]); or it checksums the frame ([`Mode::Crc`]) or counts
/// the pixels that differ from a background ([`Mode::Covered`]), both
/// outside the timed frame.
pub struct Sink {
    size: Size,
    mode: Mode,
    crc: Crc32,
    /// Pixels that differ from the background of [`Mode::Covered`].
    pub covered: u32,
    /// Pixels received.
    pub pixels: u32,
}

/// What the [`Sink`] does with the pixels.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Read them (summed into a value kept with `black_box`): the timed frame.
    #[cfg_attr(not(target_os = "none"), allow(dead_code))]
    Consume,
    /// CRC-32 of the frame (as in `workload::CrcTarget`).
    Crc,
    /// Count those that differ from this colour.
    #[cfg_attr(target_os = "none", allow(dead_code))]
    Covered(Rgb565),
}

impl Sink {
    /// A display of `width × height` pixels.
    pub fn new(width: u32, height: u32, mode: Mode) -> Self {
        Sink { size: Size::new(width, height), mode, crc: Crc32::new(), covered: 0, pixels: 0 }
    }

    /// CRC-32 of the frame ([`Mode::Crc`]).
    pub fn crc(&self) -> u32 {
        self.crc.value()
    }
}

impl OriginDimensions for Sink {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for Sink {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        // The renderer sends whole bands only; count strays so a host run
        // would notice (pixels then exceed width × height).
        for p in pixels {
            black_box(p);
            self.pixels += 1;
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        match self.mode {
            Mode::Consume => {
                let mut sum = 0u32;
                for c in colors {
                    sum = sum.wrapping_add(u32::from(c.into_storage()));
                }
                black_box(sum);
            }
            Mode::Crc => {
                for c in colors {
                    self.crc.update(&c.into_storage().to_le_bytes());
                }
            }
            Mode::Covered(bg) => {
                for c in colors {
                    self.covered += u32::from(c != bg);
                }
            }
        }
        self.pixels += area.size.width * area.size.height;
        Ok(())
    }
}
