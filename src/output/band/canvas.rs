//! A band as an `embedded-graphics` [`DrawTarget`]: any e-g drawable (text in
//! any `MonoFont`, images, styled primitives) draws into the band being
//! rendered, in frame coordinates.
//!
//! The view accepts frame rows `y0 .. y0 + height` and columns `0 .. W`;
//! pixels anywhere else are dropped, exactly as a framebuffer the size of
//! the frame would drop pixels outside it. Each band sees the part of a
//! drawable that falls on its rows, so the assembled frame is the same as
//! drawing the drawable once into a full framebuffer, whatever the band
//! height (tested against e-g drawing into a framebuffer in
//! `tests/integration/drawables.rs`).
//!
//! Clipping is done in `i64`, so rectangles anywhere in e-g's coordinate
//! space (even ones whose far corner overflows `i32`) are accepted.

use super::{BandView, clear_rows, fill_run};
use crate::blit::Blitter;
use core::convert::Infallible;
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{Dimensions, Point, Size};
use embedded_graphics_core::pixelcolor::PixelColor;
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::{Drawable, Pixel};

impl<C: PixelColor, const W: usize> BandView<'_, C, W> {
    /// The columns `x0..x1` and view rows `r0..r1` of `area` inside the
    /// view, or `None` when they do not meet.
    fn overlap(&self, area: &Rectangle) -> Option<(usize, usize, usize, usize)> {
        let (ax, ay) = (i64::from(area.top_left.x), i64::from(area.top_left.y));
        let (aw, ah) = (i64::from(area.size.width), i64::from(area.size.height));
        let (y0, n) = (i64::from(self.y0), self.rows.len() as i64);
        let x0 = ax.max(0);
        let x1 = (ax + aw).min(W as i64);
        let r0 = (ay - y0).max(0);
        let r1 = (ay + ah - y0).min(n);
        // All four are in 0..=max(W, rows) when non-empty: the casts are exact.
        (x0 < x1 && r0 < r1).then_some((x0 as usize, x1 as usize, r0 as usize, r1 as usize))
    }
}

impl<C: PixelColor, const W: usize> BandView<'_, C, W> {
    /// Draws `item` if its bounding box meets the view's clip
    /// ([`Blitter::clip`]), and skips it otherwise; `Ok(None)` when skipped.
    ///
    /// Why: a band renderer runs the frame's drawing code once per band, and
    /// an e-g drawable generates all of its pixels every time, only for the
    /// view to drop those outside it. Text is the costly case: a
    /// `MonoText` walks every glyph pixel of every character in every band.
    /// Culled by its bounding box, it is only walked in the bands it
    /// reaches; the pixels are the same, since an e-g drawable draws nothing
    /// outside its bounding box (text, primitives and images all keep to it).
    ///
    /// ```
    /// use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
    /// use embedded_graphics::text::Text;
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use microraster::Band;
    /// let style = MonoTextStyle::new(&FONT_6X10, BinaryColor::On);
    /// let hi = Text::new("Hi", Point::new(0, 7), style); // rows 0 .. 10
    /// let mut band = Band::<BinaryColor, 32, 4>::new(BinaryColor::Off);
    /// // Rows 4 .. 8 meet the text: drawn, and e-g's output comes back.
    /// let mut view = band.view(4, 4, BinaryColor::Off);
    /// assert_eq!(view.draw_visible(&hi)?, Some(Point::new(12, 7)));
    /// assert!(band.rows().iter().flatten().any(|&c| c == BinaryColor::On));
    /// // Rows 12 .. 16 do not: skipped, no glyph pixel is generated.
    /// let mut view = band.view(12, 4, BinaryColor::Off);
    /// assert_eq!(view.draw_visible(&hi)?, None);
    /// assert!(band.rows().iter().flatten().all(|&c| c == BinaryColor::Off));
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn draw_visible<D>(&mut self, item: &D) -> Result<Option<D::Output>, Infallible>
    where
        D: Drawable<Color = C> + Dimensions,
    {
        let b = item.bounding_box();
        let clip = Blitter::clip(self);
        // In i64: a box anywhere in e-g's space, even one whose far corner
        // overflows i32, is compared exactly.
        let (x0, y0) = (i64::from(b.top_left.x), i64::from(b.top_left.y));
        let (x1, y1) = (x0 + i64::from(b.size.width), y0 + i64::from(b.size.height));
        let meets = x0 < i64::from(clip.x1())
            && x1 > i64::from(clip.x0())
            && y0 < i64::from(clip.y1())
            && y1 > i64::from(clip.y0());
        if meets { item.draw(self).map(Some) } else { Ok(None) }
    }
}

