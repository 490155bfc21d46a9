//! 4×4 and 3×3 matrices over a [`Scalar`], **column-major**, for column vectors.
//!
//! `cols[c][r]` is the entry in row `r`, column `c`; a vector is transformed
//! as `M · v`, so transforms compose right to left: `clip = P · V · M · v`
//! applies the model matrix first.
//!
//! # `Fx` accuracy
//!
//! Every entry of a product is a sum of four products, each truncated once
//! (error < 2^-16 = u), so `A · B` is within `4u` of the exact product of the
//! stored entries, and `M · v` within `3u` for points (`w = 1` is exact).
//! Saturation is the hazard: keep every product and partial sum below 32768 in
//! magnitude (the envelope in [`crate::math::transform`] does). Products are
//! not associative in rounding: compose `proj * (view * model)`.

use super::vec::{at_limit, is_float};
use super::{Scalar, Vec3, Vec4};
use core::ops::Mul;

/// A 4×4 matrix, column-major: `cols[c][r]` is row `r` of column `c`.
///
/// ```
/// use microraster::math::{Mat4, Vec3};
/// // A translation by (1, 2, 3), written row by row for readability.
/// let t = Mat4::from_rows([
///     [1.0f32, 0.0, 0.0, 1.0],
///     [0.0, 1.0, 0.0, 2.0],
///     [0.0, 0.0, 1.0, 3.0],
///     [0.0, 0.0, 0.0, 1.0],
/// ]);
/// assert_eq!(t.cols[3], [1.0, 2.0, 3.0, 1.0]);
/// let p = (t * t).transform_point(Vec3::new(0.0, 0.0, 0.0));
/// assert_eq!(p.to_f32(), [2.0, 4.0, 6.0, 1.0]);
/// assert_eq!(t * Mat4::IDENTITY, t);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat4<T> {
    /// The four columns; `cols[3]` holds the translation of an affine matrix.
    pub cols: [[T; 4]; 4],
}

/// A 3×3 matrix, column-major like [`Mat4`]: the linear part of a transform,
/// used for normals.
///
/// ```
/// use microraster::math::{Mat3, Vec3};
/// // Stretching x by 2 squeezes the normals' x by 2: the inverse transpose.
/// let m = Mat3::from_cols([[2.0f32, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
/// let n = m.inverse_transpose().unwrap();
/// assert_eq!(n * Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.5, 1.0, 0.0));
/// assert_eq!(Mat3::<f32>::from_cols([[0.0; 3]; 3]).inverse_transpose(), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat3<T> {
    /// The three columns.
    pub cols: [[T; 3]; 3],
}

impl<T: Scalar> Mat4<T> {
    /// The identity.
    pub const IDENTITY: Self = {
        let (o, z) = (T::ONE, T::ZERO);
        Mat4 { cols: [[o, z, z, z], [z, o, z, z], [z, z, o, z], [z, z, z, o]] }
    };

    /// From columns (`cols[c][r]`).
    pub const fn from_cols(cols: [[T; 4]; 4]) -> Self {
        Mat4 { cols }
    }

    /// From rows (`rows[r][c]`), the order matrices are written in on paper.
    pub fn from_rows(rows: [[T; 4]; 4]) -> Self {
        Mat4 { cols: rows }.transpose()
    }

    /// From `f32` columns (`cols[c][r]`, the layout of [`Mat4::cols`]);
    /// each entry rounds to nearest and, for `Fx`, saturates.
    pub fn from_f32(cols: [[f32; 4]; 4]) -> Self {
        Mat4 { cols: cols.map(|c| c.map(T::from_f32)) }
    }

    /// The columns as `f32`.
    pub fn to_f32(self) -> [[f32; 4]; 4] {
        self.cols.map(|c| c.map(T::to_f32))
    }

