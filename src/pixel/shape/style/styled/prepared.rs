//! A styled shape with its edges built once, for the bands of a frame.
//!
//! [`Styled::draw_on`] builds a shape's edges in every band it meets: a
//! curve's chords are generated, tested against the band and the nearby ones
//! snapped, band after band, so a disc 120 px tall in 16-row bands is
//! flattened eight times. [`Prepared`] builds them once (the whole contour,
//! snapped, in a list of capacity `N` the caller owns) and each band only
//! walks the rows it holds. The pixels are the same: a row's coverage comes
//! from the edges crossing it, walked exactly from whichever row the walk
//! starts in (a band's list is the whole list restricted to its rows), as
//! the band-invariance tests check for the unprepared shape and
//! `prepared_bands_match_the_shape` for this one.

use super::Styled;
use crate::shape::scan::Chains;
use crate::shape::{Aliased, Canvas, Coverage, EdgeList, FillRule, Shape};
use crate::{ClipRect, Error, Interpolate, MAX_FRAME_DIM};

/// Edge capacity of [`Styled::prepare`]'s lists: a filled circle or ellipse
/// of any size (at most [`MAX_SEGMENTS`](crate::shape::MAX_SEGMENTS)
/// chords), a rounded rectangle or a polygon of up to 128 edges. A stroked
/// circle's two contours need up to twice as many (above a radius of about
/// 100 px): [`Prepared::new`] with `N = 256`.
pub const PREPARED_EDGES: usize = 128;

/// A [`Styled`] shape whose fill and stroke edges were built once, drawn into
/// any number of bands (or canvases) with [`Prepared::draw_on`]: each draw
/// walks only the rows of its clip, with none of the flattening and snapping
/// that [`Styled::draw_on`] repeats per band. Same pixels as
/// [`Styled::draw_on`].
///
/// Worth it for a shape that spans several bands, curved or many-sided;
/// a rectangle's fill needs no edges either way. Memory: two lists of `N`
/// edges of 20 bytes (5 KB at the default [`PREPARED_EDGES`]), owned by the
/// caller (a `static`, the stack of the frame's function).
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::shape::{Circle, Shape, ShapeStyle};
/// use microraster::{Band, Renderer, render::from_fn};
/// let disc = Circle::new((4.0, 4.0), 3.5)?.styled(ShapeStyle::fill(BinaryColor::On))?;
/// let mut prepared = disc.prepare()?; // flattened and snapped once
/// let mut band = Band::<BinaryColor, 8, 2>::new(BinaryColor::Off);
/// let (mut a, mut b) = (MockDisplay::new(), MockDisplay::new());
/// let renderer = Renderer::new(8, BinaryColor::Off);
/// renderer.render(from_fn(|view| { prepared.draw_on(view); Ok(()) }), &mut band, &mut a)?;
/// renderer.render(from_fn(|view| { disc.draw_on(view); Ok(()) }), &mut band, &mut b)?;
/// a.assert_eq(&b); // the same pixels as the shape built in every band
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Prepared<S, C, A = Aliased, const N: usize = PREPARED_EDGES> {
    styled: Styled<S, C, A>,
    fill: EdgeList<N>,
    stroke: EdgeList<N>,
    // Each list's two chains over every row, if it is two (aliased only):
    // a band walks them from its rows without looking for them again.
    chains: [Option<Chains>; 2],
}

impl<S: Shape + Clone, C: Interpolate, A: Coverage> Styled<S, C, A> {
    /// This shape with its edges built once, in lists of
    /// [`PREPARED_EDGES`] (see [`Prepared`]; [`Prepared::new`] for another
    /// capacity).
    ///
    /// Errors: [`Error::BufferTooSmall`] if the fill's or the stroke's
    /// edges do not fit (a stroked circle of a radius above about 100 px:
    /// use `Prepared::<_, _, _, 256>::new`).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::Error;
    /// use microraster::shape::{Circle, Prepared, Shape, ShapeStyle};
    /// let ring = Circle::new((220.0, 220.0), 200.0)?.styled(ShapeStyle::stroke(BinaryColor::On, 4.0))?;
    /// assert!(matches!(ring.prepare(), Err(Error::BufferTooSmall)));
    /// assert!(Prepared::<_, _, _, 256>::new(ring).is_ok());
    /// # Ok::<(), Error>(())
    /// ```
    pub fn prepare(&self) -> Result<Prepared<S, C, A>, Error> {
        Prepared::new(self.clone())
    }
}

impl<S: Shape, C: Interpolate, A: Coverage, const N: usize> Prepared<S, C, A, N> {
    /// `styled` with its fill's and stroke's edges built, each in a list of
    /// `N` edges.
    ///
    /// Errors: [`Error::BufferTooSmall`] if either part's edges do not fit.
    pub fn new(styled: Styled<S, C, A>) -> Result<Self, Error> {
        let mut p = Prepared { styled, fill: EdgeList::new(), stroke: EdgeList::new(), chains: [None; 2] };
        p.build()?;
        Ok(p)
    }

