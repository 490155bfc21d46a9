//! The shapes: plain geometry in `f32` pixels, checked when built.

use super::Coverage;
use super::edges::EdgeList;
use super::flatten::{Steps, arc_edges_stepped};
use super::stroke::{self, StrokeParams};
use super::style::{ShapeStyle, Styled};
use crate::math::Scalar;
use crate::{Error, Param};
use core::f32::consts::{FRAC_PI_2, PI};

mod arcs;
pub use arcs::{Arc, Circle, Ellipse, Sector};

/// A geometric shape: its filled region and its stroke as closed contours.
/// [`Shape::styled`] pairs it with a [`ShapeStyle`] for drawing.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, Drawable};
/// use microraster::shape::{Rect, Shape, ShapeStyle};
/// let mut display = MockDisplay::new();
/// Rect::new(1.0, 1.0, 3.0, 2.0)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
/// display.assert_pattern(&["    ", " ###", " ###"]);
/// # Ok::<(), microraster::Error>(())
/// ```
pub trait Shape: Sized {
    /// Adds the contours of the filled region to `e`.
    #[doc(hidden)]
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error>;

    /// Adds the contours of the stroke to `e`.
    #[doc(hidden)]
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error>;

    /// A conservative bound of the fill's (if `fill`) and the stroke's (if
    /// `stroke`) snapped edges, found from the geometry without building
    /// them, when the shape knows one (`None`: [`Styled::new`] builds the
    /// edges). See [`Reach`].
    #[doc(hidden)]
    fn reach(&self, fill: bool, stroke: Option<&StrokeParams>) -> Option<Reach> {
        let _ = (fill, stroke);
        None
    }

    /// The fill's corners `(x0, y0), (x1, y1)` (px, `x0 ≤ x1`, `y0 ≤ y1`)
    /// when the fill is exactly that axis-aligned box, snapped as its
    /// contour's vertices are: aliased, [`Styled`] then covers whole rows of
    /// pixels without building edges (the same pixels). `None` otherwise.
    #[doc(hidden)]
    fn fill_box(&self) -> Option<[(f32, f32); 2]> {
        None
    }

    /// Pairs the shape with a style (checked: see [`Styled::new`]).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::{Error, shape::{Circle, Shape, ShapeStyle}};
    /// let ring = Circle::new((8.0, 8.0), 6.0)?.styled(ShapeStyle::stroke(BinaryColor::On, 2.0))?;
    /// assert_eq!(ring.rows(), (1, 16)); // rows 1 ..= 15: 8 ± (6 + 1) px
    /// let bad = Circle::new((8.0, 8.0), 6.0)?.styled(ShapeStyle::stroke(BinaryColor::On, f32::NAN));
    /// assert_eq!(bad.err(), Some(Error::NonFiniteCoordinate));
    /// # Ok::<(), Error>(())
    /// ```
    fn styled<C: Copy, A: Coverage>(self, style: ShapeStyle<C, A>) -> Result<Styled<Self, C, A>, Error> {
        Styled::new(self, style)
    }
}

fn finite(v: &[f32]) -> Result<(), Error> {
    if v.iter().all(|x| x.is_finite()) { Ok(()) } else { Err(Error::NonFiniteCoordinate) }
}

/// Finite and non-negative, else the typed error.
fn size(v: &[f32]) -> Result<(), Error> {
    finite(v)?;
    if v.iter().all(|&x| x >= 0.0) { Ok(()) } else { Err(Error::InvalidParameter(Param::ShapeSize)) }
}

/// What [`Shape::reach`] promises: every edge of the fill and of the
/// stroke lies in pixel rows `rows.0 .. rows.1` and columns
/// `cols.0 .. cols.1`, each part has at most
/// `edges` edges, and no vertex is beyond the snapping range (so building
/// them cannot fail).
#[doc(hidden)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Reach {
    pub(crate) rows: (i32, i32),
    pub(crate) cols: (i32, i32),
    pub(crate) edges: usize,
}

/// Points (px) below which `reach` is trusted: `f32` steps there are at most
/// 1/8 px, so the few roundings between a point and a stroke's vertex move
/// it far less than the one-pixel margin `reach` adds. (Every input is
/// finite: sums compared with it are finite or +∞, never NaN.)
const NEAR: f32 = (1 << 20) as f32;

