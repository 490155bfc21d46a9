//! Numbers, vectors and matrices for the vertex stage.

// Without `fx`, the 16.16 helpers have no caller left.
#[cfg_attr(not(feature = "fx"), allow(dead_code, unused_imports))]
pub mod divisor;
pub mod mat;
pub mod scalar;
pub mod transform;
#[cfg_attr(not(feature = "fx"), allow(dead_code, unused_imports))]
pub(crate) mod unit;
pub mod vec;

pub use mat::{Mat3, Mat4};
#[cfg(feature = "fx")]
pub use scalar::Fx;
pub use scalar::Scalar;
pub use transform::Viewport;
pub use vec::{Vec3, Vec4};
