//! Per-vertex and per-face colours in the one-call 3D front
//! (`Object::with_vertex_colors`, `Object::with_face_colors`): equal colours
//! draw what the one material colour draws; unlit face colours show exactly;
//! vertex colours interpolate, the same for every band height; lengths that
//! do not match the mesh are errors.

use crate::framebuffer::Framebuffer;
use crate::view3d::{sphere, sphere_meshlets};
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::view3d::{CUBE, Camera, Object, View3d};
use microraster::{Error, RenderError};

const W: usize = 96;
const H: u32 = 72;
const BG: Rgb565 = Rgb565::BLACK;

/// The scene through the front in `BH`-row bands, lit or not.
fn draw<const BH: usize>(camera: &Camera, objects: &[Object<'_, Rgb565>], lit: bool) -> Vec<Rgb565> {
    let mut view = Box::new(View3d::<Rgb565, W, BH>::new(BG));
    if !lit {
        view.set_lighting(None);
    }
    let mut fb = Framebuffer::new(W as u32, H, BG);
    view.draw(camera, objects, &mut fb).unwrap();
    fb.pixels
}

/// Distinct non-background colours of an image.
fn distinct(img: &[Rgb565]) -> usize {
    let mut v: Vec<_> = img.iter().filter(|&&c| c != BG).map(|c| (c.r(), c.g(), c.b())).collect();
    v.sort_unstable();
    v.dedup();
    v.len()
}

/// Vertex and face colours all equal to the material colour draw the plain
/// objects' pixels exactly (lit, Gouraud, meshlets included); one vertex of
/// another colour changes the image.
#[test]
fn colours_equal_to_the_material_draw_the_plain_object() {
    let c = Rgb565::new(20, 40, 10);
    let (s, m) = (sphere(), sphere_meshlets());
    let per_vertex = vec![c; s.vertex_count()];
    let per_face = vec![c; CUBE.mesh().triangle_count()];
    let cam = Camera::look_at([2.0, 2.5, 6.0], [0.0, 0.2, 0.0]);
    let place = |o: Object<'static, Rgb565>, x: f32| o.scale(0.8).rotate_y(0.4).translate([x, 0.0, 0.0]);
    let plain = [
        place(Object::new(&s, c), -1.6),
        place(Object::new(&CUBE, c), 0.4),
        place(Object::new(m, c), 2.0).translate([0.0, 0.0, -2.0]),
    ];
    let coloured = [
        plain[0].with_vertex_colors(&per_vertex),
        plain[1].with_face_colors(&per_face),
        plain[2].with_vertex_colors(&per_vertex),
    ];
    let want = draw::<8>(&cam, &plain, true);
    // Lit and Gouraud-shaded: many shades, and all three objects drawn.
    assert!(distinct(&want) > 20, "{}", distinct(&want));
    assert_eq!(draw::<8>(&cam, &coloured, true), want);
    // The material colour no longer matters where the colours are set.
    let other = coloured.map(|o| o.with_color(Rgb565::RED));
    assert_eq!(draw::<8>(&cam, &other, true), want);
    // And the colours are used: a change in them changes the image.
    for k in 0..3 {
        let mut v = per_vertex.clone();
        let mut f = per_face.clone();
        v.iter_mut().for_each(|x| *x = Rgb565::WHITE);
        f.iter_mut().for_each(|x| *x = Rgb565::WHITE);
        let mut changed = coloured;
        changed[k] = match k {
            1 => changed[k].with_face_colors(&f),
            _ => changed[k].with_vertex_colors(&v),
        };
        assert_ne!(draw::<8>(&cam, &changed, true), want, "object {k}");
    }
}

/// `p` on screen (pixel column, row) for a `look_at` camera with the default
/// 50° lens, in f64.
fn project(eye: [f64; 3], target: [f64; 3], p: [f64; 3]) -> (usize, usize) {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    };
    let unit = |a: [f64; 3]| a.map(|x| x / dot(a, a).sqrt());
    let f = unit(sub(target, eye));
    let r = unit(cross(f, [0.0, 1.0, 0.0]));
    let u = cross(r, f);
    let d = sub(p, eye);
    let t = (25f64).to_radians().tan();
    let aspect = W as f64 / f64::from(H);
    let (nx, ny) = (dot(r, d) / (dot(f, d) * t * aspect), dot(u, d) / (dot(f, d) * t));
    (((1.0 + nx) * W as f64 / 2.0) as usize, ((1.0 - ny) * f64::from(H) / 2.0) as usize)
}