/// [`Shape::reach`] of a path through `pts` (closed or open) filled (if
/// `fill`) and stroked with `stroke`. Every vertex of the stroke lies within
/// `r = half · max(1, √2 for square caps, the miter limit for miter joins)`
/// of a point (offsets, round joins and caps, miters no longer than the
/// limit, pivots at the points themselves); the fill's vertices are the
/// points. Edge counts: a polygon's fill has at most `n`; a stroke at most
/// `(2n + 4)·(3 + J)`, `J` the chords of a half turn of radius `half`
/// (each side: a segment and a join per point, a join being at most `J`
/// chords or 2 edges, and two caps of at most `max(3, 2J + 1)` edges).
fn path_reach(pts: &[(f32, f32)], fill: bool, stroke: Option<&StrokeParams>) -> Option<Reach> {
    let (mut y0, mut y1, mut far) = (f32::INFINITY, f32::NEG_INFINITY, 0.0f32);
    let (mut x0, mut x1) = (f32::INFINITY, f32::NEG_INFINITY);
    for &(x, y) in pts {
        (y0, y1, far) = (y0.min(y), y1.max(y), far.max(x.abs()).max(y.abs()));
        (x0, x1) = (x0.min(x), x1.max(x));
    }
    let (mut r, mut edges) = (0.0f32, if fill { pts.len() } else { 0 });
    if let Some(p) = stroke {
        let cap = if p.cap == super::Cap::Square { core::f32::consts::SQRT_2 } else { 1.0 };
        let join = if p.join == super::Join::Miter { p.miter_limit } else { 1.0 };
        r = p.half * cap.max(join);
        let round = p.join == super::Join::Round || p.cap == super::Cap::Round;
        let j = if round { (super::flatten::segments(p.half, PI) as usize).max(2) } else { 2 };
        edges = edges.max((2 * pts.len() + 4) * (3 + j));
    }
    if pts.is_empty() || far + r >= NEAR || edges > super::MAX_EDGES {
        return None;
    }
    // Whole rows (and columns), a pixel wider each side than the exact reach.
    let (rows, cols) = ((floor(y0 - r) - 1, floor(y1 + r) + 2), (floor(x0 - r) - 1, floor(x1 + r) + 2));
    Some(Reach { rows, cols, edges })
}

/// A [`Reach`] of at most `edges` edges per part, all within `radius` px of
/// `c` (arcs and rounded corners: vertices on circles, chords inside them).
fn round_reach(c: (f32, f32), radius: f32, edges: usize) -> Option<Reach> {
    let far = c.0.abs().max(c.1.abs()) + radius;
    if far >= NEAR || edges > super::MAX_EDGES {
        return None;
    }
    let span = |v: f32| (floor(v - radius) - 1, floor(v + radius) + 2);
    Some(Reach { rows: span(c.1), cols: span(c.0), edges })
}

/// `⌊v⌋` for `|v| < 2^20` (`f32::floor` is not in `core` on every toolchain).
fn floor(v: f32) -> i32 {
    if ((v as i32) as f32) > v { v as i32 - 1 } else { v as i32 }
}

/// An axis-aligned rectangle: top-left corner and size (px).
///
/// ```
/// use microraster::shape::Rect;
/// assert!(Rect::new(0.0, 0.0, 4.0, 2.0).is_ok());
/// assert_eq!(Rect::new(0.0, 0.0, -1.0, 2.0), Err(microraster::Error::InvalidParameter(microraster::Param::ShapeSize)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    x: f32,
    y: f32,
    w: f32,
    h: f32,
}

impl Rect {
    /// Errors: NaN or infinity ([`Error::NonFiniteCoordinate`]), a negative
    /// size ([`Error::InvalidParameter`]).
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, Drawable};
    /// use microraster::shape::{Rect, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// Rect::new(0.0, 1.0, 2.0, 1.0)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
    /// display.assert_pattern(&["  ", "##"]);
    /// assert_eq!(Rect::new(f32::NAN, 0.0, 1.0, 1.0), Err(microraster::Error::NonFiniteCoordinate));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(x: f32, y: f32, w: f32, h: f32) -> Result<Self, Error> {
        finite(&[x, y])?;
        size(&[w, h])?;
        Ok(Rect { x, y, w, h })
    }

    fn corners(&self) -> [(f32, f32); 4] {
        let (x1, y1) = (self.x + self.w, self.y + self.h);
        [(self.x, self.y), (x1, self.y), (x1, y1), (self.x, y1)]
    }
}

