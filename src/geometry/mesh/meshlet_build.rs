//! [`build_meshlets`]: splits a [`Mesh`] into spatially coherent clusters,
//! without allocating (caller-provided output and scratch buffers), on the
//! host, in `build.rs` or in firmware.
//!
//! The greedy growth follows the idea of meshoptimizer's
//! `meshopt_buildMeshlets`: a cluster grows one triangle at a time over the
//! triangle adjacency, taking first a triangle that adds no new vertex (or
//! would otherwise be left stranded), then the one closest to the cluster's
//! centre; a full cluster is closed, and the next one is seeded next to it,
//! at the triangle whose vertices have the fewest triangles left (a corner of
//! the remaining surface, so no thin slivers are left behind).

use super::meshlet::{MAX_MESHLET_TRIANGLES, MAX_MESHLET_VERTICES, Meshlet, MeshletMesh};
use super::meshlet_adjacency::{State, fill_adjacency, split_scratch};
use super::{Mesh, cross, dist2, dot, sqrt, sub};
use crate::error::Error;
use crate::math::Scalar;

mod output;
use output::Output;

/// Triangles [`build_meshlets`] puts in a cluster at most: with 64 vertices a
/// compact patch of a closed mesh holds about 100 triangles, so the vertex
/// limit is what fills clusters and 128 never cuts one short.
const TRIANGLE_LIMIT: usize = MAX_MESHLET_TRIANGLES;

/// Weight of the vertices' live-triangle counts in the growth score
/// (distance · (1 + weight · live)): growth hugs the already clustered
/// surface, leaving fewer islands behind (tuned on an icosphere: 0.1 keeps
/// the worst cluster at half the radius of 0 or 0.3).
const LIVE_WEIGHT: f32 = 0.1;

/// Triangles in a typical full cluster (64 vertices on a closed mesh).
const TYPICAL_TRIANGLES: f32 = 96.0;

/// A cluster is closed only when the next triangle does not fit: it then has
/// 62 or more vertices (a triangle adds at most 3), so at least 21 triangles,
/// or [`TRIANGLE_LIMIT`] triangles.
const MIN_CLOSED_TRIANGLES: usize = (MAX_MESHLET_VERTICES - 2).div_ceil(3);

/// Clusters [`build_meshlets`] writes at most for a mesh of `triangles`
/// triangles (saturating): the size of its `meshlets` buffer.
///
/// ```
/// use microraster::mesh::meshlet_bound;
/// assert_eq!(meshlet_bound(0), 0);
/// assert!(meshlet_bound(20_000) >= 20_000 / 128);
/// ```
pub const fn meshlet_bound(triangles: usize) -> usize {
    triangles.div_ceil(if MIN_CLOSED_TRIANGLES < TRIANGLE_LIMIT {
        MIN_CLOSED_TRIANGLES
    } else {
        TRIANGLE_LIMIT
    })
}

/// Entries [`build_meshlets`] writes to `vertices` at most for `triangles`
/// triangles (saturating): three per triangle.
///
/// ```
/// use microraster::mesh::meshlet_vertex_bound;
/// assert_eq!(meshlet_vertex_bound(100), 300);
/// ```
pub const fn meshlet_vertex_bound(triangles: usize) -> usize {
    triangles.saturating_mul(3)
}

