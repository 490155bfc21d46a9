//! The angles of arcs and sectors, as whole steps of 1/4096 degree.
//!
//! An arc's end points come from its start and end angles. Reducing them by
//! whole turns is done in `f64` on the exact `f32` value, so any finite
//! angle keeps its direction (to about `|a|·2^-52` rad; past `2^52` turns
//! every `f64` is a whole number of turns, direction 0). The reduced angle is
//! then rounded to the nearest of [`TURN`] steps. The rounding is what makes
//! angles that differ by whole turns give the same point: `a0 + k·TAU` in
//! `f32` is a few ulps away from `a0`, and without the rounding a corner
//! straight above a centre that lies on a 1/32 px tie snaps up or down
//! depending on the sign of a cosine of about `±10^-7`.
//!
//! The steps are chosen so that common angles lie on them: every whole
//! degree, and `k·TAU/n` for every `n` dividing `360·4096` (2 to 10, 12, 15,
//! 16, 18, 20, 24, …). An angle within `f32` rounding of one of them
//! (`±2.1·10^-6` rad) lands exactly on it, however it was computed; sine
//! and cosine are exactly `0` and `±1` on quarter turns. An angle near the
//! midpoint between two steps can still round one way as `a0` and the
//! other as `a0 + k·TAU`: the end point then moves by `r·4.3·10^-6` px,
//! which changes the snapped point only if it lies that close to a 1/32 px
//! tie. Rounding moves an end point along its circle by at most
//! `r·2.1·10^-6` px (0.002 px at `r` = 1000).

use crate::math::Scalar;
use core::f64::consts::TAU;

/// Steps a full turn: 4096 a degree.
pub(crate) const TURN: u32 = 360 * 4096;
const QUARTER: u32 = TURN / 4;
const EIGHTH: u32 = TURN / 8;
/// One step in radians.
const STEP: f32 = (TAU / TURN as f64) as f32;

/// Starts up to this far from 0 (4 turns and a bit) are added to the sweep
/// as given, so a slice from `start + sweep` (computed in `f32`) starts
/// exactly where the one from `start` ends; farther ones are reduced first,
/// or adding the sweep would lose it (the `f32` ulp at 10^7 is 1 rad).
pub(crate) const NEAR: f32 = 32.0;

/// A direction: `0..TURN` steps clockwise on screen from +x.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Angle(u32);

impl Angle {
    /// The step nearest to `a` radians (any finite `a`).
    pub(crate) fn from_radians(a: f32) -> Self {
        // Turns: one rounding, relative 2^-53.
        let t = f64::from(a) / TAU;
        // From 2^52 on every f64 is whole: no fraction of a turn left.
        if t.abs() >= 4_503_599_627_370_496.0 {
            return Angle(0);
        }
        // ⌊t⌋ without `f64::floor` (std only); `t − ⌊t⌋` is exact.
        let whole = t as i64;
        let whole = if (whole as f64) > t { whole - 1 } else { whole };
        let steps = ((t - whole as f64) * f64::from(TURN) + 0.5) as u32;
        Angle(if steps >= TURN { steps - TURN } else { steps })
    }

    /// The angle in radians, in `[0, 2π)`.
    pub(crate) fn radians(self) -> f32 {
        self.0 as f32 * STEP
    }

    /// `(sin, cos)`: from the nearer end of the quarter turn, so `sin = cos`
    /// at 45° and quarter turns are exact.
    pub(crate) fn sin_cos(self) -> (f32, f32) {
        let (q, r) = (self.0 / QUARTER, self.0 % QUARTER);
        let (s, c) = if r <= EIGHTH {
            Scalar::sin_cos(r as f32 * STEP)
        } else {
            let (s, c) = Scalar::sin_cos((QUARTER - r) as f32 * STEP);
            (c, s)
        };
        match q {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }
}

/// `start` as used in `start + sweep`: itself when within [`NEAR`] of 0, else
/// reduced to `[0, 2π)` (on the grid).
pub(crate) fn near(start: f32) -> f32 {
    if Scalar::abs(start) <= NEAR { start } else { Angle::from_radians(start).radians() }
}

/// The start and end directions of an arc from [`near`]`(start)` sweeping
/// `sweep` (clamped to a turn): a full turn ends where it starts.
pub(crate) fn ends(start: f32, sweep: f32) -> (Angle, Angle) {
    let from = Angle::from_radians(start);
    let full = Scalar::abs(sweep) >= core::f32::consts::TAU;
    (from, if full { from } else { Angle::from_radians(start + sweep) })
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::{FRAC_PI_2, PI, TAU};

    #[test]
    fn whole_turns_give_the_same_step() {
        for d in -720..=720 {
            let a0 = (d as f32).to_radians();
            let want = Angle::from_radians(a0);
            assert_eq!(want.0, (d as i64 * 4096).rem_euclid(i64::from(TURN)) as u32, "{d}°");
            for k in [-3.0f32, -1.0, 1.0, 3.0] {
                assert_eq!(Angle::from_radians(a0 + k * TAU), want, "{d}° + {k} turns");
            }
        }
        for n in [2u32, 3, 5, 7, 12, 24] {
            let step = TAU / n as f32;
            for a0 in [0.0, -FRAC_PI_2, PI / 6.0] {
                let end = Angle::from_radians(a0 + n as f32 * step);
                assert_eq!(end, Angle::from_radians(a0), "{n} slices from {a0}");
            }
        }
    }

    #[test]
    fn quarter_turns_are_exact_and_the_rest_accurate() {
        let q = [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)];
        for (k, a) in [0.0, FRAC_PI_2, PI, -FRAC_PI_2].into_iter().enumerate() {
            assert_eq!(Angle::from_radians(a).sin_cos(), q[k], "{a}");
        }
        let mut worst = 0.0f64;
        for i in 0..20_000u32 {
            let a = Angle(i * 73 % TURN);
            let (s, c) = a.sin_cos();
            let t = f64::from(a.0) / f64::from(TURN) * core::f64::consts::TAU;
            worst = worst.max((f64::from(s) - t.sin()).abs()).max((f64::from(c) - t.cos()).abs());
            assert!(a.radians() >= 0.0 && a.radians() < TAU);
        }
        assert!(worst < 4e-7, "{worst}");
    }

    #[test]
    fn large_angles_keep_their_direction() {
        for a in [1e5f32, 1e7, 1e10, -3.3e9, 123_456.79] {
            let exact = f64::from(a).rem_euclid(core::f64::consts::TAU);
            let got = f64::from(Angle::from_radians(a).radians());
            let d = (got - exact).abs().min(core::f64::consts::TAU - (got - exact).abs());
            assert!(d < 2.2e-6 + f64::from(a).abs() * 3e-16, "{a}: {got} vs {exact}");
        }
        for a in [f32::MAX, -f32::MAX, 1e30] {
            assert_eq!(Angle::from_radians(a), Angle(0), "{a}");
        }
        assert_eq!(near(3.0), 3.0);
        assert!(near(1e7) >= 0.0 && near(1e7) < TAU);
        let (a, b) = ends(1.0, -TAU);
        assert_eq!(a, b);
    }
}
