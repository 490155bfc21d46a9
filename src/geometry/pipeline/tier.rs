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

/// The tier types are the raster's ([`crate::raster3d`]): one choice runs
/// both stages.
pub(crate) use crate::raster3d::{ExactTier, FastTier, Tier};

#[cfg(test)]
mod tests;
