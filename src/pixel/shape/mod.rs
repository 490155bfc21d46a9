//! Exact, seamless 2D shapes: rectangles, rounded rectangles, circles,
//! ellipses, arcs, sectors, polygons and thick polylines, filled and
//! stroked, aliased or anti-aliased, with solid or gradient paint.
//!
//! # Model
//! Every shape becomes closed contours of straight edges ([`EdgeList`]),
//! snapped to the 1/16 px grid of [`SubPoint<4>`](crate::SubPoint); curves
//! are flattened first ([`mod@flatten`]: at most [`TOLERANCE`] px from the true
//! curve, chords inside it). The contours are then covered
//!
//! * **aliased** ([`Aliased`]): a pixel is in when the winding number around
//!   its centre nudged by `(ε, ε²)` passes the [`FillRule`] — the top-left
//!   rule of the triangle core, generalised (proof in `src/pixel/shape/scan.rs`). Two shapes (or a
//!   shape and a triangle) sharing an edge never both cover, and never both
//!   miss, a pixel on it;
//! * **anti-aliased** ([`AntiAliased`]): each pixel gets the exact area of
//!   the snapped contours inside it as its alpha, rounded, to within
//!   `1/256` of a level anywhere in the coordinate range (`src/pixel/shape/area.rs`).
//!   Two shapes sharing an edge have coverages that sum to one along it, but
//!   drawn one after the other the second blends over the first's partial
//!   pixels: two white halves of a pixel on black leave it at 192, not 255 (a
//!   dark seam). Draw them as one [`Group`] to sum the coverages before the
//!   one blend (no seam). Where a
//!   shape overlaps itself inside one pixel (self-intersecting polygons, the
//!   joins of thick polylines), that pixel's alpha is the integral of the
//!   clamped winding number, which can exceed the area by the overlap.
//!
//! Strokes are contours too (the outline offset by half the width, or one
//! contour per segment, join and cap, united by the nonzero rule), so a
//! stroke is one fill: translucent strokes blend each pixel once.
//!
//! # Drawing
//! [`Styled`] pairs a shape with a [`ShapeStyle`] and is checked once when
//! built (NaN, negative sizes, capacity: a typed [`Error`](crate::Error)).
//! It implements `embedded-graphics`' [`Drawable`](embedded_graphics::Drawable)
//! for any `DrawTarget`, and [`Styled::draw_on`] draws on any [`Canvas`] — a
//! band ([`BandView`](crate::band::BandView)) or your own readable
//! framebuffer — with exact blending of partial pixels.
//!
//! ```
//! use embedded_graphics::mock_display::MockDisplay;
//! use embedded_graphics::{Drawable, pixelcolor::BinaryColor};
//! use microraster::shape::{Circle, Shape, ShapeStyle};
//! let mut display = MockDisplay::<BinaryColor>::new();
//! Circle::new((3.0, 3.0), 2.5)?.styled(ShapeStyle::fill(BinaryColor::On))?.draw(&mut display).unwrap();
//! // Centres within 2.5 px of (3, 3): (1.5, 1.5) is 2.12 away, (0.5, 3.5) 2.55.
//! display.assert_pattern(&["     ", " ####", " ####", " ####", " ####"]);
//! # Ok::<(), microraster::Error>(())
//! ```
//!
//! # Memory
//! Drawing keeps the edges on the stack: [`MAX_EDGES`] edges of 20 bytes,
//! plus one row's crossings (8 bytes each, aliased) or edge pieces (32 bytes
//! each, anti-aliased). More edges than that is [`Error::BufferTooSmall`](crate::Error::BufferTooSmall)
//! when the [`Styled`] is built.

mod angle;
mod area;
mod canvas;
pub mod edges;
pub mod flatten;
mod group;
mod paint;
mod scan;
mod shapes;
mod stroke;
mod style;

pub use canvas::{Canvas, TargetCanvas};
pub use edges::EdgeList;
pub use flatten::{MAX_SEGMENTS, TOLERANCE};
pub use group::Group;
pub use paint::{LinearGradient, Paint, RadialGradient};
pub use shapes::{Arc, Circle, Ellipse, Polygon, Polyline, Rect, RoundedRect, Sector, Shape};
pub use style::{Cap, Join, PREPARED_EDGES, Prepared, ShapeStyle, Styled};

use crate::ClipRect;
use crate::edge::Span;

/// The most edges one styled shape may have (horizontal edges are dropped
/// and do not count); more is [`Error::BufferTooSmall`](crate::Error::BufferTooSmall)
/// when the [`Styled`] is built.
///
/// ```
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{Error, shape::{MAX_EDGES, Polygon, Shape, ShapeStyle}};
/// // A zigzag of n points, every edge slanted (the closing one too for even
/// // n): n edges.
/// let zigzag = |n: usize| (0..n).map(|i| (i as f32, (i % 2) as f32 * 4.0)).collect::<Vec<_>>();
/// let style = ShapeStyle::fill(BinaryColor::On);
/// assert!(Polygon::new(&zigzag(MAX_EDGES))?.styled(style).is_ok());
/// assert_eq!(Polygon::new(&zigzag(MAX_EDGES + 2))?.styled(style).err(), Some(Error::BufferTooSmall));
/// # Ok::<(), Error>(())
/// ```
pub const MAX_EDGES: usize = 256;

