//! Issue 60 (integrity 3), finding 1: `DirtyBands` counts a band as shown
//! only once its transfer succeeded. After a frame whose transfer failed at
//! some band, a frame whose transfers all succeed leaves the display equal
//! to that frame rendered in full, whether the inner sink sends each band
//! before `submit` returns or keeps it on the wire until `reclaim`; and the
//! frame that fails waits for the transfers still running, so that none of
//! them finishes during a later frame.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use microraster::blit::Blitter;
use microraster::render::{BandSink, Blocking, DirtyBands, Lent, from_fn};
use microraster::{Band, RenderError, Renderer};

const W: usize = 8;
const H: usize = 4;
const HEIGHT: u32 = 16; // four bands
const BANDS: usize = 4;
const BG: Rgb565 = Rgb565::BLACK;

/// Frame `f`: every pixel a colour of its own that differs from frame to
/// frame, so every band changes between two frames.
fn colour(f: u8, x: i32, y: i32) -> Rgb565 {
    Rgb565::new(f % 32, (x * 8 + y) as u8 % 64, (f / 32 + 1) % 32)
}

fn render<'a, S, const N: usize>(
    f: u8,
    bands: &'a mut [Band<Rgb565, W, H>; N],
    sink: &mut S,
) -> Result<(), RenderError<S::Error>>
where
    S: BandSink<'a, Rgb565, W>,
{
    let frame = from_fn(|view| {
        for y in view.y0()..view.y1() {
            for x in 0..W as i32 {
                view.set_pixel(x, y, colour(f, x, y));
            }
        }
        Ok(())
    });
    Renderer::new(HEIGHT, BG).render_linked(frame, bands, sink)
}

/// Frame `f` as the display must show it.
fn expected(f: u8) -> Vec<Rgb565> {
    (0..HEIGHT as i32).flat_map(|y| (0..W as i32).map(move |x| colour(f, x, y))).collect()
}

/// A display whose `fill_contiguous` fails on its `fail_at`-th call from
/// now (0: the next), and works otherwise.
struct Flaky {
    fb: Framebuffer<Rgb565>,
    fail_at: Option<usize>,
}

impl OriginDimensions for Flaky {
    fn size(&self) -> Size {
        self.fb.size()
    }
}

impl DrawTarget for Flaky {
    type Color = Rgb565;
    type Error = ();

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), ()> {
        unreachable!("the band loop sends whole bands")
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(&mut self, area: &Rectangle, c: I) -> Result<(), ()> {
        match self.fail_at {
            Some(0) => {
                self.fail_at = None;
                Err(())
            }
            n => {
                self.fail_at = n.map(|n| n - 1);
                self.fb.fill_contiguous(area, c).map_err(|e| match e {})
            }
        }
    }
}

#[test]
fn dirty_bands_resend_a_band_whose_blocking_transfer_failed() {
    for k in 0..BANDS {
        let mut display = Flaky { fb: Framebuffer::new(W as u32, HEIGHT, BG), fail_at: None };
        let mut bands = [const { Band::<Rgb565, W, H>::new(BG) }; 2];
        let mut sink = DirtyBands::<_, BANDS>::new(Blocking(&mut display));
        render(0, &mut bands, &mut sink).unwrap();
        sink.inner().0.fail_at = Some(k);
        assert_eq!(render(1, &mut bands, &mut sink), Err(RenderError::Target(())), "k = {k}");
        render(1, &mut bands, &mut sink).unwrap();
        assert!(sink.inner().0.fb.pixels == expected(1), "band {k} failed, then was skipped");
        // The record is whole again: the same frame once more sends nothing.
        let sent = sink.sent_bands();
        render(1, &mut bands, &mut sink).unwrap();
        assert_eq!(sink.sent_bands(), sent, "k = {k}");
    }
}

/// Keeps up to `depth` bands on the wire until the renderer needs a buffer
/// or the frame ends (as DMA does), finishing the oldest first; the
/// transfer of band `fail` fails when it is waited for, in `reclaim` or in
/// a `submit` after it.
struct Dma<'a> {
    fb: Framebuffer<Rgb565>,
    wire: Vec<Lent<'a, Rgb565, W>>,
    depth: usize,
    fail: Option<usize>,
}

impl<'a> Dma<'a> {
    fn new(depth: usize) -> Self {
        Dma { fb: Framebuffer::new(W as u32, HEIGHT, BG), wire: Vec::new(), depth, fail: None }
    }

    /// Waits for the oldest band on the wire: writes it to the display, or
    /// fails (and drops it).
    fn finish(&mut self) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        if self.wire.is_empty() {
            return Ok(None);
        }
        let band = self.wire.remove(0);
        if self.fail == Some(band.index()) {
            self.fail = None;
            return Err(());
        }
        self.fb.fill_contiguous(&band.area(), band.pixels().iter().copied()).unwrap();
        Ok(Some(band))
    }
}

impl<'a> BandSink<'a, Rgb565, W> for Dma<'a> {
    type Error = ();

    fn submit(&mut self, band: Lent<'a, Rgb565, W>) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        let done = if self.wire.len() < self.depth { None } else { self.finish()? };
        self.wire.push(band);
        Ok(done)
    }

    fn reclaim(&mut self) -> Result<Option<Lent<'a, Rgb565, W>>, ()> {
        self.finish()
    }
}

#[test]
fn dirty_bands_resend_a_band_whose_transfer_failed_on_the_wire() {
    for (depth, k) in [1, 2].into_iter().flat_map(|d| (0..BANDS).map(move |k| (d, k))) {
        // A sink that holds bands is tied to their borrow: bands of their
        // own for each frame, all borrowed as long as the sink lives.
        let mut pools = [const { [const { Band::<Rgb565, W, H>::new(BG) }; 3] }; 4];
        let [a, b, c, d] = &mut pools;
        let mut sink = DirtyBands::<_, BANDS>::new(Dma::new(depth));
        render(0, a, &mut sink).unwrap();
        sink.inner().fail = Some(k);
        assert_eq!(render(1, b, &mut sink), Err(RenderError::Target(())), "depth {depth}, k = {k}");
        // The other transfers were waited for: none can finish later, over
        // a later frame's band.
        assert!(sink.inner().wire.is_empty(), "depth {depth}, k = {k}: bands left on the wire");
        render(1, c, &mut sink).unwrap();
        assert!(
            sink.inner().fb.pixels == expected(1),
            "depth {depth}: band {k} failed on the wire, then was skipped"
        );
        let sent = sink.sent_bands();
        render(1, d, &mut sink).unwrap();
        assert_eq!(sink.sent_bands(), sent, "depth {depth}, k = {k}");
    }
}
