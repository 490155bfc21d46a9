//! The display link for async drivers (feature `async`): band *k + 1*
//! renders while the transfer of band *k* is pending, and the renderer
//! awaits that transfer only when it needs the band back.
//!
//! An [`AsyncBandSink`] gets a finished band as `&[C]` for as long as its
//! transfer future lives; the other band of the pair is drawn meanwhile. The
//! borrow checker keeps the band in flight still (the renderer holds only a
//! shared borrow of it), with no `unsafe` and no allocation.
//!
//! The overlap comes from polling order, not from a second task: the
//! transfer future is polled once (which starts a DMA transfer in an
//! embassy-style driver), then the next band is drawn on the CPU, then the
//! future is awaited. A driver that does nothing until its second poll
//! gets no overlap, only the same pixels.

use core::future::{Future, poll_fn};
use core::pin::pin;
use core::task::Poll;

use embedded_graphics_core::prelude::{Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::Pass;
use super::link::Guarded;
use super::{FrameBands, Renderer};
use crate::band::Band;
use crate::{Error, Interpolate, RenderError};

/// Where finished bands go, asynchronously: a display driver whose
/// transfer of `pixels` may still run when the next band is drawn.
///
/// [`SpiPanel`](super::SpiPanel) implements it over `embedded-hal-async`'s
/// `SpiDevice`; a driver that sends straight from `pixels` by DMA
/// implements it in a few lines.
///
/// ```
/// use core::future::Future;
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::primitives::Rectangle;
/// use microraster::render::AsyncBandSink;
/// use microraster::{Band, Renderer};
/// struct Count(usize);
/// impl AsyncBandSink<Gray8> for Count {
///     type Error = ();
///     fn send(&mut self, _: Rectangle, pixels: &[Gray8]) -> impl Future<Output = Result<(), ()>> {
///         self.0 += pixels.len(); // start the transfer here, await its end below
///         async { Ok(()) }
///     }
/// }
/// let mut bands = [const { Band::<Gray8, 8, 2>::new(Gray8::new(0)) }; 2];
/// let mut sink = Count(0);
/// let renderer = Renderer::new(5, Gray8::new(0));
/// let frame = renderer.render_async((), &mut bands, &mut sink);
/// let Some(result) = microraster::render::poll_ready(frame) else { unreachable!() };
/// assert_eq!((result, sink.0), (Ok(()), 8 * 5));
/// ```
#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
pub trait AsyncBandSink<C> {
    /// What a failed transfer reports.
    type Error;

    /// A frame of `frame.bands()` bands starts; a sink that cannot serve it
    /// says so with a typed error and the frame is not drawn.
    fn begin(&mut self, frame: &FrameBands) -> Result<(), Error> {
        let _ = frame;
        Ok(())
    }

    /// Sends one band: `pixels` row by row for the rectangle `area` of the
    /// target. The band is not touched until the future completes.
    fn send(&mut self, area: Rectangle, pixels: &[C]) -> impl Future<Output = Result<(), Self::Error>>;
}

#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
impl<C: Interpolate> Renderer<C> {
    /// [`Renderer::render_linked`] into an [`AsyncBandSink`] over two bands:
    /// band *k + 1* is drawn while band *k*'s transfer is pending. Same
    /// pixels as [`Renderer::render`] for every pass. Errors as for
    /// [`Renderer::render_linked`].
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::render::{from_fn, poll_ready};
    /// use microraster::{Band, Renderer};
    /// # struct Null;
    /// # impl microraster::render::AsyncBandSink<Gray8> for Null {
    /// #     type Error = ();
    /// #     async fn send(&mut self, _: embedded_graphics::primitives::Rectangle, _: &[Gray8]) -> Result<(), ()> { Ok(()) }
    /// # }
    /// let mut bands = [const { Band::<Gray8, 8, 4>::new(Gray8::new(0)) }; 2];
    /// let mut rows = 0;
    /// let (renderer, mut sink) = (Renderer::new(10, Gray8::new(0)), Null);
    /// let pass = from_fn(|view| {
    ///     rows += view.height();
    ///     Ok(())
    /// });
    /// assert_eq!(poll_ready(renderer.render_async(pass, &mut bands, &mut sink)), Some(Ok(())));
    /// assert_eq!(rows, 10);
    /// ```
    pub async fn render_async<P, S, const W: usize, const H: usize>(
        &self,
        pass: P,
        bands: &mut [Band<C, W, H>; 2],
        sink: &mut S,
    ) -> Result<(), RenderError<S::Error>>
    where
        P: Pass<C, W, H>,
        S: AsyncBandSink<C>,
    {
        run_async(self, pass, bands, sink).await
    }
}

/// The two-band loop: draw band 0; then for each band, start its transfer,
/// draw the next band into the other buffer, await the transfer, swap.
async fn run_async<C, P, S, const W: usize, const H: usize>(
    renderer: &Renderer<C>,
    mut pass: P,
    bands: &mut [Band<C, W, H>; 2],
    sink: &mut S,
) -> Result<(), RenderError<S::Error>>
where
    C: Interpolate,
    P: Pass<C, W, H>,
    S: AsyncBandSink<C>,
{
    let frame = renderer.frame_bands::<W, H>()?;
    pass.check(renderer)?;
    sink.begin(&frame)?;
    let mut pass = Guarded::new(pass);
    let height = frame.size().height as i32;
    let mut band = |rows: &mut [[C; W]], y0: i32| {
        let used = (height - y0).min(H as i32);
        pass.draw(&mut rows[..used as usize], y0, renderer);
        used
    };
    let [a, b] = bands;
    let (mut now, mut next) = (a.rows_mut(), b.rows_mut());
    let (mut y0, mut used) = (0, band(now, 0));
    loop {
        let area = Rectangle::new(frame.offset() + Point::new(0, y0), Size::new(W as u32, used as u32));
        let send = sink.send(area, now[..used as usize].as_flattened());
        let y1 = y0 + used;
        if y1 >= height {
            send.await.map_err(RenderError::Target)?;
            break;
        }
        let mut next_used = 0;
        overlap(send, || next_used = band(next, y1)).await.map_err(RenderError::Target)?;
        core::mem::swap(&mut now, &mut next);
        (y0, used) = (y1, next_used);
    }
    pass.finish()
}

/// Polls `transfer` once (starting it), runs `work`, then awaits `transfer`.
async fn overlap<F: Future>(transfer: F, work: impl FnOnce()) -> F::Output {
    let mut transfer = pin!(transfer);
    let mut work = Some(work);
    poll_fn(move |cx| {
        let first = transfer.as_mut().poll(cx);
        match work.take() {
            Some(work) if first.is_pending() => {
                work();
                transfer.as_mut().poll(cx)
            }
            Some(work) => {
                work();
                first
            }
            None => first,
        }
    })
    .await
}

/// Polls `future` once with a waker that does nothing: its output if it is
/// ready, `None` if it is pending. For sinks that never pend (tests, doc
/// examples, a blocking driver behind the async trait); firmware awaits the
/// frame in its executor instead.
///
/// ```
/// assert_eq!(microraster::render::poll_ready(async { 7 }), Some(7));
/// ```
#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
pub fn poll_ready<F: Future>(future: F) -> Option<F::Output> {
    let future = pin!(future);
    match future.poll(&mut core::task::Context::from_waker(core::task::Waker::noop())) {
        Poll::Ready(out) => Some(out),
        Poll::Pending => None,
    }
}
