//! Cortex-M instruction counts of the speed/accuracy report's configurations
//! (`configs::LIST`, each under its report key), for `docs/data/cortex-m.tsv`.
//!
//! `bash scripts/firmware.sh sweep` builds this for `thumbv7em-none-eabihf`
//! (Cortex-M4F, hardware `f32`) and `thumbv6m-none-eabi` (Cortex-M0: soft
//! float, no 64-bit multiply, no divider), both linked for QEMU's
//! `mps2-an386` (4 MB of RAM: the report's 320 × 240 frame, full-frame bands
//! and a framebuffer fit), runs each under `-icount shift=0` and hands the
//! output to the host side of this example, which checks every frame against
//! the host's and writes the file. QEMU's only Cortex-M0 machine (the
//! micro:bit, 16 KB of RAM) cannot hold these buffers; the mps2-an386's
//! Cortex-M4 runs the `thumbv6m` code instruction for instruction, so the
//! counts are the Cortex-M0's (instructions, not cycles).
//!
//! * Target: for each configuration, one frame timed with SysTick
//!   (`examples/fw_bench/clock.rs`, calibrated first), then the CRC-32 of the
//!   framebuffer; prints `sweep KEY instr=I crc=C`.
//! * Host: `fw_sweep` prints `sweep KEY crc=C covered=N` (same code, same
//!   frames); `fw_sweep tsv OUT M4F_LOG M0_LOG` checks both target logs
//!   against the host's frames and writes `OUT`.
#![cfg_attr(target_os = "none", no_std, no_main)]

mod configs;
mod fragment;
mod frame;
// The 20k-triangle knot (460 KB of flash: the mps2-an386 has 4 MB).
#[path = "../common/knot_mesh.rs"]
mod knot_mesh;

#[cfg(target_os = "none")]
#[path = "../fw_bench/clock.rs"]
mod clock;

#[cfg(not(target_os = "none"))]
mod host;

// CRC-32 (zlib's) of the frames.
#[allow(dead_code)]
#[path = "../firmware/workload.rs"]
mod workload;

/// CRC-32 of the framebuffer's pixels (little-endian `Rgb565` words), as the
/// firmware's displays compute it.
fn crc(fb: &frame::FrameBuffer) -> u32 {
    use embedded_graphics_core::prelude::IntoStorage;
    let mut crc = workload::Crc32::new();
    for c in fb.pixels() {
        crc.update(&c.into_storage().to_le_bytes());
    }
    crc.value()
}

#[cfg(target_os = "none")]
mod firmware {
    use crate::clock::{self, ClockError, Span};
    use crate::configs::{Meter, all};
    use crate::frame::FrameBuffer;
    use cortex_m_rt::entry;
    use cortex_m_semihosting::{debug, hprintln};
    use microraster::Error;
    use panic_semihosting as _;

    /// Times the part between [`Meter::start`] and [`Meter::stop`].
    struct Timed {
        span: Option<Span>,
        ticks: Option<u64>,
    }

    impl Meter for Timed {
        fn start(&mut self) {
            self.span = Some(Span::start());
        }

        fn stop(&mut self) {
            self.ticks = self.span.take().and_then(Span::stop);
        }
    }

    #[entry]
    fn main() -> ! {
        // All bits zero: in .bss.
        static mut FB: FrameBuffer = FrameBuffer::new();
        let code = match run(FB) {
            Ok(()) => debug::EXIT_SUCCESS,
            Err(Fail::Render(key, e)) => {
                hprintln!("error: {}: {}", key, e);
                debug::EXIT_FAILURE
            }
            Err(Fail::Clock(key, e)) => {
                hprintln!("error: {}: {}", key, e);
                debug::EXIT_FAILURE
            }
        };
        debug::exit(code);
        #[allow(clippy::empty_loop)]
        loop {}
    }

    enum Fail {
        Render(&'static str, Error),
        Clock(&'static str, ClockError),
    }

    fn run(fb: &mut FrameBuffer) -> Result<(), Fail> {
        clock::calibrate().map_err(|e| Fail::Clock("calibration", e))?;
        // MICRORASTER_FW_SWEEP_ONLY=KEY (at build time): that configuration
        // alone, to count or profile one row.
        for c in all().filter(|c| option_env!("MICRORASTER_FW_SWEEP_ONLY").is_none_or(|k| c.key == k)) {
            let mut m = Timed { span: None, ticks: None };
            (c.run)(&mut m, fb).map_err(|e| Fail::Render(c.key, e))?;
            let ticks = m.ticks.ok_or(Fail::Clock(c.key, ClockError::Overflow))?;
            hprintln!("sweep {} instr={} crc={:08x}", c.key, clock::instructions(ticks), crate::crc(fb));
        }
        Ok(())
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let result = match args.as_slice() {
        [] => host::frames().map(|frames| {
            for f in frames {
                println!("sweep {} crc={:08x} covered={}", f.key, f.crc, f.covered);
            }
        }),
        ["tsv", out, m4f, m0] => host::write_tsv(out, m4f, m0),
        _ => Err("usage: fw_sweep | fw_sweep tsv OUT M4F_LOG M0_LOG".to_string()),
    };
    if let Err(e) = result {
        eprintln!("fw_sweep: {e}");
        std::process::exit(1);
    }
}
