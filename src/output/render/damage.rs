//! Damage regions: render and send only the rectangles that changed.
//!
//! A [`Damage`] list holds up to `N` rectangles in frame coordinates (the
//! old and new boxes of what moved). [`Renderer::render_damaged`] renders
//! only the rows those rectangles touch, in as few bands as they fill, with
//! the band's clip narrowed to the damaged columns, and sends the union of
//! the rectangles, each pixel once, with one `fill_contiguous` per disjoint
//! part. The pass's fixed cost per band (a closure that builds every shape)
//! is paid once per band drawn, so packing the rows matters as much as
//! narrowing them.
//!
//! # Why the pixels are a full frame's
//! A pass draws the whole frame in frame coordinates and the image does not
//! depend on which rows a band holds (the band-invariance tests) nor on the
//! clip's columns: every shape and primitive computes a pixel from the
//! geometry alone (a triangle's or shape's coverage of a pixel does not
//! depend on where the clip starts; anti-aliased rows carry the coverage
//! accumulated left of the clip). So each damaged pixel is the full frame's,
//! and pixels outside the damage are not sent: the display keeps them.
//!
//! # Disjoint parts
//! Within a band the rows split where a rectangle starts or ends; in each
//! such strip the rectangles crossing it give column intervals, merged where
//! they overlap or touch. Strip × interval parts cover the union exactly
//! once, so the pixels sent are the damaged area (no pixel twice). With
//! `N` rectangles a band has at most `2N` strips of at most `N` parts;
//! finding them is `O(N²)` per strip, no memory.

use embedded_graphics_core::geometry::Dimensions;
use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::{Pass, Renderer};
use crate::band::{Band, BandView, fill_run};
use crate::{Error, Interpolate, MAX_FRAME_DIM, RenderError};

/// A half-open box `x0..x1 × y0..y1`, non-empty, within `0..=MAX_FRAME_DIM`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Box2 {
    x0: i32,
    y0: i32,
    x1: i32,
    y1: i32,
}

impl Box2 {
    /// `r` clamped to `0..=limit` in both axes (in `i64`: any e-g rectangle),
    /// `None` if nothing is left.
    fn clamped(r: &Rectangle, w: i64, h: i64) -> Option<Box2> {
        let (x, y) = (i64::from(r.top_left.x), i64::from(r.top_left.y));
        let x0 = x.clamp(0, w);
        let y0 = y.clamp(0, h);
        let x1 = (x + i64::from(r.size.width)).clamp(0, w);
        let y1 = (y + i64::from(r.size.height)).clamp(0, h);
        // All four within 0..=MAX_FRAME_DIM: the casts are exact.
        (x0 < x1 && y0 < y1).then_some(Box2 { x0: x0 as i32, y0: y0 as i32, x1: x1 as i32, y1: y1 as i32 })
    }

    fn contains(&self, o: &Box2) -> bool {
        self.x0 <= o.x0 && self.y0 <= o.y0 && self.x1 >= o.x1 && self.y1 >= o.y1
    }

    fn rectangle(&self) -> Rectangle {
        Rectangle::new(
            Point::new(self.x0, self.y0),
            Size::new((self.x1 - self.x0) as u32, (self.y1 - self.y0) as u32),
        )
    }
}

/// Up to `N` damaged rectangles of a frame, in frame coordinates: what
/// [`Renderer::render_damaged`] renders and sends.
///
/// Rectangles are kept clamped to `0..=MAX_FRAME_DIM` (the renderer clips
/// them to the frame); an empty one is dropped, one inside another is not
/// stored, and one that holds others replaces them. A rectangle that would
/// need an `N + 1`th slot is refused with [`Error::CapacityExceeded`] and
/// the list is left as it was: nothing has been sent yet, and the caller
/// decides (render the full frame, or use a larger `N`).
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use microraster::Error;
/// use microraster::render::Damage;
/// let r = |x, y, w, h| Rectangle::new(Point::new(x, y), Size::new(w, h));
/// let mut damage = Damage::<2>::new();
/// damage.add(r(10, 10, 8, 8))?;
/// damage.add(r(12, 12, 2, 2))?; // inside the first: nothing to store
/// damage.add(r(-50, -50, 10, 10))?; // above and left of any frame: dropped
/// damage.add(r(40, 0, 4, 4))?;
/// assert_eq!(damage.rects().count(), 2);
/// assert_eq!(damage.add(r(0, 40, 4, 4)), Err(Error::CapacityExceeded { needed: 3, capacity: 2 }));
/// // What moved, by its old and new bounding boxes (anything with e-g `Dimensions`):
/// let mut moved = Damage::<4>::new();
/// moved.add_moved(&r(0, 0, 6, 6), &r(3, 0, 6, 6))?;
/// assert_eq!(moved.area(320, 240), 9 * 6); // the union, each pixel once
/// # Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Damage<const N: usize> {
    boxes: heapless::Vec<Box2, N>,
}