    /// Replaces the shape with `styled` and builds its edges in the same
    /// lists, without moving or clearing them: a shape that changes every
    /// frame (a needle, a bar) in a `static` slot pays its edges once a
    /// frame and nothing more.
    ///
    /// Errors: [`Error::BufferTooSmall`] if either part's edges do not fit
    /// (then nothing is drawn until a `set` succeeds).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::shape::{Circle, Shape, ShapeStyle};
    /// let style = ShapeStyle::fill(BinaryColor::On);
    /// let mut dot = Circle::new((10.0, 10.0), 4.0)?.styled(style)?.prepare()?;
    /// for x in 11..20 {
    ///     dot.set(Circle::new((x as f32, 10.0), 4.0)?.styled(style)?)?; // each frame
    /// }
    /// assert_eq!(dot.styled().shape(), &Circle::new((19.0, 10.0), 4.0)?);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn set(&mut self, styled: Styled<S, C, A>) -> Result<(), Error> {
        self.styled = styled;
        self.build()
    }

    /// Builds the edges of `self.styled`; both lists empty on an error.
    fn build(&mut self) -> Result<(), Error> {
        let s = &self.styled;
        let built = if A::WHOLE && s.shape.fill_box().is_some() {
            // An aliased box's fill is drawn without edges (`box_fill`).
            self.fill.clear();
            Ok(())
        } else {
            s.fill_edges(&mut self.fill)
        };
        let built = built.and_then(|()| s.stroke_edges(&mut self.stroke));
        if built.is_err() {
            self.fill.clear();
            self.stroke.clear();
        }
        // Found as `Aliased::cover` finds them, over every clip's rows.
        let every = ClipRect::new(0, 0, MAX_FRAME_DIM as i32, MAX_FRAME_DIM as i32);
        let chains =
            |e: &EdgeList<N>| if A::WHOLE { Chains::in_contour_order(e.edges(), every) } else { None };
        self.chains = [chains(&self.fill), chains(&self.stroke)];
        built
    }

    /// The styled shape.
    pub fn styled(&self) -> &Styled<S, C, A> {
        &self.styled
    }

    /// Draws on `canvas` as [`Styled::draw_on`] does (fill, then stroke),
    /// from the edges built once: only the rows of `canvas`'s clip are
    /// walked. (`&mut self`: the first draw may sort the lists in place.)
    pub fn draw_on<T: Canvas<C>>(&mut self, canvas: &mut T) {
        let s = &self.styled;
        if s.misses(canvas.clip()) {
            return;
        }
        // The same order and shortcut as `Styled::draw_on`: an aliased box
        // fill is one span per row, without its edges.
        if let Some(paint) = &s.style.fill {
            if !(A::WHOLE && s.box_fill(canvas)) {
                s.cover_with(&mut self.fill, self.chains[0], paint, s.style.fill_rule, canvas);
            }
        }
        if let Some(paint) = &s.style.stroke {
            s.cover_with(&mut self.stroke, self.chains[1], paint, FillRule::NonZero, canvas);
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::super::tests::frame_by;
    use super::*;
    use crate::shape::{Arc, Cap, Circle, Ellipse, Polygon, RoundedRect, ShapeStyle};
    use crate::test_rng::Rng;
    use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    use std::vec::Vec;

    /// Prepared and unprepared, in bands of 1, 3, 16 and 48 rows; prepared
    /// first as `before`, then `set` to `s` (the lists reused).
    fn check<S: Shape + Clone, A: Coverage>(before: Styled<S, Gray8, A>, s: Styled<S, Gray8, A>) -> usize {
        let mut p = Prepared::<_, _, _, 256>::new(before).unwrap();
        p.set(s.clone()).unwrap();
        let mut lit = 0;
        for h in [1, 3, 16, 48] {
            let want = frame_by(h, |v| s.draw_on(v));
            assert_eq!(frame_by(h, |v| p.draw_on(v)), want, "{h}-row bands");
            lit += want.iter().filter(|&&c| c != Gray8::new(20)).count();
        }
        lit
    }

    #[test]
    fn prepared_bands_match_the_shape() {
        let mut rng = Rng(0x2545_f491_4f6c_dd1d);
        let mut r = |scale: f32| rng.unit(scale);
        let mut lit = 0;
        let mut prev = None;
        for i in 0..300 {
            let c = (r(80.0) - 8.0, r(64.0) - 8.0);
            let style = ShapeStyle::fill(Gray8::new(200))
                .with_stroke(Gray8::WHITE, r(4.0))
                .with_cap(Cap::Round)
                .with_opacity(if i % 3 == 0 { 128 } else { 255 });
            let (rx, ry) = (0.5 + r(40.0), 0.5 + r(30.0));
            let rect = crate::shape::Rect::new(c.0 - rx, c.1 - ry, 2.0 * rx, 2.0 * ry).unwrap();
            let star: Vec<(f32, f32)> = (0..7).map(|_| (r(80.0) - 8.0, r(64.0) - 8.0)).collect();
            let star: &'static [(f32, f32)] = star.leak();
            let shapes = (
                Circle::new(c, rx).unwrap().styled(style).unwrap(),
                Ellipse::new(c, rx, ry).unwrap().styled(style.antialiased()).unwrap(),
                Arc::new(c, rx, r(6.0), r(8.0) - 4.0).unwrap().styled(style).unwrap(),
                rect.styled(style).unwrap(),
                RoundedRect::new(rect, r(12.0)).unwrap().styled(style.antialiased()).unwrap(),
                Polygon::new(star).unwrap().styled(style).unwrap(),
            );
            let b = prev.unwrap_or(shapes);
            lit += check(b.0, shapes.0) + check(b.1, shapes.1) + check(b.2, shapes.2);
            lit += check(b.3, shapes.3) + check(b.4, shapes.4) + check(b.5, shapes.5);
            prev = Some(shapes);
        }
        // The comparison saw shapes, not empty frames.
        assert!(lit > 1_000_000, "{lit}");
    }

    #[test]
    fn edges_that_do_not_fit_are_a_typed_error() {
        let ring = Circle::new((30.0, 30.0), 25.0).unwrap();
        let ring = ring.styled(ShapeStyle::stroke(Gray8::WHITE, 3.0)).unwrap();
        assert!(matches!(Prepared::<_, _, _, 16>::new(ring), Err(Error::BufferTooSmall)));
        assert!(Prepared::<_, _, _, 256>::new(ring).is_ok());
    }
}
