//! A plain mesh per band (`Pipeline::draw_valid_mesh_in` in a `Direct3d`
//! pass, no bins) draws the frame of the same meshes binned whole
//! (`draw_valid_mesh` into the frame's bins, then `Triangles3d`, which
//! rasterizes in the exact tier) in every band height, and counts the same
//! triangles; in the fast tier, the same frame in every band height.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, ValidMesh};
use microraster::pipeline::{MeshStats, Pipeline};
use microraster::raster3d::{PerspectiveCorrect, Precision};
use microraster::render::{Direct3d, Triangles3d};
use microraster::view3d::CUBE;
use microraster::{Band, Error, Renderer};

const W: usize = 96;
const H: u32 = 72;
const BG: Rgb565 = Rgb565::BLACK;

fn pipeline(precision: Precision) -> Pipeline<f32, 4> {
    let eye =
        transform::look_at(Vec3::new(1.5, 2.0, 5.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))
            .unwrap();
    Pipeline::perspective(eye, 0.9, 0.5, 20.0, W as u32, H)
        .unwrap()
        .with_lighting(microraster::view3d::DEFAULT_LIGHTING)
        .with_precision(precision)
}

fn scene() -> [(ValidMesh<'static>, Mat4<f32>, Rgb565); 2] {
    let sphere = ValidMesh::new(crate::view3d::sphere()).unwrap();
    [
        (sphere, transform::translation(Vec3::new(-0.8, 0.0, 0.0)), Rgb565::new(31, 40, 4)),
        (CUBE, transform::translation(Vec3::new(0.9, 0.0, -0.5)) * transform::rotation_y(0.6), Rgb565::CYAN),
    ]
}

fn binned(precision: Precision) -> (Vec<Rgb565>, u32) {
    let p = pipeline(precision);
    let mut bins = heapless::Vec::<_, 1024>::new();
    let mut emitted = 0;
    for (mesh, model, colour) in scene() {
        emitted += p.draw_valid_mesh(&mesh, &model, colour, &mut bins).unwrap().emitted;
    }
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) =
        (Box::new(Band::<Rgb565, W, 8>::new(BG)), Box::new(DepthBand::<Depth16, W, 8>::new()));
    let frame = Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect);
    Renderer::new(H, BG).render(frame, &mut band, &mut fb).unwrap();
    (fb.pixels, emitted)
}

/// The scene per band in `BH`-row bands; the triangles each band drew.
fn per_band<const BH: usize>(precision: Precision) -> (Vec<Rgb565>, u32) {
    let p = pipeline(precision);
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) =
        (Box::new(Band::<Rgb565, W, BH>::new(BG)), Box::new(DepthBand::<Depth16, W, BH>::new()));
    let mut emitted = 0;
    let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |b| {
        for (mesh, model, colour) in scene() {
            emitted += p.draw_valid_mesh_in(&mesh, &model, colour, b)?.emitted;
        }
        Ok(())
    });
    Renderer::new(H, BG).render(frame, &mut band, &mut fb).unwrap();
    (fb.pixels, emitted)
}

#[test]
fn per_band_plain_mesh_draws_the_binned_frame() {
    for precision in [Precision::Exact, Precision::Fast] {
        let (want, whole) = match precision {
            Precision::Exact => binned(precision),
            // `Triangles3d` rasterizes exactly: the fast tier's reference is
            // its own frame in one band.
            Precision::Fast => (per_band::<72>(precision).0, binned(precision).1),
        };
        assert!(want.iter().filter(|&&c| c != BG).count() > 500, "{precision:?}: the scene shows");
        for (bh, (got, banded)) in
            [(1, per_band::<1>(precision)), (7, per_band::<7>(precision)), (72, per_band::<72>(precision))]
        {
            let diff = want.iter().zip(&got).filter(|(a, b)| a != b).count();
            assert_eq!(diff, 0, "{precision:?}, {bh}-row bands: {diff} pixels differ");
            // Every triangle in at least one band; in one band, exactly the frame's.
            assert!(banded >= whole, "{precision:?}, {bh}-row bands: {banded} < {whole}");
            if bh == 72 {
                assert_eq!(banded, whole);
            }
        }
    }
}

#[test]
fn per_band_plain_mesh_errors() {
    // Wound against its normals, with back faces culled: the typed error.
    let reversed: Vec<[u16; 3]> = CUBE.mesh().indices.iter().map(|&[a, b, c]| [a, c, b]).collect();
    let inside_out = ValidMesh::new(Mesh { indices: &reversed, ..*CUBE.mesh() }).unwrap();
    let p = pipeline(Precision::Exact);
    let run = |mesh: &ValidMesh<'_>, model: Mat4<f32>| -> Result<MeshStats, Error> {
        let mut band = Box::new(Band::<Rgb565, W, 8>::new(BG));
        let mut depth = Box::new(DepthBand::<Depth16, W, 8>::new());
        let mut out = Ok(MeshStats::default());
        let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |b| {
            out = p.draw_valid_mesh_in(mesh, &model, Rgb565::RED, b);
            out.map(|_| ())
        });
        let _ = Renderer::new(H, BG).render(frame, &mut band, &mut Framebuffer::new(W as u32, H, BG));
        out
    };
    assert_eq!(run(&inside_out, Mat4::IDENTITY), Err(Error::WindingMismatch));
    let flat = transform::scaling(Vec3::new(0.0, 0.0, 0.0));
    assert_eq!(run(&CUBE, flat), Err(Error::InvalidParameter(microraster::Param::Model)));
    let nan = transform::rotation_y(f32::NAN);
    assert_eq!(run(&CUBE, nan), Err(Error::NonFiniteCoordinate));
}
