//! Lighting in model space: when the model-view matrix is a
//! similarity (a rotation times a uniform scale, plus a translation), the
//! light's direction and the eye are carried into model space once per
//! mesh, and each vertex is lit with its model normal and position: no
//! normal matrix, no model-view product, no normalised eye-space normal;
//! for `f32` the Blinn–Phong half vector's two normalisations become two
//! reciprocal square roots, or one and a division for an even exponent
//! (`Fx` keeps its two table unit vectors).
//!
//! # Same lighting
//! With `MV = s·R` (`R` a rotation) and translation `t`, the eye-space
//! normal is `normalize(R·n) = R·n̂` and the eye-space position `s·R·p + t`;
//! so `n_eye · L = n̂ · L_m` with `L_m = Rᵀ·L`, and the direction to the
//! viewer is `R` applied to `normalize(E_m − p)` with `E_m = −Rᵀ·t/s`, the
//! eye in model space. The half vector's dot product is then `n̂ · h =
//! (n̂·L_m + n̂·v̂)/√(|L_m|² + 2·L_m·v̂ + 1)` with `v̂ = (E_m − p)/|E_m − p|`,
//! which needs `1/|E_m − p|` and one more reciprocal square root instead of
//! two normalised vectors; for an even exponent `e`, `(n̂·h)^e` is the
//! square `(n̂·L_m + n̂·v̂)²/(|L_m|² + 2·L_m·v̂ + 1)` raised to `e/2`, so
//! that second root becomes one division. In exact arithmetic this is the eye-space
//! [`Lighting::shade`]; in `f32` the two differ by rounding: each rounded
//! value here is within a few units of `2^-24` relative of its exact value
//! (the reciprocal square roots within `5·2^-24`, as
//! [`unit_f32`](crate::math::unit)), and the similarity is accepted within
//! `2^-16` (below), so a lit intensity moves by at most about `2^-15` of
//! full scale: a channel can differ by one where the exact value lies that
//! close to a rounding tie. Normals of length within `2^-12` of 1 are used
//! as they are (a relative error of at most `2^-13`), others normalised.
//!
//! With the viewer at infinity ([`Viewer::Infinite`]) the half vector is
//! one eye-space vector `h`, carried into model space as `Rᵀ·h` once per
//! mesh like the light: the specular term is then one dot product, the
//! same value up to the same rounding.
//!
//! `Fx`: the same formula in 16.16 (each product rounds at `2^-16`), with
//! the eye within `2^13` of the model's origin (else eye space); the test
//! bounds it against `f64` by `(4·e + 8)·2^-16` for exponent `e`.
//!
//! The similarity test: the Gram matrix `G = MVᵀ·MV` (3×3) must be `s²·I`
//! to within `2^-16·s²` per entry (`Fx`: plus `2^-12·s`, its entries'
//! rounding). Otherwise (a non-uniform scale, a shear) lighting stays in
//! eye space.

use super::tier::Tier;
use crate::light::{Lighting, Viewer, positive, powi};
use crate::math::unit::{in_rsqrt_domain, rsqrt_f32, rsqrt_f32_fast, unit_f32};
use crate::math::{Mat4, Scalar, Vec3};

/// Per mesh: the lighting carried into model space (module docs), in the
/// pipeline's numeric type.
#[derive(Clone, Copy, Debug)]
pub(super) struct ModelLight<T> {
    /// The light's direction in model space (`Rᵀ·L`, as long as `L`).
    l: Vec3<T>,
    /// `|l|² + 1`.
    l2_plus_1: T,
    /// The eye in model space.
    eye: Vec3<T>,
    /// The half vector in model space (`Rᵀ·h`, unit) of a viewer at
    /// infinity; `None` for a viewer at the eye.
    half: Option<Vec3<T>>,
    ambient: T,
    diffuse: T,
    specular: Option<(T, u32)>,
    /// The fast tier's `(n̂·h)²` below which the specular term is under
    /// [`FAST_SPEC_FLOOR`] and is left out; 0 in the exact tier (never).
    spec_floor: T,
}

/// The largest specular term the fast tier leaves out: `2^-13` of full
/// intensity, an eighth of a 6-bit channel's step.
pub(super) const FAST_SPEC_FLOOR: f32 = 1.0 / 8192.0;

