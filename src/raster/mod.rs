//! The raster stage: exact coverage and interpolation (snapping, the
//! integer edge functions with the top-left rule, midpoint lines, screen
//! triangles and their attribute planes).
pub(crate) mod attr;
pub mod clip;
pub mod edge;
pub mod line;
pub mod primitive;
pub mod raster3d;
pub mod subpixel;
pub mod varyings;
