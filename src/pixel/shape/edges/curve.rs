//! Curves' chords in a windowed list: the ones that miss the window are
//! found on their `f32` rows and neither snapped nor stored, so a band of a
//! large curve costs its chords near the band, not all of them. The stored
//! edges are exactly those `line_to` would store (the window would drop the
//! culled ones once snapped); `tests.rs` checks it on random contours.

use super::{EdgeList, snap};
use crate::Error;

impl<const N: usize> EdgeList<N> {
    /// [`Self::line_to`] for the points of a flattened curve: in a windowed
    /// list, a chord whose `f32` rows lie wholly outside the window (by more
    /// than the half subpixel snapping can move them) is neither snapped nor
    /// stored, as the window would drop it once snapped. Its end is snapped
    /// only if a later edge starts there, so the stored edges are exactly
    /// [`Self::line_to`]'s. A band of a large curve snaps the chords near
    /// its rows, not all of them.
    #[inline(always)]
    pub(crate) fn curve_to(&mut self, x: f32, y: f32) -> Result<(), Error> {
        let side = self.side(x, y);
        if side != 0 && side == self.last_side && self.open && self.cull {
            (self.last_f, self.last_snapped) = ((x, y), false);
            return Ok(());
        }
        self.curve_point(x, y, side)
    }

    /// [`Self::curve_to`]'s kept point, out of line so that its test
    /// stays in the curve's loop.
    #[inline(never)]
    fn curve_point(&mut self, x: f32, y: f32, side: i8) -> Result<(), Error> {
        self.line_to(x, y)?;
        self.last_side = side;
        Ok(())
    }

    /// Whether [`Self::curve_to`] may cull chords: a window is set and no
    /// group member needs every edge's area term.
    pub(crate) fn culls(&self) -> bool {
        self.cull
    }

    /// Where a point lies against the window, for [`Self::curve_to`]: `-1`
    /// above it, `1` below it (with its `16·y` at least 1 past its rows), `0`
    /// otherwise, and always when the point is not one
    /// `snap` takes well inside its ±2^24 px (NaN, infinities and refused
    /// points go on to its error).
    #[inline(always)]
    pub(super) fn side(&self, x: f32, y: f32) -> i8 {
        const SAFE: f32 = 1.0e6;
        let sy = y * 16.0;
        if !(x.abs() < SAFE && y.abs() < SAFE) {
            0
        } else if sy <= self.win_f.0 {
            -1
        } else if sy >= self.win_f.1 {
            1
        } else {
            0
        }
    }

    /// The current point, snapped (after [`Self::curve_to`] culled the chord
    /// to it, snapped now from the same `f32` point, so the same value).
    #[inline(always)]
    pub(super) fn last_point(&mut self) -> Result<(i32, i32), Error> {
        if !self.last_snapped {
            self.snap_last()?;
        }
        Ok(self.last)
    }

    /// Out of line: only the first chord after culled ones comes here.
    #[inline(never)]
    fn snap_last(&mut self) -> Result<(), Error> {
        self.last = snap(self.last_f.0, self.last_f.1)?;
        self.last_snapped = true;
        Ok(())
    }
}
