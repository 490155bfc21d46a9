//! Paint: solid colour and linear or radial gradients between two colours.
//!
//! A gradient's parameter `t` is evaluated at each pixel centre, clamped to
//! `[0, 1]` (pad), and the colour is [`Mix`] of the two end colours with
//! alpha `round(255·t)`: per channel within ½ of the colour's own step of
//! the exact `c0 + t·(c1 − c0)`, plus 1/510 of the range from the 8-bit `t`.

use super::canvas::Canvas;
use crate::blend::{Blend, Mix};
use crate::color::Interpolate;
use crate::edge::Span;
use crate::{Error, Param};

/// What a shape is filled or stroked with.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::shape::{LinearGradient, Paint};
/// let solid: Paint<Rgb565> = Rgb565::new(31, 0, 0).into();
/// let ramp = Paint::Linear(LinearGradient::new((0.0, 0.0), (10.0, 0.0), [Rgb565::BLACK, Rgb565::WHITE])?);
/// # let _ = (solid, ramp);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Paint<C> {
    /// One colour.
    Solid(C),
    /// A linear gradient.
    Linear(LinearGradient<C>),
    /// A radial gradient.
    Radial(RadialGradient<C>),
}

impl<C> From<C> for Paint<C> {
    fn from(c: C) -> Self {
        Paint::Solid(c)
    }
}
impl<C> From<LinearGradient<C>> for Paint<C> {
    fn from(g: LinearGradient<C>) -> Self {
        Paint::Linear(g)
    }
}
impl<C> From<RadialGradient<C>> for Paint<C> {
    fn from(g: RadialGradient<C>) -> Self {
        Paint::Radial(g)
    }
}

/// `colors[0]` at `start`, `colors[1]` at `end`, constant along lines
/// perpendicular to `start → end` and padded beyond.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, prelude::*};
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{LinearGradient, Rect, Shape, ShapeStyle};
/// // Black at x = 0 to white at x = 16, as the fill of a bar.
/// let ramp = LinearGradient::new((0.0, 0.0), (16.0, 0.0), [Gray8::BLACK, Gray8::WHITE])?;
/// let mut display = MockDisplay::<Gray8>::new();
/// Rect::new(0.0, 0.0, 16.0, 2.0)?.styled(ShapeStyle::fill(ramp))?.draw(&mut display).unwrap();
/// let luma = |x| display.get_pixel(Point::new(x, 1)).unwrap().luma();
/// assert!(luma(0) < luma(8) && luma(8) < luma(15));
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearGradient<C> {
    start: (f32, f32),
    // (end − start) / |end − start|²: t = (p − start) · k.
    k: (f32, f32),
    colors: [C; 2],
}

impl<C> LinearGradient<C> {
    /// Errors: NaN ([`Error::NonFiniteCoordinate`]); `start == end`
    /// ([`Error::InvalidParameter`]).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::shape::LinearGradient;
    /// let g = LinearGradient::new((0.0, 0.0), (0.0, 0.0), [Gray8::BLACK, Gray8::WHITE]);
    /// assert_eq!(g, Err(microraster::Error::InvalidParameter(microraster::Param::Gradient)));
    /// ```
    pub fn new(start: (f32, f32), end: (f32, f32), colors: [C; 2]) -> Result<Self, Error> {
        let d = (end.0 - start.0, end.1 - start.1);
        let l2 = d.0 * d.0 + d.1 * d.1;
        if ![start.0, start.1, end.0, end.1, l2].iter().all(|v| v.is_finite()) {
            return Err(Error::NonFiniteCoordinate);
        }
        if l2 <= 0.0 {
            return Err(Error::InvalidParameter(Param::Gradient));
        }
        Ok(LinearGradient { start, k: (d.0 / l2, d.1 / l2), colors })
    }
}

/// `colors[0]` at `center`, `colors[1]` at distance `radius` and beyond.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, prelude::*};
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{Circle, RadialGradient, Shape, ShapeStyle};
/// // A lit ball: white in the middle, black at the rim.
/// let glow = RadialGradient::new((8.0, 8.0), 8.0, [Gray8::WHITE, Gray8::BLACK])?;
/// let mut display = MockDisplay::<Gray8>::new();
/// Circle::new((8.0, 8.0), 8.0)?.styled(ShapeStyle::fill(glow))?.draw(&mut display).unwrap();
/// let luma = |x| display.get_pixel(Point::new(x, 8)).unwrap().luma();
/// assert!(luma(8) > luma(4) && luma(4) > luma(1));
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadialGradient<C> {
    center: (f32, f32),
    inv_r: f32,
    colors: [C; 2],
}

