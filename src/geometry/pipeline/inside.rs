//! Whether a bounding sphere lies inside the clip volume with room to
//! spare: then every vertex within it has outcode 0, and the cached vertex
//! path ([`super::cache`]) skips the per-vertex clip codes (on the knot,
//! about 90 instructions per classified vertex on the Cortex-M4F).
//!
//! # Why a vertex in the sphere then has outcode 0
//! Let `m` bound the magnitude of every clip coordinate over the sphere
//! (`|row·(c, 1)| + r·|row.xyz|₁`, the largest of the four rows) and `l`
//! the largest `|row.xyz|₁`. The test asks for `w − w_min`, `z` (near) and
//! `w − z` (far, when clipped) to be at least `margin = (m + l + 1)/2^8`
//! everywhere in the sphere, and `g·w ± x`, `g·w ± y` (the guard band `g`,
//! in `f32`; `g = 1`, the view volume, in `Fx`) at least `g·margin` (the
//! least value of a plane `p` over it is `p·(c, 1) − r·|p.xyz|`, bounded
//! with `|p.xyz|₁`). A vertex's coordinates
//! as the pipeline computes them differ from the exact ones by:
//! * `f32`: three products and three sums, each rounding at 2^-24 relative
//!   to a partial sum of at most `m`: within `2^-22·m`;
//! * `Fx`: the position's conversion (2^-17 per coordinate, `2^-17·l` in
//!   all), three truncated products (2^-16 each) and the matrix's own
//!   rounding in `f32` here (2^-24 relative): within `2^-17·l + 2^-14 +
//!   2^-22·m`.
//!
//! So each computed distance of [`VertexClass::code`](crate::clip3d) (sums
//! of two coordinates, `g·w` for the guard band `g ≥ 1`) is positive: two
//! coordinate errors are below `margin`; `fl(g·w) ≥ w` for `g ≥ 1` and
//! `w > 0` (rounding is monotonic; `Fx` truncation loses at most 2^-16,
//! also inside the margin); in `f32`, `fl(g·w)` is within
//! `g·(δ + 2^-24·m)` of `g·W` for a computed `w` within `δ` of the exact
//! `W`, so the side planes' computed distances are off by less than
//! `g·(2·2^-22·m + 2^-24·m) < g·margin`; and a floating sum of a
//! non-negative exact sum is non-negative. `m ≤ 2^60` keeps every
//! coordinate finite and within the code's input limit (2^64). The sphere
//! is widened by twice the containment tolerance validation allows
//! (`SPHERE_TOLERANCE`). `tests::inside_spheres_have_only_inside_vertices`
//! checks the claim on random spheres and matrices in both numeric paths.
//!
//! # Why the guard band
//! The clipper leaves a triangle whose vertices lie inside the guard band
//! unclipped (outcode 0), so a cluster that reaches past the screen's edge
//! but not past the guard band takes the same triangles through this path
//! as through the cached one, without its per-vertex outcodes (on the knot
//! with the camera twice as close, `fw_bench`'s `knot20k-close` rows, the
//! cached path and its outcodes were 2.3 M of a 28 M frame before). `Fx`
//! keeps the view volume: its coordinates saturate at 2^15, and a test
//! that bounds them is not worth its cost there.

use crate::clip3d::ClipPlanes;
use crate::math::{Mat4, Scalar, Vec4};
use crate::mesh::SPHERE_TOLERANCE;

/// The test of the module docs for one model-view-projection matrix.
/// Small (it lives on the vertex stage's stack).
pub(super) struct InsideView {
    rows: [Vec4<f32>; 4],
    /// `|row.xyz|₁` of each row ([`l1`]) and the largest of them (`l`).
    l1: [f32; 4],
    l1_max: f32,
    /// `|p.xyz|₁` of each plane of [`InsideView::contains`], in its order.
    plane_l1: [f32; 7],
    far: bool,
    w_min: f32,
    /// The guard band of the side planes (module docs): the planes' in
    /// `f32`, 1 in `Fx`.
    guard: f32,
}

/// `|p.xyz|₁`, which bounds `|p.xyz|`.
fn l1(p: Vec4<f32>) -> f32 {
    p.x.abs() + p.y.abs() + p.z.abs()
}

impl InsideView {
    pub(super) fn new<T: Scalar>(mvp: &Mat4<T>, planes: ClipPlanes) -> Self {
        Self::from_rows::<T>(super::rows_f32(mvp), planes)
    }