impl<T: Scalar> ModelLight<T> {
    /// The model-space lighting of `lighting` for model-view `mv`, or `None`
    /// when `mv` is not a similarity (or not finite).
    pub(super) fn new(lighting: &Lighting<T>, mv: &Mat4<T>, fast: bool) -> Option<Self> {
        let col =
            |c: usize| Vec3::new(mv.cols[c][0].to_f32(), mv.cols[c][1].to_f32(), mv.cols[c][2].to_f32());
        let (c0, c1, c2, t) = (col(0), col(1), col(2), col(3));
        let s2 = (c0.dot(c0) + c1.dot(c1) + c2.dot(c2)) / 3.0;
        if !(s2 > 1e-30 && s2 < 1e30) {
            return None;
        }
        // Fx entries are rounded to 2^-16 (absolute): the Gram entries of an
        // exact similarity are then off by about 2^-14·s, which is allowed.
        let fx_slack = if crate::math::vec::is_float::<T>() {
            0.0
        } else {
            crate::math::scalar::sqrt_f32(s2) * (1.0 / 4096.0)
        };
        let tol = s2 * (1.0 / 65536.0) + fx_slack;
        let gram = [c0.dot(c0) - s2, c1.dot(c1) - s2, c2.dot(c2) - s2, c0.dot(c1), c0.dot(c2), c1.dot(c2)];
        if !gram.iter().all(|g| g.abs() <= tol) || !t.dot(t).is_finite() {
            return None;
        }
        let s = crate::math::scalar::sqrt_f32(s2);
        let d = in_f32(lighting.direction);
        // Mᵀ·v: the dot products of v with the columns.
        let mt = |v: Vec3<f32>| Vec3::new(c0.dot(v), c1.dot(v), c2.dot(v));
        let l = mt(d) * (1.0 / s);
        let eye = mt(t) * (-1.0 / s2);
        let l2_plus_1 = l.dot(l) + 1.0;
        // The infinite viewer's half vector, zero for a light towards −z
        // (as `Lighting::infinite_half`), in f32 for both types.
        let half = (lighting.viewer == Viewer::Infinite)
            .then(|| mt(unit_f32(d + Vec3::new(0.0, 0.0, 1.0))) * (1.0 / s));
        let finite = [l2_plus_1, eye.x, eye.y, eye.z];
        if !finite.iter().all(|v| v.is_finite()) {
            return None;
        }
        // Fx: an eye beyond a quarter of its range would saturate `eye − p`.
        if !crate::math::vec::is_float::<T>() && [eye.x, eye.y, eye.z].iter().any(|v| v.abs() > 8192.0) {
            return None;
        }
        let t = |v: Vec3<f32>| Vec3::new(T::from_f32(v.x), T::from_f32(v.y), T::from_f32(v.z));
        Some(ModelLight {
            l: t(l),
            l2_plus_1: T::from_f32(l2_plus_1),
            eye: t(eye),
            half: half.map(t),
            ambient: lighting.ambient,
            diffuse: lighting.diffuse,
            specular: lighting.specular,
            spec_floor: match lighting.specular {
                Some(s) if fast => spec_floor(s),
                _ => T::ZERO,
            },
        })
    }

    /// The colour factors of material `base` at model position `p` with
    /// model normal `n` (module docs; the eye-space [`Lighting::shade`]).
    /// Inlined into the vertex stage (sixth pass: f32 knot −0.5 %).
    #[inline(always)]
    pub(super) fn shade<R: Tier>(&self, n: [f32; 3], p: Vec3<T>, base: [T; 3]) -> [T; 3] {
        let mut n = Vec3::<T>::from_f32(n);
        // |n·n − 1| ≤ 2^-12 (NaN fails it): for `Fx` in 16.16, exactly as
        // in `f32` (its values below 2^8 convert exactly), without the
        // conversion and the float compares, library calls on the Cortex-M0.
        let nn = n.dot(n);
        let unit = if crate::math::vec::is_float::<T>() {
            ((1.0 - 1.0 / 4096.0)..=(1.0 + 1.0 / 4096.0)).contains(&nn.to_f32())
        } else {
            (nn - T::ONE).abs() <= T::from_f32(1.0 / 4096.0)
        };
        if !unit {
            n = n.normalize_fast();
        }
        let nl = n.dot(self.l);
        let lambert = positive(nl);
        let k = self.ambient + self.diffuse * lambert;
        let spec = match self.specular {
            Some((strength, exp)) if lambert > T::ZERO => {
                let power = match self.half {
                    Some(h) => {
                        let nh = positive(n.dot(h));
                        if R::FAST && nh * nh < self.spec_floor { T::ZERO } else { powi(nh, exp) }
                    }
                    None => self.half_power::<R>(n, nl, p, exp),
                };
                strength * power
            }
            _ => T::ZERO,
        };
        base.map(|b| b * k + spec)
    }

