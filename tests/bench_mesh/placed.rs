//! Closed meshes placed at random cover every pixel centre as often by
//! front faces as by back faces (`closed.rs` says why that means no cracks
//! and no lost triangle): the standard scene's meshes through the plain mesh
//! call, the knot through the meshlet stage, turned about three axes,
//! scaled unevenly and moved across the screen's edges, in bands of random
//! height, clipped at the guard band or (`Pipeline::confined`) at the
//! screen's edges. Placements that reach the near or far plane are skipped:
//! a cut there really opens the mesh. The cases alternate between the two
//! accuracy tiers (`closed::TIERS`).

use super::closed::{Cover, H, TIERS, W, banded, cracks};
use super::knot_mesh::{VALID_KNOT, VALID_KNOT_FX};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use microraster::edge::Cull;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{ValidMesh, ValidMeshletMesh};
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::{Precision, ScreenTriangle};
use microraster_scenes::scenes3d::Scene3d;

/// A model placement and how the frame is cut into bands.
#[derive(Clone, Copy, Debug)]
struct Placement {
    /// Angles about x, y and z, scales along x, y and z, translation.
    model: [f32; 9],
    rows: i32,
    /// Clipped at the screen's edges rather than at the guard band.
    confined: bool,
}

impl Placement {
    /// The next placement of the xorshift sequence `seed`.
    fn random(seed: &mut u64) -> Self {
        let mut r = |lo: f32, hi: f32| {
            *seed ^= *seed << 13;
            *seed ^= *seed >> 7;
            *seed ^= *seed << 17;
            lo + (hi - lo) * ((*seed >> 40) as f32 / (1u64 << 24) as f32)
        };
        let s = r(0.3, 2.2);
        let scale = if r(0.0, 1.0) < 0.5 { [s; 3] } else { [s, r(0.3, 2.2), r(0.3, 2.2)] };
        let [a, b, c] = [(); 3].map(|()| r(-3.2, 3.2));
        let model = [a, b, c, scale[0], scale[1], scale[2], r(-4.0, 4.0), r(-3.0, 3.0), r(-6.0, 3.0)];
        let rows = [1, 5, 16, 240][(r(0.0, 4.0) as usize).min(3)];
        Placement { model, rows, confined: r(0.0, 1.0) < 0.4 }
    }

    /// Whether it moves the mesh far enough out to cross the screen's edges.
    fn off_centre(&self) -> bool {
        self.model[6].abs() > 2.0 || self.model[7].abs() > 1.5
    }

    /// The standard scene's pipeline without culling, and the model matrix;
    /// `None` if a vertex of `positions` reaches the near (1) or far (20)
    /// plane.
    fn pipeline<T: Scalar, const S: u32>(&self, positions: &[[f32; 3]]) -> Option<(Pipeline<T, S>, Mat4<T>)> {
        let [ax, ay, az, sx, sy, sz, tx, ty, tz] = self.model.map(T::from_f32);
        let model = transform::translation(Vec3::new(tx, ty, tz))
            * transform::rotation_z(az)
            * transform::rotation_x(ax)
            * transform::rotation_y(ay)
            * transform::scaling(Vec3::new(sx, sy, sz));
        let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, H as u32).ok()?;
        if self.confined {
            // Clipped at the screen's edges: within half a pixel of no centre.
            pipeline = pipeline.confined();
        }
        pipeline.cull = Cull::None;
        let mv = pipeline.view() * model;
        let depth = |p: &[f32; 3]| -mv.transform_point(Vec3::from_f32(*p)).z.to_f32();
        positions.iter().all(|p| (1.01..19.9).contains(&depth(p))).then_some((pipeline, model))
    }
}

/// `mesh` through the plain mesh call as `at` places it: its coverage, or
/// `None` if the placement is skipped or `Fx` cannot hold its coordinates.
fn plain<T: Scalar, const S: u32>(mesh: &ValidMesh<'_>, at: Placement, tier: Precision) -> Option<Cover> {
    let (pipeline, model) = at.pipeline::<T, S>(mesh.mesh().positions)?;
    let pipeline = pipeline.with_precision(tier);
    let mut failed = false;
    let cover = banded::<S>(at.rows, |band, sink| {
        let mut bins = Box::new(heapless::Vec::<ScreenTriangle<S>, 1200>::new());
        let mut p = pipeline;
        p.rows = Some(band);
        let stats = p.draw_valid_mesh(mesh, &model, Rgb565::WHITE, &mut bins);
        bins.iter().for_each(&mut *sink);
        failed |= stats.is_err();
        stats.unwrap_or_default()
    });
    (!failed).then_some(cover)
}