    /// The transpose (rows become columns).
    pub fn transpose(self) -> Self {
        let c = self.cols;
        Mat4 { cols: core::array::from_fn(|i| [c[0][i], c[1][i], c[2][i], c[3][i]]) }
    }

    /// `M · v`.
    pub fn transform(self, v: Vec4<T>) -> Vec4<T> {
        let [a, b, c, d] = self.cols;
        let row = |r: usize| a[r] * v.x + b[r] * v.y + c[r] * v.z + d[r] * v.w;
        Vec4::new(row(0), row(1), row(2), row(3))
    }

    /// `M · (p, 1)`: a point, translation included. For a projection matrix
    /// this is the clip-space position.
    pub fn transform_point(self, p: Vec3<T>) -> Vec4<T> {
        self.transform(p.extend(T::ONE))
    }

    /// `M · (v, 0)` without its `w`: a direction, translation ignored.
    pub fn transform_vector(self, v: Vec3<T>) -> Vec3<T> {
        self.transform(v.extend(T::ZERO)).xyz()
    }

    /// The upper-left 3×3 block (the linear part of an affine matrix).
    pub fn upper_left(self) -> Mat3<T> {
        let c = self.cols;
        Mat3 { cols: core::array::from_fn(|i| [c[i][0], c[i][1], c[i][2]]) }
    }

    /// The normal matrix: the inverse transpose of [`Mat4::upper_left`], or
    /// `None` where [`Mat3::inverse_transpose`] gives `None`.
    pub fn normal_matrix(self) -> Option<Mat3<T>> {
        self.upper_left().inverse_transpose()
    }

    /// True if an entry is NaN, infinite or a saturated `Fx`.
    pub(crate) fn any_at_limit(&self) -> bool {
        self.cols.iter().flatten().any(|&v| at_limit(v))
    }
}

impl<T: Scalar> Mul for Mat4<T> {
    type Output = Self;
    /// The product `self · rhs` (apply `rhs` first).
    fn mul(self, rhs: Self) -> Self {
        let col = |c: [T; 4]| {
            let v = self.transform(Vec4::new(c[0], c[1], c[2], c[3]));
            [v.x, v.y, v.z, v.w]
        };
        Mat4 { cols: rhs.cols.map(col) }
    }
}

impl<T: Scalar> Mul<Vec4<T>> for Mat4<T> {
    type Output = Vec4<T>;
    /// `M · v`, like [`Mat4::transform`].
    fn mul(self, v: Vec4<T>) -> Vec4<T> {
        self.transform(v)
    }
}

impl<T: Scalar> Mat3<T> {
    /// The identity.
    pub const IDENTITY: Self = {
        let (o, z) = (T::ONE, T::ZERO);
        Mat3 { cols: [[o, z, z], [z, o, z], [z, z, o]] }
    };

    /// From columns (`cols[c][r]`).
    pub const fn from_cols(cols: [[T; 3]; 3]) -> Self {
        Mat3 { cols }
    }

    /// The transpose.
    pub fn transpose(self) -> Self {
        let c = self.cols;
        Mat3 { cols: core::array::from_fn(|i| [c[0][i], c[1][i], c[2][i]]) }
    }

    /// `M · v`.
    pub fn transform(self, v: Vec3<T>) -> Vec3<T> {
        let [a, b, c] = self.cols;
        let row = |r: usize| a[r] * v.x + b[r] * v.y + c[r] * v.z;
        Vec3::new(row(0), row(1), row(2))
    }

    /// The determinant (saturates for `Fx` once it passes 32768).
    pub fn determinant(self) -> T {
        let [a, b, c] = self.cols.map(|c| Vec3::new(c[0], c[1], c[2]));
        a.dot(b.cross(c))
    }

