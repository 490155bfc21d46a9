//! Model, view, projection and viewport transforms, generic over [`Scalar`].
//!
//! # Conventions
//!
//! * Column vectors and column-major [`Mat4`]: `clip = P · V · M · v`.
//! * Right-handed view space: the camera sits at the origin looking down −z,
//!   +y up, +x right. Rotations are counter-clockwise looking down the axis
//!   towards the origin (`rotation_z(π/2)` maps +x to +y). Angles in radians.
//! * Projections use the D3D/Vulkan depth range: a point is inside when
//!   `−w ≤ x, y ≤ w` and `0 ≤ z ≤ w`; `z/w` is 0 on the near plane and 1 on the
//!   far plane. Perspective sets `w = −z_view` (the distance along the view).
//! * [`Viewport`] maps NDC x, y ∈ [−1, 1] to pixels with y flipped: NDC
//!   (−1, +1) is the top-left *corner* of the viewport, pixel (0, 0) covers
//!   `[0, 1) × [0, 1)` as in [`SubPoint`](crate::SubPoint). Depth stays `z/w` ∈ [0, 1].
//!
//! Bad parameters never panic: the view and projection constructors return
//! [`Error::NonFiniteCoordinate`] for NaN or infinite inputs,
//! [`Error::InvalidParameter`] for degenerate ones (near ≤ 0, far ≤ near, zero
//! aspect, eye = target, …) and [`Error::CoordinateOutOfRange`] where a
//! result would saturate (`Fx`) or overflow to infinity (`f32`: finite input
//! near `f32::MAX`, or a field of view so small that `1/tan` overflows).
//! The model constructors cannot fail; NaN input gives NaN entries, which
//! [`Viewport::project`] reports.
//!
//! # Accuracy, and the `Fx` envelope
//!
//! `Fx` entries carry an *absolute* error of a few u = 2^-16, which later
//! products multiply by the coordinates they meet. Hence two rules:
//!
//! * compose as `proj * (view * model)`: the large view and model
//!   translations cancel in `view * model` before anything is rounded relative
//!   to them (`(proj * view) * model` measured about 10× worse in `Fx`);
//! * pixel errors grow as `1/w`, so geometry very close to the eye is coarser.
//!
//! Tested envelope, free of saturation: eye within ±256 per axis, target
//! within ±64, model coordinates within ±4 and scale factors in [1/4, 64]
//! (±64 with scales ≥ 1/4 measured 0.17 px), `fov_y` in [20°, 120°], aspect in
//! [1/2, 2], `near ≥ 1/16`, `far ≤ 4096`. Worst screen error measured at
//! 320×240 over 7 × 120 000 points in the frustum (7 random seeds):
//!
//! | path  | w < 1   | 1 ≤ w < 4 | w ≥ 4    |
//! |-------|---------|-----------|----------|
//! | `Fx`  | 0.48 px | 0.10 px   | 0.15 px  |
//! | `f32` | 0.036 px | 0.018 px | 0.0045 px |
//!
//! (`f32` errs by 2^-24 of the coordinates' magnitude, here up to ~450,
//! times `(W/2)·(f/aspect)/w`.) The tests also check every point against a
//! first-order bound derived from the representation; measured errors stay
//! below a third of it. Orthographic matrices hold `2/(right − left)` with
//! the same absolute error u, so the `Fx` NDC error is about `u·|x_view|`:
//! keep orthographic view volumes within about ±16.

use super::vec::at_limit;
use super::{Mat4, Scalar, Vec3, Vec4};
use crate::{Error, Param};

/// The error for a degenerate view or projection parameter.
const fn degenerate(param: Param) -> Error {
    Error::InvalidParameter(param)
}

/// Translation by `t`.
///
/// ```
/// use microraster::math::{transform::translation, Vec3};
/// let m = translation(Vec3::new(1.0f32, 2.0, 3.0));
/// assert_eq!(m.transform_point(Vec3::new(1.0, 1.0, 1.0)).to_f32(), [2.0, 3.0, 4.0, 1.0]);
/// ```
pub fn translation<T: Scalar>(t: Vec3<T>) -> Mat4<T> {
    let mut m = Mat4::IDENTITY;
    m.cols[3] = [t.x, t.y, t.z, T::ONE];
    m
}