/// `mesh` (the knot) through the meshlet stage as `at` places it, with
/// culling `cull`, as [`plain`].
fn meshlets<T: Scalar, P: Scalar>(
    mesh: &ValidMeshletMesh<'_, P>,
    at: Placement,
    cull: Cull,
    tier: Precision,
) -> Option<Cover> {
    // The premise from the `f32` knot's positions: the 16.16 knot holds the
    // same values (`fx_knot_holds_the_f32_knot_values`).
    let (mut pipeline, model) = at.pipeline::<T, 4>(VALID_KNOT.get().mesh.positions)?;
    pipeline.cull = cull;
    let pipeline = pipeline.with_precision(tier);
    let mut cache = Box::new(ClusterCache::<T, 4>::new());
    let mut failed = false;
    let cover = banded::<4>(at.rows, |band, sink| {
        let stats = pipeline.meshlet_triangles(mesh, &model, Rgb565::WHITE, &mut cache, band, sink);
        failed |= stats.is_err();
        stats.unwrap_or_default()
    });
    (!failed).then_some(cover)
}

/// Tallies of the placements checked, for the test's own premise.
#[derive(Default, Debug)]
struct Tally {
    checked: u32,
    off_centre: u32,
    clipped: u32,
}

impl Tally {
    /// Checks `cover` of placement `at` (if it was drawn) and counts it.
    fn check(&mut self, cover: Option<&Cover>, at: Placement, what: &str) {
        let Some(cover) = cover else { return };
        let (odd, _) = cracks(cover);
        assert_eq!(odd, 0, "{what} {at:?}: px with unequal front and back counts");
        self.checked += 1;
        self.off_centre += at.off_centre() as u32;
        self.clipped += (cover.clipped > 0) as u32;
    }
}

#[test]
fn the_standard_scene_placed_at_random_covers_each_centre_as_often_by_front_as_by_back_faces() {
    let meshes = Scene3d.valid_meshes();
    let mut seed = 0x5EED_C105_ED00_0001u64;
    let mut tally = Tally::default();
    for case in 0..240 {
        let at = Placement::random(&mut seed);
        let mesh = &meshes[case % 3];
        let tier = TIERS[case / 4 % 2];
        let cover = match case % 4 {
            0 => plain::<f32, 0>(mesh, at, tier),
            1 => plain::<f32, 8>(mesh, at, tier),
            2 => plain::<Fx, 4>(mesh, at, tier),
            _ => plain::<f32, 4>(mesh, at, tier),
        };
        tally.check(cover.as_ref(), at, &format!("case {case}, mesh {}", case % 3));
    }
    println!("standard scene: {tally:?}");
    assert!(tally.checked > 120 && tally.off_centre > 30 && tally.clipped > 30, "{tally:?}");
}

/// The knot, also with back faces culled: then the stage (its frustum, band
/// and normal-cone tests of whole clusters) must hand over exactly the
/// front faces' coverage.
#[test]
fn the_knot_placed_at_random_covers_each_centre_as_often_by_front_as_by_back_faces() {
    let mut seed = 0x5EED_0000_C0DE_0002u64;
    let mut tally = Tally::default();
    for case in 0..40 {
        let at = Placement::random(&mut seed);
        let tier = TIERS[case / 2 % 2];
        let [whole, culled] = [Cull::None, Cull::Clockwise].map(|cull| {
            if case % 2 == 0 {
                meshlets::<f32, f32>(&VALID_KNOT, at, cull, tier)
            } else {
                meshlets::<Fx, Fx>(&VALID_KNOT_FX, at, cull, tier)
            }
        });
        tally.check(whole.as_ref(), at, &format!("knot case {case}"));
        if let (Some(whole), Some(culled)) = (whole, culled) {
            assert!(culled.front == whole.front, "knot case {case} {at:?}: front faces differ when culled");
            assert!(culled.back.iter().all(|&b| b == 0), "knot case {case}: a back face passed the cull");
        }
    }
    println!("knot: {tally:?}");
    assert!(tally.checked > 20 && tally.off_centre > 5, "{tally:?}");
}
