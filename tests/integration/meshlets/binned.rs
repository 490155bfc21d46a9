//! The meshlet stage against the binned path: images and triangle counts.

use super::{
    BG, Clustered, H, W, binned, binned_with, covered, direct, direct_stats, direct_with, model, pipeline,
    pipeline_far, torus,
};
use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Fx, Scalar, Vec3, transform};
use microraster::mesh::ValidMesh;
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::{Affine, PerspectiveCorrect};
use microraster::render::Direct3d;
use microraster::{Band, Renderer};

#[test]
fn meshlets_draw_the_binned_image() {
    let c = torus();
    let mut frames = 0;
    for i in 0..8 {
        let angle = i as f32 * 0.83;
        let eye = [0.4 * i as f32 - 1.5, 1.2, 3.2 + 0.3 * i as f32];
        for cull in [Cull::None, Cull::Clockwise] {
            let p = pipeline::<f32>(cull, eye);
            let reference = binned::<f32, Affine, 16>(&c, &p, angle);
            assert!(covered(&reference) > 1000, "the torus is in view: {}", covered(&reference));
            let (img, skipped) = direct_stats::<f32, Affine, 16>(&c, &p, angle, Affine);
            assert_eq!(img, reference, "f32 {i} {cull:?}");
            // Both tests do work: most clusters miss a 16-row band, and with
            // back faces culled a share of those left face away.
            assert!(skipped[0] as usize > c.meshlets.len() * 2, "{skipped:?}");
            assert_eq!(skipped[1] > 0, cull == Cull::Clockwise, "{skipped:?}");
            same_as_binned(&c, &p, &reference, (cull, eye), angle, i);
            frames += 6;
        }
    }
    assert_eq!(frames, 96);
}

/// The meshlet stage's counts in one band the height of the frame (every
/// triangle drawn exactly once), against the binned path's, without culling
/// (no cluster skipped as facing away): where no cluster is skipped as
/// outside the view, the same triangles are drawn, dropped as degenerate and
/// clipped, whichever of the meshlet stage's paths each cluster takes
/// (vertex first inside the view volume, cached where a clip plane cuts
/// it: a far plane grazing the torus's back gives the second without
/// putting a whole cluster beyond it).
#[test]
fn meshlets_count_the_binned_triangles() {
    let (inside, cut) = count_both::<f32>();
    assert!(inside >= 4 && cut >= 4, "f32: {inside} views wholly inside, {cut} cut by the far plane");
    let (inside, cut) = count_both::<Fx>();
    assert!(inside >= 4 && cut >= 4, "Fx: {inside} views wholly inside, {cut} cut by the far plane");
}

/// [`meshlets_count_the_binned_triangles`] for one numeric path: the views
/// compared, wholly inside and cut by the far plane.
fn count_both<T: Scalar>() -> (u32, u32) {
    let c = torus();
    let (mut inside, mut cut) = (0, 0);
    for k in 0..32 {
        let (i, depth_in) = (k / 4, [-20.0, 0.05, 0.2, 0.4][k % 4]);
        let angle = i as f32 * 0.83;
        let eye = [0.4 * i as f32 - 1.5, 1.2, 3.2 + 0.3 * i as f32];
        let distance = eye.iter().map(|e| e * e).sum::<f32>().sqrt();
        // The torus reaches 1.42 from its centre: a far plane `depth_in`
        // short of that may cut its back.
        let p = pipeline_far::<T>(Cull::None, eye, distance + 1.42 - depth_in);
        let mut bins = heapless::Vec::<_, 8192>::new();
        let mesh = ValidMesh::new(c.mesh()).unwrap();
        let model = model::<T>(angle);
        let want = p.draw_valid_mesh(&mesh, &model, Rgb565::new(28, 44, 12), &mut bins).unwrap();
        let mut got = microraster::pipeline::MeshStats::default();
        let mut cache = ClusterCache::<T, 4>::new();
        let (mut band, mut depth) = (Band::<Rgb565, W, 120>::new(BG), DepthBand::<Depth16, W, 120>::new());
        let mut fb = Framebuffer::new(W as u32, H, BG);
        let meshlets = c.meshlets();
        Renderer::new(H, BG)
            .render(
                Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |band| {
                    got = p.draw_meshlets(&meshlets, &model, Rgb565::new(28, 44, 12), &mut cache, band)?;
                    Ok(())
                }),
                &mut band,
                &mut fb,
            )
            .unwrap();
        // The binned path also bins triangles beyond the frame's rows (in
        // the clip volume's guard band), which the meshlet stage drops at
        // its row test, uncounted.
        let beyond = bins.iter().filter(|t| t.rows().1 < 0 || t.rows().0 >= H as i32).count() as u32;
        assert!(want.emitted - beyond > 500, "{want:?}");
        // No cluster is skipped whole (their triangles would go uncounted).
        assert_eq!((got.clusters_outside, got.clusters_back_facing), (0, 0), "view {k}");
        let counts =
            |s: &microraster::pipeline::MeshStats, beyond| (s.emitted - beyond, s.degenerate, s.clipped);
        assert_eq!(counts(&got, 0), counts(&want, beyond), "view {k}: {got:?} against {want:?}");
        assert_eq!((got.back_faces, want.back_faces), (0, 0));
        if got.clipped == 0 { inside += 1 } else { cut += 1 }
    }
    (inside, cut)
}

