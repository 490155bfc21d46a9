//! The per-mesh constants of the vertex computation: clip position rows
//! and the lit colour of a vertex.

use super::Band;
use super::model_light::ModelLight;
use super::tier::Tier;
use crate::clip3d::ClipPlanes;
use crate::light::Lighting;
use crate::math::{Mat3, Mat4, Scalar, Vec3};

/// What [`Pipeline::mesh_setup`](super::Pipeline::mesh_setup) prepares for one mesh.
pub(super) struct MeshSetup<T: Scalar> {
    pub(super) ctx: VertexCtx<T>,
    pub(super) planes: ClipPlanes,
    pub(super) band: Band<T>,
    pub(super) max: [u8; 3],
}

/// Per-mesh constants of the vertex computation.
pub(super) struct VertexCtx<T: Scalar> {
    pub(super) mv: Mat4<T>,
    pub(super) mvp: Mat4<T>,
    pub(super) nm: Mat3<T>,
    pub(super) base: [T; 3],
    pub(super) lighting: Option<Lighting<T>>,
    /// `lighting` in model space, where it applies (a similarity; module
    /// docs of `model_light`).
    pub(super) model_light: Option<ModelLight<T>>,
}

impl<T: Scalar> VertexCtx<T> {
    /// Row `r` of `mvp · (p, 1)`, bit-identical to
    /// [`Mat4::transform_point`] (`d·1` is exact). For `Fx` without the
    /// saturation ([`Scalar::row_in_range`]): `mesh_setup` accepts a mesh
    /// only if no partial sum of these rows can saturate
    /// (`fx_coordinates_fit`).
    #[inline]
    pub(super) fn row(&self, r: usize, p: Vec3<T>) -> T {
        let [a, b, c, d] = &self.mvp.cols;
        T::row_in_range([a[r], b[r], c[r]], [p.x, p.y, p.z], d[r])
    }

    /// Clip `(y, w)` of `p`.
    #[inline]
    pub(super) fn yw(&self, p: Vec3<T>) -> (T, T) {
        (self.row(1, p), self.row(3, p))
    }

    /// The clip position of `p`, given its [`VertexCtx::yw`].
    #[inline]
    pub(super) fn position(&self, p: Vec3<T>, (y, w): (T, T)) -> [T; 4] {
        [self.row(0, p), y, self.row(2, p), w]
    }

    /// The lit colour of a vertex. Documented clamp: a lighting result that
    /// overflows `f32` to +infinity (huge finite factors) is full intensity,
    /// as `Fx` saturates; NaN (`0·∞`) and −infinity are channel 0. The
    /// clipper would otherwise take a non-finite value for a reason to
    /// discard the triangle.
    pub(super) fn color<R: Tier>(&self, p: Vec3<T>, normal: Option<[f32; 3]>) -> [T; 3] {
        finite_color(self.lit::<R>(p, normal, |ctx: &Self| ctx.base))
    }

    /// [`VertexCtx::color`] of material `base` instead of the mesh's
    /// colour (per-vertex and per-face colours, [`Material`](super::Material)).
    pub(super) fn color_of<R: Tier>(&self, p: Vec3<T>, normal: Option<[f32; 3]>, base: [T; 3]) -> [T; 3] {
        finite_color(self.lit::<R>(p, normal, move |_: &Self| base))
    }

    /// The lit colour of material `base`: a function, so the one-colour
    /// path (`|ctx| ctx.base`, zero-sized) passes no argument; a pointer
    /// argument cost 2 Cortex-M4F instructions per lit vertex.
    pub(super) fn lit<R: Tier>(
        &self,
        p: Vec3<T>,
        normal: Option<[f32; 3]>,
        base: impl FnOnce(&Self) -> [T; 3],
    ) -> [T; 3] {
        match (self.lighting, normal, &self.model_light) {
            (Some(_), Some(n), Some(m)) => m.shade::<R>(n, p, base(self)),
            (Some(l), Some(n), None) => {
                let n_eye = (self.nm * Vec3::from_f32(n)).normalize_fast();
                // mv·(p, 1) without its w (the same sums as transform_point).
                let [a, b, c, d] = &self.mv.cols;
                let p_eye = Vec3::new(
                    a[0] * p.x + b[0] * p.y + c[0] * p.z + d[0],
                    a[1] * p.x + b[1] * p.y + c[1] * p.z + d[1],
                    a[2] * p.x + b[2] * p.y + c[2] * p.z + d[2],
                );
                l.shade(n_eye, p_eye, base(self))
            }
            // No light, or a degenerate face without a normal: ambient only.
            (Some(l), None, _) => base(self).map(|b| b * l.ambient),
            (None, _, _) => base(self),
        }
    }
}

/// The clamp of [`VertexCtx::color`]: +infinity is full intensity, NaN and
/// −infinity channel 0.
#[inline]
pub(super) fn finite_color<T: Scalar>(c: [T; 3]) -> [T; 3] {
    c.map(|c| {
        if c.is_finite() {
            c
        } else if c > T::ZERO {
            T::ONE
        } else {
            T::ZERO
        }
    })
}

/// Colour channels from intensities.
pub(super) fn channels<T: Scalar>(c: [T; 3], max: [u8; 3]) -> [u8; 3] {
    [0, 1, 2].map(|k| c[k].to_channel(max[k]))
}
