//! The standard 3D scene on a real display: an ST7789 320 × 240 SPI panel
//! driven by [mipidsi] 0.10 over embedded-hal 1.0 SPI from an STM32F405
//! ([stm32f4xx-hal] 0.23), rendered band by band straight into the display
//! (mipidsi's `Display` is an embedded-graphics `DrawTarget`: each 16-row band
//! goes out as one `fill_contiguous`, i.e. one address window and one burst of
//! pixels). No framebuffer: the colour band (10 KB), the 16-bit depth band
//! (10 KB) and the bins (36 KB) are all the RAM it renders with (57,348 B;
//! a 320 × 240 Rgb565 framebuffer alone would be 153,600 B). The scene turns
//! a little every frame.
//!
//! # Wiring (change the pins below for your board)
//!
//! | ST7789 | STM32F405 | note |
//! |---|---|---|
//! | SCL / SCK | PA5 | SPI1 SCK |
//! | SDA / MOSI | PA7 | SPI1 MOSI |
//! | CS | PA4 | chip select (tie low and use a dummy pin if the panel has none) |
//! | DC | PA3 | data/command |
//! | RES / RST | PA2 | reset |
//! | BLK / LED | PA1 | backlight, driven high |
//! | VCC, GND | 3V3, GND | |
//!
//! The clock tree assumes an 8 MHz crystal (HSE), as on most STM32F405
//! boards (Adafruit Feather STM32F405, Olimex STM32-E407, the Netduino Plus 2,
//! ...): 168 MHz core, SPI1 at 42 MHz (APB2 84 MHz / 2). Without a crystal use
//! `Config::hsi()` instead. The memory layout is the repository's top-level
//! `memory.x` (STM32F405: 1 MB flash, 128 KB RAM), which this package's
//! `build.rs` hands to the linker.
//!
//! # Build and flash
//!
//! This example is a package of its own (`examples/st7789/Cargo.toml`), so
//! the STM32F4 HAL stays out of the other firmware builds. Build it from the
//! repository root with either toolchain path (rustup's target when
//! installed, otherwise the offline fallback of `scripts/firmware.sh`):
//!
//! ```text
//! bash scripts/firmware.sh build-st7789     # prints the ELF's path
//! ```
//!
//! or, with rustup's target installed (`rustup target add thumbv7em-none-eabihf`):
//!
//! ```text
//! cd examples/st7789
//! cargo build --release --target thumbv7em-none-eabihf
//! # ELF: examples/st7789/target/thumbv7em-none-eabihf/release/microraster-st7789
//! ```
//!
//! Flash and run it with [probe-rs](https://probe.rs) (`cargo install
//! probe-rs-tools`) through an ST-Link, J-Link or CMSIS-DAP probe on the
//! board's SWD pins:
//!
//! ```text
//! probe-rs run --chip STM32F405RGTx "$(bash scripts/firmware.sh build-st7789)"
//! ```
//!
//! `probe-rs download --chip STM32F405RGTx ELF` flashes without attaching,
//! then reset the board; `probe-rs chip list | grep STM32F405` lists the
//! packages `--chip` accepts. A panic stops at a breakpoint (visible under
//! `probe-rs run` or a debugger; without one the core locks up).
//!
//! On the host (`cargo run` in `examples/st7789`) it builds as a program that
//! only says what it is.
//!
//! [mipidsi]: https://docs.rs/mipidsi/0.10
//! [stm32f4xx-hal]: https://docs.rs/stm32f4xx-hal/0.23
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
mod firmware {
    use cortex_m_rt::entry;
    use embedded_graphics_core::draw_target::DrawTarget;
    use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
    use embedded_hal_bus::spi::ExclusiveDevice;
    use microraster::Renderer;
    use microraster::render::Triangles3d;
    use microraster::depth::{Depth16, DepthBand, DepthState};
    use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
    use microraster_scenes::scenes3d::{BINS, Scene3d};
    use microraster::{Band, RenderError};
    use mipidsi::interface::SpiInterface;
    use mipidsi::models::ST7789;
    use mipidsi::options::{ColorInversion, Orientation, Rotation};
    use stm32f4xx_hal::pac;
    use stm32f4xx_hal::prelude::*;
    use stm32f4xx_hal::rcc::Config;
    use stm32f4xx_hal::spi::{Mode, Phase, Polarity};

