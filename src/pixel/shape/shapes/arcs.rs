//! The shapes drawn around a centre along elliptic or circular arcs: ellipses,
//! circles, arcs and sectors.

use super::{Reach, Shape, finite, round_reach, size};
use crate::Error;
use crate::shape::Cap;
use crate::shape::angle::{self, Angle};
use crate::shape::edges::EdgeList;
use crate::shape::flatten::{arc_edges, arc_edges_between};
use crate::shape::stroke::{self, StrokeParams};
use core::f32::consts::{PI, SQRT_2, TAU};

/// An ellipse: centre and the two radii (px).
///
/// Its stroke is the region between the ellipses of radii `± width/2`: for
/// a circle exactly the offset curve, for a stretched ellipse as wide as
/// the pen at the four ends of the axes and narrower between them (about
/// 0.95 of the width for radii 10 × 5 and 0.82 for 20 × 5 with `width/2 =
/// 1`), where tiny-skia and SVG stroke the true offset curve.
///
/// ```
/// use microraster::shape::Ellipse;
/// assert!(Ellipse::new((5.0, 5.0), 4.0, 2.0).is_ok());
/// assert_eq!(Ellipse::new((5.0, f32::NAN), 4.0, 2.0), Err(microraster::Error::NonFiniteCoordinate));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    c: (f32, f32),
    rx: f32,
    ry: f32,
}

impl Ellipse {
    /// Errors as for [`Rect::new`](super::Rect::new).
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
    /// use microraster::shape::{Ellipse, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// Ellipse::new((4.0, 4.0), 3.0, 1.0)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
    /// // Wide, not tall: 1.5 px right of the centre is in, 1.5 px below is out.
    /// assert_eq!(display.get_pixel(Point::new(5, 4)), Some(BinaryColor::On));
    /// assert_eq!(display.get_pixel(Point::new(4, 5)), None);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(center: (f32, f32), rx: f32, ry: f32) -> Result<Self, Error> {
        finite(&[center.0, center.1])?;
        size(&[rx, ry])?;
        Ok(Ellipse { c: center, rx, ry })
    }

    fn contour<const N: usize>(&self, e: &mut EdgeList<N>, d: f32, reverse: bool) -> Result<(), Error> {
        let (rx, ry) = (self.rx + d, self.ry + d);
        if rx <= 0.0 || ry <= 0.0 {
            return Ok(());
        }
        e.close()?;
        let sweep = if reverse { -TAU } else { TAU };
        arc_edges(e, self.c, (rx, ry), 0.0, sweep)?;
        e.close()
    }
}

impl Shape for Ellipse {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        self.contour(e, 0.0, false)
    }
    /// The region between the ellipses of radii `± width/2` (for a circle
    /// exactly the offset curve).
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        self.contour(e, p.half, false)?;
        self.contour(e, -p.half, true)
    }
}

/// A circle: an [`Ellipse`] with equal radii.
///
/// ```
/// use microraster::shape::Circle;
/// assert_eq!(Circle::new((0.0, 0.0), -1.0), Err(microraster::Error::InvalidParameter(microraster::Param::ShapeSize)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle(Ellipse);

impl Circle {
    /// Errors as for [`Rect::new`](super::Rect::new).
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
    /// use microraster::shape::{Circle, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// Circle::new((2.0, 2.0), 1.0)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
    /// display.assert_pattern(&["    ", " ## ", " ## "]); // the 4 centres 0.71 px away
    /// assert_eq!(Circle::new((f32::INFINITY, 0.0), 1.0), Err(microraster::Error::NonFiniteCoordinate));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(center: (f32, f32), radius: f32) -> Result<Self, Error> {
        Ellipse::new(center, radius, radius).map(Circle)
    }
}

impl Shape for Circle {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        self.0.fill_contours(e)
    }
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        self.0.stroke_contours(e, p)
    }
}

