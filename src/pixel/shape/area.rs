//! Anti-aliased coverage: the exact area of each pixel inside the contours.
//!
//! # Method
//! For a pixel cell `[c, c+1] × [y, y+1]`, the integral of the winding
//! number over the cell is `Σ_edges dir · ∫ clamp(c + 1 − x(t), 0, 1) dt`
//! over the part of each edge inside the row strip (Green's theorem, one
//! edge at a time). Each edge's part in the strip is cut at the column
//! boundaries it crosses; in column `k` the piece of height `dt` between
//! `x = p` and `x = q` adds `dt · (k + 1 − (p + q)/2)` to cell `k` (the
//! trapezoid right of it) and `dt` to every cell right of `k` (the "cover").
//! Cells left of the clip are never visited: the part of an edge left of
//! the clip is cover, the part right of it nothing.
//!
//! The fill rule is applied to the integral: nonzero takes
//! `min(1, |v|)`, even-odd folds `v` into `[0, 1]`. Where a pixel holds one
//! layer of the shape (winding 0 or ±1 everywhere in it: every shape except
//! self-overlapping polygons and the joins of thick lines) that *is* the
//! exact area of the snapped shape inside the pixel; where contours overlap
//! inside a pixel it can overestimate it (documented in [`super`]).
//!
//! # Arithmetic
//! Integer, over the whole `±2^28`-subpixel range: every crossing (the `x`
//! of an edge at a strip boundary, the `t` at a column boundary) is the
//! exact rational `x0 + (t − y0)·dx/dy` (or its inverse) rounded down to
//! [`FB`] fraction bits of a subpixel, relative to the clip and the strip,
//! so far vertices lose nothing to cancellation. Numerators are below
//! `2^60`; a piece adds below `2^53` to a cell (one pixel is exactly
//! `2^(2·FB + 9)`), so `MAX_EDGES` edges sum below `2^61`. The crossings
//! telescope: a cell right of a piece gets its height exactly. Each edge
//! through a pixel adds at most `3 · 2^-26` px² of error there, so the
//! alpha, `⌊255·v + ½⌋` of the integer integral, is within `½ + 2^-16`
//! levels per such edge of `255 ×` the exact area (`½ + 1/256` with
//! [`MAX_EDGES`](super::MAX_EDGES)): the exact area rounded, except within
//! that margin of a tie (`tests/integration/shapes_ref/far.rs` and
//! `antialiased.rs` compare with the exact area in `f64`).
//!
//! # Fewer divisions, the same crossings
//! A 64-bit division is a library call on 32-bit cores, so the crossings
//! above are divided as rarely as their exact values allow:
//!
//! * at an edge's end the crossing is the end's `x`, a multiple of `dy` in
//!   the numerator: shifted, not divided;
//! * a strip's top crossing is the strip above's bottom one, kept per edge
//!   (the edge crossed that strip: it was active, and its piece ended on the
//!   shared boundary), so a row divides once per edge that runs through it;
//! * in a row, a piece's column crossings grow by a constant numerator per
//!   column: with `n · 2^FB = q·d + r` (`0 ≤ r < d`) held, the next one is
//!   `q + Q (+1 when r + R ≥ d)` for the exact quotient and remainder
//!   `Q·d + R = COL·dy·sign(dx)` (below `2^55`): one division for a piece's
//!   first crossing, one for the step, none after ([`Crossings`]);
//! * a division whose numerator fits 32 bits and denominator 20 (any shape
//!   on a screen) is done in 32-bit steps: the integer quotient, then the
//!   fraction's 22 bits as two 11-bit digits of long division.
//!
//! Each is the same integer as the rounded-down quotient it replaces, so the
//! alphas (and the bound above) are unchanged; the unit tests check the
//! stepped crossings and `fixed` against exact `i128` quotients.
//!
//! The row is processed in chunks of 32 cells: chunks no edge
//! reaches have one coverage and go out as one run; in the others only the
//! cells between the first and the last a piece wrote are accumulated and
//! read back one by one, the cells left and right of them being one run each.

use super::edges::{Active, BITS, Edge, EdgeList};
use super::{FillRule, Runs};
use crate::ClipRect;
use crate::edge::Span;

