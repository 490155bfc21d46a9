//! The per-mesh part of the vertex stage, before any vertex work: the
//! matrices, the whole-mesh culls (the view volume's planes against the
//! bounding sphere, then the band) and the range checks: for `Fx`, that
//! nothing saturates 16.16; for `f32`, that no clip coordinate leaves the
//! clipper's input range (±2^64), where it would discard the triangle.

use super::model_light::ModelLight;
use super::{MeshSetup, MeshStats, Pipeline, VertexCtx, material};
use crate::clip3d::INPUT_LIMIT as CLIP_INPUT_LIMIT;
use crate::clip3d::guard_band_for_range;
use crate::math::{Mat3, Mat4, Scalar, Vec3, Vec4};
use crate::mesh::Mesh;
use crate::{Error, Interpolate};

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// The per-mesh part of the vertex stage: the matrices, the whole-mesh
    /// culls (view volume, then [`Pipeline::rows`]) and the clip planes;
    /// `None` when the mesh is culled (counted in `stats`).
    pub(super) fn mesh_setup<P: Scalar, C: Interpolate>(
        &self,
        mesh: &Mesh<'_, P>,
        model: &Mat4<T>,
        color: C,
        stats: &mut MeshStats,
    ) -> Result<Option<MeshSetup<T>>, Error> {
        let Some((model_view, mvp, normal_matrix)) = self.mesh_matrices(mesh, model)? else {
            stats.mesh_culled = true;
            return Ok(None);
        };
        let band = self.band_bounds();
        if !band.sphere_touches(&mvp, mesh.bounding_sphere) {
            return Ok(None);
        }
        // A guard band beyond what snapping can represent would drop visible
        // triangles; clamp it (the `clip` field is public).
        let range = guard_band_for_range(self.size.0, self.size.1, S);
        let planes = self.clip.with_guard_band(self.clip.guard_band().min(range));
        let max = C::CHANNEL_MAX;
        let base = material::base_of(color);
        let model_light = match &self.lighting {
            Some(l) => ModelLight::new(l, &model_view, self.precision == crate::raster3d::Precision::Fast),
            _ => None,
        };
        let ctx =
            VertexCtx { mv: model_view, mvp, nm: normal_matrix, base, lighting: self.lighting, model_light };
        Ok(Some(MeshSetup { ctx, planes, band, max }))
    }

    /// The checks of [`Pipeline::mesh_setup`] that do not depend on
    /// [`Pipeline::rows`], in its order, and the matrices they yield
    /// (model-view, model-view-projection, normal matrix); `None` when the
    /// mesh lies wholly outside the view volume. The same in every band, so
    /// the `view3d` front runs it once before the first band
    /// ([`Pipeline::check_mesh`]).
    #[allow(clippy::type_complexity)]
    fn mesh_matrices<P: Scalar>(
        &self,
        mesh: &Mesh<'_, P>,
        model: &Mat4<T>,
    ) -> Result<Option<(Mat4<T>, Mat4<T>, Mat3<T>)>, Error> {
        if let Some(l) = &self.lighting {
            l.validate()?;
        }
        // A NaN rotation, scale or translation: a coordinate error, as a
        // NaN camera is (not a singular model).
        if !model.cols.iter().flatten().all(|v| v.is_finite()) {
            return Err(Error::NonFiniteCoordinate);
        }
        let fx = !crate::math::vec::is_float::<T>();
        // Fx: a matrix product that saturates changes what is drawn.
        if fx
            && !(fx_product_fits(&self.view, model)
                && fx_product_fits(&self.projection, &(self.view * *model)))
        {
            return Err(Error::CoordinateOutOfRange);
        }
        let model_view = self.view * *model;
        let mvp = self.projection * model_view;
        // A singular model is an error whether or not the mesh is in view.
        // Checked before the band test, the error cannot depend on the
        // band height: the band tests of a sphere that reaches behind the
        // eye are not nested (fuzz target `view3d`).
        let normal_matrix = model_view.normal_matrix().ok_or(Error::InvalidParameter(crate::Param::Model))?;
        if !self.sphere_visible(&mvp, mesh.bounding_sphere) {
            return Ok(None);
        }
        // A visible mesh whose coordinates cannot be held is an error, not
        // a silent loss (checked before the band test, so every band
        // agrees): for Fx where 16.16 saturates, for f32 where the clipper
        // would discard a triangle (a clip coordinate beyond 2^64).
        if fx && !fx_coordinates_fit(mesh, &model_view, &mvp) {
            return Err(Error::CoordinateOutOfRange);
        }
        if !fx && !clip_coordinates_fit(mesh, &mvp) {
            return Err(Error::CoordinateOutOfRange);
        }
        Ok(Some((model_view, mvp, normal_matrix)))
    }

    /// The errors [`Pipeline::draw_valid_mesh`] (and every `draw_*` mesh
    /// call) would return for `mesh` placed by `model`, whatever
    /// [`Pipeline::rows`] says, found without any vertex work beyond the
    /// range check: the `view3d` front calls it for every object before
    /// the first band, so such an error sends nothing.
    pub(crate) fn check_mesh<P: Scalar>(&self, mesh: &Mesh<'_, P>, model: &Mat4<T>) -> Result<(), Error> {
        self.mesh_matrices(mesh, model).map(|_| ())
    }

    /// False if the sphere lies entirely outside one plane of the view volume.
    ///
    /// Evaluated in `f32` on both paths (bit-identical for `f32`): in `Fx`
    /// the plane values of a large sphere saturate and would cull a visible
    /// mesh (one `f32` test per mesh, a few soft-float operations on parts
    /// without an FPU).
    pub(super) fn sphere_visible(&self, mvp: &Mat4<T>, (c, r): ([f32; 3], f32)) -> bool {
        let planes = view_planes(rows_f32(mvp), self.clip.far());
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        planes.iter().all(|p| p.dot(centre) >= -(r * p.xyz().length()))
    }
}

