//! The 3D fragment loop: coverage from [`TriangleSpans`], then per pixel a
//! depth test against the band's z-buffer and a colour, flat, affine or
//! perspective-correct.
//!
//! # What is interpolated, and how
//! * **Depth** `d = z/w` is linear in screen space, so it is a plane in units
//!   of 2^-16 depth steps ([`DEPTH_FRAC`]); the stored value is that plane
//!   rounded to nearest. Interpolation error is below 2^13 units (see
//!   `attr`), i.e. 1/8 of a depth step, before the final rounding.
//! * **Colour**, affine ([`Affine`]): each channel is a screen-space plane,
//!   exactly as 2D Gouraud (within 0.5 + 2^-7 of the screen-linear value).
//! * **Colour**, perspective-correct ([`PerspectiveCorrect`]): `q = 1/w`
//!   (normalised per triangle to 23 bits) and `c·q` are planes; each pixel
//!   divides `c = (c·q)/q`.
//!
//! # Per-pixel cost (beyond writing the colour)
//! | choice | adds | other |
//! |---|---|---|
//! | no depth ([`NoDepth`](crate::depth::NoDepth)) | 0 | — |
//! | depth, up to 16 bits | 1 (`u32`) | shift, compare, store |
//! | depth, 24 or 32 bits | 1 (`i64`) | clamp, shift, compare, store |
//! | flat colour | 0 | — |
//! | affine colour | 3 (`i32`) | 3 bit-field extracts (`shade`: 3 shifts and clamps for hand-made channels above the maximum) |
//! | perspective-correct colour | 4 (`i64`) | 3 `u32` divisions |
//!
//! The narrow accumulators give exactly the values of the `i64` planes (see
//! [`draw_triangle`]'s helpers): the error bounds below keep every sampled
//! value in their range. Variants (and the common depth state
//! [`DepthState::LESS_WRITE`]) are chosen by type (the depth rows' format,
//! the interpolation's type), so the loop a scene does not use is not
//! compiled.
//!
//! # Accuracy tiers
//! [`draw_triangle_in`] takes a [`Precision`]. [`Precision::Exact`] is what
//! this page describes. [`Precision::Fast`] has the same coverage, maps a
//! tiny triangle's vertex depths with two shifts (each code within one of
//! the exact tier's), and chooses colour once per triangle where that pays:
//! a triangle above the tiny size, or a tiny perspective-correct one, whose
//! vertex channels lie within 2 of each other is one colour (the middle of
//! each range, `tiny::fast`); a perspective-correct one whose `1/w` barely
//! differ is drawn screen-linear. A tiny affine triangle keeps the exact
//! tier's colour (choosing cost more than it saved). Each channel stays
//! within one step of the exact tier's (`tests/integration/fast_raster.rs`).
//!
//! # Set-up cost
//! Per triangle and band: the edge functions (for a small triangle in `i32`
//! only, see [`crate::edge`]), one determinant with its reciprocal, and per
//! plane three exact divisions done as multiplications (`attr`); a depth
//! plane only with a depth buffer, colour planes only for Gouraud triangles
//! (and, for one with a single span in the band, only once its depth test
//! passes at one of its pixels). Nothing is cached between bands (no RAM
//! per triangle).
//!
//! A tiny triangle (twice its area below 2^16 internal units: under 32 px²
//! at 4 subpixel bits) with depth of at most 16 bits has no planes: each
//! covered pixel divides its exact barycentric sums by the area (`tiny`,
//! where its bounds are derived; they lie inside the ones above, and a
//! value may differ by one unit from the plane's where the exact value is
//! that close to a rounding tie).

use crate::attr::{PlaneFrame, PlaneSetup};
use crate::band::BandView;
use crate::depth::{DepthFormat, DepthRows, DepthState};
use crate::edge::{Cull, TriangleSpans};
use crate::primitive::{center_rows, reference_pixel};
use crate::{ClipRect, Interpolate, SubPoint};

mod depth_span;
mod precision;
mod shade;
mod spans;
mod tiny;

