//! The one-call 3D front (`View3d::draw`) on fuzzed cameras, objects and
//! settings: the differential check of its per-frame records, which let a
//! band skip the chunks (plain meshes) and clusters (meshlet meshes) that
//! the bands above found outside it.
//!
//! A camera (look-at, orbit or raw; perspective with fuzzed or bad lens,
//! orthographic; a fuzzed up vector), cull, shade and lighting (none, the
//! default, specular, the viewer at infinity, a bad light), then 0–10
//! objects (more than the record's 8): the cube, icospheres of 1 and 3
//! subdivisions, a torus, the sphere in clusters, or a small fuzzed mesh
//! (often wound against its normals); each with material, per-vertex or
//! per-face colours (lengths sometimes wrong) and 0–4 steps of scale
//! (zero, negative, huge), rotation and translation (near and behind the
//! eye, far away, raw), on a frame 64 wide and 1–96 rows tall. Then:
//! * the frame in bands of 1, 3, 16 and 96 rows (96: one band, where the
//!   records never skip) gives the same result: the same error, or every
//!   pixel sent exactly once and the same image;
//! * errors only from the documented list of `View3d::draw`, all found
//!   before the first band (nothing sent);
//! * with plain meshes in their material colour only, the image equals
//!   the explicit binned path: `View3d::pipeline`, `draw_valid_mesh` of
//!   every object into one frame's bins, then `Triangles3d`.
//!
//! `VIEW3D_DEBUG=1` prints each input's scene; `VIEW3D_STATS=1` prints a
//! line per input that draws (objects, pixels drawn, binned path compared),
//! to see that a corpus is not vacuous.
#![no_main]

use std::sync::OnceLock;

use embedded_graphics_core::pixelcolor::Rgb565;
use libfuzzer_sys::fuzz_target;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::light::{Lighting, Viewer};
use microraster::math::Vec3;
use microraster::mesh::{self, Mesh, Meshlet, ValidMesh, ValidMeshletMesh};
use microraster::pipeline::Shade;
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::Triangles3d;
use microraster::view3d::{CUBE, Camera, DEFAULT_LIGHTING, Geometry, Object, View3d};
use microraster::{Band, Error, RenderError};
use microraster_fuzz::{Input, OnceFrame};

const W: usize = 64;
const MAX_ROWS: u32 = 96;
const BG: Rgb565 = Rgb565::new(3, 7, 3);

/// The built-in meshes, built once.
struct Meshes {
    small: ValidMesh<'static>,
    large: Mesh<'static>,
    torus: ValidMesh<'static>,
    clusters: &'static ValidMeshletMesh<'static>,
    /// The builder's scratch, held so that the leak checker sees it used.
    _scratch: &'static [u32],
}

fn meshes() -> &'static Meshes {
    static M: OnceLock<Meshes> = OnceLock::new();
    M.get_or_init(|| {
        let sphere = |s: u32| {
            let (nv, nt) = (mesh::icosphere_vertex_count(s), mesh::icosphere_triangle_count(s));
            let (p, n) = (Vec::leak(vec![[0.0; 3]; nv]), Vec::leak(vec![[0.0; 3]; nv]));
            mesh::icosphere(s, p, n, Vec::leak(vec![[0u16; 3]; nt])).unwrap()
        };
        let (p, n) = (Vec::leak(vec![[0.0; 3]; 96]), Vec::leak(vec![[0.0; 3]; 96]));
        let torus = mesh::torus(12, 8, 1.0, 0.35, p, n, Vec::leak(vec![[0u16; 3]; 192])).unwrap();
        let m = sphere(2);
        let (nv, nt) = (m.vertex_count(), m.triangle_count());
        let scratch = Vec::leak(vec![0u32; mesh::meshlet_scratch_len(nv, nt)]);
        let built = mesh::build_meshlets(
            m,
            Vec::leak(vec![Meshlet::default(); mesh::meshlet_bound(nt)]),
            Vec::leak(vec![0u16; mesh::meshlet_vertex_bound(nt)]),
            Vec::leak(vec![[0u8; 3]; nt]),
            scratch,
        )
        .unwrap();
        Meshes {
            small: ValidMesh::new(sphere(1)).unwrap(),
            large: sphere(3),
            torus: ValidMesh::new(torus).unwrap(),
            clusters: Box::leak(Box::new(ValidMeshletMesh::new(built).unwrap())),
            _scratch: scratch,
        }
    })
}

