//! Groups: several shapes covered as one, so anti-aliased neighbours leave
//! no seam.
//!
//! Two anti-aliased shapes sharing an edge each cover part of the pixels on
//! it, and the parts sum to one; drawn one after the other, each is blended
//! over what is there ("source-over"), and the second blends over the first's
//! partial pixel instead of filling the rest of it. Two white halves of a
//! pixel on black end at `1 − (1 − ½)·(1 − ½) = ¾` (192 of 255), not white.
//! A [`Group`] puts its members' contours in one edge list: their coverages
//! are summed in each pixel *before* the one blend, so the shared edge
//! cancels exactly and the seam gets the coverage of the union.

use super::Shape;
use super::edges::EdgeList;
use super::stroke::StrokeParams;
use crate::Error;

/// Shapes of one kind drawn as one shape, with one style: a pie chart's
/// sectors, a gauge's segments, a mesh of polygons.
///
/// Each member's contours are oriented so that its winding number is
/// positive (every member is reversed as a whole if its contours enclose a
/// negative winding integral), then all are covered together with the
/// style's fill rule. For members of winding 0 or 1 (every shape except
/// self-overlapping polygons) that is, per pixel, the sum of the members'
/// exact areas: with [`FillRule::NonZero`](super::FillRule::NonZero) the
/// union's area (`min(1, Σ)`), so members sharing an edge sum to the whole
/// pixel; with `EvenOdd` members that overlap cut holes. A member that winds
/// both ways (a figure-eight polygon) cancels, in its other-way part, the
/// coverage of members overlapping it. The members share one edge list:
/// together at most [`MAX_EDGES`](super::MAX_EDGES) edges.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::{Band, shape::{Group, Rect, Shape, ShapeStyle}};
/// // Two white bars meeting at x = 10.5, on black.
/// let halves = [Rect::new(0.0, 0.0, 10.5, 1.0)?, Rect::new(10.5, 0.0, 9.5, 1.0)?];
/// let style = ShapeStyle::fill(Gray8::WHITE).antialiased();
/// let seam = |group: bool| -> Result<u8, microraster::Error> {
///     let mut band = Band::<Gray8, 20, 1>::new(Gray8::BLACK);
///     let mut view = band.view(0, 1, Gray8::BLACK);
///     if group {
///         Group::new(&halves).styled(style)?.draw_on(&mut view);
///     } else {
///         for h in halves {
///             h.styled(style)?.draw_on(&mut view);
///         }
///     }
///     Ok(band.rows()[0][10].luma())
/// };
/// assert_eq!(seam(true)?, 255);
/// assert!(seam(false)? < 255); // one after the other: half, then half of the rest
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Group<'a, S> {
    members: &'a [S],
}

impl<'a, S: Shape> Group<'a, S> {
    /// The members, drawn as one shape once styled.
    ///
    /// ```
    /// use microraster::shape::{Group, Sector};
    /// let pie = [Sector::new((8.0, 8.0), 6.0, 0.0, 2.0)?, Sector::new((8.0, 8.0), 6.0, 2.0, 4.28)?];
    /// assert_eq!(Group::new(&pie).members().len(), 2);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const fn new(members: &'a [S]) -> Self {
        Group { members }
    }

    /// The members.
    ///
    /// ```
    /// use microraster::shape::{Group, Rect};
    /// let bars = [Rect::new(0.0, 0.0, 2.0, 2.0)?];
    /// assert_eq!(Group::new(&bars).members(), &bars);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const fn members(&self) -> &'a [S] {
        self.members
    }

    /// Each member's contours by `add`, closed and oriented positive.
    fn each<const N: usize>(
        &self,
        e: &mut EdgeList<N>,
        mut add: impl FnMut(&S, &mut EdgeList<N>) -> Result<(), Error>,
    ) -> Result<(), Error> {
        for m in self.members {
            e.close()?;
            let from = e.mark();
            add(m, e)?;
            e.close()?;
            e.orient_since(from);
        }
        Ok(())
    }
}

impl<S: Shape> Shape for Group<'_, S> {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        self.each(e, |m, e| m.fill_contours(e))
    }

    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        self.each(e, |m, e| m.stroke_contours(e, p))
    }
}
