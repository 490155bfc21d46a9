//! The raster stage: exact coverage and interpolation (snapping, the
//! integer edge functions with the top-left rule, midpoint lines, screen
//! triangles and their attribute planes).
pub(crate) mod attr;
pub(crate) mod clip;
pub mod edge;
pub mod line;
pub(crate) mod primitive;
pub mod raster3d;
pub(crate) mod subpixel;
pub mod varyings;
