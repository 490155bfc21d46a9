//! What the firmware renders, shared word for word by the firmware (on the
//! Cortex-M targets and on the host) and by `tests/firmware_crc.rs`.
//!
//! Every scene is rendered band by band into a [`CrcTarget`], which reports
//! one [`Record`] per band (CRC-32 of the band's pixels and their count) and
//! one for the whole frame. The printed records of a QEMU run must equal the
//! host's line for line: `scripts/firmware.sh check` diffs them.
//!
//! Two configurations:
//!
//! * [`m4f`] (Cortex-M4F, STM32F405 class, 128 KB RAM): the standard 2D scene
//!   through [`Renderer::render`](microraster::Renderer::render), and the standard 3D scene ([`Scene3d`](microraster_scenes::scenes3d::Scene3d),
//!   meshes in flash) with the vertex stage run once per frame (every visible
//!   triangle binned, then `Triangles3d`), once on the `f32` vertex
//!   path and once on the fixed-point [`Fx`] path; 320 × 240 `Rgb565`, 16-row
//!   bands, 16-bit depth, perspective-correct colour; each 3D frame in
//!   both accuracy tiers ([`M4F_3D`]: `Precision::Exact`, the library's
//!   reference pixels, and `Precision::Fast`, whose own frames must match
//!   between host and target just the same).
//! * [`m0`] (Cortex-M0, nRF51822, 16 KB RAM): 160 × 128 `Rgb565` in 4-row
//!   bands, nothing per frame kept in RAM: for each band the 2D scene is
//!   generated again and drawn straight into the band, and the 3D scene's
//!   vertex stage runs again on the [`Fx`] path keeping only the triangles
//!   that touch the band (a `Direct3d` pass); meshes in flash,
//!   16-bit depth, affine colour (no per-pixel division on a core without a
//!   divider); the fast tier's frames on both vertex paths beside it
//!   ([`M0_3D`]).

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::Fx;
use microraster::raster3d::{Affine, PerspectiveCorrect, Precision, ScreenTriangle};
use microraster::{Band, Error, Primitive};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::BINS;

/// Subpixel bits of every scene.
pub const S: u32 = 4;
/// Animation angle of the 3D scene (radians).
pub const ANGLE: f32 = 0.6;
/// Frame background.
pub const BACKGROUND: Rgb565 = Rgb565::BLACK;
/// Depth test of the 3D scenes.
pub const DEPTH_STATE: DepthState = DepthState::LESS_WRITE;

/// Where records go: printed over semihosting on the target, to stdout on
/// the host, into a `Vec` in the tests.
pub type Out<'a> = &'a mut dyn FnMut(&Record);

// By path: other programs include this file by path, where a plain `mod`
// would look for its children beside it (examples/firmware/), not in workload/.
#[path = "workload/crc.rs"]
mod crc;
#[path = "workload/frames.rs"]
mod frames;

#[allow(unused_imports)] // each program that includes this file uses its own
pub use crc::{Crc32, CrcTarget, Record};
#[allow(unused_imports)]
pub use frames::{mixed, mixed_streamed, scene3d, scene3d_per_band, streamed};

/// Frame of the Cortex-M4F configuration.
pub const M4F_SIZE: (usize, u32) = (320, 240);
/// Band rows of the Cortex-M4F configuration.
pub const M4F_BAND: usize = 16;
const M4W: usize = M4F_SIZE.0;

/// Everything the Cortex-M4F configuration keeps in RAM. On the target each
/// buffer is its own `static` (so the zero-initialised ones cost no flash).
pub struct M4fBuffers<'a> {
    /// The 2D scene's primitives.
    pub prims: &'a mut heapless::Vec<Primitive<Rgb565, S>, { scenes::MIXED_LEN }>,
    /// Colour band.
    pub band: &'a mut Band<Rgb565, M4W, M4F_BAND>,
    /// Depth band.
    pub depth: &'a mut DepthBand<Depth16, M4W, M4F_BAND>,
    /// The 3D scene's bins: every visible triangle of the frame.
    pub bins: &'a mut heapless::Vec<ScreenTriangle<S>, BINS>,
}

