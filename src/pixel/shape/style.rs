//! Styles and styled shapes, in the spirit of `embedded-graphics`'
//! `PrimitiveStyle` and `Styled`.

use super::stroke::StrokeParams;
use super::{Aliased, AntiAliased, Coverage, FillRule, Paint};
use crate::blend::OPAQUE;

mod bounds;
mod styled;
pub use styled::{PREPARED_EDGES, Prepared, Styled};

/// How thick lines meet at a vertex.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, prelude::*};
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::shape::{Join, Polyline, Shape, ShapeStyle};
/// // A right angle at (4, 4), 4 px wide: the miter fills the outer corner
/// // square, the bevel cuts it off.
/// let corner = [(4.0, 12.0), (4.0, 4.0), (12.0, 4.0)];
/// let drawn = |join| -> Result<bool, microraster::Error> {
///     let mut display = MockDisplay::new();
///     let style = ShapeStyle::stroke(BinaryColor::On, 4.0).with_join(join);
///     Polyline::new(&corner)?.styled(style)?.draw(&mut display).unwrap();
///     Ok(display.get_pixel(Point::new(2, 2)) == Some(BinaryColor::On))
/// };
/// assert!(drawn(Join::Miter)?);
/// assert!(!drawn(Join::Bevel)?);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Join {
    /// The outer edges extended to their meeting point, or [`Join::Bevel`]
    /// where that is farther than `miter_limit · width / 2` from the vertex.
    #[default]
    Miter,
    /// A circular arc around the vertex.
    Round,
    /// The outer corners joined by a straight edge.
    Bevel,
}

/// How open ends of thick lines finish.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, prelude::*};
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::shape::{Cap, Polyline, Shape, ShapeStyle};
/// // A 4 px wide line ending at x = 10: a butt cap stops there, a square
/// // cap reaches 2 px (half the width) beyond.
/// let line = [(2.0, 6.0), (10.0, 6.0)];
/// let reach = |cap| -> Result<bool, microraster::Error> {
///     let mut display = MockDisplay::new();
///     let style = ShapeStyle::stroke(BinaryColor::On, 4.0).with_cap(cap);
///     Polyline::new(&line)?.styled(style)?.draw(&mut display).unwrap();
///     Ok(display.get_pixel(Point::new(11, 6)) == Some(BinaryColor::On))
/// };
/// assert!(!reach(Cap::Butt)?);
/// assert!(reach(Cap::Square)?);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Cap {
    /// Square, at the end point.
    #[default]
    Butt,
    /// A half disc around the end point.
    Round,
    /// Square, extended by half the width.
    Square,
}

/// Fill and stroke of a shape. `A` ([`Aliased`] or [`AntiAliased`]) selects
/// the coverage code at compile time.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::shape::{Cap, Join, ShapeStyle};
/// let style = ShapeStyle::stroke(Rgb565::new(31, 0, 0), 3.0).with_join(Join::Round).with_cap(Cap::Round).antialiased();
/// assert_eq!(style.stroke_width, 3.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeStyle<C, A = Aliased> {
    /// Paint of the interior, if any.
    pub fill: Option<Paint<C>>,
    /// Paint of the outline, if any.
    pub stroke: Option<Paint<C>>,
    /// Width of the outline (px), centred on it; 0 draws no outline.
    pub stroke_width: f32,
    /// Joins of the outline.
    pub join: Join,
    /// Caps of open outlines (polylines, arcs).
    pub cap: Cap,
    /// Longest miter, in half widths (4, as tiny-skia's default).
    pub miter_limit: f32,
    /// Fill rule of the interior (strokes always use nonzero).
    pub fill_rule: FillRule,
    /// Coverage: [`Aliased`] or [`AntiAliased`].
    pub antialias: A,
    /// Opacity of fill and stroke (255: opaque), multiplied into each
    /// pixel's coverage: a translucent shape blends each pixel once.
    pub opacity: u8,
}

impl<C> ShapeStyle<C, Aliased> {
    /// Nothing drawn (add a fill or a stroke).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{FillRule, ShapeStyle};
    /// let style = ShapeStyle::<BinaryColor>::new();
    /// assert!(style.fill.is_none() && style.stroke.is_none());
    /// assert_eq!((style.fill_rule, style.opacity), (FillRule::NonZero, 255));
    /// ```
    pub const fn new() -> Self {
        ShapeStyle {
            fill: None,
            stroke: None,
            stroke_width: 0.0,
            join: Join::Miter,
            cap: Cap::Butt,
            miter_limit: 4.0,
            fill_rule: FillRule::NonZero,
            antialias: Aliased,
            opacity: OPAQUE,
        }
    }

    /// A solid or gradient fill.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Paint, ShapeStyle};
    /// let style = ShapeStyle::fill(BinaryColor::On);
    /// assert_eq!(style.fill, Some(Paint::Solid(BinaryColor::On)));
    /// assert!(style.stroke.is_none());
    /// ```
    pub fn fill(paint: impl Into<Paint<C>>) -> Self {
        Self::new().with_fill(paint)
    }

    /// A solid or gradient outline `width` px wide.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Paint, ShapeStyle};
    /// let style = ShapeStyle::stroke(BinaryColor::On, 2.0);
    /// assert_eq!((style.stroke, style.stroke_width), (Some(Paint::Solid(BinaryColor::On)), 2.0));
    /// assert!(style.fill.is_none());
    /// ```
    pub fn stroke(paint: impl Into<Paint<C>>, width: f32) -> Self {
        Self::new().with_stroke(paint, width)
    }
}

