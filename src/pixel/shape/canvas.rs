//! Where styled shapes draw: any [`Canvas`].

use crate::ClipRect;
use crate::band::BandView;
use crate::blend::{Blend, BlendTarget, Mix, OPAQUE};
use crate::blit::{Blitter, TargetBlitter};
use crate::color::Interpolate;
use crate::edge::Span;
use embedded_graphics_core::prelude::DrawTarget;

/// A surface for shapes: spans of one colour or of per-pixel colours, each
/// with a coverage alpha (255 = whole pixels).
///
/// A [`BandView`] is a canvas and blends partial pixels exactly ([`Mix`]);
/// [`TargetCanvas`] adapts any `DrawTarget`. For your own readable
/// framebuffer, implement the three methods (as `BandView` does, through
/// [`Blitter`] and [`BlendTarget`]).
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{Canvas, Rect, Shape, ShapeStyle};
/// use microraster::{ClipRect, edge::Span};
/// // A canvas that only measures: the covered area, in 1/255 pixels.
/// struct Area(u32);
/// impl Canvas<Gray8> for Area {
///     fn clip(&self) -> ClipRect {
///         ClipRect::new(0, 0, 32, 32)
///     }
///     fn fill(&mut self, span: Span, _: Gray8, alpha: u8) {
///         self.0 += span.len * u32::from(alpha);
///     }
///     fn shade<I: Iterator<Item = Gray8>>(&mut self, span: Span, _: I, alpha: u8) {
///         self.0 += span.len * u32::from(alpha);
///     }
/// }
/// let mut area = Area(0);
/// let square = Rect::new(2.5, 2.5, 4.0, 4.0)?.styled(ShapeStyle::fill(Gray8::WHITE).antialiased())?;
/// square.draw_on(&mut area);
/// // 4 × 4 px spread over 5 × 5 pixels: 9 whole, 12 halves, 4 quarters,
/// // each partial alpha rounded to the nearest 1/255 (128 and 64).
/// assert_eq!(area.0, 9 * 255 + 12 * 128 + 4 * 64);
/// # Ok::<(), microraster::Error>(())
/// ```
pub trait Canvas<C: Interpolate> {
    /// The pixels the canvas holds; shapes emit nothing outside.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, ClipRect, shape::Canvas};
    /// let mut band = Band::<Gray8, 8, 4>::new(Gray8::BLACK);
    /// // A view of 3 rows as frame rows 4 .. 7, at the band's width.
    /// let view = band.view(4, 3, Gray8::BLACK);
    /// assert_eq!(Canvas::<Gray8>::clip(&view), ClipRect::new(0, 4, 8, 7));
    /// ```
    fn clip(&self) -> ClipRect;
    /// `color` over `span` with coverage `alpha`.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, blend::{Blend, Mix}, edge::Span, shape::Canvas};
    /// let mut band = Band::<Gray8, 4, 1>::new(Gray8::BLACK);
    /// let mut view = band.view(0, 1, Gray8::BLACK);
    /// view.fill(Span { y: 0, x: 1, len: 2 }, Gray8::WHITE, 255);
    /// view.fill(Span { y: 0, x: 2, len: 2 }, Gray8::WHITE, 128);
    /// let half = Mix.blend(Gray8::WHITE, Gray8::BLACK, 128);
    /// assert_eq!(band.rows()[0], [Gray8::BLACK, Gray8::WHITE, Gray8::WHITE, half]);
    /// ```
    fn fill(&mut self, span: Span, color: C, alpha: u8);
    /// One colour per pixel of `span` with coverage `alpha`.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, edge::Span, shape::Canvas};
    /// let mut band = Band::<Gray8, 4, 1>::new(Gray8::BLACK);
    /// let mut view = band.view(0, 1, Gray8::BLACK);
    /// view.shade(Span { y: 0, x: 1, len: 3 }, [10, 20, 30].map(Gray8::new).into_iter(), 255);
    /// assert_eq!(band.rows()[0], [0, 10, 20, 30].map(Gray8::new));
    /// ```
    fn shade<I: Iterator<Item = C>>(&mut self, span: Span, colors: I, alpha: u8);
    /// `color` over `span` and the `rows − 1` rows below it (the same
    /// columns), coverage `alpha`: what `rows` calls of [`Canvas::fill`]
    /// draw, which is what this default does. A canvas that can fill a
    /// rectangle in one go (as [`TargetCanvas`] hands it to `fill_solid`)
    /// overrides it; an aliased [`Rect`](crate::shape::Rect)'s solid fill
    /// arrives here in one call.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, edge::Span, shape::Canvas};
    /// let mut band = Band::<Gray8, 4, 3>::new(Gray8::BLACK);
    /// let mut view = band.view(0, 3, Gray8::BLACK);
    /// view.fill_rect(Span { y: 1, x: 1, len: 2 }, 2, Gray8::WHITE, 255);
    /// let [b, w] = [Gray8::BLACK, Gray8::WHITE];
    /// assert_eq!(band.rows()[..3], [[b, b, b, b], [b, w, w, b], [b, w, w, b]]);
    /// ```
    fn fill_rect(&mut self, span: Span, rows: u32, color: C, alpha: u8) {
        for i in 0..rows {
            // `rows` comes from rows of the clip: `span.y + i` stays in i32.
            self.fill(Span { y: span.y.saturating_add(i as i32), ..span }, color, alpha);
        }
    }
}

