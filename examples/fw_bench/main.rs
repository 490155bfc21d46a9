//! Firmware benchmark: instructions per frame of each configuration in
//! [`benches::M4F`] / [`benches::M0`], measured under QEMU's instruction
//! counting, with the stack high-water mark of each frame.
//!
//! `bash scripts/firmware.sh table` builds it for both targets, runs it under
//! QEMU with `-icount shift=0` (virtual time advances 1 ns per executed
//! instruction, so a timer counts instructions) and hands its output to the
//! host side of this example, which prints the table of the README.
//!
//! * Target (`target_os = "none"`): for each configuration, one untimed
//!   preparation (a 2D scene collected into RAM), the stack painted, one
//!   timed frame into a display that only reads each pixel, the stack
//!   scanned, then one more frame into a CRC display. Prints
//!   `bench INDEX ticks=T instr=I stack=B crc=C` per configuration and `#`
//!   notes (the timer's calibration). Timers: Cortex-M4F on QEMU
//!   `mps2-an386`, SysTick on the 25 MHz core clock, 40 instructions per
//!   tick; Cortex-M0 on QEMU `microbit`, the nRF51's TIMER0 at 16 MHz,
//!   62.5 instructions per tick. A loop of a known instruction count
//!   calibrates the ratio first, and the run fails if it is off.
//! * Host: `fw_bench m4f|m0` prints each configuration's triangles, lines,
//!   covered pixels and frame CRC; `fw_bench table FILE` reads the target
//!   runs and sizes that `scripts/firmware.sh table` collected into FILE,
//!   checks every frame CRC against the host's, and prints the table.
#![cfg_attr(target_os = "none", no_std, no_main)]

// The CRC firmware's workload: its constants, CRC and buffers sizes.
#[allow(dead_code)]
#[path = "../firmware/workload.rs"]
mod workload;

#[cfg_attr(target_os = "none", allow(dead_code))]
mod benches;

#[cfg(target_os = "none")]
#[path = "../firmware/stack.rs"]
mod stack;

#[cfg(not(target_os = "none"))]
mod table;

#[cfg(target_os = "none")]
mod firmware {
    use crate::benches::{self, BACKGROUND, Bench, Buffers, Mode, Sink};
    use crate::stack;
    use crate::workload::S;
    use core::hint::black_box;
    use core::sync::atomic::{Ordering, compiler_fence};
    use cortex_m_rt::entry;
    use cortex_m_semihosting::{debug, hprintln};
    use embedded_graphics_core::pixelcolor::Rgb565;
    use microraster::depth::{Depth16, DepthBand};
    use microraster::raster3d::ScreenTriangle;
    use microraster::{Band, Error};
    use panic_semihosting as _;

    /// Cortex-M4F (timed on QEMU mps2-an386).
    #[cfg(target_abi = "eabihf")]
    #[entry]
    fn main() -> ! {
        // The CRC firmware's buffers (examples/firmware/main.rs); all zeroed (.bss).
        static mut PRIMS: heapless::Vec<microraster::Primitive<Rgb565, S>, { benches::PRIMS }> =
            heapless::Vec::new();
        static mut BAND: Band<Rgb565, { benches::M4F_SIZE.0 }, { benches::M4F_BAND }> = Band::new(BACKGROUND);
        static mut DEPTH: DepthBand<Depth16, { benches::M4F_SIZE.0 }, { benches::M4F_BAND }> =
            DepthBand::zeroed();
        static mut BINS: heapless::Vec<ScreenTriangle<S>, { benches::BINS }> = heapless::Vec::new();
        static mut CACHE: benches::Cache = benches::Cache::new();
        let b = Buffers { prims: PRIMS, band: BAND, depth: DEPTH, bins: BINS, cache: Some(CACHE) };
        finish(run(benches::M4F, benches::M4F_SIZE.1, b))
    }

    /// Cortex-M0 (timed on QEMU microbit).
    #[cfg(not(target_abi = "eabihf"))]
    #[entry]
    fn main() -> ! {
        // The CRC firmware's buffers; no primitive storage (2D scenes are streamed).
        static mut PRIMS: heapless::Vec<microraster::Primitive<Rgb565, S>, 0> = heapless::Vec::new();
        static mut BAND: Band<Rgb565, { benches::M0_SIZE.0 }, { benches::M0_BAND }> = Band::new(BACKGROUND);
        static mut DEPTH: DepthBand<Depth16, { benches::M0_SIZE.0 }, { benches::M0_BAND }> =
            DepthBand::zeroed();
        static mut BINS: heapless::Vec<ScreenTriangle<S>, { benches::BAND_BINS }> = heapless::Vec::new();
        let b = Buffers { prims: PRIMS, band: BAND, depth: DEPTH, bins: BINS, cache: None };
        finish(run(benches::M0, benches::M0_SIZE.1, b))
    }

