//! The knot is closed, so its snapped image has no cracks exactly when every
//! pixel centre is covered by as many front faces as back faces: a ray
//! through a centre enters the closed surface as often as it leaves it, and
//! the top-left rule decides a centre on a shared edge (or a silhouette
//! fold) the same way for both triangles. A triangle lost by the meshlet
//! stage (a cluster rejected by its sphere against a band, a triangle's band
//! or snap test), a vertex snapped differently in two bands or clusters, or
//! a crack in the coverage would leave some centre with a difference.
//!
//! Checked through [`Pipeline::meshlet_triangles`], band by band (bands of
//! 1, 7 and 16 rows), for the `f32` and `Fx` stages, from the standard
//! camera and from one close enough that the knot crosses the screen's
//! edges (inside the clipper's guard band, so the screen's rectangle cuts
//! the triangles; the near plane stays clear of the mesh, since a cut there
//! really opens it). Each band's triangles are covered with
//! [`TriangleSpans`] clipped to the band's rows. With back faces culled
//! (`Cull::Clockwise`: the normal-cone test rejects whole clusters), the
//! stage must hand over exactly the front faces' coverage.
//!
//! The standard scene's closed meshes are checked the same way through the
//! plain and the cached mesh calls; `placed.rs` places them and the knot at
//! random. Every check runs in both accuracy tiers ([`Precision`]): the
//! fast tier snaps differently, but each vertex to one point, so its image
//! is as watertight.

use super::knot_mesh::{VALID_KNOT, VALID_KNOT_FX};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::{Scalar, Vec3, transform};
use microraster::mesh::ValidMeshletMesh;
use microraster::pipeline::{ClusterCache, MeshStats, Pipeline, VertexCache};
use microraster::raster3d::{Precision, ScreenTriangle};
use microraster::{ClipRect, SubPoint};

pub(crate) const W: i32 = 320;
pub(crate) const H: i32 = 240;

/// Per pixel, the centres covered by front faces and by back faces.
#[derive(Clone, PartialEq, Debug)]
pub(crate) struct Cover {
    pub(crate) front: Vec<u16>,
    pub(crate) back: Vec<u16>,
    /// Triangles the 3D clipper cut ([`MeshStats`](microraster::pipeline::MeshStats)).
    pub(crate) clipped: u32,
}

/// Twice the signed area of snapped corners `v` (counter-clockwise on the
/// screen, y down, is negative).
fn area2<const S: u32>(v: [SubPoint<S>; 3]) -> i64 {
    let d = |a: SubPoint<S>, b: SubPoint<S>| (i64::from(b.x() - a.x()), i64::from(b.y() - a.y()));
    let ((ax, ay), (bx, by)) = (d(v[0], v[1]), d(v[0], v[2]));
    ax * by - bx * ay
}

/// The triangles `draw` hands to its sink for each band of `rows` rows
/// (first and last frame row, inclusive; it returns the band's stats),
/// each covered within its band.
pub(crate) fn banded<const S: u32>(
    rows: i32,
    mut draw: impl FnMut((i32, i32), &mut dyn FnMut(&ScreenTriangle<S>)) -> MeshStats,
) -> Cover {
    let n = (W * H) as usize;
    let mut c = Cover { front: vec![0; n], back: vec![0; n], clipped: 0 };
    for y0 in (0..H).step_by(rows as usize) {
        let y1 = (y0 + rows).min(H) - 1;
        let clip = ClipRect::new(0, y0, W, y1 + 1);
        let (front, back) = (&mut c.front, &mut c.back);
        let mut sink = |t: &ScreenTriangle<S>| {
            let v = t.v.map(|v| v.pos);
            let counts = if area2(v) > 0 { &mut *back } else { &mut *front };
            for s in TriangleSpans::new(v, clip, Cull::None) {
                for x in s.x..s.x + s.len as i32 {
                    counts[(s.y * W + x) as usize] += 1;
                }
            }
        };
        c.clipped += draw((y0, y1), &mut sink).clipped;
    }
    c
}

/// The knot `mesh` through the meshlet stage of `pipeline`, in bands of `rows`.
fn cover<T: Scalar, P: Scalar>(
    pipeline: &Pipeline<T, 4>,
    mesh: &ValidMeshletMesh<'_, P>,
    angle: f32,
    rows: i32,
) -> Cover {
    let model = transform::rotation_y(T::from_f32(angle));
    let mut cache = Box::new(ClusterCache::<T, 4>::new());
    banded(rows, |band, sink| {
        let stats = pipeline.meshlet_triangles(mesh, &model, Rgb565::WHITE, &mut cache, band, sink);
        stats.expect("the knot is a valid mesh")
    })
}

/// The accuracy tiers every check runs in.
pub(crate) const TIERS: [Precision; 2] = [Precision::Exact, Precision::Fast];

/// `pipeline` looking from `eye` at the origin, with culling `cull`, in
/// tier `tier`.
fn pipeline<T: Scalar>(eye: [f32; 3], cull: Cull, tier: Precision) -> Pipeline<T, 4> {
    let f = T::from_f32;
    let v = |p: [f32; 3]| Vec3::new(f(p[0]), f(p[1]), f(p[2]));
    let view = transform::look_at(v(eye), v([0.0; 3]), v([0.0, 1.0, 0.0])).unwrap();
    let mut p = Pipeline::perspective(view, f(0.9), f(1.0), f(20.0), W as u32, H as u32).unwrap();
    p.cull = cull;
    p.with_precision(tier)
}