/// Row `i` of `m` in `f32` (exact for `f32`; `Fx` rounds to 24 bits).
pub(super) fn row_f32<T: Scalar>(m: &Mat4<T>, i: usize) -> Vec4<f32> {
    let c = &m.cols;
    Vec4::new(c[0][i].to_f32(), c[1][i].to_f32(), c[2][i].to_f32(), c[3][i].to_f32())
}

/// The four rows `x, y, z, w` of `m` in `f32` ([`row_f32`]).
pub(super) fn rows_f32<T: Scalar>(m: &Mat4<T>) -> [Vec4<f32>; 4] {
    [0, 1, 2, 3].map(|i| row_f32(m, i))
}

/// The view-volume planes from the rows of a model-view-projection matrix,
/// `p · (x, 1) ≥ 0` inside: left, right, bottom, top, near, and far (near
/// again when there is no far plane). Also of the rows' values at a point
/// (`f32`): then the planes' values there.
pub(super) fn view_planes<V: Copy + core::ops::Add<Output = V> + core::ops::Sub<Output = V>>(
    [x, y, z, w]: [V; 4],
    far: bool,
) -> [V; 6] {
    [w + x, w - x, w + y, w - y, z, if far { w - z } else { z }]
}

/// The largest magnitude an `Fx` sum of products may reach without
/// saturating (2^15 less one unit: a margin for the `f32` bound's rounding).
pub(super) const FX_LIMIT: f32 = 32767.0;

/// `Fx`: true if no partial sum of `a · b` can saturate (`Σ|a_ik·b_kj|`
/// within [`FX_LIMIT`] for every entry, in `f32`), and no entry of `a` or
/// `b` is itself saturated.
pub(super) fn fx_product_fits<T: Scalar>(a: &Mat4<T>, b: &Mat4<T>) -> bool {
    // Quick accept, in `T` (integer compares for `Fx`): every partial sum is
    // at most 4·max|a|·max|b| (ordinary matrices: entries below ~90).
    let max =
        |m: &Mat4<T>| m.cols.iter().flatten().fold(T::ZERO, |m, &v| if v.abs() > m { v.abs() } else { m });
    if 4.0 * max(a).to_f32() * max(b).to_f32() < FX_LIMIT {
        return true;
    }
    let (a, b) = (a.to_f32(), b.to_f32());
    let ok = |v: f32| v.abs() < FX_LIMIT;
    if !a.iter().chain(&b).flatten().all(|&v| ok(v)) {
        return false;
    }
    // Entry (r, c) = Σ_k a[k][r]·b[c][k] (column-major).
    (0..4).all(|r| (0..4).all(|c| ok((0..4).map(|k| (a[k][r] * b[c][k]).abs()).sum::<f32>())))
}