impl<C> RadialGradient<C> {
    /// Errors: NaN ([`Error::NonFiniteCoordinate`]); a radius that is not
    /// positive ([`Error::InvalidParameter`]).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::shape::RadialGradient;
    /// assert!(RadialGradient::new((5.0, 5.0), 4.0, [Gray8::WHITE, Gray8::BLACK]).is_ok());
    /// ```
    pub fn new(center: (f32, f32), radius: f32, colors: [C; 2]) -> Result<Self, Error> {
        if ![center.0, center.1, radius].iter().all(|v| v.is_finite()) {
            return Err(Error::NonFiniteCoordinate);
        }
        if radius <= 0.0 {
            return Err(Error::InvalidParameter(Param::Gradient));
        }
        Ok(RadialGradient { center, inv_r: 1.0 / radius, colors })
    }
}

/// Alpha `round(255·clamp(t, 0, 1))`.
#[inline]
fn weight(t: f32) -> u8 {
    (t.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

impl<C: Interpolate> Paint<C> {
    /// The colour at pixel `(x, y)` (its centre).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::shape::{LinearGradient, Paint};
    /// let p = Paint::Linear(LinearGradient::new((0.0, 0.0), (10.0, 0.0), [Gray8::BLACK, Gray8::WHITE])?);
    /// assert_eq!(p.color_at(4, 0), Gray8::new(115)); // t = 0.45: round(114.75)
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn color_at(&self, x: i32, y: i32) -> C {
        match self {
            Paint::Solid(c) => *c,
            Paint::Linear(LinearGradient { colors, .. }) | Paint::Radial(RadialGradient { colors, .. }) => {
                Mix.blend(colors[1], colors[0], self.weight_at(x, y))
            }
        }
    }

    /// A gradient's `round(255·t)` at pixel `(x, y)` (0 for a solid paint).
    #[inline]
    fn weight_at(&self, x: i32, y: i32) -> u8 {
        let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
        match self {
            Paint::Solid(_) => 0,
            Paint::Linear(g) => weight((px - g.start.0) * g.k.0 + (py - g.start.1) * g.k.1),
            Paint::Radial(g) => {
                let (dx, dy) = (px - g.center.0, py - g.center.1);
                weight(crate::math::Scalar::sqrt(dx * dx + dy * dy) * g.inv_r)
            }
        }
    }

    /// Paints `span` and the `rows − 1` rows below it on `canvas` with
    /// coverage `alpha`: a solid colour as one [`Canvas::fill_rect`], a
    /// gradient row by row as [`Paint::paint`] paints it.
    pub(crate) fn paint_rect<T: Canvas<C>>(&self, canvas: &mut T, span: Span, rows: u32, alpha: u8) {
        match self {
            Paint::Solid(c) => canvas.fill_rect(span, rows, *c, alpha),
            _ => {
                for i in 0..rows {
                    // Rows of the clip: within i32.
                    self.paint(canvas, Span { y: span.y.saturating_add(i as i32), ..span }, alpha);
                }
            }
        }
    }

    /// Paints `span` on `canvas` with coverage `alpha`.
    pub(crate) fn paint<T: Canvas<C>>(&self, canvas: &mut T, span: Span, alpha: u8) {
        match self {
            Paint::Solid(c) => canvas.fill(span, *c, alpha),
            // Constant along a row (`(px − x0)·0` is 0 for every px): one colour.
            Paint::Linear(g) if g.k.0 == 0.0 => canvas.fill(span, self.color_at(span.x, span.y), alpha),
            // The row's part of `t` once per span: the same products and
            // sums as `weight_at`, in the same order, so the same weights.
            Paint::Linear(g) => {
                let row = (span.y as f32 + 0.5 - g.start.1) * g.k.1;
                let w = |x: i32| weight((x as f32 + 0.5 - g.start.0) * g.k.0 + row);
                shade_by_weight(canvas, span, g.colors, alpha, w)
            }
            Paint::Radial(g) => {
                let dy = span.y as f32 + 0.5 - g.center.1;
                let dy2 = dy * dy;
                let w = |x: i32| {
                    let dx = x as f32 + 0.5 - g.center.0;
                    weight(crate::math::Scalar::sqrt(dx * dx + dy2) * g.inv_r)
                };
                shade_by_weight(canvas, span, g.colors, alpha, w)
            }
        }
    }
}

/// `span` shaded with `colors` mixed by `w(x)` at each pixel, coverage
/// `alpha`. The colour depends on the 8-bit weight alone, which changes
/// every pixel or more: mixed again only when it changes.
#[inline]
fn shade_by_weight<C: Interpolate, T: Canvas<C>>(
    canvas: &mut T,
    span: Span,
    colors: [C; 2],
    alpha: u8,
    mut w: impl FnMut(i32) -> u8,
) {
    let first = w(span.x);
    let mut last = (first, Mix.blend(colors[1], colors[0], first));
    let each = (0..span.len as i32).map(move |i| {
        let w = w(span.x + i);
        if w != last.0 {
            last = (w, Mix.blend(colors[1], colors[0], w));
        }
        last.1
    });
    canvas.shade(span, each, alpha)
}
