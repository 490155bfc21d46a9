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
//!   through [`Renderer::render`], and the standard 3D scene ([`Scene3d`],
//!   meshes in flash) with the vertex stage run once per frame (every visible
//!   triangle binned, then `Triangles3d`), once on the `f32` vertex
//!   path and once on the fixed-point [`Fx`] path; 320 × 240 `Rgb565`, 16-row
//!   bands, 16-bit depth, perspective-correct colour.
//! * [`m0`] (Cortex-M0, nRF51822, 16 KB RAM): 160 × 128 `Rgb565` in 4-row
//!   bands, nothing per frame kept in RAM: for each band the 2D scene is
//!   generated again and drawn straight into the band, and the 3D scene's
//!   vertex stage runs again on the [`Fx`] path keeping only the triangles
//!   that touch the band (`PerBand3d`); meshes in flash,
//!   16-bit depth, affine colour (no per-pixel division on a core without a
//!   divider).

use core::convert::Infallible;
use core::fmt;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use microraster::band::BandView;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Fx, Scalar};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle};
use microraster::render::{FromFn, PerBand3d, Triangles3d, from_fn};
use microraster::{Band, Error, Primitive, RenderError, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{BINS, Scene3d};

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

/// CRC-32 as in zlib, PNG and Ethernet (reflected polynomial 0xEDB88320,
/// initial value and final XOR all ones); `CRC("123456789") = 0xCBF43926`.
#[derive(Clone, Copy, Debug)]
pub struct Crc32(u32);

const CRC_TABLE: [u32; 256] = {
    let mut table = [0u32; 256];
    let mut i = 0;
    while i < 256 {
        let mut c = i as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
            k += 1;
        }
        table[i] = c;
        i += 1;
    }
    table
};

impl Default for Crc32 {
    fn default() -> Self {
        Self::new()
    }
}

impl Crc32 {
    /// A CRC over no bytes yet.
    pub const fn new() -> Self {
        Crc32(!0)
    }

    /// Adds `bytes`.
    pub fn update(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = CRC_TABLE[((self.0 ^ b as u32) & 0xFF) as usize] ^ (self.0 >> 8);
        }
    }

    /// The CRC of everything added so far.
    pub const fn value(&self) -> u32 {
        !self.0
    }
}

/// What the firmware prints: `scene band y0 rows crc count`, where `band`
/// is the band's index or `frame` (the whole frame: the CRC runs on over
/// every band, the count is the frame's pixel count).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Record {
    /// Scene name, with the frame size and the configuration.
    pub scene: &'static str,
    /// Band index; `None` for the frame record.
    pub band: Option<u32>,
    /// First frame row.
    pub y0: i32,
    /// Number of rows.
    pub rows: u32,
    /// CRC-32 of the pixels, `Rgb565` little-endian, row by row.
    pub crc: u32,
    /// Number of pixels received.
    pub count: u32,
}

impl fmt::Display for Record {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.scene)?;
        match self.band {
            Some(b) => write!(f, " {b}")?,
            None => f.write_str(" frame")?,
        }
        write!(f, " {} {} {:08x} {}", self.y0, self.rows, self.crc, self.count)
    }
}

/// A display that keeps nothing: it checksums each band it receives and
/// reports it.
pub struct CrcTarget<'a> {
    scene: &'static str,
    size: Size,
    bands: u32,
    rows: u32,
    frame: Crc32,
    count: u32,
    /// Pixels that arrived through `draw_iter` (the renderer sends whole
    /// bands only, so any would be a bug); reported by [`CrcTarget::finish`].
    stray: (Crc32, u32),
    out: Out<'a>,
}

impl<'a> CrcTarget<'a> {
    /// A target of `width × height` pixels reporting to `out` as `scene`.
    pub fn new(scene: &'static str, width: u32, height: u32, out: Out<'a>) -> Self {
        CrcTarget {
            scene,
            size: Size::new(width, height),
            bands: 0,
            rows: 0,
            frame: Crc32::new(),
            count: 0,
            stray: (Crc32::new(), 0),
            out,
        }
    }

    /// Reports the frame record (and stray pixels, if any).
    pub fn finish(self) {
        if self.stray.1 > 0 {
            let (crc, count) = (self.stray.0.value(), self.stray.1);
            (self.out)(&Record { scene: self.scene, band: Some(u32::MAX), y0: -1, rows: 0, crc, count });
        }
        let frame = Record {
            scene: self.scene,
            band: None,
            y0: 0,
            rows: self.rows,
            crc: self.frame.value(),
            count: self.count,
        };
        (self.out)(&frame);
    }
}

impl OriginDimensions for CrcTarget<'_> {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for CrcTarget<'_> {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            let (x, y) = (p.x as u16, p.y as u16);
            self.stray.0.update(&x.to_le_bytes());
            self.stray.0.update(&y.to_le_bytes());
            self.stray.0.update(&c.into_storage().to_le_bytes());
            self.stray.1 += 1;
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        let (mut crc, mut count) = (Crc32::new(), 0u32);
        for c in colors {
            let bytes = c.into_storage().to_le_bytes();
            crc.update(&bytes);
            self.frame.update(&bytes);
            count += 1;
        }
        let record = Record {
            scene: self.scene,
            band: Some(self.bands),
            y0: area.top_left.y,
            rows: area.size.height,
            crc: crc.value(),
            count,
        };
        (self.out)(&record);
        self.bands += 1;
        self.rows += area.size.height;
        self.count += count;
        Ok(())
    }
}