impl Shape for Rect {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        e.polygon(&self.corners())
    }
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        stroke::polyline(e, &self.corners(), true, p)
    }
    fn fill_box(&self) -> Option<[(f32, f32); 2]> {
        // The first and third of `corners`: the same sums, the same snaps.
        let c = self.corners();
        Some([c[0], c[2]])
    }
}

/// A rectangle with circular corners of one radius, clamped to half the
/// shorter side. Its stroke is the exact offset outline (corners of radius
/// `r ± width/2`, clamped at 0), so the style's join does not apply.
///
/// ```
/// use microraster::shape::{Rect, RoundedRect};
/// let r = RoundedRect::new(Rect::new(0.0, 0.0, 10.0, 4.0)?, 3.0)?;
/// assert_eq!(r.radius(), 2.0); // clamped to 4 / 2
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundedRect {
    rect: Rect,
    r: f32,
}

impl RoundedRect {
    /// Errors: a NaN or negative radius, as for [`Rect::new`].
    ///
    /// ```
    /// use microraster::{Error, shape::{Rect, RoundedRect}};
    /// let rect = Rect::new(0.0, 0.0, 8.0, 6.0)?;
    /// assert_eq!(RoundedRect::new(rect, 2.0)?.radius(), 2.0); // fits: unchanged
    /// assert_eq!(RoundedRect::new(rect, -1.0), Err(Error::InvalidParameter(microraster::Param::ShapeSize)));
    /// assert_eq!(RoundedRect::new(rect, f32::NAN), Err(Error::NonFiniteCoordinate));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(rect: Rect, radius: f32) -> Result<Self, Error> {
        size(&[radius])?;
        Ok(RoundedRect { rect, r: radius.min(0.5 * rect.w.min(rect.h)) })
    }

    /// The corner radius after clamping.
    ///
    /// ```
    /// use microraster::shape::{Rect, RoundedRect};
    /// let pill = RoundedRect::new(Rect::new(0.0, 0.0, 12.0, 3.0)?, 5.0)?;
    /// assert_eq!(pill.radius(), 1.5); // half the height
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn radius(&self) -> f32 {
        self.r
    }

    /// The outline grown by `d` (shrunk for `d < 0`), radius `r + d`.
    fn contour<const N: usize>(&self, e: &mut EdgeList<N>, d: f32, reverse: bool) -> Result<(), Error> {
        let Rect { x, y, w, h } = self.rect;
        let r = (self.r + d).max(0.0);
        let (x0, y0, x1, y1) = (x - d, y - d, x + w + d, y + h + d);
        if x1 <= x0 || y1 <= y0 {
            return Ok(());
        }
        // Corner centres clockwise from top-right; each quarter starts where the previous side ends.
        let centres = [
            (x1 - r, y0 + r, -FRAC_PI_2),
            (x1 - r, y1 - r, 0.0),
            (x0 + r, y1 - r, FRAC_PI_2),
            (x0 + r, y0 + r, PI),
        ];
        e.close()?;
        // Each corner as `arc_edges(e, centre, (r, r), start, sweep)`, the
        // same values: one radius and sweep, so one chord count and step
        // rotation; a corner's end angle is usually the next one's start
        // (bit for bit), so its sine and cosine are reused.
        let sweep = if reverse { -FRAC_PI_2 } else { FRAC_PI_2 };
        let steps = Steps::new(r, sweep);
        let mut last: Option<(u32, (f32, f32))> = None;
        for k in 0..4 {
            let (cx, cy, a) = centres[if reverse { 3 - k } else { k }];
            let start = if reverse { a + FRAC_PI_2 } else { a };
            let end = start + sweep;
            let from = match last {
                Some((bits, v)) if bits == start.to_bits() => v,
                _ => Scalar::sin_cos(start),
            };
            let ends = (from, Scalar::sin_cos(end));
            last = Some((end.to_bits(), ends.1));
            arc_edges_stepped(e, (cx, cy), (r, r), ends, steps)?;
        }
        e.close()
    }
}

