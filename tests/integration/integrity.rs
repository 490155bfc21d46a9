//! Issue 13 (integrity): the `Fx` vertex path either makes the f32 path's
//! decision (drawn or not) or returns a typed error; regression tests for
//! each finding, and a property test over every rendering path.

mod every_path;
mod findings;

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::{Mat4, Scalar};
use microraster::mesh::Mesh;
use microraster::pipeline::Pipeline;
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::render::{Direct3d, Triangles3d};
use microraster::{Band, Error, Renderer};

const W: usize = 64;
const H: usize = 48;

/// The image of `mesh` drawn by `p`: the whole frame's bins at once
/// (`Triangles3d`), and the vertex stage once per 8-row band
/// (`Direct3d`, one band's bins); `Err` is the first error of either.
fn both_ways<T: Scalar>(
    p: &Pipeline<T, 4>,
    mesh: &Mesh<'_>,
    model: &Mat4<T>,
) -> Result<(Vec<Gray8>, Vec<Gray8>), Error> {
    let bg = Gray8::new(0);
    let mut bins = heapless::Vec::<ScreenTriangle<4>, 64>::new();
    p.draw_mesh(mesh, model, Gray8::new(255), &mut bins)?;
    let mut fb = Framebuffer::new(W as u32, H as u32, bg);
    let mut band = Band::<Gray8, W, 8>::new(bg);
    let mut depth = DepthBand::<Depth16, W, 8>::new();
    Renderer::new(H as u32, bg)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
        .unwrap();
    let whole = fb.pixels;
    let mut fb = Framebuffer::new(W as u32, H as u32, bg);
    let mut pb = *p;
    let mut failed = None;
    let r = Renderer::new(H as u32, bg).render(
        Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |b3| {
            bins.clear();
            pb.rows = Some(b3.rows());
            pb.draw_mesh(mesh, model, Gray8::new(255), &mut bins).inspect_err(|e| failed = Some(*e))?;
            b3.draw_all(&bins);
            Ok(())
        }),
        &mut band,
        &mut fb,
    );
    if let Some(e) = failed {
        return Err(e);
    }
    r.unwrap();
    Ok((whole, fb.pixels))
}

fn lit(img: &[Gray8]) -> usize {
    img.iter().filter(|&&c| c != Gray8::new(0)).count()
}