/// Scaling by `s.x`, `s.y`, `s.z` along the axes.
pub fn scaling<T: Scalar>(s: Vec3<T>) -> Mat4<T> {
    let mut m = Mat4::IDENTITY;
    (m.cols[0][0], m.cols[1][1], m.cols[2][2]) = (s.x, s.y, s.z);
    m
}

/// Rotation by `angle` radians about +x (y towards z).
pub fn rotation_x<T: Scalar>(angle: T) -> Mat4<T> {
    let (s, c) = angle.sin_cos();
    let mut m = Mat4::IDENTITY;
    (m.cols[1][1], m.cols[1][2], m.cols[2][1], m.cols[2][2]) = (c, s, -s, c);
    m
}

/// Rotation by `angle` radians about +y (z towards x).
pub fn rotation_y<T: Scalar>(angle: T) -> Mat4<T> {
    let (s, c) = angle.sin_cos();
    let mut m = Mat4::IDENTITY;
    (m.cols[0][0], m.cols[0][2], m.cols[2][0], m.cols[2][2]) = (c, -s, s, c);
    m
}

/// Rotation by `angle` radians about +z (x towards y).
///
/// ```
/// use microraster::math::{transform::rotation_z, Fx, Scalar, Vec3};
/// let m = rotation_z(Fx::from_f32(core::f32::consts::FRAC_PI_2));
/// let p = m.transform_point(Vec3::from_f32([1.0, 0.0, 0.0])).to_f32();
/// assert!(p[0].abs() < 1e-4 && (p[1] - 1.0).abs() < 1e-4);
/// ```
pub fn rotation_z<T: Scalar>(angle: T) -> Mat4<T> {
    let (s, c) = angle.sin_cos();
    let mut m = Mat4::IDENTITY;
    (m.cols[0][0], m.cols[0][1], m.cols[1][0], m.cols[1][1]) = (c, s, -s, c);
    m
}

/// The view matrix of a camera at `eye` looking at `target`, with `up` giving
/// the screen's up direction (right-handed; the camera looks down −z).
///
/// Errors: [`Error::NonFiniteCoordinate`] for NaN or infinite input;
/// [`Error::InvalidParameter`] if `eye == target` or `up` is zero or parallel
/// to the view direction; [`Error::CoordinateOutOfRange`] if a difference
/// or entry saturates (`Fx`) or overflows (`f32`, input near `f32::MAX`).
/// With `Fx` the side axis `view × up` is accurate to about `2^-16 / sin θ`
/// for the angle θ between `up` and the view direction, so keep θ away
/// from 0 rather than just nonzero.
///
/// ```
/// use microraster::math::{transform::look_at, Vec3};
/// let v = look_at(Vec3::new(0.0f32, 0.0, 5.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
/// assert_eq!(v.transform_point(Vec3::new(0.0, 0.0, 0.0)).to_f32(), [0.0, 0.0, -5.0, 1.0]);
/// assert!(look_at(Vec3::new(1.0f32, 1.0, 1.0), Vec3::new(1.0, 1.0, 1.0), Vec3::new(0.0, 1.0, 0.0)).is_err());
/// ```
pub fn look_at<T: Scalar>(eye: Vec3<T>, target: Vec3<T>, up: Vec3<T>) -> Result<Mat4<T>, Error> {
    let all = [eye, target, up];
    if all.iter().any(|v| !v.extend(T::ZERO).is_finite()) {
        return Err(Error::NonFiniteCoordinate);
    }
    let d = target - eye;
    if [d.x, d.y, d.z].into_iter().any(at_limit) {
        return Err(Error::CoordinateOutOfRange);
    }
    let f = d.normalize();
    // Normalising `up` first makes the zero test on `s` independent of |up|.
    let s = f.cross(up.normalize());
    if f == Vec3::ZERO || s == Vec3::ZERO {
        return Err(degenerate(Param::LookAt));
    }
    let s = s.normalize();
    let u = s.cross(f);
    let m = Mat4::from_rows([
        [s.x, s.y, s.z, -s.dot(eye)],
        [u.x, u.y, u.z, -u.dot(eye)],
        [-f.x, -f.y, -f.z, f.dot(eye)],
        [T::ZERO, T::ZERO, T::ZERO, T::ONE],
    ]);
    if m.any_at_limit() { Err(Error::CoordinateOutOfRange) } else { Ok(m) }
}

