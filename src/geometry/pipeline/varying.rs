//! The vertex stage for the fragment stage: [`Pipeline::draw_mesh_varying`]
//! emits [`FragTriangle`]s, screen triangles that carry `A` values per vertex
//! (texture coordinates, eye-space normals, …) computed by a caller's
//! function of each mesh vertex.
//!
//! A triangle that crosses a clip plane is cut as in
//! [`Pipeline::draw_valid_mesh`]; its new vertices carry barycentric weights
//! of the source triangle's corners through the clipper, so every value a
//! caller computes is interpolated at exactly the clipped position (weights
//! to 2^-16, then rounded to the nearest integer).

use super::bins::BinWriter;
use super::mesh_bins::triangle_in_view;
use super::tier::ExactTier;
use super::{MeshSetup, Pipeline, channels};
use crate::clip3d::{Class, ClipVertex};
use crate::fragment::FragTriangle;
use crate::math::{Mat4, Scalar, Vec3};
use crate::mesh::ValidMesh;
use crate::pipeline::{MeshStats, Shade};
use crate::raster3d::{ScreenTriangle, ScreenVertex};
use crate::{Error, Interpolate};

/// What a varying function sees of one mesh vertex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VertexInput<T> {
    /// Index of the vertex in the mesh's arrays (for per-vertex data such as
    /// texture coordinates kept beside the mesh).
    pub index: u16,
    /// Eye-space position (the camera at the origin looking down −z).
    pub position: Vec3<T>,
    /// Unit eye-space normal: the vertex normal, or the face normal for a
    /// mesh without normals or with [`Shade::Flat`].
    pub normal: Vec3<T>,
    /// The lit colour as the pipeline computes it (intensities, `[0, 1]`
    /// per channel before clamping): the material colour when the pipeline
    /// has no lighting.
    pub color: [T; 3],
}

/// Barycentric weights of a source triangle's corners, carried through the
/// clipper beside the colour: `[r, g, b, w0, w1, w2]`.
type Carried<T> = [T; 6];

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// [`Pipeline::draw_valid_mesh`] for the fragment stage: each vertex also
    /// gets `varying(&input)`, `A` integers (at most
    /// [`MAX_VARYING`](crate::varyings::MAX_VARYING) in magnitude; larger
    /// values are clamped), interpolated across the triangle by the
    /// fragment stage ([`crate::fragment`]).
    ///
    /// Errors: [`Error::CapacityExceeded`] if `bins` fills up, with the
    /// length it needed (`bins` is left as it was, as on any error);
    /// [`Error::InvalidParameter`] if `model` is singular; the others of
    /// [`Pipeline::draw_valid_mesh`], [`Error::WindingMismatch`] (culling
    /// on, the mesh wound against its normals) first.
    pub fn draw_mesh_varying<C: Interpolate, const A: usize, const N: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        varying: impl Fn(&VertexInput<T>) -> [i32; A],
        bins: &mut heapless::Vec<FragTriangle<S, A>, N>,
    ) -> Result<MeshStats, Error> {
        self.check_winding(mesh)?;
        let mut bins = BinWriter::new(bins);
        let result = self.varying_into(mesh.mesh(), model, color, varying, &mut bins);
        bins.finish(result)
    }

    /// The body of [`Pipeline::draw_mesh_varying`], into a [`BinWriter`];
    /// always in the exact tier (the fragment stage's own varyings).
    fn varying_into<C: Interpolate, const A: usize, const N: usize>(
        &self,
        mesh: &crate::mesh::Mesh<'_>,
        model: &Mat4<T>,
        color: C,
        varying: impl Fn(&VertexInput<T>) -> [i32; A],
        bins: &mut BinWriter<'_, FragTriangle<S, A>, N>,
    ) -> Result<MeshStats, Error> {
        let mut stats = MeshStats::default();
        let Some(MeshSetup { ctx, planes, band, max }) = self.mesh_setup(mesh, model, color, &mut stats)?
        else {
            return Ok(stats);
        };
        let flat = self.shade == Shade::Flat || mesh.normals.is_empty();

        for (i, idx) in mesh.indices.iter().enumerate() {
            let Some((pos, clip, class)) = triangle_in_view(mesh, i, &ctx, &band, planes)? else { continue };
            let face_n = if flat { mesh.face_normal(i) } else { None };
            let corner = |k: usize| {
                let n = if flat { face_n } else { mesh.normals.get(idx[k] as usize).copied() };
                let color = ctx.color::<ExactTier>(pos[k], n);
                let normal = n.map_or(Vec3::new(T::ZERO, T::ZERO, T::ONE), |n| {
                    (ctx.nm * Vec3::from_f32(n)).normalize()
                });
                let position = ctx.mv.transform_point(pos[k]).xyz();
                let input = VertexInput { index: idx[k], position, normal, color };
                (
                    color,
                    varying(&input)
                        .map(|v| v.clamp(-crate::varyings::MAX_VARYING, crate::varyings::MAX_VARYING)),
                )
            };
            let mut corners = [corner(0), corner(1), corner(2)];
            if self.shade == Shade::Flat {
                let c0 = corners[0].0;
                for c in &mut corners {
                    c.0 = c0;
                }
            }
            let values = corners.map(|c| c.1);
            if class == Class::Inside {
                if let Some(at) = self.snapped_and_kept::<ExactTier>(clip, &mut stats) {
                    self.push_fragment(at, corners.map(|c| c.0), values, max, bins, &mut stats);
                }
                continue;
            }
            let v = [0, 1, 2].map(|k| {
                let c = corners[k].0;
                let mut w = [T::ZERO; 3];
                w[k] = T::ONE;
                ClipVertex::<T, 6> { pos: clip[k], attr: [c[0], c[1], c[2], w[0], w[1], w[2]] }
            });
            self.clip_and_emit::<ExactTier, 6>(v, planes, &mut stats, |at, attr, stats| {
                let colors = attr.map(|a| [a[0], a[1], a[2]]);
                let vals = attr.map(|a| weighted(&a, &values));
                self.push_fragment(at, colors, vals, max, bins, stats);
                Ok(())
            })?;
        }
        Ok(stats)
    }

    /// Colours the vertices and appends the triangle with its values.
    fn push_fragment<const A: usize, const N: usize>(
        &self,
        mut v: [ScreenVertex<S>; 3],
        colors: [[T; 3]; 3],
        varyings: [[i32; A]; 3],
        max: [u8; 3],
        bins: &mut BinWriter<'_, FragTriangle<S, A>, N>,
        stats: &mut MeshStats,
    ) {
        for (v, c) in v.iter_mut().zip(colors) {
            v.color = channels(c, max);
        }
        let tri = ScreenTriangle { v, flat: self.shade == Shade::Flat };
        bins.push(FragTriangle { tri, varyings });
        stats.emitted += 1;
    }
}

/// `Σ w_k · values[k]` for the weights carried in `attr[3..6]`, rounded.
fn weighted<T: Scalar, const A: usize>(attr: &Carried<T>, values: &[[i32; A]; 3]) -> [i32; A] {
    // Weights to 2^-16 (each in [0, 1] up to the clipper's rounding).
    let w = [3, 4, 5].map(|k| attr[k].div_scaled(T::ONE, 1 << 16).unwrap_or(0).clamp(0, 1 << 16));
    core::array::from_fn(|j| {
        let sum: i64 = (0..3).map(|k| w[k] * values[k][j] as i64).sum();
        let v = (sum + (1 << 15)) >> 16;
        v.clamp(-(crate::varyings::MAX_VARYING as i64), crate::varyings::MAX_VARYING as i64) as i32
    })
}