/// A coordinate: mostly on a 1/8 grid within ±16, sometimes raw bits.
fn coord(inp: &mut Input<'_>) -> f32 {
    match inp.u8() % 16 {
        0 => inp.f32(),
        _ => f32::from(inp.u8() as i8) / 8.0,
    }
}

fn vec3(inp: &mut Input<'_>) -> [f32; 3] {
    [coord(inp), coord(inp), coord(inp)]
}

fn camera(inp: &mut Input<'_>) -> Camera {
    let cam = match inp.u8() % 4 {
        0 => Camera::look_at(vec3(inp), vec3(inp)),
        1 => Camera::look_at([0.0, 0.0, 6.0], [0.0; 3]),
        2 => {
            let (yaw, pitch) = (f32::from(inp.u8()) / 40.0, f32::from(inp.u8() as i8) / 90.0);
            Camera::orbit([0.0; 3], 0.5 + f32::from(inp.u8()) / 16.0, yaw, pitch)
        }
        _ => Camera::look_at([f32::from(inp.u8() as i8) / 32.0, 1.0, 4.0], [0.0; 3]),
    };
    let cam = if inp.u8().is_multiple_of(8) { cam.with_up(vec3(inp)) } else { cam };
    match inp.u8() % 8 {
        0 => cam.perspective(inp.f32(), inp.f32(), inp.f32()),
        1 => cam.perspective(0.2 + f32::from(inp.u8()) / 90.0, 0.05 + f32::from(inp.u8()) / 64.0, 8.0),
        2 => cam.orthographic(0.5 + f32::from(inp.u8()) / 16.0, 0.5, 30.0),
        _ => cam,
    }
}

fn lighting(inp: &mut Input<'_>) -> Option<Lighting<f32>> {
    match inp.u8() % 6 {
        0 => None,
        1 => Some(DEFAULT_LIGHTING.with_specular(0.5, u32::from(inp.u8() % 40))),
        2 => Some(DEFAULT_LIGHTING.with_specular(0.4, 16).with_viewer(Viewer::Infinite)),
        3 => Some(Lighting { direction: Vec3::new(inp.f32(), coord(inp), coord(inp)), ..DEFAULT_LIGHTING }),
        _ => Some(DEFAULT_LIGHTING),
    }
}

/// A fuzzed mesh of 3–24 vertices on a grid, normals from its centre
/// outward (or inward), 1–32 triangles in any winding, some indices out of
/// range: it usually fails the winding check.
struct Fuzzed {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    indices: Vec<[u16; 3]>,
}

impl Fuzzed {
    fn new(inp: &mut Input<'_>) -> Self {
        let nv = 3 + usize::from(inp.u8()) % 22;
        let positions: Vec<[f32; 3]> =
            (0..nv).map(|_| [(); 3].map(|()| f32::from(inp.u8() as i8) / 64.0)).collect();
        let (c, _) = mesh::bounding_sphere(&positions);
        let s = if inp.u8().is_multiple_of(4) { -1.0 } else { 1.0 };
        let normals = positions.iter().map(|p| [0, 1, 2].map(|i| s * (p[i] - c[i]))).collect();
        let range = nv as u16 + u16::from(inp.u8().is_multiple_of(16));
        let indices = (0..1 + inp.u8() % 32).map(|_| [(); 3].map(|()| inp.u16() % range)).collect();
        Fuzzed { positions, normals, indices }
    }

    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.normals, &self.indices, mesh::bounding_sphere(&self.positions))
    }
}

