//! Triangle coverage: integer edge functions and the top-left fill rule.
//!
//! # Method
//! Vertices are taken in *internal* units of `1/2^(S+1)` pixel (the snapped
//! coordinates doubled), so that pixel centres `X + 0.5` are the odd integers
//! `X·2^(S+1) + 2^S` for every `S`, including `S = 0`.
//!
//! For an edge `a → b` of a clockwise (on screen, y down) triangle the edge
//! function is `E(p) = A·(p.x − a.x) + B·(p.y − a.y)` with `A = a.y − b.y` and
//! `B = b.x − a.x`; `E > 0` inside. At pixel centres `E` is evaluated in the
//! *reduced* form `F = ⌊(E − bias) / 2^(S+1)⌋`, with `bias = 0` for a top or left
//! edge and `1` otherwise. Then `F ≥ 0` holds exactly when the centre is
//! covered under the top-left rule (D3D11.3 §3.4.2.1), and `F` steps by `A`
//! per column and by `B` per row, so only whole-pixel increments are needed.
//!
//! Each row's covered span is solved exactly: `F(x) = F₀ + A·x ≥ 0` gives
//! `x ≥ ⌈−F₀/A⌉` for `A > 0` and `x ≤ ⌊F₀/−A⌋` for `A < 0`. The divisions
//! are done once per triangle and clip: from row to row each quotient and its
//! remainder step by those of `B / |A|`, with a carry, which is exact. The span
//! is then filled without per-pixel tests, which is what brings flat fills
//! near the speed of a slice fill.
//!
//! Triangles at most [`SMALL_PX`] pixels on a side skip all of that: each
//! candidate centre is tested with the same edge functions in `i32`
//! (`edge::small`), which gives the same spans for less set-up.
//!
//! # Overflow proof
//! Coordinates are bounded by `|v| ≤ 2^28` subpixels ([`SubPoint`]), so in
//! internal units differences are at most `2^30`, products `2^60` and the sum
//! of two products `2^61`: setup in `i64` cannot overflow. Pixel centres are
//! only evaluated inside the triangle's bounding box (plus one row), so with
//! `ext` = the larger bounding-box side in internal units plus one pixel,
//! `|F| ≤ 2·ext² / 2^(S+1) + 1`. When that is below `i32::MAX` the per-row work
//! runs in `i32` (the *fast path*, [`fast_path_extent_px`]); otherwise in `i64`.
//! Both paths give identical pixels; only the integer width differs.

use crate::{ClipRect, SubPoint};

pub(crate) mod small;
pub use small::SMALL_PX;
mod walk;
use walk::Walker;

/// Which triangles to drop by their winding on screen (y pointing down).
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor};
/// use microraster::{Band, Cull, Primitive, Renderer, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// // Clockwise on screen (x right, y down).
/// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
/// let mut display = MockDisplay::new();
/// let r = Renderer::new(4, BinaryColor::Off).with_cull(Cull::Clockwise);
/// r.render(&scene, &mut Band::<_, 4, 4>::new(BinaryColor::Off), &mut display)?;
/// display.assert_pattern(&["....", "....", "....", "...."]);
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Cull {
    /// Draw both windings.
    #[default]
    None,
    /// Drop triangles whose vertices run clockwise on screen.
    Clockwise,
    /// Drop triangles whose vertices run counter-clockwise on screen.
    CounterClockwise,
}

/// One row of covered pixels: columns `x .. x + len` of row `y`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Span {
    /// Row.
    pub y: i32,
    /// First covered column.
    pub x: i32,
    /// Number of covered pixels (at least 1).
    pub len: u32,
}

/// Largest bounding-box side, in whole pixels, for which a triangle at `s`
/// subpixel bits takes the `i32` fast path (larger ones use `i64`); `s` above
/// [`MAX_SUBPIXEL_BITS`](crate::MAX_SUBPIXEL_BITS) is clamped to it.
///
/// ```
/// // A whole 480×320 screen takes the fast path even at 8 subpixel bits.
/// assert!(microraster::edge::fast_path_extent_px(8) >= 480);
/// ```
pub const fn fast_path_extent_px(s: u32) -> i64 {
    // Beyond MAX_SUBPIXEL_BITS no SubPoint exists; clamp rather than overflow.
    let s = if s > crate::MAX_SUBPIXEL_BITS { crate::MAX_SUBPIXEL_BITS } else { s };
    fast_ext_internal(s) / (1i64 << (s + 1)) - 1
}

