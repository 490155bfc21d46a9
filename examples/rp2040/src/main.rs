//! The standard 3D scene on both cores of an RP2040 (Raspberry Pi Pico),
//! sent to an ST7789 320 × 240 SPI panel. Each core runs the library's
//! linked band loop (`Renderer::render_linked`) over its own two band
//! buffers, its own depth band and its own bins, and draws only its share
//! of the bands: even bands on core 0, odd bands on core 1 (the other
//! core's bands are cleared, not drawn). Its [`BandSink`] sends a band of
//! its own when the shared turn counter says that band is next, so the
//! panel gets band 0, 1, 2, ... of every frame in order.
//!
//! Each core runs the vertex stage itself (the scene is small, and no
//! triangle list is shared between cores, so no `unsafe`). The panel is
//! shared through a `critical_section::Mutex` (the RP2040 HAL's critical
//! section takes a hardware spinlock, so it holds across both cores); the
//! turn counter is an atomic with load and store only (ARMv6-M has no
//! compare-and-swap, and none is needed: only the core whose band is next
//! writes it).
//!
//! QEMU has no RP2040 machine; CI builds this firmware as it is and runs
//! its emulator build (`--features emu`: the same program, plus a CRC of
//! every band sent, SPI0 in loopback and a one-core mode) in the
//! `rp2040-emu` crate, whose frames must equal the host's
//! (`cargo run -- crc N`, src/scene.rs): `bash scripts/firmware.sh rp2040`,
//! examples/rp2040/emu.
//!
//! # Wiring (Pico pin numbers: GPIO)
//!
//! ST7789 SCK GP18, MOSI GP19 (SPI0), CS GP17, DC GP16, RST GP20, backlight
//! GP21. 12 MHz crystal, 125 MHz system clock, SPI0 at 62.5 MHz.
//!
//! # Build and flash
//!
//! ```text
//! bash scripts/firmware.sh build-rp2040      # prints the ELF's path
//! probe-rs run --chip RP2040 "$(bash scripts/firmware.sh build-rp2040)"
//! ```
//!
//! or convert the ELF with `elf2uf2-rs` and copy it to the Pico's USB drive.
#![cfg_attr(target_os = "none", no_std, no_main)]

mod scene;

// The CRC-32 and the records of the other firmware (examples/firmware).
#[cfg_attr(target_os = "none", allow(dead_code))]
#[path = "../../firmware/workload/crc.rs"]
mod crc;
/// Where records go (crc.rs's `CrcTarget`, used on the host).
#[cfg_attr(target_os = "none", allow(dead_code))]
type Out<'a> = &'a mut dyn FnMut(&crc::Record);

#[cfg(all(target_os = "none", feature = "emu"))]
mod emu;
#[cfg(all(target_os = "none", feature = "emu"))]
mod mailbox;

#[cfg(target_os = "none")]
mod firmware {
    use core::cell::RefCell;
    use core::convert::Infallible;
    use core::sync::atomic::{AtomicUsize, Ordering};

    use critical_section::Mutex;
    use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
    use embedded_graphics_core::primitives::Rectangle;
    use embedded_hal::digital::OutputPin;
    use embedded_hal::spi::SpiBus;
    use microraster::render::{BandSink, Lent};
    use rp2040_hal::fugit::RateExtU32;
    use rp2040_hal::gpio::{FunctionSioOutput, FunctionSpi, Pin, PullDown, bank0};
    use rp2040_hal::multicore::{Multicore, Stack};
    use rp2040_hal::{Clock, Sio, Watchdog, clocks, pac, spi};

    #[unsafe(link_section = ".boot2")]
    #[used]
    static BOOT2_FIRMWARE: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

    use crate::scene::{self, BACKGROUND, BANDS, Bands, Bins, Depth, W};
    #[cfg(feature = "emu")]
    use crate::{emu, mailbox};

    const CORE_HZ: u32 = 125_000_000;

    type Spi0 = spi::Spi<
        spi::Enabled,
        pac::SPI0,
        (Pin<bank0::Gpio19, FunctionSpi, PullDown>, Pin<bank0::Gpio18, FunctionSpi, PullDown>),
        8,
    >;
    type Out<I> = Pin<I, FunctionSioOutput, PullDown>;

    /// The panel both cores send to, one band at a time.
    static PANEL: Mutex<RefCell<Option<Panel>>> = Mutex::new(RefCell::new(None));
    /// The next band the panel takes, counted over all frames.
    static TURN: AtomicUsize = AtomicUsize::new(0);
    static CORE1_STACK: Stack<8192> = Stack::new();

    struct Panel {
        spi: Spi0,
        dc: Out<bank0::Gpio16>,
        cs: Out<bank0::Gpio17>,
    }

