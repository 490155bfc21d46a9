//! f64 references for the transform tests, each with an error bound derived
//! from how the path computes it (see `Path` and `Tr` in mat.rs).

use super::*;
use crate::math::mat::tests::{F32, M64, Path, Tr, inv_t64};
use crate::math::vec::tests::{Exact, Rng};

pub(super) fn rows(r: [[f64; 4]; 4]) -> M64 {
    core::array::from_fn(|c| core::array::from_fn(|i| r[i][c]))
}
pub(super) fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}
pub(super) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
pub(super) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub(super) fn unit(a: [f64; 3]) -> [f64; 3] {
    a.map(|x| x / norm(a))
}
const SQ3: f64 = 1.732_050_808_0;

/// A rotation about axis `k` by `a`, each sin/cos entry off by ≤ sc + q.
pub(super) fn rot64(k: usize, a: f32, p: &Path) -> Tr {
    let (s, c) = f64::from(a).sin_cos();
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let mut t = Tr {
        v: rows([[1., 0., 0., 0.], [0., 1., 0., 0.], [0., 0., 1., 0.], [0., 0., 0., 1.]]),
        e: [[0.0; 4]; 4],
    };
    (t.v[i][i], t.v[i][j], t.v[j][i], t.v[j][j]) = (c, s, -s, c);
    for (x, y) in [(i, i), (i, j), (j, i), (j, j)] {
        t.e[x][y] = p.sc + p.q;
    }
    t
}

/// `T·Ry·Rx·Rz·S` from `f32` parameters: the input of both paths.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Model {
    pub(crate) t: [f32; 3],
    pub(crate) angles: [f32; 3],
    pub(crate) s: [f32; 3],
}
impl Model {
    pub(crate) fn random(rng: &mut Rng, t: f64, s_lo: f64, s_hi: f64) -> Self {
        let pi = core::f64::consts::PI;
        let (a, b, c) = (rng.range(-pi, pi), rng.range(-pi, pi), rng.range(-pi, pi));
        let s = [rng.range(s_lo, s_hi), rng.range(s_lo, s_hi), rng.range(s_lo, s_hi)];
        Model { t: rng.vec3(t), angles: [a, b, c], s }
    }
    pub(crate) fn build<T: Scalar>(&self) -> Mat4<T> {
        let [a, b, c] = self.angles.map(T::from_f32);
        translation(Vec3::from_f32(self.t))
            * rotation_y(a)
            * rotation_x(b)
            * rotation_z(c)
            * scaling(Vec3::from_f32(self.s))
    }
    /// The f64 matrix and the error bound of `build` on path `p`, with the
    /// translation taken relative to `origin` (also quantised, if not 0).
    pub(crate) fn reference(&self, origin: [f32; 3], p: &Path) -> Tr {
        let (mut t, mut s) = (rot64(0, 0.0, &F32), rot64(0, 0.0, &F32));
        let q = if origin == [0.0; 3] { p.q } else { 2.0 * p.q };
        for (i, (&ti, &oi)) in self.t.iter().zip(&origin).enumerate() {
            (t.v[3][i], t.e[3][i]) = (f64::from(ti) - f64::from(oi), q);
            (s.v[i][i], s.e[i][i]) = (f64::from(self.s[i]), p.q);
        }
        let [a, b, c] = self.angles;
        t.mul(&rot64(1, a, p), p).mul(&rot64(0, b, p), p).mul(&rot64(2, c, p), p).mul(&s, p)
    }
}