impl<const N: usize> Default for Damage<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> Damage<N> {
    /// No damage: a frame rendered with it sends nothing.
    pub const fn new() -> Self {
        Damage { boxes: heapless::Vec::new() }
    }

    /// Forgets every rectangle (for the next frame).
    pub fn clear(&mut self) {
        self.boxes.clear();
    }

    /// Whether nothing is damaged.
    pub fn is_empty(&self) -> bool {
        self.boxes.is_empty()
    }

    /// The stored rectangles (clamped, none inside another).
    pub fn rects(&self) -> impl Iterator<Item = Rectangle> + '_ {
        self.boxes.iter().map(Box2::rectangle)
    }

    /// Marks `rect` damaged. Errors: [`Error::CapacityExceeded`] if it needs
    /// a slot and all `N` are taken (the list is unchanged).
    pub fn add(&mut self, rect: Rectangle) -> Result<(), Error> {
        let limit = i64::from(MAX_FRAME_DIM);
        let Some(b) = Box2::clamped(&rect, limit, limit) else { return Ok(()) };
        if self.boxes.iter().any(|o| o.contains(&b)) {
            return Ok(());
        }
        let kept = self.boxes.iter().filter(|o| !b.contains(o)).count();
        if kept >= N {
            return Err(Error::CapacityExceeded { needed: kept + 1, capacity: N });
        }
        self.boxes.retain(|o| !b.contains(o));
        // `kept < N` slots are taken: there is room.
        let _ = self.boxes.push(b);
        Ok(())
    }

    /// Marks damaged what `old` covered and what `new` covers: the bounding
    /// boxes of a drawable that moved or changed (text, e-g shapes, a
    /// [`Styled`](crate::shape::Styled) shape, whose box is
    /// [`Styled::bounds`](crate::shape::Styled::bounds)). Errors as
    /// [`Damage::add`]; on an error neither box is added.
    pub fn add_moved(&mut self, old: &impl Dimensions, new: &impl Dimensions) -> Result<(), Error> {
        let before = self.boxes.clone();
        let r = self.add(old.bounding_box()).and_then(|()| self.add(new.bounding_box()));
        if r.is_err() {
            self.boxes = before;
        }
        r
    }

    /// Pixels of a `width × height` frame the damage covers (the union of
    /// the rectangles clipped to the frame, each pixel once): what
    /// [`Renderer::render_damaged`] sends.
    pub fn area(&self, width: u32, height: u32) -> u64 {
        let clipped = self.clipped(i64::from(width), i64::from(height));
        let mut n = 0u64;
        parts(&clipped, 0, height.min(MAX_FRAME_DIM) as i32, |b| {
            n += ((b.x1 - b.x0) as u64) * ((b.y1 - b.y0) as u64);
        });
        n
    }

    /// The rectangles clipped to a `w × h` frame.
    fn clipped(&self, w: i64, h: i64) -> heapless::Vec<Box2, N> {
        self.boxes.iter().filter_map(|b| Box2::clamped(&b.rectangle(), w, h)).collect()
    }
}

/// Calls `f` with disjoint boxes covering the union of `boxes` within rows
/// `y_lo..y_hi`, strip by strip from the top, left to right (see the
/// module's "Disjoint parts").
fn parts(boxes: &[Box2], y_lo: i32, y_hi: i32, mut f: impl FnMut(Box2)) {
    let mut y = y_lo;
    while y < y_hi {
        // The strip ends where any rectangle starts or ends below `y`.
        let mut next = y_hi;
        for b in boxes {
            for e in [b.y0, b.y1] {
                if e > y && e < next {
                    next = e;
                }
            }
        }
        let crosses = |b: &&Box2| b.y0 <= y && b.y1 > y;
        // Column intervals of the rectangles crossing the strip, merged.
        let mut x = i32::MIN;
        while let Some(start) = boxes.iter().filter(crosses).filter(|b| b.x1 > x).map(|b| b.x0.max(x)).min() {
            // Extend over every rectangle that starts within the interval.
            let mut end = start;
            while let Some(e) =
                boxes.iter().filter(crosses).filter(|b| b.x0 <= end && b.x1 > end).map(|b| b.x1).max()
            {
                end = e;
            }
            f(Box2 { x0: start, y0: y, x1: end, y1: next });
            x = end;
        }
        y = next;
    }
}

