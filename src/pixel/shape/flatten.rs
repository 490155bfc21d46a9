//! Curves to chords.
//!
//! An arc of radius `r` is cut into chords of equal angle `θ`; a chord stays
//! within `r·(1 − cos(θ/2))` of the arc, and `1 − cos x ≤ x²/2`, so
//! `θ = 2·√(2·TOLERANCE/r)` keeps every chord within [`TOLERANCE`] of the
//! curve: a full circle takes `⌈π·√(r / (2·TOLERANCE))⌉` chords. Chords lie
//! inside the curve (vertices on it). An ellipse is the affine image of a
//! circle, so its chords are within `max(rx, ry)·(1 − cos(θ/2))`: the same
//! count with `r = max(rx, ry)`.
//!
//! The count is capped at [`MAX_SEGMENTS`] a full turn (so memory stays
//! bounded): the tolerance holds up to `r = 2·TOLERANCE/(π/MAX_SEGMENTS)² ≈
//! 415 px`; beyond that the error is `r·(1 − cos(π/MAX_SEGMENTS))`, 0.3 px at
//! `r = 1000` (a documented clamp). Vertices are then snapped to 1/16 px,
//! which moves each by at most `√2/32 ≈ 0.044` px.

use crate::Error;
use crate::math::Scalar;
use crate::shape::EdgeList;
use core::f32::consts::{PI, TAU};

/// Largest distance (px) between a flattened curve and the true curve, below
/// the [`MAX_SEGMENTS`] cap.
///
/// ```
/// use core::f32::consts::{PI, TAU};
/// use microraster::shape::flatten::{TOLERANCE, segments};
/// for r in [0.5f32, 3.0, 10.0, 100.0, 400.0] {
///     // n equal chords of a circle: each is r·(1 − cos(π/n)) from its arc at most.
///     let n = segments(r, TAU) as f32;
///     let sagitta = r * (1.0 - (PI / n).cos());
///     assert!(sagitta <= TOLERANCE, "r {r}: {sagitta}");
/// }
/// ```
pub const TOLERANCE: f32 = 0.125;

/// Most chords for a full turn.
///
/// ```
/// use core::f32::consts::{PI, TAU};
/// use microraster::shape::flatten::{MAX_SEGMENTS, TOLERANCE, segments};
/// assert_eq!(segments(1000.0, TAU), MAX_SEGMENTS);
/// assert_eq!(segments(1000.0, TAU / 2.0), MAX_SEGMENTS / 2);
/// // Past r ≈ 415 px the cap wins over the tolerance: 0.3 px at r = 1000.
/// let err = 1000.0 * (1.0 - (PI / MAX_SEGMENTS as f32).cos());
/// assert!(err > TOLERANCE && err < 0.31, "{err}");
/// ```
pub const MAX_SEGMENTS: u32 = 128;

/// Chords for an arc of radius `r` (px) sweeping `sweep` radians (at least
/// one, at most [`MAX_SEGMENTS`] a full turn).
///
/// ```
/// use microraster::shape::flatten::segments;
/// use core::f32::consts::TAU;
/// assert_eq!(segments(100.0, TAU), 63); // ⌈π·√(100/0.25)⌉
/// assert_eq!(segments(100.0, TAU / 4.0), 16);
/// assert_eq!(segments(1e6, TAU), 128);
/// ```
pub fn segments(r: f32, sweep: f32) -> u32 {
    let full = PI * Scalar::sqrt(r.max(0.0) / (2.0 * TOLERANCE));
    let full = if full < MAX_SEGMENTS as f32 { full } else { MAX_SEGMENTS as f32 };
    let turns = Scalar::abs(sweep).min(TAU) / TAU;
    let n = full * turns;
    // Round up; `as` saturates and NaN (never reaching here) gives 0.
    let k = n as u32;
    let k = if (k as f32) < n { k + 1 } else { k };
    k.clamp(1, MAX_SEGMENTS)
}

/// The `n + 1` points of an elliptic arc (centre `c`, radii `rx, ry`) from
/// angle `start`, sweeping `sweep` (radians, positive clockwise on screen),
/// cut into `n = segments(max(rx, ry), sweep)` chords.
pub(crate) fn arc_points<E>(
    c: (f32, f32),
    radii: (f32, f32),
    start: f32,
    sweep: f32,
    point: impl FnMut(f32, f32) -> Result<(), E>,
) -> Result<(), E> {
    let sweep = sweep.clamp(-TAU, TAU);
    let ends = (Scalar::sin_cos(start), Scalar::sin_cos(start + sweep));
    arc_points_between(c, radii, ends, sweep, point)
}

/// As [`arc_points`], with the `(sin, cos)` of both end angles given: the
/// end points are exactly those, so arcs that meet at an angle meet at the
/// same point.
pub(crate) fn arc_points_between<E>(
    c: (f32, f32),
    (rx, ry): (f32, f32),
    (from, to): ((f32, f32), (f32, f32)),
    sweep: f32,
    point: impl FnMut(f32, f32) -> Result<(), E>,
) -> Result<(), E> {
    let steps = Steps::new(rx.max(ry), sweep);
    arc_points_stepped(c, (rx, ry), (from, to), steps, point)
}

