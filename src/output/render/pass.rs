//! What a frame draws: a [`Pass`] draws the frame's content into one band at
//! a time, and every band loop ([`Renderer::render`], `render_linked`,
//! `render_async`, `render_threads`) takes one. Options are values of the
//! pass (depth state, interpolation, an overlay, anti-aliasing), so there is
//! one way to render a frame and no turbofish.
//!
//! | pass | draws |
//! |---|---|
//! | `&[Primitive]`, `&[Primitive; N]`, `&heapless::Vec<Primitive, N>` | 2D triangles and lines |
//! | [`Binned2d`](super::Binned2d) | the same, each band reading only its primitives (an index you own) |
//! | `()` | nothing: the background |
//! | [`Triangles3d`] | screen triangles from the vertex stage, depth-tested |
//! | [`Direct3d`] | a closure that draws each band as a [`Band3d`](super::Band3d) (meshlets, or the vertex stage per band) |
//! | [`from_fn`] | a closure that draws each band as a [`BandView`] (e-g drawables) |
//! | [`Pass::then`] | one pass, then another closure over it (a HUD) |
//! | [`Antialiased`](crate::aa::Antialiased), [`Supersampled`](crate::aa::Supersampled) | anti-aliased frames |

mod pass3d;
pub use pass3d::{Direct3d, Triangles3d};

use core::marker::PhantomData;

use super::Renderer;
use crate::band::{BandView, LazyClear};
use crate::{Error, Interpolate, Primitive};

/// What a frame draws in each band of `W × H` pixels.
///
/// The renderer calls [`Pass::check`] once before anything is sent, then
/// [`Pass::draw`] for each band in order, top to bottom. A pass draws the
/// whole frame in frame coordinates; the band keeps its own rows, so the
/// image does not depend on `H`. After the first error the remaining bands
/// are not drawn (they go out cleared) and the frame returns
/// [`RenderError::Input`](crate::RenderError::Input) with it.
///
/// A pass of your own: a checkerboard of `size`-pixel squares, refused
/// before anything is sent if `size` is 0.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::band::BandView;
/// use microraster::blit::Blitter;
/// use microraster::render::Pass;
/// use microraster::{Band, Error, Param, Renderer};
/// struct Checkers(i32);
/// impl<const W: usize, const H: usize> Pass<BinaryColor, W, H> for Checkers {
///     fn check(&mut self, _: &Renderer<BinaryColor>) -> Result<(), Error> {
///         if self.0 > 0 { Ok(()) } else { Err(Error::InvalidParameter(Param::User)) }
///     }
///     fn draw(&mut self, band: &mut BandView<'_, BinaryColor, W>, _: &Renderer<BinaryColor>) -> Result<(), Error> {
///         for y in band.y0()..band.y1() {
///             for x in (0..W as i32).filter(|x| (x / self.0 + y / self.0) % 2 == 1) {
///                 band.set_pixel(x, y, BinaryColor::On);
///             }
///         }
///         Ok(())
///     }
/// }
/// let mut band = Band::<BinaryColor, 4, 3>::new(BinaryColor::Off);
/// let mut display = MockDisplay::new();
/// let renderer = Renderer::new(4, BinaryColor::Off);
/// renderer.render(Checkers(2), &mut band, &mut display)?;
/// display.assert_pattern(&["..##", "..##", "##..", "##.."]);
/// let refused = renderer.render(Checkers(0), &mut band, &mut MockDisplay::new());
/// assert_eq!(refused, Err(Error::InvalidParameter(Param::User).into()));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub trait Pass<C: Interpolate, const W: usize, const H: usize> {
    /// Whether the renderer clears each band to the background before
    /// [`Pass::draw`]; a pass that writes every pixel of the band itself,
    /// even when it returns an error, says `false`.
    const CLEARS: bool = true;

    /// Whether [`Pass::draw`] accepts a band at any frame row, not only at
    /// a multiple of `H` (a pass with per-band state indexed by `y0 / H`,
    /// as [`Binned2d`](super::Binned2d), says `false`). A damaged frame
    /// ([`Renderer::render_damaged`](crate::Renderer::render_damaged))
    /// packs the damaged rows of a pass that says `true` into as few bands
    /// as they fill. `false` unless a pass says otherwise.
    const ANY_ROWS: bool = false;

    /// Checks the pass against the frame before any band is drawn: errors
    /// here leave the target untouched.
    fn check(&mut self, renderer: &Renderer<C>) -> Result<(), Error> {
        let _ = renderer;
        Ok(())
    }

    /// Draws frame rows `band.y0()..band.y0() + band.height()` into `band`.
    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error>;

    /// This pass, then `overlay` over it in each band: a HUD over a 3D frame,
    /// in frame coordinates, with any `embedded-graphics` drawable. The
    /// overlay ignores depth. After the first error of either, later bands
    /// are not drawn. (On a pass whose type does not fix the band height,
    /// such as a slice of primitives, name it: `Pass::<C, W, H>::then(&scene, ..)`;
    /// or draw the overlay in the same [`from_fn`] pass.)
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::prelude::*;
    /// use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use microraster::depth::{Depth16, DepthBand, DepthState};
    /// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
    /// use microraster::render::{Pass, Triangles3d};
    /// use microraster::{Band, Renderer, SubPoint};
    /// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), color: [31, 0, 0], ..Default::default() };
    /// let red = [ScreenTriangle { v: [v(0, 0), v(8, 0), v(0, 8)], flat: true }];
    /// let mut band = Band::<Rgb565, 8, 2>::new(Rgb565::BLACK);
    /// let mut depth = DepthBand::<Depth16, 8, 2>::new();
    /// let mut display = MockDisplay::new();
    /// let hud = PrimitiveStyle::with_fill(Rgb565::WHITE);
    /// let frame = Triangles3d::new(&red, &mut depth, DepthState::LESS_WRITE, Affine)
    ///     .then(|view| Ok(Rectangle::new(Point::new(0, 0), Size::new(2, 2)).into_styled(hud).draw(view)?));
    /// Renderer::new(8, Rgb565::BLACK).render(frame, &mut band, &mut display)?;
    /// assert_eq!(display.get_pixel(Point::new(1, 1)), Some(Rgb565::WHITE)); // the HUD, over
    /// assert_eq!(display.get_pixel(Point::new(3, 1)), Some(Rgb565::RED)); // the triangle
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    fn then<O>(self, overlay: O) -> Then<Self, O>
    where
        Self: Sized,
        O: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
    {
        Then { first: self, overlay }
    }
}

