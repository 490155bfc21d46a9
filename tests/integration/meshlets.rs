//! The meshlet vertex stage (`Pipeline::draw_meshlets` through
//! `Direct3d`) draws the image of the binned path: the
//! same mesh, its triangles in cluster order, through `draw_valid_mesh` and
//! `Triangles3d`, for both numeric paths, both interpolations and any band
//! height; the cone test only rejects clusters whose every triangle faces
//! away; and in one band the height of the frame, the stage counts the
//! triangles drawn, degenerate and clipped as the binned path does.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{self, Mesh, Meshlet, MeshletMesh, ValidMesh, ValidMeshletMesh};
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect};
use microraster::render::{Direct3d, Triangles3d};
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::Scene3d;

const W: usize = 160;
const H: u32 = 120;
const BG: Rgb565 = Rgb565::BLACK;

/// A torus and its clusters: consecutive runs of triangles (the generator's
/// order is spatially coherent), each cut at 64 vertices or 12 triangles (a quarter of the tube: cones below 90°).
/// Not the crate's builder: an independent, simple one for the comparison.
struct Clustered {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    /// The triangles in cluster order (global indices), for the binned path.
    indices: Vec<[u16; 3]>,
    meshlets: Vec<Meshlet>,
    vertices: Vec<u16>,
    triangles: Vec<[u8; 3]>,
    sphere: ([f32; 3], f32),
}

fn torus() -> Clustered {
    torus_of(48, 24)
}

/// [`torus`] with `m` segments around and `n` around the tube.
fn torus_of(m: usize, n: usize) -> Clustered {
    let mut p = vec![[0.0; 3]; mesh::torus_vertex_count(m, n)];
    let mut nn = vec![[0.0; 3]; p.len()];
    let mut idx = vec![[0u16; 3]; mesh::torus_triangle_count(m, n)];
    let t = mesh::torus(m, n, 1.0, 0.42, &mut p, &mut nn, &mut idx).unwrap();
    let sphere = t.bounding_sphere;
    let mut c = Clustered {
        positions: p.clone(),
        normals: nn.clone(),
        indices: Vec::new(),
        meshlets: Vec::new(),
        vertices: Vec::new(),
        triangles: Vec::new(),
        sphere,
    };
    let mut i = 0;
    while i < idx.len() {
        let (v0, t0) = (c.vertices.len(), c.triangles.len());
        let mut local: Vec<u16> = Vec::new();
        while i < idx.len() && c.triangles.len() - t0 < 12 {
            let new = idx[i].iter().filter(|v| !local.contains(v)).count();
            if local.len() + new > 64 {
                break;
            }
            let tri = idx[i].map(|v| {
                let k = local.iter().position(|&l| l == v).unwrap_or_else(|| {
                    local.push(v);
                    local.len() - 1
                });
                k as u8
            });
            c.triangles.push(tri);
            c.indices.push(idx[i]);
            i += 1;
        }
        let pts: Vec<[f32; 3]> = local.iter().map(|&v| p[v as usize]).collect();
        let normals: Vec<[f64; 3]> =
            c.triangles[t0..].iter().map(|t| face_normal(t.map(|k| pts[k as usize]))).collect();
        let mut axis = normals.iter().fold([0.0f64; 3], |a, n| [a[0] + n[0], a[1] + n[1], a[2] + n[2]]);
        let len = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        axis = axis.map(|v| v / len);
        let min_cos =
            normals.iter().map(|n| n[0] * axis[0] + n[1] * axis[1] + n[2] * axis[2]).fold(1.0, f64::min);
        // sin of the widest angle, rounded up; no cone past 90°.
        let cutoff = if min_cos <= 0.0 { 1.0 } else { ((1.0 - min_cos * min_cos).sqrt() + 1e-6).min(1.0) };
        c.meshlets.push(Meshlet {
            vertex_offset: v0 as u32,
            triangle_offset: t0 as u32,
            vertex_count: local.len() as u8,
            triangle_count: (c.triangles.len() - t0) as u8,
            sphere: mesh::bounding_sphere(&pts),
            cone: (axis.map(|v| v as f32), cutoff as f32),
        });
        c.vertices.extend_from_slice(&local);
    }
    c
}

