//! Lighting: ambient plus one directional light, Lambert diffuse and optional
//! Blinn–Phong specular, evaluated per face (flat) or per vertex (Gouraud).
//!
//! The specular term's viewer ([`Viewer`]) is either at the eye (the
//! default: the half vector follows each vertex) or infinitely far along
//! +z (OpenGL's default light model, and TGX's): one half vector for the
//! whole mesh, no square root per vertex.
//!
//! All vectors are in eye space (the camera at the origin looking down −z).
//! The vertex stage evaluates the same formula in model space when the
//! model-view matrix is a similarity (`pipeline/model_light.rs`: fewer
//! operations per vertex, the same values up to rounding).
//! Intensities are unitless factors on the material colour; the result is
//! clamped to `[0, 1]` per channel before it becomes a colour channel.

use crate::Error;
use crate::math::{Scalar, Vec3};

/// A `Copy` lighting setup.
///
/// ```
/// use microraster::light::Lighting;
/// use microraster::math::Vec3;
/// let l = Lighting::<f32>::new(0.2, Vec3::new(0.0, 0.0, 1.0), 0.8);
/// // A surface facing the light gets ambient + diffuse = 1.0.
/// let c = l.shade(Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, -5.0), [0.5, 1.0, 0.25]);
/// assert!((c[0] - 0.5).abs() < 1e-6 && (c[1] - 1.0).abs() < 1e-6);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lighting<T> {
    /// Ambient factor.
    pub ambient: T,
    /// Unit direction *towards* the light, eye space.
    pub direction: Vec3<T>,
    /// Diffuse (Lambert) factor.
    pub diffuse: T,
    /// Specular factor and Blinn–Phong exponent (`None`: no specular term).
    pub specular: Option<(T, u32)>,
    /// Where the specular term's viewer is ([`Viewer::Local`] unless set).
    pub viewer: Viewer,
}

/// Where the Blinn–Phong half vector's viewer is.
///
/// ```
/// use microraster::light::{Lighting, Viewer};
/// use microraster::math::Vec3;
/// let l = Lighting::<f32>::new(0.0, Vec3::new(0.0, 0.0, 1.0), 0.0).with_specular(1.0, 8);
/// // Facing the light and the viewer: full specular either way.
/// let (n, p) = (Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, -5.0));
/// assert!((l.shade(n, p, [0.0; 3])[0] - 1.0).abs() < 1e-6);
/// let far = l.with_viewer(Viewer::Infinite);
/// assert!((far.shade(n, p, [0.0; 3])[0] - 1.0).abs() < 1e-6);
/// // Off the axis, only the local viewer sees the highlight move.
/// let p = Vec3::new(3.0, 0.0, -5.0);
/// assert!(l.shade(n, p, [0.0; 3])[0] < 0.9);
/// assert!((far.shade(n, p, [0.0; 3])[0] - 1.0).abs() < 1e-6);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Viewer {
    /// At the eye (the origin of eye space): the half vector is
    /// `normalize(L + normalize(−p))` at each lit point `p`: two square
    /// roots per lit vertex, or (lit in model space, `f32`, an even
    /// exponent) one and a division.
    #[default]
    Local,
    /// Infinitely far along +z (OpenGL's `GL_LIGHT_MODEL_LOCAL_VIEWER`
    /// false, its default): the half vector is `normalize(L + (0, 0, 1))`
    /// for every point, which the vertex stage computes once per mesh
    /// where it lights in model space (a similarity model-view, the usual
    /// case). A light exactly towards −z has no half vector: its specular
    /// term is `strength · 0^e` (0 for `e > 0`).
    Infinite,
}

impl<T: Scalar> Lighting<T> {
    /// No lighting: every surface shows its material colour.
    pub const UNLIT: Option<Lighting<T>> = None;

    /// Ambient plus a directional light towards `direction` (normalised here).
    pub fn new(ambient: T, direction: Vec3<T>, diffuse: T) -> Self {
        Lighting { ambient, direction: direction.normalize(), diffuse, specular: None, viewer: Viewer::Local }
    }

