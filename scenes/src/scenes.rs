//! The standard demo scenes, shared by examples, tests, benchmarks and firmware.
//!
//! A scene is a function that emits its [`Primitive`]s for a `width × height`
//! frame into a caller-supplied sink closure, so it needs no allocation: the
//! caller collects into a [`heapless::Vec`] (see [`collect`]), counts, or draws
//! directly. Each scene emits a fixed number of primitives whatever the frame
//! size, given by its `*_LEN` constant; all vertices lie inside the frame.
//!
//! Scenes are deterministic (integer geometry, a fixed-seed xorshift), so the
//! rendered frame is bit-identical on every platform and can be checked by CRC.
//! Colours are given as 8-bit RGB and scaled to each type's channel depth;
//! single-channel types (grey, [`BinaryColor`](embedded_graphics_core::pixelcolor::BinaryColor))
//! get the luma, so on a black background the light colours stay visible.
//!
//! Scenes need at least one subpixel bit (`S >= 1`, a compile error otherwise):
//! they place vertices exactly on pixel centres.
//!
//! ```
//! use embedded_graphics_core::pixelcolor::Rgb565;
//! use microraster::{Primitive, heapless};
//! use microraster_scenes::scenes;
//! let mut scene = heapless::Vec::<Primitive<Rgb565, 4>, { scenes::MIXED_LEN }>::new();
//! let dropped = scenes::collect(scenes::mixed, 320, 240, &mut scene)?;
//! assert_eq!((dropped, scene.len()), (0, scenes::MIXED_LEN));
//! # Ok::<(), microraster::Error>(())
//! ```

use microraster::heapless;
use microraster::{Error, Interpolate, Primitive};

#[cfg(doc)]
use microraster::MAX_FRAME_DIM;

mod benchmarks;
mod demo;
mod helpers;

pub use benchmarks::{
    FINE_ONE, FineTriangle, LARGE_LEN, LINES_LEN, SCATTER_LEN, TINY_LEN, benchmarks, center_pixel, large,
    lines, scatter, scatter_fine, scatter_gouraud, tiny,
};
pub use demo::{
    FILL_RULE_LEN, FILL_RULE_SIZE, GOURAUD_LEN, LINE_FAN_LEN, MIXED_LEN, all, fill_rule, gouraud, line_fan,
    mixed,
};

/// Where a scene puts its primitives.
pub type Sink<'a, C, const S: u32> = &'a mut dyn FnMut(Primitive<C, S>);

/// A scene function: `(width, height, sink)`.
///
/// Errors: [`Error::InvalidFrameSize`] if a side is 0, above
/// [`MAX_FRAME_DIM`], or smaller than the scene needs.
pub type Scene<C, const S: u32> = fn(u32, u32, Sink<'_, C, S>) -> Result<(), Error>;

/// Runs `scene` and pushes its primitives into `out`, returning how many did
/// not fit (0 when `out` had room for all of them).
pub fn collect<C: Interpolate, const S: u32, const N: usize>(
    scene: Scene<C, S>,
    width: u32,
    height: u32,
    out: &mut heapless::Vec<Primitive<C, S>, N>,
) -> Result<usize, Error> {
    let mut dropped = 0;
    scene(width, height, &mut |p| dropped += usize::from(out.push(p).is_err()))?;
    Ok(dropped)
}
