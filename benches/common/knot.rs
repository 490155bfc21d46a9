//! The 20k-triangle knot (issue 12; `examples/common/knot_mesh.rs`, included
//! by the crate root as `knot_mesh`) for the peer comparison: microraster's
//! meshlet stage against the `euc` crate (0.5, a software renderer written
//! for the host), same frame, same camera, same light.
//!
//! * microraster ([`mr_knot`]): `Direct3d` with
//!   `Pipeline::draw_meshlets` per 16-row band, 16-bit depth, Gouraud with
//!   the standard scene's light (ambient, Lambert, Blinn–Phong), back faces
//!   culled: what `examples/fw_bench` counts on the Cortex-M4F.
//! * euc ([`EucKnot`]): the same mesh as an index list through
//!   `euc::rasterizer::Triangles` with back-face culling on and its only
//!   depth buffer (`f32`, `IfLessWrite`), into a whole `W × H` `Rgb565`
//!   framebuffer. Its vertex shader computes the same lighting per corner in
//!   `f32` (euc has no index cache: every corner is shaded, as it is
//!   designed). euc interpolates perspective-correct only, so the
//!   like-for-like comparison is microraster's `PerspectiveCorrect`.
//!
//! Both frames start from the background (euc clears its colour and depth
//! buffers, microraster clears each band), so each timed call is a whole frame.
//!
//! Included with `#[path]` beside `benches/common/mod.rs` (as `crate::common`)
//! and `examples/common/knot_mesh.rs` (as `crate::knot_mesh`) by the
//! criterion benchmarks and the report.

// Each includer uses part of it (the benchmarks time, the report also counts).
#![allow(dead_code)]

use crate::common::*;
use crate::knot_mesh::{KNOT_MESH, VALID_KNOT};
use embedded_graphics::prelude::RgbColor;
use embedded_graphics_core::pixelcolor::Rgb565;
use euc::Pipeline as _;
use euc::Target as _;
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingEnabled, Triangles};
use microraster::depth::{DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Mat4, Scalar, transform};
use microraster::mesh::ValidMeshletMesh;
use microraster::pipeline::ClusterCache;
use microraster::pipeline::Pipeline;
use microraster::raster3d::Interpolation;
use microraster::raster3d::ScreenTriangle;
use microraster::render::Direct3d;
use microraster::{Band, Renderer};

/// The knot's colour (`examples/fw_bench`'s and `examples/fw_sweep`'s).
pub const KNOT_COLOR: Rgb565 = Rgb565::new(27, 46, 12);

/// Mesh triangles of the knot.
pub fn triangles() -> usize {
    KNOT_MESH.indices.len()
}

/// The knot's model matrix: the standard scene's angle about y.
pub fn knot_model<T: Scalar>() -> Mat4<T> {
    transform::rotation_y(T::from_f32(ANGLE))
}

/// One knot frame through microraster's meshlet stage (16-row bands,
/// 16-bit depth, interpolation `M`) into `target`.
pub fn mr_knot<T: Scalar, M: Interpolation + Default>(
    pipeline: &Pipeline<T, 4>,
    cache: &mut ClusterCache<T, 4>,
    band: &mut Band<Rgb565, W, 16>,
    depth: &mut DepthBand<microraster::depth::Depth16, W, 16>,
    target: &mut impl Frame,
) {
    mr_knot_of::<T, M, f32, 16>(&VALID_KNOT, pipeline, cache, band, depth, target);
}

/// [`mr_knot`] of `mesh` (the knot, its data in `f32` or, `KNOT_FX`, in
/// 16.16), in bands of `R` rows.
pub fn mr_knot_of<T: Scalar, M: Interpolation + Default, P: Scalar, const R: usize>(
    mesh: &ValidMeshletMesh<'static, P>,
    pipeline: &Pipeline<T, 4>,
    cache: &mut ClusterCache<T, 4>,
    band: &mut Band<Rgb565, W, R>,
    depth: &mut DepthBand<microraster::depth::Depth16, W, R>,
    target: &mut impl Frame,
) {
    let model = knot_model::<T>();
    Renderer::new(H as u32, BG3)
        .render(
            Direct3d::new(depth, DepthState::LESS_WRITE, M::default(), |band| {
                pipeline.draw_meshlets(mesh, &model, KNOT_COLOR, cache, band).map(|_| ())
            }),
            band,
            target,
        )
        .unwrap();
}

/// The band loop and the vertex stage of [`mr_knot`] alone: each 16-row
/// band cleared and sent, its triangles
/// ([`Pipeline::meshlet_triangles`], what `draw_meshlets` would draw) only
/// counted, no pixel drawn (`examples/fw_bench`'s stage row "band loop +
/// vertex stage only").
pub fn mr_knot_vertex_only<T: Scalar>(
    pipeline: &Pipeline<T, 4>,
    cache: &mut ClusterCache<T, 4>,
    band: &mut Band<Rgb565, W, 16>,
    target: &mut impl Frame,
) {
    let model = knot_model::<T>();
    let mut result = Ok(());
    Renderer::new(H as u32, BG3)
        .render(
            microraster::render::from_fn(|view| {
                let mut n = 0u32;
                let rows = (view.y0(), view.y1() - 1);
                let s = pipeline.meshlet_triangles(&VALID_KNOT, &model, KNOT_COLOR, cache, rows, |t| {
                    n = n.wrapping_add(std::hint::black_box(t).v[0].depth >> 16)
                });
                std::hint::black_box(n);
                if result.is_ok() {
                    result = s.map(|_| ());
                }
                Ok(())
            }),
            band,
            target,
        )
        .unwrap();
    result.unwrap();
}

