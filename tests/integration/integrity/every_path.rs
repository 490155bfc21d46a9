//! The property test: every rendering path (binned, cached, per band; f32 and
//! `Fx`) draws the same random clipped scene, or fails with the same error.

use super::lit;
use crate::framebuffer::Framebuffer;
use crate::props::{Tally, runner};
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{Mesh, ValidMesh, bounding_sphere};
use microraster::pipeline::{Pipeline, VertexCache};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::render::{Direct3d, Triangles3d};
use microraster::{Band, Error, RenderError, Renderer};
use proptest::prelude::*;

// ---------------------------------------------------------------------------
// Property: every rendering path draws the same scene.

const PW: usize = 48;
const PH: usize = 40;
const PBINS: usize = 256;

/// A random clipped scene: a camera anywhere within ±10^4, far/near up to
/// 10^5, a few triangles around the target, and sometimes vertices 10^3 to
/// 10^6 away (beyond the `Fx` range), used or unused.
#[derive(Debug, Clone)]
struct PScene {
    eye: [f32; 3],
    target: [f32; 3],
    fov: f32,
    near: f32,
    far: f32,
    pos: Vec<[f32; 3]>,
    idx: Vec<[u16; 3]>,
    model: Option<(f32, [f32; 3])>, // rotation about y, translation
    cull: Cull,
}

fn pscene() -> impl Strategy<Value = PScene> {
    let mag = |lo: f64, hi: f64| (lo.ln()..hi.ln()).prop_map(|l| l.exp() as f32);
    let signed =
        move |lo: f64, hi: f64| (mag(lo, hi), any::<bool>()).prop_map(|(m, s)| if s { -m } else { m });
    let v3 = move |lo: f64, hi: f64| [signed(lo, hi), signed(lo, hi), signed(lo, hi)];
    let far_vertex = prop_oneof![
        3 => v3(1.0e3, 1.0e4),
        1 => v3(3.3e4, 1.0e6),
    ];
    (
        (prop_oneof![2 => v3(0.5, 64.0), 1 => v3(64.0, 1.0e4)], [-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0]),
        (0.2f32..2.8, mag(0.01, 10.0), mag(2.0, 1.0e5)),
        (mag(0.02, 5.0), prop::collection::vec([-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0], 3..6)),
        prop_oneof![2 => Just(None), 1 => far_vertex.prop_map(Some)],
        prop::collection::vec([0u16..8, 0u16..8, 0u16..8], 1..5),
        0u8..3,
        prop_oneof![2 => Just(None), 1 => (-4.0f32..4.0, [-5.0f32..5.0, -5.0f32..5.0, -5.0f32..5.0]).prop_map(Some)],
        prop_oneof![Just(Cull::None), Just(Cull::Clockwise), Just(Cull::CounterClockwise)],
    )
        .prop_map(|((eye, target), (fov, near, ratio), (size, local), far_v, idx, far_use, model, cull)| {
            // Sized relative to the distance from the eye, so that most scenes
            // draw something.
            let dist = (0..3).map(|k| (eye[k] - target[k]).powi(2)).sum::<f32>().sqrt();
            let size = size * dist.max(0.5);
            let mut pos: Vec<[f32; 3]> =
                local.iter().map(|p| [0, 1, 2].map(|k| target[k] + p[k] * size)).collect();
            let n = pos.len() as u16;
            let mut idx: Vec<[u16; 3]> = idx.iter().map(|t| t.map(|i| i % n)).collect();
            if let Some(v) = far_v {
                pos.push(v);
                // 0: unused; 1: one triangle reaches it; 2: two do.
                for k in 0..far_use.min(2) {
                    idx.push([k as u16, n, (k as u16 + 1) % n]);
                }
            }
            PScene { eye, target, fov, near, far: near * ratio, pos, idx, model, cull }
        })
}

/// The image of one path (`Err`: its error), with the frame's pixels sent
/// exactly once.
type Img = Result<Vec<Gray8>, Error>;

fn frame_of(f: impl FnOnce(&mut Framebuffer<Gray8>) -> Result<(), Error>) -> Img {
    let mut fb = Framebuffer::new(PW as u32, PH as u32, Gray8::new(0));
    f(&mut fb)?;
    assert!(fb.writes.iter().all(|&w| w == 1), "a frame pixel sent {:?} times", fb.writes.iter().max());
    Ok(fb.pixels)
}

fn binned<const BH: usize>(bins: &[ScreenTriangle<4>]) -> Img {
    frame_of(|fb| {
        let mut band = Box::new(Band::<Gray8, PW, BH>::new(Gray8::new(0)));
        let mut depth = Box::new(DepthBand::<Depth16, PW, BH>::new());
        Renderer::new(PH as u32, Gray8::new(0))
            .render(Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, fb)
            .map_err(|_| Error::InvalidParameter(microraster::Param::User))
    })
}

