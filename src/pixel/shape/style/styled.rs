//! Styled shapes: a shape and its style, checked once when paired, then drawn
//! on a [`Canvas`] or any `DrawTarget`.

use super::ShapeStyle;
use crate::blend::div255_round;
use crate::shape::edges::{BITS, EdgeList};
use crate::shape::{Aliased, Canvas, Coverage, FillRule, MAX_EDGES, Shape, TargetCanvas};
use crate::{Error, Interpolate};
use embedded_graphics_core::Drawable;
use embedded_graphics_core::prelude::DrawTarget;

/// A shape with its style: checked once, then drawn with one call.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{Rect, Shape, ShapeStyle};
/// use microraster::{Band, Renderer};
/// use microraster::render::from_fn;
/// use embedded_graphics::mock_display::MockDisplay;
/// let bar = Rect::new(1.0, 0.0, 2.0, 2.0)?.styled(ShapeStyle::fill(Gray8::WHITE))?;
/// let mut band = Band::<Gray8, 4, 1>::new(Gray8::BLACK);
/// let mut display = MockDisplay::new();
/// Renderer::new(2, Gray8::BLACK).render(from_fn(|view| {  bar.draw_on(view); Ok(()) }), &mut band, &mut display).unwrap();
/// assert_eq!(display.get_pixel(embedded_graphics::prelude::Point::new(2, 1)), Some(Gray8::WHITE));
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Styled<S, C, A = Aliased> {
    shape: S,
    style: ShapeStyle<C, A>,
    // Pixel rows the fill and stroke can touch (half-open), so a band
    // that misses them costs two comparisons.
    rows: (i32, i32),
    // Fill and stroke each fit SMALL_EDGES: drawn with scratch arrays of
    // that size, not MAX_EDGES.
    small: bool,
}

/// Edge capacity of the scratch lists of a shape drawn with few edges. Every
/// draw zeroes its edge list and the coverage's per-edge arrays (56 bytes
/// per edge slot when anti-aliased); at [`MAX_EDGES`] that is 14 KB per shape
/// and band, most of a small shape's cost. Rectangles, lines, ticks and
/// small polygons fit 32.
const SMALL_EDGES: usize = 32;

impl<S: Shape, C: Copy, A: Coverage> Styled<S, C, A> {
    /// Checks the style and that the contours fit [`MAX_EDGES`].
    ///
    /// Errors: NaN anywhere ([`Error::NonFiniteCoordinate`]); a negative
    /// stroke width or a miter limit below 1 ([`Error::InvalidParameter`]);
    /// coordinates beyond the snapping range
    /// ([`Error::CoordinateOutOfRange`]); more than [`MAX_EDGES`] edges
    /// ([`Error::BufferTooSmall`]).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::{Error, shape::{Rect, ShapeStyle, Styled}};
    /// let rect = Rect::new(0.0, 0.0, 4.0, 4.0)?;
    /// assert!(Styled::new(rect, ShapeStyle::stroke(BinaryColor::On, 1.0)).is_ok());
    /// assert_eq!(Styled::new(rect, ShapeStyle::stroke(BinaryColor::On, -1.0)), Err(Error::InvalidParameter));
    /// assert_eq!(Styled::new(rect, ShapeStyle::stroke(BinaryColor::On, f32::NAN)), Err(Error::NonFiniteCoordinate));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(shape: S, style: ShapeStyle<C, A>) -> Result<Self, Error> {
        let (w, m) = (style.stroke_width, style.miter_limit);
        if !w.is_finite() || !m.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        if w < 0.0 || m < 1.0 {
            return Err(Error::InvalidParameter);
        }
        let mut s = Styled { shape, style, rows: (0, 0), small: true };
        // A shape that does not fit the small lists is built again in full
        // ones; any other error is the shape's, whatever the capacity.
        match s.extent::<SMALL_EDGES>() {
            Err(Error::BufferTooSmall) => (s.rows, s.small) = (s.extent::<MAX_EDGES>()?, false),
            r => s.rows = r?,
        }
        Ok(s)
    }

    /// The shape.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Circle, Shape, ShapeStyle};
    /// let disc = Circle::new((4.0, 4.0), 3.0)?;
    /// assert_eq!(disc.styled(ShapeStyle::fill(BinaryColor::On))?.shape(), &disc);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn shape(&self) -> &S {
        &self.shape
    }

    /// The style.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Circle, Shape, ShapeStyle};
    /// let ring = Circle::new((4.0, 4.0), 3.0)?.styled(ShapeStyle::stroke(BinaryColor::On, 2.0))?;
    /// assert_eq!(ring.style().stroke_width, 2.0);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn style(&self) -> &ShapeStyle<C, A> {
        &self.style
    }

    /// Pixel rows `.0 .. .1` (half-open) the fill and stroke can touch;
    /// `(0, 0)` for a shape that covers nothing. A band outside them is
    /// skipped at the cost of two comparisons. The bound rounds the edges'
    /// extent outward to whole rows, so it may hold one row the shape does not
    /// cover (an edge exactly on a row boundary); it never misses one.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::shape::{Rect, ShapeStyle, Styled};
    ///
    /// // y 2.25 .. 4.75 covers the pixel centres 2.5, 3.5 and 4.5: rows 2, 3, 4.
    /// let bar = Styled::new(Rect::new(0.0, 2.25, 8.0, 2.5)?, ShapeStyle::fill(Gray8::WHITE))?;
    /// assert_eq!(bar.rows(), (2, 5));
    /// // y 2.0 .. 5.0 covers the same centres; the bound holds row 5 as well.
    /// let bar = Styled::new(Rect::new(0.0, 2.0, 8.0, 3.0)?, ShapeStyle::fill(Gray8::WHITE))?;
    /// assert_eq!(bar.rows(), (2, 6));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn rows(&self) -> (i32, i32) {
        self.rows
    }

    /// The rows [`Self::rows`] reports, with edge lists of capacity `N`. Not
    /// inlined: a caller that builds many shapes holds no edge list on its
    /// stack.
    #[inline(never)]
    fn extent<const N: usize>(&self) -> Result<(i32, i32), Error> {
        let mut e = EdgeList::<N>::new();
        self.fill_edges(&mut e)?;
        let f = e.y_range();
        self.stroke_edges(&mut e)?;
        let t = e.y_range();
        let (y_min, y_max) = (f.0.min(t.0), f.1.max(t.1));
        // Subpixels to whole rows, outward; empty shapes get an empty range.
        Ok(if y_min <= y_max { (y_min >> BITS, (y_max >> BITS) + 1) } else { (0, 0) })
    }

    /// The fill's edges into `e` (emptied first), unsorted.
    fn fill_edges<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        e.clear();
        if self.style.fill.is_some() {
            self.shape.fill_contours(e)?;
            e.close()?;
        }
        Ok(())
    }

    /// The stroke's edges into `e` (emptied first), unsorted.
    fn stroke_edges<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        e.clear();
        if self.style.stroke.is_some() && self.style.stroke_width > 0.0 {
            self.shape.stroke_contours(e, &self.style.params())?;
            e.close()?;
        }
        Ok(())
    }
}

