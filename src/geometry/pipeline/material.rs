//! Where the vertex stage takes a vertex's material colour from: the mesh's
//! one colour (the common path), or a colour per vertex or per face (the
//! `view3d` front's [`Object::with_vertex_colors`] and
//! [`Object::with_face_colors`]). The source is a type chosen once per mesh,
//! so the one-colour path compiles to what it was before: no per-vertex
//! branch, no extra loads. The colour is then lit exactly as the material
//! colour is ([`VertexCtx::color_of`](super::VertexCtx::color_of)).
//!
//! [`Object::with_vertex_colors`]: crate::view3d::Object::with_vertex_colors
//! [`Object::with_face_colors`]: crate::view3d::Object::with_face_colors

use crate::Interpolate;
use crate::math::Scalar;

/// A per-mesh source of material colours, as channel factors in `[0, 1]`.
pub(crate) trait Material<T: Scalar> {
    /// True if the colour depends on the face: then one vertex shared by
    /// two faces has two colours, and the cached path (one lit colour per
    /// vertex) cannot take it.
    const PER_FACE: bool;

    /// True for [`Uniform`]: the callers then light `VertexCtx::base` in
    /// place, the code the one-colour path had before materials existed.
    const UNIFORM: bool = false;

    /// The material of mesh vertex `vertex` in face `face`; `uniform` is the
    /// mesh's one colour (also the fallback for an index out of range,
    /// which the callers' length checks exclude).
    fn base(&self, uniform: [T; 3], face: usize, vertex: usize) -> [T; 3];
}

/// The mesh's one colour.
pub(crate) struct Uniform;

impl<T: Scalar> Material<T> for Uniform {
    const PER_FACE: bool = false;
    const UNIFORM: bool = true;

    #[inline(always)]
    fn base(&self, uniform: [T; 3], _: usize, _: usize) -> [T; 3] {
        uniform
    }
}

/// One colour per mesh vertex.
pub(crate) struct PerVertex<'a, C>(pub &'a [C]);

impl<T: Scalar, C: Interpolate> Material<T> for PerVertex<'_, C> {
    const PER_FACE: bool = false;

    #[inline]
    fn base(&self, uniform: [T; 3], _: usize, vertex: usize) -> [T; 3] {
        self.0.get(vertex).map_or(uniform, |&c| base_of(c))
    }
}

/// One colour per triangle.
pub(crate) struct PerFace<'a, C>(pub &'a [C]);

impl<T: Scalar, C: Interpolate> Material<T> for PerFace<'_, C> {
    const PER_FACE: bool = true;

    #[inline]
    fn base(&self, uniform: [T; 3], face: usize, _: usize) -> [T; 3] {
        self.0.get(face).map_or(uniform, |&c| base_of(c))
    }
}

/// `color` as channel factors in `[0, 1]` (a channel of maximum 0 is 0).
/// The mesh's colour and per-vertex or per-face colours all go through
/// this, so equal colours light to equal pixels.
#[inline]
pub(crate) fn base_of<T: Scalar, C: Interpolate>(color: C) -> [T; 3] {
    let max = C::CHANNEL_MAX;
    let ch = color.to_channels();
    [0, 1, 2].map(|k| if max[k] == 0 { T::ZERO } else { T::from_f32(ch[k] as f32 / max[k] as f32) })
}
