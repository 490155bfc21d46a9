//! A built-in mesh, so a first scene needs no generator buffers: the cube
//! `[-1, 1]³` with per-face normals, the same vertices, normals and
//! triangles as [`mesh::cube`](fn@crate::mesh::cube) writes, computed at
//! compile time and checked there ([`ValidMesh::new`] is `const`).

use crate::mesh::cube::FACES;
use crate::mesh::{Mesh, ValidMesh, cube_triangle_count, cube_vertex_count};

const NV: usize = cube_vertex_count();
const NT: usize = cube_triangle_count();

/// Positions, normals and triangles.
type Tables = ([[f32; 3]; NV], [[f32; 3]; NV], [[u16; 3]; NT]);

/// The tables, in `mesh::cube`'s order.
const fn build() -> Tables {
    let corners = [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    let (mut p, mut n, mut t) = ([[0.0; 3]; NV], [[0.0; 3]; NV], [[0u16; 3]; NT]);
    let mut f = 0;
    while f < 6 {
        let [nf, u, v] = FACES[f];
        let mut k = 0;
        while k < 4 {
            let (a, b) = corners[k];
            let mut i = 0;
            while i < 3 {
                p[4 * f + k][i] = nf[i] + a * u[i] + b * v[i];
                i += 1;
            }
            n[4 * f + k] = nf;
            k += 1;
        }
        let base = 4 * f as u16;
        t[2 * f] = [base, base + 1, base + 2];
        t[2 * f + 1] = [base, base + 2, base + 3];
        f += 1;
    }
    (p, n, t)
}

const DATA: Tables = build();
static POSITIONS: [[f32; 3]; NV] = DATA.0;
static NORMALS: [[f32; 3]; NV] = DATA.1;
static INDICES: [[u16; 3]; NT] = DATA.2;

/// The cube `[-1, 1]³` (side 2, centred on the origin), 24 vertices with
/// per-face unit normals and 12 triangles counter-clockwise from outside:
/// the mesh [`mesh::cube`](fn@crate::mesh::cube) writes, as a `static`
/// checked at compile time. Scale and place it with
/// [`Object`](super::Object)'s transforms.
///
/// ```
/// use microraster::view3d::CUBE;
/// let m = CUBE.mesh();
/// assert_eq!((m.vertex_count(), m.triangle_count()), (24, 12));
/// assert_eq!(m.check_winding(), Ok(()));
/// ```
pub static CUBE: ValidMesh<'static> =
    match ValidMesh::new(Mesh::new(&POSITIONS, &NORMALS, &INDICES, ([0.0; 3], 1.732_050_8))) {
        Ok(m) => m,
        // Evaluated at compile time: a bad table is a build error.
        Err(_) => panic!("view3d::CUBE is not a valid mesh"),
    };

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::cube;

    /// The same data as the run-time generator, entry for entry.
    #[test]
    fn cube_matches_the_generator() {
        let (mut p, mut n, mut i) = ([[0.0; 3]; NV], [[0.0; 3]; NV], [[0; 3]; NT]);
        let g = cube(&mut p, &mut n, &mut i).unwrap();
        let c = CUBE.mesh();
        assert_eq!((g.positions, g.normals, g.indices), (c.positions, c.normals, c.indices));
        assert!(c.bounding_sphere.1 >= g.bounding_sphere.1 * (1.0 - 1e-6));
    }

    /// Every triangle's winding gives its outward normal: the cross product
    /// of its edges points the way of the stored normal, away from the
    /// centre (computed here, not taken from the table).
    #[test]
    fn triangles_face_outwards() {
        let c = CUBE.mesh();
        for t in c.indices {
            let [a, b, d] = t.map(|k| c.positions[usize::from(k)]);
            let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let e2 = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
            let n =
                [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
            let centre = [0, 1, 2].map(|k| (a[k] + b[k] + d[k]) / 3.0);
            let out: f32 = (0..3).map(|k| n[k] * centre[k]).sum();
            assert!(out > 0.0, "{t:?} faces inwards");
        }
    }
}
