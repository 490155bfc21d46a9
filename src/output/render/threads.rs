//! Bands rendered on host threads (the `std` feature): PNG export and tests
//! use every core. Scoped threads borrow the bands, the scene and the
//! target; the library allocates nothing itself.

extern crate std;

use core::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::link::Guarded;
use super::{Pass, Renderer};
use crate::band::Band;
use crate::{Error, Interpolate, RenderError};

#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
impl<C: Interpolate + Send + Sync> Renderer<C> {
    /// [`Renderer::render`] on `N` threads: thread `t` draws bands
    /// `t, t + N, t + 2N, …` into `bands[t]` with its own pass `passes[t]`
    /// (each 3D pass with its own depth band), then sends each under a lock on
    /// `target`. Bands reach the target in no fixed order, each with one
    /// `fill_contiguous` over its rectangle; the image is the same as
    /// [`Renderer::render`]'s with one of the passes.
    ///
    /// Errors as for [`Renderer::render`]; after a target error the other
    /// threads stop at their next band; after a pass error that thread's
    /// later bands are sent cleared, and the error of the topmost failing
    /// band is returned.
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::blit::Blitter;
    /// use microraster::render::from_fn;
    /// use microraster::{Band, Renderer};
    /// let mut bands = [const { Band::<BinaryColor, 4, 1>::new(BinaryColor::Off) }; 2];
    /// let diagonal = || from_fn(|view| Ok(view.set_pixel(view.y0(), view.y0(), BinaryColor::On)));
    /// let mut display = MockDisplay::new();
    /// Renderer::new(4, BinaryColor::Off).render_threads([diagonal(), diagonal()], &mut bands, &mut display).unwrap();
    /// display.assert_pattern(&["#...", ".#..", "..#.", "...#"]);
    /// ```
    pub fn render_threads<P, D, const W: usize, const H: usize, const N: usize>(
        &self,
        mut passes: [P; N],
        bands: &mut [Band<C, W, H>; N],
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        P: Pass<C, W, H> + Send,
        D: DrawTarget<Color = C> + Send,
        D::Error: Send,
    {
        let () = Threads::<N>::ONE_OR_MORE;
        let frame = self.frame_bands::<W, H>()?;
        self.fits::<W>(target.bounding_box())?;
        for pass in passes.iter_mut() {
            pass.check(self)?;
        }
        let height = frame.size().height as i32;
        let target = Mutex::new(target);
        let failed: Mutex<Option<D::Error>> = Mutex::new(None);
        // The pass error of the topmost band that failed.
        let refused: Mutex<Option<(i32, Error)>> = Mutex::new(None);
        let stop = AtomicBool::new(false);
        let work = |t: usize, band: &mut Band<C, W, H>, pass: P| {
            let mut pass = Guarded::new(pass);
            let mut y0 = (t * H) as i32;
            while y0 < height && !stop.load(Ordering::Relaxed) {
                let used = (height - y0).min(H as i32);
                let rows = &mut band.rows_mut()[..used as usize];
                pass.draw(rows, y0, self);
                let area =
                    Rectangle::new(frame.offset() + Point::new(0, y0), Size::new(W as u32, used as u32));
                // A poisoned lock means another thread panicked in the
                // target; the scope re-raises that panic, so stop here.
                let Ok(mut target) = target.lock() else { return };
                if let Err(e) = target.fill_contiguous(&area, rows.as_flattened().iter().copied()) {
                    stop.store(true, Ordering::Relaxed);
                    if let Ok(mut f) = failed.lock() {
                        f.get_or_insert(e);
                    }
                    return;
                }
                y0 = y0.saturating_add((N * H) as i32);
            }
            if let Some((y, e)) = pass.into_failure() {
                if let Ok(mut r) = refused.lock() {
                    if r.is_none_or(|(ry, _)| y < ry) {
                        *r = Some((y, e));
                    }
                }
            }
        };
        std::thread::scope(|s| {
            let mut jobs = bands.iter_mut().zip(passes).enumerate();
            // This thread takes the first share itself.
            let first = jobs.next();
            for (t, (band, pass)) in jobs {
                let work = &work;
                s.spawn(move || work(t, band, pass));
            }
            if let Some((t, (band, pass))) = first {
                work(t, band, pass);
            }
        });
        if let Some(e) = failed.into_inner().ok().flatten() {
            return Err(RenderError::Target(e));
        }
        match refused.into_inner().ok().flatten() {
            Some((_, e)) => Err(RenderError::Input(e)),
            None => Ok(()),
        }
    }
}

struct Threads<const N: usize>;

impl<const N: usize> Threads<N> {
    const ONE_OR_MORE: () = assert!(N >= 1, "render_threads needs at least one band");
}
