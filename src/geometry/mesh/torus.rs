//! The torus around the y axis.

use super::{
    BUFFER_TOO_SMALL, INVALID_PARAMETER, MAX_VERTICES, Mesh, cos_sin, normalize, sphere_about_origin,
};
use crate::error::Error;

/// Vertices [`torus`] writes: `major_segments · minor_segments` (saturating).
pub const fn torus_vertex_count(major_segments: usize, minor_segments: usize) -> usize {
    major_segments.saturating_mul(minor_segments)
}

/// Triangles [`torus`] writes: `2 · major_segments · minor_segments`
/// (saturating).
pub const fn torus_triangle_count(major_segments: usize, minor_segments: usize) -> usize {
    torus_vertex_count(major_segments, minor_segments).saturating_mul(2)
}

/// Writes a torus centred on the origin around the y axis (the ring lies in
/// the xz plane): the tube of radius `minor_radius` swept around a circle of
/// radius `major_radius`, with `major_segments` steps around the ring and
/// `minor_segments` around the tube. Returns it as a [`Mesh`] borrowing the
/// first [`torus_vertex_count`] / [`torus_triangle_count`] entries of the
/// buffers.
///
/// Vertex `i · minor_segments + j` is at ring angle `u = 2πi/major_segments`
/// and tube angle `v = 2πj/minor_segments`:
/// `((R + r cos v) cos u, r sin v, −(R + r cos v) sin u)`, with unit outward
/// normal `(cos v cos u, sin v, −cos v sin u)` (`micromath`'s cosine and sine,
/// renormalised so every vertex lies exactly on the torus up to rounding; the
/// angles may deviate from the nominal ones by up to 0.002 rad, invisibly).
/// The seams are shared, so the
/// mesh is closed and 2-manifold; triangles are counter-clockwise seen from
/// outside.
///
/// # Errors
///
/// * [`Error::NonFiniteCoordinate`] if a radius is NaN or infinite, or the
///   torus is too large for `f32`;
/// * [`Error::CoordinateOutOfRange`] (dedicated variants are planned) if a
///   segment count is below 3, there would be more than
///   [`MAX_VERTICES`] vertices, the radii do not satisfy
///   `0 < minor_radius < major_radius`, or a buffer is too small.
///
/// The buffers are untouched on error, except when the torus overflows `f32`.
///
/// ```
/// use microraster::mesh::{torus, torus_triangle_count, torus_vertex_count};
/// const M: usize = 24;
/// const N: usize = 12;
/// let mut positions = [[0.0; 3]; torus_vertex_count(M, N)];
/// let mut normals = [[0.0; 3]; torus_vertex_count(M, N)];
/// let mut indices = [[0; 3]; torus_triangle_count(M, N)];
/// let mesh = torus(M, N, 1.0, 0.4, &mut positions, &mut normals, &mut indices)?;
/// mesh.validate()?;
/// assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (288, 576));
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn torus<'a>(
    major_segments: usize,
    minor_segments: usize,
    major_radius: f32,
    minor_radius: f32,
    positions: &'a mut [[f32; 3]],
    normals: &'a mut [[f32; 3]],
    indices: &'a mut [[u16; 3]],
) -> Result<Mesh<'a>, Error> {
    let (m, n) = (major_segments, minor_segments);
    let (big_r, r) = (major_radius, minor_radius);
    if !big_r.is_finite() || !r.is_finite() {
        return Err(Error::NonFiniteCoordinate);
    }
    let nv = torus_vertex_count(m, n);
    if m < 3 || n < 3 || nv > MAX_VERTICES || !(0.0 < r && r < big_r) {
        return Err(INVALID_PARAMETER);
    }
    let nt = torus_triangle_count(m, n);
    let (Some(positions), Some(normals), Some(indices)) =
        (positions.get_mut(..nv), normals.get_mut(..nv), indices.get_mut(..nt))
    else {
        return Err(BUFFER_TOO_SMALL);
    };
    let tau = core::f32::consts::TAU;
    for i in 0..m {
        let (cu, su) = cos_sin(tau * i as f32 / m as f32);
        for j in 0..n {
            let (cv, sv) = cos_sin(tau * j as f32 / n as f32);
            let rho = big_r + r * cv;
            positions[i * n + j] = [rho * cu, r * sv, -rho * su];
            normals[i * n + j] = normalize([cv * cu, sv, -cv * su]);
        }
    }
    // Vertex numbers are below `nv` ≤ 65536, so the casts are exact.
    let v = |i: usize, j: usize| ((i % m) * n + j % n) as u16;
    for i in 0..m {
        for j in 0..n {
            let t = 2 * (i * n + j);
            indices[t] = [v(i, j), v(i + 1, j), v(i + 1, j + 1)];
            indices[t + 1] = [v(i, j), v(i + 1, j + 1), v(i, j + 1)];
        }
    }
    let sphere = sphere_about_origin(positions);
    if !sphere.1.is_finite() {
        return Err(Error::NonFiniteCoordinate);
    }
    Ok(Mesh::new(positions, normals, indices, sphere))
}