use depth_span::{DepthRule, LessWrite};
pub(crate) use depth_span::{depth_steps, depth_steps_approx, depth_value};
pub use precision::Precision;
pub(crate) use precision::{ExactTier, FastTier, Tier};

use spans::shade_spans;

/// Fixed-point units per depth step in the depth plane.
pub const DEPTH_FRAC: u32 = 16;

/// Bits `q = 1/w` is normalised to within each triangle.
const Q_BITS: u32 = 23;

/// A vertex after the vertex stage, ready for rasterization.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ScreenVertex<const S: u32> {
    /// Snapped screen position.
    pub pos: SubPoint<S>,
    /// Depth `z/w ∈ [0, 1]` as `round(z/w · (2^32 − 1))`: 0 at the near plane,
    /// `u32::MAX` at the far plane.
    pub depth: u32,
    /// `1/w` up to a factor common to the frame (the pipeline uses
    /// `2^30 · n / w` with `n` the near distance); only ratios matter.
    pub inv_w: u32,
    /// Colour channels in the target colour's native depth
    /// ([`Interpolate::to_channels`]), each at most its
    /// [`Interpolate::CHANNEL_MAX`]; a larger one is interpolated as given
    /// and each pixel's channel clamped to the maximum.
    pub color: [u8; 3],
}

/// A triangle after the vertex stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ScreenTriangle<const S: u32> {
    /// The vertices, in the winding they had (both windings are drawn here;
    /// culling happened in the vertex stage on the same snapped area).
    pub v: [ScreenVertex<S>; 3],
    /// Use vertex 0's colour for the whole triangle.
    pub flat: bool,
}

impl<const S: u32> ScreenTriangle<S> {
    /// The plane set-up shared by all attributes of the triangle, referenced
    /// at a band-independent pixel (see `attr`); `None` for zero area.
    #[inline(always)]
    pub(crate) fn plane_setup(&self) -> Option<PlaneSetup> {
        let frame =
            PlaneFrame { v: self.v.map(|v| (2 * v.pos.x() as i64, 2 * v.pos.y() as i64)), shift: S + 1 };
        let (rx, ry) = reference_pixel(self.v[0].pos);
        PlaneSetup::new(&frame, rx, ry)
    }

    /// The depth values of the vertices in 2^-[`DEPTH_FRAC`] steps of format `F`.
    pub(crate) fn depth_values<F: DepthFormat>(&self) -> [i64; 3] {
        self.v.map(|v| depth_steps(v.depth, F::MAX))
    }

    /// Inclusive range of pixel rows the triangle can touch.
    pub fn rows(&self) -> (i32, i32) {
        let ys = self.v.map(|v| v.pos.y());
        center_rows::<S>(ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]))
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Affine {}
    impl Sealed for super::PerspectiveCorrect {}
}

/// How per-vertex colour is interpolated: [`Affine`] or [`PerspectiveCorrect`].
pub trait Interpolation: sealed::Sealed + Copy + Default {
    /// True for perspective-correct interpolation.
    const PERSPECTIVE: bool;
}

/// Screen-space (affine) interpolation: cheaper, skews on slanted surfaces.
/// A value, passed to the render entry points (no turbofish):
///
/// ```
/// use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect};
/// assert!(!Affine::PERSPECTIVE && PerspectiveCorrect::PERSPECTIVE);
/// # use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Gray8};
/// # use microraster::{Band, Renderer, depth::{Depth16, DepthBand, DepthState}};
/// use microraster::render::Triangles3d;
/// # let (mut band, mut depth) = (Band::<Gray8, 8, 4>::new(Gray8::new(0)), DepthBand::<Depth16, 8, 4>::new());
/// # let tris: [microraster::raster3d::ScreenTriangle<4>; 0] = [];
/// # let mut display = MockDisplay::new();
/// Renderer::new(8, Gray8::new(0)).render(Triangles3d::new(&tris, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut display)?;
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct Affine;