/// Unlit, a face-coloured cube shows each visible face's colour exactly at
/// the face's centre.
#[test]
fn unlit_face_colours_are_exact() {
    let faces = [
        ([1.0, 0.0, 0.0], Rgb565::RED),
        ([-1.0, 0.0, 0.0], Rgb565::GREEN),
        ([0.0, 1.0, 0.0], Rgb565::BLUE),
        ([0.0, -1.0, 0.0], Rgb565::YELLOW),
        ([0.0, 0.0, 1.0], Rgb565::CYAN),
        ([0.0, 0.0, -1.0], Rgb565::MAGENTA),
    ];
    let m = CUBE.mesh();
    // Each triangle's colour from its face's normal.
    let colours: Vec<Rgb565> = m
        .indices
        .iter()
        .map(|t| faces.iter().find(|(n, _)| *n == m.normals[usize::from(t[0])]).unwrap().1)
        .collect();
    for eye in [[3.0, 2.5, 4.0], [-4.0, -2.0, -3.0], [1.5, 4.0, -3.5]] {
        let cam = Camera::look_at(eye, [0.0; 3]);
        let img = draw::<8>(&cam, &[Object::new(&CUBE, Rgb565::WHITE).with_face_colors(&colours)], false);
        let e = eye.map(f64::from);
        let mut seen = 0;
        for (n, c) in faces {
            let centre = n.map(f64::from);
            // Visible: the eye is on the outer side of the face's plane.
            if (0..3).map(|k| centre[k] * (e[k] - centre[k])).sum::<f64>() <= 0.0 {
                continue;
            }
            let (x, y) = project(e, [0.0; 3], centre);
            assert_eq!(img[y * W + x], c, "eye {eye:?}, face {n:?} at ({x}, {y})");
            seen += 1;
        }
        assert_eq!(seen, 3, "eye {eye:?}");
        // Unlit: nothing but the six face colours and the background.
        assert!(img.iter().all(|p| *p == BG || faces.iter().any(|(_, c)| c == p)));
    }
}

/// Unlit vertex colours interpolate across the front face of the cube (red
/// on the left edge, blue on the right): mixed in between, red falling and
/// blue rising left to right; the same image for bands of 1, 16 and all
/// 72 rows.
#[test]
fn vertex_colours_interpolate_for_every_band_height() {
    let m = CUBE.mesh();
    let colours: Vec<Rgb565> =
        m.positions.iter().map(|p| if p[0] < 0.0 { Rgb565::RED } else { Rgb565::BLUE }).collect();
    let cam = Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]);
    let objects = [Object::new(&CUBE, Rgb565::WHITE).with_vertex_colors(&colours)];
    let img = draw::<16>(&cam, &objects, false);
    assert_eq!(draw::<1>(&cam, &objects, false), img);
    assert_eq!(draw::<72>(&cam, &objects, false), img);
    let (cx, cy) = project([0.0, 0.0, 4.0], [0.0; 3], [0.0, 0.0, 1.0]);
    let mid = img[cy * W + cx];
    assert!(mid != Rgb565::RED && mid != Rgb565::BLUE && mid.r() > 0 && mid.b() > 0, "{mid:?}");
    // Along the centre row, across the face (between its projected edges).
    let (x0, _) = project([0.0, 0.0, 4.0], [0.0; 3], [-1.0, 0.0, 1.0]);
    let (x1, _) = project([0.0, 0.0, 4.0], [0.0; 3], [1.0, 0.0, 1.0]);
    let row: Vec<Rgb565> = (x0 + 1..x1).map(|x| img[cy * W + x]).collect();
    assert!(row.len() > 10 && row.iter().all(|&p| p != BG && p.g() == 0), "{row:?}");
    assert!(row.windows(2).all(|w| w[1].r() <= w[0].r() && w[1].b() >= w[0].b()), "{row:?}");
    assert!(row[0].r() > 26 && row[row.len() - 1].b() > 26, "{row:?}");
}

/// Colour slices of the wrong length, and face colours on a meshlet mesh,
/// are `InvalidParameter` before any band is sent.
#[test]
fn mismatched_colours_are_errors() {
    let (s, m) = (sphere(), sphere_meshlets());
    let cam = Camera::look_at([2.0, 2.5, 6.0], [0.0; 3]);
    let nv = s.vertex_count();
    let nt = s.triangle_count();
    let colours = vec![Rgb565::GREEN; nv + nt + 1];
    let run = |objects: &[Object<'_, Rgb565>]| {
        let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
        let mut fb = Framebuffer::new(W as u32, H, BG);
        let r = view.draw(&cam, objects, &mut fb);
        (r, fb.contiguous.len())
    };
    let bad = |param| Err(RenderError::Input(Error::InvalidParameter(param)));
    let (bad_vertex, bad_face) = (bad(microraster::Param::VertexColors), bad(microraster::Param::FaceColors));
    let plain = Object::new(&s, Rgb565::RED);
    let meshlets = Object::new(m, Rgb565::RED);
    for n in [0, nv - 1, nv + 1, nt] {
        assert_eq!(run(&[plain.with_vertex_colors(&colours[..n])]), (bad_vertex, 0), "{n} vertex colours");
        assert_eq!(
            run(&[meshlets.with_vertex_colors(&colours[..n])]),
            (bad_vertex, 0),
            "{n} meshlet colours"
        );
    }
    for n in [0, nt - 1, nt + 1, nv] {
        assert_eq!(run(&[plain.with_face_colors(&colours[..n])]), (bad_face, 0), "{n} face colours");
    }
    // Meshlets take vertex colours, not face colours (their triangles are
    // in cluster order), whatever the length.
    assert_eq!(run(&[meshlets.with_face_colors(&colours[..nt])]), (bad_face, 0));
    // A bad object after a good one still fails the frame before it starts.
    assert_eq!(run(&[plain, plain.with_face_colors(&colours[..nt + 1])]), (bad_face, 0));
    // The right lengths draw.
    let good = [plain.with_vertex_colors(&colours[..nv]), plain.with_face_colors(&colours[..nt])];
    assert_eq!(run(&good).0, Ok(()));
    assert_eq!(run(&[meshlets.with_vertex_colors(&colours[..nv])]).0, Ok(()));
}
