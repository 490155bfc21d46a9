//! Styled shapes: a shape and its style, checked once when paired, then drawn
//! on a [`Canvas`] or any `DrawTarget`.

use super::ShapeStyle;
use crate::blend::div255_round;
use crate::edge::Span;
use crate::shape::Runs;
use crate::shape::edges::{BITS, EdgeList, snap};
use crate::shape::scan::{Chains, first_row};
use crate::shape::{Aliased, Canvas, Coverage, FillRule, MAX_EDGES, Shape, TargetCanvas};
use crate::{Error, Interpolate, Param};
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
    // Pixel columns they can touch, likewise: a narrowed clip (a damaged
    // frame's columns, a narrow canvas) that misses them costs two more.
    cols: (i32, i32),
    // A part has more than `SMALL_EDGES` edges (measured by `new`; false
    // when only bounded by `Shape::reach`): drawn whole, it goes straight to
    // the large list instead of filling the small one first.
    big: bool,
}

/// Edge capacity of the scratch lists a part (fill or stroke) is first
/// drawn with. Every draw zeroes its edge list and the coverage's per-edge
/// arrays (64 bytes per edge slot when anti-aliased); at [`MAX_EDGES`] that
/// is 16 KB per shape and band, most of a small shape's cost. Rectangles,
/// lines, ticks and small polygons fit 32, and so do the edges of a large
/// shape that cross one band's rows, mostly; a part with more there is built
/// again in a list of [`MAX_EDGES`].
const SMALL_EDGES: usize = 32;

impl<S: Shape, C: Copy, A: Coverage> Styled<S, C, A> {
    /// Checks the style and that the contours fit [`MAX_EDGES`]: by
    /// measuring the contours (building them without storing them), or for
    /// polylines, polygons, arcs and rounded rectangles from the geometry
    /// alone (a bound on their extent and edge count, [`Self::rows`]), which
    /// is cheaper still.
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
    /// assert_eq!(Styled::new(rect, ShapeStyle::stroke(BinaryColor::On, -1.0)), Err(Error::InvalidParameter(microraster::Param::StrokeWidth)));
    /// assert_eq!(Styled::new(rect, ShapeStyle::stroke(BinaryColor::On, f32::NAN)), Err(Error::NonFiniteCoordinate));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(shape: S, style: ShapeStyle<C, A>) -> Result<Self, Error> {
        let (w, m) = (style.stroke_width, style.miter_limit);
        if !w.is_finite() || !m.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        if w < 0.0 {
            return Err(Error::InvalidParameter(Param::StrokeWidth));
        }
        if m < 1.0 {
            return Err(Error::InvalidParameter(Param::MiterLimit));
        }
        let mut s = Styled { shape, style, rows: (0, 0), cols: (0, 0), big: false };
        // A shape that bounds its edges from its geometry (polylines and
        // polygons) is checked without building them: drawn in every band
        // of a frame, a shape outside the band then costs next to nothing.
        let stroke = (s.style.stroke.is_some() && w > 0.0).then(|| s.style.params());
        (s.rows, s.cols, s.big) = match s.shape.reach(s.style.fill.is_some(), stroke.as_ref()) {
            Some(r) => (r.rows, r.cols, false),
            None => s.measure().map(|(rows, cols, n)| (rows, cols, n > SMALL_EDGES))?,
        };
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
    /// skipped at the cost of two comparisons. A conservative bound: it never
    /// misses a row. For most shapes it rounds the edges' extent outward to
    /// whole rows, so it may hold one row the shape does not cover (an edge
    /// exactly on a row boundary). For [`Polyline`](crate::shape::Polyline)s,
    /// [`Polygon`](crate::shape::Polygon)s, [`Arc`](crate::shape::Arc)s and
    /// [`RoundedRect`](crate::shape::RoundedRect)s it is found from the
    /// geometry without building the edges (so that building one per band is
    /// cheap), and is looser: the points' extent grown by the stroke's half
    /// width times the longest miter (or `√2` for square caps); an arc's whole
    /// circle, grown by `√2` half widths; a rounded rectangle's box grown by
    /// a half width; each with one more row each side.
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

