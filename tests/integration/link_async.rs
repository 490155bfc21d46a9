//! The async display link (feature `async`): transfers that complete after
//! a scripted number of polls never see their band change, the next band is
//! drawn while a pending transfer is in flight, and the frames (through a
//! test sink and through `SpiPanel` decoded as a MIPI-DCS panel would) are
//! the plain band loop's frames.

use core::future::{Future, poll_fn};
use core::pin::pin;
use core::task::{Context, Poll, Waker};
use std::cell::RefCell;

use crate::framebuffer::Framebuffer;
use crate::link::{BG, HEIGHT, W, bins, mixed_scene, plain_2d, plain_3d};
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::{AsyncBandSink, SpiPanel, SpiPanelError};
use microraster::render::{Triangles3d, from_fn};
use microraster::{Band, Error, RenderError, Renderer};

/// Polls `future` to the end, waking itself (the scripted futures do).
fn block_on<F: Future>(future: F) -> F::Output {
    let mut future = pin!(future);
    let mut cx = Context::from_waker(Waker::noop());
    for _ in 0..1_000_000 {
        if let Poll::Ready(out) = future.as_mut().poll(&mut cx) {
            return out;
        }
    }
    panic!("the frame never finished");
}

/// Pends `polls` times, then is ready; `check` runs at every poll.
async fn pend(mut polls: u64, mut check: impl FnMut()) {
    poll_fn(|cx| {
        check();
        if polls == 0 {
            return Poll::Ready(());
        }
        polls -= 1;
        cx.waker().wake_by_ref();
        Poll::Pending
    })
    .await
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Event {
    /// Band at row y0 handed over; its transfer pends this many polls.
    Start(i32, u64),
    /// Band at row y0 drawn.
    Draw(i32),
    /// Band at row y0 sent.
    Done(i32),
}

/// Completes each transfer after a seeded number of polls; checks at every
/// poll that the band has not changed since it was handed over; writes it
/// to the framebuffer when it completes.
struct Scripted<'l> {
    rng: Rng,
    fb: Framebuffer<Rgb565>,
    log: &'l RefCell<Vec<Event>>,
}

impl AsyncBandSink<Rgb565> for Scripted<'_> {
    type Error = ();

    fn send(&mut self, area: Rectangle, pixels: &[Rgb565]) -> impl Future<Output = Result<(), ()>> {
        let polls = self.rng.below(4);
        let (y0, copy) = (area.top_left.y, pixels.to_vec());
        self.log.borrow_mut().push(Event::Start(y0, polls));
        async move {
            pend(polls, || assert_eq!(pixels, &copy[..], "band at row {y0} changed while in flight")).await;
            self.fb.fill_contiguous(&area, pixels.iter().copied()).unwrap();
            self.log.borrow_mut().push(Event::Done(y0));
            Ok(())
        }
    }
}

/// Every band after the first is drawn after the previous one was handed
/// over, and before it completed if its transfer pended.
fn assert_overlap(log: &[Event]) {
    let at = |e: Event| log.iter().position(|&x| x == e).unwrap_or_else(|| panic!("{e:?} missing: {log:?}"));
    let starts: Vec<_> =
        log.iter().filter_map(|e| if let Event::Start(y, p) = *e { Some((y, p)) } else { None }).collect();
    for pair in starts.windows(2) {
        let ((y, polls), (next, _)) = (pair[0], pair[1]);
        let drawn = at(Event::Draw(next));
        assert!(at(Event::Start(y, polls)) < drawn, "band {next} drawn before band {y} was handed over");
        if polls > 0 {
            assert!(
                drawn < at(Event::Done(y)),
                "band {next} not drawn while band {y} was in flight: {log:?}"
            );
        }
    }
}

fn scripted_2d<const H: usize>(seed: u64) {
    let scene = mixed_scene();
    let log = RefCell::new(Vec::new());
    let mut sink = Scripted { rng: Rng::new(seed), fb: Framebuffer::new(W as u32, HEIGHT, BG), log: &log };
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; 2];
    let r = Renderer::new(HEIGHT, BG);
    block_on(r.render_async(&scene, &mut bands, &mut sink)).unwrap();
    assert!(sink.fb.pixels == plain_2d::<H>(&scene), "H = {H}, seed {seed}");
    assert_eq!(log.borrow().len(), 2 * (HEIGHT as usize).div_ceil(H));
}