    /// [`Lighting::new`], checked: the errors of [`Lighting::validate`].
    ///
    /// ```
    /// use microraster::{light::Lighting, math::Vec3, Error};
    /// assert!(Lighting::<f32>::try_new(0.2, Vec3::new(0.0, 0.0, 1.0), 0.8).is_ok());
    /// let zero = Vec3::new(0.0, 0.0, 0.0);
    /// assert_eq!(Lighting::<f32>::try_new(0.2, zero, 0.8), Err(Error::InvalidParameter(microraster::Param::LightDirection)));
    /// ```
    pub fn try_new(ambient: T, direction: Vec3<T>, diffuse: T) -> Result<Self, Error> {
        let l = Self::new(ambient, direction, diffuse);
        l.validate()?;
        Ok(l)
    }

    /// Checks the lighting: [`Error::NonFiniteCoordinate`] if a factor or the
    /// direction has a NaN or infinite component; [`Error::InvalidParameter`]
    /// if the direction is not a unit vector (a zero direction stays zero
    /// through [`Lighting::new`]; a unit vector set in the public field is
    /// accepted within 2^-8). The vertex stage runs this before each mesh.
    /// Finite factors of any size are valid: a result that overflows `f32`
    /// is clamped to full intensity (see
    /// [`Pipeline::lighting`](crate::pipeline::Pipeline::lighting)).
    pub fn validate(&self) -> Result<(), Error> {
        let d = self.direction;
        let spec = self.specular.map_or(T::ZERO, |s| s.0);
        if ![self.ambient, self.diffuse, spec, d.x, d.y, d.z].iter().all(|v| v.is_finite()) {
            return Err(Error::NonFiniteCoordinate);
        }
        // |d|² within 2^-8 of 1 (Fx normalising rounds at 2^-16).
        let len2 = d.x.to_f32() * d.x.to_f32() + d.y.to_f32() * d.y.to_f32() + d.z.to_f32() * d.z.to_f32();
        if !((1.0 - 1.0 / 256.0)..=(1.0 + 1.0 / 256.0)).contains(&len2) {
            return Err(Error::InvalidParameter(crate::Param::LightDirection));
        }
        Ok(())
    }

    /// The same lighting with a Blinn–Phong specular term.
    pub fn with_specular(self, strength: T, exponent: u32) -> Self {
        Lighting { specular: Some((strength, exponent)), ..self }
    }

    /// The same lighting with the specular term's viewer at `viewer`.
    pub fn with_viewer(self, viewer: Viewer) -> Self {
        Lighting { viewer, ..self }
    }

    /// The half vector of the [`Viewer::Infinite`] viewer (eye space),
    /// zero for a light exactly towards −z.
    pub(crate) fn infinite_half(&self) -> Vec3<T> {
        (self.direction + Vec3::new(T::ZERO, T::ZERO, T::ONE)).normalize_fast()
    }

    /// Colour factors for a unit normal `n` at eye-space position `p`, on a
    /// material with channel factors `base` (each in `[0, 1]`).
    pub fn shade(&self, n: Vec3<T>, p: Vec3<T>, base: [T; 3]) -> [T; 3] {
        let lambert = positive(n.dot(self.direction));
        let k = self.ambient + self.diffuse * lambert;
        let spec = match self.specular {
            Some((strength, exp)) if lambert > T::ZERO => {
                // Half vector between the light and the viewer.
                let h = match self.viewer {
                    Viewer::Local => (self.direction + (-p).normalize_fast()).normalize_fast(),
                    Viewer::Infinite => self.infinite_half(),
                };
                strength * powi(positive(n.dot(h)), exp)
            }
            _ => T::ZERO,
        };
        base.map(|b| b * k + spec)
    }
}

/// `max(v, 0)`, NaN to 0: the clamp of Lambert's and Blinn–Phong's dot
/// products (also in model space, `pipeline/model_light.rs`).
#[inline]
pub(crate) fn positive<T: Scalar>(v: T) -> T {
    if v > T::ZERO { v } else { T::ZERO }
}