impl Shape for RoundedRect {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        self.contour(e, 0.0, false)
    }
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        self.contour(e, p.half, false)?;
        self.contour(e, -p.half, true)
    }
    fn reach(&self, fill: bool, stroke: Option<&StrokeParams>) -> Option<Reach> {
        // A contour grown by `d` has four quarter arcs of radius r + d
        // (their points, one edge each, and the closing one) within the box
        // grown by `d`: the centre's distance to a corner of that box.
        let Rect { x, y, w, h } = self.rect;
        let d = stroke.map_or(0.0, |p| p.half);
        let quarter = |r: f32| 4 * (super::flatten::segments(r, FRAC_PI_2) as usize + 1) + 1;
        let edges = if fill { quarter(self.r) } else { 0 }.max(if stroke.is_some() {
            2 * quarter(self.r + d)
        } else {
            0
        });
        let far = x.abs().max(y.abs()).max((x + w).abs()).max((y + h).abs()) + d;
        if far >= NEAR || edges > super::MAX_EDGES {
            return None;
        }
        let (rows, cols) =
            ((floor(y - d) - 1, floor(y + h + d) + 2), (floor(x - d) - 1, floor(x + w + d) + 2));
        Some(Reach { rows, cols, edges })
    }
}

/// A closed polygon through borrowed points (px), convex or not,
/// self-intersecting or not (see [`FillRule`](super::FillRule)).
///
/// ```
/// use microraster::shape::Polygon;
/// let star = [(5.0, 0.0), (8.0, 9.0), (0.0, 3.5), (10.0, 3.5), (2.0, 9.0)];
/// assert!(Polygon::new(&star).is_ok());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Polygon<'a>(&'a [(f32, f32)]);

impl<'a> Polygon<'a> {
    /// Errors: a NaN or infinite coordinate.
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
    /// use microraster::shape::{Polygon, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// let corner = [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)];
    /// Polygon::new(&corner)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
    /// assert_eq!(display.get_pixel(Point::new(0, 0)), Some(BinaryColor::On));
    /// assert_eq!(display.get_pixel(Point::new(3, 3)), None); // beyond the diagonal
    /// assert_eq!(Polygon::new(&[(0.0, f32::NAN)]), Err(microraster::Error::NonFiniteCoordinate));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(points: &'a [(f32, f32)]) -> Result<Self, Error> {
        points.iter().try_for_each(|p| finite(&[p.0, p.1]))?;
        Ok(Polygon(points))
    }
}

impl Shape for Polygon<'_> {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        e.polygon(self.0)
    }
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        stroke::polyline(e, self.0, true, p)
    }
    fn reach(&self, fill: bool, stroke: Option<&StrokeParams>) -> Option<Reach> {
        path_reach(self.0, fill, stroke)
    }
}

/// An open polyline through borrowed points: stroke only (its fill is
/// empty). A single segment is a thick line.
///
/// ```
/// use microraster::shape::Polyline;
/// assert!(Polyline::new(&[(0.0, 0.0), (10.0, 4.0), (20.0, 0.0)]).is_ok());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Polyline<'a>(&'a [(f32, f32)]);

impl<'a> Polyline<'a> {
    /// Errors: a NaN or infinite coordinate.
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, Drawable};
    /// use microraster::shape::{Polyline, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// // One segment along y = 2, 2 px wide: rows 1 and 2, butt caps at x = 0 and 4.
    /// let line = Polyline::new(&[(0.0, 2.0), (4.0, 2.0)])?;
    /// line.styled(ShapeStyle::stroke(BinaryColor::On, 2.0))?.draw(&mut display).unwrap();
    /// display.assert_pattern(&["    ", "####", "####"]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(points: &'a [(f32, f32)]) -> Result<Self, Error> {
        points.iter().try_for_each(|p| finite(&[p.0, p.1]))?;
        Ok(Polyline(points))
    }
}

impl Shape for Polyline<'_> {
    fn fill_contours<const N: usize>(&self, _: &mut EdgeList<N>) -> Result<(), Error> {
        Ok(())
    }
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        stroke::polyline(e, self.0, false, p)
    }
    fn reach(&self, _fill: bool, stroke: Option<&StrokeParams>) -> Option<Reach> {
        // The fill is empty.
        path_reach(self.0, false, stroke)
    }
}

#[cfg(test)]
mod tests;
