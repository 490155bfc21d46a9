//! The display link: the band loop hands each finished band to a
//! [`BandSink`], which may still be sending it while the next band renders.
//!
//! A band is lent to the sink by value ([`Lent`], which holds the only
//! mutable borrow of the band's rows) and comes back only when the sink
//! returns it, from [`BandSink::submit`] (sent already, or skipped) or from
//! [`BandSink::reclaim`] (the transfer finished). The renderer cannot touch a
//! band in flight because it does not hold it: the borrow checker, not a
//! protocol, keeps the pixels still while DMA reads them, with no `unsafe`.
//!
//! With two bands ([`Renderer::render_linked`]) band *k + 1* renders while
//! band *k* is on the wire; with one (every older entry point, through
//! [`Blocking`]) the loop is the plain render-then-send loop.

use core::convert::Infallible;

use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::Pass;
use super::Renderer;
use crate::band::{Band, BandView};
use crate::{Error, Interpolate, MAX_FRAME_DIM, RenderError};

/// A finished band lent to a [`BandSink`]: frame rows [`Lent::area`], pixels
/// row by row in [`Lent::pixels`]. Only the renderer makes one; the sink
/// gives it back when the band may be drawn into again.
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
/// use microraster::render::{BandSink, FrameBands, Lent};
/// /// Records the frame and where each band goes.
/// struct Log { areas: [Rectangle; 3], frame: Option<FrameBands> }
/// impl<'a> BandSink<'a, Gray8, 8> for Log {
///     type Error = Infallible;
///     fn begin(&mut self, frame: &FrameBands) -> Result<(), microraster::Error> {
///         self.frame = Some(*frame);
///         Ok(())
///     }
///     fn submit(&mut self, band: Lent<'a, Gray8, 8>) -> Result<Option<Lent<'a, Gray8, 8>>, Infallible> {
///         assert_eq!(band.pixels().len(), band.area().size.width as usize * band.area().size.height as usize);
///         self.areas[band.index()] = band.area();
///         Ok(Some(band)) // sent synchronously: give it back
///     }
/// }
/// let mut bands = [const { microraster::Band::<Gray8, 8, 2>::new(Gray8::new(0)) }; 2];
/// let mut log = Log { areas: [Rectangle::zero(); 3], frame: None };
/// microraster::Renderer::new(5, Gray8::new(0)).render_linked((), &mut bands, &mut log).unwrap();
/// assert_eq!(log.areas[2], Rectangle::new(Point::new(0, 4), Size::new(8, 1))); // the last band: one row
/// let f = log.frame.unwrap();
/// assert_eq!((f.offset(), f.size(), f.band_rows(), f.bands()), (Point::zero(), Size::new(8, 5), 2, 3));
/// ```
pub struct Lent<'a, C, const W: usize> {
    rows: &'a mut [[C; W]],
    used: usize,
    area: Rectangle,
    index: usize,
}

impl<C: Copy, const W: usize> Lent<'_, C, W> {
    /// The band's rectangle on the target (the renderer's offset applied).
    pub fn area(&self) -> Rectangle {
        self.area
    }

    /// Which band of the frame this is: 0 at the top.
    pub fn index(&self) -> usize {
        self.index
    }

    /// The pixels, row by row, as `fill_contiguous` expects them.
    pub fn pixels(&self) -> &[C] {
        self.rows[..self.used].as_flattened()
    }
}

/// The bands of one frame, told to the sink before the first band
/// ([`BandSink::begin`]).
///
/// See [`Lent`] for a sink that reads it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameBands {
    offset: Point,
    size: Size,
    band_rows: u32,
}

impl FrameBands {
    /// Where the frame's top-left pixel goes on the target.
    pub fn offset(&self) -> Point {
        self.offset
    }

    /// Frame width and height in pixels.
    pub fn size(&self) -> Size {
        self.size
    }

    /// Rows per band (the last band may have fewer).
    pub fn band_rows(&self) -> u32 {
        self.band_rows
    }

    /// Number of bands in the frame.
    pub fn bands(&self) -> usize {
        self.size.height.div_ceil(self.band_rows) as usize
    }
}

