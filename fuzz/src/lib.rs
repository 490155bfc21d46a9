//! Shared pieces of the fuzz targets: a byte reader that turns libFuzzer's
//! input into parameters (biased towards the documented limits, ties and
//! non-finite values), and minimal exact references written from the
//! documented rules, independent of `src/`:
//!
//! * [`exact_covers`]: the top-left fill rule at pixel centres, in `i128`;
//! * [`line_reference`]: the midpoint-line rule of `microraster::line`, in `i128`;
//! * [`snap_reference`]: round-to-nearest-even snapping with the range check.
//!
//! and what the 3D targets share: [`each_path!`], [`is_f32`],
//! [`signed_area2`], [`clip_matrix_f64`].

use microraster::ClipRect;
use microraster::math::{Mat4, Scalar};
use microraster::raster3d::ScreenTriangle;

/// Reads parameters from the fuzzer's bytes; past the end every read is 0.
pub struct Input<'a> {
    data: &'a [u8],
}

impl<'a> Input<'a> {
    pub fn new(data: &'a [u8]) -> Self {
        Input { data }
    }

    pub fn u8(&mut self) -> u8 {
        match self.data.split_first() {
            Some((&b, rest)) => {
                self.data = rest;
                b
            }
            None => 0,
        }
    }

    pub fn bool(&mut self) -> bool {
        self.u8() & 1 == 1
    }

    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }

    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }

    pub fn i32(&mut self) -> i32 {
        self.u32() as i32
    }

    /// One of `opts` (`opts` non-empty).
    pub fn pick<T: Copy>(&mut self, opts: &[T]) -> T {
        opts[self.u8() as usize % opts.len()]
    }

    /// An `f32`: raw bits, or a value from a list of extremes (NaN, ±inf,
    /// ±0, subnormals, ±f32::MAX, ±f32::MAX/16, powers of two around the
    /// subpixel range, and small values).
    pub fn f32(&mut self) -> f32 {
        const SPECIAL: [f32; 24] = [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            f32::MIN_POSITIVE,
            1.0e-45,
            f32::MAX,
            f32::MIN,
            f32::MAX / 16.0,
            f32::EPSILON,
            268435456.0,
            -268435456.0,
            1.0e7,
            1.0e-7,
            65536.0,
            1.0 / 65536.0,
            32768.0,
            -32768.0,
            1.0001,
            0.9999,
        ];
        match self.u8() % 4 {
            0 => f32::from_bits(self.u32()),
            1 => SPECIAL[self.u8() as usize % SPECIAL.len()],
            2 => self.i32() as f32 / 65536.0,    // moderate, 16 fraction bits
            _ => (self.u8() as i8) as f32 / 8.0, // small, on a coarse grid
        }
    }

    /// A subpixel coordinate for `S`: the range limit ±0..2, anywhere in
    /// range, beyond it, pixel centres and corners near the frame, near the
    /// fast-path extent, or raw.
    pub fn coord(&mut self, s: u32) -> i64 {
        let one = 1i64 << s;
        let lim = 1i64 << 28;
        match self.u8() % 9 {
            0 => i64::from(self.i32()),
            1 => {
                let d = i64::from(self.u8() % 5) - 2;
                if self.bool() { lim + d } else { -lim - d }
            }
            2 => i64::from(self.i32()) % (lim + 1),
            3 => (i64::from(self.u8() as i8) << s) + one / 2, // pixel centres
            4 => i64::from(self.u8() as i8) << s,             // pixel corners
            5 => i64::from(self.u16() as i16),                // around the frame, any fraction
            6 => {
                let e = microraster::edge::fast_path_extent_px(s) * one;
                e + i64::from(self.u8() as i8)
            }
            7 => (i64::from(self.u16() % 4200) << s) + i64::from(self.u8() % 4) * (one / 4).max(1),
            _ => i64::from(self.u8() as i8) * one * 64 + i64::from(self.u8() as i8),
        }
    }

    /// A clip rectangle of at most `max` × `max` pixels: near `(px, py)`
    /// (pixels), anywhere in the frame, or from raw (clamped) values.
    pub fn clip(&mut self, px: i64, py: i64, max: i32) -> ClipRect {
        let (w, h) = (i32::from(self.u8()) % (max + 1), i32::from(self.u8()) % (max + 1));
        let (x0, y0) = match self.u8() % 4 {
            0 | 1 => {
                let c = |v: i64, d: u8| (v - i64::from(d % 64)).clamp(-100, 5000) as i32;
                (c(px, self.u8()), c(py, self.u8()))
            }
            2 => (i32::from(self.u16() % 4200) - 50, i32::from(self.u16() % 4200) - 50),
            _ => (self.i32(), self.i32()),
        };
        ClipRect::new(x0, y0, x0.saturating_add(w), y0.saturating_add(h))
    }
}