/// Largest `ext` (internal units) with `2·ext² ≤ (i32::MAX − 2)·2^(S+1)`, which
/// makes `|F| ≤ 2·ext²/2^(S+1) + 1` fit in `i32` (see the module docs).
const fn fast_ext_internal(s: u32) -> i64 {
    let limit = (i32::MAX as i64 - 2) * (1i64 << (s + 1)) / 2;
    let (mut lo, mut hi) = (0i64, 1i64 << 31);
    while lo < hi {
        let mid = (lo + hi + 1) / 2;
        if mid * mid <= limit { lo = mid } else { hi = mid - 1 }
    }
    lo
}

#[derive(Debug, Clone)]
enum Path {
    Empty,
    Small(small::Small),
    Narrow(Walker<i32>),
    Wide(Walker<i64>),
}

/// The covered spans of one triangle inside a clip rectangle, top to bottom.
///
/// ```
/// use microraster::{ClipRect, SubPoint, edge::{Cull, TriangleSpans}};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let spans = TriangleSpans::new([p(0, 0), p(4, 0), p(0, 4)], ClipRect::new(0, 0, 8, 8), Cull::None);
/// let lens: Vec<u32> = spans.map(|s| s.len).collect();
/// // Centres (3.5, 0.5), (2.5, 1.5), … lie exactly on the hypotenuse, a right
/// // edge, so the top-left rule leaves them to the neighbouring triangle.
/// assert_eq!(lens, [3, 2, 1]);
/// ```
#[derive(Debug, Clone)]
pub struct TriangleSpans {
    path: Path,
}

impl TriangleSpans {
    /// Sets up the edge functions of `v` for the pixels inside `clip`.
    ///
    /// Zero-area triangles (after snapping) and culled windings yield no spans.
    // Inlined, so a small triangle's path is known to the caller's loop
    // (`fold`) without going through the whole enum; the row solver is not.
    #[inline(always)]
    pub fn new<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect, cull: Cull) -> Self {
        match small::setup(v, clip, cull) {
            Some(path) => TriangleSpans { path },
            None => Self::solved(v, clip, cull),
        }
    }

    /// [`TriangleSpans::new`] by solving each row's span, whatever the size:
    /// the reference the per-centre test of small triangles is checked
    /// against.
    #[inline(never)]
    pub(crate) fn solved<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect, cull: Cull) -> Self {
        let empty = TriangleSpans { path: Path::Empty };
        let p = v.map(|p| (2 * p.x() as i64, 2 * p.y() as i64));
        let det = signed_area2(p);
        let clockwise = det > 0;
        if det == 0 || clip.is_empty() {
            return empty;
        }
        match (cull, clockwise) {
            (Cull::Clockwise, true) | (Cull::CounterClockwise, false) => return empty,
            _ => {}
        }
        let p = if clockwise { p } else { [p[0], p[2], p[1]] };
        let shift = S + 1;
        let one = 1i64 << shift;
        let half = 1i64 << S;
        let (min_x, max_x) = min_max(p[0].0, p[1].0, p[2].0);
        let (min_y, max_y) = min_max(p[0].1, p[1].1, p[2].1);
        // Pixels whose centre can lie inside the bounding box.
        let col0 = ((min_x - half + one - 1) >> shift).max(clip.x0() as i64);
        let col1 = ((max_x - half) >> shift).min(clip.x1() as i64 - 1);
        let row0 = ((min_y - half + one - 1) >> shift).max(clip.y0() as i64);
        // A horizontal edge (A = 0) only bounds the rows. At the top (B > 0, a
        // top edge) it takes centres on it: exactly the rows above. At the
        // bottom (B < 0) it leaves out a row whose centre lies on it.
        let flat_bottom = p.iter().filter(|q| q.1 == max_y).count() == 2;
        let on_bottom = flat_bottom && (max_y - half) & (one - 1) == 0;
        let row1 = (((max_y - half) >> shift) - on_bottom as i64).min(clip.y1() as i64 - 1);
        if col0 > col1 || row0 > row1 {
            return empty;
        }
        let cx = col0 * one + half;
        let cy = row0 * one + half;
        let mut f = [0i64; 3];
        let mut a = [0i64; 3];
        let mut b = [0i64; 3];
        for i in 0..3 {
            let (s, e) = (p[i], p[(i + 1) % 3]);
            a[i] = s.1 - e.1;
            b[i] = e.0 - s.0;
            let top_left = a[i] > 0 || (a[i] == 0 && b[i] > 0);
            let bias = if top_left { 0 } else { 1 };
            let edge = a[i] * (cx - s.0) + b[i] * (cy - s.1);
            f[i] = (edge - bias) >> shift;
        }
        // Edge functions sum their A to 0 and are not all 0: there is a left
        // edge (A > 0) and a right edge (A < 0); the third is either, or
        // horizontal (then the left edge takes its slot again).
        let left = if a[0] > 0 {
            0
        } else if a[1] > 0 {
            1
        } else {
            2
        };
        let right = if a[0] < 0 {
            0
        } else if a[1] < 0 {
            1
        } else {
            2
        };
        let mid = 3 - left - right;
        let (mid, mid_left) = if a[mid] == 0 { (left, true) } else { (mid, a[mid] > 0) };
        let edge = |i: usize| (f[i], a[i].abs(), b[i]);
        let e = [edge(left), edge(mid), edge(right)];
        let ext = (max_x - min_x).max(max_y - min_y) + one;
        let fast = ext <= const { fast_ext_internal(S) };
        let last_col = col1 - col0;
        let (x0, y, y_end) = (col0 as i32, row0 as i32, row1 as i32 + 1);
        let path = if fast {
            Path::Narrow(Walker::new(e, mid_left, x0, last_col, y, y_end))
        } else {
            Path::Wide(Walker::new(e, mid_left, x0, last_col, y, y_end))
        };
        TriangleSpans { path }
    }

    /// `f` on every remaining span, in one loop over local state (the
    /// internal iteration of `fold`, on a borrowed iterator).
    #[inline(always)]
    pub(crate) fn for_each_ref(&self, mut f: impl FnMut(Span)) {
        match &self.path {
            Path::Empty => {}
            Path::Small(s) => s.fold((), |(), span| f(span)),
            Path::Narrow(w) => w.fold((), |(), span| f(span)),
            Path::Wide(w) => w.fold((), |(), span| f(span)),
        }
    }

    /// True if this triangle took the `i32` fast path.
    pub fn is_fast_path(&self) -> bool {
        matches!(self.path, Path::Narrow(_) | Path::Small(_))
    }
}

