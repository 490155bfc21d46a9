//! The 3D path's accuracy tier: [`Precision::Exact`] (the default, every
//! value rounded from exact arithmetic) or [`Precision::Fast`] (cheaper
//! arithmetic with stated error bounds). Coverage is exact and watertight in
//! both: a tier changes how vertices are snapped and how depth and colour
//! are computed, never how the integer edge functions decide a pixel.

/// Which accuracy tier the 3D path runs in ([`Pipeline::precision`](crate::pipeline::Pipeline)).
///
/// ```
/// use microraster::raster3d::Precision;
/// assert_eq!(Precision::default(), Precision::Exact);
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Precision {
    /// Every snapped position, depth and colour rounded from exact
    /// arithmetic: the library's reference pixels.
    #[default]
    Exact,
    /// Cheaper vertex and pixel arithmetic with bounded error against
    /// [`Precision::Exact`]; coverage stays exact for its own snapped
    /// vertices, so closed meshes stay watertight.
    Fast,
}

/// [`Precision`] as a type: each tier's pixel loop is compiled on its own
/// (a runtime tier is matched once per triangle, in `Band3d::draw_in`).
pub(crate) trait Tier: sealed::Sealed + Copy + Default {
    /// True for [`Precision::Fast`].
    const FAST: bool;
}

/// [`Precision::Exact`] as a type.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct ExactTier;

/// [`Precision::Fast`] as a type.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct FastTier;

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::ExactTier {}
    impl Sealed for super::FastTier {}
}

impl Tier for ExactTier {
    const FAST: bool = false;
}
impl Tier for FastTier {
    const FAST: bool = true;
}
