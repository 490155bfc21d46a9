//! Numbers, vectors and matrices for the vertex stage.

pub mod divisor;
pub mod mat;
pub mod scalar;
pub mod transform;
pub(crate) mod unit;
pub mod vec;

pub use mat::{Mat3, Mat4};
pub use scalar::{Fx, Scalar};
pub use transform::Viewport;
pub use vec::{Vec3, Vec4};