impl<C: Interpolate, const W: usize> Canvas<C> for BandView<'_, C, W> {
    fn clip(&self) -> ClipRect {
        Blitter::clip(self)
    }
    #[inline]
    fn fill(&mut self, span: Span, color: C, alpha: u8) {
        if alpha == OPAQUE { self.fill_span(span, color) } else { self.blend_fill(Mix, span, color, alpha) }
    }
    #[inline]
    fn shade<I: Iterator<Item = C>>(&mut self, span: Span, colors: I, alpha: u8) {
        if alpha == OPAQUE {
            self.shade_span(span, colors)
        } else {
            self.blend_shade(Mix, span, colors, alpha)
        }
    }
}

/// Any `DrawTarget` as a [`Canvas`]. A `DrawTarget` cannot be read back, so
/// a partially covered pixel is mixed over [`TargetCanvas::over`]'s
/// background colour if one is given, and otherwise drawn opaque where its
/// coverage is at least ½ (alpha ≥ 128) and skipped below.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{Circle, Shape, ShapeStyle, TargetCanvas};
/// let disc = Circle::new((4.0, 4.0), 3.0)?.styled(ShapeStyle::fill(Gray8::WHITE).antialiased())?;
/// let mut display = MockDisplay::<Gray8>::new();
/// let mut canvas = TargetCanvas::new(&mut display).over(Gray8::BLACK);
/// disc.draw_on(&mut canvas);
/// canvas.finish().unwrap();
/// let edge = display.get_pixel(embedded_graphics::prelude::Point::new(1, 4)).unwrap();
/// assert!(edge.luma() > 0 && edge.luma() < 255);
/// # Ok::<(), microraster::Error>(())
/// ```
///
/// Opaque spans of one colour that continue each other row below row (same
/// columns) reach the target as one rectangle: a solid pixel-aligned
/// rectangle is one `fill_solid` call, as `embedded-graphics` draws it. The
/// last rectangle is sent by [`TargetCanvas::finish`] (or when the canvas is
/// dropped), before any other write.
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
/// use microraster::shape::{Rect, Shape, ShapeStyle, TargetCanvas};
/// # struct Frame([[bool; 8]; 8], usize);
/// # impl OriginDimensions for Frame {
/// #     fn size(&self) -> Size { Size::new(8, 8) }
/// # }
/// # impl DrawTarget for Frame {
/// #     type Color = BinaryColor;
/// #     type Error = core::convert::Infallible;
/// #     fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, px: I) -> Result<(), Self::Error> {
/// #         for Pixel(p, c) in px { self.0[p.y as usize][p.x as usize] = c.is_on(); }
/// #         Ok(())
/// #     }
/// #     fn fill_solid(&mut self, r: &Rectangle, c: BinaryColor) -> Result<(), Self::Error> {
/// #         self.1 += 1;
/// #         self.fill_contiguous(r, core::iter::repeat(c))
/// #     }
/// # }
/// // `Frame` counts its `fill_solid` calls in `.1`.
/// let mut frame = Frame([[false; 8]; 8], 0);
/// let card = Rect::new(1.0, 2.0, 5.0, 4.0)?.styled(ShapeStyle::fill(BinaryColor::On))?;
/// let mut canvas = TargetCanvas::new(&mut frame);
/// card.draw_on(&mut canvas);
/// canvas.finish().unwrap();
/// assert_eq!(frame.1, 1); // 4 rows of 5 pixels, one call
/// assert!(frame.0[5][5] && !frame.0[6][5]);
/// # Ok::<(), microraster::Error>(())
/// ```
pub struct TargetCanvas<'a, D: DrawTarget> {
    blitter: TargetBlitter<'a, D>,
    background: Option<D::Color>,
    /// Opaque rows not sent yet: the first row's span, the rows, the colour.
    pending: Option<(Span, u32, D::Color)>,
}

impl<D: DrawTarget> TargetCanvas<'_, D> {
    /// Sends the pending rectangle, if any.
    fn flush(&mut self) {
        if let Some((s, rows, c)) = self.pending.take() {
            self.blitter.fill_rect(s.x, s.y, s.len, rows, c);
        }
    }

    /// `color` over `span`, opaque: joined to the pending rectangle when it
    /// continues it.
    fn solid(&mut self, span: Span, color: D::Color) {
        if let Some((s, rows, c)) = &mut self.pending {
            if *c == color
                && s.x == span.x
                && s.len == span.len
                && i64::from(s.y) + i64::from(*rows) == i64::from(span.y)
            {
                *rows += 1;
                return;
            }
        }
        self.flush();
        self.pending = Some((span, 1, color));
    }
}

