//! 3- and 4-component vectors over a [`Scalar`] (`f32` or [`Fx`](super::Fx)).
//!
//! With [`Fx`](super::Fx) every operation saturates instead of overflowing:
//! [`Vec3::dot`] and [`Vec3::cross`] are exact to a few 2^-16 only while the
//! products stay below 32768 (components within ±104 for `dot`, ±128 for
//! `cross`). [`Vec3::length`] and [`Vec3::normalize`] scale by the largest
//! component first, so they work over the whole range: `normalize` is within
//! 8·2^-16 of the true unit vector per component (derivation in the tests),
//! `length` within `6·2^-16·|v| + 2^-16` (saturating at 32768).

use super::Scalar;
use core::ops::{Add, Mul, Neg, Sub};

/// A 3-component vector (a point, direction or normal).
///
/// ```
/// use microraster::math::{Fx, Scalar, Vec3};
/// let a = Vec3::new(1.0f32, 2.0, 2.0);
/// assert_eq!(a.length(), 3.0);
/// assert_eq!(a.cross(Vec3::new(0.0, 0.0, 1.0)), Vec3::new(2.0, -1.0, 0.0));
/// let n = Vec3::<Fx>::from_f32([0.0, 3.0, 4.0]).normalize();
/// assert!((n.to_f32()[2] - 0.8).abs() < 1e-4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec3<T> {
    /// X component.
    pub x: T,
    /// Y component.
    pub y: T,
    /// Z component.
    pub z: T,
}

/// A 4-component vector: homogeneous points (`w = 1`), directions (`w = 0`)
/// and clip-space positions.
///
/// ```
/// use microraster::math::{Vec3, Vec4};
/// let p = Vec3::new(1.0f32, 2.0, 3.0).extend(1.0);
/// assert_eq!(p, Vec4::new(1.0, 2.0, 3.0, 1.0));
/// assert_eq!((p + p).xyz(), Vec3::new(2.0, 4.0, 6.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec4<T> {
    /// X component.
    pub x: T,
    /// Y component.
    pub y: T,
    /// Z component.
    pub z: T,
    /// W component.
    pub w: T,
}

impl<T: Scalar> Vec3<T> {
    /// The zero vector.
    pub const ZERO: Self = Vec3 { x: T::ZERO, y: T::ZERO, z: T::ZERO };

    /// A vector from its components.
    pub const fn new(x: T, y: T, z: T) -> Self {
        Vec3 { x, y, z }
    }

    /// From `f32` components (rounded to nearest and saturating for `Fx`).
    pub fn from_f32(v: [f32; 3]) -> Self {
        Vec3::new(T::from_f32(v[0]), T::from_f32(v[1]), T::from_f32(v[2]))
    }

    /// From components stored as `f32` ([`Vec3::from_f32`]) or
    /// [`Fx`](super::Fx) ([`Scalar::from_fx`]): how the vertex stage reads
    /// a mesh in either type.
    ///
    /// ```
    /// use microraster::math::{Fx, Scalar, Vec3};
    /// let v = Vec3::<Fx>::from_data([0.5f32, -1.0, 2.0]);
    /// assert_eq!(v, Vec3::<Fx>::from_f32([0.5, -1.0, 2.0]));
    /// assert_eq!(Vec3::<f32>::from_data([Fx::from_f32(0.25); 3]), Vec3::new(0.25, 0.25, 0.25));
    /// ```
    #[inline(always)]
    pub fn from_data<P: Scalar>(v: [P; 3]) -> Self {
        P::vec3_to(v)
    }

    /// The components as `f32`.
    pub fn to_f32(self) -> [f32; 3] {
        [self.x.to_f32(), self.y.to_f32(), self.z.to_f32()]
    }

    /// The homogeneous vector `(x, y, z, w)`.
    pub const fn extend(self, w: T) -> Vec4<T> {
        Vec4 { x: self.x, y: self.y, z: self.z, w }
    }

