//! Meshlets: a mesh split into small, spatially coherent clusters, built
//! ahead of time (by the `obj2rs` converter, or by [`build_meshlets`](super::build_meshlets) for
//! procedural meshes) and kept in flash next to the mesh.
//!
//! A cluster has at most [`MAX_MESHLET_VERTICES`] vertices, addressed by
//! local `u8` indices, and at most [`MAX_MESHLET_TRIANGLES`] triangles. Each
//! carries a bounding sphere and a normal cone, so the vertex stage rejects a
//! whole cluster (outside the view volume, outside the band being drawn, or
//! facing away from the eye) before any of its vertices is transformed, and
//! transforms the survivors' vertices into a cluster-sized cache: the RAM a
//! mesh needs does not grow with its size.
//!
//! # Layout
//! [`MeshletMesh::vertices`] lists, cluster after cluster, the mesh vertex
//! index of each cluster-local vertex; [`MeshletMesh::triangles`] lists,
//! cluster after cluster, triangles as cluster-local indices into that list,
//! counter-clockwise seen from outside (the [`Mesh`](super::Mesh)
//! convention).
//!
//! # Normal cone
//! `cone = (axis, cutoff)`: `axis` is a unit vector and `cutoff = sin α`,
//! where `α < 90°` bounds the angle between `axis` and every triangle's face
//! normal; `cutoff ≥ 1` stands for a spread of 90° or more and never
//! rejects. For an eye at `e`, every triangle of the cluster faces away from
//! it when `axis · (c − e) > cutoff · |c − e| + r · (1 + cutoff)`, with
//! `(c, r)` the cluster's bounding sphere: every point `p` of the sphere then
//! has `axis · (p − e) > cutoff · |p − e|`, so the angle between `axis` and
//! `p − e` is below `90° − α` and `n · (p − e) > 0` for every face normal `n`.

use super::data::MeshData;
use super::winding::{face_cross, winding_agrees};
use super::{SPHERE_TOLERANCE, cross, dist2, dot, is_finite3};
use crate::error::Error;
use crate::math::Scalar;

/// Most vertices a cluster may have (local indices are `u8`).
pub const MAX_MESHLET_VERTICES: usize = 64;

/// Most triangles a cluster may have.
pub const MAX_MESHLET_TRIANGLES: usize = 128;

/// One cluster of a [`MeshletMesh`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Meshlet {
    /// Index of the cluster's first entry in [`MeshletMesh::vertices`].
    pub vertex_offset: u32,
    /// Index of the cluster's first entry in [`MeshletMesh::triangles`].
    pub triangle_offset: u32,
    /// Number of vertices, 1 to [`MAX_MESHLET_VERTICES`].
    pub vertex_count: u8,
    /// Number of triangles, 1 to [`MAX_MESHLET_TRIANGLES`].
    pub triangle_count: u8,
    /// `(centre, radius)` of a sphere containing the cluster's positions.
    pub sphere: ([f32; 3], f32),
    /// Normal cone `(unit axis, cutoff)` (module docs); `cutoff ≥ 1` never
    /// rejects.
    pub cone: ([f32; 3], f32),
}

/// A mesh with its clusters, all in borrowed (typically flash) data; its
/// positions and normals in `f32` or, for the fixed-point vertex stage, in
/// 16.16 [`Fx`](crate::math::Fx) (`P`, as for [`Mesh`](super::Mesh)).
///
/// Its `validate` checks the invariants the meshlet renderer relies on:
///
/// * the inner [`Mesh`](super::Mesh) passes
///   [`validate`](super::Mesh::validate) (its `indices` may be empty);
/// * every cluster has 1 to [`MAX_MESHLET_VERTICES`] vertices and 1 to
///   [`MAX_MESHLET_TRIANGLES`] triangles, all within
///   [`vertices`](Self::vertices) and [`triangles`](Self::triangles);
/// * every local index is below its cluster's `vertex_count`, every
///   entry of `vertices` a cluster uses is below the number of positions;
/// * every sphere and cone is finite, the radius non-negative, and every
///   position of a cluster within `radius · (1 + SPHERE_TOLERANCE)` of its
///   centre (the [`Mesh::validate`](super::Mesh::validate) rule);
/// * every cone has a unit axis and a cutoff `≥ 0`, and, unless the
///   cutoff is `≥ 1`, every triangle of its cluster is non-degenerate
///   ([`DEGENERATE_SIN2`](super::DEGENERATE_SIN2): a needle's normal is
///   rounding noise, yet its image can cover pixel centres) and its face
///   normal lies in the cone (within [`CONE_TOLERANCE`]);
/// * if the mesh has normals, the windings of its own triangles and of
///   every cluster triangle agree with them
///   ([`Mesh::check_winding`](super::Mesh::check_winding)).
///
/// Entries of `vertices` and `triangles` no cluster uses are not checked,
/// nor whether clusters overlap.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshletMesh<'a, P = f32> {
    /// The mesh: positions, normals and bounding sphere as for any
    /// [`Mesh`](super::Mesh); its `indices` may be empty (the clusters hold
    /// the triangles).
    pub mesh: super::Mesh<'a, P>,
    /// The clusters.
    pub meshlets: &'a [Meshlet],
    /// Mesh vertex index of each cluster-local vertex, cluster after cluster.
    pub vertices: &'a [u16],
    /// Cluster-local triangles, cluster after cluster.
    pub triangles: &'a [[u8; 3]],
}