/// The chord count of an arc and the rotation of one chord: all an arc's
/// inner points depend on besides its start, so arcs of one radius and sweep
/// (a rounded rectangle's corners) share one.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Steps {
    n: u32,
    // (sin, cos) of one chord's angle.
    step: (f32, f32),
}

impl Steps {
    /// For an arc of radius `r` sweeping `sweep` (already clamped to a turn).
    pub(crate) fn new(r: f32, sweep: f32) -> Self {
        let n = segments(r, sweep);
        Steps { n, step: Scalar::sin_cos(sweep / n as f32) }
    }
}

/// [`arc_points_between`] with its [`Steps`] given.
fn arc_points_stepped<E>(
    c: (f32, f32),
    (rx, ry): (f32, f32),
    (from, to): ((f32, f32), (f32, f32)),
    Steps { n, step: (sd, cd) }: Steps,
    mut point: impl FnMut(f32, f32) -> Result<(), E>,
) -> Result<(), E> {
    // Inner points by rotating the unit vector (one sin_cos per arc instead
    // of per point; drift below 1e-5 px per 100 px of radius over 128 steps).
    let (mut s, mut co) = from;
    point(c.0 + rx * co, c.1 + ry * s)?;
    for _ in 1..n {
        (co, s) = (co * cd - s * sd, s * cd + co * sd);
        point(c.0 + rx * co, c.1 + ry * s)?;
    }
    point(c.0 + rx * to.1, c.1 + ry * to.0)
}

/// [`arc_points`] as points of the contour being built in `e`: through
/// [`EdgeList::curve_to`] where the list culls chords outside its window,
/// [`EdgeList::line_to`] (the same edges, no test a point) where it does not.
pub(crate) fn arc_edges<const N: usize>(
    e: &mut EdgeList<N>,
    c: (f32, f32),
    radii: (f32, f32),
    start: f32,
    sweep: f32,
) -> Result<(), Error> {
    let sweep = sweep.clamp(-TAU, TAU);
    let ends = (Scalar::sin_cos(start), Scalar::sin_cos(start + sweep));
    arc_edges_between(e, c, radii, ends, sweep)
}

/// [`arc_points_between`] into `e`, as [`arc_edges`].
pub(crate) fn arc_edges_between<const N: usize>(
    e: &mut EdgeList<N>,
    c: (f32, f32),
    radii: (f32, f32),
    ends: ((f32, f32), (f32, f32)),
    sweep: f32,
) -> Result<(), Error> {
    arc_edges_stepped(e, c, radii, ends, Steps::new(radii.0.max(radii.1), sweep))
}

/// [`arc_edges_between`] with the arc's [`Steps`] given (the same points as
/// `arc_edges_between` for the sweep and radii they were made for).
pub(crate) fn arc_edges_stepped<const N: usize>(
    e: &mut EdgeList<N>,
    c: (f32, f32),
    radii: (f32, f32),
    ends: ((f32, f32), (f32, f32)),
    steps: Steps,
) -> Result<(), Error> {
    if e.culls() {
        arc_points_stepped(c, radii, ends, steps, |x, y| e.curve_to(x, y))
    } else {
        arc_points_stepped(c, radii, ends, steps, |x, y| e.line_to(x, y))
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// Distance from the circle to the farthest chord point, in f64.
    fn worst_sagitta(r: f32, sweep: f32) -> f64 {
        let mut pts = Vec::new();
        arc_points::<()>((0.0, 0.0), (r, r), 0.3, sweep, |x, y| {
            pts.push((f64::from(x), f64::from(y)));
            Ok(())
        })
        .unwrap();
        let mut worst = 0.0f64;
        for w in pts.windows(2) {
            for k in 0..=16 {
                let t = k as f64 / 16.0;
                let (x, y) = (w[0].0 + t * (w[1].0 - w[0].0), w[0].1 + t * (w[1].1 - w[0].1));
                worst = worst.max((f64::from(r) - (x * x + y * y).sqrt()).abs());
            }
        }
        worst
    }

    #[test]
    fn chords_stay_within_the_tolerance_below_the_cap() {
        for r in [0.1f32, 0.5, 1.0, 2.5, 7.0, 30.0, 99.5, 240.0, 400.0] {
            for sweep in [TAU, 3.0, -1.0, 0.2] {
                let e = worst_sagitta(r, sweep);
                assert!(e <= f64::from(TOLERANCE) + 1e-4, "r {r} sweep {sweep}: {e}");
            }
        }
    }

    #[test]
    fn above_the_cap_the_error_is_the_documented_one() {
        let r = 1000.0;
        let bound = f64::from(r) * (1.0 - (core::f64::consts::PI / f64::from(MAX_SEGMENTS)).cos());
        let e = worst_sagitta(r, TAU);
        assert!(e > f64::from(TOLERANCE) && e <= bound + 1e-3, "{e} vs {bound}");
    }

    #[test]
    fn counts_are_bounded_for_every_input() {
        for r in [-5.0, 0.0, f32::MAX, f32::INFINITY] {
            for sweep in [0.0, -100.0, 100.0, f32::INFINITY] {
                assert!((1..=MAX_SEGMENTS).contains(&segments(r, sweep)));
            }
        }
    }
}
