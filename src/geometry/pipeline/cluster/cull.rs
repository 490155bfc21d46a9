//! The cluster tests of [`Pipeline::draw_meshlets`](crate::pipeline::Pipeline::draw_meshlets):
//! a cluster's bounding sphere against the band's slab and the view volume,
//! and its normal cone against the eye, all in model space before any
//! vertex work.

use super::super::{Band, MeshStats, view_planes};
use crate::math::{Scalar, Vec3, Vec4};
use crate::mesh::Meshlet;

/// The cluster tests' slack, relative to a sphere's reach `r·|p.xyz|`
/// and absolute: far above their `f32` rounding (`2^-24` relative per
/// operation) and the vertex stage's own (as in [`super::super::inside`]).
const CULL_SLACK: f32 = 1.0 / 256.0;

/// The per-band, per-mesh cluster tests in model space, in `f32` on both
/// numeric paths: in 16.16 the plane values of a large sphere saturate (the
/// mesh-level tests are `f32` for the same reason), and a handful of
/// products per cluster and band is small beside the vertex work it saves.
pub(crate) struct ClusterCull {
    /// Planes `p` with `p · (x, 1) ≥ 0` inside: the view volume and the
    /// band's slab, with `|p.xyz|·(1 + CULL_SLACK)`.
    planes: [(Vec4<f32>, f32); 8], // the slab's two, then the view volume's six
    count: usize,
    /// How many of `planes` are the slab's (0 to 2).
    slab: usize,
    /// The eye as a homogeneous model-space point `(e, ew)`, `ew ≥ 0`
    /// (`ew = 0`: orthographic, `e` points towards the viewer), and the sign
    /// (±1) that turns a normal into one the screen culls when it faces
    /// away from the eye: −1 where the matrix mirrors ([`eye_point`]);
    /// `None`: no cone test.
    eye: Option<(Vec3<f32>, f32, f32)>,
}

impl ClusterCull {
    /// The tests for a model-view-projection matrix given by its rows in
    /// `f32` ([`rows_f32`](super::super::rows_f32)).
    pub(super) fn new<T: Scalar>(rows: [Vec4<f32>; 4], far: bool, band: &Band<T>, cone: bool) -> Self {
        let [x, y, _, w] = rows;
        let mut planes = [(Vec4::new(0.0, 0.0, 0.0, 0.0), 0.0); 8];
        let mut count = 0;
        let mut add = |p: Vec4<f32>| {
            planes[count] = (p, p.xyz().length() * (1.0 + CULL_SLACK));
            count += 1;
        };
        // The slab first: it rejects most clusters of a band.
        if let Some(k) = band.above {
            add(w * k.to_f32() - y);
        }
        if let Some(k) = band.below {
            add(y - w * k.to_f32());
        }
        let slab = usize::from(band.above.is_some()) + usize::from(band.below.is_some());
        for p in view_planes(rows, far) {
            add(p);
        }
        ClusterCull { planes, count, slab, eye: if cone { eye_point(x, y, w) } else { None } }
    }

    /// Counts and drops a cluster that certainly has no triangle in the band
    /// facing the eye.
    #[inline]
    pub(super) fn keeps(&self, m: &Meshlet, stats: &mut MeshStats) -> bool {
        if !self.slab_keeps(m) || !self.view_keeps(m) {
            stats.clusters_outside += 1;
            return false;
        }
        let away = self.faces_away(m);
        stats.clusters_back_facing += away as u32;
        !away
    }

    /// False if the cluster's sphere lies beyond one of `planes`.
    #[inline]
    fn within(planes: &[(Vec4<f32>, f32)], (c, r): ([f32; 3], f32)) -> bool {
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        // Written as the rejection, so that NaN keeps the cluster.
        !planes.iter().any(|(p, len)| p.dot(centre) < -(r * *len + CULL_SLACK))
    }

    /// The band's part of [`ClusterCull::keeps`]: false if the cluster lies
    /// wholly above or below the band.
    #[inline]
    pub(crate) fn slab_keeps(&self, m: &Meshlet) -> bool {
        Self::within(&self.planes[..self.slab], m.sphere)
    }

    /// The view volume's part of [`ClusterCull::keeps`] (the same for every
    /// band).
    #[inline]
    pub(crate) fn view_keeps(&self, m: &Meshlet) -> bool {
        Self::within(&self.planes[self.slab..self.count], m.sphere)
    }

    /// The cone's part of [`ClusterCull::keeps`]: true if every triangle of
    /// the cluster is one the screen culls (the same for every band): faces
    /// away from the eye, or towards it where the matrix mirrors.
    #[inline]
    pub(crate) fn faces_away(&self, m: &Meshlet) -> bool {
        let ((c, r), (axis, cutoff)) = (m.sphere, m.cone);
        match self.eye {
            Some((e, ew, sign)) if cutoff < 1.0 => {
                faces_away(Vec3::from_f32(c), r, axis.map(|a| a * sign), cutoff, e, ew)
            }
            _ => false,
        }
    }
}