/// Centre, radius, start angle and sweep (radians: 0 along +x, positive
/// clockwise on screen; sweeps beyond a full turn are clamped to one). A
/// start beyond ±[`angle::NEAR`] is stored reduced; the end directions are
/// on the [`angle`] grid.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ArcGeom {
    c: (f32, f32),
    r: f32,
    start: f32,
    sweep: f32,
    from: Angle,
    to: Angle,
}

impl ArcGeom {
    fn new(c: (f32, f32), r: f32, start: f32, sweep: f32) -> Result<Self, Error> {
        finite(&[c.0, c.1, start, sweep])?;
        size(&[r])?;
        let (start, sweep) = (angle::near(start), sweep.clamp(-TAU, TAU));
        let (from, to) = angle::ends(start, sweep);
        Ok(ArcGeom { c, r, start, sweep, from, to })
    }

    /// The same arc swept the other way (from its end back to its start).
    fn reversed(&self) -> Self {
        ArcGeom { start: self.to.radians(), sweep: -self.sweep, from: self.to, to: self.from, ..*self }
    }

    /// The arc at radius `r`, forwards or backwards, as points on the current contour.
    fn points<const N: usize>(&self, e: &mut EdgeList<N>, r: f32, reverse: bool) -> Result<(), Error> {
        let g = if reverse { self.reversed() } else { *self };
        let ends = (g.from.sin_cos(), g.to.sin_cos());
        arc_edges_between(e, self.c, (r, r), ends, g.sweep)
    }
}

/// A circular arc: stroke only (its fill is empty, as in `embedded-graphics`).
///
/// A start within ±32 rad is used as given (an arc from `start + sweep`
/// starts where this one ends); a larger one is first reduced by whole
/// turns in `f64`, so the sweep is not lost (the `f32` ulp at 10^7 is 1 rad).
/// The two end directions are then rounded to 1/4096 degree: every whole
/// degree and quarter turn is exact, an end point moves by at most
/// `r·2.1·10^-6` px, and angles a whole turn apart on that grid give the
/// same points ([`Sector`] has an example).
///
/// ```
/// use microraster::shape::Arc;
/// assert!(Arc::new((8.0, 8.0), 6.0, 0.0, 3.0).is_ok());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc(ArcGeom);

impl Arc {
    /// Errors as for [`Rect::new`](super::Rect::new); `start` and `sweep` must be finite.
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
    /// use microraster::shape::{Arc, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// // The lower half (clockwise from +x), stroked 2 px wide: radii 2 to 4.
    /// Arc::new((4.0, 4.0), 3.0, 0.0, PI)?.styled(ShapeStyle::stroke(BinaryColor::On, 2.0))?.draw(&mut display).unwrap();
    /// assert_eq!(display.get_pixel(Point::new(4, 7)), Some(BinaryColor::On));
    /// assert_eq!(display.get_pixel(Point::new(4, 0)), None);
    /// assert_eq!(Arc::new((4.0, 4.0), 3.0, 0.0, f32::NAN), Err(microraster::Error::NonFiniteCoordinate));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(center: (f32, f32), radius: f32, start: f32, sweep: f32) -> Result<Self, Error> {
        ArcGeom::new(center, radius, start, sweep).map(Arc)
    }
}

