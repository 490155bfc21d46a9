//! The display link's numbers: bytes sent per frame with and without dirty
//! bands, a frame-time model of the double-banded loop against the blocking
//! one, and the host speed-up of threaded bands.
//!
//! `cargo run --release --example link` prints the tables;
//! `cargo run --release --example link -- docs/link.md` also replaces the text
//! between the `<!-- link:begin -->` and `<!-- link:end -->` markers of that
//! file with them.
//!
//! * Bytes: 60 frames at 320 × 240 Rgb565, 16-row bands, 2 bytes a pixel on
//!   the wire, of the standard 3D scene spinning (angle 0.05 rad a frame) and
//!   of the car dashboard while driving (`examples/common/dashboard_live.rs`:
//!   needle and speed readout follow 64 → 88 km/h, 15 frames at 88, then
//!   down to 68). Each frame is sent by the plain band loop (every band) and
//!   by the double-banded loop through `DirtyBands` into a second display;
//!   the example asserts after every frame that both displays are the same.
//! * Frame time: a model. Instructions of the same scene on the Cortex-M4F,
//!   the vertex stage and each band apart, come from `docs/data/link-m4f.tsv`
//!   (QEMU, `bash scripts/firmware.sh link`, examples/fw_link.rs); one
//!   instruction per cycle at 168 MHz (STM32F405).
//! * Speed-up: wall time of the 60 frames drawn by `Triangles3d` on one thread
//!   and by `render_threads` on two, best of 5 runs each, in the same run.
//! * Damage regions: the same drive with `Renderer::render_damaged`, each
//!   frame damaged by the needle's old and new bounds and the readout's
//!   (`dashboard_live::damage`); bytes sent per frame against the damaged
//!   area's (the union of the rectangles, `Damage::area`), and the
//!   Cortex-M4F instructions per frame of `fw_bench`'s `dashboard-drive` row
//!   against its `dashboard` row (a full frame), read from
//!   `docs/data/fw-bench.tsv`; the verdicts computed from them.

use std::time::Instant;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
use microraster::render::{Blocking, Damage, DirtyBands};
use microraster::render::{Triangles3d, from_fn};
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

#[path = "common/dashboard_live.rs"]
mod live;
#[allow(dead_code)] // the constants the demo and benches use
#[path = "common/dashboard.rs"]
mod scene;

const W: usize = 320;
const HEIGHT: u32 = 240;
const BAND: usize = 16;
const BANDS: usize = HEIGHT as usize / BAND;
const FRAMES: usize = 60;
const BG: Rgb565 = Rgb565::BLACK;
const CPU_HZ: f64 = 168e6;
const TSV: &str = "docs/data/link-m4f.tsv";
const FW_TSV: &str = "docs/data/fw-bench.tsv";

fn bins(angle: f32) -> heapless::Vec<ScreenTriangle<4>, BINS> {
    let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, HEIGHT).expect("scene");
    let mut bins = heapless::Vec::new();
    Scene3d.draw::<f32, Rgb565, 4, BINS>(&pipeline, angle, &mut bins).expect("scene");
    bins
}

fn angle(frame: usize) -> f32 {
    frame as f32 * 0.05
}

/// A display that keeps what it was sent and counts the pixels.
struct Screen {
    pixels: Vec<Rgb565>,
    sent: u64,
}

impl Screen {
    fn new() -> Self {
        Screen { pixels: vec![Rgb565::RED; W * HEIGHT as usize], sent: 0 }
    }
}

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        Size::new(W as u32, HEIGHT)
    }
}

impl DrawTarget for Screen {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), Self::Error> {
        unreachable!("the band loop sends whole bands")
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        c: I,
    ) -> Result<(), Self::Error> {
        let start = area.top_left.y as usize * W + area.top_left.x as usize;
        let n = area.size.width as usize * area.size.height as usize;
        assert_eq!(area.size.width as usize, W, "whole rows");
        for (dst, c) in self.pixels[start..start + n].iter_mut().zip(c) {
            *dst = c;
        }
        self.sent += n as u64;
        Ok(())
    }
}

/// Bytes sent in each frame: every band, and with dirty bands.
type Sent = (Vec<u64>, Vec<u64>);

