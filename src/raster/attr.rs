//! Attribute planes: values interpolated linearly in screen space across a
//! triangle (Gouraud colour, depth, perspective numerators and `1/w`).
//!
//! A value `v` with vertex values `v₀, v₁, v₂` is the plane
//! `v(p) = v₀ + λ₁(v₁ − v₀) + λ₂(v₂ − v₀)`, the barycentric weights taken from
//! the same snapped coordinates as coverage. Setup (once per triangle and
//! band; the determinant and its divisor once for all of a triangle's
//! values, [`PlaneSetup`]) computes, each rounded to nearest in the caller's
//! fixed-point units:
//! the per-pixel gradients `gx`, `gy` and the value `base` at a reference
//! pixel centre inside the clip. Then
//! `v(x, y) = base + gx·(x − rx) + gy·(y − ry)` is evaluated at each span
//! start and stepped by `gx` along the span.
//!
//! # Error bound
//! Each of `base`, `gx`, `gy` is within ½ unit of exact. Reference and sample
//! pixels lie in the same frame (`< 2^12` apart on each axis) and a span adds
//! fewer than 2^12 steps, so any sampled value is within
//! `½·(1 + 3·2^12) < 2^13` units of exact. Callers choose their fixed-point
//! scale from that: Gouraud colour uses 2^20 units per channel step (error
//! < 2^-7, so every output channel is within 0.5 + 2^-7 of exact); depth
//! uses 2^16 units per depth step (error < 1/8 LSB).
//!
//! # Overflow
//! Values are at most 2^56 in magnitude, and the exact value at every pixel
//! the caller samples lies between the vertex values, so it fits `i64`.
//! Gradients of slivers can exceed `i64`, and so can the terms `gx·(x − rx)`;
//! evaluation therefore uses wrapping arithmetic, which is exact modulo 2^64
//! and so returns the (in-range) sum. Setup runs in `i64` when the products fit
//! (checked on bit lengths), dividing exactly by the determinant in one of
//! the ways of [`divide`] (chosen by its size and the target); where only the
//! numerators fit, by splitting off their quotients first
//! ([`PlaneSetup::plane_split`], the deep subpixel precisions); and in `i128`
//! otherwise. All give the same correctly rounded values.

mod channel;
mod divide;

pub(crate) use channel::{COLOR_FRAC, COLOR_HALF, channel_clamped, channel_in_range};
use divide::Divisor;

/// Vertex positions in internal units (`1/2^(S+1)` px).
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneFrame {
    /// Internal coordinates of the three vertices.
    pub v: [(i64, i64); 3],
    /// `log2` of one pixel in internal units (`S + 1`).
    pub shift: u32,
}

/// One interpolated value, in the caller's fixed-point units.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Plane {
    base: i64,
    gx: i64,
    gy: i64,
    rx: i32,
    ry: i32,
}

impl Plane {
    /// The plane through `values` (|v| ≤ 2^56) at the vertices of `frame`,
    /// referenced at pixel `(rx, ry)`. `None` for a zero-area triangle.
    pub fn new(frame: &PlaneFrame, values: [i64; 3], rx: i32, ry: i32) -> Option<Plane> {
        Some(PlaneSetup::new(frame, rx, ry)?.plane(values))
    }

    /// The value at the centre of pixel `(x, y)`.
    #[inline]
    pub fn at(&self, x: i32, y: i32) -> i64 {
        self.at_offset(x - self.rx, y - self.ry)
    }

    /// The pixel `(rx, ry)` the plane is referenced at; every plane of one
    /// [`PlaneSetup`] has the same.
    #[inline]
    pub fn reference(&self) -> (i32, i32) {
        (self.rx, self.ry)
    }

    /// [`Plane::at`] of the pixel `(dx, dy)` from the reference pixel
    /// ([`Plane::reference`]), for callers that sample several planes of one
    /// [`PlaneSetup`] at the same pixel: one offset for all.
    #[inline]
    pub fn at_offset(&self, dx: i32, dy: i32) -> i64 {
        self.base.wrapping_add(self.gx.wrapping_mul(dx.into())).wrapping_add(self.gy.wrapping_mul(dy.into()))
    }

