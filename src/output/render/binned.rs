//! 2D primitives read only in the bands they touch, through an index the
//! caller owns ([`Binned2d`]).
//!
//! # Why
//! A slice of primitives as a [`Pass`] is read whole in every band: each
//! primitive's rows are compared with the band's, and for a scene of many
//! small primitives (the report's scene "tiny": 10,000 triangles of a few
//! pixels, 15 bands) that re-reading of every primitive in every band is
//! about a third of the frame on the host. Here the frame's first step
//! sorts the primitives' indices by band (a counting sort, stable), and
//! each band then draws its own list.
//!
//! # Same pixels
//! A band draws the primitives that touch it in their order in the slice,
//! exactly as the slice pass does (it skips the others, which would draw
//! nothing there), so the frame is the same, pixel for pixel (tested).

use super::{Pass, Renderer};
use crate::band::{BandView, LazyClear};
use crate::{Error, Interpolate, Primitive};

/// 2D primitives drawn band by band through `index`, a buffer the caller
/// owns: each band reads only the primitives that touch it (module docs).
///
/// `index` holds one `u16` per band of the frame, and one per band that
/// each primitive touches: a primitive of up to `H` rows touches
/// at most two bands of `H` rows. Too short an index, or more than 65,536
/// primitives, is [`Error::CapacityExceeded`] before anything is sent.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::render::Binned2d;
/// use microraster::{Band, Primitive, Renderer, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
/// let mut band = Band::<BinaryColor, 4, 2>::new(BinaryColor::Off);
/// // Two bands (2 entries) and the triangle in both (2).
/// let mut index = [0u16; 4];
/// let mut display = MockDisplay::new();
/// Renderer::new(4, BinaryColor::Off).render(Binned2d::new(&scene, &mut index), &mut band, &mut display)?;
/// display.assert_pattern(&["###.", "##..", "#...", "...."]);
/// let short = Renderer::new(4, BinaryColor::Off).render(Binned2d::new(&scene, &mut index[..3]), &mut band, &mut MockDisplay::new());
/// assert_eq!(short, Err(microraster::Error::CapacityExceeded { needed: 4, capacity: 3 }.into()));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
#[derive(Debug)]
pub struct Binned2d<'a, C, const S: u32> {
    prims: &'a [Primitive<C, S>],
    /// Bucket ends (one per band, after [`Pass::check`]), then the entries.
    index: &'a mut [u16],
    bands: usize,
}

impl<'a, C, const S: u32> Binned2d<'a, C, S> {
    /// `prims`, drawn in order, with `index` for their per-band lists.
    pub fn new(prims: &'a [Primitive<C, S>], index: &'a mut [u16]) -> Self {
        Binned2d { prims, index, bands: 0 }
    }
}

/// The bands `lo..=hi` of `H` rows that frame rows `first..=last` of a
/// frame `height` rows tall touch, if any. Inlined with `H` a constant:
/// its divisions are shifts for a power of two (a call with `H` as an
/// argument was a tenth of the tiny scene's frame on the host).
#[inline(always)]
fn band_range<const H: usize>((first, last): (i32, i32), height: u32) -> Option<(usize, usize)> {
    let (lo, hi) = (first.max(0), last.min(height as i32 - 1));
    (lo <= hi).then(|| (lo as usize / H.max(1), hi as usize / H.max(1)))
}

impl<C: Interpolate, const S: u32, const W: usize, const H: usize> Pass<C, W, H> for Binned2d<'_, C, S> {
    // As the slice pass: rows cleared as they are first written.
    const CLEARS: bool = false;

    /// Sorts the primitives into their bands' lists.
    fn check(&mut self, renderer: &Renderer<C>) -> Result<(), Error> {
        let height = renderer.height();
        let bands = renderer.frame_bands::<W, H>()?.bands();
        let capacity = self.index.len().min(u16::MAX as usize);
        if self.prims.len() > 1 << 16 {
            return Err(Error::CapacityExceeded { needed: self.prims.len(), capacity: 1 << 16 });
        }
        // The length that suffices: every primitive's bands counted.
        let prims = self.prims;
        let too_small = || {
            let all = prims.iter().filter_map(|p| band_range::<H>(p.rows(), height));
            Error::CapacityExceeded {
                needed: bands + all.map(|(lo, hi)| hi - lo + 1).sum::<usize>(),
                capacity,
            }
        };
        if bands > capacity {
            return Err(too_small());
        }
        // Counts per band, then each band's end: entries start after them.
        let (ends, entries) = self.index.split_at_mut(bands);
        ends.fill(0);
        let mut total = bands;
        for p in self.prims {
            if let Some((lo, hi)) = band_range::<H>(p.rows(), height) {
                if total + hi - lo + 1 > capacity {
                    return Err(too_small());
                }
                total += hi - lo + 1;
                for count in &mut ends[lo..=hi] {
                    *count += 1; // at most the entries counted: below 2^16
                }
            }
        }
        // Starts, then filled in order (stable): each start moves to its end.
        let mut start = 0u16;
        for e in ends.iter_mut() {
            (start, *e) = (start + *e, start);
        }
        for (i, p) in self.prims.iter().enumerate() {
            if let Some((lo, hi)) = band_range::<H>(p.rows(), height) {
                for end in &mut ends[lo..=hi] {
                    entries[usize::from(*end)] = i as u16;
                    *end += 1;
                }
            }
        }
        self.bands = bands;
        Ok(())
    }

    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        let k = band.y0().max(0) as usize / H.max(1);
        let (ends, entries) = self.index.split_at(self.bands.min(self.index.len()));
        let start = if k == 0 { 0 } else { ends.get(k - 1).copied().unwrap_or(0) };
        let end = ends.get(k).copied().unwrap_or(0);
        let list = entries.get(usize::from(start)..usize::from(end)).unwrap_or(&[]);
        let mut view = LazyClear::<C, W, H>::new(band, renderer.background());
        super::pass::draw_prims(
            list.iter().filter_map(|&i| self.prims.get(usize::from(i))),
            &mut view,
            renderer,
        );
        view.finish();
        Ok(())
    }
}