/// Per-vertex and per-face colours for the largest mesh, sliced to length.
fn palette() -> &'static [Rgb565] {
    static P: OnceLock<Vec<Rgb565>> = OnceLock::new();
    P.get_or_init(|| {
        (0..1400u32).map(|i| Rgb565::new((i * 7 % 32) as u8, (i * 13 % 64) as u8, (i % 32) as u8)).collect()
    })
}

fn object<'a>(inp: &mut Input<'_>, fuzzed: &'a Mesh<'a>) -> Object<'a, Rgb565> {
    let m = meshes();
    let geometry: Geometry<'a> = match inp.u8() % 8 {
        0 => (&CUBE).into(),
        1 | 2 => (&m.small).into(),
        3 => (&m.large).into(),
        4 => (&m.torus).into(),
        5 | 6 => m.clusters.into(),
        _ => fuzzed.into(),
    };
    let color = Rgb565::new(inp.u8() % 32, inp.u8() % 64, inp.u8() % 32);
    let mut o = Object::new(geometry, color);
    for _ in 0..inp.u8() % 5 {
        o = match inp.u8() % 8 {
            0 => o.scale(inp.pick(&[0.0, -1.0, 0.3, 1e-20, 1e20, 2.0])),
            1 => o.scale_xyz(vec3(inp)),
            2 => o.rotate_x(f32::from(inp.u8()) / 40.0),
            3 => o.rotate_y(f32::from(inp.u8()) / 40.0),
            4 => o.rotate_z(f32::from(inp.u8()) / 40.0),
            _ => o.translate(vec3(inp)),
        };
    }
    let (nv, nt) = match geometry {
        Geometry::Mesh(g) => (g.vertex_count(), g.triangle_count()),
        Geometry::Valid(g) => (g.mesh().vertex_count(), g.mesh().triangle_count()),
        Geometry::Meshlets(g) => (g.get().mesh.vertex_count(), g.get().mesh.triangle_count()),
    };
    // Mostly the right length, sometimes one short or one long.
    let len = |n: usize, k: u8| match k % 16 {
        0 => n.saturating_sub(1),
        1 => n + 1,
        _ => n,
    };
    match inp.u8() % 4 {
        0 => o.with_vertex_colors(&palette()[..len(nv, inp.u8())]),
        1 => o.with_face_colors(&palette()[..len(nt, inp.u8())]),
        _ => o,
    }
}

type Settings = (Cull, Shade, Option<Lighting<f32>>);

/// A front of `BH`-row bands with `settings`.
fn view<const BH: usize>(settings: Settings) -> Box<View3d<Rgb565, W, BH>> {
    let mut view = Box::new(View3d::<Rgb565, W, BH>::new(BG));
    view.set_cull(settings.0);
    view.set_shade(settings.1);
    view.set_lighting(settings.2);
    view
}

