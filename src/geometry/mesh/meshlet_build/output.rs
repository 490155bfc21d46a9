//! The output side of [`build_meshlets`](super::build_meshlets): the caller's
//! buffers as they fill, and closing a cluster into its [`Meshlet`] (bounding
//! sphere and normal cone).

use super::super::meshlet::{MAX_MESHLET_VERTICES, Meshlet, MeshletMesh};
use super::super::meshlet_adjacency::State;
use super::super::winding::face_cross;
use super::super::{Mesh, bounding_sphere, cross, dot, sqrt};
use super::Open;
use crate::error::Error;
use crate::math::Scalar;

/// The output buffers and how much of them is written.
pub(super) struct Output<'a> {
    pub(super) meshlets: &'a mut [Meshlet],
    pub(super) vertices: &'a mut [u16],
    pub(super) triangles: &'a mut [[u8; 3]],
    pub(super) clusters: usize,
    pub(super) verts: usize,
    pub(super) tris: usize,
    /// The vertex range of the last closed cluster (empty before the first).
    pub(super) last: (usize, usize),
}

impl Output<'_> {
    /// Writes the open cluster's [`Meshlet`] (sphere and cone) and clears its
    /// vertices' local indices. Past the end of `meshlets` it only counts
    /// the cluster, so that the error can say how many are needed.
    pub(super) fn close<P: Scalar>(
        &mut self,
        st: &mut State<'_>,
        mesh: &Mesh<'_, P>,
        c: &Open,
    ) -> Result<(), Error> {
        self.clusters += 1;
        self.last = (c.vo, c.vo + c.verts);
        let members = &self.vertices[c.vo..c.vo + c.verts];
        let mut points = [[0.0; 3]; MAX_MESHLET_VERTICES];
        for (p, &v) in points.iter_mut().zip(members) {
            *p = mesh.point_f32(v);
            st.local[usize::from(v)] = 0;
        }
        let Some(slot) = self.meshlets.get_mut(self.clusters - 1) else { return Ok(()) };
        let corners = |t: &[u8; 3]| t.map(|k| points[usize::from(k)]);
        let tris = &self.triangles[c.to..c.to + c.tris];
        // Counts are at most 64 and 128 (`Open::fits`); offsets below 2³² (the
        // triangle count is checked): the casts are exact.
        let mut m = Meshlet {
            vertex_offset: c.vo as u32,
            triangle_offset: c.to as u32,
            vertex_count: c.verts as u8,
            triangle_count: c.tris as u8,
            sphere: bounding_sphere(&points[..c.verts]),
            cone: normal_cone(tris.iter().map(corners)),
        };
        // The cluster passes by construction, except where rounding is
        // coarse (subnormal triangles: then a cone that never rejects) or
        // the radius squared overflows (coordinates near 10¹⁹).
        let view =
            MeshletMesh { mesh: *mesh, meshlets: &[], vertices: self.vertices, triangles: self.triangles }
                .data();
        if view.validate_cluster(&m) == Err(Error::InvalidMeshlet) {
            m.cone = ([0.0, 0.0, 1.0], 1.0);
            if view.validate_cluster(&m) == Err(Error::InvalidMeshlet) {
                return Err(Error::CoordinateOutOfRange);
            }
        }
        *slot = m;
        Ok(())
    }
}

/// The normal cone `(axis, cutoff)` of triangles given by their corners: the
/// axis is the mean unit face normal; the cutoff the largest sine between it
/// and a face normal, rounded up so [`MeshletMesh::validate`] passes without
/// its tolerance, or 1 (never rejects) if the spread reaches 90° or a
/// triangle is degenerate (its normal cannot be vouched for, `validate`).
fn normal_cone<I: Iterator<Item = [[f32; 3]; 3]> + Clone>(tris: I) -> ([f32; 3], f32) {
    const NEVER: ([f32; 3], f32) = ([0.0, 0.0, 1.0], 1.0);
    if tris.clone().any(|t| face_cross(t).is_none()) {
        return NEVER;
    }
    let mut sum = [0.0f32; 3];
    for (n, len2) in tris.clone().filter_map(face_cross) {
        let len = sqrt(len2);
        for k in 0..3 {
            sum[k] += n[k] / len;
        }
    }
    let len = sqrt(dot(sum, sum));
    // Normals that cancel out (or only degenerate triangles): no cone.
    if len.is_nan() || len <= 1.0e-3 {
        return NEVER;
    }
    let axis = sum.map(|x| x / len);
    let mut max_sin2 = 0.0f32;
    for (n, len2) in tris.filter_map(face_cross) {
        if dot(axis, n) < 0.0 {
            return (axis, 1.0);
        }
        let s = cross(axis, n);
        max_sin2 = max_sin2.max(dot(s, s) / len2);
    }
    // Margins cover the rounding of the division and the square root.
    let cutoff = sqrt(max_sin2) * (1.0 + 1.0e-5) + 1.0e-6;
    (axis, if cutoff < 1.0 { cutoff } else { 1.0 })
}