    /// [`Plane::at`] modulo 2^32 (its low 32 bits), for accumulators whose
    /// samples are known to fit 32 bits: 32-bit products instead of 64-bit.
    #[inline]
    pub fn at_low32(&self, x: i32, y: i32) -> u32 {
        let (dx, dy) = ((x - self.rx) as u32, (y - self.ry) as u32);
        let g = |g: i64, d: u32| (g as u32).wrapping_mul(d);
        (self.base as u32).wrapping_add(g(self.gx, dx)).wrapping_add(g(self.gy, dy))
    }

    /// Increment per pixel to the right.
    #[inline]
    pub fn step_x(&self) -> i64 {
        self.gx
    }

    /// Multiplies the plane's values by `2^s` modulo 2^64 (`s < 64`, in
    /// place): its [`Plane::at`] and [`Plane::step_x`] become exactly the
    /// old ones shifted left by `s`, the bits above 64 dropped, as
    /// multiplying by `2^s` commutes with the wrapping sums and products
    /// `at` takes. Done once per triangle instead of at each span's start.
    #[inline]
    pub fn mul_pow2_wrapping(&mut self, s: u32) {
        (self.base, self.gx, self.gy) = (self.base << s, self.gx << s, self.gy << s);
    }
}

/// The part of plane set-up shared by every value of one triangle: the
/// determinant (prepared once for exact division, [`divide`]), the
/// edge vectors and the reference pixel. Planes made from it are exactly those
/// of [`Plane::new`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneSetup {
    ex: (i32, i32),
    ey: (i32, i32),
    /// Reference pixel centre relative to vertex 0, internal units.
    p: (i32, i32),
    det: i64,
    div: Divisor,
    shift: u32,
    /// Bits of the largest `|e|`, and of the larger of `|px|`, `|py|` plus one.
    ebits: u32,
    pbits: u32,
    /// Values whose differences have at most this many bits take the `i64`
    /// path with no check on their numerators ([`PlaneSetup::plane`]).
    dlimit: u32,
    rx: i32,
    ry: i32,
    /// Whether planes need `gx` and `gy` ([`PlaneSetup::sampled_only_on`]).
    need: (bool, bool),
}

impl PlaneSetup {
    /// `None` for a zero-area triangle. Inlined: built in place (returning
    /// its 100-odd bytes is a `memcpy` call on Cortex-M).
    #[inline(always)]
    pub fn new(frame: &PlaneFrame, rx: i32, ry: i32) -> Option<PlaneSetup> {
        let [(x0, y0), (x1, y1), (x2, y2)] = frame.v;
        // Frames are made of snapped vertices, |2·v| ≤ 2^29: the edge
        // vectors (below 2^30) and the reference offset (below 2^30 plus
        // 4096 pixels of at most 2^9 units) fit i32, and 32-bit arithmetic
        // is what Cortex-M does in one instruction.
        let d = |a: i64, b: i64| (a - b) as i32;
        let (ex, ey) = ((d(y2, y0), d(y1, y0)), (d(x1, x0), d(x2, x0)));
        let w = |a: i32, b: i32| a as i64 * b as i64;
        let det = w(ey.0, ex.0) - w(ey.1, ex.1);
        if det == 0 {
            return None;
        }
        let one = 1i64 << frame.shift;
        let half = one >> 1;
        // Reference pixel centre relative to vertex 0, internal units.
        let p = ((rx as i64 * one + half - x0) as i32, (ry as i64 * one + half - y0) as i32);
        // Every quotient is by `det`: with the edge vectors negated along
        // with a negative `det` (the same ratios), the divisor is positive.
        let (ex, ey, det) = if det < 0 { ((-ex.0, -ex.1), (-ey.0, -ey.1), -det) } else { (ex, ey, det) };
        let emax = ex.0.unsigned_abs() | ex.1.unsigned_abs() | ey.0.unsigned_abs() | ey.1.unsigned_abs();
        // |nx·px + ny·py| < 2^(nbits + pbits).
        let pbits = bits((p.0.unsigned_abs() | p.1.unsigned_abs()) as u64) + 1;
        let div = Divisor::new(det as u64);
        let need = (true, true);
        let ebits = bits(emax as u64);
        // dbits + ebits + 1 + max(shift, pbits) ≤ 63 (see `plane`).
        let dlimit = 62u32.saturating_sub(ebits + frame.shift.max(pbits));
        Some(PlaneSetup { ex, ey, p, det, div, shift: frame.shift, ebits, pbits, dlimit, rx, ry, need })
    }