/// One frame through a front of `BH`-row bands: its result and image.
fn front<const BH: usize>(
    settings: Settings,
    camera: &Camera,
    objects: &[Object<'_, Rgb565>],
    rows: u32,
) -> (Result<(), RenderError<core::convert::Infallible>>, Vec<Option<Rgb565>>) {
    let mut frame = OnceFrame::new(W as i32, rows as i32);
    let r = view::<BH>(settings).draw(camera, objects, &mut frame);
    (r, frame.px)
}

/// The explicit binned path of the same frame (plain meshes, material colours).
fn binned(
    settings: Settings,
    camera: &Camera,
    objects: &[Object<'_, Rgb565>],
    rows: u32,
) -> Option<Vec<Option<Rgb565>>> {
    let (pipe, renderer) = view::<8>(settings).pipeline(camera, rows).ok()?;
    let mut bins = Box::new(heapless::Vec::<_, 16384>::new());
    for o in objects {
        let m = match o.geometry() {
            Geometry::Mesh(m) => ValidMesh::new(m).ok()?,
            Geometry::Valid(m) => m,
            _ => return None,
        };
        pipe.draw_valid_mesh(&m, &o.model(), o.color(), &mut *bins).ok()?;
    }
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(BG), DepthBand::<Depth16, W, 8>::new());
    let mut frame = OnceFrame::new(W as i32, rows as i32);
    let tris = Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect);
    renderer.render(tris, &mut band, &mut frame).ok()?;
    Some(frame.px)
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let rows = 1 + u32::from(inp.u8()) % MAX_ROWS;
    let settings = (
        inp.pick(&[Cull::Clockwise, Cull::Clockwise, Cull::None, Cull::CounterClockwise]),
        inp.pick(&[Shade::Gouraud, Shade::Gouraud, Shade::Flat]),
        lighting(&mut inp),
    );
    let cam = camera(&mut inp);
    let fuzzed = Fuzzed::new(&mut inp);
    let fuzzed_mesh = fuzzed.mesh();
    let objects: Vec<_> = (0..inp.u8() % 11).map(|_| object(&mut inp, &fuzzed_mesh)).collect();

    if std::env::var_os("VIEW3D_DEBUG").is_some() {
        eprintln!("rows {rows} {settings:?}\n{cam:?}\n{objects:#?}");
    }
    let (want, image) = front::<{ MAX_ROWS as usize }>(settings, &cam, &objects, rows);
    let others = [
        (1, front::<1>(settings, &cam, &objects, rows)),
        (3, front::<3>(settings, &cam, &objects, rows)),
        (16, front::<16>(settings, &cam, &objects, rows)),
    ];
    for (bh, (got, other)) in others {
        assert_eq!(got, want, "{bh}-row bands");
        if want.is_ok() {
            let differ = image.iter().zip(&other).filter(|(a, b)| a != b).count();
            assert_eq!(differ, 0, "{bh}-row bands: {differ} pixels differ from one band");
        }
    }
    match want {
        Ok(()) => {
            assert!(image.iter().all(Option::is_some), "a pixel not sent");
            let plain = objects.iter().all(|o| {
                matches!(o.colors(), microraster::view3d::Colors::Material)
                    && !matches!(o.geometry(), Geometry::Meshlets(_))
            });
            let reference = if plain { binned(settings, &cam, &objects, rows) } else { None };
            if let Some(reference) = &reference {
                let differ = image.iter().zip(reference).filter(|(a, b)| a != b).count();
                assert_eq!(differ, 0, "{differ} pixels differ from the binned path");
            }
            if std::env::var_os("VIEW3D_STATS").is_some() {
                let drawn = image.iter().filter(|&&c| c != Some(BG)).count();
                eprintln!(
                    "STATS ok {} objects, {drawn} of {} pixels drawn, binned {}",
                    objects.len(),
                    image.len(),
                    reference.is_some()
                );
            }
        }
        // The light's, then the camera's errors first (`View3d::pipeline`),
        // then the objects' (a mesh's validation and winding, colours that
        // do not fit it, a singular model, a clip coordinate beyond ±2^64),
        // all before the first band: nothing is sent (issue 60).
        Err(e) => {
            assert!(image.iter().all(Option::is_none), "{e:?} after a band was sent");
            match view::<8>(settings).pipeline(&cam, rows) {
                Err(first) => assert_eq!(e, RenderError::Input(first)),
                Ok(_) => {
                    // A NaN or infinite model (a NaN step, a scale that
                    // overflows) is NonFiniteCoordinate (issue 63), and only then.
                    let non_finite = objects.iter().any(|o| !o.model().cols.iter().flatten().all(|v| v.is_finite()));
                    assert!(
                        matches!(
                            e,
                            RenderError::Input(
                                Error::InvalidParameter(_)
                                    | Error::InvalidMesh(_)
                                    | Error::WindingMismatch
                                    | Error::CoordinateOutOfRange
                            )
                        ) || (non_finite && e == RenderError::Input(Error::NonFiniteCoordinate)),
                        "undocumented error {e:?}"
                    )
                }
            }
        }
    }
});