/// Bytes each frame sends: the plain band loop (`full`, every band) and the
/// double-banded loop through `DirtyBands` (`dirty`). Asserts after every
/// frame that the display fed by dirty bands shows the full render's frame.
fn sent(
    frames: usize,
    mut full: impl FnMut(usize, &mut Screen),
    mut dirty: impl FnMut(usize, &mut DirtyBands<Blocking<'_, Screen>, BANDS>),
) -> Sent {
    let (mut plain, mut skipping) = (Screen::new(), Screen::new());
    let mut sink = DirtyBands::<_, BANDS>::new(Blocking(&mut skipping));
    let (mut all, mut some) = (Vec::new(), Vec::new());
    for f in 0..frames {
        let before = (plain.sent, sink.sent_pixels());
        full(f, &mut plain);
        dirty(f, &mut sink);
        all.push((plain.sent - before.0) * 2);
        some.push((sink.sent_pixels() - before.1) * 2);
        assert!(sink.inner().0.pixels == plain.pixels, "frame {f}: dirty bands show another frame");
    }
    (all, some)
}

/// The spinning 3D scene's bytes per frame (every band, dirty bands).
fn scene3d_sent(frames: &[heapless::Vec<ScreenTriangle<4>, BINS>]) -> Sent {
    let r = Renderer::new(HEIGHT, BG);
    let (mut band, mut bands) =
        (Band::<Rgb565, W, BAND>::new(BG), [const { Band::<Rgb565, W, BAND>::new(BG) }; 2]);
    let (mut depth, mut depth2) =
        (DepthBand::<Depth16, W, BAND>::new(), DepthBand::<Depth16, W, BAND>::new());
    sent(
        frames.len(),
        |f, screen| {
            r.render(
                Triangles3d::new(&frames[f], &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
                &mut band,
                screen,
            )
            .expect("frame");
        },
        |f, sink| {
            r.render_linked(
                Triangles3d::new(&frames[f], &mut depth2, DepthState::LESS_WRITE, PerspectiveCorrect),
                &mut bands,
                sink,
            )
            .expect("frame");
        },
    )
}

/// The driving dashboard's bytes per frame (every band, dirty bands).
fn dashboard_sent() -> Sent {
    let r = Renderer::new(HEIGHT, scene::NIGHT);
    let mut band = Band::<Rgb565, W, BAND>::new(scene::NIGHT);
    let mut bands = [const { Band::<Rgb565, W, BAND>::new(scene::NIGHT) }; 2];
    sent(
        live::FRAMES,
        |f, screen| {
            r.render(from_fn(|view| live::dashboard_at(view, live::speed(f))), &mut band, screen)
                .expect("frame");
        },
        |f, sink| {
            let mut failed = Ok(());
            r.render_linked(
                from_fn(|view| {
                    if failed.is_ok() {
                        failed = live::dashboard_at(view, live::speed(f));
                    };
                    Ok(())
                }),
                &mut bands,
                sink,
            )
            .expect("frame");
            failed.expect("dashboard");
        },
    )
}

/// A display that keeps what it was sent, in rectangles of any shape, and
/// counts the pixels.
struct Patches {
    pixels: Vec<Rgb565>,
    sent: u64,
}

impl OriginDimensions for Patches {
    fn size(&self) -> Size {
        Size::new(W as u32, HEIGHT)
    }
}

impl DrawTarget for Patches {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), Self::Error> {
        unreachable!("the band loop sends rectangles")
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        c: I,
    ) -> Result<(), Self::Error> {
        for (p, c) in area.points().zip(c) {
            self.pixels[p.y as usize * W + p.x as usize] = c;
            self.sent += 1;
        }
        Ok(())
    }
}

/// The drive with damage regions: bytes sent and damaged bytes in frames
/// 2–60 (a full frame first), asserting after every frame that the display
/// shows the full render's frame.
fn damage_sent() -> (Vec<u64>, Vec<u64>) {
    let r = Renderer::new(HEIGHT, scene::NIGHT);
    let mut band = Band::<Rgb565, W, BAND>::new(scene::NIGHT);
    let mut shown = Patches { pixels: vec![Rgb565::RED; W * HEIGHT as usize], sent: 0 };
    let mut full = Screen::new();
    r.render(from_fn(|view| live::dashboard_at(view, live::speed(0))), &mut band, &mut shown).expect("frame");
    let (mut sent, mut damaged) = (Vec::new(), Vec::new());
    for f in 1..live::FRAMES {
        let (from, to) = (live::speed(f - 1), live::speed(f));
        let mut damage = Damage::<4>::new();
        live::damage(from, to, &mut damage).expect("damage");
        let before = shown.sent;
        r.render_damaged(from_fn(|view| live::dashboard_at(view, to)), &damage, &mut band, &mut shown)
            .expect("frame");
        sent.push((shown.sent - before) * 2);
        damaged.push(damage.area(W as u32, HEIGHT) * 2);
        r.render(from_fn(|view| live::dashboard_at(view, to)), &mut band, &mut full).expect("frame");
        assert!(shown.pixels == full.pixels, "frame {f}: the damaged display shows another frame");
    }
    (sent, damaged)
}

/// The damage-region line: bytes against the damaged area, instructions
/// against a full frame (from `docs/data/fw-bench.tsv`), each with its verdict.
fn damage_line() -> String {
    let (sent, damaged) = damage_sent();
    let n = sent.len() as f64;
    let mean = |v: &[u64]| v.iter().sum::<u64>() as f64 / n;
    let within = sent.iter().zip(&damaged).all(|(s, d)| s <= d);
    let bytes = format!(
        "Damage regions (`Renderer::render_damaged`), dashboard while driving, frames 2–60 after one full frame: \
         {:.0} bytes sent per frame (max {}), damaged area {:.0} bytes per frame (max {}): sent ≤ damaged in every frame: **{}**; \
         {:.1} % of a full frame's 153600 bytes.",
        mean(&sent),
        sent.iter().max().copied().unwrap_or(0),
        mean(&damaged),
        damaged.iter().max().copied().unwrap_or(0),
        if within { "met" } else { "missed" },
        100.0 * mean(&sent) / (W * HEIGHT as usize * 2) as f64,
    );
    let tsv = std::fs::read_to_string(FW_TSV).unwrap_or_default();
    let row = |key: &str| {
        tsv.lines()
            .map(|l| l.split('\t').collect::<Vec<_>>())
            .find(|f| f.len() > 2 && f[0] == "m4f" && f[1].starts_with(key))
            .and_then(|f| f[2].parse::<f64>().ok())
    };
    let instr = match (row("dashboard/"), row("dashboard-drive/")) {
        (Some(full), Some(drive)) => format!(
            " Cortex-M4F (`{FW_TSV}`, `bash scripts/firmware.sh table`): {drive:.0} instructions per damaged frame \
             against {full:.0} for a full frame: {:.1} % (target ≤ 25 %): **{}**.",
            100.0 * drive / full,
            if drive <= 0.25 * full { "met" } else { "missed" }
        ),
        _ => format!(
            " Cortex-M4F: no `dashboard` and `dashboard-drive` rows in `{FW_TSV}` (`bash scripts/firmware.sh table` writes them)."
        ),
    };
    format!("{bytes}{instr}\n")
}

/// Bytes sent per frame, all bands and with dirty bands, for each scene.
fn bytes_table(scenes: &[(&str, Sent)]) -> String {
    let mut s = String::new();
    s += "| 60 frames, 320×240 Rgb565, 16-row bands | bytes per frame (frames 2–60: mean, min, max) | bytes, all 60 frames |\n|---|---|---|\n";
    for (name, (all, some)) in scenes {
        let total_all: u64 = all.iter().sum();
        for (how, per_frame) in [("every band sent", all), ("dirty bands (`DirtyBands`)", some)] {
            let later = &per_frame[1..];
            let mean = later.iter().sum::<u64>() as f64 / later.len() as f64;
            let (min, max) =
                (later.iter().min().copied().unwrap_or(0), later.iter().max().copied().unwrap_or(0));
            let total: u64 = per_frame.iter().sum();
            let mean_all = total_all as f64 / all.len() as f64;
            s += &format!(
                "| {name}, {how} | {mean:.0} ({min} – {max}): {:.1} % | {total}: {:.1} % |\n",
                100.0 * mean / mean_all,
                100.0 * total as f64 / total_all as f64
            );
        }
    }
    s
}

/// One measured frame on the M4F: vertex-stage instructions and each
/// band's rendering instructions (docs/data/link-m4f.tsv, `bash
/// scripts/firmware.sh link`).
struct Measured {
    vertex: f64,
    bands: Vec<f64>,
}

fn measured(tsv: &str) -> Vec<Measured> {
    let mut frames: Vec<Measured> = Vec::new();
    for line in tsv.lines().filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split('\t').collect();
        let num = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).expect("number in link-m4f.tsv");
        match f[0] {
            "vertex" => frames.push(Measured { vertex: num(2), bands: Vec::new() }),
            "band" => frames.last_mut().expect("vertex record first").bands.push(num(3)),
            other => panic!("unknown record {other:?} in link-m4f.tsv"),
        }
    }
    frames
}