/// Splits `mesh` into clusters of at most [`MAX_MESHLET_VERTICES`] vertices
/// and [`MAX_MESHLET_TRIANGLES`] triangles, written to the front of
/// `meshlets`, `vertices` and `triangles`, each with its bounding sphere and
/// normal cone; returns them as a [`MeshletMesh`] around `mesh`, which passes
/// [`MeshletMesh::validate`]. Every triangle of `mesh` appears exactly once,
/// with its winding (its corners may be rotated). Clusters are spatially
/// coherent (see the module docs); on a closed mesh most are full (64
/// vertices).
///
/// Buffer sizes: `meshlets` [`meshlet_bound`]`(t)`, `vertices`
/// [`meshlet_vertex_bound`]`(t)` (both upper bounds; fewer suffice for most
/// meshes), `triangles` exactly `t`, `scratch`
/// [`meshlet_scratch_len`](super::meshlet_scratch_len)`(v, t)`, for `v` positions and `t` triangles.
/// Time O(t · 64 · triangles per vertex), plus an O(t) search for each
/// cluster that runs out of neighbouring triangles.
///
/// # Errors
///
/// The errors of [`Mesh::validate`]; [`Error::CapacityExceeded`] if a
/// buffer is short, with the length that suffices as `needed`: exactly `t`
/// for `triangles`, [`meshlet_scratch_len`](super::meshlet_scratch_len) for
/// `scratch`, the exact cluster count of this mesh for `meshlets` (the
/// clustering runs to the end to count them), and the bound
/// [`meshlet_vertex_bound`]`(t)` for `vertices` (clustering cannot go on
/// without its vertex lists); the buffers may then be partly written;
/// [`Error::InvalidParameter`] if the mesh has more than `u32::MAX / 3`
/// triangles; [`Error::CoordinateOutOfRange`] if a cluster's radius squared
/// overflows `f32` (coordinates near 10¹⁹, which [`Mesh::validate`] accepts).
///
/// ```
/// use microraster::mesh::*;
/// let (mut p, mut n, mut i) = ([[0.0; 3]; 42], [[0.0; 3]; 42], [[0; 3]; 80]);
/// let mesh = icosphere(1, &mut p, &mut n, &mut i)?;
/// let mut meshlets = [Meshlet::default(); meshlet_bound(80)];
/// let mut vertices = [0; meshlet_vertex_bound(80)];
/// let mut triangles = [[0; 3]; 80];
/// let mut scratch = [0; meshlet_scratch_len(42, 80)];
/// let m = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch)?;
/// m.validate()?;
/// assert_eq!(m.meshlets.len(), 1); // 42 vertices fit one cluster
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn build_meshlets<'a, P: Scalar>(
    mesh: Mesh<'a, P>,
    meshlets: &'a mut [Meshlet],
    vertices: &'a mut [u16],
    triangles: &'a mut [[u8; 3]],
    scratch: &mut [u32],
) -> Result<MeshletMesh<'a, P>, Error> {
    mesh.data().validate()?;
    let (nv, nt) = (mesh.positions.len(), mesh.indices.len());
    if nt > (u32::MAX / 3) as usize {
        return Err(Error::InvalidParameter(crate::Param::TriangleCount));
    }
    if triangles.len() < nt {
        return Err(Error::CapacityExceeded { needed: nt, capacity: triangles.len() });
    }
    let mut st = split_scratch(scratch, nv, nt)?;
    let vertex_bound = meshlet_vertex_bound(nt);
    fill_adjacency(&mut st, &mesh);
    let mut out = Output { meshlets, vertices, triangles, clusters: 0, verts: 0, tris: 0, last: (0, 0) };
    let reach2 = reach2(&mesh);
    let mut cluster = Open::new(0, 0);
    // Centre of the last closed cluster: where the next one is sought.
    let mut anchor = mesh.bounding_sphere.0;
    loop {
        let pick = if cluster.tris == 0 {
            seed(&st, &mesh, &out, anchor).map(|t| (t, true))
        } else {
            let members = &out.vertices[cluster.vo..cluster.vo + cluster.verts];
            match neighbour(&st, &mesh, members, cluster.centre()) {
                Some(t) => Some((t, true)),
                None => nearest(&st, &mesh, cluster.centre()).map(|(t, d2)| (t, d2 <= reach2)),
            }
        };
        let Some((t, near)) = pick else { break };
        let tri = mesh.indices[t];
        if !cluster.fits(&st, tri) || (!near && cluster.tris >= MIN_CLOSED_TRIANGLES) {
            anchor = cluster.centre();
            out.close(&mut st, &mesh, &cluster)?;
            cluster = Open::new(out.verts, out.tris);
            continue;
        }
        cluster
            .add(&mut st, &mut out, &mesh, t, tri)
            .map_err(|_| Error::CapacityExceeded { needed: vertex_bound, capacity: out.vertices.len() })?;
    }
    if cluster.tris > 0 {
        out.close(&mut st, &mesh, &cluster)?;
    }
    let Output { meshlets, vertices, triangles, clusters, verts, tris, .. } = out;
    if clusters > meshlets.len() {
        return Err(Error::CapacityExceeded { needed: clusters, capacity: meshlets.len() });
    }
    Ok(MeshletMesh {
        mesh,
        meshlets: &meshlets[..clusters],
        vertices: &vertices[..verts],
        triangles: &triangles[..tris],
    })
}

/// The cluster being grown.
struct Open {
    /// Offsets of its first vertex and triangle in the output.
    vo: usize,
    to: usize,
    verts: usize,
    tris: usize,
    /// Sum of its triangles' centroids.
    sum: [f32; 3],
}

impl Open {
    fn new(vo: usize, to: usize) -> Self {
        Open { vo, to, verts: 0, tris: 0, sum: [0.0; 3] }
    }

    /// Mean of the triangle centroids.
    fn centre(&self) -> [f32; 3] {
        let n = self.tris.max(1) as f32;
        self.sum.map(|x| x / n)
    }

    fn fits(&self, st: &State<'_>, tri: [u16; 3]) -> bool {
        self.verts + new_vertices(st, tri) <= MAX_MESHLET_VERTICES && self.tris < TRIANGLE_LIMIT
    }

    /// Appends triangle `t` (which [`fits`](Open::fits)).
    fn add<P: Scalar>(
        &mut self,
        st: &mut State<'_>,
        out: &mut Output<'_>,
        mesh: &Mesh<'_, P>,
        t: usize,
        tri: [u16; 3],
    ) -> Result<(), Error> {
        let mut local = [0u8; 3];
        for (l, v) in local.iter_mut().zip(tri.map(usize::from)) {
            if st.local[v] == 0 {
                *out.vertices.get_mut(out.verts).ok_or(Error::BufferTooSmall)? = v as u16;
                out.verts += 1;
                self.verts += 1;
                st.local[v] = self.verts as u32;
            }
            // At most 64 vertices: the local index fits a `u8`.
            *l = (st.local[v] - 1) as u8;
        }
        // `triangles` holds at least as many entries as the mesh has triangles.
        out.triangles[out.tris] = local;
        out.tris += 1;
        self.tris += 1;
        for (s, c) in self.sum.iter_mut().zip(centroid(mesh, tri)) {
            *s += c;
        }
        st.emit(t, tri);
        Ok(())
    }
}

