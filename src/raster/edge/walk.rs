//! The row solver's per-row state: each edge's exact quotient and remainder,
//! stepped from row to row in `i32` or `i64` ([`EdgeInt`]). The bounds it
//! relies on are proved in the overflow proof of [`edge`](super)'s module docs.

use super::Span;

/// Integer widths the per-row walker can run in.
pub(crate) trait EdgeInt: Copy + Ord + core::fmt::Debug {
    const ZERO: Self;
    const ONE: Self;
    fn from_i64(v: i64) -> Self;
    fn to_i64(self) -> i64;
    fn add(self, o: Self) -> Self;
    fn sub(self, o: Self) -> Self;
    fn neg(self) -> Self;
    /// `(⌊n/d⌋, n − ⌊n/d⌋·d)` for `d > 0`.
    fn div_rem_floor(n: Self, d: Self) -> (Self, Self);
}

macro_rules! edge_int {
    ($t:ty) => {
        impl EdgeInt for $t {
            const ZERO: Self = 0;
            const ONE: Self = 1;
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
            fn sub(self, o: Self) -> Self {
                self - o
            }
            #[inline(always)]
            fn neg(self) -> Self {
                -self
            }
            #[inline(always)]
            fn div_rem_floor(n: Self, d: Self) -> (Self, Self) {
                let (q, r) = (n / d, n % d);
                if r < 0 { (q - 1, r + d) } else { (q, r) }
            }
        }
    };
}
edge_int!(i32);
edge_int!(i64);

/// Per-row state of a triangle's edges, kept as the exact quotient and
/// remainder `F = q·d + r` of each reduced edge function by `d = |A|`
/// (`0 ≤ r < d`). Edge 0 is a left edge (`A > 0`: the first covered column is
/// `−q`), edge 2 a right edge (`A < 0`: the last covered column is `q`), edge
/// 1 either (`mid_left`); a horizontal edge (`A = 0`) only bounds the rows and
/// is applied to them at set-up (its slot then repeats edge 0). From row to
/// row `F` grows by `B = bq·d + br`, so `q` grows by `bq` and `r` by `br`, plus
/// a carry when `r` reaches `d`: exact, with no division. Stored per edge: the
/// column bound `c` (`−q` or `q`), `e = r − d` (in `−d..0`, so the carry is
/// `e + br ≥ 0`), and the bound's steps (`∓bq`, `∓1`). Every `q` lies between
/// 0 and the `F` it stands for, and `|e + br| < d`, within the bounds of the
/// module docs.
#[derive(Debug, Clone)]
pub(crate) struct Walker<T> {
    c: [T; 3],
    e: [T; 3],
    d: [T; 3],
    br: [T; 3],
    step: [T; 3],
    unit: [T; 3],
    mid_left: bool,
    x0: i32,
    last_col: T, // columns x0..=x0+last_col are inside bbox ∩ clip
    y: i32,
    y_end: i32,
}

impl<T: EdgeInt> Walker<T> {
    /// The walker at row `y` for reduced edge functions `f` (at column `x0`
    /// of that row) with `d = |A| > 0` and row steps `b`, in `i64`; the
    /// caller proves every `F` value the walk reaches fits `T`.
    #[inline(always)]
    pub(super) fn new(
        e: [(i64, i64, i64); 3],
        mid_left: bool,
        x0: i32,
        last_col: i64,
        y: i32,
        y_end: i32,
    ) -> Self {
        let mut w = Walker {
            c: [T::ZERO; 3],
            e: [T::ZERO; 3],
            d: [T::ONE; 3],
            br: [T::ZERO; 3],
            step: [T::ZERO; 3],
            unit: [T::ZERO; 3],
            mid_left,
            x0,
            last_col: T::from_i64(last_col),
            y,
            y_end,
        };
        // One row needs no row step; a repeated edge no second division.
        let steps = y_end - y > 1;
        for (i, &(f, d, b)) in e.iter().enumerate() {
            if i == 1 && e[1] == e[0] {
                (w.c[1], w.e[1], w.d[1], w.br[1], w.step[1], w.unit[1]) =
                    (w.c[0], w.e[0], w.d[0], w.br[0], w.step[0], w.unit[0]);
                continue;
            }
            let left = i == 0 || (i == 1 && mid_left);
            let sign = |v: T| if left { v.neg() } else { v };
            let d = T::from_i64(d);
            let (q, r) = T::div_rem_floor(T::from_i64(f), d);
            (w.c[i], w.e[i], w.d[i], w.unit[i]) = (sign(q), r.sub(d), d, sign(T::ONE));
            if steps {
                let (bq, br) = T::div_rem_floor(T::from_i64(b), d);
                (w.step[i], w.br[i]) = (sign(bq), br);
            }
        }
        w
    }

    /// The bounds of the current row (`lo > hi` if it is empty), stepping the
    /// state to the next row.
    #[inline(always)]
    fn row(c: &mut [T; 3], e: &mut [T; 3], w: &Self) -> (T, T) {
        let lo = T::ZERO.max(c[0]);
        let hi = w.last_col.min(c[2]);
        let (lo, hi) = if w.mid_left { (lo.max(c[1]), hi) } else { (lo, hi.min(c[1])) };
        for i in 0..3 {
            // Next row: F + B, as quotient and remainder.
            let ne = e[i].add(w.br[i]);
            let carry = ne >= T::ZERO;
            e[i] = if carry { ne.sub(w.d[i]) } else { ne };
            c[i] = c[i].add(w.step[i]).add(if carry { w.unit[i] } else { T::ZERO });
        }
        (lo, hi)
    }

    #[inline(always)]
    fn span(&self, y: i32, lo: T, hi: T) -> Span {
        let (lo, hi) = (lo.to_i64(), hi.to_i64());
        Span { y, x: self.x0 + lo as i32, len: (hi - lo + 1) as u32 }
    }

    #[inline(always)]
    pub(super) fn next_span(&mut self) -> Option<Span> {
        let (mut c, mut e) = (self.c, self.e);
        let mut out = None;
        while self.y < self.y_end {
            let y = self.y;
            let (lo, hi) = Self::row(&mut c, &mut e, self);
            self.y += 1;
            if lo <= hi {
                out = Some(self.span(y, lo, hi));
                break;
            }
        }
        (self.c, self.e) = (c, e);
        out
    }

    /// All remaining spans, in one loop over local state.
    #[inline(always)]
    pub(super) fn fold<B, G: FnMut(B, Span) -> B>(&self, init: B, mut g: G) -> B {
        let (mut c, mut e) = (self.c, self.e);
        let mut acc = init;
        for y in self.y..self.y_end {
            let (lo, hi) = Self::row(&mut c, &mut e, self);
            if lo <= hi {
                acc = g(acc, self.span(y, lo, hi));
            }
        }
        acc
    }
}
