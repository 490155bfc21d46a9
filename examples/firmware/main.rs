//! Firmware: renders the standard 2D and 3D scenes band by band into a
//! display that only checksums each band, and prints one line per band,
//! `scene band y0 rows crc32 pixels`, then exits.
//!
//! * On a bare-metal Cortex-M target (`target_os = "none"`) it is a
//!   `#![no_std]` `#![no_main]` program: output and exit status go through
//!   semihosting (QEMU, or a debug probe), and a panic exits with failure.
//!   thumbv7em-none-eabihf (Cortex-M4F) runs the `workload::m4f`
//!   configuration and the fragment-stage scene (`fragment`: textures,
//!   per-pixel lighting, translucency, 2 × 2 supersampling),
//!   thumbv6m-none-eabi (Cortex-M0) `workload::m0`.
//! * On the host it prints the same lines for `m4f`, `m0` or (no argument)
//!   both: the reference the QEMU runs must match.
//!
//! `bash scripts/firmware.sh check` builds it for both targets, runs it
//! under QEMU and diffs the lines with the host's.
#![cfg_attr(target_os = "none", no_std, no_main)]

// Each target runs one of the two configurations.
#[cfg_attr(target_os = "none", allow(dead_code))]
mod workload;

// The Cortex-M4F's fragment-stage scene.
#[cfg_attr(not(target_abi = "eabihf"), allow(dead_code))]
mod fragment;

#[cfg(target_os = "none")]
#[path = "stack.rs"]
mod stack;

#[cfg(target_os = "none")]
mod firmware {
    #[cfg(target_abi = "eabihf")]
    use crate::fragment;
    use crate::stack;
    use crate::workload::*;
    use cortex_m_rt::entry;
    use cortex_m_semihosting::{debug, hprintln};
    use embedded_graphics_core::pixelcolor::Rgb565;
    use microraster::Band;
    #[cfg(target_abi = "eabihf")]
    use microraster::Primitive;
    use microraster::depth::{Depth16, DepthBand};
    use microraster::raster3d::ScreenTriangle;
    #[cfg(target_abi = "eabihf")]
    use microraster_scenes::{scenes, scenes3d};
    use panic_semihosting as _;

    fn print(r: &Record) {
        hprintln!("{}", r);
    }

    /// Cortex-M4F: the [`m4f`] configuration.
    #[cfg(target_abi = "eabihf")]
    #[entry]
    fn main() -> ! {
        // cortex-m-rt turns these into `&'static mut` references. Each buffer
        // is its own static, so the size tool shows them; all are zeroed, so
        // they cost no flash (.bss: the renderer clears the depth band to far
        // at every band anyway).
        static mut PRIMS: heapless::Vec<Primitive<Rgb565, S>, { scenes::MIXED_LEN }> = heapless::Vec::new();
        static mut BAND: Band<Rgb565, { M4F_SIZE.0 }, M4F_BAND> = Band::new(BACKGROUND);
        static mut DEPTH: DepthBand<Depth16, { M4F_SIZE.0 }, M4F_BAND> = DepthBand::zeroed();
        static mut BINS: heapless::Vec<ScreenTriangle<S>, { scenes3d::BINS }> = heapless::Vec::new();
        // The fragment-stage scene's own buffers (fragment.rs).
        static mut SAMPLES: Band<Rgb565, { fragment::SW }, { fragment::SH }> = Band::new(BACKGROUND);
        static mut FDEPTH: DepthBand<Depth16, { fragment::SW }, { fragment::SH }> = DepthBand::zeroed();
        static mut FOUT: Band<Rgb565, { M4F_SIZE.0 }, { fragment::ROWS }> = Band::new(BACKGROUND);
        static mut FBINS: fragment::Bins = fragment::Bins::new();
        stack::paint();
        let result = m4f(M4fBuffers { prims: PRIMS, band: BAND, depth: DEPTH, bins: BINS }, &mut print)
            .and_then(|()| {
                let b = fragment::FragBuffers { samples: SAMPLES, depth: FDEPTH, out: FOUT, bins: FBINS };
                fragment::fragment(fragment::NAME, b, &mut print)
            });
        finish(result)
    }

    /// Cortex-M0: the [`m0`] configuration.
    #[cfg(not(target_abi = "eabihf"))]
    #[entry]
    fn main() -> ! {
        static mut BAND: Band<Rgb565, { M0_SIZE.0 }, M0_BAND> = Band::new(BACKGROUND);
        static mut DEPTH: DepthBand<Depth16, { M0_SIZE.0 }, M0_BAND> = DepthBand::zeroed();
        static mut BINS: heapless::Vec<ScreenTriangle<S>, BAND_BINS> = heapless::Vec::new();
        stack::paint();
        finish(m0(M0Buffers { band: BAND, depth: DEPTH, bins: BINS }, &mut print))
    }

    /// Exits through semihosting: success, or failure with the error. First
    /// prints the stack's high-water mark as a `#` line (not a record: the
    /// host has no such line, and the comparison skips it).
    fn finish(result: Result<(), microraster::Error>) -> ! {
        let (used, room) = stack::high_water();
        hprintln!("# stack: {} of {} bytes used", used, room);
        let code = match (result, stack::check((used, room))) {
            (Ok(()), Ok(())) => debug::EXIT_SUCCESS,
            (Err(e), _) => {
                hprintln!("error: {}", e);
                debug::EXIT_FAILURE
            }
            (Ok(()), Err((used, room))) => {
                hprintln!(
                    "error: stack {} of {} bytes used, less than {} to spare",
                    used,
                    room,
                    stack::MARGIN
                );
                debug::EXIT_FAILURE
            }
        };
        debug::exit(code);
        #[allow(clippy::empty_loop)]
        loop {}
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    let mut print = |r: &workload::Record| println!("{r}");
    let result = match which.as_str() {
        "m4f" => workload::m4f_host(&mut print).and_then(|()| fragment::fragment_host(&mut print)),
        "m0" => workload::m0_host(&mut print),
        "" => workload::m4f_host(&mut print)
            .and_then(|()| fragment::fragment_host(&mut print))
            .and_then(|()| workload::m0_host(&mut print)),
        other => {
            eprintln!("usage: firmware [m4f|m0] (got {other:?})");
            std::process::exit(2);
        }
    };
    if let Err(e) = result {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
