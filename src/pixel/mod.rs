//! The pixel stage, opt-in (cargo feature `fragment`): per-pixel work
//! beside the raster stage (fragment shaders, textures and sprites,
//! blending, anti-aliasing, anti-aliased lines and the 2D shapes built on
//! exact coverage).
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod aa;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod blend;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod fragment;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod line_aa;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod shape;
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub mod texture;