impl<S: Shape, C: Interpolate, A: Coverage> Styled<S, C, A> {
    /// Draws on `canvas` (a band view, or a readable framebuffer): fill
    /// first, then stroke; partial pixels are blended exactly.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, shape::{Rect, Shape, ShapeStyle}};
    /// // White inside x 1 .. 4, then a 2 px black outline on top (x 0 .. 2 and 3 .. 5).
    /// let style = ShapeStyle::fill(Gray8::WHITE).with_stroke(Gray8::BLACK, 2.0);
    /// let boxed = Rect::new(1.0, -2.0, 3.0, 5.0)?.styled(style)?;
    /// let mut band = Band::<Gray8, 6, 1>::new(Gray8::BLACK);
    /// boxed.draw_on(&mut band.view(0, 1, Gray8::new(9)));
    /// let [g, b, w] = [Gray8::new(9), Gray8::BLACK, Gray8::WHITE];
    /// assert_eq!(band.rows()[0], [b, b, w, b, b, g]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn draw_on<T: Canvas<C>>(&self, canvas: &mut T) {
        let clip = canvas.clip();
        if clip.y1() <= self.rows.0 || clip.y0() >= self.rows.1 {
            return;
        }
        if self.small { self.draw_in::<SMALL_EDGES, T>(canvas) } else { self.draw_in::<MAX_EDGES, T>(canvas) }
    }

    /// [`Self::draw_on`] with edge lists of capacity `N`, which `new` found
    /// the shape to fit. Each capacity its own frame, for the stack.
    #[inline(never)]
    fn draw_in<const N: usize, T: Canvas<C>>(&self, canvas: &mut T) {
        let clip = canvas.clip();
        let op = u32::from(self.style.opacity);
        // Coverage times opacity, rounded; exact (and free) when opaque.
        let alpha = |a: u8| if op == 255 { a } else { div255_round(u32::from(a) * op) as u8 };
        // One edge list for both. Checked in `new`: building the edges
        // cannot fail again.
        let mut e = EdgeList::<N>::new();
        if let (Some(paint), Ok(())) = (&self.style.fill, self.fill_edges(&mut e)) {
            e.sort_by_top();
            A::cover(&e, self.style.fill_rule, clip, |span, a| paint.paint(canvas, span, alpha(a)));
        }
        if let (Some(paint), Ok(())) = (&self.style.stroke, self.stroke_edges(&mut e)) {
            e.sort_by_top();
            A::cover(&e, FillRule::NonZero, clip, |span, a| paint.paint(canvas, span, alpha(a)));
        }
    }
}

/// Draws into any `DrawTarget` (see [`TargetCanvas`] for partial pixels,
/// which a `DrawTarget` cannot read back).
impl<S: Shape, C: Interpolate, A: Coverage> Drawable for Styled<S, C, A> {
    type Color = C;
    type Output = ();

    fn draw<D: DrawTarget<Color = C>>(&self, target: &mut D) -> Result<(), D::Error> {
        let mut canvas = TargetCanvas::new(target);
        self.draw_on(&mut canvas);
        canvas.finish()
    }
}