fn per_band<T: Scalar, const BH: usize>(
    p: &Pipeline<T, 4>,
    mesh: &ValidMesh<'_>,
    model: &Mat4<T>,
    cached: bool,
) -> Img {
    frame_of(|fb| {
        let mut band = Box::new(Band::<Gray8, PW, BH>::new(Gray8::new(0)));
        let mut depth = Box::new(DepthBand::<Depth16, PW, BH>::new());
        let mut bins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
        let mut cache = Box::new(VertexCache::<T, 4, 8>::new());
        let mut pb = *p;
        let r = Renderer::new(PH as u32, Gray8::new(0)).render(
            Direct3d::new(&mut *depth, DepthState::LESS_WRITE, Affine, |b3| {
                bins.clear();
                pb.rows = Some(b3.rows());
                if cached {
                    pb.draw_valid_mesh_cached(mesh, model, Gray8::new(200), &mut cache, &mut bins)?;
                } else {
                    pb.draw_valid_mesh(mesh, model, Gray8::new(200), &mut bins)?;
                }
                b3.draw_all(&bins);
                Ok(())
            }),
            &mut band,
            fb,
        );
        match r {
            Ok(()) => Ok(()),
            Err(RenderError::Input(e)) => Err(e),
            Err(RenderError::Target(_)) => unreachable!(),
        }
    })
}

/// Every path of one numeric type: the images (or errors) must all be equal.
/// Returns the image and, for comparing f32 with `Fx`, the image without
/// the far plane and without depth test (see `prop_every_path_…`).
fn every_path<T: Scalar>(
    sc: &PScene,
    conv: impl Fn(f32) -> Result<T, Error>,
) -> Result<(Vec<Gray8>, Vec<Gray8>), Error> {
    let v = |a: [f32; 3]| -> Result<Vec3<T>, Error> { Ok(Vec3::new(conv(a[0])?, conv(a[1])?, conv(a[2])?)) };
    let view = transform::look_at(v(sc.eye)?, v(sc.target)?, v([0.0, 1.0, 0.0])?)?;
    let mut p = Pipeline::<T, 4>::perspective(
        view,
        conv(sc.fov)?,
        conv(sc.near)?,
        conv(sc.far)?,
        PW as u32,
        PH as u32,
    )?;
    p.cull = sc.cull;
    let model = match sc.model {
        None => Mat4::IDENTITY,
        Some((a, t)) => transform::translation(v(t)?) * transform::rotation_y(conv(a)?),
    };
    let mesh = ValidMesh::new(Mesh::new(&sc.pos, &[], &sc.idx, bounding_sphere(&sc.pos)))?;
    let mut bins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
    let whole = p.draw_valid_mesh(&mesh, &model, Gray8::new(200), &mut bins).map(|_| ());
    let mut cbins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
    let mut cache = Box::new(VertexCache::<T, 4, 8>::new());
    let cached = p.draw_valid_mesh_cached(&mesh, &model, Gray8::new(200), &mut cache, &mut cbins).map(|_| ());
    assert_eq!(whole, cached, "cached vertex stage: another result");
    let images = [
        whole.and_then(|_| binned::<PH>(&bins)),
        whole.and_then(|_| binned::<1>(&bins)),
        whole.and_then(|_| binned::<3>(&bins)),
        whole.and_then(|_| binned::<16>(&bins)),
        cached.and_then(|_| binned::<PH>(&cbins)),
        cached.and_then(|_| binned::<1>(&cbins)),
        cached.and_then(|_| binned::<3>(&cbins)),
        cached.and_then(|_| binned::<16>(&cbins)),
        per_band::<T, 1>(&p, &mesh, &model, false),
        per_band::<T, 3>(&p, &mesh, &model, false),
        per_band::<T, 16>(&p, &mesh, &model, false),
        per_band::<T, PH>(&p, &mesh, &model, false),
        per_band::<T, 1>(&p, &mesh, &model, true),
        per_band::<T, 3>(&p, &mesh, &model, true),
        per_band::<T, 16>(&p, &mesh, &model, true),
        per_band::<T, PH>(&p, &mesh, &model, true),
    ];
    const NAMES: [&str; 16] = [
        "binned, full-frame band",
        "binned, 1-row bands",
        "binned, 3-row bands",
        "binned, 16-row bands",
        "cached, full-frame band",
        "cached, 1-row bands",
        "cached, 3-row bands",
        "cached, 16-row bands",
        "per band, 1 row",
        "per band, 3 rows",
        "per band, 16 rows",
        "per band, full frame",
        "per band (cached), 1 row",
        "per band (cached), 3 rows",
        "per band (cached), 16 rows",
        "per band (cached), full frame",
    ];
    for (img, name) in images.iter().zip(NAMES).skip(1) {
        if img != &images[0] {
            let n = |i: &Img| i.as_ref().map(|i| lit(i)).map_err(|e| *e);
            panic!("{name}: {:?} pixels, binned full frame: {:?}", n(img), n(&images[0]));
        }
    }
    let mut open = p;
    open.clip = open.clip.with_far(false);
    let mut bins = heapless::Vec::<ScreenTriangle<4>, PBINS>::new();
    open.draw_valid_mesh(&mesh, &model, Gray8::new(200), &mut bins)?;
    let cross = frame_of(|fb| {
        let mut band = Box::new(Band::<Gray8, PW, 16>::new(Gray8::new(0)));
        let mut depth = Box::new(DepthBand::<Depth16, PW, 16>::new());
        Renderer::new(PH as u32, Gray8::new(0))
            .render(Triangles3d::new(&bins, &mut depth, DepthState::DISABLED, Affine), &mut band, fb)
            .map_err(|_| Error::InvalidParameter(microraster::Param::User))
    })?;
    Ok((images[0].clone()?, cross))
}

