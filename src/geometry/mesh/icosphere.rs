//! The unit icosphere: a recursively subdivided icosahedron.

use super::{BUFFER_TOO_SMALL, INVALID_PARAMETER, Mesh, add, normalize, sphere_about_origin};
use crate::error::Error;

/// Most subdivisions [`icosphere`] accepts: 6 gives 40962 vertices, 7 would
/// exceed the 65536 vertices that `u16` indices can address.
pub const ICOSPHERE_MAX_SUBDIVISIONS: u32 = 6;

/// Vertices [`icosphere`] writes for `subdivisions`: `10·4ⁿ + 2`
/// (saturating at `usize::MAX`).
pub const fn icosphere_vertex_count(subdivisions: u32) -> usize {
    pow4(subdivisions).saturating_mul(10).saturating_add(2)
}

/// Triangles [`icosphere`] writes for `subdivisions`: `20·4ⁿ` (saturating at
/// `usize::MAX`).
pub const fn icosphere_triangle_count(subdivisions: u32) -> usize {
    pow4(subdivisions).saturating_mul(20)
}

/// `4ⁿ`, saturating.
const fn pow4(n: u32) -> usize {
    if n >= usize::BITS / 2 { usize::MAX } else { 1 << (2 * n) }
}

/// `1/√(1+φ²)` and `φ/√(1+φ²)`: the icosahedron `(0, ±1, ±φ)` scaled to the
/// unit sphere.
const A: f32 = 0.5257311;
const B: f32 = 0.8506508;

const CORNERS: [[f32; 3]; 12] = [
    [-A, B, 0.0],
    [A, B, 0.0],
    [-A, -B, 0.0],
    [A, -B, 0.0],
    [0.0, -A, B],
    [0.0, A, B],
    [0.0, -A, -B],
    [0.0, A, -B],
    [B, 0.0, -A],
    [B, 0.0, A],
    [-B, 0.0, -A],
    [-B, 0.0, A],
];

/// Counter-clockwise seen from outside.
const FACES: [[u8; 3]; 20] = [
    [0, 11, 5],
    [0, 5, 1],
    [0, 1, 7],
    [0, 7, 10],
    [0, 10, 11],
    [1, 5, 9],
    [5, 11, 4],
    [11, 10, 2],
    [10, 7, 6],
    [7, 1, 8],
    [3, 9, 4],
    [3, 4, 2],
    [3, 2, 6],
    [3, 6, 8],
    [3, 8, 9],
    [4, 9, 5],
    [2, 4, 11],
    [6, 2, 10],
    [8, 6, 7],
    [9, 8, 1],
];

/// The 30 edges `[a, b]` with `a < b`, in order of first appearance. In a
/// consistently oriented closed mesh every edge appears once as `a → b` and
/// once as `b → a`, so taking the increasing direction lists each edge once
/// (an inconsistent `FACES` table fails to compile here).
const EDGES: [[u8; 2]; 30] = {
    let mut edges = [[0u8; 2]; 30];
    let mut n = 0;
    let mut f = 0;
    while f < FACES.len() {
        let mut k = 0;
        while k < 3 {
            let (a, b) = (FACES[f][k], FACES[f][(k + 1) % 3]);
            if a < b {
                edges[n] = [a, b];
                n += 1;
            }
            k += 1;
        }
        f += 1;
    }
    assert!(n == 30);
    edges
};