/// The double-banded frame time: band k + 1 renders from the moment band
/// k's transfer starts, which is when band k is rendered and band k − 1
/// sent (`B_k = max(R_k, S_{k−1})`, `R_{k+1} = B_k + r_{k+1}`, `S_k = B_k + s`).
fn double_banded(v: f64, r: &[f64], s: f64) -> f64 {
    let (mut rendered, mut sent) = (v + r[0], v);
    for k in 0..r.len() {
        let start = rendered.max(sent);
        sent = start + s;
        rendered = start + r.get(k + 1).copied().unwrap_or(0.0);
    }
    sent
}

fn model_table() -> String {
    let tsv = std::fs::read_to_string(TSV).expect(TSV);
    let frames = measured(&tsv);
    let all: Vec<f64> = frames.iter().flat_map(|f| f.bands.iter().copied()).collect();
    let (lo, hi) = all.iter().fold((f64::INFINITY, 0f64), |(lo, hi), &r| (lo.min(r), hi.max(r)));
    let mean_v = frames.iter().map(|f| f.vertex).sum::<f64>() / frames.len() as f64;
    let bytes = (W * BAND * 2) as f64;
    let mut s = format!(
        "Model, from measured Cortex-M4F instructions per band (`{TSV}`, `bash scripts/firmware.sh link`: \
         {} frames of the spinning 3D scene, QEMU `-icount`) at 1 instruction per cycle and 168 MHz: \
         vertex stage v (mean {:.2} ms), band k rendered in r_k ({:.3} – {:.3} ms over all bands), \
         a band of {bytes:.0} bytes sent in s = 8 · {bytes:.0} / f_SPI. \
         Blocking: T = v + Σ (r_k + s). Double-banded: R_0 = v + r_0, S_{{−1}} = v; \
         band k's transfer starts at B_k = max(R_k, S_{{k−1}}), ends at S_k = B_k + s, \
         and band k + 1 renders meanwhile: R_{{k+1}} = B_k + r_{{k+1}}; T = S_{{n−1}}, n = {BANDS}. \
         Frame times are means over the measured frames; the SpiPanel sink's conversion into its \
         wire buffer is not counted.\n\n",
        frames.len(),
        mean_v / CPU_HZ * 1e3,
        lo / CPU_HZ * 1e3,
        hi / CPU_HZ * 1e3,
    );
    s += "| SPI clock | s per band (ms) | blocking frame (ms) | double-banded frame (ms) | ratio |\n|---|---|---|---|---|\n";
    for mhz in [20.0, 40.0, 62.5] {
        let send = 8.0 * bytes / (mhz * 1e6);
        let (mut blocking, mut double) = (0.0, 0.0);
        for f in &frames {
            let r: Vec<f64> = f.bands.iter().map(|i| i / CPU_HZ).collect();
            let v = f.vertex / CPU_HZ;
            blocking += v + r.iter().map(|r| r + send).sum::<f64>();
            double += double_banded(v, &r, send);
        }
        let n = frames.len() as f64;
        let (blocking, double) = (blocking / n, double / n);
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
    // Other jobs on the machine take cores from the second thread: say how busy it was before the runs.
    let load = std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|l| l.split_whitespace().next().map(str::to_owned))
        .unwrap_or_else(|| "unknown".into());
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
            r.render(
                Triangles3d::new(tris, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
                &mut band,
                &mut Null,
            )
            .expect("frame");
        }
    });
    let two = best(&mut || {
        let mut bands = [const { Band::<Rgb565, W, BAND>::new(BG) }; 2];
        let mut depth = [const { DepthBand::<Depth16, W, BAND>::zeroed() }; 2];
        for tris in frames {
            r.render_threads(
                depth
                    .each_mut()
                    .map(|d| Triangles3d::new(tris, d, DepthState::LESS_WRITE, PerspectiveCorrect)),
                &mut bands,
                &mut Null,
            )
            .expect("frame");
        }
    });
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!(
        "| host, {cores} cores reported, load average {load} (1 min, before the run), 60 frames (bins ready) | one thread `render` (ms) | two threads `render_threads` (ms) | speed-up |\n|---|---|---|---|\n\
         | best of 5 | {:.1} | {:.1} | {:.2}× |\n",
        one * 1e3,
        two * 1e3,
        one / two
    )
}

fn main() {
    let frames: Vec<_> = (0..FRAMES).map(|f| bins(angle(f))).collect();
    let text = format!(
        "Written by `cargo run --release --example link -- docs/link.md`.\n\n{}\n{}\n{}\n{}",
        bytes_table(&[
            ("spinning 3D scene", scene3d_sent(&frames)),
            ("dashboard while driving", dashboard_sent())
        ]),
        damage_line(),
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
