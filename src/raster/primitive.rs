//! Scene primitives: triangles and lines with their shading.
//!
//! Primitives hold snapped vertices (so every coordinate is already validated)
//! and the range of pixel rows they can touch, which lets the band renderer
//! skip a primitive that misses a band with two comparisons.
//!
//! Both kinds keep those rows as their first field (`repr(C)`), so a
//! [`Primitive`]'s rows lie at one offset whichever kind it holds (tested):
//! the band loop reads them with no branch on the kind. The slice pass
//! makes that test for every primitive in every band.

use crate::attr::{COLOR_FRAC, COLOR_HALF, Plane, PlaneFrame, channel_clamped, channel_in_range};
use crate::blit::Blitter;
use crate::edge::{Cull, TriangleSpans};
use crate::line::{line_pixels, line_rows};
use crate::{Error, Interpolate, SubPoint};

/// How a triangle is coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shading<C> {
    /// One colour for the whole triangle.
    Flat(C),
    /// A colour per vertex, interpolated linearly in screen space (Gouraud).
    Gouraud([C; 3]),
}

/// A triangle with snapped vertices.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::{SubPoint, Triangle};
/// let t = Triangle::<_, 4>::from_f32([(0.0, 0.0), (10.5, 2.0), (3.0, 8.25)], Rgb565::new(31, 0, 0))?;
/// assert_eq!(t.rows(), (0, 7)); // centres y + 0.5 for y in 0..=7 lie within 0..=8.25
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(C)]
pub struct Triangle<C, const S: u32> {
    // Computed once here: the band renderer asks for it in every band.
    rows: (i32, i32),
    vertices: [SubPoint<S>; 3],
    shading: Shading<C>,
}

impl<C: Interpolate, const S: u32> Triangle<C, S> {
    /// A triangle with the given shading.
    pub const fn new(vertices: [SubPoint<S>; 3], shading: Shading<C>) -> Self {
        let [a, b, c] = [vertices[0].y(), vertices[1].y(), vertices[2].y()];
        let lo = if a < b { a } else { b };
        let hi = if a > b { a } else { b };
        let rows = center_rows::<S>(if lo < c { lo } else { c }, if hi > c { hi } else { c });
        Triangle { vertices, shading, rows }
    }

    /// A flat-coloured triangle.
    pub const fn flat(vertices: [SubPoint<S>; 3], color: C) -> Self {
        Self::new(vertices, Shading::Flat(color))
    }

    /// A Gouraud-shaded triangle with one colour per vertex.
    pub const fn gouraud(vertices: [SubPoint<S>; 3], colors: [C; 3]) -> Self {
        Self::new(vertices, Shading::Gouraud(colors))
    }

    /// A flat triangle from `f32` pixel coordinates, snapped to nearest.
    pub fn from_f32(v: [(f32, f32); 3], color: C) -> Result<Self, Error> {
        let mut out = [SubPoint::default(); 3];
        for (o, (x, y)) in out.iter_mut().zip(v) {
            *o = SubPoint::from_f32(x, y)?;
        }
        Ok(Self::flat(out, color))
    }

    /// The snapped vertices.
    pub const fn vertices(&self) -> [SubPoint<S>; 3] {
        self.vertices
    }

    /// The shading.
    pub const fn shading(&self) -> Shading<C> {
        self.shading
    }

    /// Inclusive range of pixel rows whose centres lie within the vertical
    /// extent of the triangle (empty if `.0 > .1`).
    pub const fn rows(&self) -> (i32, i32) {
        self.rows
    }

    /// Rasterizes into `blitter` (clipped to its clip rectangle).
    pub fn draw<B: Blitter<C>>(&self, blitter: &mut B, cull: Cull) {
        let spans = TriangleSpans::new(self.vertices, blitter.clip(), cull);
        match self.shading {
            // The span fill inlined into the row loop (`TriangleSpans::fold`).
            Shading::Flat(c) => spans.fold(
                (),
                #[inline(always)]
                |(), s| blitter.fill_span(s, c),
            ),
            Shading::Gouraud(cs) => self.draw_gouraud(spans, cs, blitter),
        }
    }

