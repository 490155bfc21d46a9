//! Tiny triangles in the fast tier ([`Precision::Fast`](crate::raster3d::Precision)):
//! the same coverage walk as the exact tier's [`draw`](super::draw), with
//! depth and colour as weighted sums of the covered centre's edge
//! functions, each value two multiply-adds and a shift instead of exact
//! sums divided per pixel.
//!
//! # What is computed, and its error
//! At a covered centre the weights `w_i = E_i` (unbiased edge functions,
//! summing to `det < 2^16`) give a value `V = Σ w_i·v_i / det`. Here each
//! `v_i / det` is prepared once per triangle as a whole `K_i`, rounded to
//! nearest at a scale `2^s`, so `Σ w_i·K_i` is `V·2^s` within
//! `Σ w_i/2 = det/2`, and `u32` arithmetic holds it (the sum is below
//! `2^32` by the choice of `s`; with `w_0 = det − w_1 − w_2` it is
//! `w_1·(K_1 − K_0) + w_2·(K_2 − K_0) + det·K_0`, exact modulo 2^32).
//!
//! * **Depth**: `v_i` the vertex depth in `2^-16` steps less the smallest
//!   of the three, `s` as large as keeps their range below `2^31`: `V`
//!   within `det/2^(s+1) + 1` units (`< 2^-16 + 2^-(s+1)` steps), so the
//!   stored code, rounded half up, is within one of the exact tier's
//!   (that one within `1/2 + 2^-7` of `V`).
//! * **Colour**: a channel whose three vertex values lie within 2 of each
//!   other (most of a lit mesh's tiny triangles, in every channel) is the
//!   middle of that range at every pixel: the exact tier's channel, a
//!   rounding of a value inside the range, is within one of it. Otherwise
//!   `v_i` the channel, `s = 23`: within `2^-8` before rounding half up,
//!   so within one of the exact tier's. Perspective-correct: where the
//!   vertices' `1/w` differ so little that the screen-linear value is within
//!   `Δ ≤ 1/2` of the perspective-correct one (`perspective`'s bound), the
//!   screen-linear value, within `1/2 + 2^-8` before rounding, so within one;
//!   otherwise the exact tier's own perspective-correct colour.

use super::perspective::{PerspFactors, shade_perspective};
use super::super::{DepthRule, Interpolation, LessWrite, ScreenTriangle, depth_steps};
use crate::Interpolate;
use crate::band::BandView;
use crate::depth::{DepthFormat, DepthState};
use crate::edge::small::Small;

/// Scale of the colour weights: a channel of up to 255 times `2^23`, plus
/// the rounding, stays below `2^31`.
const COLOR_SHIFT: u32 = 23;

/// Draws `tri`, whose coverage walk is `small` (as the exact tier's
/// [`draw`](super::draw) takes it), in the fast tier.
#[inline(always)]
pub(crate) fn draw<C, F, M, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    small: &Small,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    if F::ENABLED && state == DepthState::LESS_WRITE {
        draw_with::<C, F, M, _, S, W>(tri, small, color, depth, LessWrite);
    } else {
        draw_with::<C, F, M, _, S, W>(tri, small, color, depth, state);
    }
}

#[inline(always)]
fn draw_with<C, F, M, D, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    small: &Small,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: D,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    D: DepthRule,
{
    let det = small.det() as u32;
    let bias = small.biases().map(|b| b as u32);
    let z = if F::ENABLED { Weighted::depth::<F, S>(tri, det, bias) } else { Weighted::default() };
    let y0 = color.y0();
    // The colour's set-up, made at the first pixel that passes its depth
    // test (none for a hidden triangle).
    let mut shade = None;
    small.for_each_centre(|x, y, e| {
        let e = e.map(|e| e as u32);
        let Some(p) = color.row_mut(y).and_then(|r| r.get_mut(x as usize)) else { return };
        if F::ENABLED {
            let Some(slot) = depth.get_mut((y - y0) as usize).and_then(|r| r.get_mut(x as usize)) else {
                return;
            };
            let code = z.depth_code(e);
            if !state.test().passes(code, F::to_u32(*slot)) {
                return;
            }
            if state.write() {
                *slot = F::from_u32(code);
            }
        }
        *p = shade.get_or_insert_with(|| FastShade::<C>::new::<M, S>(tri, det, bias)).at(tri, e, bias, det);
    });
}

/// A value of the triangle as `(e_1·a + e_2·b + c) >> s` at a centre of
/// biased edge functions `e` (module docs; `c` holds the biases, the
/// depth's base and the rounding).
#[derive(Clone, Copy, Default)]
struct Weighted {
    a: u32,
    b: u32,
    c: u32,
    s: u32,
    /// Depth: the smallest vertex depth plus half a step, in `2^-16` steps.
    base: u32,
}

