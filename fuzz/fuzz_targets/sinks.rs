//! The display link when transfers fail (issue 60): a sequence of up to 10
//! frames drawn by `render_linked` through `DirtyBands` into a display whose
//! transfers fail at fuzzed points. The inner sink sends each band before
//! `submit` returns (`Blocking` over a `DrawTarget`) or keeps up to two on
//! the wire, finishing them in a fuzzed order (as DMA does); a failed
//! transfer leaves garbage on half of its band, as one cut short leaves a
//! panel. Frames are picked from four fuzzed scenes (so bands repeat and
//! are skipped), sometimes after `force_full_frame`.
//!
//! Checks: a frame fails only with the sink's error; when it returns, no
//! band is left on the wire; **every frame whose transfers all succeed
//! leaves the display equal to that frame drawn in full** (`DirtyBands`
//! never skips a band that was not delivered), and the same frame drawn
//! again then sends nothing.
#![no_main]

use embedded_graphics_core::pixelcolor::Gray8;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use libfuzzer_sys::fuzz_target;
use microraster::blit::Blitter;
use microraster::render::{BandSink, Blocking, DirtyBands, Lent, from_fn};
use microraster::{Band, RenderError, Renderer};
use microraster_fuzz::Input;

const W: usize = 16;
const MAX_HEIGHT: usize = 40;
/// Signatures for the most bands: one-row bands of the tallest frame.
const SIGS: usize = MAX_HEIGHT;
/// What the display shows before the first frame, and where a failed
/// transfer wrote: no scene has it.
const GARBAGE: Gray8 = Gray8::new(7);
const PALETTE: [u8; 4] = [0x00, 0x40, 0x80, 0xC0];
const MAX_FRAMES: usize = 10;

/// The sink's error: which transfer failed.
#[derive(Debug, PartialEq)]
struct Fail(usize);

/// The display: what it shows, and which transfer (counted from when it was
/// armed) fails.
struct Screen {
    px: Vec<Gray8>,
    transfers: usize,
    fail_at: Option<usize>,
}

impl Screen {
    fn transfer(&mut self, area: &Rectangle, pixels: &[Gray8]) -> Result<(), Fail> {
        let (y0, rows) = (area.top_left.y as usize, area.size.height as usize);
        assert!(area.top_left.x == 0 && area.size.width == W as u32, "band {area:?} not a whole band");
        assert_eq!(pixels.len(), rows * W, "band {area:?}: {} pixels", pixels.len());
        let dst = &mut self.px[y0 * W..(y0 + rows) * W];
        let n = self.transfers;
        self.transfers += 1;
        if self.fail_at == Some(n) {
            dst.iter_mut().step_by(2).for_each(|d| *d = GARBAGE);
            return Err(Fail(n));
        }
        dst.copy_from_slice(pixels);
        Ok(())
    }
}

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        Size::new(W as u32, (self.px.len() / W) as u32)
    }
}

impl DrawTarget for Screen {
    type Color = Gray8;
    type Error = Fail;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, _: I) -> Result<(), Fail> {
        panic!("the band loop sends whole bands with fill_contiguous");
    }

    fn fill_contiguous<I: IntoIterator<Item = Gray8>>(&mut self, area: &Rectangle, c: I) -> Result<(), Fail> {
        let pixels: Vec<Gray8> = c.into_iter().collect();
        self.transfer(area, &pixels)
    }
}

/// Keeps up to `depth` bands on the wire; finishes one (picked by `order`)
/// when it has no room or the renderer reclaims. A failed transfer drops
/// its band.
struct Dma<'a> {
    screen: Screen,
    wire: Vec<Lent<'a, Gray8, W>>,
    depth: usize,
    order: u64,
}

impl<'a> Dma<'a> {
    fn finish(&mut self) -> Result<Option<Lent<'a, Gray8, W>>, Fail> {
        if self.wire.is_empty() {
            return Ok(None);
        }
        self.order = self.order.rotate_right(1);
        let band = self.wire.remove(self.order as usize % self.wire.len());
        self.screen.transfer(&band.area(), band.pixels())?;
        Ok(Some(band))
    }
}

impl<'a> BandSink<'a, Gray8, W> for Dma<'a> {
    type Error = Fail;

    fn submit(&mut self, band: Lent<'a, Gray8, W>) -> Result<Option<Lent<'a, Gray8, W>>, Fail> {
        if self.depth == 0 {
            // Sent before `submit` returns.
            return self.screen.transfer(&band.area(), band.pixels()).map(|()| Some(band));
        }
        let done = if self.wire.len() < self.depth { None } else { self.finish()? };
        self.wire.push(band);
        Ok(done)
    }

    fn reclaim(&mut self) -> Result<Option<Lent<'a, Gray8, W>>, Fail> {
        self.finish()
    }
}

/// What the target needs of either inner sink.
trait Display {
    fn screen(&mut self) -> &mut Screen;
    /// Bands still on the wire.
    fn kept(&self) -> usize;
}

impl Display for Blocking<'_, Screen> {
    fn screen(&mut self) -> &mut Screen {
        &mut *self.0
    }
    fn kept(&self) -> usize {
        0
    }
}

