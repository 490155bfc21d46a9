//! Bands rendered on host threads (the `std` feature): PNG export and tests
//! use every core. Scoped threads borrow the bands, the scene and the
//! target; the library allocates nothing itself.

extern crate std;

use core::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::Renderer;
use crate::band::{Band, BandView};
use crate::depth::{DepthBand, DepthFormat, DepthState};
use crate::raster3d::{Interpolation, ScreenTriangle};
use crate::{Interpolate, RenderError};

#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
impl<C: Interpolate + Send + Sync> Renderer<C> {
    /// [`Renderer::render_with`] on `N` threads: thread `t` draws bands
    /// `t, t + N, t + 2N, …` into `bands[t]` with its own `scratch[t]` (a
    /// depth band, or `()`), then sends each under a lock on `target`. Bands
    /// reach the target in no fixed order, each with one `fill_contiguous`
    /// over its rectangle; the image is the same as [`Renderer::render_with`]'s.
    ///
    /// Errors as for [`Renderer::render`]; after a target error the other
    /// threads stop at their next band.
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::blit::Blitter;
    /// use microraster::{Band, Renderer};
    /// let mut bands = [const { Band::<BinaryColor, 4, 1>::new(BinaryColor::Off) }; 2];
    /// let mut display = MockDisplay::new();
    /// Renderer::new(4, BinaryColor::Off)
    ///     .render_with_threads(&mut bands, &mut [(); 2], &mut display, |view, _, y0, _| {
    ///         view.set_pixel(y0, y0, BinaryColor::On) // the diagonal
    ///     })
    ///     .unwrap();
    /// display.assert_pattern(&["#...", ".#..", "..#.", "...#"]);
    /// ```
    pub fn render_with_threads<D, T, const W: usize, const H: usize, const N: usize>(
        &self,
        bands: &mut [Band<C, W, H>; N],
        scratch: &mut [T; N],
        target: &mut D,
        draw: impl Fn(&mut BandView<'_, C, W>, &mut T, i32, i32) + Sync,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C> + Send,
        D::Error: Send,
        T: Send,
    {
        let () = Threads::<N>::ONE_OR_MORE;
        let frame = self.frame_bands::<W, H>()?;
        self.fits::<W>(target.bounding_box())?;
        let height = frame.size().height as i32;
        let target = Mutex::new(target);
        let failed: Mutex<Option<D::Error>> = Mutex::new(None);
        let stop = AtomicBool::new(false);
        let work = |t: usize, band: &mut Band<C, W, H>, scratch: &mut T| {
            let mut y0 = (t * H) as i32;
            while y0 < height && !stop.load(Ordering::Relaxed) {
                let used = (height - y0).min(H as i32);
                let rows = &mut band.rows_mut()[..used as usize];
                let mut view = BandView::from_rows(rows, y0, Some(self.background));
                draw(&mut view, scratch, y0, y0 + used);
                let area =
                    Rectangle::new(frame.offset() + Point::new(0, y0), Size::new(W as u32, used as u32));
                // A poisoned lock means another thread panicked in the
                // target; the scope re-raises that panic, so stop here.
                let Ok(mut target) = target.lock() else { return };
                if let Err(e) = target.fill_contiguous(&area, view.pixels()) {
                    stop.store(true, Ordering::Relaxed);
                    if let Ok(mut f) = failed.lock() {
                        f.get_or_insert(e);
                    }
                    return;
                }
                y0 = y0.saturating_add((N * H) as i32);
            }
        };
        std::thread::scope(|s| {
            let mut jobs = bands.iter_mut().zip(scratch.iter_mut()).enumerate();
            // This thread takes the first share itself.
            let first = jobs.next();
            for (t, (band, scratch)) in jobs {
                let work = &work;
                s.spawn(move || work(t, band, scratch));
            }
            if let Some((t, (band, scratch))) = first {
                work(t, band, scratch);
            }
        });
        match failed.into_inner().ok().flatten() {
            Some(e) => Err(RenderError::Target(e)),
            None => Ok(()),
        }
    }

    /// [`Renderer::render_3d`] on `N` threads, each with its own band and
    /// depth band (see [`Renderer::render_with_threads`]); the same image.
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::depth::{Depth16, DepthBand, DepthState};
    /// use microraster::raster3d::Affine;
    /// use microraster::{Band, Renderer};
    /// let mut bands = [const { Band::<BinaryColor, 4, 2>::new(BinaryColor::Off) }; 2];
    /// let mut depth = [DepthBand::<Depth16, 4, 2>::zeroed(), DepthBand::zeroed()];
    /// let mut display = MockDisplay::new();
    /// Renderer::new(4, BinaryColor::Off)
    ///     .render_3d_threads::<_, _, _, 4, 4, 2, 2>(&[], &mut bands, &mut depth, DepthState::LESS_WRITE, Affine, &mut display)
    ///     .unwrap();
    /// display.assert_pattern(&["....", "....", "....", "...."]);
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn render_3d_threads<D, F, M, const S: u32, const W: usize, const H: usize, const N: usize>(
        &self,
        triangles: &[ScreenTriangle<S>],
        bands: &mut [Band<C, W, H>; N],
        depth: &mut [DepthBand<F, W, H>; N],
        state: DepthState,
        interp: M,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C> + Send,
        D::Error: Send,
        F: DepthFormat,
        DepthBand<F, W, H>: Send,
        M: Interpolation,
    {
        let _ = interp; // a value, so the call needs no turbofish
        self.render_with_threads(bands, depth, target, |view, depth, y0, y1| {
            super::band3d::<C, F, M, W, H>(view, depth, state, y0, y1).draw_all(triangles)
        })
    }
}

/// A compile-time check on the number of threads.
struct Threads<const N: usize>;

impl<const N: usize> Threads<N> {
    const ONE_OR_MORE: () = assert!(N >= 1, "render_with_threads needs at least one band");
}
