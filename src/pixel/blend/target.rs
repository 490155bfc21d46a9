//! Blending into surfaces: [`BlendTarget`] and the [`BlendBlitter`].

use super::Blend;
use crate::ClipRect;
use crate::band::BandView;
use crate::blit::Blitter;
use crate::color::Interpolate;
use crate::edge::Span;

/// A surface that can be blended into: it can read back what it holds.
/// Implemented for [`BandView`]; implement it for your own framebuffer to use
/// [`BlendBlitter`] and [`LineAa`](crate::line_aa::LineAa) on it.
///
/// Pixels outside [`BlendTarget::clip`] must be ignored (never a panic).
pub trait BlendTarget<C: Interpolate> {
    /// The pixels this target holds.
    fn clip(&self) -> ClipRect;

    /// Blends `color` into pixel `(x, y)` with `mode` and `alpha`.
    fn blend_pixel<B: Blend>(&mut self, mode: B, x: i32, y: i32, color: C, alpha: u8);

    /// Blends `color` into every pixel of `span`.
    fn blend_fill<B: Blend>(&mut self, mode: B, span: Span, color: C, alpha: u8) {
        for i in 0..span.len as i32 {
            self.blend_pixel(mode, span.x.saturating_add(i), span.y, color, alpha);
        }
    }

    /// Blends one colour per pixel of `span`, left to right.
    fn blend_shade<B: Blend, I: Iterator<Item = C>>(&mut self, mode: B, span: Span, colors: I, alpha: u8) {
        for (i, c) in (0..span.len as i32).zip(colors) {
            self.blend_pixel(mode, span.x.saturating_add(i), span.y, c, alpha);
        }
    }
}

impl<C: Interpolate, const W: usize> BandView<'_, C, W> {
    /// The pixels of `span` in this view, if it lies wholly inside.
    fn span_mut(&mut self, s: Span) -> Option<&mut [C]> {
        let x0 = usize::try_from(s.x).ok()?;
        self.row_mut(s.y)?.get_mut(x0..x0.checked_add(s.len as usize)?)
    }
}

impl<C: Interpolate, const W: usize> BlendTarget<C> for BandView<'_, C, W> {
    fn clip(&self) -> ClipRect {
        Blitter::clip(self)
    }

    #[inline]
    fn blend_pixel<B: Blend>(&mut self, mode: B, x: i32, y: i32, color: C, alpha: u8) {
        let x = usize::try_from(x).ok();
        if let Some(p) = x.and_then(|x| self.row_mut(y)?.get_mut(x)) {
            *p = mode.blend(color, *p, alpha);
        }
    }

    #[inline]
    fn blend_fill<B: Blend>(&mut self, mode: B, span: Span, color: C, alpha: u8) {
        if let Some(px) = self.span_mut(span) {
            mode.blend_fill(px, color, alpha);
        }
    }

    #[inline]
    fn blend_shade<B: Blend, I: Iterator<Item = C>>(&mut self, mode: B, span: Span, colors: I, alpha: u8) {
        if let Some(px) = self.span_mut(span) {
            mode.blend_span(px, colors, alpha);
        }
    }
}

/// A [`Blitter`] that blends every pixel it is given into a [`BlendTarget`]
/// with a fixed mode and alpha; see the [module docs](super) for an example.
pub struct BlendBlitter<'t, T, B> {
    target: &'t mut T,
    mode: B,
    alpha: u8,
}

impl<'t, T, B: Blend> BlendBlitter<'t, T, B> {
    /// Blends into `target` with `mode` and `alpha` (255 = opaque).
    pub fn new(target: &'t mut T, mode: B, alpha: u8) -> Self {
        BlendBlitter { target, mode, alpha }
    }

    /// The alpha.
    pub fn alpha(&self) -> u8 {
        self.alpha
    }

    /// Changes the alpha for later primitives.
    pub fn set_alpha(&mut self, alpha: u8) {
        self.alpha = alpha;
    }
}

impl<C: Interpolate, T: BlendTarget<C>, B: Blend> Blitter<C> for BlendBlitter<'_, T, B> {
    fn clip(&self) -> ClipRect {
        self.target.clip()
    }

    #[inline]
    fn set_pixel(&mut self, x: i32, y: i32, color: C) {
        self.target.blend_pixel(self.mode, x, y, color, self.alpha);
    }

    #[inline]
    fn fill_span(&mut self, span: Span, color: C) {
        self.target.blend_fill(self.mode, span, color, self.alpha);
    }

    #[inline]
    fn shade_span<I: Iterator<Item = C>>(&mut self, span: Span, colors: I) {
        self.target.blend_shade(self.mode, span, colors, self.alpha);
    }
}