    /// `max(0, n̂ · h)^exp` for the Blinn–Phong half vector `h` at `p`.
    ///
    /// For `f32` and an even `exp`: the square `(n̂·h)² = (n̂·L_m +
    /// n̂·v̂)²/(|L_m|² + 2·L_m·v̂ + 1)` (module docs) raised to `exp/2`, one
    /// division where the root form takes a reciprocal square root (an
    /// estimate and three Newton steps, about 19 instructions on the
    /// Cortex-M4F, against one `VDIV` of 14 cycles). Error: the sums'
    /// rounding enters both forms alike; squaring and dividing add `2·2^-24`
    /// relative to the square, where the root (`5·2^-24`) and its product
    /// added `2·6·2^-24`, so the module docs' bound holds (tested against
    /// `f64` with an even and an odd exponent).
    ///
    /// Otherwise (`Fx`, or an odd `exp`): [`ModelLight::half_dot`] to the
    /// power `exp`.
    ///
    /// The fast tier: `v̂` by [`rsqrt_f32_fast`], an odd exponent by one
    /// more fast root, and a term whose `(n̂·h)²` lies below `spec_floor`
    /// left out before the division and the power.
    #[inline(always)]
    fn half_power<R: Tier>(&self, n: Vec3<T>, nl: T, p: Vec3<T>, exp: u32) -> T {
        if crate::math::vec::is_float::<T>() && (exp & 1 == 0 || R::FAST) {
            if let Some((x, h2)) = self.half_terms_f32::<R>(n, nl, p) {
                let floor = self.spec_floor.to_f32();
                if R::FAST && !(x > 0.0 && x * x >= floor * h2 && in_rsqrt_domain(h2)) {
                    // Below the floor (or no half vector): under FAST_SPEC_FLOOR.
                    return if exp == 0 { T::ONE } else { T::ZERO };
                }
                if exp & 1 == 1 {
                    return powi(T::from_f32(x * rsqrt_f32_fast(h2).unwrap_or(0.0)), exp);
                }
                // Outside rsqrt_f32's domain the root form gave 0 too (h = 0:
                // the viewer exactly against the light).
                let q = if x > 0.0 && in_rsqrt_domain(h2) { x * x / h2 } else { 0.0 };
                return powi(T::from_f32(q), exp / 2);
            }
        }
        let nh = self.half_dot(n, nl, p);
        if R::FAST && nh * nh < self.spec_floor { T::ZERO } else { powi(nh, exp) }
    }

    /// `max(0, n̂ · h)` for the Blinn–Phong half vector `h` at `p`: for
    /// `f32` by two reciprocal square roots, for `Fx` (whose unit vectors
    /// come from a table, [`Vec3::normalize_fast`]) by two unit vectors.
    fn half_dot(&self, n: Vec3<T>, nl: T, p: Vec3<T>) -> T {
        let nh = if crate::math::vec::is_float::<T>() {
            let nh = match self.half_terms_f32::<super::tier::ExactTier>(n, nl, p) {
                Some((x, h2)) => match rsqrt_f32(h2) {
                    Some(rh) => x * rh,
                    None => 0.0, // h = 0: the viewer exactly against the light
                },
                // The vertex at the eye, or out of range: the vectors themselves.
                None => {
                    let (n, d, l) = (in_f32(n), in_f32(self.eye - p), in_f32(self.l));
                    n.dot(unit_f32(l + unit_f32(d)))
                }
            };
            T::from_f32(nh)
        } else {
            n.dot((self.l + (self.eye - p).normalize_fast()).normalize_fast())
        };
        positive(nh)
    }

