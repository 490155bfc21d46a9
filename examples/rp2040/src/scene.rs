//! What the example draws, shared word for word by the firmware (each
//! core) and by the host's reference (`cargo run -- crc N`, which the
//! emulator run in `bash scripts/firmware.sh rp2040` compares against):
//! the standard 3D scene at 320 × 240, 16-row bands, perspective-correct
//! colour, 16-bit depth, the animation angle advancing 0.05 rad a frame.

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::pipeline::Pipeline;
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle, draw_triangle};
use microraster::render::{BandSink, from_fn};
use microraster::{Band, Error, RenderError, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

/// Frame width (landscape).
pub const W: usize = 320;
/// Frame height.
pub const H: u32 = 240;
/// Rows of a band.
pub const BAND: usize = 16;
/// Bands of a frame.
#[cfg_attr(not(target_os = "none"), allow(dead_code))] // the firmware's
pub const BANDS: usize = H as usize / BAND;
/// Subpixel bits.
pub const S: u32 = 4;
/// Frame background.
pub const BACKGROUND: Rgb565 = Rgb565::BLACK;

/// One core's triangles of a frame (every visible one: each core runs the
/// vertex stage itself).
pub type Bins = heapless::Vec<ScreenTriangle<S>, BINS>;
/// One core's two colour bands (the linked loop fills one while the other
/// is sent).
pub type Bands = [Band<Rgb565, W, BAND>; 2];
/// One core's depth band.
pub type Depth = DepthBand<Depth16, W, BAND>;

/// The frame's vertex pipeline (the same for every frame).
pub fn pipeline() -> Pipeline<f32, S> {
    Scene3d::pipeline::<f32, S>(W as u32, H).unwrap()
}

/// The frame's renderer.
pub fn renderer() -> Renderer<Rgb565> {
    Renderer::new(H, BACKGROUND)
}

/// Frame `frame`'s vertex stage: its visible triangles into `bins`.
pub fn vertex(pipeline: &Pipeline<f32, S>, frame: usize, bins: &mut Bins) -> Result<(), Error> {
    bins.clear();
    Scene3d.draw::<f32, Rgb565, S, BINS>(pipeline, frame as f32 * 0.05, bins).map(|_| ())
}

/// The frame's bands: the linked band loop over `bands`, drawing `bins`
/// into the bands for which `mine(index)` holds (the others are only
/// cleared) and handing every band to `sink`.
pub fn raster<'a, K: BandSink<'a, Rgb565, W>>(
    mine: impl Fn(usize) -> bool,
    bins: &Bins,
    bands: &'a mut Bands,
    depth: &mut Depth,
    sink: &mut K,
) -> Result<(), RenderError<K::Error>> {
    let pass = from_fn(|view| {
        if !mine(view.y0() as usize / BAND) {
            return Ok(());
        }
        let rows = view.height();
        depth.clear(rows);
        let mut z = depth.rows_mut(rows);
        for tri in bins.iter() {
            draw_triangle(tri, view, &mut z, DepthState::LESS_WRITE, PerspectiveCorrect);
        }
        Ok(())
    });
    renderer().render_linked(pass, bands, sink)
}
