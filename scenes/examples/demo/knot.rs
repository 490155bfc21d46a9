//! The 20k-triangle benchmark knot (`examples/common/knot_mesh.rs`) at
//! 320×240 through the meshlet stage: `Direct3d` with
//! `Pipeline::draw_meshlets` per band, no bins. The frame must equal the
//! binned path's (the same triangles in cluster order through
//! `draw_valid_mesh` and `Triangles3d`), which the demo checks.

use super::{Canvas, Result, save};
use embedded_graphics_core::pixelcolor::Rgb888;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::{Mat4, transform};
use microraster::mesh::ValidMesh;
use microraster::pipeline::{ClusterCache, MeshStats, Pipeline};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::render::{Direct3d, Triangles3d};
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::Scene3d;
use std::path::Path;

#[path = "../../../examples/common/knot_mesh.rs"]
mod knot_mesh;

// The standard 3D scene's frame, bands, angle and background.
use super::scene3d::{ANGLE, BACKGROUND, BAND_ROWS, HEIGHT, S, W};
const COLOR: Rgb888 = Rgb888::new(222, 186, 98);

fn model() -> Mat4<f32> {
    transform::rotation_y(ANGLE)
}

/// The knot through the meshlet stage in 16-row bands with `pipeline`
/// (its accuracy tier is the pipeline's), and what the stage skipped.
pub fn meshlet_frame(pipeline: &Pipeline<f32, S>) -> Result<(Canvas, MeshStats)> {
    let mut canvas = Canvas::new(W as u32, HEIGHT);
    let mut band = Band::<Rgb888, W, BAND_ROWS>::new(BACKGROUND);
    let mut depth = DepthBand::<Depth16, W, BAND_ROWS>::new();
    let mut cache = ClusterCache::<f32, S>::new();
    let mut total = MeshStats::default();
    Renderer::new(HEIGHT, BACKGROUND)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |band| {
                let s = pipeline.draw_meshlets(&knot_mesh::VALID_KNOT, &model(), COLOR, &mut cache, band)?;
                total.emitted += s.emitted;
                total.clusters_outside += s.clusters_outside;
                total.clusters_back_facing += s.clusters_back_facing;
                Ok(())
            }),
            &mut band,
            &mut canvas,
        )
        .map_err(|e| e.to_string())?;
    Ok((canvas, total))
}

/// Writes knot.png to `out` and prints what the meshlet stage skipped.
pub fn run(out: &Path) -> Result<()> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, HEIGHT)?;
    let (canvas, total) = meshlet_frame(&pipeline)?;
    let mut band = Band::<Rgb888, W, BAND_ROWS>::new(BACKGROUND);
    let mut depth = DepthBand::<Depth16, W, BAND_ROWS>::new();

    // The binned path, same triangles in cluster order: the same frame.
    let mut bins = Box::new(heapless::Vec::<ScreenTriangle<S>, 16384>::new());
    let mesh = ValidMesh::new(knot_mesh::KNOT_MESH)?;
    pipeline.draw_valid_mesh(&mesh, &model(), COLOR, &mut bins)?;
    let mut binned = Canvas::new(W as u32, HEIGHT);
    Renderer::new(HEIGHT, BACKGROUND)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut binned)
        .map_err(|e| e.to_string())?;
    if binned.px != canvas.px {
        return Err("the meshlet stage and the binned path drew different knots".into());
    }
    save(&canvas, &out.join("knot.png"))?;
    let clusters = knot_mesh::KNOT.meshlets.len();
    println!(
        "knot.png: {} triangles in {clusters} clusters; drawn {} (summed over bands), {} binned; \
         clusters skipped over the 15 bands: {} outside the band or view, {} facing away; \
         identical to the binned path",
        knot_mesh::KNOT.triangles.len(),
        total.emitted,
        bins.len(),
        total.clusters_outside,
        total.clusters_back_facing
    );
    Ok(())
}