/// Where finished bands go: a display driver that may keep sending a band
/// after [`BandSink::submit`] returns (DMA), or skip it ([`DirtyBands`](super::DirtyBands)).
///
/// The contract: `submit` either returns the band (done with it) or keeps
/// it; `reclaim` waits until a band it keeps is done and returns it, in any
/// order, and returns `None` only when it keeps none. The renderer calls
/// `reclaim` when it needs a buffer and at the end of the frame, so when
/// `render_*` returns every band is back and every transfer finished. A
/// failed `submit` keeps no band, a failed `reclaim` drops the band whose
/// transfer failed; the renderer still reclaims the others.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::render::{BandSink, Lent};
/// /// Keeps the last band "on the wire" until the renderer needs it back.
/// struct Dma<'a> { wire: Option<Lent<'a, Gray8, 8>>, sent: usize }
/// impl<'a> BandSink<'a, Gray8, 8> for Dma<'a> {
///     type Error = ();
///     fn submit(&mut self, band: Lent<'a, Gray8, 8>) -> Result<Option<Lent<'a, Gray8, 8>>, ()> {
///         self.sent += band.pixels().len(); // start the transfer here
///         Ok(self.wire.replace(band)) // an earlier band is done: hand it back
///     }
///     fn reclaim(&mut self) -> Result<Option<Lent<'a, Gray8, 8>>, ()> {
///         Ok(self.wire.take()) // wait for the transfer here
///     }
/// }
/// let mut bands = [const { microraster::Band::<Gray8, 8, 2>::new(Gray8::new(0)) }; 2];
/// let mut sink = Dma { wire: None, sent: 0 };
/// microraster::Renderer::new(5, Gray8::new(0)).render_linked((), &mut bands, &mut sink).unwrap();
/// assert_eq!(sink.sent, 8 * 5);
/// ```
pub trait BandSink<'a, C, const W: usize> {
    /// What a failed transfer reports.
    type Error;

    /// A frame of `frame.bands()` bands starts. A sink that cannot serve
    /// it (for example [`DirtyBands`](super::DirtyBands) with too few
    /// signatures) says so with a typed error and the frame is not drawn.
    fn begin(&mut self, frame: &FrameBands) -> Result<(), Error> {
        let _ = frame;
        Ok(())
    }

    /// Takes a finished band: returns it if the sink is done with it (sent
    /// synchronously, or skipped), or keeps it while it is sent.
    #[allow(clippy::type_complexity)]
    fn submit(&mut self, band: Lent<'a, C, W>) -> Result<Option<Lent<'a, C, W>>, Self::Error>;

    /// Waits until a band the sink keeps is sent and returns it; `None` if it
    /// keeps none. A sink that never keeps a band needs only this default.
    #[allow(clippy::type_complexity)]
    fn reclaim(&mut self) -> Result<Option<Lent<'a, C, W>>, Self::Error> {
        Ok(None)
    }
}

/// The blocking adaptor: any embedded-graphics `DrawTarget` as a
/// [`BandSink`], each band sent with one `fill_contiguous` before `submit`
/// returns (today's behaviour).
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::render::Blocking;
/// use microraster::{Band, Renderer};
/// let mut bands = [const { Band::<BinaryColor, 4, 2>::new(BinaryColor::Off) }; 2];
/// let mut display = MockDisplay::new();
/// Renderer::new(4, BinaryColor::Off)
///     .render_linked((), &mut bands, &mut Blocking(&mut display))
///     .unwrap();
/// display.assert_pattern(&["....", "....", "....", "...."]);
/// ```
pub struct Blocking<'d, D>(pub &'d mut D);

impl<'a, D: DrawTarget, const W: usize> BandSink<'a, D::Color, W> for Blocking<'_, D> {
    type Error = D::Error;

    fn submit(&mut self, band: Lent<'a, D::Color, W>) -> Result<Option<Lent<'a, D::Color, W>>, D::Error> {
        self.0.fill_contiguous(&band.area, band.pixels().iter().copied())?;
        Ok(Some(band))
    }
}

