//! Issue 60: what the vertex stage's whole-mesh checks reject, and when.
//!
//! - A mesh whose clip coordinates leave the clipper's input range (±2^64)
//!   is `CoordinateOutOfRange` on every path, not a frame drawn without
//!   it; just inside the range it draws the image it draws at small sizes.
//! - `View3d::draw` checks what does not depend on the band (a singular
//!   model) before the first band, so such an error sends nothing.
//! - The explicit path (`ValidMesh::new` + `draw_valid_mesh`) returns
//!   `WindingMismatch` for a mesh wound inside out when culling is on.

use crate::framebuffer::Framebuffer;
use crate::view3d::clusters;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, ValidMesh, bounding_sphere};
use microraster::pipeline::{Pipeline, VertexCache};
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::Triangles3d;
use microraster::view3d::{CUBE, Camera, DEFAULT_LIGHTING, Object, View3d};
use microraster::{Band, Error, RenderError, Renderer};

const W: usize = 96;
const H: u32 = 72;
const BG: Rgb565 = Rgb565::BLACK;
const EYE: [f32; 3] = [0.3, 0.3, 3.0];
const FOV: f32 = 0.8;

/// The triangle `(0,0,0), (k,0,0), (0,k,0)`, facing the eye.
fn triangle(k: f32) -> ([[f32; 3]; 3], [[u16; 3]; 1]) {
    ([[0.0, 0.0, 0.0], [k, 0.0, 0.0], [0.0, k, 0.0]], [[0, 1, 2]])
}

fn camera() -> Camera {
    Camera::look_at(EYE, [0.0; 3]).perspective(FOV, 0.25, 64.0)
}

fn pipeline() -> Pipeline<f32, 4> {
    let v = |a: [f32; 3]| Vec3::new(a[0], a[1], a[2]);
    let view = transform::look_at(v(EYE), v([0.0; 3]), v([0.0, 1.0, 0.0])).unwrap();
    Pipeline::perspective(view, FOV, 0.25, 64.0, W as u32, H).unwrap().with_lighting(DEFAULT_LIGHTING)
}

/// The largest `k` whose triangle keeps every clip coordinate within 2^64,
/// in `f64` from the matrices' entries: `|m_rc|·k` for the model axes x
/// and y (c = 0, 1) of each clip row r (the translation is tiny beside
/// 2^64 and moves it by far less than the margins used below).
fn k_limit() -> f64 {
    let v = |a: [f32; 3]| Vec3::new(a[0], a[1], a[2]);
    let view = transform::look_at(v(EYE), v([0.0; 3]), v([0.0, 1.0, 0.0])).unwrap().to_f32();
    let proj = transform::perspective(FOV, W as f32 / H as f32, 0.25, 64.0).unwrap().to_f32();
    // Column-major: entry (r, c) of proj·view = Σ_k proj[k][r]·view[c][k].
    let entry =
        |r: usize, c: usize| (0..4).map(|k| f64::from(proj[k][r]) * f64::from(view[c][k])).sum::<f64>();
    let most = (0..4).flat_map(|r| [entry(r, 0), entry(r, 1)]).map(f64::abs).fold(0.0, f64::max);
    2f64.powi(64) / most
}

/// The front's frame of one object: the result, the pixels, the bands sent.
fn front(
    objects: &[Object<'_, Rgb565>],
) -> (Result<(), RenderError<core::convert::Infallible>>, Vec<Rgb565>, usize) {
    let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::BLUE);
    let r = view.draw(&camera(), objects, &mut fb);
    (r, fb.pixels, fb.contiguous.len())
}

/// The explicit binned path: `draw_mesh` into bins, then `Triangles3d`.
fn binned(m: &Mesh<'_>) -> Result<Vec<Rgb565>, Error> {
    let mut bins = heapless::Vec::<_, 64>::new();
    pipeline().draw_mesh(m, &Mat4::IDENTITY, Rgb565::WHITE, &mut bins)?;
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(BG), DepthBand::<Depth16, W, 8>::new());
    let frame = Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect);
    Renderer::new(H, BG).render(frame, &mut band, &mut fb).unwrap();
    Ok(fb.pixels)
}

fn lit(img: &[Rgb565]) -> usize {
    img.iter().filter(|&&c| c != BG && c != Rgb565::BLUE).count()
}