/// Cells accumulated at once.
pub(crate) const CHUNK: usize = 32;

/// Fraction bits of a subpixel in crossings (`fixed_rem`'s 32-bit path
/// divides in two steps of 11).
const FB: u32 = 22;
const _: () = assert!(FB == 2 * 11);
/// One subpixel, a pixel (a column's width, a strip's height) in crossing units.
const SUB: i64 = 1 << FB;
const COL: i64 = SUB << BITS;
/// The integral over one whole pixel: `COL · 2·COL` (areas are kept doubled,
/// so the trapezoid's `(p + q)/2` needs no rounding).
const FULL: i64 = COL * 2 * COL;

/// `n / d` (`d > 0`) rounded down to `FB` fraction bits: `⌊n · 2^FB / d⌋`
/// without forming `n · 2^FB` (`|n| < 2^60`, `d < 2^31`, and a result that
/// fits: `|n / d| < 2^40`, as every crossing, a coordinate, is).
#[inline]
fn fixed(n: i64, d: i64) -> i64 {
    fixed_rem(n, d).0
}

/// [`fixed()`] and its remainder: `(q, r)` with `n · 2^FB = q·d + r`,
/// `0 ≤ r < d`, so a crossing can be stepped exactly ([`Crossings`]).
#[inline]
fn fixed_rem(n: i64, d: i64) -> (i64, i64) {
    // Shapes on a screen have numerators below 2^31 and denominators below
    // 2^20: then both steps are 32-bit divisions, which Cortex-M3 and up do
    // in hardware (a 64-bit one is a library call). The same quotients.
    if let (Ok(n32), Ok(d32)) = (i32::try_from(n), u32::try_from(d)) {
        if d32 < 1 << 20 {
            // Euclidean: n = a·d + b, 0 ≤ b < d.
            let d = d32 as i32;
            let (a, b) = (n32.div_euclid(d), n32.rem_euclid(d) as u32);
            // b·2^FB = c·d + r in two base-2^11 digits, each step below 2^31:
            // b < 2^20, then r1 < d < 2^20.
            let (c1, r1) = ((b << 11) / d32, (b << 11) % d32);
            let (c2, r) = ((r1 << 11) / d32, (r1 << 11) % d32);
            return ((i64::from(a) << FB) + i64::from((c1 << 11) | c2), i64::from(r));
        }
    }
    // One quotient-and-remainder (`__aeabi_ldivmod` on 32-bit Arm), made
    // Euclidean: n = a·d + b, 0 ≤ b < d.
    let (mut a, mut b) = (n / d, n % d);
    if b < 0 {
        (a, b) = (a - 1, b + d);
    }
    // 0 ≤ b < d < 2^31: b · 2^FB < 2^53, unsigned: b·2^FB = c·d + r.
    let (bs, du) = ((b as u64) << FB, d as u64);
    let (c, r) = (bs / du, bs % du);
    ((a << FB) + c as i64, r as i64)
}

/// One edge clipped to a row strip: its left and right end, `x` in
/// crossing units from the clip's left side (`i64`: far vertices), `t` from
/// the strip's top (at most `16 · 2^FB`). Both ends lie on a strip boundary
/// or an end point of the edge, whole subpixels, so `|rt − lt|` is the
/// piece's exact height. 32 bytes: with the edge's index, not its copy.
#[derive(Debug, Clone, Copy, Default)]
struct Piece {
    lx: i64,
    rx: i64,
    lt: i32,
    rt: i32,
    edge: u32,
    dir: i32,
}

/// Where the strip starts: the clip's left side and the strip's top (subpixels).
#[derive(Clone, Copy)]
struct Origin {
    ox: i64,
    s0: i64,
}

impl Origin {
    /// `e` relative to the origin: `(x0, y0, dx, dy)` in subpixels.
    #[inline]
    fn rel(self, e: &Edge) -> (i64, i64, i64, i64) {
        let (x0, y0) = (i64::from(e.x0) - self.ox, i64::from(e.y0) - self.s0);
        (x0, y0, i64::from(e.x1) - i64::from(e.x0), i64::from(e.y1) - i64::from(e.y0))
    }

