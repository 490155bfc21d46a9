//! The fragment stage at 320×240 (`examples/common/fragment_scene.rs`, shared
//! with the firmware): textures, per-pixel lighting and translucency,
//! rendered in 16-row bands, supersampled 2 × 2 (`fragment.png`) and aliased
//! (`fragment_aliased.png`).

use super::{Canvas, Result, save, with_caption};
use embedded_graphics_core::pixelcolor::Rgb888;
use microraster::aa::Ssaa;
use microraster::aa::Supersampled;
use microraster::depth::{Depth16, DepthBand};
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::from_fn;
use microraster::{Band, Renderer};
use std::path::Path;

#[allow(dead_code)] // the firmware uses the per-band parts
#[path = "../../../examples/common/fragment_scene.rs"]
mod fragment_scene;
use fragment_scene::{BACKGROUND, FragBins, FragmentScene, H, W, draw_passes};

const S: u32 = super::S;
const BAND_ROWS: usize = 16;
type Z = Depth16;
type P = PerspectiveCorrect;
type Bins = FragBins<S, 1024, 1024, 64, 2048>;

/// The frame in `BAND_ROWS`-row bands.
fn render(b: &Bins) -> Result<Canvas> {
    let mut canvas = Canvas::new(W as u32, H);
    let mut band = Box::new(Band::<Rgb888, W, BAND_ROWS>::new(BACKGROUND));
    let mut depth = Box::new(DepthBand::<Z, W, BAND_ROWS>::new());
    let mut result = Ok(());
    Renderer::new(H, BACKGROUND)
        .render(
            from_fn(|view| {
                let (y0, y1) = (view.y0(), view.y1());
                if result.is_ok() {
                    result = draw_passes::<_, Z, P, S, W, BAND_ROWS, 1024, 1024, 64, 2048>(
                        b, view, &mut depth, y0, y1,
                    );
                };
                Ok(())
            }),
            &mut band,
            &mut canvas,
        )
        .map_err(|e| format!("{e:?}"))?;
    result?;
    Ok(canvas)
}

/// The frame supersampled 2 × 2 (`Ssaa<2>`): the same passes on a 640-wide
/// sample band of 32 rows with its own depth band, box-filtered per band.
fn render_ssaa2(b: &Bins) -> Result<Canvas> {
    let mut b2 = Box::new(b.clone());
    b2.scale(2)?;
    let mut canvas = Canvas::new(W as u32, H);
    let mut samples = Box::new(Band::<Rgb888, { 2 * W }, { 2 * BAND_ROWS }>::new(BACKGROUND));
    let mut depth = Box::new(DepthBand::<Z, { 2 * W }, { 2 * BAND_ROWS }>::new());
    let mut out = Box::new(Band::<Rgb888, W, BAND_ROWS>::new(BACKGROUND));
    let mut result = Ok(());
    Renderer::new(H, BACKGROUND)
        .render(
            Supersampled::new(Ssaa::<2>, &mut samples, |view| {
                let (sy0, sy1) = (view.y0(), view.y1());
                if result.is_ok() {
                    result = draw_passes::<_, Z, P, S, { 2 * W }, { 2 * BAND_ROWS }, 1024, 1024, 64, 2048>(
                        &b2, view, &mut depth, sy0, sy1,
                    );
                };
                Ok(())
            }),
            &mut out,
            &mut canvas,
        )
        .map_err(|e| format!("{e:?}"))?;
    result?;
    Ok(canvas)
}

/// Writes fragment.png (supersampled 2 × 2) and fragment_aliased.png to `out`.
pub fn run(out: &Path) -> Result<()> {
    let scene = FragmentScene::<S>::new(W as u32, H)?;
    let mut b = Box::new(Bins::new());
    scene.draw(&mut b)?;
    save(&render(&b)?, &out.join("fragment_aliased.png"))?;
    let frame = render_ssaa2(&b)?;
    let frame = with_caption(
        &frame,
        &[
            "Bricks: bilinear, perspective-correct texture.",
            "Spheres: Gouraud (left), per-pixel Phong (right).",
            "Tori: translucent (alpha 140), no depth writes.",
            "Supersampled 2x2 in 16-row bands.",
        ],
    )?;
    save(&frame, &out.join("fragment.png"))?;
    println!(
        "fragment.png: {} Gouraud, {} Phong, {} textured, {} translucent triangles; 16-row bands",
        b.gouraud.len(),
        b.phong.len(),
        b.textured.len(),
        b.glass.len()
    );
    Ok(())
}
