//! The display link's numbers: bytes sent per frame with and without dirty
//! bands, a frame-time model of the double-banded loop against the blocking
//! one, and the host speed-up of threaded bands.
//!
//! `cargo run --release --example link` prints the tables;
//! `cargo run --release --example link -- README.md` also replaces the text
//! between the `<!-- link:begin -->` and `<!-- link:end -->` markers of that
//! file with them.
//!
//! * Bytes: the standard 3D scene spinning (angle 0.05 rad a frame) for 60
//!   frames at 320 × 240 Rgb565, 16-row bands, 2 bytes a pixel on the wire.
//! * Frame time: a model. Instructions per frame of the same scene on the
//!   Cortex-M4F come from `docs/data/cortex-m.tsv` (QEMU, `bash
//!   scripts/firmware.sh sweep`), split evenly over the 15 bands after the
//!   vertex stage; one instruction per cycle at 168 MHz (STM32F405).
//! * Speed-up: wall time of the 60 frames drawn by `render_3d` on one thread
//!   and by `render_3d_threads` on two, best of 5 runs each, in the same run.

use std::time::Instant;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
use microraster::render::DirtyBands;
use microraster::scenes3d::{BINS, Scene3d};
use microraster::{Band, Renderer};

const W: usize = 320;
const HEIGHT: u32 = 240;
const BAND: usize = 16;
const BANDS: usize = HEIGHT as usize / BAND;
const FRAMES: usize = 60;
const BG: Rgb565 = Rgb565::BLACK;
const CPU_HZ: f64 = 168e6;
const KEY_FRAME: &str = "mesh3d/f32/D16/persp/band16/S4";
const KEY_VERTEX: &str = "mesh3d/vertex/f32";

fn bins(angle: f32) -> heapless::Vec<ScreenTriangle<4>, BINS> {
    let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, HEIGHT).expect("scene");
    let mut bins = heapless::Vec::new();
    Scene3d.draw::<f32, Rgb565, 4, BINS>(&pipeline, angle, &mut bins).expect("scene");
    bins
}

fn angle(frame: usize) -> f32 {
    frame as f32 * 0.05
}

/// Bytes sent per frame, all bands and with dirty bands.
fn bytes_table(frames: &[heapless::Vec<ScreenTriangle<4>, BINS>]) -> String {
    let mut bands = [const { Band::<Rgb565, W, BAND>::new(BG) }; 2];
    let mut depth = DepthBand::<Depth16, W, BAND>::new();
    let mut sink = DirtyBands::<(), BANDS>::new(());
    let mut per_frame = Vec::new();
    for tris in frames {
        let before = sink.sent_pixels();
        Renderer::new(HEIGHT, BG)
            .render_3d_linked(
                tris,
                &mut bands,
                &mut depth,
                DepthState::LESS_WRITE,
                PerspectiveCorrect,
                &mut sink,
            )
            .expect("frame");
        per_frame.push((sink.sent_pixels() - before) * 2);
    }
    let full = (W * HEIGHT as usize * 2) as u64;
    let later = &per_frame[1..];
    let mean = later.iter().sum::<u64>() as f64 / later.len() as f64;
    let (min, max) = (later.iter().min().copied().unwrap_or(0), later.iter().max().copied().unwrap_or(0));
    let total: u64 = per_frame.iter().sum();
    let mut s = String::new();
    s += "| 60 frames, spinning 3D scene, 320×240 Rgb565, 16-row bands | bytes per frame (frames 2–60: mean, min, max) | bytes, all 60 frames |\n|---|---|---|\n";
    s += &format!("| every band sent | {full} | {} |\n", full * FRAMES as u64);
    s += &format!(
        "| dirty bands (`DirtyBands`) | {mean:.0} ({min} – {max}): {:.1} % | {total}: {:.1} % |\n",
        100.0 * mean / full as f64,
        100.0 * total as f64 / (full * FRAMES as u64) as f64
    );
    s
}

/// Instructions per frame of `key` on the M4F from docs/data/cortex-m.tsv.
fn m4f_count(tsv: &str, key: &str) -> Option<f64> {
    tsv.lines().find_map(|l| {
        let mut f = l.split('\t');
        (f.next() == Some("m4f") && f.next() == Some(key)).then(|| f.next()?.parse().ok())?
    })
}

