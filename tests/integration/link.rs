//! The display link (`microraster::render::link`, `DirtyBands`, host
//! threads): sinks that finish bands out of step never see a band change
//! while they hold it; double-banded, dirty-skipping and threaded frames are
//! the plain band loop's frames; bad configurations are typed errors.

use std::sync::mpsc;

use crate::framebuffer::Framebuffer;
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::{BandSink, Blocking, DirtyBands, Lent};
use microraster::render::{Triangles3d, from_fn};
use microraster::{Band, Error, Primitive, RenderError, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{BINS, Scene3d};

pub const W: usize = 96;
pub const HEIGHT: u32 = 72;
pub const BG: Rgb565 = Rgb565::new(2, 5, 9);

/// A band in flight: what the sink was given, to compare when it lets go.
struct Held<'a, const W: usize> {
    band: Lent<'a, Rgb565, W>,
    copy: Vec<Rgb565>,
}

/// Keeps up to `depth` bands "on the wire" and finishes them in an order
/// drawn from a seeded generator; writes a band to the framebuffer only when
/// it finishes, after checking that its pixels did not change since submit.
struct Scripted<'a, const W: usize> {
    held: Vec<Held<'a, W>>,
    depth: usize,
    rng: Rng,
    fb: Framebuffer<Rgb565>,
    finished: usize,
}

impl<'a, const W: usize> Scripted<'a, W> {
    fn new(depth: usize, seed: u64) -> Self {
        Scripted {
            held: Vec::new(),
            depth,
            rng: Rng::new(seed),
            fb: Framebuffer::new(W as u32, HEIGHT, BG),
            finished: 0,
        }
    }

    fn finish(&mut self, i: usize) -> Lent<'a, Rgb565, W> {
        let Held { band, copy } = self.held.swap_remove(i);
        assert_eq!(band.pixels(), &copy[..], "band {} changed while in flight", band.index());
        self.fb.fill_contiguous(&band.area(), band.pixels().iter().copied()).unwrap();
        self.finished += 1;
        band
    }
}

impl<'a, const W: usize> BandSink<'a, Rgb565, W> for Scripted<'a, W> {
    type Error = ();

    fn submit(&mut self, band: Lent<'a, Rgb565, W>) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        let copy = band.pixels().to_vec();
        self.held.push(Held { band, copy });
        // Sometimes finish one at once (any of those held), else keep it.
        if self.held.len() > self.depth || self.rng.below(3) == 0 {
            let i = self.rng.below(self.held.len() as u64) as usize;
            return Ok(Some(self.finish(i)));
        }
        Ok(None)
    }

    fn reclaim(&mut self) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        if self.held.is_empty() {
            return Ok(None);
        }
        let i = self.rng.below(self.held.len() as u64) as usize;
        Ok(Some(self.finish(i)))
    }
}

pub fn mixed_scene() -> heapless::Vec<Primitive<Rgb565, 4>, { scenes::MIXED_LEN }> {
    let mut scene = heapless::Vec::new();
    assert_eq!(scenes::collect(scenes::mixed, W as u32, HEIGHT, &mut scene).unwrap(), 0);
    scene
}

pub fn plain_2d<const H: usize>(scene: &[Primitive<Rgb565, 4>]) -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
    let mut band = Band::<Rgb565, W, H>::new(BG);
    Renderer::new(HEIGHT, BG).render(scene, &mut band, &mut fb).unwrap();
    fb.pixels
}

pub fn bins(angle: f32) -> heapless::Vec<microraster::raster3d::ScreenTriangle<4>, BINS> {
    let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, HEIGHT).unwrap();
    let mut bins = heapless::Vec::new();
    Scene3d.draw::<f32, Rgb565, 4, BINS>(&pipeline, angle, &mut bins).unwrap();
    bins
}

pub fn plain_3d<const H: usize>(angle: f32) -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
    let (mut band, mut depth) = (Band::<Rgb565, W, H>::new(BG), DepthBand::<Depth16, W, H>::new());
    Renderer::new(HEIGHT, BG)
        .render(
            Triangles3d::new(&bins(angle), &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.pixels
}

fn scripted_2d<const H: usize, const N: usize>(seed: u64) {
    let scene = mixed_scene();
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; N];
    let mut sink = Scripted::<W>::new(N - 1, seed);
    Renderer::new(HEIGHT, BG).render_linked(&scene, &mut bands, &mut sink).unwrap();
    assert!(sink.held.is_empty(), "every band back when the frame returns");
    assert_eq!(sink.finished, (HEIGHT as usize).div_ceil(H));
    assert!(sink.fb.pixels == plain_2d::<H>(&scene), "H = {H}, N = {N}, seed {seed}");
}