    /// The colour planes of a Gouraud triangle with vertex channels `ch`
    /// (`None` for a channel the colour lacks, or zero area).
    fn planes(&self, ch: [[u8; 3]; 3]) -> [Option<Plane>; 3] {
        let frame =
            PlaneFrame { v: self.vertices.map(|p| (2 * p.x() as i64, 2 * p.y() as i64)), shift: S + 1 };
        let (rx, ry) = reference_pixel(self.vertices[0]);
        let max = C::CHANNEL_MAX;
        let mut planes = [None; 3];
        for (k, plane) in planes.iter_mut().enumerate() {
            if max[k] > 0 {
                let values = [0, 1, 2].map(|v| (ch[v][k] as i64) << COLOR_FRAC);
                *plane = Plane::new(&frame, values, rx, ry);
            }
        }
        planes
    }

    fn draw_gouraud<B: Blitter<C>>(&self, spans: TriangleSpans, cs: [C; 3], blitter: &mut B) {
        let ch = cs.map(|c| c.to_channels());
        let planes = self.planes(ch);
        let max = C::CHANNEL_MAX;
        // `to_channels` keeps every channel in range for the crate's colours;
        // a hand-made `Interpolate` may not, and keeps the clamped loop.
        if ch.iter().all(|c| c.iter().zip(max).all(|(&v, m)| v <= m)) {
            gouraud_spans::<C, B, false>(spans, &planes, blitter);
        } else {
            gouraud_spans::<C, B, true>(spans, &planes, blitter);
        }
    }
}

/// The Gouraud span loop of [`Triangle::draw`]. `CLAMP`: each channel
/// clamped to `0..=max` ([`channel_clamped`]); without it (every vertex
/// channel in range) a bit-field extract ([`channel_in_range`]): a covered
/// centre's exact value is a convex combination of the vertices' and the
/// sample lies within `2^13` units of it (`attr`), so both give the same
/// pixels. The accumulators then fit `i32` as they are (below `2^28` in
/// magnitude with the half step), so each span starts from the plane's low
/// 32 bits ([`Plane::at_low32`]); and a step beyond `i32` only occurs where
/// a span is one pixel long (two covered centres differ by less than
/// `2^28`), where it is unused: truncated or clamped, the same pixels.
#[inline(always)]
fn gouraud_spans<C: Interpolate, B: Blitter<C>, const CLAMP: bool>(
    spans: TriangleSpans,
    planes: &[Option<Plane>; 3],
    blitter: &mut B,
) {
    let max = C::CHANNEL_MAX;
    for span in spans {
        let mut acc = [0i32; 3];
        let mut step = [0i32; 3];
        for k in 0..3 {
            if let Some(p) = &planes[k] {
                if CLAMP {
                    // Inside the triangle the value is a channel (< 2^28); a step that
                    // does not fit i32 only occurs where spans are one pixel long.
                    // The rounding's half step is added here once (`channel_clamped`).
                    let biased = p.at(span.x, span.y).saturating_add(COLOR_HALF as i64);
                    acc[k] = biased.clamp(i32::MIN as i64, i32::MAX as i64) as i32;
                    step[k] = p.step_x().clamp(i32::MIN as i64, i32::MAX as i64) as i32;
                } else {
                    acc[k] = (p.at_low32(span.x, span.y) as i32).wrapping_add(COLOR_HALF);
                    step[k] = p.step_x() as i32;
                }
            }
        }
        let colors = (0..span.len).map(|_| {
            let ch = |k: usize| {
                if CLAMP { channel_clamped(acc[k], max[k]) } else { channel_in_range(acc[k], max[k]) }
            };
            let c = [ch(0), ch(1), ch(2)];
            for k in 0..3 {
                acc[k] = acc[k].wrapping_add(step[k]); // the step after the last pixel is unused
            }
            C::from_channels(c)
        });
        blitter.shade_span(span, colors);
    }
}

