//! Bounding spheres of point sets: [`bounding_sphere`] (the better of the
//! axis-aligned box centre and Ritter's centre, with the tightest `f32`
//! radius) for meshes and meshlets, and the origin-centred sphere of the
//! generated shapes.

use super::{add, dist2, is_finite3, sqrt, sub};

/// A bounding sphere of `positions`, for [`Mesh::bounding_sphere`](super::Mesh::bounding_sphere); the
/// generators and the `obj2rs` converter use it.
///
/// The centre is the better of two candidates, the centre of the axis-aligned
/// bounding box and the centre found by Ritter's algorithm; the radius is the
/// smallest `f32` with `|p − centre|² ≤ radius²` (evaluated in `f32`) for
/// every position. This is not the minimal enclosing sphere, but usually
/// within a few percent of it. O(n), no allocation.
///
/// An empty slice gives `([0.0; 3], 0.0)`. If a position is not finite, or
/// squared distances overflow `f32` (coordinates beyond about 10¹⁹), the radius
/// is infinite, which [`Mesh::validate`](super::Mesh::validate) rejects.
///
/// ```
/// use microraster::mesh::bounding_sphere;
/// let (centre, radius) = bounding_sphere(&[[1.0, 0.0, 0.0], [3.0, 0.0, 0.0], [2.0, 1.0, 0.0]]);
/// assert_eq!((centre, radius), ([2.0, 0.0, 0.0], 1.0));
/// ```
pub fn bounding_sphere(positions: &[[f32; 3]]) -> ([f32; 3], f32) {
    let Some(&first) = positions.first() else {
        return ([0.0; 3], 0.0);
    };
    if !positions.iter().all(|&p| is_finite3(p)) {
        return ([0.0; 3], f32::INFINITY);
    }
    let (mut lo, mut hi) = (first, first);
    for p in positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    // Halves first: `lo + hi` could overflow.
    let aabb = [0, 1, 2].map(|k| lo[k] * 0.5 + hi[k] * 0.5);
    let ritter = ritter_centre(positions, first);
    let (ra, rr) = (radius_about(positions, aabb), radius_about(positions, ritter));
    if rr < ra { (ritter, rr) } else { (aabb, ra) }
}

/// Centre of Ritter's bounding sphere: the sphere on the diameter between an
/// extreme pair, grown to take in every outlier in one pass.
fn ritter_centre(positions: &[[f32; 3]], first: [f32; 3]) -> [f32; 3] {
    let farthest = |from: [f32; 3]| {
        positions.iter().copied().max_by(|&a, &b| dist2(a, from).total_cmp(&dist2(b, from))).unwrap_or(from)
    };
    let y = farthest(first);
    let z = farthest(y);
    let mut c = [0, 1, 2].map(|k| y[k] * 0.5 + z[k] * 0.5);
    let mut r = sqrt(dist2(y, z)) * 0.5;
    for &p in positions {
        let d2 = dist2(p, c);
        if d2 > r * r {
            let d = sqrt(d2);
            let grown = (r + d) * 0.5;
            let t = (d - grown) / d;
            c = add(c, sub(p, c).map(|x| x * t));
            r = grown;
        }
    }
    c
}

/// The smallest `f32` radius `r` with `|p − centre|² ≤ r²` in `f32` for every
/// position (infinity if the squares overflow).
fn radius_about(positions: &[[f32; 3]], centre: [f32; 3]) -> f32 {
    let max_d2 = positions.iter().map(|&p| dist2(p, centre)).fold(0.0f32, f32::max);
    if !max_d2.is_finite() {
        return f32::INFINITY;
    }
    let mut r = sqrt(max_d2);
    // `sqrt` is within an ulp or two: step to the smallest radius that works.
    while r * r < max_d2 {
        r = r.next_up();
    }
    while r > 0.0 && r.next_down() * r.next_down() >= max_d2 {
        r = r.next_down();
    }
    r
}

/// The sphere about the origin, for the generated (origin-centred) shapes.
pub(super) fn sphere_about_origin(positions: &[[f32; 3]]) -> ([f32; 3], f32) {
    ([0.0; 3], radius_about(positions, [0.0; 3]))
}