/// The empty frame: every band cleared to the background.
impl<C: Interpolate, const W: usize, const H: usize> Pass<C, W, H> for () {
    const ANY_ROWS: bool = true;

    fn draw(&mut self, _: &mut BandView<'_, C, W>, _: &Renderer<C>) -> Result<(), Error> {
        Ok(())
    }
}

/// 2D primitives in order, triangles culled as the renderer's
/// [`Cull`](crate::edge::Cull) says.
impl<C: Interpolate, const S: u32, const W: usize, const H: usize> Pass<C, W, H> for &[Primitive<C, S>] {
    // Rows are cleared as they are first written (`LazyClear`): most rows'
    // first span then costs one pass over the row, not two.
    const CLEARS: bool = false;
    const ANY_ROWS: bool = true;

    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        let mut view = LazyClear::<C, W, H>::new(band, renderer.background());
        draw_prims(self.iter(), &mut view, renderer);
        view.finish();
        Ok(())
    }
}

/// Draws those of `prims` that touch `view`'s rows, in order: the body of
/// the slice pass and of [`Binned2d`](super::Binned2d).
#[inline(always)]
pub(super) fn draw_prims<'p, C: Interpolate + 'p, const S: u32, const W: usize, const H: usize>(
    prims: impl Iterator<Item = &'p Primitive<C, S>>,
    view: &mut LazyClear<'_, '_, C, W, H>,
    renderer: &Renderer<C>,
) {
    let (y0, y1) = (view.view().y0(), view.view().y1());
    for prim in prims {
        let (lo, hi) = prim.rows();
        if lo < y1 && hi >= y0 {
            match prim {
                Primitive::Triangle(t) => t.draw(view, renderer.cull()),
                // Pixel by pixel: clear the line's rows once, then no checks.
                Primitive::Line(l) => {
                    view.clear_rows(lo, hi);
                    l.draw(view.view());
                }
            }
        }
    }
}