/// One snapped triangle's edges in internal units (`2^-(S+1)` px): each edge
/// `(ex, ey, k, tie)`, positive inside, `tie` true for a top or left edge.
pub struct ExactTriangle {
    edges: [(i128, i128, i128, bool); 3],
    half: i128,
    pub clockwise: bool,
}

impl ExactTriangle {
    /// `None` for zero area. `v` in subpixel units at `s` bits.
    pub fn new(v: [(i32, i32); 3], s: u32) -> Option<Self> {
        let p = v.map(|q| (2 * i128::from(q.0), 2 * i128::from(q.1)));
        let cross = |u: (i128, i128), w: (i128, i128)| u.0 * w.1 - u.1 * w.0;
        let sub = |u: (i128, i128), w: (i128, i128)| (u.0 - w.0, u.1 - w.1);
        let area2 = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        if area2 == 0 {
            return None;
        }
        let edges = [0, 1, 2].map(|i| {
            let (a, b, c) = (p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
            let d = sub(b, a);
            let horizontal = d.1 == 0;
            // Top: horizontal with the third vertex below (y down). Left: the
            // third vertex lies to the right of the edge at its own height.
            let top = horizontal && c.1 > a.1;
            let dd = (c.0 - a.0) * d.1 - d.0 * (c.1 - a.1);
            let left = !horizontal && (dd > 0) == (d.1 > 0);
            let inside = cross(d, sub(c, a)).signum();
            (-inside * d.1, inside * d.0, inside * (d.1 * a.0 - d.0 * a.1), top || left)
        });
        Some(ExactTriangle { edges, half: 1i128 << s, clockwise: area2 > 0 })
    }

    /// Whether the centre of pixel `(x, y)` is covered (top-left rule).
    pub fn covers(&self, x: i32, y: i32) -> bool {
        let (cx, cy) = ((2 * i128::from(x) + 1) * self.half, (2 * i128::from(y) + 1) * self.half);
        self.edges.iter().all(|&(ex, ey, k, tie)| {
            let v = ex * cx + ey * cy + k;
            v > 0 || (v == 0 && tie)
        })
    }

    /// Exact barycentric weights of the centre of `(x, y)` as `f64`
    /// (`λ_i` for vertex `i`); the numerators are exact `i128`.
    pub fn bary(v: [(i32, i32); 3], s: u32, x: i32, y: i32) -> [f64; 3] {
        let p = v.map(|q| (2 * i128::from(q.0), 2 * i128::from(q.1)));
        let c = ((2 * i128::from(x) + 1) << s, (2 * i128::from(y) + 1) << s);
        let cr = |a: (i128, i128), b: (i128, i128), q: (i128, i128)| {
            (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0)
        };
        let det = cr(p[0], p[1], p[2]) as f64;
        [cr(p[1], p[2], c) as f64 / det, cr(p[2], p[0], c) as f64 / det, cr(p[0], p[1], c) as f64 / det]
    }
}

/// The documented line rule (`microraster::line` module docs), evaluated
/// directly in exact `i128` arithmetic at every major index of `clip`.
pub fn line_reference(a: (i32, i32), b: (i32, i32), s: u32, clip: ClipRect) -> Vec<(i32, i32)> {
    let (dx, dy) = (i128::from(b.0) - i128::from(a.0), i128::from(b.1) - i128::from(a.1));
    let x_major = dx.abs() >= dy.abs();
    let (ua, va, ub, du, dv) = if x_major { (a.0, a.1, b.0, dx, dy) } else { (a.1, a.0, b.1, dy, dx) };
    let (ua, va, ub) = (i128::from(ua), i128::from(va), i128::from(ub));
    let (c0, c1, k0, k1) = if x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let mut out = Vec::new();
    if du == 0 {
        return out;
    }
    let majors: Vec<i32> = if du > 0 { (c0..c1).collect() } else { (c0..c1).rev().collect() };
    for m in majors {
        let c = (2 * i128::from(m) + 1) << s; // doubled centre
        let inside = if du > 0 { 2 * ua <= c && c < 2 * ub } else { 2 * ub < c && c <= 2 * ua };
        if !inside {
            continue;
        }
        let (n, q) = (2 * va * du + dv * (c - 2 * ua), (2 * du) << s);
        let minor = if q < 0 { (-n).div_euclid(-q) } else { n.div_euclid(q) }; // floor(n / q)
        if (i128::from(k0)..i128::from(k1)).contains(&minor) {
            let minor = minor as i32;
            out.push(if x_major { (m, minor) } else { (minor, m) });
        }
    }
    out
}

/// What snapping `v` to `s` subpixel bits must give: `None` for NaN/inf,
/// `Some(Err(()))` beyond ±2^28 subpixels, else the value rounded to
/// nearest, ties to even (computed exactly in `f64`: `v · 2^s` is exact).
pub fn snap_reference(v: f32, s: u32) -> Option<Result<i64, ()>> {
    if !v.is_finite() {
        return None;
    }
    let scaled = f64::from(v) * f64::from(1u32 << s);
    let r = scaled.round_ties_even();
    Some(if r.abs() > f64::from(1u32 << 28) { Err(()) } else { Ok(r as i64) })
}

/// A `w × h` frame that accepts each pixel at most once and nothing outside
/// it (the fuzz targets' "sent exactly once" and "`Drawable` draws each pixel
/// once" checks): a pixel drawn twice or off the frame panics.
pub struct OnceFrame<C> {
    /// Width in pixels.
    pub w: i32,
    /// Height in pixels.
    pub h: i32,
    /// Row-major pixels, `None` where nothing was drawn.
    pub px: Vec<Option<C>>,
}

impl<C: embedded_graphics_core::pixelcolor::PixelColor> OnceFrame<C> {
    /// An empty frame.
    pub fn new(w: i32, h: i32) -> Self {
        OnceFrame { w, h, px: vec![None; (w * h) as usize] }
    }
}

impl<C> embedded_graphics_core::geometry::OriginDimensions for OnceFrame<C> {
    fn size(&self) -> embedded_graphics_core::geometry::Size {
        embedded_graphics_core::geometry::Size::new(self.w as u32, self.h as u32)
    }
}

impl<C: embedded_graphics_core::pixelcolor::PixelColor> embedded_graphics_core::draw_target::DrawTarget
    for OnceFrame<C>
{
    type Color = C;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = embedded_graphics_core::Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for embedded_graphics_core::Pixel(p, c) in pixels {
            assert!(p.x >= 0 && p.y >= 0 && p.x < self.w && p.y < self.h, "pixel {p:?} outside the frame");
            let i = (p.y * self.w + p.x) as usize;
            assert!(self.px[i].is_none(), "pixel {p:?} drawn twice");
            self.px[i] = Some(c);
        }
        Ok(())
    }
}