    /// The inverse transpose `(M⁻¹)ᵀ`, which maps normals of a surface
    /// transformed by `M` (renormalise them afterwards if `M` scales).
    ///
    /// Returns `None` if `M` is singular (determinant 0 after scaling, below),
    /// has a NaN or infinite entry, or if an entry of the result overflows
    /// (saturates, for `Fx`). It never panics.
    ///
    /// The matrix is first scaled by a power of two so that its largest entry
    /// lies in [1, 16): exact for `f32` (it only avoids overflow), and for `Fx`
    /// it keeps small matrices from losing relative precision and large ones
    /// from saturating the determinant. The error grows with the condition
    /// number; for model-view matrices with scale factors in [1/4, 16] the
    /// tests bound it to first order and measured transformed normals within
    /// 4.3·10^-4 rad (`Fx`) and 7·10^-7 rad (`f32`) of their true direction.
    pub fn inverse_transpose(self) -> Option<Self> {
        let mut m = T::ZERO;
        for &v in self.cols.iter().flatten() {
            if !v.is_finite() {
                return None;
            }
            m = if v.abs() > m { v.abs() } else { m };
        }
        // B = s·M with s = 2^k; then M⁻ᵀ = s · B⁻ᵀ.
        let (two, half, sixteen) = (T::ONE + T::ONE, T::from_f32(0.5), T::from_f32(16.0));
        // 2^14 is the largest power of two below the Fx limit; f32 spans 2^±126.
        let max_k = if is_float::<T>() { 126 } else { 14 };
        let (mut s, mut k) = (T::ONE, 0);
        while m > T::ZERO && m < T::ONE && k < max_k {
            (m, s, k) = (m * two, s * two, k + 1);
        }
        while m >= sixteen && k > -126 {
            (m, s, k) = (m * half, s * half, k - 1);
        }
        let [a, b, c] = self.cols.map(|c| Vec3::new(c[0], c[1], c[2]) * s);
        // The columns of B⁻ᵀ are the pairwise cross products over det B.
        let (bc, ca, ab) = (b.cross(c), c.cross(a), a.cross(b));
        let det = a.dot(bc);
        if det == T::ZERO || at_limit(det) {
            return None;
        }
        let col = |v: Vec3<T>| [v.x / det * s, v.y / det * s, v.z / det * s];
        let r = Mat3 { cols: [col(bc), col(ca), col(ab)] };
        if r.cols.iter().flatten().any(|&v| at_limit(v)) { None } else { Some(r) }
    }
}

impl<T: Scalar> Mul<Vec3<T>> for Mat3<T> {
    type Output = Vec3<T>;
    /// `M · v`, like [`Mat3::transform`].
    fn mul(self, v: Vec3<T>) -> Vec3<T> {
        self.transform(v)
    }
}

#[cfg(test)]
pub(crate) mod tests {
    extern crate std;
    use super::*;
    use crate::math::Fx;
    use crate::math::vec::tests::{Exact, Rng, U};
    use std::println;

    /// A column-major f64 matrix, the reference arithmetic.
    pub(crate) type M64 = [[f64; 4]; 4];

    pub(crate) fn m64<T: Exact>(m: Mat4<T>) -> M64 {
        m.cols.map(|c| c.map(T::f64))
    }
    pub(crate) fn mul64(a: &M64, b: &M64) -> M64 {
        core::array::from_fn(|c| core::array::from_fn(|r| (0..4).map(|k| a[k][r] * b[c][k]).sum()))
    }
    pub(crate) fn apply64(a: &M64, v: [f64; 4]) -> [f64; 4] {
        core::array::from_fn(|r| (0..4).map(|k| a[k][r] * v[k]).sum())
    }
    /// The inverse transpose of the upper-left 3×3 block, by cofactors.
    pub(crate) fn inv_t64(a: &M64) -> [[f64; 3]; 3] {
        let col = |i: usize| [a[i][0], a[i][1], a[i][2]];
        let cross = |p: [f64; 3], q: [f64; 3]| {
            [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]
        };
        let (x, y, z) = (col(0), col(1), col(2));
        let yz = cross(y, z);
        let det: f64 = (0..3).map(|i| x[i] * yz[i]).sum();
        [yz, cross(z, x), cross(x, y)].map(|c| c.map(|v| v / det))
    }