/// An array of primitives, as its slice.
impl<C: Interpolate, const S: u32, const N: usize, const W: usize, const H: usize> Pass<C, W, H>
    for &[Primitive<C, S>; N]
{
    const CLEARS: bool = false;
    const ANY_ROWS: bool = true;

    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        Pass::<C, W, H>::draw(&mut &self[..], band, renderer)
    }
}

/// A `heapless::Vec` of primitives, as its slice.
impl<C: Interpolate, const S: u32, const N: usize, const W: usize, const H: usize> Pass<C, W, H>
    for &heapless::Vec<Primitive<C, S>, N>
{
    const CLEARS: bool = false;
    const ANY_ROWS: bool = true;

    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        Pass::<C, W, H>::draw(&mut &self[..], band, renderer)
    }
}

/// A pass from a closure that draws the frame's content into each band, in
/// frame coordinates: any `embedded-graphics` drawable (the band is a
/// `DrawTarget`), microraster's primitives through
/// [`Blitter`](crate::blit::Blitter), [`draw_triangle`](crate::raster3d::draw_triangle)
/// with your own depth band. The band is cleared to the background first.
/// e-g's draw errors convert with `?` (a band's is `Infallible`).
///
/// The closure draws the whole frame's 2D in each band: e-g clips by pixel,
/// so a drawable's pixels outside the band are generated and dropped; skip
/// drawables whose bounding box misses the band's
/// [`bounding_box`](embedded_graphics_core::geometry::Dimensions::bounding_box)
/// to avoid that.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::prelude::*;
/// use embedded_graphics::primitives::{Circle, PrimitiveStyle};
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::render::from_fn;
/// use microraster::{edge::Cull, Band, Renderer, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let mut band = Band::<BinaryColor, 8, 3>::new(BinaryColor::Off); // 3-row bands
/// let mut display = MockDisplay::new();
/// let frame = from_fn(|view| {
///     Triangle::flat([p(0, 0), p(5, 0), p(0, 5)], BinaryColor::On).draw(view, Cull::None);
///     Circle::new(Point::new(4, 4), 4).into_styled(PrimitiveStyle::with_fill(BinaryColor::On)).draw(view)?;
///     Ok(())
/// });
/// Renderer::new(8, BinaryColor::Off).render(frame, &mut band, &mut display)?;
/// display.assert_pattern(&[
///     "####....", "###.....", "##......", "#.......",
///     ".....##.", "....####", "....####", ".....##.",
/// ]);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub fn from_fn<C, const W: usize, G>(draw: G) -> FromFn<C, G, W>
where
    C: Interpolate,
    G: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
{
    FromFn { draw, _c: PhantomData }
}

/// The pass of [`from_fn`].
pub struct FromFn<C, G, const W: usize> {
    draw: G,
    _c: PhantomData<fn(C)>,
}

impl<C, G, const W: usize, const H: usize> Pass<C, W, H> for FromFn<C, G, W>
where
    C: Interpolate,
    G: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
{
    // Frame coordinates: the closure sees the view's rows, wherever they start.
    const ANY_ROWS: bool = true;

    fn draw(&mut self, band: &mut BandView<'_, C, W>, _: &Renderer<C>) -> Result<(), Error> {
        (self.draw)(band)
    }
}

/// The pass of [`Pass::then`]: `first`, then `overlay` in each band.
pub struct Then<P, O> {
    first: P,
    overlay: O,
}

impl<C, P, O, const W: usize, const H: usize> Pass<C, W, H> for Then<P, O>
where
    C: Interpolate,
    P: Pass<C, W, H>,
    O: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
{
    const CLEARS: bool = P::CLEARS;
    const ANY_ROWS: bool = P::ANY_ROWS;

    fn check(&mut self, renderer: &Renderer<C>) -> Result<(), Error> {
        self.first.check(renderer)
    }

    fn draw(&mut self, band: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        self.first.draw(band, renderer)?;
        (self.overlay)(band)
    }
}