/// `look_at` in f64 with a first-order bound on each row's error (2-norm),
/// from: quantised inputs (q), `normalize` (≤ 8 units per component, see
/// vec.rs), cross products of unit vectors (≤ 3 units per component) and
/// |δ(v/|v|)| ≤ |δv|/|v|.
pub(super) fn look_at_ref(eye: [f32; 3], target: [f32; 3], up: [f32; 3], p: &Path) -> Tr {
    let (e, t, up) = (eye.map(f64::from), target.map(f64::from), up.map(f64::from));
    let d = [t[0] - e[0], t[1] - e[1], t[2] - e[2]];
    let (f, c) = (unit(d), cross(unit(d), unit(up)));
    let (s, dn) = (unit(c), norm(d));
    let u = cross(s, f);
    let (na, nc) = (8.0 * SQ3 * (p.abs + p.rel), 3.0 * SQ3 * (p.abs + p.rel));
    let df = SQ3 * (2.0 * p.q + p.rel * dn) / dn + na;
    let dc = df + SQ3 * p.q / norm(up) + na + nc;
    let ds = dc / norm(c) + na;
    let du = ds + df + nc;
    let dt = |dr: f64, r: [f64; 3]| {
        let mag: f64 = (0..3).map(|i| (r[i] * e[i]).abs()).sum();
        dr * norm(e) + SQ3 * p.q + 3.0 * p.abs + 3.01 * p.rel * mag
    };
    Tr {
        v: rows([
            [s[0], s[1], s[2], -dot(s, e)],
            [u[0], u[1], u[2], -dot(u, e)],
            [-f[0], -f[1], -f[2], dot(f, e)],
            [0.0, 0.0, 0.0, 1.0],
        ]),
        e: rows([[ds, ds, ds, dt(ds, s)], [du, du, du, dt(du, u)], [df, df, df, dt(df, f)], [0.0; 4]]),
    }
}

/// `perspective` in f64 with its entries' error bounds (quotient rule).
pub(super) fn perspective_ref(fov: f32, aspect: f32, near: f32, far: f32, p: &Path) -> Tr {
    let (fov, a, n, fr) = (f64::from(fov), f64::from(aspect), f64::from(near), f64::from(far));
    let (s, c) = (fov / 2.0).sin_cos();
    let (f, dsc) = (c / s, p.sc + p.q / 2.0 + p.abs);
    let df = dsc * (1.0 + c / s) / s + p.abs + p.rel * f;
    let dfa = (df + f / a * p.q) / a + p.abs + p.rel * f / a;
    let (dd, aa) = (n - fr, fr / (n - fr));
    let da = (p.q + aa.abs() * (2.0 * p.q + p.rel * dd.abs())) / dd.abs() + p.abs + p.rel * aa.abs();
    let db = aa.abs() * p.q + n * da + p.abs + p.rel * (n * aa).abs();
    Tr {
        v: rows([[f / a, 0., 0., 0.], [0., f, 0., 0.], [0., 0., aa, n * aa], [0., 0., -1., 0.]]),
        e: rows([[dfa, 0., 0., 0.], [0., df, 0., 0.], [0., 0., da, db], [0.; 4]]),
    }
}

/// `V·M` in f64 with its error bound. Computed `V·M` has the translation
/// `R̂·t + (−R̂·eye)`, in which the rotation error cancels to `δR·(t − eye)`:
/// so the bound is `R̂ · (M shifted by −eye)` plus the rounding of the two
/// products `R̂·t` and `R̂·eye` (3u each for Fx, γ3·Σ|r||x| for f32).
pub(super) fn model_view_ref(eye: [f32; 3], target: [f32; 3], up: [f32; 3], m: &Model, p: &Path) -> Tr {
    let mut r = look_at_ref(eye, target, up, p);
    (r.v[3], r.e[3]) = ([0.0, 0.0, 0.0, 1.0], [0.0; 4]);
    let mut mv = r.mul(&m.reference(eye, p), p);
    for i in 0..3 {
        let mag: f64 = (0..3).map(|k| r.v[k][i].abs() * f64::from(m.t[k].abs() + eye[k].abs())).sum();
        mv.e[3][i] += 6.0 * p.abs + 4.01 * p.rel * mag;
    }
    mv
}

pub(super) fn la<T: Scalar>(eye: [f32; 3], target: [f32; 3], up: [f32; 3]) -> Result<Mat4<T>, Error> {
    look_at(Vec3::from_f32(eye), Vec3::from_f32(target), Vec3::from_f32(up))
}

pub(super) fn worst<T: Exact>(m: Mat4<T>, r: &Tr) -> f64 {
    let mut w = 0f64;
    for (k, (c, (rc, ec))) in m.cols.iter().zip(r.v.iter().zip(&r.e)).enumerate() {
        for (x, (rx, ex)) in c.iter().zip(rc.iter().zip(ec)) {
            let d = (x.f64() - rx).abs();
            // The slack covers the f64 reference's own rounding.
            assert!(d <= ex + 1e-12 * (1.0 + rx.abs()), "{} vs {rx}: error {d:e} > {ex:e}", x.f64());
            if k < 3 && *ex > 0.0 {
                w = w.max(d / ex); // linear part: translations are just quantised
            }
        }
    }
    w
}