/// A pixel where the two images differ must lie within one pixel of an edge
/// of both: a neighbour where `reference` has the value `other` has there,
/// or where `other` itself changes (a sliver a pixel wide may appear or
/// vanish: the `Fx` vertex error is below half a pixel, docs/limits.md). A
/// triangle dropped or added whole fails this.
fn within_a_pixel(reference: &[Gray8], other: &[Gray8]) -> Option<(usize, usize)> {
    let on = |img: &[Gray8], x: i32, y: i32| {
        (0..PW as i32).contains(&x)
            && (0..PH as i32).contains(&y)
            && img[y as usize * PW + x as usize] != Gray8::new(0)
    };
    for y in 0..PH as i32 {
        for x in 0..PW as i32 {
            let want = on(other, x, y);
            if on(reference, x, y) != want
                && !(-1..=1).any(|dy| {
                    (-1..=1).any(|dx| {
                        let (qx, qy) = (x + dx, y + dy);
                        (0..PW as i32).contains(&qx)
                            && (0..PH as i32).contains(&qy)
                            && (on(reference, qx, qy) == want || on(other, qx, qy) != want)
                    })
                })
            {
                return Some((x as usize, y as usize));
            }
        }
    }
    None
}

/// 5,000 random clipped scenes (cameras within ±10^4, far/near up to 10^5,
/// coordinates up to 10^4 and beyond the `Fx` range) through every path:
/// binned and cached, each with bands of 1, 3, 16 and 40 rows, and per band
/// (1, 3, 16 and 40 rows), with and without the vertex cache, in f32 and in
/// `Fx`. Within a numeric type every path
/// gives the same image or the same error; `Fx` fails only with
/// `CoordinateOutOfRange` (16.16 cannot hold a value) or where f32 fails, and
/// otherwise draws what f32 draws to within a pixel. That comparison is made
/// without the far plane and depth test: `Fx` holds the projection's
/// `far/(near − far)` to 2^-16, which moves its far plane by a relative
/// `2^-16·far/near` (docs/limits.md), so near the far plane the two paths
/// may decide differently (counted, not failed).
#[test]
fn prop_every_path_draws_the_same_scene() {
    std::thread::Builder::new().stack_size(64 << 20).spawn(every_path_prop).unwrap().join().unwrap();
}

fn every_path_prop() {
    let tally = Tally::default();
    runner(5000)
        .run(&pscene(), |sc| {
            let a = every_path::<f32>(&sc, Ok);
            let b = every_path::<Fx>(&sc, Fx::try_from_f32);
            match (&a, &b) {
                (Ok((ia, a)), Ok((ib, b))) => {
                    if lit(ia) != lit(ib) {
                        tally.add("depth or far plane decides differently");
                    }
                    tally.add(if lit(a) > 0 {
                        "both drawn"
                    } else if lit(b) > 0 {
                        "Fx only"
                    } else {
                        "neither"
                    });
                    if a != b {
                        tally.add("Fx ≠ f32 (edge pixels)");
                    }
                    if let Some(at) = within_a_pixel(a, b) {
                        prop_assert!(
                            false,
                            "Fx differs from f32 by more than a pixel at {:?} ({} vs {} pixels)",
                            at,
                            lit(b),
                            lit(a)
                        );
                    }
                    if let Some(at) = within_a_pixel(b, a) {
                        prop_assert!(
                            false,
                            "f32 differs from Fx by more than a pixel at {:?} ({} vs {} pixels)",
                            at,
                            lit(a),
                            lit(b)
                        );
                    }
                }
                (Ok(_), Err(Error::CoordinateOutOfRange)) => tally.add("Fx out of range"),
                (Err(e), Err(f)) => {
                    prop_assert!(e == f || *f == Error::CoordinateOutOfRange, "f32 {:?}, Fx {:?}", e, f);
                    tally.add("both errors");
                }
                _ => prop_assert!(
                    false,
                    "f32 {:?} but Fx {:?}",
                    a.as_ref().map(|i| lit(&i.1)),
                    b.as_ref().map(|i| lit(&i.1))
                ),
            }
            Ok(())
        })
        .unwrap();
    tally.report("integrity: every path");
    for k in ["both drawn", "neither", "Fx out of range"] {
        assert!(tally.get(k) >= 30, "too few '{k}' cases");
    }
}
