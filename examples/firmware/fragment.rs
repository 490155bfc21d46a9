//! The fragment-stage scene (`examples/common/fragment_scene.rs`) on the
//! Cortex-M4F: textures, per-pixel lighting, translucency and 2 × 2
//! supersampling at 320 × 240 `Rgb565` with 16-bit depth, in 4-row bands
//! whose vertex stage runs once per band (only that band's triangles are
//! kept), so it fits beside the other scenes' buffers in the STM32F405's
//! 128 KB: [`FragBuffers`] says how much it takes.

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::aa::Ssaa;
use microraster::aa::Supersampled;
use microraster::depth::{Depth16, DepthBand};
use microraster::raster3d::PerspectiveCorrect;
use microraster::texture::from_rgb8;
use microraster::{Band, Error, Renderer};

#[allow(dead_code)]
#[path = "../common/fragment_scene.rs"]
mod fragment_scene;
pub use fragment_scene::FragBins;
use fragment_scene::{BACKGROUND, FragmentScene, H, W, draw_passes};

use crate::workload::{CrcTarget, Out, S};

/// Output band rows.
pub const ROWS: usize = 4;
/// Samples per pixel along each axis.
const N: usize = 2;
/// The sample band's width and rows.
pub const SW: usize = N * W;
/// The sample band's rows.
pub const SH: usize = N * ROWS;
/// One band's triangles per pass (Gouraud, Phong, textured, translucent):
/// the most any 4-row band of the scene needs (31, 31, 7 and 106), with
/// room to spare.
pub type Bins = FragBins<S, 40, 40, 10, 128>;

/// Everything the scene keeps in RAM.
pub struct FragBuffers<'a> {
    /// Colour samples of one band (2 × 2 per pixel).
    pub samples: &'a mut Band<Rgb565, SW, SH>,
    /// Depth samples of one band.
    pub depth: &'a mut DepthBand<Depth16, SW, SH>,
    /// The resolved band, sent to the display.
    pub out: &'a mut Band<Rgb565, W, ROWS>,
    /// One band's triangles, on the sample grid.
    pub bins: &'a mut Bins,
}

/// The scene's name in the records.
pub const NAME: &str = "fragment-ssaa2/320x240";

/// [`fragment`] with buffers on the heap (host).
#[cfg(not(target_os = "none"))]
pub fn fragment_host(out: Out<'_>) -> Result<(), Error> {
    let b = FragBuffers {
        samples: &mut Box::new(Band::new(Rgb565::new(0, 0, 0))),
        depth: &mut Box::new(DepthBand::new()),
        out: &mut Box::new(Band::new(Rgb565::new(0, 0, 0))),
        bins: &mut Box::new(Bins::new()),
    };
    fragment(NAME, b, out)
}

/// Renders the scene into `out`'s records as `name`.
pub fn fragment(name: &'static str, b: FragBuffers<'_>, out: Out<'_>) -> Result<(), Error> {
    let FragBuffers { samples, depth, out: band, bins } = b;
    let mut scene = FragmentScene::<S>::new(W as u32, H)?;
    let background: Rgb565 = from_rgb8(microraster::Interpolate::to_channels(BACKGROUND));
    let mut target = CrcTarget::new(name, W as u32, H, out);
    let mut result = Ok(());
    Renderer::new(H, background)
        .render(
            Supersampled::new(Ssaa::<N>, samples, |view| {
                let (sy0, sy1) = (view.y0(), view.y1());
                if result.is_ok() {
                    result = band_pass(&mut scene, bins, view, depth, sy0, sy1);
                };
                Ok(())
            }),
            band,
            &mut target,
        )
        .map_err(|e| match e {
            microraster::RenderError::Input(e) => e,
            microraster::RenderError::Target(never) => match never {},
        })?;
    result?;
    target.finish();
    Ok(())
}

/// The vertex stage for frame rows `sy0/N .. sy1/N`, its triangles moved to
/// the sample grid, then the passes.
fn band_pass(
    scene: &mut FragmentScene<S>,
    bins: &mut Bins,
    view: &mut microraster::band::BandView<'_, Rgb565, SW>,
    depth: &mut DepthBand<Depth16, SW, SH>,
    sy0: i32,
    sy1: i32,
) -> Result<(), Error> {
    let n = N as i32;
    scene.set_rows(Some((sy0 / n, (sy1 - 1) / n)));
    bins.clear();
    scene.draw(bins)?;
    bins.scale(N)?;
    draw_passes::<Rgb565, Depth16, PerspectiveCorrect, S, SW, SH, 40, 40, 10, 128>(
        bins, view, depth, sy0, sy1,
    )
}