/// Fragments of the knot's frame: every pixel of every screen triangle the
/// binned path emits (back faces culled), before the depth test.
pub fn fragments() -> u64 {
    let p = pipeline3d::<f32, 4>();
    let mut bins = Box::new(heapless::Vec::<ScreenTriangle<4>, 16384>::new());
    let mesh = microraster::mesh::ValidMesh::new(KNOT_MESH).unwrap();
    p.draw_valid_mesh(&mesh, &knot_model::<f32>(), KNOT_COLOR, &mut bins).unwrap();
    let clip = microraster::ClipRect::new(0, 0, W as i32, H as i32);
    bins.iter()
        .map(|t| {
            microraster::edge::TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None)
                .map(|s| s.len as u64)
                .sum::<u64>()
        })
        .sum()
}

/// The knot through euc: its shader's uniforms, the index list and the
/// buffers.
pub struct EucKnot {
    shader: EucShader,
    /// The mesh's triangles as a flat index list (euc draws groups of three).
    indices: Vec<u32>,
    /// Colour buffer.
    pub color: Buffer2d<Rgb565>,
    depth: Buffer2d<f32>,
}

/// The uniforms of euc's shaders: matrices and light in `f32`.
struct EucShader {
    /// Model-view-projection, rows.
    mvp: [[f32; 4]; 4],
    /// Model-view, rows (a rotation and a translation: it maps normals too).
    mv: [[f32; 4]; 4],
    light: [f32; 3],
    base: [f32; 3],
}

fn to_f32(m: &M4) -> [[f32; 4]; 4] {
    m.map(|r| r.map(|v| v as f32))
}

fn apply32(m: &[[f32; 4]; 4], p: [f32; 4]) -> [f32; 4] {
    [0, 1, 2, 3].map(|i| m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] * p[3])
}

fn unit32(v: [f32; 3]) -> [f32; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / l)
}

fn dot32(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl EucKnot {
    /// Uniforms from the standard scene's camera and light, the knot at [`ANGLE`].
    pub fn new() -> Self {
        let (view, proj) = camera();
        let mv = mul(&view, &rot_y(ANGLE as f64));
        let mvp = mul(&proj, &mv);
        let c = KNOT_COLOR;
        let shader = EucShader {
            mvp: to_f32(&mvp),
            mv: to_f32(&mv),
            light: norm(LIGHT).map(|v| v as f32),
            base: [c.r() as f32 / 31.0, c.g() as f32 / 63.0, c.b() as f32 / 31.0],
        };
        EucKnot {
            shader,
            indices: KNOT_MESH.indices.iter().flatten().map(|&i| u32::from(i)).collect(),
            color: Buffer2d::new([W, H], BG3),
            depth: Buffer2d::new([W, H], 1.0),
        }
    }

    /// One frame: both buffers cleared, every triangle drawn.
    pub fn frame(&mut self) {
        self.color.clear(BG3);
        self.depth.clear(1.0);
        self.shader.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingEnabled>, _>(
            &self.indices,
            &mut self.color,
            Some(&mut self.depth),
        );
    }

    /// The colour buffer's pixels, row by row.
    pub fn pixels(&self) -> &[Rgb565] {
        self.color.as_ref()
    }
}

impl Default for EucKnot {
    fn default() -> Self {
        Self::new()
    }
}

impl euc::Pipeline for EucShader {
    type Vertex = u32;
    type VsOut = (f32, f32, f32);
    type Pixel = Rgb565;

    /// Transform and light one corner (the standard scene's formula, as the
    /// f64 reference pipeline `Ref3d` writes it).
    #[inline]
    fn vert(&self, &i: &u32) -> ([f32; 4], Self::VsOut) {
        let p = KNOT_MESH.positions[i as usize];
        let n = KNOT_MESH.normals[i as usize];
        let clip = apply32(&self.mvp, [p[0], p[1], p[2], 1.0]);
        let e = apply32(&self.mv, [p[0], p[1], p[2], 1.0]);
        let nv = apply32(&self.mv, [n[0], n[1], n[2], 0.0]);
        let n = unit32([nv[0], nv[1], nv[2]]);
        let lambert = dot32(n, self.light).max(0.0);
        let spec = if lambert > 0.0 {
            let v = unit32([e[0], e[1], e[2]]);
            let h = unit32([0, 1, 2].map(|k| self.light[k] - v[k]));
            SPECULAR as f32 * dot32(n, h).max(0.0).powi(SHININESS)
        } else {
            0.0
        };
        let c = self.base.map(|b| (b * (AMBIENT as f32 + DIFFUSE as f32 * lambert) + spec).clamp(0.0, 1.0));
        (clip, (c[0], c[1], c[2]))
    }

    #[inline]
    fn frag(&self, &(r, g, b): &Self::VsOut) -> Rgb565 {
        let q = |v: f32, m: f32| (v.clamp(0.0, 1.0) * m + 0.5) as u8;
        Rgb565::new(q(r, 31.0), q(g, 63.0), q(b, 31.0))
    }
}