#[test]
fn async_sink_sees_no_band_change_and_gets_the_plain_frame_2d() {
    for seed in 0..8 {
        scripted_2d::<1>(seed);
        scripted_2d::<5>(seed);
        scripted_2d::<16>(seed);
        scripted_2d::<72>(seed);
    }
}

#[test]
fn async_sink_gets_the_plain_frame_3d() {
    for (seed, angle) in [0.0f32, 0.7, 2.1, 4.0].into_iter().enumerate() {
        let log = RefCell::new(Vec::new());
        let mut sink =
            Scripted { rng: Rng::new(seed as u64), fb: Framebuffer::new(W as u32, HEIGHT, BG), log: &log };
        let mut bands = [const { Band::<Rgb565, W, 8>::new(BG) }; 2];
        let mut depth = DepthBand::<Depth16, W, 8>::new();
        let (r, tris) = (Renderer::new(HEIGHT, BG), bins(angle));
        let frame = r.render_async(
            Triangles3d::new(&tris, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut bands,
            &mut sink,
        );
        block_on(frame).unwrap();
        assert!(sink.fb.pixels == plain_3d::<8>(angle), "angle {angle}");
    }
}

/// A pattern that differs in every band and row, so a band drawn into the
/// buffer in flight would show.
fn pattern(x: usize, y: i32) -> Rgb565 {
    Rgb565::from(RawU16::new((x as u16).wrapping_mul(31) ^ (y as u16).wrapping_mul(977)))
}

#[test]
fn next_band_is_drawn_while_the_last_is_in_flight() {
    for seed in 0..16 {
        let log = RefCell::new(Vec::new());
        let mut sink =
            Scripted { rng: Rng::new(seed), fb: Framebuffer::new(W as u32, HEIGHT, BG), log: &log };
        let mut bands = [const { Band::<Rgb565, W, 7>::new(BG) }; 2];
        let r = Renderer::new(HEIGHT, BG);
        let frame = r.render_async(
            from_fn(|view| {
                let (y0, y1) = (view.y0(), view.y1());
                log.borrow_mut().push(Event::Draw(y0));
                for y in y0..y1 {
                    for x in 0..W {
                        microraster::blit::Blitter::set_pixel(view, x as i32, y, pattern(x, y));
                    }
                }
                Ok(())
            }),
            &mut bands,
            &mut sink,
        );
        block_on(frame).unwrap();
        let expected: Vec<_> = (0..HEIGHT as i32).flat_map(|y| (0..W).map(move |x| pattern(x, y))).collect();
        assert!(sink.fb.pixels == expected, "seed {seed}");
        assert_overlap(&log.borrow());
    }
}

/// A MIPI-DCS panel as the controller sees the wire: DC low bytes are
/// commands, CASET/RASET set the window, RAMWR starts writing pixels
/// (big-endian Rgb565) that run on through the window.
struct Panel {
    dc_high: bool,
    command: Option<u8>,
    window: [u16; 4],
    next: usize,
    fb: Framebuffer<Rgb565>,
    polls: Rng,
}

impl Panel {
    fn receive(&mut self, bytes: &[u8]) {
        if !self.dc_high {
            assert_eq!(bytes.len(), 1, "one command byte at a time");
            self.command = Some(bytes[0]);
            self.next = 0;
            return;
        }
        let word = |i: usize| u16::from_be_bytes([bytes[i], bytes[i + 1]]);
        match self.command {
            Some(0x2A) => (self.window[0], self.window[2]) = (word(0), word(2)),
            Some(0x2B) => (self.window[1], self.window[3]) = (word(0), word(2)),
            Some(0x2C) => {
                let [x0, y0, x1, _] = self.window.map(i32::from);
                let width = (x1 - x0 + 1) as usize;
                for px in bytes.chunks_exact(2) {
                    let p = Point::new(x0 + (self.next % width) as i32, y0 + (self.next / width) as i32);
                    let c = Rgb565::from(RawU16::new(u16::from_be_bytes([px[0], px[1]])));
                    self.fb.fill_contiguous(&Rectangle::new(p, Size::new(1, 1)), [c]).unwrap();
                    self.next += 1;
                }
            }
            other => panic!("data after {other:?}"),
        }
    }
}

struct Spi<'p>(&'p RefCell<Panel>);
struct Dc<'p>(&'p RefCell<Panel>);