impl Iterator for TriangleSpans {
    type Item = Span;

    // Always inlined: the 3D fragment loop takes each triangle's first span
    // with it, and a call per triangle showed in its cost.
    #[inline(always)]
    fn next(&mut self) -> Option<Span> {
        match &mut self.path {
            Path::Empty => None,
            Path::Small(s) => s.next_span(),
            Path::Narrow(w) => w.next_span(),
            Path::Wide(w) => w.next_span(),
        }
    }

    // Internal iteration (`for_each`, `sum`, …) walks the rows in one loop
    // instead of one `next` call per span.
    #[inline]
    fn fold<B, G: FnMut(B, Span) -> B>(self, init: B, g: G) -> B {
        match &self.path {
            Path::Empty => init,
            Path::Small(s) => s.fold(init, g),
            Path::Narrow(w) => w.fold(init, g),
            Path::Wide(w) => w.fold(init, g),
        }
    }
}

/// The spans left after the first ones, walked by internal iteration: a
/// [`TriangleSpans`], or a small triangle's own state ([`small::setup_state`]).
pub(crate) trait SpanRest {
    /// `f` on every remaining span, top to bottom.
    fn for_each_ref(&self, f: impl FnMut(Span));
}

impl SpanRest for TriangleSpans {
    #[inline(always)]
    fn for_each_ref(&self, f: impl FnMut(Span)) {
        TriangleSpans::for_each_ref(self, f)
    }
}

impl SpanRest for small::Small {
    #[inline(always)]
    fn for_each_ref(&self, mut f: impl FnMut(Span)) {
        self.fold((), |(), span| f(span))
    }
}

/// Twice the signed area in internal units; positive for clockwise on screen.
pub(crate) fn signed_area2(p: [(i64, i64); 3]) -> i64 {
    (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
}

fn min_max<T: Ord + Copy>(a: T, b: T, c: T) -> (T, T) {
    (a.min(b).min(c), a.max(b).max(c))
}