impl Weighted {
    /// Weights of vertex values `v` (non-negative, `Σ w_i·v_i / det` below
    /// `2^32 / 2^s − 1`) at scale `2^s`, plus `round` once.
    #[inline(always)]
    fn new(v: [u32; 3], s: u32, round: u32, det: u32, bias: [u32; 3]) -> Self {
        // v_i·2^s + det/2 < 2^32 (callers' bounds): one 32-bit division each.
        let k = v.map(|v| ((v << s) + det / 2) / det);
        let (a, b) = (k[1].wrapping_sub(k[0]), k[2].wrapping_sub(k[0]));
        let c = det.wrapping_mul(k[0]).wrapping_add(bias[1].wrapping_mul(a)).wrapping_add(bias[2].wrapping_mul(b));
        Weighted { a, b, c: c.wrapping_add(round), s, base: 0 }
    }

    /// The depth weights of `tri` in format `F` (at most 16 bits: a vertex
    /// depth is below `2^32` in `2^-16` steps).
    #[inline(always)]
    fn depth<F: DepthFormat, const S: u32>(tri: &ScreenTriangle<S>, det: u32, bias: [u32; 3]) -> Self {
        let d = tri.v.map(|v| depth_steps(v.depth, F::MAX) as u32);
        let lo = d[0].min(d[1]).min(d[2]);
        let range = d[0].max(d[1]).max(d[2]) - lo;
        // range·2^s below 2^31 (or, at s = 0, below 2^32 − 2^16): with the
        // rounding term below 2^15, every sum stays within u32.
        let s = range.leading_zeros().saturating_sub(1);
        let mut w = Self::new(d.map(|d| d - lo), s, 0, det, bias);
        w.base = lo + (1 << 15);
        w
    }

    #[inline(always)]
    fn sum(&self, e: [u32; 3]) -> u32 {
        e[1].wrapping_mul(self.a).wrapping_add(e[2].wrapping_mul(self.b)).wrapping_add(self.c)
    }

    /// The stored depth code at biased edge functions `e`.
    #[inline(always)]
    fn depth_code(&self, e: [u32; 3]) -> u32 {
        ((self.sum(e) >> self.s) + self.base) >> 16
    }

    /// The rounded channel at biased edge functions `e`.
    #[inline(always)]
    fn channel(&self, e: [u32; 3]) -> u8 {
        (self.sum(e) >> COLOR_SHIFT) as u8
    }
}

/// The fast tier's colour of a tiny triangle (module docs).
enum FastShade<C> {
    /// One colour for every pixel: flat, or every channel within 2.
    Const(C),
    /// Screen-linear weights per channel (`None` for a channel the colour
    /// type lacks).
    Linear([Option<Weighted>; 3]),
    /// The exact tier's perspective-correct colour.
    Perspective(PerspFactors),
}

impl<C: Interpolate> FastShade<C> {
    #[inline(never)]
    fn new<M: Interpolation, const S: u32>(tri: &ScreenTriangle<S>, det: u32, bias: [u32; 3]) -> Self {
        if tri.flat {
            return FastShade::Const(C::from_channels(tri.v[0].color));
        }
        let max = C::CHANNEL_MAX;
        let (mut lo, mut hi) = ([0u8; 3], [0u8; 3]);
        for k in 0..3 {
            let c = tri.v.map(|v| v.color[k]);
            (lo[k], hi[k]) = (c[0].min(c[1]).min(c[2]), c[0].max(c[1]).max(c[2]));
        }
        let spread = (0..3).map(|k| if max[k] == 0 { 0 } else { hi[k] - lo[k] }).max().unwrap_or(0);
        if spread <= 2 {
            // The middle of each channel's range (module docs).
            return FastShade::Const(C::from_channels([0, 1, 2].map(|k| lo[k] + (hi[k] - lo[k]) / 2)));
        }
        if M::PERSPECTIVE {
            // Δ = spread/2 · (a_max − a_min)/a_min ≤ 1/2 (`perspective`'s
            // bound, on the unnormalised 1/w: only their ratios enter).
            let a = tri.v.map(|v| u64::from(v.inv_w));
            let (a_min, a_max) = (a[0].min(a[1]).min(a[2]), a[0].max(a[1]).max(a[2]));
            if u64::from(spread) * (a_max - a_min) > a_min {
                return FastShade::Perspective(PerspFactors::new::<C, S>(tri, det));
            }
        }
        let weights = |k: usize| {
            (max[k] > 0)
                .then(|| Weighted::new(tri.v.map(|v| u32::from(v.color[k])), COLOR_SHIFT, 1 << (COLOR_SHIFT - 1), det, bias))
        };
        FastShade::Linear([weights(0), weights(1), weights(2)])
    }

    /// The colour at biased edge functions `e`.
    #[inline(always)]
    fn at<const S: u32>(&self, tri: &ScreenTriangle<S>, e: [u32; 3], bias: [u32; 3], det: u32) -> C {
        match self {
            FastShade::Const(c) => *c,
            FastShade::Linear(w) => {
                C::from_channels([0, 1, 2].map(|k| w[k].as_ref().map_or(0, |w| w.channel(e))))
            }
            FastShade::Perspective(f) => {
                shade_perspective::<C, S>(tri, f, [0, 1, 2].map(|i| e[i] + bias[i]), det)
            }
        }
    }
}