/// The last rectangle reaches the target even without [`TargetCanvas::finish`].
impl<D: DrawTarget> Drop for TargetCanvas<'_, D> {
    fn drop(&mut self) {
        self.flush();
    }
}

impl<'a, D: DrawTarget> TargetCanvas<'a, D>
where
    D::Color: Interpolate,
{
    /// Draws into `target` (clipped as [`TargetBlitter::new`]).
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor};
    /// use microraster::shape::{Rect, Shape, ShapeStyle, TargetCanvas};
    /// let bar = Rect::new(1.0, 0.0, 2.0, 1.0)?.styled(ShapeStyle::fill(BinaryColor::On))?;
    /// let mut display = MockDisplay::new();
    /// let mut canvas = TargetCanvas::new(&mut display);
    /// bar.draw_on(&mut canvas);
    /// canvas.finish().unwrap();
    /// display.assert_pattern(&[" ##"]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(target: &'a mut D) -> Self {
        TargetCanvas { blitter: TargetBlitter::new(target), background: None, pending: None }
    }

    /// Mixes partial pixels over `background`.
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, prelude::*};
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::shape::{Rect, Shape, ShapeStyle, TargetCanvas};
    /// // Pixel 1 is a quarter covered: skipped plain, grey over black.
    /// let bar = Rect::new(0.0, 0.0, 1.25, 1.0)?.styled(ShapeStyle::fill(Gray8::WHITE).antialiased())?;
    /// let (mut plain, mut over) = (MockDisplay::<Gray8>::new(), MockDisplay::<Gray8>::new());
    /// bar.draw_on(&mut TargetCanvas::new(&mut plain));
    /// bar.draw_on(&mut TargetCanvas::new(&mut over).over(Gray8::BLACK));
    /// assert_eq!(plain.get_pixel(Point::new(1, 0)), None);
    /// let grey = over.get_pixel(Point::new(1, 0)).unwrap().luma();
    /// assert!(grey > 0 && grey < 128);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn over(mut self, background: D::Color) -> Self {
        self.background = Some(background);
        self
    }

    /// The first error the target reported, if any.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use microraster::shape::{Rect, Shape, ShapeStyle, TargetCanvas};
    /// # struct Broken;
    /// # impl OriginDimensions for Broken {
    /// #     fn size(&self) -> Size { Size::new(8, 8) }
    /// # }
    /// # impl DrawTarget for Broken {
    /// #     type Color = BinaryColor;
    /// #     type Error = &'static str;
    /// #     fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, _: I) -> Result<(), &'static str> {
    /// #         Err("bus")
    /// #     }
    /// # }
    /// let mut display = Broken; // a DrawTarget whose every write fails with "bus"
    /// let bar = Rect::new(0.0, 0.0, 4.0, 2.0)?.styled(ShapeStyle::fill(BinaryColor::On))?;
    /// let mut canvas = TargetCanvas::new(&mut display);
    /// bar.draw_on(&mut canvas);
    /// assert_eq!(canvas.finish(), Err("bus"));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn finish(mut self) -> Result<(), D::Error> {
        self.flush();
        self.blitter.error.take().map_or(Ok(()), Err)
    }

    /// The colour a pixel of coverage `alpha` gets, `None` if skipped.
    fn partial(&self, c: D::Color, alpha: u8) -> Option<D::Color> {
        match self.background {
            Some(bg) => Some(Mix.blend(c, bg, alpha)),
            None => (alpha >= 128).then_some(c),
        }
    }
}

impl<D: DrawTarget> Canvas<D::Color> for TargetCanvas<'_, D>
where
    D::Color: Interpolate,
{
    fn clip(&self) -> ClipRect {
        self.blitter.clip()
    }

    fn fill(&mut self, span: Span, color: D::Color, alpha: u8) {
        if alpha == OPAQUE {
            self.solid(span, color);
        } else if let Some(c) = self.partial(color, alpha) {
            self.solid(span, c);
        }
    }

    /// One `fill_solid` for the whole rectangle (joined to the rows that
    /// follow it when they continue it, as spans are).
    fn fill_rect(&mut self, span: Span, rows: u32, color: D::Color, alpha: u8) {
        let color = if alpha == OPAQUE { Some(color) } else { self.partial(color, alpha) };
        if let (Some(c), true) = (color, rows > 0) {
            self.flush();
            self.pending = Some((span, rows, c));
        }
    }

    fn shade<I: Iterator<Item = D::Color>>(&mut self, span: Span, colors: I, alpha: u8) {
        // Writes stay in order: the pending rectangle first.
        self.flush();
        if alpha == OPAQUE {
            self.blitter.shade_span(span, colors);
        } else if alpha >= 128 || self.background.is_some() {
            for (i, c) in colors.enumerate().take(span.len as usize) {
                if let Some(c) = self.partial(c, alpha) {
                    self.blitter.set_pixel(span.x + i as i32, span.y, c);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;
