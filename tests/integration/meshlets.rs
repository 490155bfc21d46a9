//! The meshlet vertex stage (`Pipeline::draw_meshlets` through
//! `Direct3d`) draws the image of the binned path: the
//! same mesh, its triangles in cluster order, through `draw_valid_mesh` and
//! `Triangles3d`, for both numeric paths, both interpolations and any band
//! height; the cone test only rejects clusters whose every triangle faces
//! away; and in one band the height of the frame, the stage counts the
//! triangles drawn, degenerate and clipped as the binned path does.

mod binned;
mod cluster_cache;
mod cones;
mod fx_data;

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::RgbColor;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Mat4, Scalar, Vec3, transform};
use microraster::mesh::{self, Mesh, Meshlet, MeshletMesh, ValidMesh, ValidMeshletMesh};
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::Interpolation;
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
    binned_with::<T, M, BH>(c, p, &model::<T>(angle))
}

/// [`binned`] with the torus placed by `model`.
fn binned_with<T: Scalar, M: Interpolation, const BH: usize>(
    c: &Clustered,
    p: &Pipeline<T, 4>,
    model: &Mat4<T>,
) -> Vec<Rgb565> {
    let mut bins = heapless::Vec::<_, 8192>::new();
    let mesh = ValidMesh::new(c.mesh()).unwrap();
    p.draw_valid_mesh(&mesh, model, Rgb565::new(28, 44, 12), &mut bins).unwrap();
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
    direct_of::<T, M, BH, f32>(&c.meshlets(), p, angle, interp)
}

/// [`direct_stats`] of any meshlet mesh (its data in `f32` or 16.16).
fn direct_of<T: Scalar, M: Interpolation, const BH: usize, P: Scalar>(
    mesh: &ValidMeshletMesh<'_, P>,
    p: &Pipeline<T, 4>,
    angle: f32,
    interp: M,
) -> (Vec<Rgb565>, [u32; 2]) {
    direct_with::<T, M, BH, P>(mesh, p, &model::<T>(angle), interp)
}

/// [`direct_of`] with the mesh placed by `model`.
fn direct_with<T: Scalar, M: Interpolation, const BH: usize, P: Scalar>(
    mesh: &ValidMeshletMesh<'_, P>,
    p: &Pipeline<T, 4>,
    model: &Mat4<T>,
    interp: M,
) -> (Vec<Rgb565>, [u32; 2]) {
    let mut skipped = [0; 2];
    let mut cache = ClusterCache::<T, 4>::new();
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, BH>::new(BG), DepthBand::<Depth16, W, BH>::new());
    Renderer::new(H, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, interp, |band| {
                let s = p.draw_meshlets(mesh, model, Rgb565::new(28, 44, 12), &mut cache, band)?;
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