impl Display for Dma<'_> {
    fn screen(&mut self) -> &mut Screen {
        &mut self.screen
    }
    fn kept(&self) -> usize {
        self.wire.len()
    }
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let height = 1 + inp.u8() as usize % MAX_HEIGHT;
    let screen = Screen { px: vec![GARBAGE; W * height], transfers: 0, fail_at: None };
    // Four scenes, each a palette colour per row, varied along the row.
    let scenes: Vec<Vec<u8>> =
        (0..4).map(|_| (0..height).map(|_| PALETTE[inp.u8() as usize % 4]).collect()).collect();
    match inp.u8() % 6 {
        0 => run::<1>(&mut inp, screen, &scenes),
        1 => run::<3>(&mut inp, screen, &scenes),
        2 => run::<8>(&mut inp, screen, &scenes),
        3 => run_dma::<1>(&mut inp, screen, &scenes),
        4 => run_dma::<3>(&mut inp, screen, &scenes),
        _ => run_dma::<8>(&mut inp, screen, &scenes),
    }
});

fn run<const H: usize>(inp: &mut Input, mut screen: Screen, scenes: &[Vec<u8>]) {
    let mut pools = pools::<H>();
    let mut pools = pools.iter_mut();
    let mut sink = DirtyBands::<_, SIGS>::new(Blocking(&mut screen));
    frames::<H, _>(inp, &mut sink, scenes, || pools.next().unwrap());
}

fn run_dma<const H: usize>(inp: &mut Input, screen: Screen, scenes: &[Vec<u8>]) {
    let (depth, order) = (inp.u8() as usize % 3, u64::from(inp.u32()) | 1 << 40);
    let mut pools = pools::<H>();
    let mut pools = pools.iter_mut();
    let mut sink = DirtyBands::<_, SIGS>::new(Dma { screen, wire: Vec::new(), depth, order });
    frames::<H, _>(inp, &mut sink, scenes, || pools.next().unwrap());
}

/// Bands for every frame and its repeat: a sink that keeps bands is tied to
/// their borrow, so each frame draws into bands of its own, all borrowed as
/// long as the sink lives.
fn pools<const H: usize>() -> Vec<[Band<Gray8, W, H>; 3]> {
    (0..2 * MAX_FRAMES).map(|_| [const { Band::new(Gray8::new(0)) }; 3]).collect()
}

/// Draws up to `MAX_FRAMES` fuzzed frames through `sink`, each with bands
/// from `pool`, and checks each (module docs).
fn frames<'a, const H: usize, S>(
    inp: &mut Input,
    sink: &mut DirtyBands<S, SIGS>,
    scenes: &[Vec<u8>],
    mut pool: impl FnMut() -> PoolOf<'a, H>,
) where
    S: BandSink<'a, Gray8, W, Error = Fail> + Display,
{
    let height = sink.inner().screen().px.len() / W;
    let renderer = Renderer::new(height as u32, Gray8::new(0));
    let frames = 1 + inp.u8() as usize % MAX_FRAMES;
    for f in 0..frames {
        let how = inp.u8();
        let scene = &scenes[usize::from(how % 4)];
        if how & 0x40 != 0 {
            sink.force_full_frame();
        }
        // Often no failure; else at one of the frame's transfers, or past them.
        let fail_at = (how & 0x80 != 0).then(|| inp.u8() as usize % (height.div_ceil(H) + 1));
        let screen = sink.inner().screen();
        (screen.transfers, screen.fail_at) = (0, fail_at);
        let result = draw::<H, S>(&renderer, scene, pool(), sink);
        assert_eq!(sink.inner().kept(), 0, "frame {f}: a band left on the wire");
        match result {
            Err(RenderError::Target(Fail(n))) => assert_eq!(Some(n), fail_at, "frame {f}"),
            Err(e) => panic!("frame {f}: {e:?}"),
            Ok(()) => {
                let screen = sink.inner().screen();
                assert!(fail_at.is_none_or(|n| n >= screen.transfers), "frame {f}: a failure not reported");
                let want: Vec<Gray8> = (0..height * W).map(|i| pixel(scene, i % W, i / W)).collect();
                assert!(screen.px == want, "frame {f}: the display is not the frame (H = {H})");
                // The record is whole: the same frame again sends nothing.
                screen.fail_at = None;
                let sent = sink.sent_bands();
                draw::<H, S>(&renderer, scene, pool(), sink).unwrap();
                assert_eq!(sink.sent_bands(), sent, "frame {f}: an unchanged band sent again");
            }
        }
    }
}

/// The bands a frame borrows: owned by the caller for as long as the sink.
type PoolOf<'a, const H: usize> = &'a mut [Band<Gray8, W, H>; 3];

fn draw<'a, const H: usize, S>(
    renderer: &Renderer<Gray8>,
    scene: &[u8],
    bands: PoolOf<'a, H>,
    sink: &mut DirtyBands<S, SIGS>,
) -> Result<(), RenderError<Fail>>
where
    S: BandSink<'a, Gray8, W, Error = Fail>,
{
    let frame = from_fn(|view| {
        for y in view.y0()..view.y1() {
            for x in 0..W {
                view.set_pixel(x as i32, y, pixel(scene, x, y as usize));
            }
        }
        Ok(())
    });
    renderer.render_linked(frame, bands, sink)
}

/// The scene's pixel: its row's palette colour, plus the column's low bits.
fn pixel(scene: &[u8], x: usize, y: usize) -> Gray8 {
    Gray8::new(scene[y] | (x as u8 & 0x0F) << 1)
}