fn render_error(e: RenderError<Infallible>) -> Error {
    match e {
        RenderError::Input(e) => e,
        RenderError::Target(never) => match never {},
    }
}

/// The standard 2D scene ([`scenes::mixed`]) collected into `prims`, then
/// [`Renderer::render`].
pub fn mixed<const W: usize, const H: usize>(
    name: &'static str,
    height: u32,
    prims: &mut heapless::Vec<Primitive<Rgb565, S>, { scenes::MIXED_LEN }>,
    band: &mut Band<Rgb565, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    prims.clear();
    if scenes::collect(scenes::mixed, W as u32, height, prims)? != 0 {
        return Err(Error::BufferTooSmall);
    }
    let mut target = CrcTarget::new(name, W as u32, height, out);
    Renderer::new(height, BACKGROUND).render(&prims[..], band, &mut target).map_err(render_error)?;
    target.finish();
    Ok(())
}

/// The same scene with no primitive storage: for each band the scene
/// function runs again and the primitives that touch the band are drawn
/// straight into it (the pixels are those of [`mixed`]).
pub fn mixed_streamed<const W: usize, const H: usize>(
    name: &'static str,
    height: u32,
    band: &mut Band<Rgb565, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    let mut target = CrcTarget::new(name, W as u32, height, out);
    let frame = streamed::<W>(scenes::mixed::<Rgb565, S>, height);
    Renderer::new(height, BACKGROUND).render(frame, band, &mut target).map_err(render_error)?;
    target.finish();
    Ok(())
}

/// The pass that runs `scene` again for every band and draws the
/// primitives touching the band straight into it: a 2D frame with no
/// primitive storage. The scene's first error is the frame's.
pub fn streamed<const W: usize>(
    scene: scenes::Scene<Rgb565, S>,
    height: u32,
) -> FromFn<Rgb565, impl FnMut(&mut BandView<'_, Rgb565, W>) -> Result<(), Error>, W> {
    from_fn(move |view| {
        let (y0, y1) = (view.y0(), view.y1());
        scene(W as u32, height, &mut |p| {
            let (lo, hi) = p.rows();
            if lo < y1 && hi >= y0 {
                p.draw(view, Cull::None);
            }
        })
    })
}

/// The standard 3D scene ([`Scene3d`], meshes in flash) with the vertex
/// stage run once per frame: every visible triangle binned, then
/// `Triangles3d` with `M` colour interpolation.
pub fn scene3d<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize>(
    name: &'static str,
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?;
    bins.clear();
    Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins)?;
    let mut target = CrcTarget::new(name, W as u32, height, out);
    Renderer::new(height, BACKGROUND)
        .render(Triangles3d::new(bins, depth, DEPTH_STATE, M::default()), band, &mut target)
        .map_err(render_error)?;
    target.finish();
    Ok(())
}

/// Triangles one band of the Cortex-M0 configuration may hold: the most any
/// band of its frame needs (between 81 and 96: 80 fail), with room to spare;
/// a band that needs more fails with [`Error::CapacityExceeded`], on the
/// host as on the target. Each entry is 64 bytes of the micro:bit's 16 KB:
/// 128 left the benchmark's deepest frame 16 bytes of stack.
pub const BAND_BINS: usize = 96;

/// The standard 3D scene with the vertex stage run once per band
/// (`PerBand3d`): `bins` holds one band's triangles.
#[allow(clippy::too_many_arguments)]
pub fn scene3d_per_band<T: Scalar, M: Interpolation, const W: usize, const H: usize, const N: usize>(
    name: &'static str,
    height: u32,
    bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    out: Out<'_>,
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, height)?;
    let mut target = CrcTarget::new(name, W as u32, height, out);
    let geometry = |y0: i32, y1: i32, bins: &mut heapless::Vec<ScreenTriangle<S>, N>| {
        pipeline.rows = Some((y0, y1 - 1));
        Scene3d.draw::<T, Rgb565, S, N>(&pipeline, ANGLE, bins).map(|_| ())
    };
    Renderer::new(height, BACKGROUND)
        .render(PerBand3d::new(bins, depth, DEPTH_STATE, M::default(), geometry), band, &mut target)
        .map_err(render_error)?;
    target.finish();
    Ok(())
}

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
    scene3d::<f32, PerspectiveCorrect, M4W, M4F_BAND, BINS>(
        "scene3d-f32/320x240",
        h,
        bins,
        band,
        depth,
        &mut *out,
    )?;
    scene3d::<Fx, PerspectiveCorrect, M4W, M4F_BAND, BINS>("scene3d-fx/320x240", h, bins, band, depth, out)
}

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
    scene3d_per_band::<Fx, Affine, M0W, M0_BAND, BAND_BINS>("scene3d-fx/160x128", h, bins, band, depth, out)
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