impl<C: PixelColor, const W: usize> Dimensions for BandView<'_, C, W> {
    /// The band's pixels in frame coordinates: columns `0..W`, rows
    /// `y0 .. y0 + height`.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    /// use microraster::Band;
    /// let mut band = Band::<BinaryColor, 8, 4>::new(BinaryColor::Off);
    /// let view = band.view(12, 3, BinaryColor::Off); // frame rows 12..15
    /// assert_eq!(view.bounding_box(), Rectangle::new(Point::new(0, 12), Size::new(8, 3)));
    /// ```
    fn bounding_box(&self) -> Rectangle {
        // A view has at most MAX_FRAME_DIM rows and W ≤ MAX_FRAME_DIM: exact.
        Rectangle::new(Point::new(0, self.y0), Size::new(W as u32, self.rows.len() as u32))
    }
}

/// Draws in frame coordinates; pixels outside the view are dropped.
///
/// ```
/// use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
/// use embedded_graphics::text::Text;
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use microraster::Band;
/// let mut band = Band::<BinaryColor, 32, 4>::new(BinaryColor::Off);
/// let mut view = band.view(4, 4, BinaryColor::Off); // frame rows 4..8
/// let style = MonoTextStyle::new(&FONT_6X10, BinaryColor::On);
/// // The text spans frame rows 0..10; this band gets its rows 4..8.
/// Text::new("Hi", Point::new(0, 7), style).draw(&mut view)?;
/// assert!(band.rows().iter().flatten().any(|&c| c == BinaryColor::On));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
impl<C: PixelColor, const W: usize> DrawTarget for BandView<'_, C, W> {
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            let x = usize::try_from(p.x).ok();
            if let Some(px) = x.and_then(|x| self.row_mut(p.y)?.get_mut(x)) {
                *px = c;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        let Some((x0, x1, r0, r1)) = self.overlap(area) else { return Ok(()) };
        // Colours run row by row over the whole `area`: skip the rows above
        // the view and, in each row, the columns left and right of it.
        let width = area.size.width as usize;
        let left = (i64::from(x0 as i32) - i64::from(area.top_left.x)) as usize; // ≥ 0
        let right = width - left - (x1 - x0);
        let above = (i64::from(self.y0) + r0 as i64 - i64::from(area.top_left.y)) as usize;
        let mut it = colors.into_iter();
        skip(&mut it, above.saturating_mul(width));
        for (k, row) in self.rows[r0..r1].iter_mut().enumerate() {
            skip(&mut it, left);
            for (p, c) in row[x0..x1].iter_mut().zip(&mut it) {
                *p = c;
            }
            if k + 1 < r1 - r0 {
                skip(&mut it, right);
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Infallible> {
        if let Some((x0, x1, r0, r1)) = self.overlap(area) {
            for row in &mut self.rows[r0..r1] {
                fill_run(&mut row[x0..x1], color);
            }
        }
        Ok(())
    }

    fn clear(&mut self, color: C) -> Result<(), Infallible> {
        clear_rows(self.rows, color);
        Ok(())
    }
}

/// Drops `n` items of `it` (fewer if it ends first).
#[inline]
fn skip<I: Iterator>(it: &mut I, n: usize) {
    if n > 0 {
        it.nth(n - 1);
    }
}
