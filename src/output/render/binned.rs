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
/// `index` holds one `u16` per band of the frame (its count of primitives),
/// and one per band that each primitive touches (the primitive's number): a
/// primitive of up to `H` rows touches at most two bands of `H` rows. The
/// index may be any length (past 65,535 entries too): too short an index is
/// [`Error::CapacityExceeded`] with the length that suffices as `needed` and
/// the index's length as `capacity`. A primitive's number is a `u16`, so at
/// most 65,535 primitives: more is [`Error::CapacityExceeded`] with the
/// number of primitives as `needed` and 65,535 as `capacity`. Both before
/// anything is sent.
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
    /// Each band's count (one per band, after [`Pass::check`]), then the
    /// entries, band after band.
    index: &'a mut [u16],
    bands: usize,
    /// The band [`Pass::draw`] expects next and where its entries start:
    /// bands come in order, so each start is the last one plus a count.
    next: (usize, usize),
}

impl<'a, C, const S: u32> Binned2d<'a, C, S> {
    /// `prims`, drawn in order, with `index` for their per-band lists.
    pub fn new(prims: &'a [Primitive<C, S>], index: &'a mut [u16]) -> Self {
        Binned2d { prims, index, bands: 0, next: (0, 0) }
    }
}

/// The most primitives: a primitive's number is a `u16` entry, and so is a
/// band's count, which may be every primitive.
const MAX_PRIMS: usize = u16::MAX as usize;

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
        let capacity = self.index.len();
        if self.prims.len() > MAX_PRIMS {
            return Err(Error::CapacityExceeded { needed: self.prims.len(), capacity: MAX_PRIMS });
        }
        // The length that suffices: every primitive's bands counted.
        let prims = self.prims;
        let too_small = || {
            let all = prims.iter().filter_map(|p| band_range::<H>(p.rows(), height));
            Error::CapacityExceeded {
                needed: all.fold(bands, |n, (lo, hi)| n.saturating_add(hi - lo + 1)),
                capacity,
            }
        };
        if bands > capacity {
            return Err(too_small());
        }
        // Counts per band (at most the primitives: below 2^16).
        let (counts, entries) = self.index.split_at_mut(bands);
        counts.fill(0);
        let mut total = 0usize;
        for p in self.prims {
            if let Some((lo, hi)) = band_range::<H>(p.rows(), height) {
                if hi - lo + 1 > entries.len() - total {
                    return Err(too_small());
                }
                total += hi - lo + 1;
                for count in &mut counts[lo..=hi] {
                    *count += 1;
                }
            }
        }
        // Filled in order (stable), a run of bands at a time whose entries
        // number at most 2^16 - 1, so that each band's fill position,
        // counted from the run's first entry, fits its `u16` (one run unless
        // the index is longer than that, so one pass over the primitives).
        let (mut first, mut base) = (0, 0);
        while first < bands {
            let (mut last, mut run) = (first, 0usize);
            while last < bands && run + usize::from(counts[last]) <= MAX_PRIMS {
                run += usize::from(counts[last]);
                last += 1;
            }
            fill_run::<C, S, H>(self.prims, height, &mut counts[first..last], first, &mut entries[base..]);
            (first, base) = (last, base + run);
        }
        self.bands = bands;
        self.next = (0, 0);
        Ok(())
    }

    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        let k = band.y0().max(0) as usize / H.max(1);
        let (counts, entries) = self.index.split_at(self.bands.min(self.index.len()));
        let start = match self.next {
            (next, start) if next == k => start,
            // Out of order (not the band loop): the counts before `k` summed.
            _ => counts.iter().take(k).map(|&c| usize::from(c)).sum(),
        };
        let count = counts.get(k).map_or(0, |&c| usize::from(c));
        self.next = (k + 1, start + count);
        let list = entries.get(start..start + count).unwrap_or(&[]);
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

/// Writes the entries of bands `first..first + counts.len()` (whose counts
/// sum to at most 2^16 - 1) into `entries`, band after band, each band's
/// primitives in their order; `counts` are the same when it returns.
fn fill_run<C: Interpolate, const S: u32, const H: usize>(
    prims: &[Primitive<C, S>],
    height: u32,
    counts: &mut [u16],
    first: usize,
    entries: &mut [u16],
) {
    // Starts, then each start moves to its end as its band fills.
    let mut start = 0u16;
    for c in counts.iter_mut() {
        (start, *c) = (start + *c, start);
    }
    let after = first + counts.len();
    for (i, p) in prims.iter().enumerate() {
        if let Some((lo, hi)) = band_range::<H>(p.rows(), height) {
            if lo < after && hi >= first {
                for end in &mut counts[lo.max(first) - first..=hi.min(after - 1) - first] {
                    entries[usize::from(*end)] = i as u16; // i < 2^16 - 1: checked
                    *end += 1;
                }
            }
        }
    }
    // Ends back to counts.
    let mut start = 0u16;
    for c in counts.iter_mut() {
        (start, *c) = (*c, *c - start);
    }
}
