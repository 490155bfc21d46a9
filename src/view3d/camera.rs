//! The camera of the front: where it is, where it looks, and its lens.
//!
//! Building a camera cannot fail: its inputs are checked when a frame is
//! drawn ([`View3d::draw`](super::View3d::draw) returns the error), so a
//! camera that moves every frame needs no `?` or `unwrap` where it is made.

use crate::light::Lighting;
use crate::math::{Mat4, Scalar, Vec3, transform};
use crate::pipeline::Pipeline;
use crate::{Error, Param};

/// How the camera projects: perspective (the default) or orthographic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Projection {
    /// Vertical field of view `fov_y` (radians, in `(0, π)`) and the distances
    /// of the near and far clip planes (`0 < near < far`).
    Perspective {
        /// Vertical field of view in radians.
        fov_y: f32,
        /// Distance of the near plane.
        near: f32,
        /// Distance of the far plane.
        far: f32,
    },
    /// A view box `height` world units tall (its width follows the frame's
    /// aspect ratio) between the planes at `near` and `far` (`near < far`).
    Orthographic {
        /// Height of the view box.
        height: f32,
        /// Distance of the near plane.
        near: f32,
        /// Distance of the far plane.
        far: f32,
    },
}

/// The default lens: 50° vertical field of view; near and far planes at
/// 0.25 and 64 units, which keeps 16-bit depth fine-grained for scenes a
/// few units across.
pub const DEFAULT_PROJECTION: Projection =
    Projection::Perspective { fov_y: 50.0f32.to_radians(), near: 0.25, far: 64.0 };

/// A camera: eye, target, the world's up direction (+y by default) and a
/// [`Projection`].
///
/// ```
/// use microraster::view3d::{Camera, Projection};
/// let cam = Camera::look_at([0.0, 1.0, 4.0], [0.0, 0.0, 0.0]);
/// assert_eq!(cam.eye(), [0.0, 1.0, 4.0]);
/// let ortho = cam.orthographic(3.0, 0.5, 20.0);
/// assert_eq!(ortho.projection(), Projection::Orthographic { height: 3.0, near: 0.5, far: 20.0 });
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    eye: [f32; 3],
    target: [f32; 3],
    up: [f32; 3],
    projection: Projection,
}

impl Camera {
    /// A perspective camera ([`DEFAULT_PROJECTION`]) at `eye` looking at
    /// `target`, +y up.
    pub const fn look_at(eye: [f32; 3], target: [f32; 3]) -> Self {
        Camera { eye, target, up: [0.0, 1.0, 0.0], projection: DEFAULT_PROJECTION }
    }

    /// A camera circling `target` at `distance`: `yaw` radians about +y
    /// (0 looks from +z towards −z) and `pitch` radians above the
    /// horizontal (keep it inside ±π/2: straight above or below, +y is
    /// along the view direction; use [`Camera::with_up`] there).
    ///
    /// ```
    /// use microraster::view3d::Camera;
    /// let cam = Camera::orbit([0.0; 3], 5.0, 0.0, 0.0);
    /// assert_eq!(cam.eye(), [0.0, 0.0, 5.0]);
    /// let side = Camera::orbit([0.0; 3], 5.0, core::f32::consts::FRAC_PI_2, 0.0);
    /// assert!((side.eye()[0] - 5.0).abs() < 1e-5 && side.eye()[2].abs() < 1e-5);
    /// ```
    pub fn orbit(target: [f32; 3], distance: f32, yaw: f32, pitch: f32) -> Self {
        let (sy, cy) = Scalar::sin_cos(yaw);
        let (sp, cp) = Scalar::sin_cos(pitch);
        let d = [cp * sy, sp, cp * cy];
        let eye = [0, 1, 2].map(|k| target[k] + distance * d[k]);
        Camera::look_at(eye, target)
    }

    /// The same camera with another up direction (not parallel to the view
    /// direction).
    pub const fn with_up(self, up: [f32; 3]) -> Self {
        Camera { up, ..self }
    }

    /// The same camera with a perspective lens: see [`Projection::Perspective`].
    pub const fn perspective(self, fov_y: f32, near: f32, far: f32) -> Self {
        Camera { projection: Projection::Perspective { fov_y, near, far }, ..self }
    }

    /// The same camera with an orthographic lens: see
    /// [`Projection::Orthographic`].
    pub const fn orthographic(self, height: f32, near: f32, far: f32) -> Self {
        Camera { projection: Projection::Orthographic { height, near, far }, ..self }
    }