/// Pixel position of a clip-space point on path `p` with its error bound:
/// the divide's quotient rule, then `(ndc + 1)·W/2` (exact for Fx).
pub(super) fn screen_ref(c: [f64; 4], e: [f64; 4], vp: (f64, f64), p: &Path) -> ([f64; 2], [f64; 2]) {
    let px = |x: f64, ex: f64, half: f64, sign: f64| {
        let n = x / c[3];
        // Once w's bound reaches w the quotient is unbounded: infinity.
        let den = if c[3] > e[3] { c[3] - e[3] } else { 0.0 };
        let dn = (ex + n.abs() * e[3]) / den + p.abs + p.rel * n.abs();
        let v = (1.0 + sign * n) * half;
        (v, half * (dn + p.rel * (1.0 + sign * n).abs()) + p.rel * v.abs())
    };
    let ((x, ex), (y, ey)) = (px(c[0], e[0], vp.0 / 2.0, 1.0), px(c[1], e[1], vp.1 / 2.0, -1.0));
    ([x, y], [ex, ey])
}

/// The look_at inputs the derived bound assumes: |target − eye| ≥ 1, |up| ≥ 1/4
/// and at least 0.1 rad between up and the view direction.
pub(super) fn in_envelope(eye: [f32; 3], target: [f32; 3], up: [f32; 3]) -> bool {
    let d = [0, 1, 2].map(|i| f64::from(target[i]) - f64::from(eye[i]));
    let u = up.map(f64::from);
    norm(d) >= 1.0 && norm(u) >= 0.25 && norm(cross(unit(d), unit(u))) >= 0.1
}

/// `(A⁻ᵀ, bound)` for the upper-left 3×3 of `a`: the first-order perturbation
/// `|N|·|δA|ᵀ·|N|` of the entries' own bound (plus u/s for the Fx halving when
/// s < 1), and the rounding of the cofactors (2 products), the determinant (3)
/// and the quotient, evaluated on the scaled `B = s·A` as the code does.
pub(super) fn inverse_transpose_ref(a: &Tr, p: &Path) -> ([[f64; 3]; 3], [[f64; 3]; 3]) {
    let x = inv_t64(&a.v);
    let mx = (0..3).flat_map(|c| (0..3).map(move |r| a.v[c][r].abs())).fold(0.0, f64::max);
    let mut s = 1.0;
    while mx * s < 1.0 {
        s *= 2.0;
    }
    while mx * s >= 16.0 {
        s /= 2.0;
    }
    let halving = if s < 1.0 { p.abs / s } else { 0.0 };
    let col = |c: usize| [0, 1, 2].map(|r| a.v[c][r] * s);
    let (bx, by, bz) = (col(0), col(1), col(2));
    let cof = [cross(by, bz), cross(bz, bx), cross(bx, by)];
    let dcof = |c: usize, r: usize| {
        let (u, v) = [(by, bz), (bz, bx), (bx, by)][c];
        let (i, j) = ((r + 1) % 3, (r + 2) % 3);
        2.0 * p.abs + 2.01 * p.rel * ((u[i] * v[j]).abs() + (u[j] * v[i]).abs())
    };
    let det = dot(bx, cof[0]);
    let ddet: f64 =
        (0..3).map(|i| bx[i].abs() * dcof(0, i) + p.abs + 3.01 * p.rel * (bx[i] * cof[0][i]).abs()).sum();
    let bound = core::array::from_fn(|c| {
        core::array::from_fn(|r| {
            let pert: f64 = (0..3)
                .flat_map(|i| (0..3).map(move |j| (i, j)))
                .map(|(i, j)| x[i][r].abs() * (a.e[i][j] + halving) * x[c][j].abs())
                .sum();
            let rb = cof[c][r] / det;
            let arith = (dcof(c, r) + rb.abs() * ddet) / det.abs() + p.abs + p.rel * rb.abs();
            pert + s * arith + if s < 1.0 { p.abs } else { 0.0 }
        })
    });
    (x, bound)
}
