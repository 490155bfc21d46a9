//! An [`AsyncBandSink`] for MIPI-DCS SPI panels (ST7789, ILI9341, GC9A01,
//! ...) over `embedded-hal-async`'s `SpiDevice` and a data/command pin
//! (feature `async`).
//!
//! Chosen over an async display driver from crates.io: the async forks of
//! mipidsi (`lcd-async`) take whole framebuffers of raw bytes, while a band
//! sink needs only the three window commands a frame (CASET, RASET, RAMWR),
//! which every MIPI-DCS controller shares; `SpiDevice` is the interface
//! every async HAL (embassy-stm32, embassy-rp, esp-hal, ...) implements, with DMA.
//!
//! The window is set once a frame, at its first band: the controller's
//! write pointer then runs on across bands (chip select may rise between
//! them), so each later band is one pixel write, started at the first poll
//! of [`AsyncBandSink::send`]. The band is converted into `wire` (Rgb565 to
//! big-endian bytes) before that write: the library has no `unsafe` to lend
//! the band's memory to the SPI as bytes.

use embedded_graphics_core::pixelcolor::IntoStorage;
use embedded_graphics_core::primitives::Rectangle;
use embedded_hal::digital::OutputPin;
use embedded_hal_async::spi::SpiDevice;

use super::{AsyncBandSink, FrameBands};
use crate::Error;

/// MIPI DCS: column address set, row address set, memory write.
const CASET: u8 = 0x2A;
const RASET: u8 = 0x2B;
const RAMWR: u8 = 0x2C;

/// What a failed [`SpiPanel`] transfer reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
pub enum SpiPanelError<S, P> {
    /// The SPI device failed.
    Spi(S),
    /// The data/command pin failed.
    Dc(P),
    /// A band does not fit the wire buffer or the panel's 16-bit addresses.
    Window,
}

/// A MIPI-DCS panel on an async SPI device: frames of 16-bit colours
/// (`Rgb565`) sent band by band, each band from `wire`, which must hold one
/// band (`2 · W · H` bytes; [`Error::BufferTooSmall`] otherwise).
///
/// ```
/// # use core::convert::Infallible;
/// # use embedded_hal_async::spi::{ErrorType, Operation, SpiDevice};
/// # struct Spi(usize);
/// # impl ErrorType for Spi { type Error = Infallible; }
/// # impl SpiDevice for Spi {
/// #     async fn transaction(&mut self, ops: &mut [Operation<'_, u8>]) -> Result<(), Infallible> {
/// #         for op in ops { if let Operation::Write(b) = op { self.0 += b.len(); } }
/// #         Ok(())
/// #     }
/// # }
/// # struct Pin;
/// # impl embedded_hal::digital::ErrorType for Pin { type Error = Infallible; }
/// # impl embedded_hal::digital::OutputPin for Pin {
/// #     fn set_low(&mut self) -> Result<(), Infallible> { Ok(()) }
/// #     fn set_high(&mut self) -> Result<(), Infallible> { Ok(()) }
/// # }
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::render::{SpiPanel, poll_ready};
/// use microraster::{Band, Renderer};
/// let mut bands = [const { Band::<Rgb565, 8, 4>::new(Rgb565::new(0, 0, 0)) }; 2];
/// let mut wire = [0u8; 2 * 8 * 4];
/// let mut panel = SpiPanel::new(Spi(0), Pin, &mut wire);
/// let renderer = Renderer::new(8, Rgb565::new(0, 0, 0));
/// let frame = renderer.render_async((), &mut bands, &mut panel);
/// assert_eq!(poll_ready(frame), Some(Ok(())));
/// // Window commands (1 + 4 bytes, twice, and 1), then 8 × 8 pixels of 2 bytes.
/// assert_eq!(panel.release().0.0, 11 + 128);
/// ```
#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
pub struct SpiPanel<'w, SPI, DC> {
    spi: SPI,
    dc: DC,
    wire: &'w mut [u8],
    /// The frame's rectangle, until its first band has set the window.
    window: Option<Rectangle>,
}

impl<'w, SPI, DC> SpiPanel<'w, SPI, DC> {
    /// The panel on `spi` with data/command pin `dc`, bands staged in `wire`.
    pub fn new(spi: SPI, dc: DC, wire: &'w mut [u8]) -> Self {
        SpiPanel { spi, dc, wire, window: None }
    }

    /// The SPI device and the pin back.
    pub fn release(self) -> (SPI, DC) {
        (self.spi, self.dc)
    }
}

impl<SPI: SpiDevice, DC: OutputPin> SpiPanel<'_, SPI, DC> {
    async fn command(&mut self, cmd: u8, args: &[u8]) -> Result<(), SpiPanelError<SPI::Error, DC::Error>> {
        self.dc.set_low().map_err(SpiPanelError::Dc)?;
        self.spi.write(&[cmd]).await.map_err(SpiPanelError::Spi)?;
        if args.is_empty() {
            return Ok(());
        }
        self.dc.set_high().map_err(SpiPanelError::Dc)?;
        self.spi.write(args).await.map_err(SpiPanelError::Spi)
    }

    /// CASET, RASET and RAMWR for `area` (inclusive 16-bit bounds).
    async fn set_window(&mut self, area: Rectangle) -> Result<(), SpiPanelError<SPI::Error, DC::Error>> {
        let bounds = |start: i32, len: u32| {
            let first = u16::try_from(start).ok()?;
            let last = u16::try_from(i64::from(start) + i64::from(len) - 1).ok()?;
            let ([a, b], [c, d]) = (first.to_be_bytes(), last.to_be_bytes());
            Some([a, b, c, d])
        };
        let x = bounds(area.top_left.x, area.size.width).ok_or(SpiPanelError::Window)?;
        let y = bounds(area.top_left.y, area.size.height).ok_or(SpiPanelError::Window)?;
        self.command(CASET, &x).await?;
        self.command(RASET, &y).await?;
        self.command(RAMWR, &[]).await
    }
}

impl<C, SPI, DC> AsyncBandSink<C> for SpiPanel<'_, SPI, DC>
where
    C: IntoStorage<Storage = u16> + Copy,
    SPI: SpiDevice,
    DC: OutputPin,
{
    type Error = SpiPanelError<SPI::Error, DC::Error>;

    fn begin(&mut self, frame: &FrameBands) -> Result<(), Error> {
        let band_bytes = 2 * u64::from(frame.size().width) * u64::from(frame.band_rows());
        if (self.wire.len() as u64) < band_bytes {
            return Err(Error::BufferTooSmall);
        }
        self.window = Some(Rectangle::new(frame.offset(), frame.size()));
        Ok(())
    }

    async fn send(&mut self, _area: Rectangle, pixels: &[C]) -> Result<(), Self::Error> {
        let n = 2 * pixels.len();
        let Some(wire) = self.wire.get_mut(..n) else {
            return Err(SpiPanelError::Window);
        };
        for (bytes, &c) in wire.chunks_exact_mut(2).zip(pixels) {
            bytes.copy_from_slice(&c.into_storage().to_be_bytes());
        }
        if let Some(window) = self.window.take() {
            self.set_window(window).await?;
        }
        self.dc.set_high().map_err(SpiPanelError::Dc)?;
        self.spi.write(&self.wire[..n]).await.map_err(SpiPanelError::Spi)
    }
}