impl Shape for Arc {
    fn fill_contours<const N: usize>(&self, _: &mut EdgeList<N>) -> Result<(), Error> {
        Ok(())
    }
    fn reach(&self, _fill: bool, stroke: Option<&StrokeParams>) -> Option<Reach> {
        // The annulus's two arcs (n + 1 edges at most each, the outer one's
        // chords the more numerous) and two caps (a start, the cap, an end:
        // at most 2 + max(3, J) edges); every vertex within r + half·√2 of
        // the centre (square caps' corners; round ones reach r + half).
        let (p, g) = (stroke?, &self.0);
        let n = crate::shape::flatten::segments(g.r + p.half, g.sweep) as usize;
        let j = if p.cap == Cap::Round { crate::shape::flatten::segments(p.half, PI) as usize } else { 3 };
        round_reach(g.c, g.r + p.half * SQRT_2, 2 * (n + 1) + 2 + 2 * (2 + j.max(3)))
    }
    /// The annular sector between radii `r ± width/2`, with the caps.
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        // Positive sweep only, so the caps' orientation is known.
        let g = &if self.0.sweep < 0.0 { self.0.reversed() } else { self.0 };
        e.close()?;
        g.points(e, g.r + p.half, false)?;
        g.points(e, (g.r - p.half).max(0.0), true)?;
        e.close()?;
        for (end, dir) in [(g.from, -1.0), (g.to, 1.0)] {
            let (s, c) = end.sin_cos();
            // The tangent pointing away from the arc at this end; the
            // clockwise annulus runs from outer to inner at the end and from
            // inner to outer at the start: the opposite of an open stroke's
            // outline, so the caps are flipped.
            let t = (-s * dir, c * dir);
            stroke::cap(e, (g.c.0 + g.r * c, g.c.1 + g.r * s), t, true, p)?;
        }
        Ok(())
    }
}

/// A pie slice: the centre plus an arc.
///
/// Angles as for [`Arc`]: any finite start keeps its sweep, and the end
/// directions are rounded to 1/4096 degree, so starts a whole turn apart
/// draw the same slice and `n` slices from `a0 + k·TAU/n` close at the wrap
/// (angles on that grid, as every whole degree; `docs/limits.md`).
///
/// ```
/// use core::f32::consts::{FRAC_PI_2, TAU};
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, Drawable};
/// use microraster::shape::{Sector, Shape, ShapeStyle};
/// let draw = |start: f32| {
///     let mut d = MockDisplay::new();
///     let s = Sector::new((8.03125, 8.03125), 6.0, start, 1.0).unwrap();
///     s.styled(ShapeStyle::fill(BinaryColor::On)).unwrap().draw(&mut d).unwrap();
///     d
/// };
/// // The corner straight above a centre on a 1/32 px tie: the same pixels.
/// assert_eq!(draw(-FRAC_PI_2), draw(-FRAC_PI_2 + TAU));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sector(ArcGeom);

impl Sector {
    /// Errors as for [`Arc::new`].
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
    /// use microraster::shape::{Sector, Shape, ShapeStyle};
    /// let mut display = MockDisplay::new();
    /// // The quarter from +x clockwise to +y: down and right of the centre.
    /// Sector::new((4.0, 4.0), 3.0, 0.0, FRAC_PI_2)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
    /// assert_eq!(display.get_pixel(Point::new(5, 5)), Some(BinaryColor::On));
    /// assert_eq!(display.get_pixel(Point::new(2, 5)), None);
    /// assert_eq!(display.get_pixel(Point::new(5, 2)), None);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(center: (f32, f32), radius: f32, start: f32, sweep: f32) -> Result<Self, Error> {
        ArcGeom::new(center, radius, start, sweep).map(Sector)
    }
}

impl Shape for Sector {
    fn fill_contours<const N: usize>(&self, e: &mut EdgeList<N>) -> Result<(), Error> {
        e.close()?;
        e.line_to(self.0.c.0, self.0.c.1)?;
        self.0.points(e, self.0.r, false)?;
        e.close()
    }
    /// The outline (two radii and the arc) with the style's joins at every
    /// chord vertex: several edges a chord, so large sectors can exceed
    /// [`MAX_EDGES`](crate::shape::MAX_EDGES) ([`Error::BufferTooSmall`] when styled).
    fn stroke_contours<const N: usize>(&self, e: &mut EdgeList<N>, p: &StrokeParams) -> Result<(), Error> {
        let g = &self.0;
        stroke::sector(e, g.c, g.r, (g.start, g.sweep), (g.from, g.to), p)
    }
}