    /// Where `e` crosses row `t` (subpixels, absolute, within the edge's
    /// rows): `x` in crossing units from the clip's left side. At the
    /// edge's ends that is the end's `x`, exactly (`fixed` of a multiple of
    /// `dy`), with no division.
    #[inline]
    fn x_at(self, e: &Edge, t: i64) -> i64 {
        let ox = self.ox;
        if t == i64::from(e.y0) {
            return (i64::from(e.x0) - ox) << FB;
        }
        if t == i64::from(e.y1) {
            return (i64::from(e.x1) - ox) << FB;
        }
        let (x0, _, dx, dy) = self.rel(e);
        // |x0| < 2^29, dy ≤ 2^29, |t − e.y0| ≤ 2^29, |dx| ≤ 2^29: below 2^60.
        fixed(x0 * dy + (t - i64::from(e.y0)) * dx, dy)
    }

    /// `e` between rows `t0 < t1` (subpixels, absolute), crossing them at
    /// `x0` and `x1` ([`Self::x_at`]), as a piece.
    #[inline]
    fn piece(self, e: &Edge, edge: u32, (t0, x0): (i64, i64), (t1, x1): (i64, i64)) -> Piece {
        let (a, b) = ((x0, ((t0 - self.s0) * SUB) as i32), (x1, ((t1 - self.s0) * SUB) as i32));
        let (l, r) = if a.0 <= b.0 { (a, b) } else { (b, a) };
        Piece { lx: l.0, rx: r.0, lt: l.1, rt: r.1, edge, dir: e.dir }
    }

    /// Where `e` crosses the column boundaries `x`, `x + 16`, … (subpixels
    /// from the clip's left side), for `x` strictly inside the piece's `x`
    /// extent (so `dx ≠ 0`): `t` in crossing units from the strip's top.
    #[inline]
    fn crossings(self, e: &Edge, x: i64) -> Crossings {
        let (x0, y0, dx, dy) = self.rel(e);
        let s = dx.signum();
        // |y0 · dx| and |(x − x0) · dy| below 2^59 each; the result lies in
        // the strip, 0 ..= 16 · 2^FB.
        let (q, r) = fixed_rem(y0 * dx * s + (x - x0) * dy * s, dx * s);
        Crossings { q, r, d: dx * s, rise: dy * s, step: None }
    }
}

/// One edge's crossings of successive column boundaries, left to right:
/// `t = ⌊n · 2^FB / d⌋` with `n` growing by `16·dy·sign(dx)` a column, kept
/// as `n · 2^FB = q·d + r` (`0 ≤ r < d`) and stepped by the exact quotient
/// and remainder of that growth, `Q·d + R = COL·dy·sign(dx)` (below `2^55`):
/// one division for the first crossing, one for the step (at the second),
/// none after. The same `t` as dividing at every column.
struct Crossings {
    q: i64,
    r: i64,
    d: i64,
    rise: i64,
    step: Option<(i64, i64)>,
}

impl Crossings {
    /// The current crossing (within the strip: `0 ..= 16 · 2^FB`).
    #[inline]
    fn t(&self) -> i32 {
        self.q as i32
    }

    /// Moves to the next column boundary.
    #[inline]
    fn advance(&mut self) {
        let (d, rise) = (self.d, self.rise);
        // COL·rise = (16·rise)·2^FB: the step is `fixed_rem(16·rise, d)`.
        let (sq, sr) = *self.step.get_or_insert_with(|| fixed_rem((COL >> FB) * rise, d));
        (self.q, self.r) = (self.q + sq, self.r + sr);
        if self.r >= d {
            (self.q, self.r) = (self.q + 1, self.r - d);
        }
    }
}

/// Doubled area of height `|b − a|` times a pixel's width, signed by `dir`:
/// what a piece gives every cell right of it.
#[inline]
fn cover(dir: i32, a: i32, b: i32) -> i64 {
    i64::from(dir) * i64::from((b - a).abs()) * 2 * COL
}