fn model_table() -> String {
    let tsv = std::fs::read_to_string("docs/data/cortex-m.tsv").expect("docs/data/cortex-m.tsv");
    let (frame, vertex) =
        (m4f_count(&tsv, KEY_FRAME).expect(KEY_FRAME), m4f_count(&tsv, KEY_VERTEX).expect(KEY_VERTEX));
    let n = BANDS as f64;
    let v = vertex / CPU_HZ;
    let r = (frame - vertex) / n / CPU_HZ;
    let bytes = (W * BAND * 2) as f64;
    let mut s = format!(
        "Model: v = {vertex:.0} vertex-stage instructions, r = ({frame:.0} − {vertex:.0}) / {BANDS} instructions per band, \
         at 1 instruction per cycle and 168 MHz: v = {:.2} ms, r = {:.3} ms; a band is {bytes:.0} bytes, \
         s = 8 · {bytes:.0} / f_SPI. Blocking: T = v + n·(r + s). Double-banded: T = v + r + (n − 1)·max(r, s) + s, n = {BANDS}.\n\n",
        v * 1e3,
        r * 1e3
    );
    s += "| SPI clock | s per band (ms) | blocking frame (ms) | double-banded frame (ms) | ratio |\n|---|---|---|---|---|\n";
    for mhz in [20.0, 40.0, 62.5] {
        let send = 8.0 * bytes / (mhz * 1e6);
        let blocking = v + n * (r + send);
        let double = v + r + (n - 1.0) * r.max(send) + send;
        s += &format!(
            "| {mhz} MHz | {:.3} | {:.2} | {:.2} | {:.2} |\n",
            send * 1e3,
            blocking * 1e3,
            double * 1e3,
            blocking / double
        );
    }
    s
}

/// Wall time of the frames on one thread and on two, best of 5.
fn speedup_table(frames: &[heapless::Vec<ScreenTriangle<4>, BINS>]) -> String {
    struct Null;
    impl OriginDimensions for Null {
        fn size(&self) -> Size {
            Size::new(W as u32, HEIGHT)
        }
    }
    impl DrawTarget for Null {
        type Color = Rgb565;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
            pixels.into_iter().for_each(|p| {
                std::hint::black_box(p);
            });
            Ok(())
        }
        fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
            &mut self,
            _: &Rectangle,
            c: I,
        ) -> Result<(), Self::Error> {
            std::hint::black_box(c.into_iter().fold(0u32, |a, p| a ^ u32::from(p.into_storage())));
            Ok(())
        }
    }
    let r = Renderer::new(HEIGHT, BG);
    let best = |f: &mut dyn FnMut()| {
        (0..5)
            .map(|_| {
                let t = Instant::now();
                f();
                t.elapsed().as_secs_f64()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let one = best(&mut || {
        let (mut band, mut depth) = (Band::<Rgb565, W, BAND>::new(BG), DepthBand::<Depth16, W, BAND>::new());
        for tris in frames {
            r.render_3d::<_, _, PerspectiveCorrect, 4, W, BAND>(
                tris,
                &mut band,
                &mut depth,
                DepthState::LESS_WRITE,
                &mut Null,
            )
            .expect("frame");
        }
    });
    let two = best(&mut || {
        let mut bands = [const { Band::<Rgb565, W, BAND>::new(BG) }; 2];
        let mut depth = [const { DepthBand::<Depth16, W, BAND>::zeroed() }; 2];
        for tris in frames {
            r.render_3d_threads(
                tris,
                &mut bands,
                &mut depth,
                DepthState::LESS_WRITE,
                PerspectiveCorrect,
                &mut Null,
            )
            .expect("frame");
        }
    });
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!(
        "| host, {cores} cores reported, 60 frames (bins ready) | one thread `render_3d` (ms) | two threads `render_3d_threads` (ms) | speed-up |\n|---|---|---|---|\n\
         | best of 5 | {:.1} | {:.1} | {:.2}× |\n",
        one * 1e3,
        two * 1e3,
        one / two
    )
}

fn main() {
    let frames: Vec<_> = (0..FRAMES).map(|f| bins(angle(f))).collect();
    let text = format!(
        "Written by `cargo run --release --example link -- README.md`.\n\n{}\n{}\n{}",
        bytes_table(&frames),
        model_table(),
        speedup_table(&frames)
    );
    print!("{text}");
    if let Some(path) = std::env::args().nth(1) {
        let old = std::fs::read_to_string(&path).expect("readable file");
        let (begin, end) = ("<!-- link:begin -->\n", "<!-- link:end -->");
        let (Some(a), Some(b)) = (old.find(begin), old.find(end)) else {
            panic!("{path} has no {begin:?} … {end:?} markers");
        };
        let new = format!("{}{begin}{text}{}", &old[..a], &old[b..]);
        std::fs::write(&path, new).expect("writable file");
    }
}