#[test]
fn out_of_step_sink_sees_no_band_change_and_gets_the_plain_frame_2d() {
    for seed in 0..8 {
        scripted_2d::<1, 2>(seed);
        scripted_2d::<5, 2>(seed);
        scripted_2d::<16, 2>(seed);
        scripted_2d::<7, 3>(seed);
        scripted_2d::<72, 2>(seed);
    }
}

/// The standard 3D scene at `angle`, double-banded into `sink` (the bands
/// and the depth band are the caller's: a sink may hold bands across calls).
fn linked_3d<'a, S, const H: usize, const N: usize>(
    angle: f32,
    bands: &'a mut [Band<Rgb565, W, H>; N],
    depth: &mut DepthBand<Depth16, W, H>,
    sink: &mut S,
) where
    S: BandSink<'a, Rgb565, W>,
    S::Error: core::fmt::Debug,
{
    Renderer::new(HEIGHT, BG)
        .render_linked(
            Triangles3d::new(&bins(angle), depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            bands,
            sink,
        )
        .unwrap();
}

fn scripted_3d<const H: usize, const N: usize>(angle: f32, seed: u64) {
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; N];
    let mut depth = DepthBand::<Depth16, W, H>::new();
    let mut sink = Scripted::<W>::new(N - 1, seed);
    linked_3d(angle, &mut bands, &mut depth, &mut sink);
    assert!(sink.fb.pixels == plain_3d::<H>(angle), "H = {H}, N = {N}, angle {angle}");
}

#[test]
fn out_of_step_sink_gets_the_plain_frame_3d() {
    for (i, angle) in [0.0f32, 0.7, 2.1, 4.0].into_iter().enumerate() {
        scripted_3d::<1, 2>(angle, i as u64);
        scripted_3d::<8, 2>(angle, i as u64);
        scripted_3d::<13, 4>(angle, i as u64);
    }
}

/// Sends each band to a "DMA" thread that copies it out slowly, row by row
/// with yields, and checks at the end that it did not change meanwhile.
struct ThreadSink<'a, const W: usize> {
    to_wire: mpsc::Sender<(Lent<'a, Rgb565, W>, Vec<Rgb565>)>,
    back: mpsc::Receiver<Lent<'a, Rgb565, W>>,
    in_flight: usize,
}

impl<'a, const W: usize> BandSink<'a, Rgb565, W> for ThreadSink<'a, W> {
    type Error = ();

    fn submit(&mut self, band: Lent<'a, Rgb565, W>) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        let copy = band.pixels().to_vec();
        self.to_wire.send((band, copy)).map_err(|_| ())?;
        self.in_flight += 1;
        Ok(None)
    }

    fn reclaim(&mut self) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        if self.in_flight == 0 {
            return Ok(None);
        }
        self.in_flight -= 1;
        self.back.recv().map(Some).map_err(|_| ())
    }
}

fn threaded_sink<const H: usize>() {
    let scene = mixed_scene();
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; 2];
    let mut fb = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
    std::thread::scope(|s| {
        let (to_wire, wire) = mpsc::channel::<(Lent<'_, Rgb565, W>, Vec<Rgb565>)>();
        let (done, back) = mpsc::channel();
        let fb = &mut fb;
        s.spawn(move || {
            for (band, copy) in wire {
                for (i, row) in band.pixels().chunks(W).enumerate() {
                    let mut area = band.area();
                    area.top_left.y += i as i32;
                    area.size.height = 1;
                    fb.fill_contiguous(&area, row.iter().copied()).unwrap();
                    std::thread::yield_now();
                }
                assert_eq!(band.pixels(), &copy[..], "band {} changed while on the wire", band.index());
                done.send(band).unwrap();
            }
        });
        let mut sink = ThreadSink { to_wire, back, in_flight: 0 };
        Renderer::new(HEIGHT, BG).render_linked(&scene, &mut bands, &mut sink).unwrap();
        assert_eq!(sink.in_flight, 0);
    });
    assert!(fb.pixels == plain_2d::<H>(&scene), "H = {H}");
}

#[test]
fn sink_on_another_thread_sees_no_band_change() {
    threaded_sink::<1>();
    threaded_sink::<6>();
    threaded_sink::<16>();
}