/// Issue 60, finding 2: from 10^3 to just inside the range the triangle
/// draws as many pixels (the same wedge of the screen); beyond it
/// (10^19, 1.8·10^19, and one part in 256 past the exact bound) the front
/// and `draw_mesh` drew nothing with `Ok`. Now: `CoordinateOutOfRange`,
/// and the front sends nothing.
#[test]
fn a_mesh_beyond_the_clippers_range_is_an_error_not_a_blank_frame() {
    let k_max = k_limit();
    println!("k_max = {k_max:e}");
    assert!((5e18..1e19).contains(&k_max), "{k_max:e}");
    let (p, i) = triangle(1e3);
    let small = Mesh::new(&p, &[], &i, bounding_sphere(&p));
    let reference = binned(&small).unwrap();
    assert!(lit(&reference) > 500, "{} pixels", lit(&reference));
    let (r, img, _) = front(&[Object::new(&small, Rgb565::WHITE)]);
    assert!(r.is_ok() && img == reference, "the front draws what draw_mesh draws");

    let inside = [1e6, 1e12, 3e18, k_max * (1.0 - 1.0 / 256.0)];
    let beyond = [k_max * (1.0 + 1.0 / 256.0), 1e19, 1.8e19];
    for k in inside.into_iter().chain(beyond) {
        let (p, i) = triangle(k as f32);
        let m = Box::leak(Box::new(Mesh::new(
            Vec::leak(p.to_vec()),
            &[],
            Vec::leak(i.to_vec()),
            bounding_sphere(&p),
        )));
        // The mesh checks accept it: the range depends on the camera.
        assert_eq!(m.validate(), Ok(()), "k = {k:e}");
        let valid = ValidMesh::new(*m).unwrap();
        let meshlets = clusters(*m);
        let drawn = binned(m);
        for objects in [
            [Object::new(&*m, Rgb565::WHITE)],
            [Object::new(&valid, Rgb565::WHITE)],
            [Object::new(meshlets, Rgb565::WHITE)],
        ] {
            let (r, img, sent) = front(&objects);
            if k < k_max {
                assert_eq!(r, Ok(()), "k = {k:e}");
                // The same pixels as draw_mesh; as many as at k = 10^3 (the
                // same wedge, its edges rounded differently).
                assert!(drawn.as_ref() == Ok(&img), "k = {k:e}: the front draws what draw_mesh draws");
                assert_eq!(lit(&img), lit(&reference), "k = {k:e}");
            } else {
                assert_eq!((r, sent), (Err(RenderError::Input(Error::CoordinateOutOfRange)), 0), "k = {k:e}");
                assert!(img.iter().all(|&c| c == Rgb565::BLUE), "k = {k:e}: nothing sent");
            }
        }
        if k < k_max {
            assert_eq!(drawn.map(|img| lit(&img)), Ok(lit(&reference)), "k = {k:e}: draw_mesh");
        } else {
            assert_eq!(drawn.err(), Some(Error::CoordinateOutOfRange), "k = {k:e}: draw_mesh");
            let mut bins = heapless::Vec::<_, 64>::new();
            let p = pipeline();
            assert_eq!(
                p.draw_valid_mesh(&valid, &Mat4::IDENTITY, BG, &mut bins).err(),
                Some(Error::CoordinateOutOfRange)
            );
            let mut cache = VertexCache::<f32, 4, 8>::new();
            let cached = p.draw_valid_mesh_cached(&valid, &Mat4::IDENTITY, BG, &mut cache, &mut bins);
            assert_eq!(cached.err(), Some(Error::CoordinateOutOfRange));
            assert!(bins.is_empty());
        }
    }
}

