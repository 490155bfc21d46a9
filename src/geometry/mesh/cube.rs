//! The cube `[-1, 1]³` with per-face normals.

use super::{BUFFER_TOO_SMALL, Mesh, sphere_about_origin};
use crate::error::Error;

/// Vertices [`cube`] writes: 4 per face, so each face has its own normal.
pub const fn cube_vertex_count() -> usize {
    24
}

/// Triangles [`cube`] writes: 2 per face.
pub const fn cube_triangle_count() -> usize {
    12
}

/// `(outward normal, u, v)` per face with `u × v = normal`, so the corners
/// `n − u − v, n + u − v, n + u + v, n − u + v` run counter-clockwise seen
/// from outside. (Also the table of the const-built `view3d::CUBE`.)
pub(crate) const FACES: [[[f32; 3]; 3]; 6] = [
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    [[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
    [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]],
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
    [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
    [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
];

/// Writes the axis-aligned cube `[-1, 1]³` (side 2, centred on the origin)
/// into the buffers and returns it as a [`Mesh`] borrowing their first
/// [`cube_vertex_count`] / [`cube_triangle_count`] entries.
///
/// Each face has its own 4 vertices carrying the face's outward unit normal,
/// so flat shading needs no extra work. Triangles are counter-clockwise seen
/// from outside; the bounding sphere is centred on the origin with radius √3.
///
/// # Errors
///
/// [`Error::CoordinateOutOfRange`] (a dedicated variant is planned) if a
/// buffer is too small; the buffers are then left untouched.
///
/// ```
/// use microraster::mesh::{cube, cube_triangle_count, cube_vertex_count};
/// let mut positions = [[0.0; 3]; cube_vertex_count()];
/// let mut normals = [[0.0; 3]; cube_vertex_count()];
/// let mut indices = [[0; 3]; cube_triangle_count()];
/// let mesh = cube(&mut positions, &mut normals, &mut indices)?;
/// mesh.validate()?;
/// assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (24, 12));
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn cube<'a>(
    positions: &'a mut [[f32; 3]],
    normals: &'a mut [[f32; 3]],
    indices: &'a mut [[u16; 3]],
) -> Result<Mesh<'a>, Error> {
    let (nv, nt) = (cube_vertex_count(), cube_triangle_count());
    let (Some(positions), Some(normals), Some(indices)) =
        (positions.get_mut(..nv), normals.get_mut(..nv), indices.get_mut(..nt))
    else {
        return Err(BUFFER_TOO_SMALL);
    };
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    for (f, [n, u, v]) in FACES.iter().enumerate() {
        for (k, (a, b)) in corners.iter().enumerate() {
            positions[4 * f + k] = [0, 1, 2].map(|i| n[i] + a * u[i] + b * v[i]);
            normals[4 * f + k] = *n;
        }
        let base = 4 * f as u16;
        indices[2 * f] = [base, base + 1, base + 2];
        indices[2 * f + 1] = [base, base + 2, base + 3];
    }
    let sphere = sphere_about_origin(positions);
    Ok(Mesh::new(positions, normals, indices, sphere))
}