    fn run<const W: usize, const H: usize, const N: usize, const P: usize>(
        list: &[Bench],
        height: u32,
        mut b: Buffers<'_, W, H, N, P>,
    ) -> Result<(), Fail> {
        clock::start();
        calibrate()?;
        for (i, bench) in list.iter().enumerate() {
            benches::prepare(bench.work, height, &mut b)?;
            let mut sink = Sink::new(W as u32, height, Mode::Consume);
            stack::paint();
            let t = clock::Span::start();
            let result = benches::frame(black_box(bench.work), height, BACKGROUND, &mut b, &mut sink);
            let ticks = t.stop().ok_or(Fail::Timer)?;
            black_box(&result);
            let (stack, _) = stack::high_water();
            result?;
            let mut crc = Sink::new(W as u32, height, Mode::Crc);
            benches::frame(bench.work, height, BACKGROUND, &mut b, &mut crc)?;
            hprintln!(
                "bench {} ticks={} instr={} stack={} crc={:08x}",
                i,
                ticks,
                clock::instructions(ticks),
                stack,
                crc.crc()
            );
        }
        Ok(())
    }

    /// Exactly `2 n` instructions (`n >= 1`): `subs` and `bne`, `n` times.
    #[inline(always)]
    fn spin(n: u32) {
        // SAFETY: register arithmetic and a local branch only.
        unsafe {
            core::arch::asm!(
                "2:",
                "subs {0}, #1",
                "bne 2b",
                inout(reg) n => _,
                options(nomem, nostack),
            );
        }
    }

    /// Times loops of known instruction counts and checks that the timer
    /// ticks once per [`clock::PER_TICK`] instructions (to 1 part in 10^4);
    /// prints the measured ratio and the measurement's own overhead.
    fn calibrate() -> Result<(), Fail> {
        const N1: u32 = 100_000;
        const N2: u32 = 5_100_000;
        let time = |n: u32| {
            let t = clock::Span::start();
            spin(n);
            t.stop()
        };
        let empty = {
            let t = clock::Span::start();
            t.stop()
        };
        let (t1, t2, empty) = match (time(N1), time(N2), empty) {
            (Some(a), Some(b), Some(e)) => (a, b, e),
            _ => return Err(Fail::Timer),
        };
        // Instructions per tick, in thousandths.
        let ratio = 2_000 * u64::from(N2 - N1) / (t2 - t1).max(1);
        let (num, den) = clock::PER_TICK;
        let nominal = 1_000 * num / den;
        hprintln!(
            "# timer: {}; {} instructions in {} ticks: {}.{:03} instructions per tick (nominal {}.{:03}); \
             an empty timed region reads {} ticks; resolution 1 tick",
            clock::NAME,
            2 * u64::from(N2 - N1),
            t2 - t1,
            ratio / 1000,
            ratio % 1000,
            nominal / 1000,
            nominal % 1000,
            empty,
        );
        if ratio.abs_diff(nominal) * 10_000 > nominal {
            return Err(Fail::Calibration);
        }
        Ok(())
    }

    /// Why the benchmark failed.
    enum Fail {
        Render(Error),
        /// A timed region too long for the timer.
        Timer,
        /// The timer does not tick once per [`clock::PER_TICK`] instructions.
        Calibration,
    }

    impl From<Error> for Fail {
        fn from(e: Error) -> Self {
            Fail::Render(e)
        }
    }

    /// Exits through semihosting: success, or failure with the error.
    fn finish(result: Result<(), Fail>) -> ! {
        let code = match result {
            Ok(()) => debug::EXIT_SUCCESS,
            Err(e) => {
                match e {
                    Fail::Render(e) => hprintln!("error: {}", e),
                    Fail::Timer => hprintln!("error: a timed region is too long for {}", clock::NAME),
                    Fail::Calibration => hprintln!(
                        "error: the timer does not tick once per {}/{} instructions",
                        clock::PER_TICK.0,
                        clock::PER_TICK.1
                    ),
                }
                debug::EXIT_FAILURE
            }
        };
        debug::exit(code);
        #[allow(clippy::empty_loop)]
        loop {}
    }

    /// The instruction-counting timer.
    mod clock {
        use super::{Ordering, compiler_fence};

        /// Instructions per tick, `(numerator, denominator)`.
        #[cfg(target_abi = "eabihf")]
        pub const PER_TICK: (u64, u64) = (40, 1);
        #[cfg(not(target_abi = "eabihf"))]
        pub const PER_TICK: (u64, u64) = (125, 2);

        /// Instructions in `ticks` ticks.
        pub fn instructions(ticks: u64) -> u64 {
            ticks * PER_TICK.0 / PER_TICK.1
        }

        /// A timed region.
        pub struct Span(u32);

        impl Span {
            /// Starts timing.
            #[inline(always)]
            pub fn start() -> Span {
                compiler_fence(Ordering::SeqCst);
                let s = Span(begin());
                compiler_fence(Ordering::SeqCst);
                s
            }

