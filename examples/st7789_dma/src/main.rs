//! The ST7789 example's DMA build: the standard 3D scene on an ST7789
//! 320 × 240 SPI panel, sent by DMA from an STM32F405 through microraster's
//! async display link. `Renderer::render_async` draws band *k + 1*
//! while [`SpiPanel`] sends band *k*: the SPI write of embassy-stm32 starts
//! its DMA transfer at the first poll and the renderer awaits it only when
//! it needs that band buffer back.
//!
//! RAM it renders with: two 16-row Rgb565 bands (2 × 10 KB), the wire
//! buffer `SpiPanel` converts a band into (10 KB of big-endian bytes: the
//! library has no `unsafe` to hand the band itself to the DMA), the 16-bit
//! depth band (10 KB) and the bins (36 KB).
//!
//! Wiring and clocks as in `examples/st7789` (SPI1: SCK PA5, MOSI PA7, CS
//! PA4, DC PA3, RST PA2, backlight PA1; 8 MHz crystal, 168 MHz core, SPI1
//! at 42 MHz). SPI1 TX uses DMA2 stream 3.
//!
//! No async executor crate: the frame future is polled in a loop
//! ([`block_on`]), which is all one task needs; embassy-stm32's DMA
//! interrupt completes the transfer, the next poll sees it.
//!
//! # Build and flash
//!
//! ```text
//! bash scripts/firmware.sh build-st7789-dma   # prints the ELF's path
//! probe-rs run --chip STM32F405RGTx "$(bash scripts/firmware.sh build-st7789-dma)"
//! ```
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
mod firmware {
    use core::future::Future;
    use core::pin::pin;
    use core::task::{Context, Poll, Waker};

    use cortex_m_rt::entry;
    use embassy_stm32::gpio::{Level, Output, Speed};
    use embassy_stm32::time::Hertz;
    use embassy_stm32::{bind_interrupts, dma, peripherals, rcc, spi};
    use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
    use embedded_hal::digital::OutputPin;
    use embedded_hal_async::spi::SpiDevice;
    use embedded_hal_bus::spi::ExclusiveDevice;
    use microraster::depth::{Depth16, DepthBand, DepthState};
    use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
    use microraster::render::{SpiPanel, Triangles3d};
    use microraster_scenes::scenes3d::{BINS, Scene3d};
    use microraster::{Band, Renderer};

    /// Frame size (landscape), band rows, subpixel bits.
    const W: usize = 320;
    const H: u32 = 240;
    const BAND: usize = 16;
    const S: u32 = 4;
    const BACKGROUND: Rgb565 = Rgb565::BLACK;
    const CORE_HZ: u32 = 168_000_000;

    bind_interrupts!(struct Irqs {
        DMA2_STREAM3 => dma::InterruptHandler<peripherals::DMA2_CH3>;
    });

