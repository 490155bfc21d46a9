//! Anti-aliased lines: Xiaolin Wu's algorithm in exact integer arithmetic on
//! subpixel end points, blended into a [`BlendTarget`] (a band, or your own
//! readable framebuffer).
//!
//! # The coverage rule
//!
//! Coordinates are pixels with pixel `(x, y)` covering `[x, x+1) × [y, y+1)`
//! and its centre at `(x + ½, y + ½)`, as everywhere in microraster. The
//! **major axis** is x when `|dx| ≥ |dy|`, else y (the same choice as
//! [`crate::line`]); the line's direction does not matter (`a → b` and `b → a`
//! give the same pixels).
//!
//! For each major-axis column `M` (a row for steep lines) the segment
//! overlaps, with overlap length `g ∈ (0, 1]` pixels (1 for interior columns;
//! the two end columns get the fraction of the column the segment covers —
//! Wu's "gap" weighting of the end points), take the minor coordinate `v` of
//! the infinite line through `a` and `b` at the column centre `M + ½` (for an
//! end column this may lie just beyond the end point, as in Wu's algorithm),
//! and split it between the two pixel centres around it: with `t = v − ½`,
//! `j = ⌊t⌋` and `f = t − j`, the exact Wu intensities of the line alpha `A`
//! (0..=255) are
//!
//! * `I(M, j)     = A · g · (1 − f)`
//! * `I(M, j + 1) = A · g · f`
//!
//! The alphas drawn are `G = round(A·g)` (so `G = A` exactly in interior
//! columns), `hi = round(G·f)` for pixel `j + 1` and `lo = G − hi` for pixel
//! `j`, rounding half up. Hence:
//!
//! * **The two alphas of a column sum to `G`**: exactly the line alpha in
//!   every interior column, and within ½ of `A·g` in the two end columns.
//! * **Error bound**: `|hi − I(M, j+1)| ≤ ½ + ½f` and `|lo − I(M, j)| ≤ ½ +
//!   ½(1 − f)`, both below 1 (one 8-bit alpha step); in interior columns
//!   both are at most ½ (correctly rounded).
//! * Each pixel gets at most one alpha per line (different columns never
//!   share a pixel), blended once with [`Mix`] (or the mode of
//!   [`LineAa::draw_with`]) and the colour of the line. Pixels whose alpha is
//!   0 are skipped.
//! * A zero-length segment draws nothing; a segment shorter than a pixel
//!   draws one or two columns with small `g`, so intensity changes
//!   continuously as end points move by a subpixel.
//!
//! Unlike [`Line`](crate::Line) the end points are not half-open: a polyline
//! blends the two partial columns at a shared vertex once from each segment
//! (their `g` add up to about 1 for collinear segments).
//!
//! # Arithmetic and clipping
//!
//! Integer only, in `i64`. The minor coordinate at a column centre is a
//! rational `n / den` whose remainder steps by a constant per column (as in
//! the midpoint line), and `hi` is kept as an exact quotient by a second
//! remainder, so each column costs a few additions and no division; the two
//! end columns are computed directly. The first visible column and the
//! columns whose pixels can meet the clip rectangle's minor range are found
//! by exact division before stepping, so a long line costs only its visible
//! columns, drawing into any band gives exactly the pixels that drawing the
//! whole frame gives there (no state crosses bands), and every end point in
//! [`SubPoint`]'s ±2^28 range works without overflow (the set-up uses checked
//! arithmetic: a flaw would draw nothing, never panic).
//!
//! In the band loop, draw anti-aliased lines from
//! [`from_fn`](crate::render::from_fn)'s closure, after the
//! geometry they lie on ([`Primitive`](crate::Primitive) holds no blended
//! primitives). [`line_aa_pixels`] gives the raw `(x, y, alpha)` pixels for
//! any other sink.
//!
//! ```
//! use embedded_graphics::pixelcolor::Gray8;
//! use microraster::line_aa::{line_aa_pixels, LineAa};
//! use microraster::{Band, ClipRect, SubPoint};
//! let p = |x: f32, y: f32| SubPoint::<4>::from_f32(x, y).unwrap();
//! // From (0, 0.5) to (4, 1.5): at column centres x = 0.5 .. 3.5 the line is at
//! // y = 0.625, 0.875, 1.125, 1.375; each splits between the rows around it.
//! let px: Vec<_> = line_aa_pixels(p(0.0, 0.5), p(4.0, 1.5), ClipRect::new(0, 0, 8, 8), 255).collect();
//! assert_eq!(
//!     px,
//!     [(0, 0, 223), (0, 1, 32), (1, 0, 159), (1, 1, 96), (2, 0, 96), (2, 1, 159), (3, 0, 32), (3, 1, 223)]
//! );
//! // The same line drawn white on black.
//! let mut band = Band::<Gray8, 8, 2>::new(Gray8::new(0));
//! let mut view = band.view(0, 2, Gray8::new(0));
//! LineAa::new(p(0.0, 0.5), p(4.0, 1.5), Gray8::new(255)).draw(&mut view);
//! assert_eq!(band.rows()[1][1], Gray8::new(96));
//! ```

mod pixels;
pub use pixels::{LineAaPixels, line_aa_pixels};

use crate::SubPoint;
use crate::blend::{Blend, BlendTarget, Mix, OPAQUE};
use crate::color::Interpolate;

/// An anti-aliased line segment (see the [module docs](self)).
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::line_aa::LineAa;
/// use microraster::{Band, SubPoint};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let mut band = Band::<Rgb565, 16, 8>::new(Rgb565::new(0, 0, 0));
/// let mut view = band.view(0, 8, Rgb565::new(0, 0, 0));
/// LineAa::new(p(1, 1), p(15, 6), Rgb565::new(31, 63, 31)).with_alpha(200).draw(&mut view);
/// assert!(band.rows().iter().flatten().any(|c| *c != Rgb565::new(0, 0, 0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LineAa<C, const S: u32> {
    start: SubPoint<S>,
    end: SubPoint<S>,
    color: C,
    alpha: u8,
}

impl<C: Interpolate, const S: u32> LineAa<C, S> {
    /// An opaque anti-aliased line from `start` to `end`.
    pub const fn new(start: SubPoint<S>, end: SubPoint<S>, color: C) -> Self {
        LineAa { start, end, color, alpha: OPAQUE }
    }

    /// The same line with line alpha `alpha` (255 = opaque): every pixel's
    /// coverage is scaled by it.
    pub const fn with_alpha(self, alpha: u8) -> Self {
        LineAa { alpha, ..self }
    }

    /// Start point.
    pub const fn start(&self) -> SubPoint<S> {
        self.start
    }

    /// End point.
    pub const fn end(&self) -> SubPoint<S> {
        self.end
    }

    /// Colour.
    pub const fn color(&self) -> C {
        self.color
    }

    /// Line alpha.
    pub const fn alpha(&self) -> u8 {
        self.alpha
    }

    /// Blends the line into `target` with [`Mix`] (source-over), each pixel
    /// with its coverage alpha.
    pub fn draw<T: BlendTarget<C>>(&self, target: &mut T) {
        self.draw_with(target, Mix);
    }

    /// Blends the line into `target` with `mode`, each pixel with its
    /// coverage alpha (e.g. [`Additive`](crate::blend::Additive) for glowing
    /// lines).
    pub fn draw_with<T: BlendTarget<C>, B: Blend>(&self, target: &mut T, mode: B) {
        for (x, y, a) in line_aa_pixels(self.start, self.end, target.clip(), self.alpha) {
            target.blend_pixel(mode, x, y, self.color, a);
        }
    }
}