impl embedded_hal_async::spi::ErrorType for Spi<'_> {
    type Error = core::convert::Infallible;
}

impl embedded_hal_async::spi::SpiDevice for Spi<'_> {
    async fn transaction(
        &mut self,
        ops: &mut [embedded_hal_async::spi::Operation<'_, u8>],
    ) -> Result<(), Self::Error> {
        for op in ops {
            let embedded_hal_async::spi::Operation::Write(bytes) = op else { panic!("only writes") };
            let polls = self.0.borrow_mut().polls.below(3);
            pend(polls, || {}).await;
            self.0.borrow_mut().receive(bytes);
        }
        Ok(())
    }
}

impl embedded_hal::digital::ErrorType for Dc<'_> {
    type Error = core::convert::Infallible;
}

impl embedded_hal::digital::OutputPin for Dc<'_> {
    fn set_low(&mut self) -> Result<(), Self::Error> {
        self.0.borrow_mut().dc_high = false;
        Ok(())
    }
    fn set_high(&mut self) -> Result<(), Self::Error> {
        self.0.borrow_mut().dc_high = true;
        Ok(())
    }
}

fn panel(seed: u64) -> RefCell<Panel> {
    let fb = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
    RefCell::new(Panel { dc_high: false, command: None, window: [0; 4], next: 0, fb, polls: Rng::new(seed) })
}

fn spi_panel_2d<const H: usize>(seed: u64) {
    let scene = mixed_scene();
    let state = panel(seed);
    let mut wire = vec![0u8; 2 * W * H];
    let mut sink = SpiPanel::new(Spi(&state), Dc(&state), &mut wire);
    let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; 2];
    for _ in 0..2 {
        // Twice: the second frame sets its window again.
        state.borrow_mut().fb = Framebuffer::new(W as u32, HEIGHT, Rgb565::BLACK);
        let r = Renderer::new(HEIGHT, BG);
        block_on(r.render_async(&scene, &mut bands, &mut sink)).unwrap();
        let shown = state.borrow();
        assert!(shown.fb.pixels == plain_2d::<H>(&scene), "H = {H}, seed {seed}");
        assert!(shown.fb.writes.iter().all(|&n| n == 1), "each pixel sent once");
    }
}

#[test]
fn spi_panel_frames_decode_to_the_plain_frame() {
    for seed in 0..4 {
        spi_panel_2d::<1>(seed);
        spi_panel_2d::<16>(seed);
        spi_panel_2d::<72>(seed);
    }
}

#[test]
fn spi_panel_bad_configurations_are_typed_errors() {
    let state = panel(0);
    let mut bands = [const { Band::<Rgb565, W, 8>::new(BG) }; 2];
    let mut small = vec![0u8; 2 * W * 8 - 1];
    let mut sink = SpiPanel::new(Spi(&state), Dc(&state), &mut small);
    let r = Renderer::new(HEIGHT, BG);
    let frame = r.render_async((), &mut bands, &mut sink);
    assert_eq!(block_on(frame), Err(RenderError::Input(Error::BufferTooSmall)));
    assert!(state.borrow().command.is_none(), "nothing sent");
    // A frame left of column 0 has no 16-bit panel address.
    let mut wire = vec![0u8; 2 * W * 8];
    let mut sink = SpiPanel::new(Spi(&state), Dc(&state), &mut wire);
    let r = r.with_offset(Point::new(-1, 0));
    let frame = r.render_async((), &mut bands, &mut sink);
    assert_eq!(block_on(frame), Err(RenderError::Target(SpiPanelError::Window)));
}