/// A right-handed perspective projection with D3D/Vulkan depth: `fov_y` is
/// the vertical field of view in radians, `aspect` = width / height, `near`
/// and `far` the positive distances of the clip planes.
///
/// With `f = 1/tan(fov_y/2)` the matrix is, by rows,
/// `[f/aspect 0 0 0; 0 f 0 0; 0 0 A near·A; 0 0 −1 0]` with
/// `A = far/(near − far)`: computing `near·far/(near − far)` as `near·A`
/// avoids the `near·far` product, which saturates `Fx`.
///
/// Errors: [`Error::NonFiniteCoordinate`] for NaN or infinite input;
/// [`Error::InvalidParameter`] if `fov_y ∉ (0, π)`, `aspect ≤ 0`, `near ≤ 0` or `far ≤ near`; and
/// [`Error::CoordinateOutOfRange`] if an entry saturates (`Fx`) or overflows
/// (`f32`: a fov or aspect near 0, or `near` and `far` huge and close
/// together).
///
/// ```
/// use microraster::math::{transform::perspective, Vec3};
/// let p = perspective(1.0f32, 4.0 / 3.0, 0.5, 100.0).unwrap();
/// let near = p.transform_point(Vec3::new(0.0, 0.0, -0.5));
/// let far = p.transform_point(Vec3::new(0.0, 0.0, -100.0));
/// assert_eq!(near.z / near.w, 0.0);
/// assert!((far.z / far.w - 1.0).abs() < 1e-6);
/// assert!(perspective(1.0f32, 1.0, 0.0, 100.0).is_err());
/// ```
pub fn perspective<T: Scalar>(fov_y: T, aspect: T, near: T, far: T) -> Result<Mat4<T>, Error> {
    if ![fov_y, aspect, near, far].into_iter().all(T::is_finite) {
        return Err(Error::NonFiniteCoordinate);
    }
    let pi = T::from_f32(core::f32::consts::PI);
    if !(fov_y > T::ZERO && fov_y < pi) {
        return Err(degenerate(Param::FieldOfView));
    }
    // Finite here, so `<=` is the negation of `>`.
    if aspect <= T::ZERO {
        return Err(degenerate(Param::AspectRatio));
    }
    if !(near > T::ZERO && far > near) {
        return Err(degenerate(Param::NearFar));
    }
    let (s, c) = (fov_y * T::from_f32(0.5)).sin_cos();
    let f = c / s;
    let a = far / (near - far);
    let z = T::ZERO;
    let m = Mat4::from_rows([[f / aspect, z, z, z], [z, f, z, z], [z, z, a, near * a], [z, z, -T::ONE, z]]);
    if m.any_at_limit() || s <= T::ZERO { Err(Error::CoordinateOutOfRange) } else { Ok(m) }
}

/// An orthographic projection of the view-space box `[left, right] ×
/// [bottom, top]` between the planes at distances `near` and `far` in front
/// of the camera (`z_view = −near` maps to depth 0, `−far` to 1; `w = 1`).
///
/// Errors: [`Error::NonFiniteCoordinate`] for NaN or infinite input;
/// [`Error::InvalidParameter`] unless `left < right`, `bottom < top` and `near < far`; and
/// [`Error::CoordinateOutOfRange`] if a difference or entry saturates
/// (`Fx`) or overflows (`f32`).
///
/// ```
/// use microraster::math::{transform::orthographic, Vec3};
/// let o = orthographic(-2.0f32, 2.0, -1.0, 1.0, 1.0, 5.0).unwrap();
/// assert_eq!(o.transform_point(Vec3::new(2.0, -1.0, -3.0)).to_f32(), [1.0, -1.0, 0.5, 1.0]);
/// ```
pub fn orthographic<T: Scalar>(
    left: T,
    right: T,
    bottom: T,
    top: T,
    near: T,
    far: T,
) -> Result<Mat4<T>, Error> {
    if ![left, right, bottom, top, near, far].into_iter().all(T::is_finite) {
        return Err(Error::NonFiniteCoordinate);
    }
    if !(left < right && bottom < top) {
        return Err(degenerate(Param::ViewBox));
    }
    if near >= far {
        return Err(degenerate(Param::NearFar));
    }
    let (w, h, d) = (right - left, top - bottom, near - far);
    let two = T::ONE + T::ONE;
    let z = T::ZERO;
    let m = Mat4::from_rows([
        [two / w, z, z, -((right + left) / w)],
        [z, two / h, z, -((top + bottom) / h)],
        [z, z, T::ONE / d, near / d],
        [z, z, z, T::ONE],
    ]);
    let sums = [w, h, d, right + left, top + bottom];
    if m.any_at_limit() || sums.into_iter().any(at_limit) { Err(Error::CoordinateOutOfRange) } else { Ok(m) }
}