/// A sink that sends nothing: renders a frame only for its side effects
/// (tests, timing).
impl<'a, C, const W: usize> BandSink<'a, C, W> for () {
    type Error = Infallible;

    fn submit(&mut self, band: Lent<'a, C, W>) -> Result<Option<Lent<'a, C, W>>, Infallible> {
        Ok(Some(band))
    }
}

impl<C: Interpolate> Renderer<C> {
    /// [`Renderer::render`] over `N ≥ 2` bands into a [`BandSink`]: band
    /// *k + 1* renders while the sink still sends band *k*. Same pixels as
    /// [`Renderer::render`] for every pass and band height. One band is a
    /// compile error (use [`Renderer::render`]). A 3D pass's depth band
    /// serves every band: only the band being drawn uses it.
    ///
    /// Errors as for [`Renderer::render`] (the sink's instead of the
    /// target's), plus [`RenderError::Input`] with what [`BandSink::begin`]
    /// refuses, or [`Error::InvalidParameter`] if the sink breaks its
    /// contract (keeps a band but `reclaim` returns `None`).
    ///
    /// After [`RenderError::Target`] the bands before the failed transfer
    /// were sent, the failed band may be partly shown, the later bands were
    /// not sent (the previous frame shows there); the transfers still
    /// running were waited for (their errors dropped), so none finishes in
    /// a later frame. To repair the display, render the frame again (a
    /// [`DirtyBands`](super::DirtyBands) sink resends the failed band).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::render::Blocking;
    /// use microraster::{Band, Primitive, Renderer, SubPoint, Triangle};
    /// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
    /// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
    /// let mut bands = [const { Band::<BinaryColor, 4, 1>::new(BinaryColor::Off) }; 2];
    /// let mut display = MockDisplay::new();
    /// let r = Renderer::new(4, BinaryColor::Off);
    /// r.render_linked(&scene, &mut bands, &mut Blocking(&mut display)).unwrap();
    /// display.assert_pattern(&["###.", "##..", "#...", "...."]);
    /// ```
    pub fn render_linked<'a, P, S, const W: usize, const H: usize, const N: usize>(
        &self,
        pass: P,
        bands: &'a mut [Band<C, W, H>; N],
        sink: &mut S,
    ) -> Result<(), RenderError<S::Error>>
    where
        P: Pass<C, W, H>,
        S: BandSink<'a, C, W>,
    {
        let () = Pool::<N>::TWO_OR_MORE;
        run(self, pass, bands, sink)
    }

    /// The frame's bands, if the renderer's size and offset are valid for
    /// `W × H` bands.
    pub(crate) fn frame_bands<const W: usize, const H: usize>(&self) -> Result<FrameBands, Error> {
        if self.height == 0 || self.height > MAX_FRAME_DIM {
            return Err(Error::InvalidFrameSize);
        }
        // Every band rectangle must be addressable: offset + frame within i32.
        if self.offset.x.checked_add(W as i32).is_none()
            || self.offset.y.checked_add(self.height as i32).is_none()
        {
            return Err(Error::CoordinateOutOfRange);
        }
        Ok(FrameBands { offset: self.offset, size: Size::new(W as u32, self.height), band_rows: H as u32 })
    }
}

/// A compile-time check on the number of bands of the double-banded loop.
struct Pool<const N: usize>;

impl<const N: usize> Pool<N> {
    const TWO_OR_MORE: () =
        assert!(N >= 2, "the linked band loop needs at least two bands (one: Renderer::render)");
}