    /// The rows [`Self::rows`] reports; the shape's error if it has one.
    #[cfg(test)]
    fn extent(&self) -> Result<(i32, i32), Error> {
        self.measure().map(|m| m.0)
    }

    /// The rows [`Self::rows`] reports, the columns likewise and the larger
    /// part's edge count; the shape's error if it has one. One pass over
    /// the contours into a measuring list, which stores no edge: a shape of
    /// any size costs its contours' construction and no 5 KB list to zero
    /// (nor a second pass when it does not fit the small one). Not inlined:
    /// a caller that builds many shapes keeps one copy.
    #[inline(never)]
    fn measure(&self) -> Result<Measured, Error> {
        let mut e = EdgeList::measuring();
        self.fill_edges(&mut e)?;
        let (f, fx, n) = (e.y_range(), e.x_range(), e.len());
        self.stroke_edges(&mut e)?;
        let (t, tx, n) = (e.y_range(), e.x_range(), n.max(e.len()));
        // Subpixels to whole pixels, outward; empty shapes get an empty
        // range. Columns: no coverage lies right of every edge (closed
        // contours wind 0 there) nor left of them.
        let whole = |a: (i32, i32), b: (i32, i32)| {
            let (lo, hi) = (a.0.min(b.0), a.1.max(b.1));
            if lo <= hi { (lo >> BITS, (hi >> BITS) + 1) } else { (0, 0) }
        };
        Ok((whole(f, t), whole(fx, tx), n))
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

/// Pixel rows and columns (half-open) and the larger part's edge count.
type Measured = ((i32, i32), (i32, i32), usize);

impl<S: Shape, C: Interpolate, A: Coverage> Styled<S, C, A> {
    /// Draws on `canvas` (a band view, or a readable framebuffer): fill
    /// first, then stroke; partial pixels are blended exactly. An aliased
    /// [`Rect`](crate::shape::Rect)'s fill is written as one span per row,
    /// without building its edges (the same pixels as the scan).
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
        if self.misses(clip) {
            return;
        }
        // Only edges that cross the clip's rows can change a pixel in them
        // (a row strip's coverage comes from the edges crossing it, aliased
        // and anti-aliased alike), so only those are stored, sorted and
        // scanned: a band of a large ring holds a few of its edges. Each part
        // goes in a small list unless its edges in the band do not fit.
        // A shape whose rows are all in the clip keeps every edge: no window
        // (nothing to drop, no chord worth testing).
        let whole = clip.y0() <= self.rows.0 && clip.y1() >= self.rows.1;
        let window =
            (!whole).then(|| (clip.y0().saturating_mul(1 << BITS), clip.y1().saturating_mul(1 << BITS)));
        // A part too large for the small list, all of whose rows are in the
        // clip, would fill it and then be built again: the large one first.
        let small = !(self.big && whole);
        for stroke in [false, true] {
            if !stroke && A::WHOLE && self.box_fill(canvas) {
                continue;
            }
            if !small || self.part_in::<SMALL_EDGES, T>(canvas, stroke, window) == Err(Error::BufferTooSmall)
            {
                // `new` checked that the whole part fits MAX_EDGES.
                let _ = self.part_in::<MAX_EDGES, T>(canvas, stroke, window);
            }
        }
    }

    /// The fill of a box ([`Shape::fill_box`]), aliased, as one whole span
    /// per row: no edges built, sorted or walked. `false` (nothing drawn)
    /// if the shape is no box.
    ///
    /// The same pixels as the scan: the box's snapped contour has two
    /// vertical edges, at `x0` (up) and `x1` (down), winding ±1 between
    /// them (inside by either rule) from row centre `y0` to `y1`, half-open.
    /// The scan enters an edge at the rows whose centre `yc` has
    /// `y0 ≤ yc < y1` and starts a span at the first column whose centre is
    /// at or right of the edge's `x`: both are [`first_row`] of the
    /// coordinate, clamped to the clip as the scan clamps. An empty box
    /// (`x0 = x1` or `y0 = y1`) covers nothing either way.
    #[inline(never)]
    fn box_fill<T: Canvas<C>>(&self, canvas: &mut T) -> bool {
        let Some([a, b]) = self.shape.fill_box() else { return false };
        let Some(paint) = &self.style.fill else { return true };
        // `new` built this contour (`extent`): the same snaps succeeded there.
        let (Ok(a), Ok(b)) = (snap(a.0, a.1), snap(b.0, b.1)) else { return true };
        let clip = canvas.clip();
        // Within the clip, so within i32.
        let at = |v: i32, lo: i32, hi: i32| first_row(v).clamp(i64::from(lo), i64::from(hi)) as i32;
        let (x0, x1) = (at(a.0, clip.x0(), clip.x1()), at(b.0, clip.x0(), clip.x1()));
        let (y0, y1) = (at(a.1, clip.y0(), clip.y1()), at(b.1, clip.y0(), clip.y1()));
        let op = u32::from(self.style.opacity);
        // Coverage 255 times opacity, rounded, as `part_in` (which hands
        // alpha 0 on too: a `TargetCanvas` over a background paints it).
        let alpha = if op == 255 { 255 } else { div255_round(255 * op) as u8 };
        if x0 < x1 && y0 < y1 {
            paint.paint_rect(canvas, Span { y: y0, x: x0, len: (x1 - x0) as u32 }, (y1 - y0) as u32, alpha);
        }
        true
    }

    /// The fill (or the stroke) on `canvas`, with an edge list of capacity
    /// `N` holding the edges between subpixel rows `window` (all of them if `None`). Builds the edges
    /// first: if they do not fit, nothing is drawn and the error returned.
    /// Each capacity its own frame, for the stack.
    #[inline(never)]
    fn part_in<const N: usize, T: Canvas<C>>(
        &self,
        canvas: &mut T,
        stroke: bool,
        window: Option<(i32, i32)>,
    ) -> Result<(), Error> {
        let (paint, rule) = match stroke {
            false => (&self.style.fill, self.style.fill_rule),
            true => (&self.style.stroke, FillRule::NonZero),
        };
        let Some(paint) = paint else { return Ok(()) };
        let mut e = EdgeList::<N>::new();
        if let Some((lo, hi)) = window {
            e.window(lo, hi);
        }
        if stroke {
            self.stroke_edges(&mut e)?
        } else {
            self.fill_edges(&mut e)?
        }
        self.cover_with(&mut e, None, paint, rule, canvas);
        Ok(())
    }

    /// `e`'s coverage in `canvas`'s clip, painted with `paint` at the
    /// style's opacity: the last step of every part's draw. `chains`: the
    /// list's two chains found over every row (aliased only), walked
    /// without looking for them again.
    #[inline(always)]
    fn cover_with<const N: usize, T: Canvas<C>>(
        &self,
        e: &mut EdgeList<N>,
        chains: Option<Chains>,
        paint: &crate::shape::Paint<C>,
        rule: FillRule,
        canvas: &mut T,
    ) {
        let op = u32::from(self.style.opacity);
        // Coverage times opacity, rounded; exact (and free) when opaque.
        let alpha = |a: u8| if op == 255 { a } else { div255_round(u32::from(a) * op) as u8 };
        let clip = canvas.clip();
        let out = |span, a| paint.paint(canvas, span, alpha(a));
        match chains {
            Some(c) if A::WHOLE => c.within(clip).walk(e.edges(), clip, &mut Runs::new(out)),
            _ => A::cover(e, rule, clip, out),
        }
    }

    /// Whether `clip` misses every row or every column the shape can touch.
    #[inline(always)]
    fn misses(&self, clip: crate::ClipRect) -> bool {
        clip.y1() <= self.rows.0
            || clip.y0() >= self.rows.1
            || clip.x1() <= self.cols.0
            || clip.x0() >= self.cols.1
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

mod prepared;
pub use prepared::{PREPARED_EDGES, Prepared};

#[cfg(test)]
mod tests;