fn face_normal([a, b, c]: [[f32; 3]; 3]) -> [f64; 3] {
    let d = |p: [f32; 3], q: [f32; 3]| [0, 1, 2].map(|k| p[k] as f64 - q[k] as f64);
    let (u, v) = (d(b, a), d(c, a));
    let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    n.map(|x| x / len)
}

impl Clustered {
    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.normals, &self.indices, self.sphere)
    }
    fn meshlets(&self) -> ValidMeshletMesh<'_> {
        ValidMeshletMesh::new(MeshletMesh {
            mesh: Mesh::new(&self.positions, &self.normals, &[], self.sphere),
            meshlets: &self.meshlets,
            vertices: &self.vertices,
            triangles: &self.triangles,
        })
        .unwrap()
    }
}

fn model<T: Scalar>(angle: f32) -> Mat4<T> {
    let f = T::from_f32;
    transform::rotation_y(f(angle)) * transform::rotation_x(f(0.6 + angle * 0.7))
}

fn pipeline<T: Scalar>(cull: Cull, eye: [f32; 3]) -> Pipeline<T, 4> {
    pipeline_far(cull, eye, 20.0)
}

/// [`pipeline`] with its far plane at `far`.
fn pipeline_far<T: Scalar>(cull: Cull, eye: [f32; 3], far: f32) -> Pipeline<T, 4> {
    let f = T::from_f32;
    let view = transform::look_at(
        Vec3::new(f(eye[0]), f(eye[1]), f(eye[2])),
        Vec3::new(f(0.0), f(0.0), f(0.0)),
        Vec3::new(f(0.0), f(1.0), f(0.0)),
    )
    .unwrap();
    let light = Scene3d::pipeline::<T, 4>(W as u32, H).unwrap().lighting.unwrap();
    let p = Pipeline::perspective(view, f(0.9), f(0.5), f(far), W as u32, H).unwrap();
    let mut p = p.with_lighting(light);
    p.cull = cull;
    p
}

fn binned<T: Scalar, M: Interpolation, const BH: usize>(
    c: &Clustered,
    p: &Pipeline<T, 4>,
    angle: f32,
) -> Vec<Rgb565> {
    let mut bins = heapless::Vec::<_, 8192>::new();
    let mesh = ValidMesh::new(c.mesh()).unwrap();
    p.draw_valid_mesh(&mesh, &model::<T>(angle), Rgb565::new(28, 44, 12), &mut bins).unwrap();
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, BH>::new(BG), DepthBand::<Depth16, W, BH>::new());
    Renderer::new(H, BG)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, M::default()), &mut band, &mut fb)
        .unwrap();
    fb.pixels
}

fn direct<T: Scalar, M: Interpolation, const BH: usize>(
    c: &Clustered,
    p: &Pipeline<T, 4>,
    angle: f32,
    interp: M,
) -> Vec<Rgb565> {
    direct_stats::<T, M, BH>(c, p, angle, interp).0
}