/// Pixels whose front and back counts differ, and pixels covered at all.
pub(crate) fn cracks(c: &Cover) -> (usize, usize) {
    let odd = c.front.iter().zip(&c.back).filter(|(f, b)| f != b).count();
    (odd, c.front.iter().filter(|&&f| f > 0).count())
}

fn check<T: Scalar, P: Scalar>(mesh: &ValidMeshletMesh<'_, P>, name: &str, tier: Precision) {
    // The standard camera (`Scene3d::pipeline`), and one at half its distance.
    for (eye, crosses_edges) in [([0.0, 1.9, 5.6], false), ([0.0, 0.95, 2.8], true)] {
        for angle in [0.6, 2.2] {
            let whole = cover(&pipeline::<T>(eye, Cull::None, tier), mesh, angle, 16);
            let (odd, covered) = cracks(&whole);
            println!("{name} eye {eye:?} angle {angle}: {covered} px covered, {} clipped", whole.clipped);
            assert!(covered > 10_000, "{name}: the knot covers {covered} px");
            let border = (0..W * H).filter(|&i| {
                let (x, y) = (i % W, i / W);
                whole.front[i as usize] > 0 && (x == 0 || y == 0 || x == W - 1 || y == H - 1)
            });
            assert_eq!(
                border.count() > 0,
                crosses_edges,
                "{name} eye {eye:?}: the knot on the screen's edges"
            );
            assert_eq!(
                odd, 0,
                "{name} eye {eye:?} angle {angle}: {odd} px with unequal front and back counts"
            );
            for rows in [1, 7] {
                assert!(
                    cover(&pipeline::<T>(eye, Cull::None, tier), mesh, angle, rows) == whole,
                    "{name} rows {rows}"
                );
            }
            // Back faces culled: the front faces' coverage, and nothing else.
            let culled = cover(&pipeline::<T>(eye, Cull::Clockwise, tier), mesh, angle, 16);
            assert!(
                culled.front == whole.front,
                "{name} eye {eye:?} angle {angle}: front faces differ when culled"
            );
            assert!(culled.back.iter().all(|&b| b == 0), "{name}: a back face passed the cull");
        }
    }
}

#[test]
fn the_knot_covers_each_centre_as_often_by_front_as_by_back_faces_f32() {
    for tier in TIERS {
        check::<f32, f32>(&VALID_KNOT, &format!("f32 {tier:?}"), tier);
    }
}

#[test]
fn the_knot_covers_each_centre_as_often_by_front_as_by_back_faces_fx() {
    use microraster::math::Fx;
    for tier in TIERS {
        check::<Fx, Fx>(&VALID_KNOT_FX, &format!("Fx {tier:?}"), tier);
    }
}

/// The standard scene's three closed meshes (`Scene3d`: a sphere, a torus
/// and a cube, whose faces share positions rather than vertices) through
/// the plain mesh call (its 8-entry cache on the stack) and through vertex
/// caches of 3 and 64 entries and of the largest mesh, band by band (a
/// closed mesh adds nothing to the difference, so neither do three).
#[test]
fn the_standard_scene_covers_each_centre_as_often_by_front_as_by_back_faces() {
    use microraster_scenes::scenes3d::{CACHE_VERTICES, Scene3d};
    fn check_scene<T: Scalar, const V: usize>(name: &str, tier: Precision) {
        let mut pipeline = Scene3d::pipeline::<T, 4>(W as u32, H as u32).unwrap().with_precision(tier);
        pipeline.cull = Cull::None;
        for angle in [0.0, 0.9, 2.5] {
            let mut cache = Box::new(VertexCache::<T, 4, V>::new());
            let mut draw = |rows: i32, cached: bool| {
                let cache = &mut cache;
                banded(rows, |band, sink| {
                    let mut bins = Box::new(heapless::Vec::<ScreenTriangle<4>, 2400>::new());
                    let mut p = pipeline;
                    p.rows = Some(band);
                    let stats = if cached {
                        Scene3d.draw_cached::<T, Rgb565, 4, V, 2400>(&p, angle, cache, &mut bins)
                    } else {
                        Scene3d.draw::<T, Rgb565, 4, 2400>(&p, angle, &mut bins)
                    };
                    bins.iter().for_each(&mut *sink);
                    stats.expect("the standard scene fits its bins")
                })
            };
            let whole = draw(16, false);
            let (odd, covered) = cracks(&whole);
            assert!(covered > 15_000, "{name}: the scene covers {covered} px");
            assert_eq!(odd, 0, "{name} angle {angle}: {odd} px with unequal front and back counts");
            for (rows, cached) in [(16, true), (7, true), (1, false)] {
                assert!(draw(rows, cached) == whole, "{name} angle {angle} rows {rows} cached {cached}");
            }
        }
    }
    for tier in TIERS {
        check_scene::<f32, 3>("f32, 3 entries", tier);
        check_scene::<f32, 64>("f32, 64 entries", tier);
        check_scene::<f32, CACHE_VERTICES>("f32, whole mesh", tier);
        check_scene::<microraster::math::Fx, 64>("Fx, 64 entries", tier);
    }
}