/// The spinning 3D scene, 60 frames: with dirty bands the display (which
/// keeps what it was sent) shows each frame exactly, and fewer bands go out.
fn dirty_animation<const H: usize, const N: usize>() -> (u64, u64) {
    let mut display = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; 2];
    let mut depth = DepthBand::<Depth16, W, H>::new();
    let mut sink = DirtyBands::<_, N>::new(Blocking(&mut display));
    let per_frame = (HEIGHT as usize).div_ceil(H) as u64;
    for frame in 0..60 {
        // A still spell in the middle: frames 20..30 repeat one angle.
        let angle = if (20..30).contains(&frame) { 1.0 } else { frame as f32 * 0.05 };
        linked_3d(angle, &mut bands, &mut depth, &mut sink);
        if frame == 40 {
            sink.force_full_frame();
        }
        let shown = &sink.inner().0.pixels;
        assert!(*shown == plain_3d::<H>(angle), "wrong skip: H = {H}, frame {frame}");
    }
    (sink.sent_bands(), 60 * per_frame)
}

#[test]
fn dirty_bands_never_skip_wrongly_and_skip_something() {
    for (sent, all) in [dirty_animation::<4, 18>(), dirty_animation::<9, 8>(), dirty_animation::<16, 5>()] {
        assert!(sent < all, "{sent} of {all} bands sent");
    }
}

#[test]
fn dirty_bands_single_pixel_changes_are_sent() {
    // Every pixel of a band changed alone, to every other colour of a
    // small palette: each frame sends exactly that band.
    let palette = [BG, Rgb565::new(2, 5, 8), Rgb565::new(3, 5, 9), Rgb565::BLACK];
    let mut bands = [const { Band::<Rgb565, 8, 4>::new(BG) }; 2];
    let mut display = Framebuffer::new(8, 8, Rgb565::BLACK);
    let mut sink = DirtyBands::<_, 2>::new(Blocking(&mut display));
    let r = Renderer::new(8, BG);
    r.render_linked((), &mut bands, &mut sink).unwrap();
    let mut expected = 2;
    for (x, y) in (0..8).flat_map(|y| (0..8).map(move |x| (x, y))) {
        for &c in &palette[1..] {
            r.render_linked(
                from_fn(|view| {
                    use microraster::blit::Blitter;
                    view.set_pixel(x, y, c);
                    Ok(())
                }),
                &mut bands,
                &mut sink,
            )
            .unwrap();
            // The changed band, then the band back to the background.
            expected += 1;
            assert_eq!(sink.sent_bands(), expected, "pixel ({x}, {y})");
            r.render_linked((), &mut bands, &mut sink).unwrap();
            expected += 1;
            assert_eq!(sink.sent_bands(), expected);
        }
    }
}

#[test]
fn dirty_bands_too_few_signatures_is_a_typed_error() {
    let mut bands = [const { Band::<Rgb565, 8, 4>::new(BG) }; 2];
    let mut sink = DirtyBands::<(), 2>::new(());
    let r = Renderer::new(9, BG); // three bands
    assert_eq!(r.render_linked((), &mut bands, &mut sink), Err(RenderError::Input(Error::BufferTooSmall)));
    assert_eq!(sink.sent_bands(), 0);
}

/// Keeps every band and never gives one back: breaks the contract.
struct Hoarder<'a>(Vec<Lent<'a, Rgb565, 8>>);

impl<'a> BandSink<'a, Rgb565, 8> for Hoarder<'a> {
    type Error = ();
    fn submit(&mut self, band: Lent<'a, Rgb565, 8>) -> Result<Option<Lent<'a, Rgb565, 8>>, ()> {
        self.0.push(band);
        Ok(None)
    }
}

#[test]
fn sink_that_keeps_bands_is_a_typed_error() {
    let mut bands = [const { Band::<Rgb565, 8, 4>::new(BG) }; 2];
    let mut sink = Hoarder(Vec::new());
    let r = Renderer::new(12, BG);
    assert_eq!(
        r.render_linked((), &mut bands, &mut sink),
        Err(RenderError::Input(Error::InvalidParameter(microraster::Param::BandSink)))
    );
}

fn threads_3d<const H: usize, const N: usize>(angle: f32) {
    let mut fb = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; N];
    let mut depth = [const { DepthBand::<Depth16, W, H>::zeroed() }; N];
    let tris = bins(angle);
    Renderer::new(HEIGHT, BG)
        .render_threads(
            depth.each_mut().map(|d| Triangles3d::new(&tris, d, DepthState::LESS_WRITE, PerspectiveCorrect)),
            &mut bands,
            &mut fb,
        )
        .unwrap();
    assert_eq!(fb.contiguous.len(), (HEIGHT as usize).div_ceil(H), "one fill per band");
    assert!(fb.pixels == plain_3d::<H>(angle), "H = {H}, N = {N}");
}

#[test]
fn threaded_frames_are_the_plain_frames() {
    for angle in [0.0f32, 1.3, 3.5] {
        threads_3d::<1, 2>(angle);
        threads_3d::<7, 2>(angle);
        threads_3d::<16, 3>(angle);
        threads_3d::<72, 2>(angle);
    }
}