    /// Planes made from now on will be sampled only along the span of `len`
    /// pixels from `(x, y)` (a triangle with one covered span in the band):
    /// a gradient the samples never use (`gy` off the reference row, `gx`
    /// for one pixel in the reference column) is left 0 and costs no
    /// division. The other values are those of [`PlaneSetup::plane`], so the
    /// samples are too.
    #[inline]
    pub fn sampled_only_on(&mut self, x: i32, y: i32, len: u32) {
        self.need = (len > 1 || x != self.rx, y != self.ry);
    }

    /// The plane through `values` (|v| ≤ 2^56) at the vertices.
    #[inline]
    pub fn plane(&self, values: [i64; 3]) -> Plane {
        let mut p = Plane::default();
        self.plane_into(values, &mut p);
        p
    }

    /// [`PlaneSetup::plane`] written to `out`: in place where the caller
    /// keeps its planes (returning one is a copy through the stack).
    pub fn plane_into(&self, values: [i64; 3], out: &mut Plane) {
        *out = self.plane_value(values);
    }

    #[inline(always)]
    fn plane_value(&self, values: [i64; 3]) -> Plane {
        let (d1, d2) = (values[1] - values[0], values[2] - values[0]);
        if d1 | d2 == 0 {
            // Constant (a colour channel equal at the three vertices, common
            // on small triangles): every numerator is 0, and so is every
            // quotient.
            return Plane { base: values[0], gx: 0, gy: 0, rx: self.rx, ry: self.ry };
        }
        let (ex, ey, (px, py)) = (self.ex, self.ey, self.p);
        // Exact in i64 when the magnitudes allow (checked on bit lengths, as
        // `checked_mul` costs much more on Cortex-M); divisions then go by
        // the reciprocal, far cheaper than an i64 (let alone i128) library
        // division. |d·e| < 2^(dbits + ebits); with that ≤ 2^62, |nx|, |ny|
        // < 2^nbits ≤ 2^63, and the numerators below are < 2^63.
        let dbits = bits(d1.unsigned_abs() | d2.unsigned_abs());
        let m = |d: i64, e: i32| d * e as i64;
        let n = || (m(d1, ex.0) - m(d2, ex.1), m(d2, ey.0) - m(d1, ey.1));
        let fast = if dbits <= self.dlimit {
            // |nx|, |ny| < 2^(dbits + ebits + 1): the check below holds a
            // priori (`dlimit`), as it does for every plane of a small triangle.
            Some(n())
        } else {
            (dbits + self.ebits <= 62).then(n).filter(|&(nx, ny)| {
                bits(nx.unsigned_abs() | ny.unsigned_abs()) + self.shift.max(self.pbits) <= 63
            })
        };
        let (gx, gy, off) = if let Some((nx, ny)) = fast {
            let gx = if self.need.0 { self.div.div_round(nx << self.shift) } else { 0 };
            let gy = if self.need.1 { self.div.div_round(ny << self.shift) } else { 0 };
            (gx, gy, self.div.div_round(m(nx, px) + m(ny, py)))
        } else {
            self.plane_long(d1, d2)
        };
        Plane { base: values[0].wrapping_add(off), gx, gy, rx: self.rx, ry: self.ry }
    }

    /// `(gx, gy, offset)` of [`PlaneSetup::plane`] beyond its `i64` fast
    /// path: [`PlaneSetup::plane_split`], else [`PlaneSetup::plane_wide`].
    /// Out of line and cold, as the `i128` set-up was alone: the common
    /// path's code stays as it was (an inlined call here cost the standard
    /// scene's frame 0.5 % at `S = 4`).
    #[cold]
    #[inline(never)]
    fn plane_long(&self, d1: i64, d2: i64) -> (i64, i64, i64) {
        self.plane_split(d1, d2).unwrap_or_else(|| self.plane_wide(d1, d2))
    }