/// Tolerance of the normal-cone check in [`MeshletMesh::validate`], in units
/// of the cutoff `sin α`: a face normal `n` passes when `axis · n ≥ 0` and
/// `|axis × n| ≤ (cutoff + CONE_TOLERANCE) · |n|` (an angle at most about
/// 10⁻⁴ rad beyond `α` for moderate cones). Also the allowed deviation of
/// `|axis|²` from 1. [`build_meshlets`](super::build_meshlets) writes cones
/// that pass without it.
pub const CONE_TOLERANCE: f32 = 1.0e-4;

/// A [`MeshletMesh`] as its checks read it (its mesh's rows as `f32`,
/// [`MeshData`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct MeshletData<'a> {
    pub(crate) mesh: MeshData<'a>,
    pub(crate) meshlets: &'a [Meshlet],
    pub(crate) vertices: &'a [u16],
    pub(crate) triangles: &'a [[u8; 3]],
}

impl<'a, P: Scalar> MeshletMesh<'a, P> {
    /// The clusters and their mesh as the checks read them.
    pub(crate) fn data(&self) -> MeshletData<'a> {
        MeshletData {
            mesh: self.mesh.data(),
            meshlets: self.meshlets,
            vertices: self.vertices,
            triangles: self.triangles,
        }
    }
}

impl MeshletData<'_> {
    /// [`MeshletMesh`]'s `validate` (the struct docs).
    pub(crate) const fn validate(&self) -> Result<(), Error> {
        // Plain loops: a `const fn`, so a `static` is checked at compile time.
        if let Err(e) = self.mesh.validate() {
            return Err(e);
        }
        if let Err(e) = self.mesh.check_winding_unvalidated() {
            return Err(e);
        }
        let mut i = 0;
        while i < self.meshlets.len() {
            if let Err(e) = self.validate_cluster(&self.meshlets[i]) {
                return Err(e);
            }
            i += 1;
        }
        Ok(())
    }

    /// Cluster `c`'s vertex and triangle ranges, or `None` if they are out of
    /// bounds or the counts are out of range.
    pub(crate) const fn cluster_ranges(&self, c: &Meshlet) -> Option<(usize, usize, usize, usize)> {
        let (vo, vc) = (c.vertex_offset as usize, c.vertex_count as usize);
        let (to, tc) = (c.triangle_offset as usize, c.triangle_count as usize);
        let ok_counts = vc >= 1 && vc <= MAX_MESHLET_VERTICES && tc >= 1 && tc <= MAX_MESHLET_TRIANGLES;
        // `checked_add`: offsets near `usize::MAX` on 32-bit targets.
        let (Some(ve), Some(te)) = (vo.checked_add(vc), to.checked_add(tc)) else {
            return None;
        };
        if ok_counts && ve <= self.vertices.len() && te <= self.triangles.len() {
            Some((vo, vc, to, tc))
        } else {
            None
        }
    }

    /// Checks one cluster (all but the mesh-wide checks of `validate`).
    pub(crate) const fn validate_cluster(&self, c: &Meshlet) -> Result<(), Error> {
        let Some((vo, vc, to, tc)) = self.cluster_ranges(c) else {
            return Err(Error::InvalidMeshlet);
        };
        let ((centre, radius), (axis, cutoff)) = (c.sphere, c.cone);
        if !is_finite3(centre) || !radius.is_finite() || !is_finite3(axis) || !cutoff.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        let r = radius * (1.0 + SPHERE_TOLERANCE);
        let axis_len2 = dot(axis, axis);
        let unit = axis_len2 >= 1.0 - CONE_TOLERANCE && axis_len2 <= 1.0 + CONE_TOLERANCE;
        if radius < 0.0 || r * r == f32::INFINITY || cutoff < 0.0 || !unit {
            return Err(Error::InvalidMeshlet);
        }
        let positions = self.mesh.positions;
        let mut k = 0;
        while k < vc {
            let v = self.vertices[vo + k] as usize;
            if v >= positions.len() {
                return Err(Error::InvalidMeshlet);
            }
            if dist2(positions.get(v), centre) > r * r {
                return Err(Error::InvalidMeshlet);
            }
            k += 1;
        }
        let normals = self.mesh.normals;
        let bound = cutoff + CONE_TOLERANCE;
        let mut t = 0;
        while t < tc {
            let [a, b, cc] = self.triangles[to + t];
            if a as usize >= vc || b as usize >= vc || cc as usize >= vc {
                return Err(Error::InvalidMeshlet);
            }
            let a = self.vertices[vo + a as usize] as usize;
            let b = self.vertices[vo + b as usize] as usize;
            let cc = self.vertices[vo + cc as usize] as usize;
            let p = [positions.get(a), positions.get(b), positions.get(cc)];
            if !normals.is_empty() && !winding_agrees(p, [normals.get(a), normals.get(b), normals.get(cc)]) {
                return Err(Error::WindingMismatch);
            }
            if cutoff < 1.0 {
                // A degenerate triangle's normal is rounding noise: no cone
                // can vouch that it faces away.
                let Some((n, len2)) = face_cross(p) else {
                    return Err(Error::InvalidMeshlet);
                };
                let s = cross(axis, n);
                // Both sides are finite: `face_cross` bounds `len2`.
                if dot(axis, n) < 0.0 || dot(s, s) > bound * bound * len2 {
                    return Err(Error::InvalidMeshlet);
                }
            }
            t += 1;
        }
        Ok(())
    }
}