/// Which winding numbers are inside.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, prelude::*};
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::shape::{FillRule, Polygon, Shape, ShapeStyle};
/// // A pentagram: its centre has winding number 2.
/// let star = [(5.0, 0.0), (8.0, 9.0), (0.0, 3.5), (10.0, 3.5), (2.0, 9.0)];
/// let centre = Point::new(5, 5);
/// for (rule, filled) in [(FillRule::NonZero, true), (FillRule::EvenOdd, false)] {
///     let style = ShapeStyle::fill(BinaryColor::On).with_fill_rule(rule);
///     let mut display = MockDisplay::new();
///     Polygon::new(&star)?.styled(style)?.draw(&mut display).unwrap();
///     assert_eq!(display.get_pixel(centre) == Some(BinaryColor::On), filled);
/// }
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FillRule {
    /// Nonzero winding (overlapping contours of one direction unite).
    #[default]
    NonZero,
    /// Odd winding (overlaps cut holes).
    EvenOdd,
}

impl FillRule {
    /// True if winding number `w` is inside.
    ///
    /// ```
    /// use microraster::shape::FillRule;
    /// assert!(FillRule::NonZero.inside(2) && !FillRule::EvenOdd.inside(2));
    /// ```
    pub const fn inside(self, w: i32) -> bool {
        match self {
            FillRule::NonZero => w != 0,
            FillRule::EvenOdd => w & 1 != 0,
        }
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Aliased {}
    impl Sealed for super::AntiAliased {}
}

/// How pixel coverage is computed: [`Aliased`] or [`AntiAliased`], chosen by
/// the type of [`ShapeStyle::antialias`]. Sealed: the two are the only
/// kinds; code generic over either names the bound.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{Circle, Coverage, Shape, ShapeStyle, Styled};
/// // One disc builder for both kinds of coverage.
/// fn disc<A: Coverage>(style: ShapeStyle<Gray8, A>) -> Result<Styled<Circle, Gray8, A>, microraster::Error> {
///     Circle::new((8.0, 8.0), 6.0)?.styled(style)
/// }
/// let sharp = disc(ShapeStyle::fill(Gray8::WHITE))?;
/// let smooth = disc(ShapeStyle::fill(Gray8::WHITE).antialiased())?;
/// assert_eq!(sharp.rows(), smooth.rows());
/// # Ok::<(), microraster::Error>(())
/// ```
pub trait Coverage: sealed::Sealed + Copy + Default + core::fmt::Debug {
    /// Whole pixels (in or out): a box fill is then rows of whole spans.
    #[doc(hidden)]
    const WHOLE: bool;
    /// Emits `(span, alpha)` runs of the covered pixels of `edges` in `clip`
    /// (the edges in the order they were built; sorted here where needed).
    #[doc(hidden)]
    fn cover<F: FnMut(Span, u8), const N: usize>(
        edges: &mut EdgeList<N>,
        rule: FillRule,
        clip: ClipRect,
        out: F,
    );
}

/// Whole pixels: in or out, by the top-left rule.
///
/// ```
/// use microraster::shape::{Aliased, ShapeStyle};
/// let s: ShapeStyle<u8, Aliased> = ShapeStyle::fill(1u8);
/// # let _ = s;
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Aliased;

/// Exact area coverage as alpha.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::shape::{AntiAliased, ShapeStyle};
/// let s: ShapeStyle<Gray8, AntiAliased> = ShapeStyle::fill(Gray8::WHITE).antialiased();
/// # let _ = s;
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct AntiAliased;

impl Coverage for Aliased {
    const WHOLE: bool = true;
    fn cover<F: FnMut(Span, u8), const N: usize>(
        edges: &mut EdgeList<N>,
        rule: FillRule,
        clip: ClipRect,
        out: F,
    ) {
        // One contour every row crosses twice needs no sort (`scan::Chains`).
        if let Some(chains) = scan::Chains::in_contour_order(edges.edges(), clip) {
            return chains.walk(edges.edges(), clip, &mut Runs::new(out));
        }
        edges.sort_by_top();
        scan::scan(edges, rule, clip, &mut Runs::new(out));
    }
}

impl Coverage for AntiAliased {
    const WHOLE: bool = false;
    fn cover<F: FnMut(Span, u8), const N: usize>(
        edges: &mut EdgeList<N>,
        rule: FillRule,
        clip: ClipRect,
        out: F,
    ) {
        edges.sort_by_top();
        area::scan(edges, rule, clip, &mut Runs::new(out));
    }
}

/// Merges adjacent pixels of one row and alpha into one span; alpha 0 is
/// dropped.
pub(crate) struct Runs<F> {
    out: F,
    pending: Option<(Span, u8)>,
}

impl<F: FnMut(Span, u8)> Runs<F> {
    fn new(out: F) -> Self {
        Runs { out, pending: None }
    }

    #[inline]
    pub(crate) fn push(&mut self, y: i32, x: i32, len: u32, alpha: u8) {
        if let Some((s, a)) = &mut self.pending {
            if *a == alpha && s.y == y && s.x + s.len as i32 == x {
                s.len += len;
                return;
            }
        }
        self.flush();
        if alpha > 0 && len > 0 {
            self.pending = Some((Span { y, x, len }, alpha));
        }
    }

    /// `span` whole, alpha 255, after any pending span: for a caller that
    /// joined its row's touching spans itself (the aliased scan).
    #[inline]
    pub(crate) fn emit(&mut self, span: Span) {
        self.flush();
        (self.out)(span, 255);
    }

    pub(crate) fn flush(&mut self) {
        if let Some((s, a)) = self.pending.take() {
            (self.out)(s, a);
        }
    }
}