    /// [`InsideView::new`] from the matrix's rows in `f32` ([`super::rows_f32`]).
    pub(super) fn from_rows<T: Scalar>(rows: [Vec4<f32>; 4], planes: ClipPlanes) -> Self {
        let l1s = rows.map(l1);
        // Fx acts on w_min no smaller than its smallest value, 2^-16.
        let w_min = planes.w_min().max(ClipPlanes::W_MIN);
        let guard = if crate::math::vec::is_float::<T>() { planes.guard_band() } else { 1.0 };
        let view = super::view_planes(rows, planes.far()).map(l1);
        // Only with a guard band: each product and sum is a library call in
        // the Cortex-M0's soft float.
        let sides = if guard == 1.0 {
            view
        } else {
            super::view_planes([rows[0], rows[1], rows[2], rows[3] * guard], true).map(l1)
        };
        InsideView {
            rows,
            l1: l1s,
            l1_max: l1s.into_iter().fold(0.0, f32::max),
            plane_l1: [l1s[3], sides[0], sides[1], sides[2], sides[3], view[4], view[5]],
            far: planes.far(),
            w_min,
            guard,
        }
    }

    /// True if every point of the sphere `(c, r)` (as validated, within
    /// its tolerance) has outcode 0 as the vertex stage computes it. The
    /// planes' values at the centre are sums of the rows' (`(w + x)·c =
    /// w·c + x·c`): their `f32` rounding differs from the planes' own
    /// products by a few `2^-24·m`, far inside the margin's `2^-8·m`.
    pub(super) fn contains(&self, (c, r): ([f32; 3], f32)) -> bool {
        let r = r * (1.0 + 2.0 * SPHERE_TOLERANCE);
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        let d = self.rows.map(|row| row.dot(centre));
        let mut m = 0.0f32;
        for (d, l1) in d.iter().zip(self.l1) {
            m = m.max(d.abs() + r * l1);
        }
        // Also false for NaN and infinity.
        if m.is_nan() || m > 1.152_921_5e18 {
            return false;
        }
        let margin = (m + self.l1_max + 1.0) / 256.0;
        // The least of `p · (q, 1)` over the sphere is `p · (c, 1) − r·|p.xyz|`:
        // w − w_min, then the view volume's planes, with the guard band's
        // `g·w` in the four sides (the near and far planes take none).
        let [v0, v1, v2, v3, v4, v5] = super::view_planes(d, self.far);
        let at_centre = [d[3] - self.w_min, v0, v1, v2, v3, v4, v5];
        if self.guard == 1.0 {
            // Two products fewer: soft float on the Cortex-M0 (`Fx`).
            return at_centre.iter().zip(self.plane_l1).all(|(v, l1)| v - r * l1 >= margin);
        }
        let (gw, g_margin) = (self.guard * d[3], self.guard * margin);
        let sides = [gw + d[0], gw - d[0], gw + d[1], gw - d[1]];
        let needed = [margin, g_margin, g_margin, g_margin, g_margin, margin, margin];
        let at_centre = [at_centre[0], sides[0], sides[1], sides[2], sides[3], v4, v5];
        at_centre.iter().zip(self.plane_l1).zip(needed).all(|((v, l1), need)| v - r * l1 >= need)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::clip3d::VertexClass;
    use crate::math::{Fx, Vec3, transform};

    /// The matrix of an eye at `z = 5` looking at the origin, near 1, far
    /// 10 (also the sphere rows' tests).
    pub(in crate::geometry::pipeline) fn eye_at_z5() -> crate::math::Mat4<f32> {
        let view =
            transform::look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))
                .unwrap();
        transform::perspective(0.8, 1.0, 1.0, 10.0).unwrap() * view
    }

    /// xorshift in [-1, 1) (also the sphere rows' tests).
    pub(in crate::geometry::pipeline) fn rng(seed: &mut u64) -> f32 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        ((*seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0) as f32
    }

    /// Clip position of `p` as the vertex stage computes it.
    fn clip<T: Scalar>(mvp: &Mat4<T>, p: [f32; 3]) -> [T; 4] {
        let p = Vec3::<T>::from_f32(p);
        let [a, b, c, d] = &mvp.cols;
        [0, 1, 2, 3].map(|r| a[r] * p.x + b[r] * p.y + c[r] * p.z + d[r])
    }

    fn check<T: Scalar>(
        seed: &mut u64,
        planes: ClipPlanes,
        accepted: &mut u32,
        near_edge: &mut u32,
        beyond: &mut u32,
    ) {
        // A camera looking at the origin from a random direction; spheres
        // scattered over and beyond the view, some hugging its edges.
        let dir = Vec3::new(rng(seed), rng(seed), rng(seed) + 2.0);
        let eye = dir * (2.0 + 3.0 * rng(seed).abs());
        let Ok(view) = transform::look_at(eye, Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)) else {
            return;
        };
        let fov = 0.5 + rng(seed).abs();
        let Ok(proj) = transform::perspective(fov, 1.3, 0.5, 12.0) else { return };
        let mvp_f = proj * view;
        let mvp = Mat4::<T>::from_f32(mvp_f.to_f32());
        let test = InsideView::new(&mvp, planes);
        let coder = VertexClass::<T>::new(planes);
        for _ in 0..40 {
            let c = [rng(seed) * 3.0, rng(seed) * 3.0, rng(seed) * 3.0];
            let r = rng(seed).abs() * 0.6;
            if !test.contains((c, r)) {
                continue;
            }
            *accepted += 1;
            for i in 0..64 {
                // Points on and just inside the sphere (the tolerance).
                let d = Vec3::new(rng(seed), rng(seed), rng(seed));
                let len = d.length();
                if len == 0.0 {
                    continue;
                }
                let s = r * (1.0 + SPHERE_TOLERANCE) / len * if i % 4 == 0 { 1.0 } else { rng(seed).abs() };
                let p = [c[0] + d.x * s, c[1] + d.y * s, c[2] + d.z * s];
                let v = clip(&mvp, p);
                assert_eq!(coder.code(&v), 0, "{c:?} {r} {p:?}");
                // How close to the view volume's edge the accepted points get.
                let v = v.map(|x| x.to_f32());
                let edge = [v[3] - v[0], v[3] + v[0], v[3] - v[1], v[3] + v[1], v[2], v[3] - v[2]];
                *near_edge += edge.iter().any(|&e| e < 0.05 * v[3]) as u32;
                *beyond += (v[0].abs() > v[3] || v[1].abs() > v[3]) as u32;
            }
        }
    }

    /// Whenever a sphere is accepted, every point of it (within the
    /// validation tolerance) has outcode 0, in `f32` and in `Fx`, with and
    /// without the far plane.
    #[test]
    fn inside_spheres_have_only_inside_vertices() {
        let mut seed = 0x5851_f42d_4c95_7f2du64;
        let (mut accepted, mut near_edge, mut beyond) = (0, 0, 0);
        for i in 0..600 {
            let planes = if i % 2 == 0 { ClipPlanes::DEFAULT } else { ClipPlanes::NO_FAR };
            let planes = if i % 3 == 0 { planes.with_guard_band(1.0) } else { planes };
            check::<f32>(&mut seed, planes, &mut accepted, &mut near_edge, &mut beyond);
            check::<Fx>(&mut seed, planes, &mut accepted, &mut near_edge, &mut beyond);
        }
        // Not vacuous: many spheres pass, their points reach the edges, and
        // in `f32` with a guard band many lie beyond the view volume's sides.
        assert!(accepted > 2_000 && near_edge > 1_000 && beyond > 1_000, "{accepted} {near_edge} {beyond}");
    }

    /// The same at a guard band the random spheres reach (the default, 256,
    /// lies far beyond them): in `f32` the side planes are the guard band's.
    #[test]
    fn spheres_inside_a_narrow_guard_band_have_only_inside_vertices() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let (mut accepted, mut near_edge, mut beyond) = (0, 0, 0);
        for i in 0..600 {
            let planes = if i % 2 == 0 { ClipPlanes::DEFAULT } else { ClipPlanes::NO_FAR };
            check::<f32>(&mut seed, planes.with_guard_band(1.5), &mut accepted, &mut near_edge, &mut beyond);
        }
        // Not vacuous: many spheres pass, most of their points beyond the view volume.
        assert!(accepted > 10_000 && beyond > 40_000, "{accepted} {beyond}");
    }

    /// Spheres across a plane, behind the eye or beyond the range are not
    /// inside.
    #[test]
    fn spheres_across_the_edges_are_not_inside() {
        let mvp = eye_at_z5();
        // The view volume's sides: guard band 1 in `f32`, any in `Fx`.
        let view = InsideView::new(&mvp, ClipPlanes::DEFAULT.with_guard_band(1.0));
        let fx = InsideView::new(&Mat4::<Fx>::from_f32(mvp.to_f32()), ClipPlanes::DEFAULT);
        assert!(view.contains(([0.0; 3], 0.5)) && fx.contains(([0.0; 3], 0.5)));
        assert!(!view.contains(([0.0; 3], 3.0)) && !fx.contains(([0.0; 3], 3.0))); // beyond the sides
        // In `f32` the guard band's sides (256 by default): beyond the
        // screen, not beyond the guard band.
        let test = InsideView::new(&mvp, ClipPlanes::DEFAULT);
        assert!(test.contains(([0.0; 3], 3.0)));
        assert!(test.contains(([50.0, 0.0, 0.0], 0.5)) && !view.contains(([50.0, 0.0, 0.0], 0.5)));
        assert!(!test.contains(([1000.0, 0.0, 0.0], 1.0))); // beyond the guard band
        assert!(!test.contains(([0.0, -1000.0, 0.0], 1.0)));
        assert!(!test.contains(([0.0, 0.0, 4.5], 0.2))); // across the near plane
        assert!(!test.contains(([0.0, 0.0, -5.5], 0.2))); // beyond the far plane
        assert!(test.contains(([0.0, 0.0, -4.0], 0.2)));
        assert!(InsideView::new(&mvp, ClipPlanes::NO_FAR).contains(([0.0, 0.0, -5.5], 0.2)));
        assert!(!test.contains(([0.0; 3], f32::NAN)));
        assert!(!test.contains(([1e30, 0.0, 0.0], 1.0)));
    }
}