/// The perspective divide: NDC `(x/w, y/w, z/w)` of a clip-space position.
///
/// Errors: [`Error::NonFiniteCoordinate`] for NaN or infinite input;
/// [`Error::CoordinateOutOfRange`] if `w ≤ 0` (the point is not in front of
/// the camera: clip against the near plane first) or a quotient saturates.
pub fn to_ndc<T: Scalar>(clip: Vec4<T>) -> Result<Vec3<T>, Error> {
    if !clip.is_finite() {
        return Err(Error::NonFiniteCoordinate);
    }
    if clip.w <= T::ZERO {
        return Err(Error::CoordinateOutOfRange);
    }
    let n = Vec3::new(clip.x / clip.w, clip.y / clip.w, clip.z / clip.w);
    if [n.x, n.y, n.z].into_iter().any(at_limit) { Err(Error::CoordinateOutOfRange) } else { Ok(n) }
}

/// The screen rectangle NDC maps to: top-left corner `(x, y)` and size in
/// pixels.
///
/// ```
/// use microraster::math::{transform::{look_at, perspective, Viewport}, Mat4, Vec3};
/// let vp = Viewport::new(0.0f32, 0.0, 320.0, 240.0);
/// assert_eq!(vp.to_screen(Vec3::new(-1.0, 1.0, 0.0)), (0.0, 0.0)); // top-left corner
/// assert_eq!(vp.to_screen(Vec3::new(0.0, 0.0, 0.0)), (160.0, 120.0));
/// // The whole pipeline: a point straight ahead lands in the middle.
/// let view = look_at(Vec3::new(0.0, 0.0, 10.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
/// let proj = perspective(1.0, 320.0 / 240.0, 1.0, 100.0).unwrap();
/// let mvp: Mat4<f32> = proj * view;
/// let s = vp.project(mvp.transform_point(Vec3::new(0.0, 0.0, 0.0))).unwrap();
/// assert!((s.x - 160.0).abs() < 1e-4 && (s.y - 120.0).abs() < 1e-4 && s.z > 0.0 && s.z < 1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viewport<T> {
    /// Left edge in pixels.
    pub x: T,
    /// Top edge in pixels.
    pub y: T,
    /// Width in pixels.
    pub width: T,
    /// Height in pixels.
    pub height: T,
}

impl<T: Scalar> Viewport<T> {
    /// A viewport with top-left corner `(x, y)` and the given size in pixels.
    pub const fn new(x: T, y: T, width: T, height: T) -> Self {
        Viewport { x, y, width, height }
    }

    /// Pixel position of an NDC point: `x + (ndc.x + 1)·width/2`,
    /// `y + (1 − ndc.y)·height/2`. Saturates for `Fx` beyond ±32768 px; use
    /// [`Viewport::project`] for a checked result.
    pub fn to_screen(self, ndc: Vec3<T>) -> (T, T) {
        let half = T::from_f32(0.5);
        (self.x + (ndc.x + T::ONE) * (self.width * half), self.y + (T::ONE - ndc.y) * (self.height * half))
    }

    /// Clip space to `(x_px, y_px, depth)` with `depth = z/w`: [`to_ndc`] then
    /// [`Viewport::to_screen`], with the errors of [`to_ndc`] plus
    /// [`Error::CoordinateOutOfRange`] if a pixel coordinate saturates.
    pub fn project(self, clip: Vec4<T>) -> Result<Vec3<T>, Error> {
        let ndc = to_ndc(clip)?;
        let (x, y) = self.to_screen(ndc);
        if at_limit(x) || at_limit(y) { Err(Error::CoordinateOutOfRange) } else { Ok(Vec3::new(x, y, ndc.z)) }
    }
}

#[cfg(test)]
mod reference;
#[cfg(test)]
mod tests;
