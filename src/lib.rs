//! microraster: a `no_std`, allocation-free, fixed-point rasterizer for small displays.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod clip;
pub mod edge;
pub mod error;
pub mod subpixel;

pub use clip::{ClipRect, MAX_FRAME_DIM};
pub use error::{Error, RenderError};
pub use subpixel::{MAX_SUBPIXEL_BITS, SubPoint};