/// Perspective-correct interpolation: one division per channel and pixel.
/// A value, passed to the render entry points (no turbofish):
///
/// ```
/// use microraster::raster3d::{Interpolation, PerspectiveCorrect};
/// # use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Gray8};
/// # use microraster::{Band, Renderer, depth::{Depth16, DepthBand, DepthState}};
/// use microraster::render::Direct3d;
/// # let (mut band, mut depth) = (Band::<Gray8, 8, 4>::new(Gray8::new(0)), DepthBand::<Depth16, 8, 4>::new());
/// # let mut display = MockDisplay::new();
/// Renderer::new(8, Gray8::new(0)).render(Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |_band| Ok(())), &mut band, &mut display)?;
/// assert!(PerspectiveCorrect::PERSPECTIVE);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct PerspectiveCorrect;

impl Interpolation for Affine {
    const PERSPECTIVE: bool = false;
}
impl Interpolation for PerspectiveCorrect {
    const PERSPECTIVE: bool = true;
}

/// Rasterizes `tri` into a band's colour and depth rows, colour
/// interpolated as `interp` says ([`Affine`] or [`PerspectiveCorrect`]).
/// `depth` holds the depth rows of the view's rows, first to last
/// ([`DepthBand::rows_mut`](crate::depth::DepthBand::rows_mut)); a row it
/// lacks is not drawn (with [`NoDepth`](crate::depth::NoDepth), pass
/// [`DepthRows::none`]). Every parameter is inferred from the arguments.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex, draw_triangle};
/// use microraster::{Band, SubPoint};
/// let v = |x, y| ScreenVertex {
///     pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
///     color: [200, 0, 0],
///     inv_w: 1 << 30,
///     ..Default::default()
/// };
/// let tri = ScreenTriangle { v: [v(0, 0), v(8, 0), v(0, 4)], flat: true };
/// let mut band = Band::<Gray8, 8, 4>::new(Gray8::BLACK);
/// let mut depth = DepthBand::<Depth16, 8, 4>::new();
/// let mut view = band.view(0, 4, Gray8::BLACK);
/// draw_triangle(&tri, &mut view, &mut depth.rows_mut(4), DepthState::LESS_WRITE, Affine);
/// assert_eq!(view.pixels().next(), Some(Gray8::new(200)));
/// assert_eq!(depth.get(0, 0), Some(0)); // depth 0: at the near plane
/// ```
pub fn draw_triangle<C, F, M, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    depth: &mut DepthRows<'_, F, W>,
    state: DepthState,
    interp: M,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    let clip = crate::blit::Blitter::clip(color);
    draw_tier::<C, F, M, ExactTier, S, W>(tri, color, clip, depth, state, interp);
}

/// [`draw_triangle`] in accuracy tier `precision`: [`Precision::Exact`]
/// draws the same pixels; [`Precision::Fast`] the same coverage, with each
/// depth within one code and each colour channel within one step of the
/// exact tier's (`tests/integration/fast_raster.rs`).
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::raster3d::{Affine, Precision, ScreenTriangle, ScreenVertex, draw_triangle_in};
/// use microraster::{Band, SubPoint};
/// let v = |x, y, g| ScreenVertex {
///     pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
///     color: [0, g, 0],
///     inv_w: 1 << 30,
///     depth: 1 << 31,
/// };
/// let tri = ScreenTriangle { v: [v(0, 0, 0), v(8, 0, 63), v(0, 4, 0)], flat: false };
/// let mut band = Band::<Rgb565, 8, 4>::new(Rgb565::BLACK);
/// let mut depth = DepthBand::<Depth16, 8, 4>::new();
/// let mut view = band.view(0, 4, Rgb565::BLACK);
/// draw_triangle_in(&tri, &mut view, &mut depth.rows_mut(4), DepthState::LESS_WRITE, Affine, Precision::Fast);
/// let g = view.pixels().nth(2).unwrap().g(); // 2.5/8 of the way to 63: 19.7
/// assert!((19..=21).contains(&g));
/// assert!(depth.get(0, 0).unwrap().abs_diff(0x8000) <= 1);
/// ```
pub fn draw_triangle_in<C, F, M, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    depth: &mut DepthRows<'_, F, W>,
    state: DepthState,
    interp: M,
    precision: Precision,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    let clip = crate::blit::Blitter::clip(color);
    draw_clipped(tri, color, clip, depth, state, interp, precision);
}