/// The cone test of [`MeshletMesh`](crate::mesh::MeshletMesh): `axis · v >
/// cutoff · |v| + r · ew · (1 + cutoff)` with `v = c · ew − e`, with a
/// slack of `2^-6` relative to `|v|` and to the right-hand side (`f32`
/// rounding is far below it).
fn faces_away(c: Vec3<f32>, r: f32, axis: [f32; 3], cutoff: f32, e: Vec3<f32>, ew: f32) -> bool {
    const SLACK: f32 = 1.0 / 64.0;
    let v = c * ew - e;
    let len = v.length();
    if !(len > 0.0 && len.is_finite()) {
        return false;
    }
    Vec3::from_f32(axis).dot(v) - (cutoff + SLACK) * len > r * ew * (1.0 + cutoff) * (1.0 + SLACK)
}

/// The centre of projection in model space: the homogeneous point `E` with
/// clip `x = y = w = 0`, the 4D cross product of those rows, scaled so that
/// its largest component is 1, with `ew ≥ 0`; and the sign that orients the
/// cone test as the screen orients triangles. `None` if the rows are
/// degenerate.
///
/// # Why the sign comes from the rows
/// A triangle of model points `v_i` with winding normal
/// `n = (v1 − v0) × (v2 − v0)` lands on screen (y down) with twice the
/// signed area `−det[X_i, Y_i, W_i] / (W0·W1·W2)` (times the viewport's
/// positive scales), and by the Cauchy–Binet formula
/// `det[X_i, Y_i, W_i] = −n · (v0·Ew − Ee)` for `(Ee, Ew)` the cofactors
/// below. With every `W_i > 0` (what the clipper leaves), the screen culls
/// it (`Cull::Clockwise`: area above 0) exactly when `n · (v0·ew − e) > 0`
/// for `(e, ew) = (Ee, Ew)`, which is [`faces_away`]'s test. Scaled to
/// `ew ≥ 0`, a negative `Ew` flips the normals' sense (sign −1): a matrix
/// that mirrors (a model matrix of negative determinant, a mirroring view
/// or projection) shows the faces away from the eye counter-clockwise. An
/// earlier version signed `E` by the depth row instead, which agrees with
/// the rows for an ordinary camera only: with a mirror, the cones rejected
/// clusters the screen keeps (found by the `closed` fuzz target).
fn eye_point(a: Vec4<f32>, b: Vec4<f32>, c: Vec4<f32>) -> Option<(Vec3<f32>, f32, f32)> {
    let (a, b, c) = ([a.x, a.y, a.z, a.w], [b.x, b.y, b.z, b.w], [c.x, c.y, c.z, c.w]);
    let det3 = |i: usize, j: usize, k: usize| {
        a[i] * (b[j] * c[k] - b[k] * c[j]) - a[j] * (b[i] * c[k] - b[k] * c[i])
            + a[k] * (b[i] * c[j] - b[j] * c[i])
    };
    let e = [det3(1, 2, 3), -det3(0, 2, 3), det3(0, 1, 3), -det3(0, 1, 2)];
    let sign = if e[3] < 0.0 { -1.0 } else { 1.0 };
    let m = e.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let e = e.map(|v| v * sign / m);
    Some((Vec3::new(e[0], e[1], e[2]), e[3], sign))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift in [-1, 1).
    fn rng(seed: &mut u64) -> f64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    fn unit(v: [f64; 3]) -> [f64; 3] {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|x| x / l)
    }

    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// Whenever the cone test rejects, every normal in the cone faces away
    /// from every point of the sphere, in f64, for eyes at finite points and
    /// at infinity.
    #[test]
    fn cone_test_rejects_only_clusters_facing_away() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let (mut rejected, mut cases) = ([0u32; 1], 0u32);
        for i in 0..40_000 {
            let axis = unit([0; 3].map(|_| rng(&mut seed)));
            let alpha = (rng(&mut seed) + 1.0) * 0.75; // up to 86°
            let cutoff = alpha.sin();
            let c = [0; 3].map(|_| rng(&mut seed) * 4.0);
            let r = (rng(&mut seed) + 1.0) * 0.3;
            let ew = if i % 4 == 0 { 0.0 } else { 1.0 };
            let e = if ew == 0.0 {
                unit([0; 3].map(|_| rng(&mut seed)))
            } else {
                [0; 3].map(|_| rng(&mut seed) * 8.0)
            };
            let f = |v: [f64; 3]| v.map(|x| x as f32);
            let verdict = [faces_away(
                Vec3::from_f32(f(c)),
                r as f32,
                f(axis),
                cutoff as f32,
                Vec3::from_f32(f(e)),
                ew as f32,
            )];
            cases += 1;
            for (k, &away) in verdict.iter().enumerate() {
                if !away {
                    continue;
                }
                rejected[k] += 1;
                // Extreme normals of the cone and points of the sphere.
                for _ in 0..64 {
                    let q = unit([0; 3].map(|_| rng(&mut seed)));
                    let perp = unit([0, 1, 2].map(|j| q[j] - dot(q, axis) * axis[j]));
                    let n = [0, 1, 2].map(|j| axis[j] * alpha.cos() + perp[j] * alpha.sin());
                    let d = unit([0; 3].map(|_| rng(&mut seed)));
                    let p = [0, 1, 2].map(|j| c[j] + d[j] * r);
                    let v = if ew == 0.0 { e.map(|x| -x) } else { [0, 1, 2].map(|j| p[j] - e[j]) };
                    assert!(dot(n, v) > 0.0, "case {i} path {k}: a normal faces the eye");
                }
            }
        }
        // The test is not vacuous: it rejects a good share.
        assert!(rejected.iter().all(|&r| r > cases / 10), "{rejected:?} of {cases}");
    }
}