    /// Frame size (landscape).
    const W: usize = 320;
    const H: u32 = 240;
    /// Band rows.
    const BAND: usize = 16;
    /// Subpixel bits.
    const S: u32 = 4;
    const BACKGROUND: Rgb565 = Rgb565::BLACK;

    #[entry]
    fn main() -> ! {
        // cortex-m-rt turns these into `&'static mut` references; all three
        // are zero-initialised (.bss: RAM, no flash).
        static mut BAND_BUF: Band<Rgb565, W, BAND> = Band::new(BACKGROUND);
        static mut DEPTH: DepthBand<Depth16, W, BAND> = DepthBand::zeroed();
        static mut BINS_BUF: heapless::Vec<ScreenTriangle<S>, BINS> = heapless::Vec::new();
        // mipidsi's SPI staging buffer: pixels are converted into it and sent
        // in bursts of this many bytes.
        static mut SPI_BUF: [u8; 512] = [0; 512];

        let dp = pac::Peripherals::take().unwrap();
        let cp = cortex_m::Peripherals::take().unwrap();
        let mut rcc = dp.RCC.freeze(Config::hse(8.MHz()).sysclk(168.MHz()));
        let mut delay = cp.SYST.delay(&rcc.clocks);

        let gpioa = dp.GPIOA.split(&mut rcc);
        let sck = gpioa.pa5.into_alternate().speed(stm32f4xx_hal::gpio::Speed::VeryHigh);
        let mosi = gpioa.pa7.into_alternate().speed(stm32f4xx_hal::gpio::Speed::VeryHigh);
        let cs = gpioa.pa4.into_push_pull_output();
        let dc = gpioa.pa3.into_push_pull_output();
        let rst = gpioa.pa2.into_push_pull_output();
        let mut backlight = gpioa.pa1.into_push_pull_output();

        let mode = Mode { polarity: Polarity::IdleHigh, phase: Phase::CaptureOnSecondTransition };
        let spi = dp.SPI1.spi((Some(sck), pac::SPI1::NoMiso, Some(mosi)), mode, 42.MHz(), &mut rcc);
        let spi = ExclusiveDevice::new_no_delay(spi, cs).unwrap();
        let interface = SpiInterface::new(spi, dc, SPI_BUF);
        let mut display = mipidsi::Builder::new(ST7789, interface)
            .reset_pin(rst)
            .display_size(240, 320)
            .orientation(Orientation::new().rotate(Rotation::Deg90))
            // Most ST7789 modules need inverted colours; drop this line if
            // yours shows a negative.
            .invert_colors(ColorInversion::Inverted)
            .init(&mut delay)
            .unwrap();
        backlight.set_high();

        let mut angle = 0.0f32;
        loop {
            frame(angle, BINS_BUF, BAND_BUF, DEPTH, &mut display).unwrap();
            angle += 0.05;
        }
    }

    /// One frame: the vertex stage bins every visible triangle, then the
    /// bands are rendered and sent to `display` one by one.
    fn frame<D: DrawTarget<Color = Rgb565>>(
        angle: f32,
        bins: &mut heapless::Vec<ScreenTriangle<S>, BINS>,
        band: &mut Band<Rgb565, W, BAND>,
        depth: &mut DepthBand<Depth16, W, BAND>,
        display: &mut D,
    ) -> Result<(), RenderError<D::Error>> {
        let pipeline = Scene3d::pipeline::<f32, S>(W as u32, H)?;
        bins.clear();
        Scene3d.draw::<f32, Rgb565, S, BINS>(&pipeline, angle, bins)?;
        Renderer::new(H, BACKGROUND).render(Triangles3d::new(bins, depth, DepthState::LESS_WRITE, PerspectiveCorrect), band, display)
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
        "microraster-st7789: firmware for an STM32F405 with an ST7789 SPI display; build it with \
         `bash scripts/firmware.sh build-st7789` and flash it with probe-rs (see src/main.rs)"
    );
}
