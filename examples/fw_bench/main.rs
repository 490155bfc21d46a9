//! Firmware benchmark: instructions per frame of each configuration in
//! `benches::M4F` / `benches::M0`, measured under QEMU's instruction
//! counting, with the stack high-water mark of each frame.
//!
//! `bash scripts/firmware.sh table` builds it for both targets, runs it under
//! QEMU with `-icount shift=0` (virtual time advances 1 ns per executed
//! instruction, so a timer counts instructions) and hands its output to the
//! host side of this example, which prints the table of docs/firmware.md.
//!
//! * Target (`target_os = "none"`): for each configuration, one untimed
//!   preparation (a 2D scene collected into RAM), one untimed frame (the
//!   timed one is then a steady frame), the stack painted, one
//!   timed frame into a display that only reads each pixel, the stack
//!   scanned (the run fails if the frame left less than `stack::MARGIN`
//!   bytes of room), then one more frame into a CRC display. Prints
//!   `bench INDEX ticks=T instr=I stack=B crc=C` per configuration and `#`
//!   notes (the timer's calibration). Timers: Cortex-M4F on QEMU
//!   `mps2-an386`, SysTick on the 25 MHz core clock, 40 instructions per
//!   tick; Cortex-M0 on QEMU `microbit`, the nRF51's TIMER0 at 16 MHz,
//!   62.5 instructions per tick. A loop of a known instruction count
//!   calibrates the ratio first, and the run fails if it is off.
//! * Host: `fw_bench m4f|m0` prints each configuration's triangles, lines,
//!   covered pixels and frame CRC; `fw_bench table FILE` reads the target
//!   runs and sizes that `scripts/firmware.sh table` collected into FILE,
//!   checks every frame CRC against the host's, and prints the table;
//!   `fw_bench table FILE TSV_OUT [DOC]` also writes its rows as
//!   tab-separated data (`docs/data/fw-bench.tsv`, which the report reads)
//!   and the table into docs/firmware.md (between its `fw-table:begin/end` markers).
#![cfg_attr(target_os = "none", no_std, no_main)]

// The CRC firmware's workload: its constants, CRC and buffers sizes.
#[allow(dead_code)]
#[path = "../firmware/workload.rs"]
mod workload;

#[cfg_attr(target_os = "none", allow(dead_code))]
mod benches;

mod sink;

#[cfg(target_os = "none")]
mod clock;

#[cfg(target_os = "none")]
#[path = "../firmware/stack.rs"]
mod stack;

#[cfg(not(target_os = "none"))]
mod table;