/// Calls `$run::<T, S>(inp)`, `inp` the `&mut Input` `$inp`, for the
/// numeric path and subpixel precision that its next byte picks: `f32` or
/// `Fx`, each at `S` = 0, 4 or 8.
#[macro_export]
macro_rules! each_path {
    ($inp:expr, $run:ident) => {{
        let inp: &mut $crate::Input = $inp;
        match inp.u8() % 6 {
            0 => $run::<f32, 0>(inp),
            1 => $run::<f32, 4>(inp),
            2 => $run::<f32, 8>(inp),
            3 => $run::<::microraster::math::Fx, 0>(inp),
            4 => $run::<::microraster::math::Fx, 4>(inp),
            _ => $run::<::microraster::math::Fx, 8>(inp),
        }
    }};
}

/// Whether `T` is `f32` (it holds NaN; `Fx` does not).
pub fn is_f32<T: Scalar>() -> bool {
    T::from_f32(f32::NAN).to_f32().is_nan()
}

/// Twice the signed area of `t`'s snapped corners, exactly.
pub fn signed_area2<const S: u32>(t: &ScreenTriangle<S>) -> i64 {
    let p = t.v.map(|v| (i64::from(v.pos.x()), i64::from(v.pos.y())));
    (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
}

/// `proj · view · model` in `f64` (columns, from the matrices as the path
/// holds them), and the same product of their entries' absolute values: row
/// `r` of the second, applied to `|x|, |y|, |z|, 1`, bounds the terms of a
/// point's clip coordinate `r`, the scale of the path's rounding.
pub fn clip_matrix_f64<T: Scalar>(
    proj: Mat4<T>,
    view: Mat4<T>,
    model: Mat4<T>,
) -> ([[f64; 4]; 4], [[f64; 4]; 4]) {
    let cols = |m: Mat4<T>| m.to_f32().map(|c| c.map(f64::from));
    let mul = |a: [[f64; 4]; 4], b: [[f64; 4]; 4]| -> [[f64; 4]; 4] {
        core::array::from_fn(|c| core::array::from_fn(|r| (0..4).map(|k| a[k][r] * b[c][k]).sum()))
    };
    let abs = |a: [[f64; 4]; 4]| a.map(|c| c.map(f64::abs));
    let (p, v, m) = (cols(proj), cols(view), cols(model));
    (mul(p, mul(v, m)), mul(abs(p), mul(abs(v), abs(m))))
}
