#![doc = include_str!("../README.md")]
//! ## Modules
//!
//! One module per pipeline stage, in the order a vertex travels (the source
//! folders are the stages: `src/geometry/`, `src/raster/`, `src/pixel/`,
//! `src/output/`; the paths below are flat):
//!
//! * geometry, meshes in and snapped screen triangles out: [`math`],
//!   [`mesh`], [`light`], [`clip3d`], [`pipeline`] (the vertex stage);
//! * raster, exact coverage and interpolation: snapping ([`SubPoint`]),
//!   [`edge`] (triangle coverage), [`mod@line`] (midpoint lines), the
//!   clip rectangle ([`ClipRect`]), the 2D primitives ([`Primitive`]),
//!   [`raster3d`] (screen triangles), [`varyings`];
//! * pixel, the opt-in per-pixel work (cargo feature `fragment`):
//!   `fragment` (shaders), `texture`, `blend`, `aa`, `line_aa`, `shape`;
//! * output, the buffers and the band loop down to the `DrawTarget`:
//!   [`band`], [`depth`], [`blit`] (where pixels go), [`render`].
//!
//! On top: [`view3d`], the one-call 3D front, and [`prelude`], the names
//! most programs need.
#![no_std]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

// The stages are folders; their modules keep the flat public paths.
mod geometry;
mod output;
#[cfg(feature = "fragment")]
mod pixel;
mod raster;
#[cfg(test)]
mod test_rng;

mod color;
mod error;
pub mod prelude;
pub mod view3d;

pub use geometry::{clip3d, light, math, mesh, pipeline};
pub use output::{band, blit, depth, render};
#[cfg(feature = "fragment")]
pub use pixel::{aa, blend, fragment, line_aa, shape, texture};
use raster::attr;
use raster::{clip, primitive, subpixel};
pub use raster::{edge, line, raster3d, varyings};

pub use band::Band;
pub use clip::{ClipRect, MAX_FRAME_DIM};
pub use color::Interpolate;
pub use edge::Cull;
pub use error::{Error, MeshFault, Param, Region, RenderError};
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