#[cfg(target_os = "none")]
mod firmware {
    use crate::benches::{self, BACKGROUND, Bench, Buffers, Mode, Sink};
    use crate::clock::{self, ClockError};
    use crate::stack;
    use crate::workload::S;
    use core::hint::black_box;
    use cortex_m_rt::entry;
    use cortex_m_semihosting::{debug, hprintln};
    use embedded_graphics_core::pixelcolor::Rgb565;
    use microraster::depth::{Depth16, DepthBand};
    #[cfg(target_abi = "eabihf")]
    use microraster::math::Fx;
    #[cfg(target_abi = "eabihf")]
    use microraster::pipeline::ClusterCache;
    use microraster::raster3d::ScreenTriangle;
    use microraster::{Band, Error};
    #[cfg(target_abi = "eabihf")]
    use microraster::{mesh::MAX_MESHLET_VERTICES, pipeline::VertexCache};
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
        static mut CLUSTER: ClusterCache<f32, S> = ClusterCache::new();
        static mut CLUSTER_FX: ClusterCache<Fx, S> = ClusterCache::new();
        static mut CHUNK: VertexCache<f32, S, MAX_MESHLET_VERTICES> = VertexCache::new();
        // Taller bands, for the rows that measure what they buy.
        static mut BAND20: Band<Rgb565, { benches::M4F_SIZE.0 }, { benches::TALL_20 }> =
            Band::new(BACKGROUND);
        static mut DEPTH20: DepthBand<Depth16, { benches::M4F_SIZE.0 }, { benches::TALL_20 }> =
            DepthBand::zeroed();
        static mut BAND32: Band<Rgb565, { benches::M4F_SIZE.0 }, { benches::TALL_32 }> =
            Band::new(BACKGROUND);
        static mut DEPTH32: DepthBand<Depth16, { benches::M4F_SIZE.0 }, { benches::TALL_32 }> =
            DepthBand::zeroed();
        static mut BAND48: Band<Rgb565, { benches::M4F_SIZE.0 }, { benches::TALL_48 }> =
            Band::new(BACKGROUND);
        static mut DEPTH48: DepthBand<Depth16, { benches::M4F_SIZE.0 }, { benches::TALL_48 }> =
            DepthBand::zeroed();
        static mut BAND240: Band<Rgb565, { benches::M4F_SIZE.0 }, { benches::TALL_240 }> =
            Band::new(BACKGROUND);
        static mut DEPTH240: DepthBand<Depth16, { benches::M4F_SIZE.0 }, { benches::TALL_240 }> =
            DepthBand::zeroed();
        // The one-call front, with its own bands and cluster cache.
        static mut VIEW: benches::View<{ benches::M4F_SIZE.0 }, { benches::M4F_BAND }> =
            benches::View::new(BACKGROUND);
        // The knots' frame bins (the full-frame way of `benches::ways`).
        static mut KNOT_BINS: benches::KnotBins = heapless::Vec::new();
        static mut KNOT5K_BINS: benches::Knot5kBins = heapless::Vec::new();
        let cluster = Some((CLUSTER, CLUSTER_FX));
        let tall = Some(benches::Tall {
            band20: BAND20,
            depth20: DEPTH20,
            band32: BAND32,
            depth32: DEPTH32,
            band48: BAND48,
            depth48: DEPTH48,
            band240: BAND240,
            depth240: DEPTH240,
        });
        let (cache, chunk, view, knot_bins) =
            (Some(CACHE), Some(CHUNK), Some(VIEW), Some((KNOT_BINS, KNOT5K_BINS)));
        let b = Buffers {
            prims: PRIMS,
            band: BAND,
            depth: DEPTH,
            bins: BINS,
            cache,
            cluster,
            chunk,
            tall,
            view,
            knot_bins,
        };
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
        let b = Buffers {
            prims: PRIMS,
            band: BAND,
            depth: DEPTH,
            bins: BINS,
            cache: None,
            cluster: None,
            chunk: None,
        };
        finish(run(benches::M0, benches::M0_SIZE.1, b))
    }

    fn run<const W: usize, const H: usize, const N: usize, const P: usize>(
        list: &[Bench],
        height: u32,
        mut b: Buffers<'_, W, H, N, P>,
    ) -> Result<(), Fail> {
        // Profile mode (`firmware.sh profile`): the rows' frames and nothing
        // else, for an instruction log whose counts are the frames'.
        let profile = option_env!("MICRORASTER_FW_PROFILE").is_some();
        if !profile {
            clock::calibrate()?;
        }
        let select = option_env!("MICRORASTER_FW_BENCH");
        for (i, bench) in list.iter().enumerate().filter(|(i, b)| benches::selected(select, *i, b)) {
            benches::prepare(bench.work, height, &mut b)?;
            let mut sink = Sink::new(W as u32, height, Mode::Consume);
            if profile {
                benches::frame(bench.work, height, BACKGROUND, &mut b, &mut sink)?;
                hprintln!("bench {} profiled", i);
                continue;
            }
            // One untimed frame first, so the timed one is a frame of an
            // animation: a cluster cache then holds this row's previous
            // frame, not another row's records (whose capacity made the
            // first row of a new camera read 2 % more), as TGX's count is
            // its steady frame too.
            warm_up(bench, height, &mut b)?;
            stack::paint();
            let t = clock::Span::start();
            let result = benches::frame(black_box(bench.work), height, BACKGROUND, &mut b, &mut sink);
            let ticks = t.stop().ok_or(ClockError::Overflow)?;
            black_box(&result);
            let water = stack::high_water();
            result?;
            stack::check(water).map_err(|(used, room)| Fail::Stack(i, used, room))?;
            let mut crc = Sink::new(W as u32, height, Mode::Crc);
            benches::frame(bench.work, height, BACKGROUND, &mut b, &mut crc)?;
            hprintln!(
                "bench {} ticks={} instr={} stack={} crc={:08x}",
                i,
                ticks,
                clock::instructions(ticks),
                water.0,
                crc.crc()
            );
        }
        Ok(())
    }

    /// One untimed frame of `bench` (apart, so its display's bytes are not
    /// in the stack frame of `run`, whose size every row's stack figure
    /// includes).
    #[inline(never)]
    fn warm_up<const W: usize, const H: usize, const N: usize, const P: usize>(
        bench: &Bench,
        height: u32,
        b: &mut Buffers<'_, W, H, N, P>,
    ) -> Result<(), Error> {
        let mut sink = Sink::new(W as u32, height, Mode::Consume);
        benches::frame(bench.work, height, BACKGROUND, b, &mut sink)
    }

    /// Why the benchmark failed.
    enum Fail {
        Render(Error),
        Clock(ClockError),
        /// Configuration, stack bytes used, bytes of room ([`stack::MARGIN`]).
        Stack(usize, usize, usize),
    }

    impl From<Error> for Fail {
        fn from(e: Error) -> Self {
            Fail::Render(e)
        }
    }

    impl From<ClockError> for Fail {
        fn from(e: ClockError) -> Self {
            Fail::Clock(e)
        }
    }

    /// Exits through semihosting: success, or failure with the error.
    fn finish(result: Result<(), Fail>) -> ! {
        let code = match result {
            Ok(()) => debug::EXIT_SUCCESS,
            Err(e) => {
                match e {
                    Fail::Render(e) => hprintln!("error: {}", e),
                    Fail::Clock(e) => hprintln!("error: {}", e),
                    Fail::Stack(i, used, room) => hprintln!(
                        "error: configuration {}: stack {} of {} bytes used, less than {} to spare",
                        i,
                        used,
                        room,
                        stack::MARGIN
                    ),
                }
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
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let result = match args.as_slice() {
        [t @ ("m4f" | "m0")] => table::host(t).map(|recs| {
            for r in recs {
                println!("{r}");
            }
        }),
        ["table", file, rest @ ..] if rest.len() <= 2 => std::fs::read_to_string(file)
            .map_err(|e| format!("{file}: {e}"))
            .and_then(|input| table::table(&input))
            .and_then(|(t, tsv)| {
                print!("{t}");
                // The same rows for the report (docs/data/fw-bench.tsv).
                if let Some(out) = rest.first() {
                    std::fs::write(out, tsv).map_err(|e| format!("{out}: {e}"))?;
                }
                rest.get(1).map_or(Ok(()), |readme| table::update_readme(readme, &t))
            }),
        _ => Err("usage: fw_bench m4f|m0 | fw_bench table FILE [TSV_OUT [DOC]]".to_string()),
    };
    if let Err(e) = result {
        eprintln!("fw_bench: {e}");
        std::process::exit(1);
    }
}
