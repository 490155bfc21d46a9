//! CRC-32 and the display that only checksums what it receives: one
//! [`Record`] per band and one per frame, the lines a QEMU run must match.

use core::convert::Infallible;
use core::fmt;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;

use super::Out;

/// CRC-32 as in zlib, PNG and Ethernet (reflected polynomial 0xEDB88320,
/// initial value and final XOR all ones); `CRC("123456789") = 0xCBF43926`.
#[derive(Clone, Copy, Debug)]
pub struct Crc32(u32);

const CRC_TABLE: [u32; 256] = {
    let mut table = [0u32; 256];
    let mut i = 0;
    while i < 256 {
        let mut c = i as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
            k += 1;
        }
        table[i] = c;
        i += 1;
    }
    table
};

impl Default for Crc32 {
    fn default() -> Self {
        Self::new()
    }
}

impl Crc32 {
    /// A CRC over no bytes yet.
    pub const fn new() -> Self {
        Crc32(!0)
    }

    /// Adds `bytes`.
    pub fn update(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = CRC_TABLE[((self.0 ^ b as u32) & 0xFF) as usize] ^ (self.0 >> 8);
        }
    }

    /// The CRC of everything added so far.
    pub const fn value(&self) -> u32 {
        !self.0
    }
}

/// What the firmware prints: `scene band y0 rows crc count`, where `band`
/// is the band's index or `frame` (the whole frame: the CRC runs on over
/// every band, the count is the frame's pixel count).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Record {
    /// Scene name, with the frame size and the configuration.
    pub scene: &'static str,
    /// Band index; `None` for the frame record.
    pub band: Option<u32>,
    /// First frame row.
    pub y0: i32,
    /// Number of rows.
    pub rows: u32,
    /// CRC-32 of the pixels, `Rgb565` little-endian, row by row.
    pub crc: u32,
    /// Number of pixels received.
    pub count: u32,
}

impl fmt::Display for Record {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.scene)?;
        match self.band {
            Some(b) => write!(f, " {b}")?,
            None => f.write_str(" frame")?,
        }
        write!(f, " {} {} {:08x} {}", self.y0, self.rows, self.crc, self.count)
    }
}

/// A display that keeps nothing: it checksums each band it receives and
/// reports it.
pub struct CrcTarget<'a> {
    scene: &'static str,
    size: Size,
    bands: u32,
    rows: u32,
    frame: Crc32,
    count: u32,
    /// Pixels that arrived through `draw_iter` (the renderer sends whole
    /// bands only, so any would be a bug); reported by [`CrcTarget::finish`].
    stray: (Crc32, u32),
    out: Out<'a>,
}

impl<'a> CrcTarget<'a> {
    /// A target of `width × height` pixels reporting to `out` as `scene`.
    pub fn new(scene: &'static str, width: u32, height: u32, out: Out<'a>) -> Self {
        CrcTarget {
            scene,
            size: Size::new(width, height),
            bands: 0,
            rows: 0,
            frame: Crc32::new(),
            count: 0,
            stray: (Crc32::new(), 0),
            out,
        }
    }

    /// Reports the frame record (and stray pixels, if any).
    pub fn finish(self) {
        if self.stray.1 > 0 {
            let (crc, count) = (self.stray.0.value(), self.stray.1);
            (self.out)(&Record { scene: self.scene, band: Some(u32::MAX), y0: -1, rows: 0, crc, count });
        }
        let frame = Record {
            scene: self.scene,
            band: None,
            y0: 0,
            rows: self.rows,
            crc: self.frame.value(),
            count: self.count,
        };
        (self.out)(&frame);
    }
}

impl OriginDimensions for CrcTarget<'_> {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for CrcTarget<'_> {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            let (x, y) = (p.x as u16, p.y as u16);
            self.stray.0.update(&x.to_le_bytes());
            self.stray.0.update(&y.to_le_bytes());
            self.stray.0.update(&c.into_storage().to_le_bytes());
            self.stray.1 += 1;
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        let (mut crc, mut count) = (Crc32::new(), 0u32);
        for c in colors {
            let bytes = c.into_storage().to_le_bytes();
            crc.update(&bytes);
            self.frame.update(&bytes);
            count += 1;
        }
        let record = Record {
            scene: self.scene,
            band: Some(self.bands),
            y0: area.top_left.y,
            rows: area.size.height,
            crc: crc.value(),
            count,
        };
        (self.out)(&record);
        self.bands += 1;
        self.rows += area.size.height;
        self.count += count;
        Ok(())
    }
}