    /// How a numeric path rounds, for the derived error bounds: each rounding
    /// operation errs by at most `abs + rel·|result|` (Fx: u, 0; f32: 0,
    /// 2^-24), `f32` parameters are quantised by `q` (Fx: u/2, f32: 0) and
    /// sin/cos of an exact angle err by at most `sc`.
    pub(crate) struct Path {
        pub(crate) abs: f64,
        pub(crate) rel: f64,
        pub(crate) q: f64,
        pub(crate) sc: f64,
    }
    pub(crate) const FX: Path = Path { abs: U, rel: 0.0, q: U / 2.0, sc: 0.53 * U };
    pub(crate) const F32: Path = Path { abs: 0.0, rel: 1.0 / 16_777_216.0, q: 0.0, sc: 2.1e-7 };

    /// An f64 reference matrix `v` and an entry-wise bound `e` on the error of
    /// its `T` twin, propagated to first order: for `C = A·B`,
    /// `e_C ≤ |A|·e_B + e_A·|B| + rounding`, where Fx truncates each product
    /// not involving 0 or ±1 once (sums are exact) and f32 errs by γ4·Σ|a||b|.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Tr {
        pub(crate) v: M64,
        pub(crate) e: M64,
    }
    impl Tr {
        pub(crate) fn mul(&self, b: &Tr, p: &Path) -> Tr {
            let (mut v, mut e) = ([[0.0; 4]; 4], [[0.0; 4]; 4]);
            for c in 0..4 {
                let col = self.apply(b.v[c], b.e[c], p);
                (v[c], e[c]) = col;
            }
            Tr { v, e }
        }
        /// `A·x` for a vector `x` with error bound `ex`.
        pub(crate) fn apply(&self, x: [f64; 4], ex: [f64; 4], p: &Path) -> ([f64; 4], [f64; 4]) {
            let (a, ea) = (&self.v, &self.e);
            let trivial = |t: f64| t == 0.0 || t.abs() == 1.0;
            let v = apply64(a, x);
            let e = core::array::from_fn(|r| {
                (0..4)
                    .map(|k| {
                        let rounding = if trivial(a[k][r]) || trivial(x[k]) { 0.0 } else { p.abs };
                        a[k][r].abs() * ex[k]
                            + ea[k][r] * x[k].abs()
                            + rounding
                            + p.rel * 4.01 * (a[k][r] * x[k]).abs()
                    })
                    .sum()
            });
            (v, e)
        }
    }

    fn random<T: Scalar>(rng: &mut Rng, r: f64) -> Mat4<T> {
        Mat4::from_f32(core::array::from_fn(|_| core::array::from_fn(|_| rng.range(-r, r))))
    }

    #[test]
    fn products_against_f64() {
        // Fx: stored entries are exact inputs, each of the 4 products truncates
        // once (< u) and sums are exact: |error| < 4u (3u for points, w = 1).
        // f32: |error| ≤ γ4 · Σ|a||b| with γ4 = 4·2^-24/(1 − 4·2^-24).
        let (mut rng, mut worst_fx, mut worst_f32) = (Rng(3), 0f64, 0f64);
        let g4 = 4.0 * 2f64.powi(-24) / (1.0 - 4.0 * 2f64.powi(-24));
        for _ in 0..20_000 {
            let (a, b) = (random::<Fx>(&mut rng, 8.0), random::<Fx>(&mut rng, 64.0));
            let e = mul64(&m64(a), &m64(b));
            for (c, ec) in m64(a * b).iter().zip(&e) {
                for (v, ev) in c.iter().zip(ec) {
                    worst_fx = worst_fx.max((v - ev).abs() / U);
                }
            }
            let p = Vec3::<Fx>::from_f32(rng.vec3(64.0));
            let ep = apply64(&m64(b), [p.x.f64(), p.y.f64(), p.z.f64(), 1.0]);
            let q = b.transform_point(p);
            for (v, ev) in [q.x, q.y, q.z, q.w].into_iter().zip(ep) {
                assert!((v.f64() - ev).abs() < 3.0 * U);
            }
            let (a, b) = (random::<f32>(&mut rng, 8.0), random::<f32>(&mut rng, 64.0));
            let (ea, eb) = (m64(a), m64(b));
            let (e, ab) = (mul64(&ea, &eb), m64(a * b));
            for c in 0..4 {
                for r in 0..4 {
                    let mag: f64 = (0..4).map(|k| (ea[k][r] * eb[c][k]).abs()).sum();
                    worst_f32 = worst_f32.max((ab[c][r] - e[c][r]).abs() / (g4 * mag));
                }
            }
        }
        println!(
            "Mat4 products: 20000 each, Fx worst {worst_fx:.2}u (bound 4u), f32 worst {worst_f32:.3} of γ4·Σ|ab|"
        );
        assert!(worst_fx < 4.0 && worst_f32 <= 1.0);
    }

    #[test]
    fn layout_transpose_and_identity() {
        let m = Mat4::<f32>::from_f32(core::array::from_fn(|c| core::array::from_fn(|r| (4 * c + r) as f32)));
        assert_eq!(m.transpose().transpose(), m);
        assert_eq!(Mat4::from_rows(m.cols), m.transpose());
        assert_eq!(m * Mat4::IDENTITY, m);
        assert_eq!(Mat4::IDENTITY * m, m);
        assert_eq!(m.transform_vector(Vec3::new(1.0, 0.0, 0.0)), Vec3::new(0.0, 1.0, 2.0));
        assert_eq!((m * Vec4::new(0.0, 0.0, 0.0, 1.0)).to_f32(), [12.0, 13.0, 14.0, 15.0]);
        assert_eq!(m.upper_left().cols[1], [4.0, 5.0, 6.0]);
        assert_eq!(Mat4::<Fx>::from_f32(m.to_f32()).to_f32(), m.to_f32());
        assert_eq!(Mat3::<Fx>::IDENTITY.transpose().determinant(), Fx::ONE);
    }

    #[test]
    fn singular_and_non_finite_inverse_transpose_is_none() {
        let z = Mat3::<Fx>::from_cols([[Fx::ZERO; 3]; 3]);
        assert_eq!(z.inverse_transpose(), None);
        let rank2 = Mat3::<f32>::from_cols([[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 0.0]]);
        assert_eq!(rank2.inverse_transpose(), None);
        let nan = Mat3::from_cols([[f32::NAN, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        assert_eq!(nan.inverse_transpose(), None);
        // Fx: the inverse of a 2^-15 scaling is 2^15, beyond range: None, not garbage.
        let tiny = Mat3::from_cols([
            [Fx::from_bits(2), Fx::ZERO, Fx::ZERO],
            [Fx::ZERO, Fx::ONE, Fx::ZERO],
            [Fx::ZERO, Fx::ZERO, Fx::ONE],
        ]);
        assert_eq!(tiny.inverse_transpose(), None);
        let huge = Mat3::<f32>::from_cols([[1e30, 0.0, 0.0], [0.0, 1e30, 0.0], [0.0, 0.0, 1e30]]);
        assert!((huge.inverse_transpose().unwrap().cols[0][0] - 1e-30).abs() < 1e-36);
        let tiny = Mat3::<f32>::from_cols([[1e-30, 0.0, 0.0], [0.0, 2e-30, 0.0], [0.0, 0.0, 1e-30]]);
        assert!((tiny.inverse_transpose().unwrap().cols[1][1] - 5e29).abs() < 1e23);
        assert_eq!(Mat4::<f32>::IDENTITY.normal_matrix(), Some(Mat3::IDENTITY));
    }
}