/// The Cortex-M4F configuration (see the module docs).
pub fn m4f(b: M4fBuffers<'_>, out: Out<'_>) -> Result<(), Error> {
    let h = M4F_SIZE.1;
    let M4fBuffers { prims, band, depth, bins } = b;
    mixed("mixed/320x240", h, prims, band, &mut *out)?;
    for (precision, [f32_name, fx_name]) in M4F_3D {
        scene3d::<f32, PerspectiveCorrect, M4W, M4F_BAND, BINS>(
            f32_name, precision, h, bins, band, depth, &mut *out,
        )?;
        scene3d::<Fx, PerspectiveCorrect, M4W, M4F_BAND, BINS>(
            fx_name, precision, h, bins, band, depth, &mut *out,
        )?;
    }
    Ok(())
}

/// The Cortex-M4F's 3D frames: per accuracy tier, the `f32` and the `Fx`
/// frame's name (the exact ones first, as before the fast tier).
pub const M4F_3D: [(Precision, [&str; 2]); 2] = [
    (Precision::Exact, ["scene3d-f32/320x240", "scene3d-fx/320x240"]),
    (Precision::Fast, ["scene3d-f32-fast/320x240", "scene3d-fx-fast/320x240"]),
];

/// The Cortex-M0's 3D frames: the exact tier's `Fx` frame, then the fast
/// tier's `Fx` and (soft float) `f32` frames.
pub const M0_3D: [(Precision, bool, &str); 3] = [
    (Precision::Exact, true, "scene3d-fx/160x128"),
    (Precision::Fast, true, "scene3d-fx-fast/160x128"),
    (Precision::Fast, false, "scene3d-f32-fast/160x128"),
];

/// [`m4f`] with buffers on the heap (host).
#[cfg(not(target_os = "none"))]
pub fn m4f_host(out: Out<'_>) -> Result<(), Error> {
    let b = M4fBuffers {
        prims: &mut Box::new(heapless::Vec::new()),
        band: &mut Box::new(Band::new(BACKGROUND)),
        depth: &mut Box::new(DepthBand::new()),
        bins: &mut Box::new(heapless::Vec::new()),
    };
    m4f(b, out)
}

/// Triangles one band of the Cortex-M0 configuration may hold: the most any
/// band of its frame needs (between 81 and 96: 80 fail), with room to spare;
/// a band that needs more fails with [`Error::CapacityExceeded`], on the
/// host as on the target. Each entry is 64 bytes of the micro:bit's 16 KB:
/// 128 left the benchmark's deepest frame 16 bytes of stack.
pub const BAND_BINS: usize = 96;

/// Frame of the Cortex-M0 configuration.
pub const M0_SIZE: (usize, u32) = (160, 128);
/// Band rows of the Cortex-M0 configuration.
pub const M0_BAND: usize = 4;
const M0W: usize = M0_SIZE.0;

/// Everything the Cortex-M0 configuration keeps in RAM.
pub struct M0Buffers<'a> {
    /// Colour band.
    pub band: &'a mut Band<Rgb565, M0W, M0_BAND>,
    /// Depth band.
    pub depth: &'a mut DepthBand<Depth16, M0W, M0_BAND>,
    /// One band's triangles.
    pub bins: &'a mut heapless::Vec<ScreenTriangle<S>, BAND_BINS>,
}

/// The Cortex-M0 configuration (see the module docs).
pub fn m0(b: M0Buffers<'_>, out: Out<'_>) -> Result<(), Error> {
    let h = M0_SIZE.1;
    let M0Buffers { band, depth, bins } = b;
    mixed_streamed("mixed/160x128", h, band, &mut *out)?;
    for (precision, fx, name) in M0_3D {
        if fx {
            scene3d_per_band::<Fx, Affine, M0W, M0_BAND, BAND_BINS>(
                name, precision, h, bins, band, depth, &mut *out,
            )?;
        } else {
            scene3d_per_band::<f32, Affine, M0W, M0_BAND, BAND_BINS>(
                name, precision, h, bins, band, depth, &mut *out,
            )?;
        }
    }
    Ok(())
}

/// [`m0`] with buffers on the heap (host).
#[cfg(not(target_os = "none"))]
pub fn m0_host(out: Out<'_>) -> Result<(), Error> {
    let b = M0Buffers {
        band: &mut Box::new(Band::new(BACKGROUND)),
        depth: &mut Box::new(DepthBand::new()),
        bins: &mut Box::new(heapless::Vec::new()),
    };
    m0(b, out)
}
