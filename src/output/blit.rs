//! Blitters: where rasterized spans and pixels are written.
//!
//! The rasterizers ([`crate::edge`], [`crate::line`]) only produce coordinates;
//! a [`Blitter`] turns them into colour. The band renderer blits into a
//! [`BandView`](crate::band::BandView); [`TargetBlitter`] blits straight into
//! any `embedded-graphics` [`DrawTarget`] (a full framebuffer, or a
//! `MockDisplay` in tests), with no band at all.

use crate::ClipRect;
use crate::edge::Span;
use embedded_graphics_core::prelude::{DrawTarget, Pixel, PixelColor, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

/// A sink for pixels. Implementors provide [`Blitter::clip`] and
/// [`Blitter::set_pixel`]; the span methods have per-pixel defaults that fast
/// implementors override.
pub trait Blitter<C: PixelColor> {
    /// The pixels this blitter accepts; rasterizers never emit outside it.
    fn clip(&self) -> ClipRect;

    /// Writes one pixel inside [`Blitter::clip`].
    fn set_pixel(&mut self, x: i32, y: i32, color: C);

    /// Writes `color` over a span inside the clip. The default writes pixel
    /// by pixel and stops at `i32::MAX` (columns beyond it do not exist;
    /// the rasterizers never emit such a span).
    fn fill_span(&mut self, span: Span, color: C) {
        for x in span_columns(span) {
            self.set_pixel(x, span.y, color);
        }
    }

    /// Writes one colour per pixel of the span, left to right (the default
    /// stops at `i32::MAX`, as [`Blitter::fill_span`]).
    fn shade_span<I: Iterator<Item = C>>(&mut self, span: Span, colors: I) {
        for (x, c) in span_columns(span).zip(colors) {
            self.set_pixel(x, span.y, c);
        }
    }
}

/// The columns of `span`, cut at `i32::MAX` (no overflow for any span).
fn span_columns(span: Span) -> impl Iterator<Item = i32> {
    let end = (i64::from(span.x) + i64::from(span.len)).min(i64::from(i32::MAX) + 1);
    // Every x < end ≤ 2^31 fits an i32.
    (i64::from(span.x)..end).map(|x| x as i32)
}

/// Blits directly into a [`DrawTarget`]: spans become `fill_solid` and
/// `fill_contiguous` calls. The first error the target reports is kept in
/// [`TargetBlitter::error`] and later writes are skipped.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{blit::TargetBlitter, edge::Cull, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let mut display = MockDisplay::<BinaryColor>::new();
/// let mut blitter = TargetBlitter::new(&mut display);
/// Triangle::flat([p(0, 0), p(3, 0), p(0, 3)], BinaryColor::On).draw(&mut blitter, Cull::None);
/// assert!(blitter.error.is_none());
/// display.assert_pattern(&["##", "# "]);
/// ```
pub struct TargetBlitter<'a, D: DrawTarget> {
    target: &'a mut D,
    clip: ClipRect,
    /// The first error reported by the target, if any.
    pub error: Option<D::Error>,
}

impl<'a, D: DrawTarget> TargetBlitter<'a, D> {
    /// Blits into `target`, clipped to its bounding box and to
    /// `0..MAX_FRAME_DIM` on both axes (the rasterizers' pixel range; pixels at
    /// negative coordinates are never drawn).
    pub fn new(target: &'a mut D) -> Self {
        let b = target.bounding_box();
        let (w, h) = (b.size.width.min(i32::MAX as u32) as i32, b.size.height.min(i32::MAX as u32) as i32);
        let clip = ClipRect::new(
            b.top_left.x,
            b.top_left.y,
            b.top_left.x.saturating_add(w),
            b.top_left.y.saturating_add(h),
        );
        TargetBlitter { target, clip, error: None }
    }

    /// `color` over columns `x .. x + w` of rows `y .. y + h`, one
    /// `fill_solid` call (the target clips, as for spans). Only the shape
    /// kit's direct drawing joins spans into rectangles.
    #[cfg(feature = "shapes")]
    pub(crate) fn fill_rect(&mut self, x: i32, y: i32, w: u32, h: u32, color: D::Color) {
        if self.error.is_none() {
            let r = self.target.fill_solid(&Rectangle::new(Point::new(x, y), Size::new(w, h)), color);
            self.keep(r);
        }
    }

    fn keep(&mut self, r: Result<(), D::Error>) {
        if let (Err(e), None) = (r, &self.error) {
            self.error = Some(e);
        }
    }
}

impl<D: DrawTarget> Blitter<D::Color> for TargetBlitter<'_, D> {
    fn clip(&self) -> ClipRect {
        self.clip
    }

    fn set_pixel(&mut self, x: i32, y: i32, color: D::Color) {
        if self.error.is_none() {
            let r = self.target.draw_iter(core::iter::once(Pixel(Point::new(x, y), color)));
            self.keep(r);
        }
    }

    fn fill_span(&mut self, span: Span, color: D::Color) {
        if self.error.is_none() {
            let r = self.target.fill_solid(&span_rect(span), color);
            self.keep(r);
        }
    }

    fn shade_span<I: Iterator<Item = D::Color>>(&mut self, span: Span, colors: I) {
        if self.error.is_none() {
            let r = self.target.fill_contiguous(&span_rect(span), colors);
            self.keep(r);
        }
    }
}

fn span_rect(s: Span) -> Rectangle {
    Rectangle::new(Point::new(s.x, s.y), Size::new(s.len, 1))
}