    /// `(gx, gy, offset)` of [`PlaneSetup::plane`] where the numerators
    /// `nx`, `ny` fit `i64` but their products with `2^shift` or the
    /// reference offset do not (deep subpixel precision: the standard
    /// scene's perspective-correct planes at `S = 8`), without `i128`:
    /// with `n = q·det + r` (floor division, `0 ≤ r < det`),
    /// `n·k = q·k·det + r·k`, and `r·k` fits. So each quotient is `q·k` plus
    /// the floor division of the small remainder term, rounded as
    /// `div_round_i128` rounds (ties away from zero: `+1` when `2r > det`,
    /// or `2r = det` with a non-negative quotient). `None` where a bound
    /// below fails; the values are then [`PlaneSetup::plane_wide`]'s.
    #[inline]
    fn plane_split(&self, d1: i64, d2: i64) -> Option<(i64, i64, i64)> {
        let dbits = bits(d1.unsigned_abs() | d2.unsigned_abs());
        // |n| < 2^63; r < det < 2^(2·ebits + 1), so r·2^shift and
        // r·p (|p| < 2^(pbits − 1)) stay below 2^61.
        if dbits + self.ebits > 62 || 2 * self.ebits + 2 + self.shift.max(self.pbits) > 62 {
            return None;
        }
        let (ex, ey, (px, py)) = (self.ex, self.ey, self.p);
        let m = |d: i64, e: i32| d * e as i64;
        let (nx, ny) = (m(d1, ex.0) - m(d2, ex.1), m(d2, ey.0) - m(d1, ey.1));
        let ((qx, rx), (qy, ry)) = (self.div.div_floor_rem(nx), self.div.div_floor_rem(ny));
        // q·2^shift and q·p below 2^61: every sum below fits, and each
        // result is the exact (in-range) quotient.
        if bits(qx.unsigned_abs() | qy.unsigned_abs()) + self.shift.max(self.pbits) > 61 {
            return None;
        }
        let det = self.det;
        let round = |q: i64, r: i64| q + i64::from(2 * r > det || (2 * r == det && q >= 0));
        let scaled = |q: i64, r: i64| {
            let (q2, r2) = self.div.div_floor_rem(r << self.shift);
            round((q << self.shift) + q2, r2)
        };
        let gx = if self.need.0 { scaled(qx, rx) } else { 0 };
        let gy = if self.need.1 { scaled(qy, ry) } else { 0 };
        let (q3, r3) = self.div.div_floor_rem(rx * px as i64 + ry * py as i64);
        Some((gx, gy, round(qx * px as i64 + qy * py as i64 + q3, r3)))
    }

    /// `(gx, gy, offset)` of [`PlaneSetup::plane`] in `i128`, for values
    /// whose products do not fit `i64`. Out of line: its 128-bit divisions
    /// would otherwise make the common path spill its registers.
    #[cold]
    #[inline(never)]
    fn plane_wide(&self, d1: i64, d2: i64) -> (i64, i64, i64) {
        let (ex, ey, (px, py)) = (self.ex, self.ey, self.p);
        let w = |a: i64, b: i32| a as i128 * b as i128;
        let nx = w(d1, ex.0) - w(d2, ex.1);
        let ny = w(d2, ey.0) - w(d1, ey.1);
        let det = self.det as i128;
        let one = 1i128 << self.shift;
        // Truncation to i64 wraps; evaluation is modular (module docs).
        let gx = div_round_i128(nx * one, det) as i64;
        let gy = div_round_i128(ny * one, det) as i64;
        (gx, gy, div_round_i128(nx * px as i128 + ny * py as i128, det) as i64)
    }
}

/// Bit length of `v`.
#[inline]
fn bits(v: u64) -> u32 {
    64 - v.leading_zeros()
}

/// `n / d` rounded to nearest (ties away from zero); `d != 0`.
fn div_round_i128(n: i128, d: i128) -> i128 {
    let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
    if n >= 0 { (n + d / 2) / d } else { -((-n + d / 2) / d) }
}

#[cfg(test)]
mod tests;