impl<C: Interpolate> Renderer<C> {
    /// Renders and sends only `damage`: the damaged rows, in bands of at
    /// most `H` (packed from the first damaged row where the pass accepts
    /// any rows, [`Pass::ANY_ROWS`], else within the frame's bands of `H`
    /// rows), each cleared and drawn with its clip narrowed to the damaged
    /// columns, then the damaged parts sent with one `fill_contiguous` each
    /// (disjoint: no pixel twice; [`Damage::area`] pixels in all). Rows the
    /// damage misses are neither drawn nor sent. Inside the damage the display then shows
    /// what [`Renderer::render`] of the same pass shows; outside, it keeps
    /// what it had. Rectangles are clipped to the frame; an empty damage
    /// sends nothing and returns `Ok`.
    ///
    /// Errors as [`Renderer::render`], all before anything is sent
    /// (a damage list too long for `N` is refused when it is built,
    /// [`Damage::add`]). After the pass's first error, the later damaged
    /// parts are sent as background and the error is returned.
    ///
    /// The double-banded link ([`render_linked`](Renderer::render_linked))
    /// lends whole bands to its sink, so damaged frames go through this
    /// blocking loop. A [`DirtyBands`](super::DirtyBands) sink does not see
    /// them: before its next full frame, call
    /// [`force_full_frame`](super::DirtyBands::force_full_frame) (its
    /// records describe the display before the damaged frames).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    /// use microraster::render::{Damage, from_fn};
    /// use microraster::shape::{Rect, Shape, ShapeStyle};
    /// use microraster::{Band, Renderer};
    /// let at = |x: f32| Rect::new(x, 1.0, 2.0, 2.0)?.styled(ShapeStyle::fill(BinaryColor::On));
    /// let (old, new) = (at(1.0)?, at(4.0)?);
    /// let mut band = Band::<BinaryColor, 8, 2>::new(BinaryColor::Off);
    /// let r = Renderer::new(4, BinaryColor::Off);
    /// let mut display = MockDisplay::new();
    /// r.render(from_fn(|v| { old.draw_on(v); Ok(()) }), &mut band, &mut display)?;
    /// display.assert_pattern(&["........", ".##.....", ".##.....", "........"]);
    /// // The square moved: damage its old and new boxes, render only those.
    /// let mut damage = Damage::<4>::new();
    /// damage.add_moved(&old, &new)?;
    /// display.set_allow_overdraw(true);
    /// let moved = from_fn(|v| { new.draw_on(v); Ok(()) });
    /// r.render_damaged(moved, &damage, &mut band, &mut display)?;
    /// display.assert_pattern(&["........", "....##..", "....##..", "........"]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn render_damaged<P, D, const W: usize, const H: usize, const N: usize>(
        &self,
        mut pass: P,
        damage: &Damage<N>,
        band: &mut Band<C, W, H>,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        P: Pass<C, W, H>,
        D: DrawTarget<Color = C>,
    {
        let frame = self.frame_bands::<W, H>()?;
        self.fits::<W>(target.bounding_box())?;
        pass.check(self)?;
        let height = frame.size().height as i32;
        let boxes = damage.clipped(W as i64, i64::from(frame.size().height));
        let mut failed: Option<Error> = None;
        let mut y = 0i32;
        // Chunks of at most `H` rows from the first damaged row not yet
        // drawn: within its band of `H` rows (at a multiple of `H`), or
        // anywhere for a pass that accepts any rows (`Pass::ANY_ROWS`), so
        // that the damaged rows fill as few bands as they can.
        while let Some(top) = boxes.iter().filter(|b| b.y1 > y).map(|b| b.y0.max(y)).min() {
            let band_end = if P::ANY_ROWS { top + H as i32 } else { top - top % H as i32 + H as i32 };
            let limit = band_end.min(height);
            let touching = |b: &&Box2| b.y0 < limit && b.y1 > top;
            // `top` is some rectangle's row: at least that one touches.
            let Some(cover) = boxes.iter().filter(touching).copied().reduce(|a, b| Box2 {
                x0: a.x0.min(b.x0),
                y0: a.y0.min(b.y0),
                x1: a.x1.max(b.x1),
                y1: a.y1.max(b.y1),
            }) else {
                break;
            };
            let (y0, y1) = (top, cover.y1.min(limit));
            let rows = &mut band.rows_mut()[..(y1 - y0) as usize];
            if P::CLEARS || failed.is_some() {
                for row in rows.iter_mut() {
                    fill_run(&mut row[cover.x0 as usize..cover.x1 as usize], self.background());
                }
            }
            if failed.is_none() {
                let mut view = BandView::from_rows(rows, y0, None).with_columns(cover.x0, cover.x1);
                if let Err(e) = pass.draw(&mut view, self) {
                    failed = Some(e);
                }
            }
            let mut sent = Ok(());
            parts(&boxes, y0, y1, |p| {
                if sent.is_err() {
                    return;
                }
                let area = Rectangle::new(
                    frame.offset() + Point::new(p.x0, p.y0),
                    Size::new((p.x1 - p.x0) as u32, (p.y1 - p.y0) as u32),
                );
                let px = rows[(p.y0 - y0) as usize..(p.y1 - y0) as usize]
                    .iter()
                    .flat_map(|row| row[p.x0 as usize..p.x1 as usize].iter().copied());
                sent = target.fill_contiguous(&area, px);
            });
            sent.map_err(RenderError::Target)?;
            y = y1;
        }
        failed.map_or(Ok(()), |e| Err(RenderError::Input(e)))
    }
}