/// A line segment, drawn with the midpoint algorithm (see [`crate::line`]).
///
/// The start pixel is drawn and the end pixel is not (lines are half-open), so
/// a polyline lights each shared vertex once.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor};
/// use microraster::{Band, Line, Primitive, Renderer, SubPoint};
/// let p = |x, y| SubPoint::<4>::pixel_center(x, y).unwrap();
/// let scene = [Primitive::from(Line::new(p(0, 1), p(4, 1), BinaryColor::On))];
/// let mut display = MockDisplay::new();
/// Renderer::new(3, BinaryColor::Off).render(&scene, &mut Band::<_, 4, 2>::new(BinaryColor::Off), &mut display)?;
/// display.assert_pattern(&["....", "####", "...."]);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(C)]
pub struct Line<C, const S: u32> {
    // Computed once here: the band renderer asks for it in every band.
    rows: (i32, i32),
    start: SubPoint<S>,
    end: SubPoint<S>,
    color: C,
}

impl<C: Interpolate, const S: u32> Line<C, S> {
    /// A line from `start` to `end`.
    pub fn new(start: SubPoint<S>, end: SubPoint<S>, color: C) -> Self {
        let rows = line_rows(start, end).unwrap_or((1, 0));
        Line { start, end, color, rows }
    }

    /// Start point (its pixel is drawn).
    pub const fn start(&self) -> SubPoint<S> {
        self.start
    }

    /// End point (its pixel is not drawn).
    pub const fn end(&self) -> SubPoint<S> {
        self.end
    }

    /// Colour.
    pub const fn color(&self) -> C {
        self.color
    }

    /// Inclusive range of rows the line can touch (empty if `.0 > .1`).
    pub const fn rows(&self) -> (i32, i32) {
        self.rows
    }

    /// Rasterizes into `blitter` (clipped to its clip rectangle).
    pub fn draw<B: Blitter<C>>(&self, blitter: &mut B) {
        for (x, y) in line_pixels(self.start, self.end, blitter.clip()) {
            blitter.set_pixel(x, y, self.color);
        }
    }
}

