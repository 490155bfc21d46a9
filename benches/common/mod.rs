//! The renderers under comparison, shared word for word by the criterion
//! benchmarks (`benches/peers.rs`) and the report
//! (`cargo run --release --example report`, which includes this file with
//! `#[path]`). Each one draws a whole `W × H` frame, background included, of
//! the same scene from `microraster_scenes::scenes` / `microraster_scenes::scenes3d`:
//!
//! * microraster: the band renderer ([`mr_band`]) and direct drawing through
//!   `TargetBlitter` ([`mr_direct`]); the 3D scene through the vertex stage and
//!   `Triangles3d` ([`mr3d`]);
//! * embedded-graphics 0.8: `Triangle` / `Line` styled primitives ([`eg`]);
//! * tiny-skia 0.12: `fill_path` without anti-aliasing, hairline
//!   `stroke_path` for lines ([`skia`]);
//! * an f64 reference rasterizer ([`reference`], copied from
//!   `tests/integration/reference.rs`: point-in-triangle on the pixel centres,
//!   boundary excluded; lines by the f64 midpoint rule of
//!   `tests/integration/lines.rs`) and an f64 reference 3D pipeline
//!   ([`Ref3d`]: f64 transform, lighting, depth test and perspective-correct
//!   colour);
//! * the physical ceiling: a slice fill of the whole framebuffer ([`memset`]).
//!
//! Targets: [`SliceFb`], a plain `Vec<Rgb565>` whose `fill_solid` and
//! `fill_contiguous` are slice operations (what a DMA-fed display or a plain
//! framebuffer offers), and [`EgFb`], embedded-graphics' own `Framebuffer`,
//! whose `DrawTarget` implementation only has a per-pixel `draw_iter` (every
//! `fill_solid` and `fill_contiguous` goes through it pixel by pixel).
#![allow(dead_code)]

use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::Rgb565;

/// Frame width.
pub const W: usize = 320;
/// Frame height.
pub const H: usize = 240;
/// Background of every frame (all-zero bits, so byte buffers clear with 0).
pub const BG: Rgb565 = Rgb565::BLACK;
/// Animation angle of the 3D scene: the firmware's (`examples/firmware/workload.rs`).
pub const ANGLE: f32 = 0.6;

mod targets;
pub use targets::*;

pub mod shape_set;

// ---------------------------------------------------------------------------
// 2D scenes
// ---------------------------------------------------------------------------

mod scene2d;
pub use scene2d::*;

// ---------------------------------------------------------------------------
// The 3D scene (benchmark scene 4)
// ---------------------------------------------------------------------------

mod scene3d;
pub use scene3d::*;

// --- the f64 reference pipeline ---------------------------------------------

mod reference3d;
pub use reference3d::*;