    #[entry]
    fn main() -> ! {
        // cortex-m-rt turns these into `&'static mut` references (.bss).
        static mut BANDS: [Band<Rgb565, W, BAND>; 2] = [const { Band::new(BACKGROUND) }; 2];
        static mut DEPTH: DepthBand<Depth16, W, BAND> = DepthBand::zeroed();
        static mut BINS_BUF: heapless::Vec<ScreenTriangle<S>, BINS> = heapless::Vec::new();
        static mut WIRE: [u8; 2 * W * BAND] = [0; 2 * W * BAND];

        let p = embassy_stm32::init(clocks());
        let mut config = spi::Config::default();
        config.frequency = Hertz(42_000_000);
        config.mode = spi::MODE_3;
        let spi = spi::Spi::new_txonly(p.SPI1, p.PA5, p.PA7, p.DMA2_CH3, Irqs, config);
        let cs = Output::new(p.PA4, Level::High, Speed::VeryHigh);
        let mut dc = Output::new(p.PA3, Level::Low, Speed::VeryHigh);
        let mut rst = Output::new(p.PA2, Level::Low, Speed::Low);
        let _backlight = Output::new(p.PA1, Level::High, Speed::Low);
        let Ok(mut spi) = ExclusiveDevice::new_no_delay(spi, cs);

        rst.set_low();
        ms(10);
        rst.set_high();
        ms(120);
        block_on(init(&mut spi, &mut dc)).unwrap();

        let mut panel = SpiPanel::new(spi, dc, WIRE);
        let renderer = Renderer::new(H, BACKGROUND);
        let pipeline = Scene3d::pipeline::<f32, S>(W as u32, H).unwrap();
        let mut angle = 0.0f32;
        loop {
            BINS_BUF.clear();
            Scene3d.draw::<f32, Rgb565, S, BINS>(&pipeline, angle, BINS_BUF).unwrap();
            let frame = renderer.render_async(Triangles3d::new(BINS_BUF, DEPTH, DepthState::LESS_WRITE, PerspectiveCorrect), BANDS, &mut panel);
            block_on(frame).unwrap();
            angle += 0.05;
        }
    }

    /// 8 MHz crystal, PLL to 168 MHz; APB2 (SPI1) at 84 MHz, so SPI1 at 42 MHz.
    fn clocks() -> embassy_stm32::Config {
        let mut config = embassy_stm32::Config::default();
        config.rcc.hse = Some(rcc::Hse { freq: Hertz(8_000_000), mode: rcc::HseMode::Oscillator });
        config.rcc.pll_src = rcc::PllSource::HSE;
        config.rcc.pll = Some(rcc::Pll {
            prediv: rcc::PllPreDiv::DIV4,
            mul: rcc::PllMul::MUL168,
            divp: Some(rcc::PllPDiv::DIV2),
            divq: Some(rcc::PllQDiv::DIV7),
            divr: None,
        });
        config.rcc.ahb_pre = rcc::AHBPrescaler::DIV1;
        config.rcc.apb1_pre = rcc::APBPrescaler::DIV4;
        config.rcc.apb2_pre = rcc::APBPrescaler::DIV2;
        config.rcc.sys = rcc::Sysclk::PLL1_P;
        config
    }

    fn ms(n: u32) {
        cortex_m::asm::delay(n * (CORE_HZ / 1000));
    }

    /// The ST7789 power-up sequence: sleep out, 16-bit colour, landscape
    /// (MADCTL MV | MX), inverted colours (most modules), display on.
    async fn init<SPI: SpiDevice, DC: OutputPin>(spi: &mut SPI, dc: &mut DC) -> Result<(), ()> {
        let steps: [(u8, &[u8], u32); 5] =
            [(0x11, &[], 120), (0x3A, &[0x55], 0), (0x36, &[0x60], 0), (0x21, &[], 0), (0x29, &[], 20)];
        for (cmd, args, wait) in steps {
            dc.set_low().map_err(drop)?;
            spi.write(&[cmd]).await.map_err(drop)?;
            if !args.is_empty() {
                dc.set_high().map_err(drop)?;
                spi.write(args).await.map_err(drop)?;
            }
            ms(wait);
        }
        Ok(())
    }

    /// Polls `future` until it is ready: one task, nothing else to run.
    fn block_on<F: Future>(future: F) -> F::Output {
        let mut future = pin!(future);
        let mut cx = Context::from_waker(Waker::noop());
        loop {
            if let Poll::Ready(out) = future.as_mut().poll(&mut cx) {
                return out;
            }
        }
    }

    #[panic_handler]
    fn panic(_: &core::panic::PanicInfo) -> ! {
        loop {
            cortex_m::asm::bkpt();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    println!(
        "microraster-st7789-dma: firmware for an STM32F405 with an ST7789 SPI display, sent by DMA; \
         build it with `bash scripts/firmware.sh build-st7789-dma` and flash it with probe-rs (see src/main.rs)"
    );
}