    /// In `f32`, `n̂·h·|h| = n̂·L_m + n̂·v̂` and `|h|² = |L_m|² + 2·L_m·v̂ + 1`
    /// (module docs) at `p`, with `v̂` from one reciprocal square root; `None`
    /// where `|E_m − p|²` is outside [`rsqrt_f32`]'s domain.
    /// The fast tier's root is [`rsqrt_f32_fast`].
    #[inline(always)]
    fn half_terms_f32<R: Tier>(&self, n: Vec3<T>, nl: T, p: Vec3<T>) -> Option<(f32, f32)> {
        let (n, d, l) = (in_f32(n), in_f32(self.eye - p), in_f32(self.l));
        let r = if R::FAST { rsqrt_f32_fast(d.dot(d)) } else { rsqrt_f32(d.dot(d)) }?;
        let (nv, lv) = (n.dot(d) * r, l.dot(d) * r);
        Some((nl.to_f32() + nv, self.l2_plus_1.to_f32() + 2.0 * lv))
    }
}

/// The fast tier's `spec_floor` for specular `(strength, exp)`: a `q =
/// (n̂·h)²` (by bisection to `2^-14`, once per mesh) with
/// `|strength|·q^(exp/2)` below half of `FAST_SPEC_FLOOR`, so every term
/// left out below it is under that floor. 1 when every term is.
fn spec_floor<T: Scalar>((strength, exp): (T, u32)) -> T {
    let (s, eps) = (strength.abs(), T::from_f32(FAST_SPEC_FLOOR * 0.5));
    // s·(√q)^exp from q: its squares, and √q for an odd exponent.
    let term = |q: T| s * powi(q, exp / 2) * if exp & 1 == 1 { q.sqrt() } else { T::ONE };
    let (mut lo, mut hi) = (T::ZERO, T::ONE);
    if term(hi) < eps {
        return hi;
    }
    for _ in 0..14 {
        let mid = (lo + hi) * T::from_f32(0.5);
        if term(mid) < eps { lo = mid } else { hi = mid }
    }
    lo
}

