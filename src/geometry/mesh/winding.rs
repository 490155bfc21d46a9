//! The opt-in check that triangle windings agree with the vertex normals,
//! and the face-normal predicate shared with meshlet validation and the
//! meshlet builder.

use super::{Mesh, cross, dot, sub};
use crate::error::Error;

/// A triangle is degenerate, and skipped by [`Mesh::check_winding`] and the
/// meshlet cone checks, when `|e1 × e2|² ≤ DEGENERATE_SIN2 · |e1|² · |e2|²`
/// (the sine of the angle between its edges `e1`, `e2` from the first
/// corner is at most 10⁻⁴): its face normal is then mostly rounding noise.
pub const DEGENERATE_SIN2: f32 = 1.0e-8;

/// The unnormalised face normal `(b − a) × (c − a)` of a triangle and its
/// squared length, or `None` if the triangle is degenerate
/// ([`DEGENERATE_SIN2`]) or its products overflow `f32`.
pub(crate) const fn face_cross(p: [[f32; 3]; 3]) -> Option<([f32; 3], f32)> {
    let (e1, e2) = (sub(p[1], p[0]), sub(p[2], p[0]));
    let n = cross(e1, e2);
    let len2 = dot(n, n);
    let scale = dot(e1, e1) * dot(e2, e2);
    // NaN or infinite products fail both comparisons: treated as degenerate.
    if len2 > DEGENERATE_SIN2 * scale && scale < f32::INFINITY && len2 < f32::INFINITY {
        Some((n, len2))
    } else {
        None
    }
}

/// Whether the winding of the triangle with positions `p` agrees with its
/// vertex normals `n` (the [`Mesh::check_winding`] rule; degenerate
/// triangles agree).
pub(crate) const fn winding_agrees(p: [[f32; 3]; 3], n: [[f32; 3]; 3]) -> bool {
    match face_cross(p) {
        None => true,
        Some((face, _)) => {
            let sum = [n[0][0] + n[1][0] + n[2][0], n[0][1] + n[1][1] + n[2][1], n[0][2] + n[1][2] + n[2][2]];
            // NaN (an overflow) is no evidence of a mismatch.
            let d = dot(face, sum);
            d >= 0.0 || d.is_nan()
        }
    }
}

impl Mesh<'_> {
    /// Checks that every triangle is wound counter-clockwise seen from the
    /// side its vertex normals point to: for each non-degenerate triangle
    /// (see [`DEGENERATE_SIN2`]) the face normal `(b − a) × (c − a)` must
    /// not point against the sum of its three vertex normals (their dot
    /// product is `≥ 0`). A mesh without normals passes. Opt-in (O(triangles)),
    /// because [`validate`](Mesh::validate) does not need it; a mesh with the
    /// wrong winding is drawn inside out (culled from the front), which this
    /// check catches at build time. A `const fn`, like `validate`.
    ///
    /// # Errors
    ///
    /// The errors of [`validate`](Mesh::validate), which runs first; then
    /// [`Error::WindingMismatch`] for the first disagreeing triangle.
    ///
    /// ```
    /// use microraster::{Error, mesh::Mesh};
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// let up = [[0.0, 0.0, 1.0]; 3];
    /// let sphere = ([0.5, 0.5, 0.0], 0.71);
    /// assert_eq!(Mesh::new(&positions, &up, &[[0, 1, 2]], sphere).check_winding(), Ok(()));
    /// assert_eq!(
    ///     Mesh::new(&positions, &up, &[[0, 2, 1]], sphere).check_winding(),
    ///     Err(Error::WindingMismatch)
    /// );
    /// ```
    pub const fn check_winding(&self) -> Result<(), Error> {
        if let Err(e) = self.validate() {
            return Err(e);
        }
        self.check_winding_unvalidated()
    }

    /// [`check_winding`](Mesh::check_winding) for a mesh already validated.
    pub(crate) const fn check_winding_unvalidated(&self) -> Result<(), Error> {
        if self.normals.is_empty() {
            return Ok(());
        }
        let mut i = 0;
        while i < self.indices.len() {
            let [a, b, c] = self.indices[i];
            let (a, b, c) = (a as usize, b as usize, c as usize);
            let p = [self.positions[a], self.positions[b], self.positions[c]];
            let n = [self.normals[a], self.normals[b], self.normals[c]];
            if !winding_agrees(p, n) {
                return Err(Error::WindingMismatch);
            }
            i += 1;
        }
        Ok(())
    }
}