/// The check looks at the vertices the triangles use, and only for a mesh
/// in view: a far vertex no triangle uses is no error (the image is the
/// small triangle's), and a mesh beyond the range but wholly behind the
/// eye is culled whole with `Ok`.
#[test]
fn unused_far_vertices_and_culled_meshes_are_no_error() {
    let (p, i) = triangle(1e3);
    let reference = binned(&Mesh::new(&p, &[], &i, bounding_sphere(&p))).unwrap();
    let far = [p[0], p[1], p[2], [1.8e19, 0.0, 0.0]];
    let with_far = Mesh::new(&far, &[], &i, bounding_sphere(&far));
    assert_eq!(binned(&with_far).as_ref(), Ok(&reference));
    let (r, img, _) = front(&[Object::new(&with_far, Rgb565::WHITE)]);
    assert!(r.is_ok() && img == reference);

    let (p, i) = triangle(1.8e19);
    let m = Mesh::new(&p, &[], &i, bounding_sphere(&p));
    // Moved behind the eye (the camera looks down −z from z = 3).
    let behind = Object::new(&m, Rgb565::WHITE).rotate_y(core::f32::consts::PI).translate([0.0, 0.0, 1e20]);
    let (r, img, sent) = front(&[behind]);
    assert_eq!((r, lit(&img), sent), (Ok(()), 0, (H as usize).div_ceil(16)));
}

/// Issue 60, finding 5: a good cube and a cube scaled by 0. The singular
/// model failed in the first band and every band was sent cleared (the
/// good cube lost); it is now found before the first band, so nothing is
/// sent, in either order and for meshlet objects too.
#[test]
fn a_singular_model_sends_nothing() {
    let good = Object::new(&CUBE, Rgb565::RED);
    let flat = Object::new(&CUBE, Rgb565::GREEN).scale(0.0);
    let sphere = crate::view3d::sphere_meshlets();
    let flat_clusters = Object::new(sphere, Rgb565::GREEN).scale(0.0);
    let want = Err(RenderError::Input(Error::InvalidParameter(microraster::Param::Model)));
    for objects in [[good, flat], [flat, good], [good, flat_clusters]] {
        let (r, img, sent) = front(&objects);
        assert_eq!((r, sent), (want, 0));
        assert!(img.iter().all(|&c| c == Rgb565::BLUE), "nothing sent");
    }
    // The good cube alone draws.
    let (r, img, _) = front(&[good]);
    assert!(r.is_ok() && lit(&img) > 500);
}

/// Issue 60, finding 8: the README's explicit path, `ValidMesh::new` +
/// `draw_valid_mesh` (+ `Triangles3d`), drew a cube wound inside out as
/// its dark inside with `Ok`. With culling on it is now
/// `WindingMismatch` (bins untouched), on the cached and varying calls
/// too; with culling off it draws, and a cube wound right draws.
#[test]
fn an_inside_out_mesh_on_the_explicit_path_is_a_winding_mismatch() {
    let reversed: Vec<[u16; 3]> = CUBE.mesh().indices.iter().map(|&[a, b, c]| [a, c, b]).collect();
    let inside_out = ValidMesh::new(Mesh { indices: &reversed, ..*CUBE.mesh() }).unwrap();
    let model = transform::rotation_y(0.4);
    for cull in [Cull::Clockwise, Cull::CounterClockwise, Cull::None] {
        let mut p = pipeline();
        p.cull = cull;
        let mut bins = heapless::Vec::<_, 64>::new();
        let first = p.draw_valid_mesh(&CUBE, &model, Rgb565::RED, &mut bins).unwrap().emitted;
        assert!(first > 0 && bins.len() == first as usize);
        let mut cache = VertexCache::<f32, 4, 8>::new();
        let whole = p.draw_valid_mesh(&inside_out, &model, Rgb565::RED, &mut bins).map(|s| s.emitted);
        let cached = p
            .draw_valid_mesh_cached(&inside_out, &model, Rgb565::RED, &mut cache, &mut bins)
            .map(|s| s.emitted);
        let mut frag = heapless::Vec::<_, 64>::new();
        let varying = p
            .draw_mesh_varying(&inside_out, &model, Rgb565::RED, |_| [0i32; 1], &mut frag)
            .map(|s| s.emitted);
        if cull == Cull::None {
            assert!(whole.is_ok() && whole == cached && whole == varying, "{whole:?} {cached:?} {varying:?}");
            assert_eq!(bins.len(), first as usize + 2 * whole.unwrap() as usize);
        } else {
            let want = Err(Error::WindingMismatch);
            assert_eq!((whole, cached, varying), (want, want, want), "{cull:?}");
            assert_eq!(bins.len(), first as usize, "{cull:?}: bins untouched");
            // `draw_mesh` does not look at the winding (documented).
            assert!(p.draw_mesh(inside_out.mesh(), &model, Rgb565::RED, &mut bins).is_ok());
        }
    }
}
