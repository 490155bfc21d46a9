//! microraster's demo scenes, for development only (`publish = false`): the
//! standard 2D scenes ([`scenes`]: the demo's, the benchmark scenes and the
//! firmware's `mixed`) and the standard 3D scene ([`scenes3d`]: an icosphere,
//! a torus and a cube, their meshes as flash-resident statics).
//!
//! They are shared by microraster's tests, benchmarks, examples, report and
//! firmware, and live outside the library so that a program using
//! microraster never sees them. Everything here is built on microraster's
//! public API; like the library, the crate is `no_std` and allocation-free.
//!
//! ```
//! use embedded_graphics_core::pixelcolor::Rgb565;
//! use microraster::Primitive;
//! use microraster_scenes::scenes;
//! let mut scene = microraster::heapless::Vec::<Primitive<Rgb565, 4>, { scenes::MIXED_LEN }>::new();
//! assert_eq!(scenes::collect(scenes::mixed, 320, 240, &mut scene)?, 0);
//! # Ok::<(), microraster::Error>(())
//! ```
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod scenes;
pub mod scenes3d;