    /// Where the camera is.
    pub const fn eye(&self) -> [f32; 3] {
        self.eye
    }

    /// The point the camera looks at.
    pub const fn target(&self) -> [f32; 3] {
        self.target
    }

    /// The world's up direction.
    pub const fn up(&self) -> [f32; 3] {
        self.up
    }

    /// The lens.
    pub const fn projection(&self) -> Projection {
        self.projection
    }

    /// The view matrix ([`transform::look_at`]).
    ///
    /// Errors: those of [`transform::look_at`] (NaN or infinite input:
    /// [`Error::NonFiniteCoordinate`]; eye on the target or up along the
    /// view direction: [`Error::InvalidParameter`]; a difference or entry
    /// that overflows `f32`, input near `f32::MAX`:
    /// [`Error::CoordinateOutOfRange`]).
    ///
    /// ```
    /// use microraster::{view3d::Camera, Error};
    /// assert!(Camera::look_at([0.0, 0.0, 3.0], [0.0; 3]).view().is_ok());
    /// assert_eq!(Camera::look_at([f32::NAN, 0.0, 3.0], [0.0; 3]).view(), Err(Error::NonFiniteCoordinate));
    /// assert_eq!(Camera::look_at([f32::MAX, 0.0, 0.0], [0.0; 3]).view(), Err(Error::CoordinateOutOfRange));
    /// ```
    pub fn view(&self) -> Result<Mat4<f32>, Error> {
        transform::look_at(Vec3::from_f32(self.eye), Vec3::from_f32(self.target), Vec3::from_f32(self.up))
    }

    /// The vertex stage for a `width × height` frame with 4 subpixel bits:
    /// [`Pipeline::perspective`] or [`Pipeline::new`] with
    /// [`transform::orthographic`], back faces culled (the pipeline's
    /// default), `lighting` if any.
    pub(crate) fn pipeline(
        &self,
        width: u32,
        height: u32,
        lighting: Option<Lighting<f32>>,
    ) -> Result<Pipeline<f32, 4>, Error> {
        let view = self.view()?;
        let mut p = match self.projection {
            Projection::Perspective { fov_y, near, far } => {
                Pipeline::perspective(view, fov_y, near, far, width, height)?
            }
            Projection::Orthographic { height: h, near, far } => {
                if !(h.is_finite() && h > 0.0) {
                    return Err(if h.is_finite() {
                        Error::InvalidParameter(Param::ViewBox)
                    } else {
                        Error::NonFiniteCoordinate
                    });
                }
                // The aspect ratio of a frame Pipeline::new accepts is finite.
                let half_w = 0.5 * h * width as f32 / height.max(1) as f32;
                let proj = transform::orthographic(-half_w, half_w, -0.5 * h, 0.5 * h, near, far)?;
                Pipeline::new(view, proj, 1.0, width, height)?
            }
        };
        p.lighting = lighting;
        Ok(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_lenses_are_errors() {
        let cam = Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]);
        assert!(cam.pipeline(32, 32, None).is_ok());
        assert!(cam.orthographic(2.0, 0.5, 10.0).pipeline(32, 24, None).is_ok());
        let e = |c: Camera| c.pipeline(32, 32, None).err();
        assert_eq!(e(cam.perspective(0.0, 0.5, 10.0)), Some(Error::InvalidParameter(Param::FieldOfView)));
        assert_eq!(e(cam.perspective(1.0, 2.0, 1.0)), Some(Error::InvalidParameter(Param::NearFar)));
        assert_eq!(e(cam.perspective(f32::NAN, 0.5, 10.0)), Some(Error::NonFiniteCoordinate));
        assert_eq!(e(cam.orthographic(0.0, 0.5, 10.0)), Some(Error::InvalidParameter(Param::ViewBox)));
        assert_eq!(e(cam.orthographic(f32::INFINITY, 0.5, 10.0)), Some(Error::NonFiniteCoordinate));
        assert_eq!(e(cam.orthographic(2.0, 5.0, 1.0)), Some(Error::InvalidParameter(Param::NearFar)));
        assert_eq!(e(cam.with_up([0.0, 0.0, 1.0])), Some(Error::InvalidParameter(Param::LookAt)));
        assert_eq!(cam.pipeline(0, 32, None).err(), Some(Error::InvalidFrameSize));
    }
}