    /// Dot product (saturates for `Fx` once a product or sum passes 32768).
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product, right-handed: `x × y = z`.
    pub fn cross(self, o: Self) -> Self {
        Vec3::new(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }

    /// The largest absolute component (0 for the zero vector).
    pub fn max_abs(self) -> T {
        let (x, y, z) = (self.x.abs(), self.y.abs(), self.z.abs());
        let m = if y > x { y } else { x };
        if z > m { z } else { m }
    }

    /// Euclidean length. Scaled by the largest component first, so it neither
    /// overflows nor loses `Fx` precision on short vectors.
    pub fn length(self) -> T {
        let m = self.max_abs();
        if m == T::ZERO {
            return T::ZERO;
        }
        m * self.scaled_norm_sq(m).sqrt()
    }

    /// The unit vector in the same direction. The zero vector (and, for `f32`,
    /// anything with a NaN) is returned unchanged rather than dividing by zero.
    pub fn normalize(self) -> Self {
        let m = self.max_abs();
        if m == T::ZERO || !m.is_finite() {
            return self;
        }
        let s = self.scaled_norm_sq(m).sqrt();
        // (v/m)/|v/m|: every quotient lies in [-1, 1], the root in [1, √3].
        Vec3::new((self.x / m) / s, (self.y / m) / s, (self.z / m) / s)
    }

    /// The unit vector for shading, without a division or a square root
    /// (a reciprocal square root by Newton steps): for `f32` within
    /// `6·2^-24` of the exact unit vector per component (where the squared
    /// length lies in `[2^-100, 2^100]`; beyond, and for NaN, exactly
    /// [`Vec3::normalize`]); for `Fx` within `2^-16` per component (an eighth
    /// of [`Vec3::normalize`]'s bound) at a quarter of its instructions on
    /// the Cortex-M0. The zero vector is returned unchanged.
    pub fn normalize_fast(self) -> Self {
        T::unit3(self)
    }

    /// `|v/m|²` for `m` the largest component: always within [1, 3].
    fn scaled_norm_sq(self, m: T) -> T {
        let (x, y, z) = (self.x / m, self.y / m, self.z / m);
        x * x + y * y + z * z
    }
}

impl<T: Scalar> Vec4<T> {
    /// The zero vector.
    pub const ZERO: Self = Vec4 { x: T::ZERO, y: T::ZERO, z: T::ZERO, w: T::ZERO };

    /// A vector from its components.
    pub const fn new(x: T, y: T, z: T, w: T) -> Self {
        Vec4 { x, y, z, w }
    }

    /// From `f32` components (rounded to nearest and saturating for `Fx`).
    pub fn from_f32(v: [f32; 4]) -> Self {
        Vec4::new(T::from_f32(v[0]), T::from_f32(v[1]), T::from_f32(v[2]), T::from_f32(v[3]))
    }

    /// The components as `f32`.
    pub fn to_f32(self) -> [f32; 4] {
        [self.x.to_f32(), self.y.to_f32(), self.z.to_f32(), self.w.to_f32()]
    }

    /// The first three components.
    pub const fn xyz(self) -> Vec3<T> {
        Vec3 { x: self.x, y: self.y, z: self.z }
    }

    /// Dot product of all four components.
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y + self.z * o.z + self.w * o.w
    }

    /// The length of the `(x, y, z, w)` vector (scaled like [`Vec3::length`]).
    pub fn length(self) -> T {
        let m = self.xyz().max_abs();
        let m = if self.w.abs() > m { self.w.abs() } else { m };
        if m == T::ZERO {
            return T::ZERO;
        }
        let (x, y, z, w) = (self.x / m, self.y / m, self.z / m, self.w / m);
        m * (x * x + y * y + z * z + w * w).sqrt()
    }

    /// The unit vector in the same 4D direction; zero stays zero.
    pub fn normalize(self) -> Self {
        let l = self.length();
        if l == T::ZERO || !l.is_finite() {
            return self;
        }
        Vec4::new(self.x / l, self.y / l, self.z / l, self.w / l)
    }

    /// True if no component is NaN or infinite (always true for `Fx`).
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite() && self.w.is_finite()
    }
}