/// `x^e` by repeated squaring (`x` in `[0, 1]`, so nothing grows): the
/// Blinn–Phong exponent is an integer ([`Lighting::with_specular`]), so no
/// `powf`; `⌊log₂ e⌋` squarings and at most as many products. Error against
/// the exact `x^e`: `f32` within `e·2^-24` relative (each of the products
/// adds at most `2^-24` relative, raised to the power it still enters with:
/// `e − 1` in all), plus `e·2^-149` absolute where products are subnormal;
/// `Fx` within `e·2^-16` absolute (each truncation is below
/// `2^-16` and, `x ≤ 1`, a later product multiplies an earlier error by at
/// most the power of `x` it meets, `e − 1` in all). Tested against f64.
pub(crate) fn powi<T: Scalar>(mut x: T, mut e: u32) -> T {
    let mut r = T::ONE;
    while e > 0 {
        if e & 1 == 1 {
            r = r * x;
        }
        x = x * x;
        e >>= 1;
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;

    #[test]
    fn powi_within_bound_of_exact_power() {
        let mut n = 0;
        let (mut worst_f, mut worst_x) = (0.0f64, 0.0f64);
        for e in 1..=128u32 {
            for i in 0..=512 {
                let x = i as f32 / 512.0 * (1.0 - 1e-3 * (e % 7) as f32);
                let exact = f64::from(x).powf(f64::from(e));
                let f = f64::from(powi(x, e));
                let (err, e64) = ((f - exact).abs(), f64::from(e));
                if exact >= 2f64.powi(-126) {
                    worst_f = worst_f.max(err / exact / e64);
                }
                assert!(
                    err <= e64 * (2f64.powi(-24) * exact + 2f64.powi(-149)),
                    "f32 {x}^{e}: {f} vs {exact}"
                );
                let fx = Fx::from_f32(x);
                let exact = (f64::from(fx.to_bits()) / 65536.0).powf(f64::from(e));
                let got = f64::from(powi(fx, e).to_bits()) / 65536.0;
                worst_x = worst_x.max((got - exact).abs() / f64::from(e));
                assert!((got - exact).abs() <= f64::from(e) / 65536.0, "Fx {x}^{e}: {got} vs {exact}");
                n += 1;
            }
        }
        assert_eq!(n, 128 * 513);
        // The bounds are not vacuous: errors of a sizeable part of them occur.
        assert!(worst_f > 2f64.powi(-27) && worst_x > 2f64.powi(-19), "{worst_f:e} {worst_x:e}");
    }

    #[test]
    fn lambert_and_blinn_phong_match_f64() {
        let mut n_checked = 0;
        for i in 0..400 {
            let a = i as f32 * 0.0157; // 0 .. 2π
            let n = Vec3::new(a.cos(), a.sin(), 0.0);
            let light = Lighting::<f32>::new(0.1, Vec3::new(1.0, 0.0, 0.0), 0.7).with_specular(0.5, 16);
            let p = Vec3::new(0.0, 0.0, -4.0);
            let got = light.shade(n, p, [1.0, 0.5, 0.0]);
            // f64 reference.
            let (nx, ny) = (f64::from(a).cos(), f64::from(a).sin());
            let lam = nx.max(0.0);
            // Half vector of light (1,0,0) and view (0,0,1).
            let h = (0.5f64.sqrt(), 0.0, 0.5f64.sqrt());
            let spec = if lam > 0.0 { 0.5 * (nx * h.0 + ny * h.1).max(0.0).powi(16) } else { 0.0 };
            let want = [1.0, 0.5, 0.0].map(|b: f64| b * (0.1 + 0.7 * lam) + spec);
            for k in 0..3 {
                assert!((f64::from(got[k]) - want[k]).abs() < 1e-5, "{a}: {got:?} vs {want:?}");
            }
            let fx = Lighting::<Fx>::new(
                Fx::from_f32(0.1),
                Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO),
                Fx::from_f32(0.7),
            )
            .with_specular(Fx::from_f32(0.5), 16);
            let gf =
                fx.shade(Vec3::from_f32([n.x, n.y, 0.0]), Vec3::from_f32([0.0, 0.0, -4.0]), [Fx::ONE; 3]);
            let wf = 0.1 + 0.7 * lam + spec;
            // Fx: each product rounds at 2^-16; 16 squarings and a few products.
            assert!((f64::from(gf[0].to_f32()) - wf).abs() < 40.0 / 65536.0, "Fx {a}");
            n_checked += 1;
        }
        assert_eq!(n_checked, 400);
    }
}