fn alpha(v: i64, rule: FillRule) -> u8 {
    let cov = match rule {
        FillRule::NonZero => v.abs().min(FULL),
        FillRule::EvenOdd => {
            let m = v.abs() % (2 * FULL);
            if m > FULL { 2 * FULL - m } else { m }
        }
    };
    // cov ≤ 2^53: 255·cov < 2^61.
    ((cov * 255 + FULL / 2) / FULL) as u8
}

/// Emits `(span, alpha)` runs of the exact coverage of `edges` (sorted by
/// top) inside `clip`.
pub(crate) fn scan<F: FnMut(Span, u8), const N: usize>(
    edges: &EdgeList<N>,
    rule: FillRule,
    clip: ClipRect,
    runs: &mut Runs<F>,
) {
    let (y_min, y_max) = edges.y_range();
    if edges.is_empty() || clip.is_empty() {
        return;
    }
    let one = 1i64 << BITS;
    let lo = (i64::from(y_min).div_euclid(one)).max(i64::from(clip.y0())) as i32;
    let hi = super::scan::div_ceil(i64::from(y_max), one).min(i64::from(clip.y1())) as i32;
    let cols = i64::from(clip.x1() - clip.x0());
    // Written as the row's pieces come, never zeroed ahead.
    let mut pieces = heapless::Vec::<Piece, N>::new();
    // Each edge's crossing of the last strip's bottom, by edge index: a slot
    // per edge entered so far, added as edges enter (not zeroed ahead).
    let mut xs = heapless::Vec::<i64, N>::new();
    let mut active = Active::<N>::new();
    let mut cells = Cells { area: [0; CHUNK], start: [0; CHUNK + 1] };
    for y in lo..hi {
        let o = Origin { ox: i64::from(clip.x0()) * one, s0: i64::from(y) * one };
        let s1 = o.s0 + one;
        let (mut min_x, mut max_x) = (i64::MAX, i64::MIN);
        pieces.clear();
        active.advance(edges.edges(), s1, o.s0);
        // Fits: at most N edges enter.
        let _ = xs.resize(active.entered(), 0);
        for (i, e) in active.indexed(edges.edges()) {
            let (t0, t1) = (i64::from(e.y0).max(o.s0), i64::from(e.y1).min(s1));
            if t0 >= t1 {
                continue;
            }
            // The strip's top crossing is the previous strip's bottom one
            // when the edge ran through it (it did, from row `lo + 1` on,
            // unless it starts in this strip: then it is its end).
            let x0 = if i64::from(e.y0) < o.s0 && y > lo { xs[i as usize] } else { o.x_at(e, t0) };
            let x1 = o.x_at(e, t1);
            xs[i as usize] = x1;
            let p = o.piece(e, i, (t0, x0), (t1, x1));
            (min_x, max_x) = (min_x.min(p.lx), max_x.max(p.rx));
            // Fits: a piece per active edge, at most N.
            let _ = pieces.push(p);
        }
        if pieces.is_empty() {
            continue;
        }
        // Columns (from the clip's left side) the pieces can reach.
        let x_lo = min_x.div_euclid(COL).clamp(0, cols) as i32;
        let x_hi = (max_x.div_euclid(COL) + 1).clamp(0, cols) as i32;
        let strip = Strip { edges: edges.edges(), pieces: &pieces, o, y, cx0: clip.x0() };
        strip.row((x_lo, x_hi), rule, &mut cells, runs);
    }
    runs.flush();
}

/// One chunk's accumulators (doubled areas): each cell's partial area, and
/// the winding change entering at each cell. Kept by the caller, all zeros
/// between chunks: a chunk reads (and zeroes again) only the cells its
/// pieces wrote, most of a thin stroke's chunk is one run either side of
/// them, and most chunks of a large shape (its inside, or the hole of a
/// ring) are one coverage and need neither.
struct Cells {
    area: [i64; CHUNK],
    start: [i64; CHUNK + 1],
}

/// One row strip's pieces.
struct Strip<'a> {
    edges: &'a [Edge],
    pieces: &'a [Piece],
    o: Origin,
    y: i32,
    cx0: i32,
}