/// Writes the icosphere of radius 1 centred on the origin, obtained by
/// splitting each triangle of an icosahedron into 4, `subdivisions` times
/// (0 gives the icosahedron), pushing new vertices onto the sphere at every
/// level. Returns it as a [`Mesh`] borrowing the first
/// [`icosphere_vertex_count`] / [`icosphere_triangle_count`] entries of the
/// buffers.
///
/// Vertices are shared (each edge vertex is stored once): the mesh is closed
/// and 2-manifold, with `10·4ⁿ + 2` vertices and `20·4ⁿ` triangles,
/// counter-clockwise seen from outside. Normals equal the positions (unit,
/// outward). No hash map, search or scratch buffer is needed: vertices are
/// numbered canonically (12 corners, then the interior points of each of the
/// 30 edges, then the interior points of each of the 20 faces) and each face's
/// triangular grid maps onto those numbers directly. O(vertices) time, no
/// recursion.
///
/// # Errors
///
/// [`Error::CoordinateOutOfRange`] (dedicated variants are planned) if
/// `subdivisions` exceeds [`ICOSPHERE_MAX_SUBDIVISIONS`] or a buffer is too
/// small; the buffers are then left untouched.
///
/// ```
/// use microraster::mesh::{icosphere, icosphere_triangle_count, icosphere_vertex_count};
/// const N: u32 = 2;
/// let mut positions = [[0.0; 3]; icosphere_vertex_count(N)];
/// let mut normals = [[0.0; 3]; icosphere_vertex_count(N)];
/// let mut indices = [[0; 3]; icosphere_triangle_count(N)];
/// let mesh = icosphere(N, &mut positions, &mut normals, &mut indices)?;
/// mesh.validate()?;
/// assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (162, 320));
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn icosphere<'a>(
    subdivisions: u32,
    positions: &'a mut [[f32; 3]],
    normals: &'a mut [[f32; 3]],
    indices: &'a mut [[u16; 3]],
) -> Result<Mesh<'a>, Error> {
    if subdivisions > ICOSPHERE_MAX_SUBDIVISIONS {
        return Err(INVALID_PARAMETER);
    }
    let (nv, nt) = (icosphere_vertex_count(subdivisions), icosphere_triangle_count(subdivisions));
    let (Some(positions), Some(normals), Some(indices)) =
        (positions.get_mut(..nv), normals.get_mut(..nv), indices.get_mut(..nt))
    else {
        return Err(BUFFER_TOO_SMALL);
    };
    let grid = Grid::new(subdivisions);
    let k = grid.k;
    for (p, c) in positions.iter_mut().zip(CORNERS) {
        *p = normalize(c);
    }
    // Level by level, coarse to fine: at level L the new points are those
    // whose barycentric weights (summing to k) are multiples of s = k/2^L
    // but not of 2s. Such a point is the midpoint of two older neighbours
    // s steps away, and is placed at their normalised sum. Points on edges
    // are computed once from each adjacent face, identically (the sum is
    // commutative).
    for level in 1..=subdivisions {
        let s = k >> level;
        for f in 0..FACES.len() {
            for j in (0..=k).step_by(s) {
                for i in (0..=k - j).step_by(s) {
                    let w = [k - i - j, i, j];
                    let (x, y) = match w.map(|x| (x / s) % 2 == 1) {
                        [false, false, false] => continue,
                        [true, true, _] => (0, 1),
                        [true, _, _] => (0, 2),
                        _ => (1, 2),
                    };
                    let (mut q1, mut q2) = (w, w);
                    q1[x] += s;
                    q1[y] -= s;
                    q2[x] -= s;
                    q2[y] += s;
                    let (a, b) =
                        (positions[grid.vertex(f, q1[1], q1[2])], positions[grid.vertex(f, q2[1], q2[2])]);
                    positions[grid.vertex(f, i, j)] = normalize(add(a, b));
                }
            }
        }
    }
    let mut tri = 0;
    for f in 0..FACES.len() {
        // Every index is below `nv` ≤ 65536, so the casts are exact.
        let v = |i, j| grid.vertex(f, i, j) as u16;
        for j in 0..k {
            for i in 0..k - j {
                indices[tri] = [v(i, j), v(i + 1, j), v(i, j + 1)];
                tri += 1;
                if i + j + 1 < k {
                    indices[tri] = [v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)];
                    tri += 1;
                }
            }
        }
    }
    debug_assert_eq!(tri, nt);
    normals.copy_from_slice(positions);
    let sphere = sphere_about_origin(positions);
    Ok(Mesh::new(positions, normals, indices, sphere))
}

/// Canonical vertex numbering of the subdivided icosahedron with `k = 2ⁿ`
/// segments per edge. Face grid point `(i, j)` (`i, j ≥ 0`, `i + j ≤ k`) is
/// `A + i/k·(B − A) + j/k·(C − A)` for the face `[A, B, C]`.
struct Grid {
    k: usize,
}

impl Grid {
    fn new(subdivisions: u32) -> Self {
        Grid { k: 1 << subdivisions }
    }

    /// First vertex of the interior of edge `e`.
    fn edge_base(&self, e: usize) -> usize {
        12 + e * (self.k - 1)
    }

    /// Vertex `t` (`0 < t < k`, counted from `a`) of the edge between corners
    /// `a` and `b`.
    fn edge_vertex(&self, a: u8, b: u8, t: usize) -> usize {
        let (e, t) = match EDGES.iter().position(|&e| e == [a, b]) {
            Some(e) => (e, t),
            // `EDGES` holds every edge in one of the two directions.
            None => (EDGES.iter().position(|&e| e == [b, a]).unwrap_or(0), self.k - t),
        };
        self.edge_base(e) + t - 1
    }

    /// Vertex number of grid point `(i, j)` of face `f`.
    fn vertex(&self, f: usize, i: usize, j: usize) -> usize {
        let k = self.k;
        let [a, b, c] = FACES[f];
        match (i, j) {
            (0, 0) => usize::from(a),
            (_, 0) if i == k => usize::from(b),
            (0, _) if j == k => usize::from(c),
            (_, 0) => self.edge_vertex(a, b, i),
            (0, _) => self.edge_vertex(a, c, j),
            _ if i + j == k => self.edge_vertex(b, c, j),
            _ => {
                // Interior rows j = 1..=k−2 hold i = 1..=k−1−j.
                let per_face = (k - 1) * (k - 2) / 2;
                let row = (j - 1) * (k - 1) - (j - 1) * j / 2;
                12 + 30 * (k - 1) + f * per_face + row + i - 1
            }
        }
    }
}
