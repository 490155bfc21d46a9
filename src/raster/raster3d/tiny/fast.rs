//! The colour of a tiny triangle in the fast tier
//! ([`Precision::Fast`](crate::raster3d::Precision)), perspective-correct:
//! the same coverage and depth formula as the exact tier's (the parent
//! module), with the colour chosen once per drawn triangle. Affine
//! triangles take the exact tier's colour (below).
//!
//! The depth's vertex values come from `depth_steps_approx` (two shifts):
//! within one unit of `2^-8` steps of the exact tier's, so each stored code
//! is within one of the exact tier's.
//!
//! # The colour, and its error
//! At a covered centre the exact tier's channel rounds a convex
//! combination of the vertex values, so it lies in their range
//! `[c_min, c_max]`.
//!
//! * A triangle whose vertex values lie within 2 of each other in every
//!   channel (most of a lit mesh's tiny triangles) is the middle of each
//!   range at every pixel: within one of the exact tier's channel, and no
//!   per-pixel work.
//! * Otherwise, where the vertices' `1/w` differ so little that the
//!   screen-linear value is within `Δ ≤ 1/2` of the perspective-correct
//!   one (`perspective`'s bound), the exact screen-linear colour (each
//!   channel rounded exactly, so within `1/2 + Δ ≤ 1` before rounding, and
//!   within one after); otherwise the exact tier's perspective-correct
//!   colour.
//!
//! The choice is a few bytes, made at the first pixel that passes its depth
//! test: a larger state (per-channel weights, tried first) cost its copies
//! more than the pixels of a triangle of one or two pixels saved.
//!
//! # Why not for affine triangles
//! There the exact tier's colour is a few multiplies and one rounding per
//! pixel, and the choice itself (three ranges) costs about as much: at the
//! knot's one or two pixels per triangle, making it cost the fast tier's
//! frame 3 % (Cortex-M4F, `fw_bench`: 16,517,200 with it, 16,022,760
//! without), with the camera twice as close 0.7 %.

use super::super::ScreenTriangle;
use crate::Interpolate;

/// The fast tier's colour of one tiny triangle (module docs).
#[derive(Clone, Copy)]
pub(super) enum FastShade<C> {
    /// One colour at every pixel: flat, or every channel within 2.
    Const(C),
    /// The exact tier's screen-linear colour.
    Affine,
    /// The exact tier's perspective-correct colour.
    Perspective,
}

impl<C: Interpolate> FastShade<C> {
    /// The perspective-correct colour of `tri`. Out of line: made once per
    /// drawn triangle.
    #[inline(never)]
    pub(super) fn new<const S: u32>(tri: &ScreenTriangle<S>) -> Self {
        if tri.flat {
            return FastShade::Const(C::from_channels(tri.v[0].color));
        }
        let max = C::CHANNEL_MAX;
        let (mut mid, mut spread) = ([0u8; 3], 0u8);
        for k in 0..3 {
            let c = tri.v.map(|v| v.color[k]);
            let (lo, hi) = (c[0].min(c[1]).min(c[2]), c[0].max(c[1]).max(c[2]));
            mid[k] = lo + (hi - lo) / 2;
            if max[k] > 0 {
                spread = spread.max(hi - lo);
            }
        }
        if spread <= 2 {
            return FastShade::Const(C::from_channels(mid));
        }
        // Δ = spread/2 · (a_max − a_min)/a_min ≤ 1/2 on the 1/w as given
        // (only their ratios enter; `perspective`'s bound).
        let a = tri.v.map(|v| u64::from(v.inv_w));
        let (a_min, a_max) = (a[0].min(a[1]).min(a[2]), a[0].max(a[1]).max(a[2]));
        if u64::from(spread) * (a_max - a_min) > a_min {
            return FastShade::Perspective;
        }
        FastShade::Affine
    }
}