/// A model matrix that mirrors (negative determinant) turns the torus's
/// outward faces clockwise on screen: culling keeps the faces that face away
/// from the eye, and the normal cones must reject the clusters that face it
/// (found by the `closed` fuzz target, 2026-12-02: the cone test rejected
/// clusters facing away in 3D, which a mirror shows counter-clockwise, and
/// the image lost them). The same holds for a mirroring projection or view.
#[test]
fn mirrored_models_draw_the_binned_image() {
    fn check<T: Scalar>() {
        let c = torus();
        let f = T::from_f32;
        for i in 0..4 {
            let angle = i as f32 * 0.83;
            let eye = [0.4 * i as f32 - 1.5, 1.2, 3.2 + 0.3 * i as f32];
            let p = pipeline::<T>(Cull::Clockwise, eye);
            for s in [[-1.0, 1.0, 1.0], [1.0, -1.0, 1.0], [-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]] {
                let mirror = transform::scaling(Vec3::new(f(s[0]), f(s[1]), f(s[2])));
                let m = model::<T>(angle) * mirror;
                let reference = binned_with::<T, Affine, 16>(&c, &p, &m);
                assert!(covered(&reference) > 1000, "the torus is in view: {}", covered(&reference));
                let (img, skipped) = direct_with::<T, Affine, 16, f32>(&c.meshlets(), &p, &m, Affine);
                assert_eq!(img, reference, "{i} {s:?}");
                assert!(skipped[1] > 0, "the cones reject clusters: {skipped:?}");
            }
        }
    }
    check::<f32>();
    check::<Fx>();
}

/// The torus close enough to reach past the frame's edges: the clusters
/// across an edge lie inside the clip volume's guard band, so in `f32` they
/// take the meshlet stage's vertex-first path (`InsideView` tests the guard
/// band), in `Fx` the cached one with its outcodes; both must draw what the
/// binned path draws, in every band height.
#[test]
fn clusters_across_the_frame_edges_draw_the_binned_image() {
    let c = torus();
    let mut edges_met = 0;
    for i in 0..6 {
        let angle = i as f32 * 1.1;
        let eye = [0.3 * i as f32 - 0.8, 0.9 - 0.3 * i as f32, 2.0 + 0.1 * i as f32];
        for cull in [Cull::None, Cull::Clockwise] {
            let p = pipeline::<f32>(cull, eye);
            let reference = binned::<f32, Affine, 16>(&c, &p, angle);
            // Covered pixels on the frame's border: the torus crosses it.
            let border = (0..reference.len())
                .filter(|&k| {
                    let (x, y) = (k % W, k / W);
                    (x == 0 || x == W - 1 || y == 0 || y == H as usize - 1) && reference[k] != BG
                })
                .count();
            edges_met += usize::from(border > 20);
            let (img, _) = direct_stats::<f32, Affine, 16>(&c, &p, angle, Affine);
            assert_eq!(img, reference, "f32 {i} {cull:?}");
            same_as_binned(&c, &p, &reference, (cull, eye), angle, i);
        }
    }
    // Not vacuous: the views reach past the frame's edges.
    assert!(edges_met >= 10, "{edges_met} of 12 views reach the edges");
}

/// The meshlet stage's image of view `i` (pipeline `p`, made from `cull`
/// and `eye`, whose binned 16-row affine image is `reference`) against the
/// binned path's in the other band heights (1, 3 and 120 rows),
/// perspective-correct, and in `Fx`.
fn same_as_binned(
    c: &Clustered,
    p: &Pipeline<f32, 4>,
    reference: &[Rgb565],
    (cull, eye): (Cull, [f32; 3]),
    angle: f32,
    i: usize,
) {
    assert_eq!(direct::<f32, Affine, 1>(c, p, angle, Affine), reference, "f32 rows 1 {i}");
    assert_eq!(direct::<f32, Affine, 3>(c, p, angle, Affine), reference, "f32 rows 3 {i}");
    assert_eq!(direct::<f32, Affine, 120>(c, p, angle, Affine), reference, "f32 full {i}");
    let reference = binned::<f32, PerspectiveCorrect, 16>(c, p, angle);
    assert_eq!(direct::<f32, _, 16>(c, p, angle, PerspectiveCorrect), reference, "persp {i}");
    let p = pipeline::<Fx>(cull, eye);
    let reference = binned::<Fx, Affine, 16>(c, &p, angle);
    assert_eq!(direct::<Fx, Affine, 16>(c, &p, angle, Affine), reference, "Fx {i} {cull:?}");
}