            /// Ticks since [`Span::start`]; `None` if the timer cannot tell.
            #[inline(always)]
            pub fn stop(self) -> Option<u64> {
                compiler_fence(Ordering::SeqCst);
                let t = end(self.0);
                compiler_fence(Ordering::SeqCst);
                t
            }
        }

        // Cortex-M4F: SysTick on the core clock (QEMU mps2-an386: 25 MHz,
        // so one tick per 40 instructions under `-icount shift=0`). It counts
        // down from 2^24 − 1; a region that wraps it (more than 671 million
        // instructions) is reported as unmeasurable through COUNTFLAG.
        #[cfg(target_abi = "eabihf")]
        pub const NAME: &str = "SysTick, core clock (QEMU mps2-an386, 25 MHz), 24 bits";
        #[cfg(target_abi = "eabihf")]
        const SYST_CSR: *mut u32 = 0xE000_E010 as *mut u32;
        #[cfg(target_abi = "eabihf")]
        const SYST_RVR: *mut u32 = 0xE000_E014 as *mut u32;
        #[cfg(target_abi = "eabihf")]
        const SYST_CVR: *mut u32 = 0xE000_E018 as *mut u32;

        /// Starts the timer.
        #[cfg(target_abi = "eabihf")]
        pub fn start() {
            // SAFETY: SysTick registers; no interrupt (TICKINT clear).
            unsafe {
                SYST_CSR.write_volatile(0);
                SYST_RVR.write_volatile(0x00FF_FFFF);
                SYST_CVR.write_volatile(0);
                SYST_CSR.write_volatile(0b101); // ENABLE, CLKSOURCE = core clock
                // The counter loads the reload value on its first tick.
                while SYST_CVR.read_volatile() == 0 {}
            }
        }

        #[cfg(target_abi = "eabihf")]
        #[inline(always)]
        fn begin() -> u32 {
            // SAFETY: SysTick registers. Reading CSR clears COUNTFLAG.
            unsafe {
                SYST_CSR.read_volatile();
                SYST_CVR.read_volatile()
            }
        }

        #[cfg(target_abi = "eabihf")]
        #[inline(always)]
        fn end(start: u32) -> Option<u64> {
            // SAFETY: SysTick registers.
            let (now, csr) = unsafe { (SYST_CVR.read_volatile(), SYST_CSR.read_volatile()) };
            let wrapped = csr & (1 << 16) != 0;
            (!wrapped && now <= start).then(|| u64::from(start - now))
        }

        // Cortex-M0: the nRF51's TIMER0 (QEMU microbit) at 16 MHz, 32 bits:
        // one tick per 62.5 instructions, wraps after 268 · 10^9.
        #[cfg(not(target_abi = "eabihf"))]
        pub const NAME: &str = "nRF51 TIMER0 (QEMU microbit, 16 MHz), 32 bits";
        #[cfg(not(target_abi = "eabihf"))]
        const TIMER0: usize = 0x4000_8000;

        #[cfg(not(target_abi = "eabihf"))]
        fn reg(offset: usize) -> *mut u32 {
            (TIMER0 + offset) as *mut u32
        }

        /// Starts the timer.
        #[cfg(not(target_abi = "eabihf"))]
        pub fn start() {
            // SAFETY: TIMER0 registers.
            unsafe {
                reg(0x004).write_volatile(1); // TASKS_STOP
                reg(0x504).write_volatile(0); // MODE: timer
                reg(0x508).write_volatile(3); // BITMODE: 32 bits
                reg(0x510).write_volatile(0); // PRESCALER: 16 MHz
                reg(0x00C).write_volatile(1); // TASKS_CLEAR
                reg(0x000).write_volatile(1); // TASKS_START
            }
        }

        #[cfg(not(target_abi = "eabihf"))]
        #[inline(always)]
        fn now() -> u32 {
            // SAFETY: TIMER0 registers: capture into CC[0], read it.
            unsafe {
                reg(0x040).write_volatile(1); // TASKS_CAPTURE[0]
                reg(0x540).read_volatile() // CC[0]
            }
        }

        #[cfg(not(target_abi = "eabihf"))]
        #[inline(always)]
        fn begin() -> u32 {
            now()
        }

        #[cfg(not(target_abi = "eabihf"))]
        #[inline(always)]
        fn end(start: u32) -> Option<u64> {
            Some(u64::from(now().wrapping_sub(start)))
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let result = match args.as_slice() {
        [t @ ("m4f" | "m0")] => table::host(t).map(|recs| {
            for r in recs {
                println!("{r}");
            }
        }),
        ["table", file] => std::fs::read_to_string(file)
            .map_err(|e| format!("{file}: {e}"))
            .and_then(|input| table::table(&input))
            .map(|t| print!("{t}")),
        _ => Err("usage: fw_bench m4f|m0 | fw_bench table FILE".to_string()),
    };
    if let Err(e) = result {
        eprintln!("fw_bench: {e}");
        std::process::exit(1);
    }
}