/// Anything a scene can hold: what [`Renderer::render`](crate::Renderer::render)
/// draws, in order. (`embedded_graphics::prelude` has a trait of the same
/// name: with both preludes glob-imported, write `microraster::Primitive`.)
///
/// ```
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{Line, Primitive, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let scene = [
///     Primitive::from(Triangle::flat([p(0, 0), p(8, 0), p(0, 8)], BinaryColor::On)),
///     Primitive::from(Line::new(p(0, 9), p(8, 9), BinaryColor::On)),
/// ];
/// // Each knows its rows, for the band loop.
/// assert_eq!(scene[0].rows(), (0, 7));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Primitive<C, const S: u32> {
    /// A filled triangle.
    Triangle(Triangle<C, S>),
    /// A line segment.
    Line(Line<C, S>),
}

impl<C: Interpolate, const S: u32> Primitive<C, S> {
    /// Inclusive range of rows the primitive can touch (empty if `.0 > .1`).
    pub fn rows(&self) -> (i32, i32) {
        match self {
            Primitive::Triangle(t) => t.rows(),
            Primitive::Line(l) => l.rows(),
        }
    }

    /// Rasterizes into `blitter`; `cull` applies to triangles only.
    pub fn draw<B: Blitter<C>>(&self, blitter: &mut B, cull: Cull) {
        match self {
            Primitive::Triangle(t) => t.draw(blitter, cull),
            Primitive::Line(l) => l.draw(blitter),
        }
    }
}

impl<C, const S: u32> From<Triangle<C, S>> for Primitive<C, S> {
    fn from(t: Triangle<C, S>) -> Self {
        Primitive::Triangle(t)
    }
}

impl<C, const S: u32> From<Line<C, S>> for Primitive<C, S> {
    fn from(l: Line<C, S>) -> Self {
        Primitive::Line(l)
    }
}

/// The pixel holding `v`, clamped into the frame: a reference for attribute
/// planes that does not depend on the band (so every band height rounds the
/// same way) and lies within 2^12 pixels of every sample (see `attr`).
pub(crate) fn reference_pixel<const S: u32>(v: SubPoint<S>) -> (i32, i32) {
    let max = crate::MAX_FRAME_DIM as i32 - 1;
    ((v.x() >> S).clamp(0, max), (v.y() >> S).clamp(0, max))
}

/// Rows whose centre `y + 0.5` lies in `[lo, hi]` (subpixel units), for
/// [`SubPoint`] coordinates (`|lo|, |hi| ≤ 2^28`): in 32 bits, since
/// `|2y| ≤ 2^29` and the rounding terms are below `2^(S + 2) ≤ 2^10`.
pub(crate) const fn center_rows<const S: u32>(lo: i32, hi: i32) -> (i32, i32) {
    debug_assert!(lo.unsigned_abs() <= 1 << 28 && hi.unsigned_abs() <= 1 << 28);
    let (lo, hi) = (2 * lo, 2 * hi);
    let (one, half) = (1i32 << (S + 1), 1i32 << S);
    ((lo - half + one - 1) >> (S + 1), (hi - half) >> (S + 1))
}

#[cfg(test)]
mod tests {
    use super::{Interpolate, Line, Primitive, Shading, SubPoint, Triangle};
    use crate::Band;
    use crate::blit::Blitter;
    use crate::edge::{Cull, TriangleSpans};
    use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, Rgb888};

    /// The offsets of a triangle's and a line's rows within their
    /// [`Primitive`] (module docs: equal, so the band loop's row test does not
    /// branch on the kind). This guards the layout the speed depends on.
    fn row_offsets<C: Interpolate>(color: C) -> [usize; 2] {
        let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
        let prims = [
            Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], color)),
            Primitive::from(Line::new(p(0, 0), p(4, 4), color)),
        ];
        prims.each_ref().map(|prim| {
            let rows = match prim {
                Primitive::Triangle(t) => &t.rows,
                Primitive::Line(l) => &l.rows,
            };
            rows as *const (i32, i32) as usize - prim as *const Primitive<C, 4> as usize
        })
    }

    /// The Gouraud loop without the per-pixel clamp draws exactly the
    /// clamped loop's pixels, for random triangles of every size and shape
    /// (slivers, spans of one pixel, vertices beyond the band) and colours
    /// with 5-, 6- and 8-bit channels.
    #[test]
    fn unclamped_gouraud_is_the_clamped_loop() {
        fn check<C: Interpolate + PartialEq + core::fmt::Debug>(
            rng: &mut crate::test_rng::Rng,
            color: impl Fn(u64) -> C,
        ) -> usize {
            let mut lit = 0;
            for i in 0..3_000 {
                let reach = [40, 600, 6_000, 60_000][i % 4];
                let p = |rng: &mut crate::test_rng::Rng| {
                    SubPoint::<4>::new(rng.in_range(reach) as i32 + 500, rng.in_range(reach) as i32 + 150)
                        .unwrap()
                };
                let v = [p(rng), p(rng), p(rng)];
                let tri = Triangle::gouraud(v, [color(rng.next()), color(rng.next()), color(rng.next())]);
                let Shading::Gouraud(cs) = tri.shading else { unreachable!() };
                let bg = color(0);
                let (mut a, mut b) = (Band::<C, 64, 20>::new(bg), Band::<C, 64, 20>::new(bg));
                for (band, clamp) in [(&mut a, true), (&mut b, false)] {
                    let mut view = band.view(2, 20, bg);
                    let spans = TriangleSpans::new(v, view.clip(), Cull::None);
                    let planes = tri.planes(cs.map(|c| c.to_channels()));
                    if clamp {
                        super::gouraud_spans::<C, _, true>(spans, &planes, &mut view);
                    } else {
                        super::gouraud_spans::<C, _, false>(spans, &planes, &mut view);
                    }
                }
                assert!(a.rows() == b.rows(), "{v:?} {cs:?}");
                lit += a.rows().iter().flatten().filter(|&&c| c != bg).count();
            }
            lit
        }
        let mut rng = crate::test_rng::Rng(0x6A0_2A0D);
        let rgb565 = |r: u64| Rgb565::new(r as u8 & 31, (r >> 8) as u8 & 63, (r >> 16) as u8 & 31);
        let rgb888 = |r: u64| Rgb888::new(r as u8, (r >> 8) as u8, (r >> 16) as u8);
        assert!(check(&mut rng, rgb565) > 100_000);
        assert!(check(&mut rng, rgb888) > 100_000);
    }

    #[test]
    fn rows_lie_at_one_offset_for_both_kinds() {
        for offsets in [
            row_offsets(Rgb565::new(31, 0, 0)),
            row_offsets(Rgb888::new(255, 0, 0)),
            row_offsets(BinaryColor::On),
        ] {
            assert_eq!(offsets[0], offsets[1]);
        }
    }
}