    impl Panel {
        /// One MIPI-DCS command and its argument bytes.
        fn command(&mut self, cmd: u8, args: &[u8]) {
            let _ = self.cs.set_low();
            let _ = self.dc.set_low();
            let _ = self.spi.write(&[cmd]);
            let _ = self.spi.flush();
            let _ = self.dc.set_high();
            let _ = self.spi.write(args);
            let _ = self.spi.flush();
            let _ = self.cs.set_high();
        }

        /// A band: its window, then its pixels as big-endian Rgb565.
        fn send(&mut self, area: Rectangle, pixels: &[Rgb565]) {
            let (x, y) = (area.top_left.x as u16, area.top_left.y as u16);
            let (x1, y1) = (x + area.size.width as u16 - 1, y + area.size.height as u16 - 1);
            let [a, b] = x.to_be_bytes();
            let [c, d] = x1.to_be_bytes();
            self.command(0x2A, &[a, b, c, d]);
            let [a, b] = y.to_be_bytes();
            let [c, d] = y1.to_be_bytes();
            self.command(0x2B, &[a, b, c, d]);
            self.command(0x2C, &[]);
            let _ = self.cs.set_low();
            let mut chunk = [0u8; 64];
            for px in pixels.chunks(32) {
                for (bytes, c) in chunk.chunks_exact_mut(2).zip(px) {
                    bytes.copy_from_slice(&c.into_storage().to_be_bytes());
                }
                let _ = self.spi.write(&chunk[..2 * px.len()]);
            }
            let _ = self.spi.flush();
            let _ = self.cs.set_high();
        }
    }

    /// Sends this core's bands in turn; hands the others back untouched.
    struct Share {
        core: usize,
        /// Cores rendering: 2, or 1 (core 0 alone; the emulator build's
        /// one-core mode).
        cores: usize,
        frame: usize,
    }

    /// Whether band `index` is core `core`'s.
    fn mine(core: usize, cores: usize, index: usize) -> bool {
        cores == 1 || index % 2 == core
    }

    /// What core `core` does now (the emulator build reports it).
    #[cfg_attr(not(feature = "emu"), allow(unused_variables))]
    fn state(core: usize, state: u32) {
        #[cfg(feature = "emu")]
        emu::state(core, state);
    }

    #[cfg(not(feature = "emu"))]
    mod mailbox {
        pub const RENDER: u32 = 1;
        pub const WAIT: u32 = 2;
        pub const SEND: u32 = 3;
        pub const VERTEX: u32 = 4;
    }

    impl<'a> BandSink<'a, Rgb565, W> for Share {
        type Error = Infallible;

        fn submit(&mut self, band: Lent<'a, Rgb565, W>) -> Result<Option<Lent<'a, Rgb565, W>>, Infallible> {
            if mine(self.core, self.cores, band.index()) {
                let turn = self.frame.wrapping_mul(BANDS).wrapping_add(band.index());
                state(self.core, mailbox::WAIT);
                while TURN.load(Ordering::Acquire) != turn {
                    core::hint::spin_loop();
                }
                state(self.core, mailbox::SEND);
                critical_section::with(|cs| {
                    if let Some(panel) = PANEL.borrow_ref_mut(cs).as_mut() {
                        panel.send(band.area(), band.pixels());
                    }
                    #[cfg(feature = "emu")]
                    emu::band(cs, self.frame, band.index(), band.area(), band.pixels());
                });
                TURN.store(turn.wrapping_add(1), Ordering::Release);
                state(self.core, mailbox::RENDER);
            }
            Ok(Some(band))
        }
    }

    /// One core's endless loop: its bins, its bands, its share of each frame.
    fn render(core: usize, cores: usize, bins: &mut Bins, bands: &mut Bands, depth: &mut Depth) -> ! {
        let pipeline = scene::pipeline();
        let mut sink = Share { core, cores, frame: 0 };
        loop {
            state(core, mailbox::VERTEX);
            scene::vertex(&pipeline, sink.frame, bins).unwrap();
            state(core, mailbox::RENDER);
            scene::raster(|i| mine(core, cores, i), bins, bands, depth, &mut sink).unwrap();
            sink.frame += 1;
        }
    }

    fn ms(n: u32) {
        cortex_m::asm::delay(n * (CORE_HZ / 1000));
    }

