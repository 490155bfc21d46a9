//! A `no_std`, allocation-free, fixed-point banded rasterizer for the small
//! displays that microcontrollers drive: exact, seamless fills, shaded and
//! lit meshes, a 2D kit of anti-aliased shapes and sprites, drawn in
//! horizontal bands into a buffer you own and sent to any
//! `embedded-graphics` `DrawTarget`, so no framebuffer is needed.
//!
//! **What it guarantees.** Vertices snap to a fixed-point subpixel grid and
//! coverage comes from integer edge functions with the top-left fill rule:
//! triangles sharing an edge draw each pixel on it exactly once, and a frame
//! is the same pixels for every band height, on the host and on Cortex-M.
//! `#![no_std]`, no `alloc`, `#![forbid(unsafe_code)]`, no panics on user
//! input: bad input is a typed [`Error`], every numeric range is documented.
//!
//! A lit, spinning cube on a 240 × 240 display in 16-row bands (15 KB of
//! buffers instead of a 113 KB framebuffer), with the [`prelude`]:
//!
//! ```
//! use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
//! use microraster::prelude::*;
//! # use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
//! # use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
//! # let mut display = Framebuffer::<Rgb565, RawU16, LittleEndian, 240, 240, { buffer_size::<Rgb565>(240, 240) }>::new();
//!
//! let mut view = View240x240::new(Rgb565::BLACK); // 240 px wide, 16-row bands
//! let camera = Camera::look_at([0.0, 2.0, 5.0], [0.0, 0.0, 0.0]);
//! for frame in 0..3 { // `loop` on the device
//!     let cube = Object::new(&CUBE, Rgb565::CYAN).rotate_y(frame as f32 * 0.05);
//!     view.draw(&camera, &[cube], &mut display)?; // any embedded-graphics DrawTarget
//! }
//! # use embedded_graphics::{image::GetPixel, prelude::Point};
//! # assert_ne!(display.pixel(Point::new(120, 120)), Some(Rgb565::BLACK));
//! # Ok::<(), RenderError<core::convert::Infallible>>(())
//! ```
//!
//! Where to start: [`view3d`] (the one-call 3D front), [`Renderer`] and
//! [`render::Pass`] (one way to render any frame: 2D primitives, 3D
//! triangles, e-g drawables, a HUD with `.then`), `shape` and `texture` (the
//! 2D kit, features `shapes` and `textures`), [`pipeline`] (the explicit 3D
//! API). The repository's README and its `docs/` folder hold the recipes,
//! the measured speed and memory tables, the firmware and the tests.
//!
//! ## Cargo features
//!
//! | feature | default | what it adds |
//! |---|---|---|
//! | `shapes` | on | the 2D kit, module `shape` (needs `fragment`) |
//! | `textures` | on | textures and sprites, module `texture` (needs `fragment`) |
//! | `fragment` | with either | fragment shaders, blending, anti-aliasing: `fragment`, `blend`, `aa`, `line_aa` |
//! | `fx` | on | the 16.16 scalar `math::Fx` for parts without an FPU (adds the `fixed` crate) |
//! | `std` | off | `Renderer::render_threads` on scoped host threads |
//! | `async` | off | `Renderer::render_async`, `render::SpiPanel` over `embedded-hal-async` |
//! | `defmt` | off | `defmt::Format` for the errors and statistics a firmware logs |
//!
//! A program links only what it calls either way; turning a feature off
//! shortens the build and the API.
//!
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
//! * pixel, the opt-in per-pixel work (cargo features `fragment`,
//!   `textures`, `shapes`): `fragment` (shaders), `texture`, `blend`, `aa`,
//!   `line_aa`, `shape`;
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

/// The code blocks of the repository's `docs/` pages, compiled and run as
/// doctests (`cargo test --doc`); not part of the API.
#[cfg(doctest)]
mod docs_pages {
    #[doc = include_str!("../docs/use.md")]
    struct Use;
    #[doc = include_str!("../docs/3d.md")]
    struct ThreeD;
    #[doc = include_str!("../docs/shapes.md")]
    struct Shapes;
    #[doc = include_str!("../docs/link.md")]
    struct Link;
    #[doc = include_str!("../docs/firmware.md")]
    struct Firmware;
    #[doc = include_str!("../docs/performance.md")]
    struct Performance;
    #[doc = include_str!("../docs/guarantees.md")]
    struct Guarantees;
    #[doc = include_str!("../docs/project.md")]
    struct Project;
}

mod color;
mod error;
pub mod prelude;
pub mod view3d;

pub use geometry::{clip3d, light, math, mesh, pipeline};
pub use output::{band, blit, depth, render};
#[cfg(feature = "shapes")]
pub use pixel::shape;
#[cfg(feature = "textures")]
pub use pixel::texture;
#[cfg(feature = "fragment")]
pub use pixel::{aa, blend, fragment, line_aa};
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
