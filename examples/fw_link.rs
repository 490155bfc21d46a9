//! Cortex-M4F instructions per band of the standard 3D scene, for the
//! display link's frame-time model (`examples/link.rs`).
//!
//! `bash scripts/firmware.sh link` builds this for `thumbv7em-none-eabihf`
//! linked for QEMU's `mps2-an386`, runs it under `-icount shift=0` (SysTick
//! counts instructions: `examples/fw_bench/clock.rs`, calibrated first) and
//! writes its records to `docs/data/link-m4f.tsv`. For each of [`ANGLES`]
//! the 320 × 240 scene (f32 vertex stage, 16-bit depth, perspective-correct,
//! 16-row bands, 4 subpixel bits) is drawn by `render_linked` into a sink
//! that reads the timer at every band it is handed: the instructions from
//! one band's hand-over to the next are that band's rendering.
//! Records: `vertex FRAME INSTR` and `band FRAME INDEX INSTR`.
//!
//! On the host it prints what it is.
#![cfg_attr(target_os = "none", no_std, no_main)]

/// Scene angles (rad) of the measured frames: a quarter turn in eight steps.
#[allow(dead_code)]
const ANGLES: [f32; 8] = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4];

#[cfg(target_os = "none")]
#[path = "fw_bench/clock.rs"]
mod clock;

#[cfg(target_os = "none")]
mod firmware {
    use crate::clock::{self, Span};
    use cortex_m_rt::entry;
    use cortex_m_semihosting::{debug, hprintln};
    use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
    use microraster::depth::{Depth16, DepthBand, DepthState};
    use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
    use microraster::render::{BandSink, Lent, Triangles3d};
    use microraster::{Band, Renderer};
    use microraster_scenes::scenes3d::{BINS, Scene3d};
    use panic_semihosting as _;

    const W: usize = 320;
    const H: u32 = 240;
    const BAND: usize = 16;
    const BANDS: usize = H as usize / BAND;

    /// Reads the timer at every band: band k's rendering ends where it is
    /// handed over, and band k + 1's starts there.
    struct Stopwatch {
        span: Option<Span>,
        instr: [Option<u64>; BANDS],
    }

    impl<'a> BandSink<'a, Rgb565, W> for Stopwatch {
        type Error = ();

        fn submit(&mut self, band: Lent<'a, Rgb565, W>) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
            let ticks = self.span.take().and_then(Span::stop);
            if let Some(slot) = self.instr.get_mut(band.index()) {
                *slot = ticks.map(clock::instructions);
            }
            self.span = Some(Span::start());
            Ok(Some(band))
        }
    }

    #[entry]
    fn main() -> ! {
        // .bss: zero-initialised.
        static mut BINS_BUF: heapless::Vec<ScreenTriangle<4>, BINS> = heapless::Vec::new();
        static mut BANDS_BUF: [Band<Rgb565, W, BAND>; 2] = [const { Band::new(Rgb565::BLACK) }; 2];
        static mut DEPTH: DepthBand<Depth16, W, BAND> = DepthBand::zeroed();
        let ok = run(BINS_BUF, BANDS_BUF, DEPTH).is_some();
        debug::exit(if ok { debug::EXIT_SUCCESS } else { debug::EXIT_FAILURE });
        #[allow(clippy::empty_loop)]
        loop {}
    }

    fn run(
        bins: &mut heapless::Vec<ScreenTriangle<4>, BINS>,
        bands: &mut [Band<Rgb565, W, BAND>; 2],
        depth: &mut DepthBand<Depth16, W, BAND>,
    ) -> Option<()> {
        clock::calibrate().ok()?;
        let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, H).ok()?;
        let renderer = Renderer::new(H, Rgb565::BLACK);
        for (frame, &angle) in crate::ANGLES.iter().enumerate() {
            bins.clear();
            let span = Span::start();
            Scene3d.draw::<f32, Rgb565, 4, BINS>(&pipeline, angle, bins).ok()?;
            let vertex = clock::instructions(span.stop()?);
            hprintln!("vertex {} {}", frame, vertex);
            let mut sink = Stopwatch { span: Some(Span::start()), instr: [None; BANDS] };
            renderer
                .render_linked(
                    Triangles3d::new(bins, depth, DepthState::LESS_WRITE, PerspectiveCorrect),
                    bands,
                    &mut sink,
                )
                .ok()?;
            for (band, instr) in sink.instr.iter().enumerate() {
                hprintln!("band {} {} {}", frame, band, (*instr)?);
            }
        }
        Some(())
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    println!("fw_link: Cortex-M4F instructions per band; run it with `bash scripts/firmware.sh link`");
}
