//! microraster: a `no_std`, allocation-free, fixed-point rasterizer for small displays.
//!
//! Triangles and lines are snapped to a fixed-point subpixel grid
//! ([`SubPoint`]), covered with integer edge functions under the top-left fill
//! rule ([`edge`]), and drawn band by band ([`Band`], [`Renderer`]) into any
//! `embedded-graphics` [`DrawTarget`](embedded_graphics_core::draw_target::DrawTarget).
//! Pipeline stages, one module each: [`subpixel`] → [`edge`] / [`mod@line`] →
//! [`blit`] → [`band`] → [`render`].
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod attr;
pub mod band;
pub mod blit;
pub mod clip;
pub mod color;
pub mod edge;
pub mod error;
pub mod line;
pub mod primitive;
pub mod render;
pub mod scenes;
pub mod subpixel;

pub use band::Band;
pub use clip::{ClipRect, MAX_FRAME_DIM};
pub use color::Interpolate;
pub use error::{Error, RenderError};
pub use primitive::{Line, Primitive, Shading, Triangle};
pub use render::Renderer;
pub use subpixel::{MAX_SUBPIXEL_BITS, SubPoint};
