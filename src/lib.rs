#![doc = include_str!("../README.md")]
//! ## Modules
//!
//! One module per pipeline stage: [`subpixel`] (snapping) → [`edge`] (triangle
//! coverage) and [`mod@line`] (midpoint lines) → [`blit`] (where pixels go) →
//! [`band`] (the band buffer) → [`render`] (the band loop).
//!
//! On top: [`view3d`], the one-call 3D front, and [`prelude`], the names
//! most programs need.
#![no_std]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod aa;
mod attr;
pub mod band;
#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod blend;
pub mod blit;
pub mod clip;
pub mod clip3d;
pub mod color;
pub mod depth;
pub mod edge;
pub mod error;
#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod fragment;
pub mod light;
pub mod line;
#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod line_aa;
pub mod math;
pub mod mesh;
pub mod pipeline;
pub mod prelude;
pub mod primitive;
pub mod raster3d;
pub mod render;
// Anti-aliased coverage and gradients blend (`blend`), so shapes go with the
// fragment stage's modules.
#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod shape;
pub mod subpixel;
#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod texture;
pub mod varyings;
pub mod view3d;

pub use band::Band;
pub use clip::{ClipRect, MAX_FRAME_DIM};
pub use color::Interpolate;
pub use edge::Cull;
pub use error::{Error, RenderError};
/// The `heapless` this crate is built with (its `Vec` holds the bins of
/// [`Pipeline::draw_mesh`](crate::pipeline::Pipeline::draw_mesh)): name
/// `microraster::heapless::Vec` so a different `heapless` in your crate
/// cannot cause a type mismatch.
///
/// ```
/// use microraster::heapless::Vec;
/// use microraster::raster3d::ScreenTriangle;
/// let bins: Vec<ScreenTriangle<4>, 64> = Vec::new();
/// assert!(bins.is_empty());
/// ```
pub use heapless;
pub use primitive::{Line, Primitive, Shading, Triangle};
pub use render::Renderer;
pub use subpixel::{MAX_SUBPIXEL_BITS, SubPoint};
