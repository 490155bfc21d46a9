//! The pixel stage, opt-in (cargo features `fragment`, `textures`,
//! `shapes`): per-pixel work beside the raster stage (fragment shaders,
//! blending, anti-aliasing, anti-aliased lines; with `textures` textures
//! and sprites, with `shapes` the 2D shapes built on exact coverage).
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod aa;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod blend;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod fragment;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod line_aa;
#[cfg(feature = "shapes")]
#[cfg_attr(docsrs, doc(cfg(feature = "shapes")))]
pub mod shape;
#[cfg(feature = "textures")]
#[cfg_attr(docsrs, doc(cfg(feature = "textures")))]
pub mod texture;