/// The image and the clusters skipped (outside, back-facing), summed over bands.
fn direct_stats<T: Scalar, M: Interpolation, const BH: usize>(
    c: &Clustered,
    p: &Pipeline<T, 4>,
    angle: f32,
    interp: M,
) -> (Vec<Rgb565>, [u32; 2]) {
    let mut skipped = [0; 2];
    let mut cache = ClusterCache::<T, 4>::new();
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, BH>::new(BG), DepthBand::<Depth16, W, BH>::new());
    let mesh = c.meshlets();
    let model = model::<T>(angle);
    Renderer::new(H, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, interp, |band| {
                let s = p.draw_meshlets(&mesh, &model, Rgb565::new(28, 44, 12), &mut cache, band)?;
                skipped[0] += s.clusters_outside;
                skipped[1] += s.clusters_back_facing;
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    (fb.pixels, skipped)
}

fn covered(img: &[Rgb565]) -> usize {
    img.iter().filter(|&&c| c != BG).count()
}

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
            assert_eq!(direct::<f32, Affine, 1>(&c, &p, angle, Affine), reference, "f32 rows 1 {i}");
            assert_eq!(direct::<f32, Affine, 3>(&c, &p, angle, Affine), reference, "f32 rows 3 {i}");
            assert_eq!(direct::<f32, Affine, 120>(&c, &p, angle, Affine), reference, "f32 full {i}");
            let reference = binned::<f32, PerspectiveCorrect, 16>(&c, &p, angle);
            assert_eq!(direct::<f32, _, 16>(&c, &p, angle, PerspectiveCorrect), reference, "persp {i}");
            let p = pipeline::<Fx>(cull, eye);
            let reference = binned::<Fx, Affine, 16>(&c, &p, angle);
            assert_eq!(direct::<Fx, Affine, 16>(&c, &p, angle, Affine), reference, "Fx {i} {cull:?}");
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

/// One frame of `c` through `cache` (16-row bands, f32, affine), each band
/// drawing the mesh once per model of `models`, model `k` with cache
/// `k mod cache.len()` (whose record holds `N` clusters).
fn frame_with<const N: usize, const K: usize>(
    c: &Clustered,
    p: &Pipeline<f32, 4>,
    models: &[Mat4<f32>],
    cache: &mut [ClusterCache<f32, 4, N, K>],
) -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, 16>::new(BG), DepthBand::<Depth16, W, 16>::new());
    let mesh = c.meshlets();
    let n = cache.len();
    Renderer::new(H, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |band| {
                for (k, model) in models.iter().enumerate() {
                    p.draw_meshlets(&mesh, model, Rgb565::new(28, 44, 12), &mut cache[k % n], band)?;
                }
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.pixels
}

/// The frame's cluster record (`ClusterCache`) never changes a frame: one
/// cache kept through frames of other matrices, shared by two (each with a
/// record) or five (more than it keeps records of) placements of a mesh
/// drawn in turn in every band, and kept while the mesh itself is
/// moved in place (same buffers, same matrix: only the new frame tells),
/// draws what fresh caches draw.
#[test]
fn a_kept_cluster_cache_draws_what_fresh_caches_draw() {
    let mut c = torus();
    let mut kept = [ClusterCache::new(), ClusterCache::new()];
    let fresh = || [ClusterCache::new(), ClusterCache::new()];
    for i in 0..6 {
        let (angle, eye) = (i as f32 * 0.71, [0.5 * i as f32 - 1.2, 1.0, 3.4]);
        let p = pipeline::<f32>(Cull::Clockwise, eye);
        let one = [model::<f32>(angle)];
        let want = frame_with(&c, &p, &one, &mut fresh());
        assert!(covered(&want) > 1000);
        assert_eq!(frame_with(&c, &p, &one, &mut kept), want, "frame {i}");
        let two =
            [model::<f32>(angle), transform::translation(Vec3::new(0.9, -0.4, -1.0)) * model::<f32>(angle)];
        let want = frame_with(&c, &p, &two, &mut fresh());
        assert_eq!(frame_with(&c, &p, &two, &mut kept[..1]), want, "frame {i}, one cache for two");
        assert_eq!(frame_with(&c, &p, &two, &mut kept), want, "frame {i}, a cache each");
        // More placements than one cache keeps records of (four): they
        // take each other's places in turn.
        let five = [0.0, 0.5, 1.0, 1.5, 2.0].map(|dx| {
            transform::translation(Vec3::new(dx - 1.0, 0.3 * dx - 0.3, -2.0 - dx)) * model::<f32>(angle)
        });
        let want = frame_with(&c, &p, &five, &mut [0; 5].map(|_| ClusterCache::new()));
        assert_eq!(frame_with(&c, &p, &five, &mut kept[..1]), want, "frame {i}, one cache for five");
    }
    // The mesh moved in place between two frames of the same matrix.
    let p = pipeline::<f32>(Cull::Clockwise, [0.3, 1.0, 3.4]);
    let one = [model::<f32>(0.4)];
    let before = frame_with(&c, &p, &one, &mut kept);
    let shift = [0.0, 0.7, 0.0];
    for v in c.positions.iter_mut() {
        (0..3).for_each(|k| v[k] += shift[k]);
    }
    for m in c.meshlets.iter_mut() {
        (0..3).for_each(|k| m.sphere.0[k] += shift[k]);
    }
    (0..3).for_each(|k| c.sphere.0[k] += shift[k]);
    let want = frame_with(&c, &p, &one, &mut fresh());
    assert_ne!(want, before, "the move shows");
    assert_eq!(frame_with(&c, &p, &one, &mut kept), want, "after the move");
}

/// A mesh of more clusters than the frame record keeps: those beyond it are
/// tested per band, and the image is still the binned path's.
#[test]
fn clusters_beyond_the_frame_record_are_drawn() {
    let c = torus_of(128, 24);
    assert!(c.meshlets.len() > microraster::pipeline::FRAME_CLUSTERS + 100, "{}", c.meshlets.len());
    for (i, cull) in [Cull::Clockwise, Cull::None].into_iter().enumerate() {
        let p = pipeline::<f32>(cull, [0.4 * i as f32 - 0.8, 1.1, 3.3]);
        let angle = 0.5 + i as f32;
        let reference = binned::<f32, Affine, 16>(&c, &p, angle);
        assert!(covered(&reference) > 1000);
        assert_eq!(direct::<f32, Affine, 16>(&c, &p, angle, Affine), reference, "{cull:?}");
    }
}

/// The record's capacity changes no pixel: none (every cluster tested per
/// band), part of the mesh's clusters, all of them; for one mesh, or for
/// two placements drawn in turn with records for none, one or both.
#[test]
fn the_record_capacity_changes_no_pixel() {
    let c = torus();
    assert!(c.meshlets.len() > 64, "{}", c.meshlets.len());
    for i in 0..4 {
        let p = pipeline::<f32>(Cull::Clockwise, [0.5 * i as f32 - 1.0, 1.2, 3.3]);
        let angle = 0.9 * i as f32;
        let reference = binned::<f32, Affine, 16>(&c, &p, angle);
        let one = [model::<f32>(angle)];
        let none = frame_with(&c, &p, &one, &mut [ClusterCache::<f32, 4, 0, 0>::sized()]);
        assert_eq!(none, reference, "none {i}");
        let part = frame_with(&c, &p, &one, &mut [ClusterCache::<f32, 4, 64>::sized()]);
        assert_eq!(part, reference, "64 {i}");
        assert_eq!(frame_with(&c, &p, &one, &mut [ClusterCache::new()]), reference, "256 {i}");
        let two =
            [model::<f32>(angle), transform::translation(Vec3::new(0.8, 0.2, -1.5)) * model::<f32>(angle)];
        let want = frame_with(&c, &p, &two, &mut [ClusterCache::new(), ClusterCache::new()]);
        for (k, got) in [
            frame_with(&c, &p, &two, &mut [ClusterCache::<f32, 4, 256, 0>::sized()]),
            frame_with(&c, &p, &two, &mut [ClusterCache::<f32, 4, 256, 1>::sized()]),
            frame_with(&c, &p, &two, &mut [ClusterCache::<f32, 4, 100, 2>::sized()]),
        ]
        .into_iter()
        .enumerate()
        {
            assert_eq!(got, want, "two placements, {k} records, {i}");
        }
    }
}