/// The band loop over a pool of bands (one or more) into `sink`.
pub(crate) fn run<'a, C, P, S, const W: usize, const H: usize>(
    renderer: &Renderer<C>,
    mut pass: P,
    bands: &'a mut [Band<C, W, H>],
    sink: &mut S,
) -> Result<(), RenderError<S::Error>>
where
    C: Interpolate,
    P: Pass<C, W, H>,
    S: BandSink<'a, C, W>,
{
    let frame = renderer.frame_bands::<W, H>()?;
    pass.check(renderer)?;
    sink.begin(&frame)?;
    let mut pass = Guarded::new(pass);
    let height = frame.size.height as i32;
    let mut fresh = bands.iter_mut();
    // A band the sink handed back from `submit`: the next one to draw into.
    let mut spare: Option<&'a mut [[C; W]]> = None;
    let mut in_flight = 0usize;
    let (mut y0, mut index) = (0i32, 0usize);
    while y0 < height {
        let rows = match spare.take().or_else(|| fresh.next().map(|b| b.rows_mut())) {
            Some(rows) => rows,
            None => {
                in_flight -= 1;
                match reclaim(sink) {
                    Ok(rows) => rows,
                    Err(e) => return Err(drain(sink, in_flight, e)),
                }
            }
        };
        let used = (height - y0).min(H as i32);
        pass.draw(&mut rows[..used as usize], y0, renderer);
        let area = Rectangle::new(frame.offset + Point::new(0, y0), Size::new(W as u32, used as u32));
        let band = Lent { rows, used: used as usize, area, index };
        match sink.submit(band) {
            Ok(Some(back)) => spare = Some(back.rows),
            Ok(None) => in_flight += 1,
            Err(e) => return Err(drain(sink, in_flight, RenderError::Target(e))),
        }
        (y0, index) = (y0 + used, index + 1);
    }
    // Every transfer finishes before the frame returns.
    while in_flight > 0 {
        in_flight -= 1;
        if let Err(e) = reclaim(sink) {
            return Err(drain(sink, in_flight, e));
        }
    }
    pass.finish()
}

/// After the frame's error `first`: waits for the `in_flight` transfers
/// still running (none may finish over a later frame), errors dropped,
/// until the sink says it keeps none.
fn drain<'a, C: 'a, S: BandSink<'a, C, W>, const W: usize>(
    sink: &mut S,
    in_flight: usize,
    first: RenderError<S::Error>,
) -> RenderError<S::Error> {
    for _ in 0..in_flight {
        if let Ok(None) = sink.reclaim() {
            break;
        }
    }
    first
}

/// A pass that stops drawing at its first error: later bands are cleared
/// to the background, and the error is the frame's result.
pub(crate) struct Guarded<P> {
    pass: P,
    /// The first error, with the frame row of the band it came from.
    failed: Option<(i32, Error)>,
}

impl<P> Guarded<P> {
    pub(crate) fn new(pass: P) -> Self {
        Guarded { pass, failed: None }
    }

    /// Draws rows `rows` at frame row `y0`, cleared first if the pass asks
    /// (or after an error, when the pass no longer writes them).
    pub(crate) fn draw<C: Interpolate, const W: usize, const H: usize>(
        &mut self,
        rows: &mut [[C; W]],
        y0: i32,
        renderer: &Renderer<C>,
    ) where
        P: Pass<C, W, H>,
    {
        let clear = P::CLEARS || self.failed.is_some();
        let mut view = BandView::from_rows(rows, y0, clear.then_some(renderer.background()));
        if self.failed.is_none() {
            // The failing band goes out as drawn (a pass that does not
            // clear writes every pixel even when it fails).
            if let Err(e) = self.pass.draw(&mut view, renderer) {
                self.failed = Some((y0, e));
            }
        }
    }

    /// The first error and the frame row of its band, if any.
    pub(crate) fn into_failure(self) -> Option<(i32, Error)> {
        self.failed
    }

    /// The frame's result.
    pub(crate) fn finish<E>(self) -> Result<(), RenderError<E>> {
        self.into_failure().map_or(Ok(()), |(_, e)| Err(RenderError::Input(e)))
    }
}

/// A band back from the sink, or the typed error of a sink that kept one
/// and returned none.
fn reclaim<'a, C, S, const W: usize>(sink: &mut S) -> Result<&'a mut [[C; W]], RenderError<S::Error>>
where
    S: BandSink<'a, C, W>,
{
    match sink.reclaim().map_err(RenderError::Target)? {
        Some(band) => Ok(band.rows),
        None => Err(Error::InvalidParameter(crate::Param::BandSink).into()),
    }
}