    #[rp2040_hal::entry]
    fn main() -> ! {
        // cortex-m-rt's `&'static mut` statics (.bss): one set per core.
        static mut BINS0: Bins = heapless::Vec::new();
        static mut BINS1: Bins = heapless::Vec::new();
        static mut BANDS0: Bands = [const { microraster::Band::new(BACKGROUND) }; 2];
        static mut BANDS1: Bands = [const { microraster::Band::new(BACKGROUND) }; 2];
        static mut DEPTH0: Depth = microraster::depth::DepthBand::zeroed();
        static mut DEPTH1: Depth = microraster::depth::DepthBand::zeroed();

        let mut pac = pac::Peripherals::take().unwrap();
        let mut watchdog = Watchdog::new(pac.WATCHDOG);
        let clocks = clocks::init_clocks_and_plls(
            12_000_000,
            pac.XOSC,
            pac.CLOCKS,
            pac.PLL_SYS,
            pac.PLL_USB,
            &mut pac.RESETS,
            &mut watchdog,
        )
        .ok()
        .unwrap();
        let mut sio = Sio::new(pac.SIO);
        let pins = rp2040_hal::gpio::Pins::new(pac.IO_BANK0, pac.PADS_BANK0, sio.gpio_bank0, &mut pac.RESETS);
        let spi =
            spi::Spi::<_, _, _, 8>::new(pac.SPI0, (pins.gpio19.into_function(), pins.gpio18.into_function()))
                .init(
                    &mut pac.RESETS,
                    clocks.peripheral_clock.freq(),
                    62_500_000u32.Hz(),
                    embedded_hal::spi::MODE_3,
                );
        #[cfg(feature = "emu")]
        emu::loopback();
        let mut panel =
            Panel { spi, dc: pins.gpio16.into_push_pull_output(), cs: pins.gpio17.into_push_pull_output() };
        let mut rst = pins.gpio20.into_push_pull_output();
        let _ = pins.gpio21.into_push_pull_output().set_high(); // backlight
        let _ = rst.set_low();
        ms(10);
        let _ = rst.set_high();
        ms(120);
        // Sleep out, 16-bit colour, landscape (MADCTL MV | MX), inverted
        // colours (most modules), display on.
        for (cmd, args, wait) in
            [(0x11, &[][..], 120), (0x3A, &[0x55], 0), (0x36, &[0x60], 0), (0x21, &[], 0)]
        {
            panel.command(cmd, args);
            ms(wait);
        }
        panel.command(0x29, &[]);
        critical_section::with(|cs| PANEL.borrow_ref_mut(cs).replace(panel));

        #[cfg(feature = "emu")]
        let cores = emu::cores();
        #[cfg(not(feature = "emu"))]
        let cores = 2;
        if cores == 2 {
            let (bins1, bands1, depth1) = (BINS1, BANDS1, DEPTH1);
            let mut mc = Multicore::new(&mut pac.PSM, &mut pac.PPB, &mut sio.fifo);
            let core1 = &mut mc.cores()[1];
            core1.spawn(CORE1_STACK.take().unwrap(), move || render(1, 2, bins1, bands1, depth1)).unwrap();
        }
        render(0, cores, BINS0, BANDS0, DEPTH0)
    }

    #[panic_handler]
    fn panic(_: &core::panic::PanicInfo) -> ! {
        #[cfg(feature = "emu")]
        emu::panicked();
        loop {
            cortex_m::asm::bkpt();
        }
    }
}

/// On the host: a note, or with `crc N` the reference the emulator run
/// must match, frames 0 to N - 1 of src/scene.rs rendered into crc.rs's
/// `CrcTarget` (one record per band, one per frame), each line prefixed
/// with its frame number.
#[cfg(not(target_os = "none"))]
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let frames = match args.as_slice() {
        [] => {
            println!(
                "microraster-rp2040: firmware for an RP2040 (both cores) with an ST7789 SPI display; build it with \
                 `bash scripts/firmware.sh build-rp2040` and flash it with probe-rs (see src/main.rs); \
                 `-- crc N` prints the frames the emulator run must match"
            );
            return;
        }
        [crc, n] if crc == "crc" => n.parse::<usize>().unwrap_or_else(|e| panic!("crc N: {e}")),
        _ => panic!("usage: microraster-rp2040 [crc N]"),
    };
    let pipeline = scene::pipeline();
    let mut bins = Box::new(scene::Bins::new());
    let mut bands = Box::new([const { microraster::Band::new(scene::BACKGROUND) }; 2]);
    let mut depth = Box::new(scene::Depth::new());
    for n in 0..frames {
        let mut print = |r: &crc::Record| println!("{n} {r}");
        let mut target = crc::CrcTarget::new("rp2040/320x240", scene::W as u32, scene::H, &mut print);
        let mut sink = microraster::render::Blocking(&mut target);
        scene::vertex(&pipeline, n, &mut bins).unwrap();
        scene::raster(|_| true, &bins, &mut bands, &mut depth, &mut sink).unwrap();
        target.finish();
    }
}