/// Whether `T` is the floating-point path (resolves at compile time).
pub(crate) fn is_float<T: Scalar>() -> bool {
    T::from_f32(1.0e-30) != T::ZERO
}

/// True if `v` is NaN, infinite or a saturated `Fx` (an unusable result).
pub(crate) fn at_limit<T: Scalar>(v: T) -> bool {
    !v.is_finite() || v.abs() >= T::from_f32(f32::MAX)
}

macro_rules! vec_ops {
    ($V:ident { $($f:ident),+ }) => {
        impl<T: Scalar> Add for $V<T> {
            type Output = Self;
            fn add(self, o: Self) -> Self {
                $V { $($f: self.$f + o.$f),+ }
            }
        }
        impl<T: Scalar> Sub for $V<T> {
            type Output = Self;
            fn sub(self, o: Self) -> Self {
                $V { $($f: self.$f - o.$f),+ }
            }
        }
        impl<T: Scalar> Neg for $V<T> {
            type Output = Self;
            fn neg(self) -> Self {
                $V { $($f: -self.$f),+ }
            }
        }
        /// Scaling by a scalar.
        impl<T: Scalar> Mul<T> for $V<T> {
            type Output = Self;
            fn mul(self, s: T) -> Self {
                $V { $($f: self.$f * s),+ }
            }
        }
    };
}
vec_ops!(Vec3 { x, y, z });
vec_ops!(Vec4 { x, y, z, w });

#[cfg(test)]
pub(crate) mod tests {
    extern crate std;
    use super::*;
    use crate::math::Fx;
    use std::println;

    /// 2^-16, the `Fx` resolution.
    pub(crate) const U: f64 = 1.0 / 65536.0;

    /// SplitMix64: a small deterministic generator for the random tests.
    pub(crate) struct Rng(pub u64);
    impl Rng {
        pub(crate) fn next(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }
        /// Uniform in `[lo, hi)`, as an `f32` (so both paths get the same input).
        pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f32 {
            (lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64) as f32
        }
        pub(crate) fn vec3(&mut self, r: f64) -> [f32; 3] {
            [self.range(-r, r), self.range(-r, r), self.range(-r, r)]
        }
    }

    /// Exact conversion to `f64` for the references (`to_f32` rounds large `Fx`).
    pub(crate) trait Exact: Scalar {
        fn f64(self) -> f64;
    }
    impl Exact for f32 {
        fn f64(self) -> f64 {
            f64::from(self)
        }
    }
    impl Exact for Fx {
        fn f64(self) -> f64 {
            f64::from(self.to_bits()) * U
        }
    }
    fn fx64(v: Fx) -> f64 {
        v.f64()
    }

    #[test]
    fn normalize_and_length_against_f64() {
        // Fx bound per component, from the operation count in `normalize`: the
        // quotients v/m are off by < u; each square adds 2|q|u + u ≤ 3u, so the
        // sum of squares (in [1,3]) by ≤ 9u and its root by ≤ 9u/2 + u; the final
        // division adds u/s + |q|·5.5u/s² + u ≤ 7.5u. Stated bound: 8u.
        // f32: about 6 roundings of relative 2^-24 each: bound 8·2^-24.
        let mut rng = Rng(1);
        let (mut worst_fx, mut worst_f32, mut worst_len, mut n) = (0f64, 0f64, 0f64, 0);
        for i in 0..100_000 {
            let r = [1e-2, 1.0, 100.0, 10_000.0][i % 4];
            let v = rng.vec3(r);
            let fx = Vec3::<Fx>::from_f32(v);
            let e = [fx64(fx.x), fx64(fx.y), fx64(fx.z)]; // exact Fx input
            let len = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
            if len == 0.0 {
                continue;
            }
            let nf = fx.normalize();
            for (c, t) in [nf.x, nf.y, nf.z].into_iter().zip(e) {
                worst_fx = worst_fx.max((fx64(c) - t / len).abs() / U);
            }
            // |v| = m·√q: the root's relative error ≤ 5.5u, then one truncation (< u).
            worst_len = worst_len.max(((fx64(fx.length()) - len).abs() - U).max(0.0) / (len * U));
            let vf = Vec3::new(v[0], v[1], v[2]);
            let lf = vf.iter_f64().map(|c| c * c).sum::<f64>().sqrt();
            let nf32 = vf.normalize();
            for (c, t) in nf32.iter_f64().zip(vf.iter_f64()) {
                worst_f32 = worst_f32.max((c - t / lf).abs() / 2f64.powi(-24));
            }
            assert!((f64::from(vf.length()) - lf).abs() <= lf * 8.0 * 2f64.powi(-24));
            n += 1;
        }
        println!(
            "normalize: {n} vectors, Fx worst {worst_fx:.2}u (bound 8u), |v| {worst_len:.2}u·|v| + u \
             (bound 6u·|v| + u), f32 worst {worst_f32:.2}·2^-24 (bound 8)"
        );
        assert!(worst_fx <= 8.0 && worst_len <= 6.0 && worst_f32 <= 8.0);
    }