/// A [`MeshletMesh`] that passed [`MeshletMesh::validate`], so the renderer
/// draws it without checking it again. The data are shared references, so
/// they cannot change afterwards. A `static` is checked at compile time by
/// [`ValidMeshletMesh::new_const`] (what `obj2rs` writes), where an invalid
/// one is a build error naming the cause; [`ValidMeshletMesh::new`] (also a
/// `const fn`) returns the error instead.
///
/// ```
/// use microraster::mesh::{Mesh, Meshlet, MeshletMesh, ValidMeshletMesh};
/// static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// static CLUSTERS: [Meshlet; 1] = [Meshlet {
///     vertex_offset: 0,
///     triangle_offset: 0,
///     vertex_count: 3,
///     triangle_count: 1,
///     sphere: ([0.5, 0.5, 0.0], 0.71),
///     cone: ([0.0, 0.0, 1.0], 0.0),
/// }];
/// // Checked at compile time: an invalid mesh is a build error naming the cause.
/// static TRI: ValidMeshletMesh<'static> = ValidMeshletMesh::new_const(MeshletMesh {
///     mesh: Mesh::new(&POSITIONS, &[], &[], ([0.5, 0.5, 0.0], 0.71)),
///     meshlets: &CLUSTERS,
///     vertices: &[0, 1, 2],
///     triangles: &[[0, 1, 2]],
/// });
/// assert_eq!(TRI.get().meshlets.len(), 1);
/// // At run time, `new` returns the error.
/// let bad = MeshletMesh { triangles: &[[0, 1, 3]], ..*TRI.get() };
/// assert_eq!(ValidMeshletMesh::new(bad), Err(microraster::Error::InvalidMeshlet));
/// ```
///
/// The same mesh with a cluster-local index past the cluster's vertices
/// does not build:
///
/// ```compile_fail
/// use microraster::mesh::{Mesh, Meshlet, MeshletMesh, ValidMeshletMesh};
/// static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// static CLUSTERS: [Meshlet; 1] = [Meshlet {
///     vertex_offset: 0,
///     triangle_offset: 0,
///     vertex_count: 3,
///     triangle_count: 1,
///     sphere: ([0.5, 0.5, 0.0], 0.71),
///     cone: ([0.0, 0.0, 1.0], 0.0),
/// }];
/// static TRI: ValidMeshletMesh<'static> = ValidMeshletMesh::new_const(MeshletMesh {
///     mesh: Mesh::new(&POSITIONS, &[], &[], ([0.5, 0.5, 0.0], 0.71)),
///     meshlets: &CLUSTERS,
///     vertices: &[0, 1, 2],
///     triangles: &[[0, 1, 3]],
/// });
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValidMeshletMesh<'a, P = f32>(pub(super) MeshletMesh<'a, P>);

impl<'a, P> ValidMeshletMesh<'a, P> {
    /// The meshlet mesh.
    pub const fn get(&self) -> &MeshletMesh<'a, P> {
        &self.0
    }
}