/// [`draw_triangle_in`] with the view's clip rectangle made by the caller
/// ([`Blitter::clip`](crate::blit::Blitter::clip) of `color`), once per band
/// rather than once per triangle (its clamps cost a few percent of a dense
/// mesh's frame).
#[inline(always)]
pub(crate) fn draw_clipped<C, F, M, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    clip: ClipRect,
    depth: &mut DepthRows<'_, F, W>,
    state: DepthState,
    interp: M,
    precision: Precision,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    match precision {
        Precision::Exact => draw_tier::<C, F, M, ExactTier, S, W>(tri, color, clip, depth, state, interp),
        Precision::Fast => draw_tier::<C, F, M, FastTier, S, W>(tri, color, clip, depth, state, interp),
    }
}

/// [`draw_triangle`] in tier `P`, clipped to `clip` (the view's). Out of
/// line, one function per tier: the vertex stage that calls it per
/// triangle was tuned with one call here, and the exact tier's loop keeps
/// its own registers and stack frame.
#[inline(never)]
fn draw_tier<C, F, M, P, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    clip: ClipRect,
    depth: &mut DepthRows<'_, F, W>,
    state: DepthState,
    interp: M,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    P: Tier,
{
    let _ = interp; // a value, so the call needs no turbofish
    let depth: &mut [[F::Storage; W]] = depth;
    let v = tri.v.map(|v| v.pos);
    // A small triangle (most of a dense mesh's) keeps its coverage state in
    // this frame: stored into a `TriangleSpans` and read back, it cost a
    // few dozen loads and stores per triangle.
    match crate::edge::small::setup_state(v, clip, Cull::None) {
        Some(Some(mut small)) => {
            // Most of a dense mesh's: no plane set-up (`tiny`).
            if tiny::eligible::<F>(&small) {
                return tiny::draw::<C, F, M, P, S, W>(tri, &small, color, depth, state);
            }
            let Some(first) = small.next_span() else { return };
            let second = small.next_span();
            shade_spans::<C, F, M, P, S, W, _>(tri, (first, second, &small), color, depth, state);
        }
        Some(None) => {}
        None => {
            let mut spans = TriangleSpans::solved(v, clip, Cull::None);
            let Some(first) = spans.next() else { return };
            let second = spans.next();
            shade_spans::<C, F, M, P, S, W, _>(tri, (first, second, &spans), color, depth, state);
        }
    }
}

/// The triangle's `1/w` values scaled by a common power of two so the largest
/// has `bits` bits (rounding only if a value must shift right): ratios are all
/// that matter, and the products with interpolated values stay bounded.
///
/// In `u32` (`bits` of 1 to 31): a value shifted left stays below 2^`bits`,
/// and one shifted right by `k` is rounded half up as
/// `⌊q / 2^k⌋ + (bit k − 1 of q)`, which is `⌊(q + 2^(k−1)) / 2^k⌋`
/// without the sum's 33rd bit (64-bit shifts are several instructions on
/// the Cortex-M; tested against the `u64` form).
pub(crate) fn normalised_q<const S: u32>(tri: &ScreenTriangle<S>, bits: u32) -> [i64; 3] {
    debug_assert!((1..=31).contains(&bits));
    let qmax = tri.v.iter().map(|v| v.inv_w).max().unwrap_or(0).max(1);
    let shift = bits as i32 - (32 - qmax.leading_zeros()) as i32;
    tri.v.map(|v| {
        let q = v.inv_w;
        let q = if shift >= 0 {
            q << shift
        } else {
            // 1 ≤ k ≤ 32 − bits ≤ 31.
            let k = shift.unsigned_abs();
            (q >> k) + ((q >> (k - 1)) & 1)
        };
        q.max(1) as i64
    })
}
