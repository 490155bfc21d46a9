//! Meshlets: a mesh split into small, spatially coherent clusters, built
//! ahead of time (by the `obj2rs` converter, or by [`build_meshlets`] for
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

/// A mesh with its clusters, all in borrowed (typically flash) data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshletMesh<'a> {
    /// The mesh: positions, normals and bounding sphere as for any
    /// [`Mesh`](super::Mesh); its `indices` may be empty (the clusters hold
    /// the triangles).
    pub mesh: super::Mesh<'a>,
    /// The clusters.
    pub meshlets: &'a [Meshlet],
    /// Mesh vertex index of each cluster-local vertex, cluster after cluster.
    pub vertices: &'a [u16],
    /// Cluster-local triangles, cluster after cluster.
    pub triangles: &'a [[u8; 3]],
}