impl Strip<'_> {
    /// Columns `x_lo..x_hi` (from the clip's left side), chunk by chunk.
    fn row<F: FnMut(Span, u8)>(
        &self,
        (x_lo, x_hi): (i32, i32),
        rule: FillRule,
        Cells { area, start }: &mut Cells,
        runs: &mut Runs<F>,
    ) {
        let mut c0 = x_lo;
        while c0 < x_hi {
            let len = (x_hi - c0).min(CHUNK as i32);
            let (f0, f1) = (i64::from(c0) * COL, i64::from(c0 + len) * COL);
            let mut base = 0i64;
            // Cells the pieces wrote: area[k_lo..k_hi], start[k_lo + 1 ..= k_hi].
            let (mut k_lo, mut k_hi) = (i64::from(len), 0i64);
            for p in self.pieces {
                if p.rx <= f0 {
                    base += cover(p.dir, p.lt, p.rt);
                } else if p.lx < f1 {
                    let e = &self.edges[p.edge as usize];
                    // The part left of the chunk is cover for all of it.
                    let (mut ax, mut at) = (p.lx, p.lt);
                    // Its crossings of the column boundaries, from the
                    // chunk's left side or the piece's first one on.
                    let mut k = (ax.max(f0) - f0).div_euclid(COL);
                    let mut cross = None::<Crossings>;
                    if ax < f0 {
                        let c = cross.insert(self.o.crossings(e, f0 >> FB));
                        base += cover(p.dir, at, c.t());
                        (ax, at) = (f0, c.t());
                    }
                    // Column by column, to the right end or the chunk's side.
                    k_lo = k_lo.min(k);
                    while k < i64::from(len) {
                        let side = f0 + (k + 1) * COL;
                        let end = p.rx <= side;
                        let bt = if end {
                            p.rt
                        } else {
                            match &mut cross {
                                Some(c) => c.advance(),
                                None => cross = Some(self.o.crossings(e, side >> FB)),
                            }
                            cross.as_ref().map_or(0, Crossings::t)
                        };
                        let bx = if end { p.rx } else { side };
                        // The trapezoid right of the piece in column k, and
                        // its height as cover for the columns after it.
                        let dt = i64::from(p.dir) * i64::from((bt - at).abs());
                        area[k as usize] += dt * (2 * side - ax - bx);
                        start[k as usize + 1] += dt * 2 * COL;
                        if end {
                            break;
                        }
                        (ax, at, k) = (bx, bt, k + 1);
                    }
                    k_hi = k_hi.max((k + 1).min(i64::from(len)));
                }
            }
            let x = self.cx0 + c0;
            if k_lo >= k_hi {
                runs.push(self.y, x, len as u32, alpha(base, rule));
            } else {
                // Left of the first written cell the coverage is `base`,
                // right of the last one `base` plus every piece's height:
                // one run each. The cells read are zeroed again, so the
                // arrays are all zeros at every chunk's start.
                let (lo, hi) = (k_lo as usize, k_hi as usize);
                if lo > 0 {
                    runs.push(self.y, x, lo as u32, alpha(base, rule));
                }
                // Cells of one integral in a row (a stroke's inside, the
                // cells between two pieces) are one run: the alpha and the
                // push once per change of the integral, not per cell.
                let mut cover = base;
                let (mut run, mut run_x) = (None::<i64>, lo);
                for k in lo..hi {
                    cover += core::mem::take(&mut start[k]);
                    let v = cover + core::mem::take(&mut area[k]);
                    if run != Some(v) {
                        if let Some(r) = run {
                            runs.push(self.y, x + run_x as i32, (k - run_x) as u32, alpha(r, rule));
                        }
                        (run, run_x) = (Some(v), k);
                    }
                }
                if let Some(r) = run {
                    runs.push(self.y, x + run_x as i32, (hi - run_x) as u32, alpha(r, rule));
                }
                cover += core::mem::take(&mut start[hi]);
                if hi < len as usize {
                    runs.push(self.y, x + hi as i32, (len as usize - hi) as u32, alpha(cover, rule));
                }
            }
            c0 += len;
        }
    }
}

#[cfg(test)]
mod tests;
