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
//! `x ≥ ⌈−F₀/A⌉` for `A > 0` and `x ≤ ⌊F₀/−A⌋` for `A < 0`. The span is then
//! filled without per-pixel tests, which is what brings flat fills near the
//! speed of a slice fill.
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

/// Which triangles to drop by their winding on screen (y pointing down).
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

/// Integer widths the per-row walker can run in.
pub(crate) trait EdgeInt: Copy + Ord + core::fmt::Debug {
    const ZERO: Self;
    fn from_i64(v: i64) -> Self;
    fn to_i64(self) -> i64;
    fn add(self, o: Self) -> Self;
    /// ⌊n/d⌋ for `d > 0`.
    fn div_floor(n: Self, d: Self) -> Self;
    fn neg(self) -> Self;
}

macro_rules! edge_int {
    ($t:ty) => {
        impl EdgeInt for $t {
            const ZERO: Self = 0;
            #[inline(always)]
            fn from_i64(v: i64) -> Self {
                v as $t // callers prove the value fits
            }
            #[inline(always)]
            fn to_i64(self) -> i64 {
                self as i64
            }
            #[inline(always)]
            fn add(self, o: Self) -> Self {
                self + o
            }
            #[inline(always)]
            fn div_floor(n: Self, d: Self) -> Self {
                let q = n / d;
                if n % d != 0 && n < 0 { q - 1 } else { q }
            }
            #[inline(always)]
            fn neg(self) -> Self {
                -self
            }
        }
    };
}
edge_int!(i32);
edge_int!(i64);

/// Per-row state of the three reduced edge functions.
#[derive(Debug, Clone)]
pub(crate) struct Walker<T> {
    f: [T; 3],
    a: [T; 3],
    b: [T; 3],
    x0: i32,
    last_col: T, // columns x0..=x0+last_col are inside bbox ∩ clip
    y: i32,
    y_end: i32,
}

impl<T: EdgeInt> Walker<T> {
    #[inline(always)]
    fn next_span(&mut self) -> Option<Span> {
        while self.y < self.y_end {
            let y = self.y;
            let mut lo = T::ZERO;
            let mut hi = self.last_col;
            for i in 0..3 {
                let (f, a) = (self.f[i], self.a[i]);
                if a > T::ZERO {
                    lo = lo.max(T::div_floor(f, a).neg());
                } else if a < T::ZERO {
                    hi = hi.min(T::div_floor(f, a.neg()));
                } else if f < T::ZERO {
                    hi = T::from_i64(-1);
                }
                self.f[i] = f.add(self.b[i]);
            }
            self.y += 1;
            if lo <= hi {
                let (lo, hi) = (lo.to_i64(), hi.to_i64());
                return Some(Span { y, x: self.x0 + lo as i32, len: (hi - lo + 1) as u32 });
            }
        }
        None
    }
}

#[derive(Debug, Clone)]
enum Path {
    Empty,
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
    pub fn new<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect, cull: Cull) -> Self {
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
        let row1 = ((max_y - half) >> shift).min(clip.y1() as i64 - 1);
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
        let ext = (max_x - min_x).max(max_y - min_y) + one;
        let fast = ext <= const { fast_ext_internal(S) };
        let last_col = col1 - col0;
        let (x0, y, y_end) = (col0 as i32, row0 as i32, row1 as i32 + 1);
        let path = if fast {
            Path::Narrow(Walker {
                f: f.map(|v| v as i32),
                a: a.map(|v| v as i32),
                b: b.map(|v| v as i32),
                x0,
                last_col: last_col as i32,
                y,
                y_end,
            })
        } else {
            Path::Wide(Walker { f, a, b, x0, last_col, y, y_end })
        };
        TriangleSpans { path }
    }

    /// True if there are certainly no spans (zero area, culled, or no pixel
    /// centre of the bounding box inside the clip).
    pub(crate) fn is_empty(&self) -> bool {
        matches!(self.path, Path::Empty)
    }

    /// True if this triangle took the `i32` fast path.
    pub fn is_fast_path(&self) -> bool {
        matches!(self.path, Path::Narrow(_))
    }
}

impl Iterator for TriangleSpans {
    type Item = Span;

    #[inline]
    fn next(&mut self) -> Option<Span> {
        match &mut self.path {
            Path::Empty => None,
            Path::Narrow(w) => w.next_span(),
            Path::Wide(w) => w.next_span(),
        }
    }
}

/// Twice the signed area in internal units; positive for clockwise on screen.
pub(crate) fn signed_area2(p: [(i64, i64); 3]) -> i64 {
    (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
}

fn min_max(a: i64, b: i64, c: i64) -> (i64, i64) {
    (a.min(b).min(c), a.max(b).max(c))
}
