//! The accuracy tier ([`Precision`]) as a type for the vertex stage's hot
//! loops: [`Pipeline::precision`](super::Pipeline) is read once per mesh
//! (`match` in the entry points) and the stage runs instantiated for
//! [`ExactTier`] or [`FastTier`], so each tier's branches are resolved at
//! compile time and the exact tier's code is the code it was.
//!
//! # What the fast tier changes, and its bounds
//! * Snapping (`fast_snap`): `f32` takes one reciprocal of `w` and
//!   multiplies (the exact tier divides each coordinate); `Fx` takes its
//!   quotients from the divisor's 32-bit reciprocal without the exact
//!   correction steps. Every route that snaps a vertex (eager, cached,
//!   clipped) uses the same arithmetic, so a vertex shared by triangles and
//!   by clusters snaps to the same point: coverage stays watertight. Each
//!   snapped coordinate is within one subpixel of the exact tier's.
//! * Depth and `1/w`: from the same reciprocal, within a few units of the
//!   exact `u32` values (far below one 16-bit depth code).
//! * Lighting (`fast_light`): fewer Newton steps and a specular power that
//!   skips negligible highlights; the lit intensity stays within `2^-12` of
//!   the exact tier's.

#[allow(unused_imports)] // the docs' links
use crate::raster3d::Precision;

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::ExactTier {}
    impl Sealed for super::FastTier {}
}

/// A vertex-stage tier (sealed): [`ExactTier`] or [`FastTier`].
pub(crate) trait Tier: sealed::Sealed + Copy {
    /// Whether this is [`Precision::Fast`].
    const FAST: bool;
}

/// [`Precision::Exact`] as a type.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ExactTier;

/// [`Precision::Fast`] as a type.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FastTier;

impl Tier for ExactTier {
    const FAST: bool = false;
}

impl Tier for FastTier {
    const FAST: bool = true;
}

#[cfg(test)]
mod tests;