/// `v`'s components as `f32`, each as [`Scalar::to_f32`] gives it (exact
/// for `f32`, and for `Fx` below 2^8 in magnitude; else rounded to nearest).
#[inline(always)]
fn in_f32<T: Scalar>(v: Vec3<T>) -> Vec3<f32> {
    Vec3::from_f32(v.to_f32())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Fx, transform};

    /// Model-space lighting agrees with eye-space lighting (both against an
    /// f64 evaluation) within the bound of the module docs, over random
    /// rotations, scales, translations, normals and positions; shears are
    /// refused.
    #[test]
    fn model_space_is_eye_space() {
        model_space_is_eye_space_for(Viewer::Local, 24);
    }

    /// The same with an odd exponent: the `f32` half vector through its
    /// second reciprocal square root, not the square (`half_power`).
    #[test]
    fn model_space_is_eye_space_odd_exponent() {
        model_space_is_eye_space_for(Viewer::Local, 25);
    }

    /// The same with the viewer at infinity (one half vector per mesh).
    #[test]
    fn model_space_is_eye_space_infinite_viewer() {
        model_space_is_eye_space_for(Viewer::Infinite, 24);
    }

    fn model_space_is_eye_space_for(viewer: Viewer, exp: u32) {
        let mut rng = crate::math::vec::tests::Rng(0x0DE1_5EED);
        let mut rnd = || (rng.next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
        let light = Lighting::<f32>::new(0.15, Vec3::new(0.3, 0.8, 0.5), 0.7)
            .with_specular(0.6, exp)
            .with_viewer(viewer);
        let light_fx =
            Lighting::<Fx>::new(Fx::from_f32(0.15), Vec3::from_f32([0.3, 0.8, 0.5]), Fx::from_f32(0.7))
                .with_specular(Fx::from_f32(0.6), exp)
                .with_viewer(viewer);
        let (mut worst, mut worst_fx) = (0.0f64, 0.0f64);
        let mut n_spec = 0;
        for _ in 0..2_000 {
            let (a, b, c) = (rnd() as f32 * 3.0, rnd() as f32 * 3.0, rnd() as f32 * 3.0);
            let s = (rnd() as f32 + 1.5) * 2.0;
            let m = transform::translation(Vec3::new(rnd() as f32, rnd() as f32, rnd() as f32 * 2.0 - 6.0))
                * transform::rotation_x(a)
                * transform::rotation_y(b)
                * transform::rotation_z(c)
                * transform::scaling(Vec3::new(s, s, s));
            let ml = ModelLight::new(&light, &m, false).expect("a similarity");
            let m_fx = Mat4 { cols: m.cols.map(|c| c.map(Fx::from_f32)) };
            let ml_fx = ModelLight::new(&light_fx, &m_fx, false).expect("a similarity in Fx");
            for _ in 0..20 {
                let n = [rnd(), rnd(), rnd()];
                let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                let n = n.map(|v| (v / len) as f32);
                let p = Vec3::new(rnd() as f32 * 0.5, rnd() as f32 * 0.5, rnd() as f32 * 0.5);
                let got = ml.shade::<super::super::tier::ExactTier>(n, p, [1.0, 0.5, 0.25]);
                let got_fx = ml_fx.shade::<super::super::tier::ExactTier>(
                    n,
                    Vec3::from_f32([p.x, p.y, p.z]),
                    [Fx::ONE, Fx::from_f32(0.5), Fx::from_f32(0.25)],
                );
                // f64 eye space.
                let mf = |r: usize, v: [f64; 4]| (0..4).map(|k| f64::from(m.cols[k][r]) * v[k]).sum::<f64>();
                let pe = [0, 1, 2].map(|r| mf(r, [f64::from(p.x), f64::from(p.y), f64::from(p.z), 1.0]));
                let ne = [0, 1, 2].map(|r| mf(r, [f64::from(n[0]), f64::from(n[1]), f64::from(n[2]), 0.0]));
                let unit = |v: [f64; 3]| {
                    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                    v.map(|x| x / l)
                };
                let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
                let ne = unit(ne);
                let l = [light.direction.x, light.direction.y, light.direction.z].map(f64::from);
                let lam = dot(ne, l).max(0.0);
                let v = match viewer {
                    Viewer::Local => unit(pe.map(|x| -x)),
                    Viewer::Infinite => [0.0, 0.0, 1.0],
                };
                let h = unit([0, 1, 2].map(|i| l[i] + v[i]));
                let spec = if lam > 0.0 { 0.6 * dot(ne, h).max(0.0).powi(exp as i32) } else { 0.0 };
                n_spec += usize::from(spec > 0.01);
                let want = [1.0, 0.5, 0.25].map(|b: f64| b * (0.15 + 0.7 * lam) + spec);
                for k in 0..3 {
                    worst = worst.max((f64::from(got[k]) - want[k]).abs());
                    worst_fx = worst_fx.max((f64::from(got_fx[k].to_f32()) - want[k]).abs());
                }
                let eye = light.shade(
                    Vec3::new(ne[0] as f32, ne[1] as f32, ne[2] as f32),
                    Vec3::new(pe[0] as f32, pe[1] as f32, pe[2] as f32),
                    [1.0, 0.5, 0.25],
                );
                for k in 0..3 {
                    assert!((eye[k] - got[k]).abs() < 2e-5, "{eye:?} vs {got:?}");
                }
            }
        }
        assert!(worst < 2f64.powi(-15), "{worst:e}");
        assert!(n_spec > 1000, "{n_spec}");
        // Fx: the half vector comes from two table unit vectors (within 2^-16
        // per component, so n·h within 4·2^-16 with its products), and the
        // exponent multiplies that error: (e·4 + 8)·2^-16 in all.
        let bound_fx = f64::from(exp * 4 + 8) / 65536.0;
        assert!(worst_fx < bound_fx && worst_fx > 2f64.powi(-16), "{worst_fx:e}");
        // A shear or a non-uniform scale keeps eye-space lighting.
        assert!(ModelLight::new(&light, &transform::scaling(Vec3::new(1.0, 1.1, 1.0)), false).is_none());
        let mut shear = Mat4::<f32>::IDENTITY;
        shear.cols[1][0] = 0.01;
        assert!(ModelLight::new(&light, &shear, false).is_none());
    }
}
