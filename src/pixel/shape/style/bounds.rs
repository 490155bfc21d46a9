//! Conservative pixel bounds of a styled shape: the rectangle a damage
//! region ([`render::Damage`](crate::render::Damage)) needs when the shape
//! moves.
//!
//! # Why the bound holds, for every join and cap
//! The bound is taken from the edges the rasterizer itself draws, not from
//! the shape's description: the fill's contours and the stroke's outline
//! (offset segments, miter points within the miter limit, bevels, round
//! joins and caps flattened to segments, square caps), snapped to the
//! `1/16` px grid exactly as [`Styled::draw_on`] snaps them. Both coverage
//! modes light a pixel only where the edges enclose some area:
//!
//! * aliased: a pixel is lit when its centre is inside the edges, so the
//!   centre lies within the edges' extent `[x_min, x_max] × [y_min, y_max]`
//!   (in subpixels);
//! * anti-aliased: a pixel's coverage is the exact area of the edges'
//!   region inside the pixel, integer arithmetic with no rounding up from
//!   zero: a pixel outside the extent gets area 0 and is not touched.
//!
//! A pixel `[px, px + 1)` meets the extent only if `px ≤ x_max / 16` and
//! `px + 1 > x_min / 16`, so columns `⌊x_min / 16⌋ ..= ⌊x_max / 16⌋` (the
//! same for rows) hold every pixel either mode can light. The rectangle
//! is at most one pixel wider and taller than the lit pixels' box on each
//! side (an extent ending exactly on a pixel boundary keeps that pixel), and
//! the miter limit bounds how far a join reaches beyond the stroke
//! (`miter_limit · width / 2` from the vertex): the outline's edges stop
//! there, so does the bound (tested in `tests/integration/damage_bounds.rs`).

use super::Styled;
use crate::shape::edges::{BITS, EdgeList};
use crate::shape::{Coverage, MAX_EDGES, Shape};
use crate::{Error, MAX_FRAME_DIM};
use embedded_graphics_core::geometry::{Dimensions, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

/// Edge capacity tried first (as `Styled::new` does): most shapes fit.
const FEW: usize = 32;

impl<S: Shape, C: Copy, A: Coverage> Styled<S, C, A> {
    /// The pixels the shape can light, fill and stroke, with any join
    /// (miter up to its limit, round, bevel) and cap, aliased or
    /// anti-aliased: no pixel outside is ever written by
    /// [`Styled::draw_on`] or by drawing it into a `DrawTarget`. At most one
    /// pixel more than the lit pixels' box on each side (see the module's
    /// proof). An empty rectangle at the origin for a shape that lights
    /// nothing. Costs one build of the edges (as [`Styled::new`] does).
    ///
    /// Also the shape's e-g [`Dimensions::bounding_box`], so a moved styled
    /// shape goes into a damage list like text or any e-g drawable
    /// ([`Damage::add_moved`](crate::render::Damage::add_moved)).
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use microraster::shape::{Join, Polyline, Rect, Shape, ShapeStyle};
    /// // A 4 × 2 bar at (1, 1): pixels 1..5 × 1..3, plus the row and column
    /// // its edges end on (x = 5, y = 3 exactly).
    /// let bar = Rect::new(1.0, 1.0, 4.0, 2.0)?.styled(ShapeStyle::fill(Gray8::WHITE))?;
    /// assert_eq!(bar.bounds(), Rectangle::new(Point::new(1, 1), Size::new(5, 3)));
    /// // A 2 px stroke meeting at a right angle with a miter reaches out to
    /// // the corner of its outline: (9, 1) for the corner at (8, 2).
    /// let corner = Polyline::new(&[(2.0, 2.0), (8.0, 2.0), (8.0, 8.0)])?;
    /// let pen = ShapeStyle::stroke(Gray8::WHITE, 2.0).with_join(Join::Miter);
    /// let b = corner.styled(pen)?.bounds();
    /// assert_eq!((b.top_left, b.bottom_right()), (Point::new(2, 1), Some(Point::new(9, 8))));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn bounds(&self) -> Rectangle {
        // `new` built these edges with one of the two capacities: neither
        // can fail here. Were it to, the whole coordinate range is still a
        // bound.
        let extent = match self.extent_xy::<FEW>() {
            Err(Error::BufferTooSmall) => self.extent_xy::<MAX_EDGES>(),
            r => r,
        };
        let Ok(extent) = extent else {
            return Rectangle::new(Point::zero(), Size::new(MAX_FRAME_DIM, MAX_FRAME_DIM));
        };
        let Some((x0, y0, x1, y1)) = extent else { return Rectangle::zero() };
        // Subpixels (within ±2^28, checked by snapping) to whole pixels,
        // outward: first ⌊v / 16⌋, last ⌊v / 16⌋ inclusive.
        let (px0, py0) = (x0 >> BITS, y0 >> BITS);
        let (px1, py1) = ((x1 >> BITS) + 1, (y1 >> BITS) + 1);
        Rectangle::new(Point::new(px0, py0), Size::new((px1 - px0) as u32, (py1 - py0) as u32))
    }

    /// The subpixel extent `(x_min, y_min, x_max, y_max)` of the fill's and
    /// the stroke's edges, `None` if there are none; edge lists of
    /// capacity `N`.
    #[inline(never)]
    fn extent_xy<const N: usize>(&self) -> Result<Option<(i32, i32, i32, i32)>, Error> {
        let style = self.style();
        let mut e = EdgeList::<N>::new();
        let mut ext: Option<(i32, i32, i32, i32)> = None;
        let mut take = |e: &EdgeList<N>| {
            for g in e.edges() {
                let (lo_x, hi_x) = (g.x0.min(g.x1), g.x0.max(g.x1));
                let (lo_y, hi_y) = (g.y0.min(g.y1), g.y0.max(g.y1));
                ext = Some(match ext {
                    None => (lo_x, lo_y, hi_x, hi_y),
                    Some((a, b, c, d)) => (a.min(lo_x), b.min(lo_y), c.max(hi_x), d.max(hi_y)),
                });
            }
        };
        if style.fill.is_some() {
            self.shape().fill_contours(&mut e)?;
            e.close()?;
            take(&e);
        }
        if style.stroke.is_some() && style.stroke_width > 0.0 {
            e.clear();
            self.shape().stroke_contours(&mut e, &style.params())?;
            e.close()?;
            take(&e);
        }
        Ok(ext)
    }
}

/// The shape's [`Styled::bounds`], so a styled shape is a damage source as
/// any e-g drawable is.
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use microraster::shape::{Circle, Shape, ShapeStyle};
/// let dot = Circle::new((10.0, 10.0), 3.0)?.styled(ShapeStyle::fill(Gray8::WHITE))?;
/// assert_eq!(dot.bounding_box(), dot.bounds());
/// assert!(dot.bounding_box().contains(Point::new(7, 7)));
/// # Ok::<(), microraster::Error>(())
/// ```
impl<S: Shape, C: Copy, A: Coverage> Dimensions for Styled<S, C, A> {
    fn bounding_box(&self) -> Rectangle {
        self.bounds()
    }
}