/// `Fx`: true if every model, eye and clip coordinate of the mesh fits
/// 16.16 without saturating any partial sum of
/// `row · (p, 1)`. A bound over the bounding sphere decides at once for
/// nearly every mesh; only a mesh whose sphere reaches beyond the range has
/// the vertices of its triangles checked one by one.
pub(super) fn fx_coordinates_fit<T: Scalar, P: Scalar>(
    mesh: &Mesh<'_, P>,
    mv: &Mat4<T>,
    mvp: &Mat4<T>,
) -> bool {
    let (mv, mvp) = (mv.to_f32(), mvp.to_f32());
    // `Σ_i |m_ri|·e_i + |m_r3|` for each row of both matrices, where `e`
    // bounds `|p_i|`; every partial sum of the row's `Fx` evaluation is at
    // most this.
    let fits = |e: [f32; 3]| {
        e.iter().all(|&v| v < FX_LIMIT)
            && [&mv, &mvp].iter().all(|m| {
                (0..4).all(|r| (0..3).map(|i| m[i][r].abs() * e[i]).sum::<f32>() + m[3][r].abs() < FX_LIMIT)
            })
    };
    let (c, radius) = mesh.bounding_sphere;
    // The sphere contains the mesh up to `SPHERE_TOLERANCE` (validated).
    let r = radius * (1.0 + 2.0 * crate::mesh::SPHERE_TOLERANCE);
    // Otherwise the vertices that triangles use (an unused vertex is never
    // transformed for drawing).
    // A meshlet mesh keeps its triangles in its clusters (no `indices`):
    // then every vertex counts.
    let fits_at = |p: &[P; 3]| fits(p.map(|v| v.to_f32().abs()));
    fits(c.map(|c| c.abs() + r))
        || if mesh.indices.is_empty() {
            mesh.positions.iter().all(fits_at)
        } else {
            mesh.indices.iter().flatten().all(|&i| mesh.positions.get(usize::from(i)).is_none_or(fits_at))
        }
}

/// `f32`: true if every clip coordinate of the vertices the mesh's
/// triangles use is finite and at most [`CLIP_INPUT_LIMIT`] (2^64) in
/// magnitude, as the vertex stage computes it: beyond that the clipper
/// discards the triangle ([`clip3d`](crate::clip3d)), and a visible
/// triangle would vanish with `Ok`. A bound over the bounding sphere
/// decides at once for nearly every mesh; otherwise every vertex a
/// triangle uses is transformed and checked exactly as the clipper checks
/// it (an unused far vertex is no error; a meshlet mesh has no `indices`,
/// so all its vertices count).
pub(super) fn clip_coordinates_fit<T: Scalar, P: Scalar>(mesh: &Mesh<'_, P>, mvp: &Mat4<T>) -> bool {
    let m = mvp.to_f32();
    let (c, radius) = mesh.bounding_sphere;
    let r = radius * (1.0 + 2.0 * crate::mesh::SPHERE_TOLERANCE);
    let e = c.map(|c| c.abs() + r);
    // `Σ|m_ri|·e_i + |m_r3|` bounds `|row · (p, 1)|` over the sphere; half
    // the limit leaves room for rounding (NaN and overflow fail it).
    let bound = |row: usize| (0..3).map(|i| m[i][row].abs() * e[i]).sum::<f32>() + m[3][row].abs();
    if (0..4).all(|row| bound(row) < 0.5 * CLIP_INPUT_LIMIT) {
        return true;
    }
    let [a, b, cz, d] = &mvp.cols;
    let lim = T::from_f32(CLIP_INPUT_LIMIT);
    let fits_at = |p: &[P; 3]| {
        let p = Vec3::<T>::from_data(*p);
        // The rows of `VertexCtx::row`, the test of `clip3d::classify`.
        (0..4).all(|r| {
            let v = T::row_in_range([a[r], b[r], cz[r]], [p.x, p.y, p.z], d[r]);
            v.is_finite() && v.abs() <= lim
        })
    };
    if mesh.indices.is_empty() {
        mesh.positions.iter().all(fits_at)
    } else {
        mesh.indices.iter().flatten().all(|&i| mesh.positions.get(usize::from(i)).is_none_or(fits_at))
    }
}
