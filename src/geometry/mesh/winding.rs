//! The opt-in check that triangle windings agree with the vertex normals,
//! and the face-normal predicate shared with meshlet validation and the
//! meshlet builder.

use super::{cross, dot, sub};

/// A triangle is degenerate when `|e1 × e2|² ≤ DEGENERATE_SIN2 · |e1|² ·
/// |e2|²` (the sine of the angle between its edges `e1`, `e2` from the first
/// corner is at most 10⁻⁴): its face normal is then mostly rounding noise.
/// [`Mesh::check_winding`](super::Mesh::check_winding) skips it; a meshlet
/// cluster with one has no normal cone (cutoff `≥ 1`,
/// [`MeshletMesh::validate`](super::MeshletMesh::validate)), since its
/// image can still cover pixel centres whichever way it faces.
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
/// vertex normals `n` (the [`Mesh::check_winding`](super::Mesh::check_winding) rule; degenerate
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