/// Distinct vertices of `tri` not yet in the open cluster.
fn new_vertices(st: &State<'_>, tri: [u16; 3]) -> usize {
    let [a, b, c] = tri;
    let new = |v: u16| st.local[usize::from(v)] == 0;
    usize::from(new(a)) + usize::from(new(b) && b != a) + usize::from(new(c) && c != a && c != b)
}

fn centroid<P: Scalar>(mesh: &Mesh<'_, P>, tri: [u16; 3]) -> [f32; 3] {
    let p = tri.map(|v| mesh.point_f32(v));
    [0, 1, 2].map(|k| (p[0][k] + p[1][k] + p[2][k]) / 3.0)
}

/// The next triangle for the open cluster among those sharing a vertex
/// with it (`members`): fewest new vertices first (none, or a triangle that
/// would otherwise be stranded: one of its vertices has no other live
/// triangle), then the smallest distance to `centre` weighted by
/// [`LIVE_WEIGHT`].
fn neighbour<P: Scalar>(
    st: &State<'_>,
    mesh: &Mesh<'_, P>,
    members: &[u16],
    centre: [f32; 3],
) -> Option<usize> {
    let mut best: Option<(usize, usize, f32)> = None;
    for &v in members {
        for &t in st.live_tris(usize::from(v)) {
            let tri = mesh.indices[t as usize];
            let extra = match new_vertices(st, tri) {
                0 => 0,
                _ if tri.iter().any(|&w| st.live[usize::from(w)] == 1) => 0,
                e => e + 1,
            };
            let live: u32 = tri.iter().map(|&w| st.live[usize::from(w)]).sum();
            let d = sqrt(dist2(centroid(mesh, tri), centre)) * (1.0 + LIVE_WEIGHT * live as f32);
            if best.is_none_or(|(_, be, bd)| extra < be || (extra == be && d < bd)) {
                best = Some((t as usize, extra, d));
            }
        }
    }
    best.map(|(t, _, _)| t)
}

/// The first triangle of a new cluster: next to the last closed cluster, the
/// live triangle whose vertices have the fewest live triangles (a corner of
/// what is left), nearest `anchor` among equals; else the live triangle
/// nearest `anchor`.
fn seed<P: Scalar>(st: &State<'_>, mesh: &Mesh<'_, P>, out: &Output<'_>, anchor: [f32; 3]) -> Option<usize> {
    let members = &out.vertices[out.last.0..out.last.1];
    let mut best: Option<(usize, u32, f32)> = None;
    for &v in members {
        for &t in st.live_tris(usize::from(v)) {
            let tri = mesh.indices[t as usize];
            let live: u32 = tri.iter().map(|&w| st.live[usize::from(w)]).sum();
            let d = dist2(centroid(mesh, tri), anchor);
            if best.is_none_or(|(_, bl, bd)| live < bl || (live == bl && d < bd)) {
                best = Some((t as usize, live, d));
            }
        }
    }
    best.map(|(t, _, _)| t).or_else(|| nearest(st, mesh, anchor).map(|(t, _)| t))
}

/// The live triangle whose centroid is nearest `point` (O(triangles)), and
/// its squared distance.
fn nearest<P: Scalar>(st: &State<'_>, mesh: &Mesh<'_, P>, point: [f32; 3]) -> Option<(usize, f32)> {
    let mut best: Option<(usize, f32)> = None;
    for (w, &bits) in st.done.iter().enumerate() {
        if bits == u32::MAX {
            continue;
        }
        for t in w * 32..(w * 32 + 32).min(mesh.indices.len()) {
            if st.is_done(t) {
                continue;
            }
            let d = dist2(centroid(mesh, mesh.indices[t]), point);
            if best.is_none_or(|(_, bd)| d < bd) {
                best = Some((t, d));
            }
        }
    }
    best
}

/// Squared distance from a cluster's centre within which a triangle not
/// adjacent to it still joins it: 1.5 times the radius of a disk of
/// [`TYPICAL_TRIANGLES`] mean-sized triangles. Farther ones (islands left
/// elsewhere) start a new cluster once the open one has
/// [`MIN_CLOSED_TRIANGLES`], so no cluster spans the mesh.
fn reach2<P: Scalar>(mesh: &Mesh<'_, P>) -> f32 {
    let mut area = 0.0f32;
    for i in 0..mesh.indices.len() {
        let p = mesh.indices[i].map(|v| mesh.point_f32(v));
        let n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        area += sqrt(dot(n, n)) * 0.5;
    }
    let mean = area / mesh.indices.len().max(1) as f32;
    2.25 * mean * TYPICAL_TRIANGLES / core::f32::consts::PI
}