impl<C> Default for ShapeStyle<C, Aliased> {
    fn default() -> Self {
        Self::new()
    }
}

impl<C, A: Coverage> ShapeStyle<C, A> {
    /// With this fill.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Paint, ShapeStyle};
    /// let style = ShapeStyle::stroke(BinaryColor::On, 1.0).with_fill(BinaryColor::Off);
    /// assert_eq!(style.fill, Some(Paint::Solid(BinaryColor::Off)));
    /// assert_eq!(style.stroke, Some(Paint::Solid(BinaryColor::On))); // kept
    /// ```
    pub fn with_fill(self, paint: impl Into<Paint<C>>) -> Self {
        ShapeStyle { fill: Some(paint.into()), ..self }
    }
    /// With this outline.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Paint, ShapeStyle};
    /// let style = ShapeStyle::fill(BinaryColor::Off).with_stroke(BinaryColor::On, 3.0);
    /// assert_eq!((style.stroke, style.stroke_width), (Some(Paint::Solid(BinaryColor::On)), 3.0));
    /// assert_eq!(style.fill, Some(Paint::Solid(BinaryColor::Off))); // kept
    /// ```
    pub fn with_stroke(self, paint: impl Into<Paint<C>>, width: f32) -> Self {
        ShapeStyle { stroke: Some(paint.into()), stroke_width: width, ..self }
    }
    /// With this join.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Join, ShapeStyle};
    /// assert_eq!(ShapeStyle::stroke(BinaryColor::On, 2.0).join, Join::Miter);
    /// assert_eq!(ShapeStyle::stroke(BinaryColor::On, 2.0).with_join(Join::Round).join, Join::Round);
    /// ```
    pub fn with_join(self, join: Join) -> Self {
        ShapeStyle { join, ..self }
    }
    /// With this cap.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Cap, ShapeStyle};
    /// assert_eq!(ShapeStyle::stroke(BinaryColor::On, 2.0).cap, Cap::Butt);
    /// assert_eq!(ShapeStyle::stroke(BinaryColor::On, 2.0).with_cap(Cap::Square).cap, Cap::Square);
    /// ```
    pub fn with_cap(self, cap: Cap) -> Self {
        ShapeStyle { cap, ..self }
    }
    /// With this fill rule.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{FillRule, ShapeStyle};
    /// let style = ShapeStyle::fill(BinaryColor::On).with_fill_rule(FillRule::EvenOdd);
    /// assert_eq!(style.fill_rule, FillRule::EvenOdd);
    /// ```
    pub fn with_fill_rule(self, fill_rule: FillRule) -> Self {
        ShapeStyle { fill_rule, ..self }
    }
    /// With this opacity (0 transparent, 255 opaque). On a plain
    /// `DrawTarget` a partial pixel follows [`TargetCanvas`](super::TargetCanvas)'s rule.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::shape::{Rect, Shape, ShapeStyle};
    /// use microraster::{Band, Renderer};
    /// use microraster::render::from_fn;
    /// use embedded_graphics::mock_display::MockDisplay;
    /// let veil = Rect::new(0.0, 0.0, 2.0, 1.0)?.styled(ShapeStyle::fill(Gray8::WHITE).with_opacity(128))?;
    /// let mut band = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
    /// let mut display = MockDisplay::new();
    /// Renderer::new(1, Gray8::BLACK).render(from_fn(|view| {  veil.draw_on(view); Ok(()) }), &mut band, &mut display).unwrap();
    /// assert_eq!(display.get_pixel(embedded_graphics::prelude::Point::new(0, 0)), Some(Gray8::new(128)));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn with_opacity(self, opacity: u8) -> Self {
        ShapeStyle { opacity, ..self }
    }
    /// The same style, anti-aliased.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, shape::{Rect, Shape, ShapeStyle}};
    /// let bar = Rect::new(0.0, 0.0, 1.25, 1.0)?.styled(ShapeStyle::fill(Gray8::WHITE).antialiased())?;
    /// let mut band = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
    /// bar.draw_on(&mut band.view(0, 1, Gray8::BLACK));
    /// let edge = band.rows()[0][1].luma(); // a quarter of the pixel covered: grey
    /// assert!(edge > 0 && edge < 255);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn antialiased(self) -> ShapeStyle<C, AntiAliased> {
        self.with_coverage(AntiAliased)
    }
    /// The same style, aliased.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, shape::{Rect, Shape, ShapeStyle}};
    /// let style = ShapeStyle::fill(Gray8::WHITE).antialiased().aliased();
    /// let bar = Rect::new(0.0, 0.0, 1.25, 1.0)?.styled(style)?;
    /// let mut band = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
    /// bar.draw_on(&mut band.view(0, 1, Gray8::BLACK));
    /// assert_eq!(band.rows()[0], [Gray8::WHITE, Gray8::BLACK]); // centre 1.5 is outside
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn aliased(self) -> ShapeStyle<C, Aliased> {
        self.with_coverage(Aliased)
    }

    fn with_coverage<B: Coverage>(self, antialias: B) -> ShapeStyle<C, B> {
        let ShapeStyle { fill, stroke, stroke_width, join, cap, miter_limit, fill_rule, opacity, .. } = self;
        ShapeStyle { fill, stroke, stroke_width, join, cap, miter_limit, fill_rule, antialias, opacity }
    }

    fn params(&self) -> StrokeParams {
        StrokeParams {
            half: 0.5 * self.stroke_width,
            join: self.join,
            cap: self.cap,
            miter_limit: self.miter_limit,
        }
    }
}