    impl Vec3<f32> {
        fn iter_f64(self) -> impl Iterator<Item = f64> {
            [self.x, self.y, self.z].into_iter().map(f64::from)
        }
    }

    #[test]
    fn zero_nan_and_saturation_do_not_panic() {
        assert_eq!(Vec3::<f32>::ZERO.normalize(), Vec3::ZERO);
        assert_eq!(Vec3::<Fx>::ZERO.normalize(), Vec3::ZERO);
        assert_eq!(Vec4::<Fx>::ZERO.normalize(), Vec4::ZERO);
        assert!(Vec3::new(f32::NAN, 1.0, 0.0).normalize().x.is_nan());
        let big = Vec3::<Fx>::from_f32([30000.0, -30000.0, 30000.0]);
        assert_eq!(big.length(), Fx::MAX);
        assert!((big.normalize().x.to_f32() - 0.57735).abs() < 1e-4);
        assert_eq!(big.dot(big), Fx::MAX);
        let tiny = Vec3::<Fx>::from_f32([0.0, 3.0 / 65536.0, 4.0 / 65536.0]).normalize();
        assert!((tiny.y.to_f32() - 0.6).abs() < 1e-4 && (tiny.z.to_f32() - 0.8).abs() < 1e-4);
        assert!(at_limit(Fx::MIN) && at_limit(f32::INFINITY) && !at_limit(Fx::ONE));
    }

    #[test]
    fn ops_dot_cross_against_f64() {
        // Components within ±100: Fx products are exact up to one truncation
        // (< u) each and inputs are exact, so dot ≤ 3u and cross ≤ 2u off.
        let mut rng = Rng(2);
        for _ in 0..10_000 {
            let (a, b) = (rng.vec3(100.0), rng.vec3(100.0));
            let (fa, fb) = (Vec3::<Fx>::from_f32(a), Vec3::<Fx>::from_f32(b));
            let ea = [fx64(fa.x), fx64(fa.y), fx64(fa.z)];
            let eb = [fx64(fb.x), fx64(fb.y), fx64(fb.z)];
            let dot = ea[0] * eb[0] + ea[1] * eb[1] + ea[2] * eb[2];
            assert!((fx64(fa.dot(fb)) - dot).abs() <= 3.0 * U);
            let c = fa.cross(fb);
            assert!((fx64(c.y) - (ea[2] * eb[0] - ea[0] * eb[2])).abs() <= 2.0 * U);
            let s = (fa - fb + fa * Fx::ONE + -fb).to_f32();
            let t = Vec3::new(a[0], a[1], a[2]);
            assert!((s[0] - 2.0 * (a[0] - b[0])).abs() < 1e-3 && (t * 2.0f32).x == 2.0 * a[0]);
        }
        let p = Vec4::<f32>::from_f32([3.0, 0.0, 4.0, 0.0]);
        assert_eq!((p.length(), p.normalize().z, p.dot(p)), (5.0, 0.8, 25.0));
        assert_eq!(Vec4::new(1.0, 2.0, 3.0, 4.0) - p * 1.0, -Vec4::new(2.0, -2.0, 1.0, -4.0));
    }
}
