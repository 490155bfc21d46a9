//! Tiny triangles (most of a dense mesh's): depth and colour (flat, affine
//! or perspective-correct) computed at each covered centre from its
//! barycentric coordinates, with no plane set-up.
//!
//! # Why
//! A plane costs a determinant reciprocal and up to three exact divisions
//! per triangle and band (`attr`), and a span start per row; a triangle of
//! one or two pixels uses each plane once or twice. Here a value costs one
//! short division per covered pixel instead.
//!
//! # What is computed
//! A small triangle ([`Small`]) with `det < 2^16` (twice its area in
//! internal units of `2^-(S+1)` px: below 32 px² at `S = 4`) is drawn here.
//! At a covered centre its unbiased edge functions `E_i` (edge `i` opposite
//! vertex `i`) are integers in `[0, det]` that sum to `det`, and `E_i / det`
//! is exactly the barycentric coordinate of vertex `i`. A value is
//! `Σ E_i·v_i / det`:
//!
//! * **Depth** (formats of up to 16 bits): `v_i = ⌊d_i / 2^8⌋`, `d_i` the
//!   vertex depth in `2^-16` steps ([`depth_steps`], itself within
//!   `2^-15` steps of `depth·MAX/(2^32 − 1)`), so `v_i < 2^24` and the sum
//!   `< det·2^24 < 2^40` (`u64`); its quotient by `det` is floored and
//!   the stored code is that rounded half up (one 16-bit quotient,
//!   [`depth_code`]). Against
//!   the exact plane through the snapped vertices' depths: vertex values
//!   `< 2^-8 + 2^-15` low (a convex combination keeps that), the floor
//!   `< 2^-8`, the rounding `1/2`: `|stored − exact| < 1/2 + 2^-7 + 2^-15`,
//!   inside the plane path's `1/2 + 1/8 + 2^-16` (`raster3d` module docs).
//! * **Colour**, affine: `v_i` the channel values (`≤ 255`, exact), the sum
//!   `< det·2^8 < 2^24` (`u32`), rounded half up exactly: within `1/2` of
//!   the screen-linear value (the plane path: `1/2 + 2^-7`).
//! * **Colour**, perspective-correct: `Σ E_i·c_i·q_i / Σ E_i·q_i` with
//!   `q_i` the plane path's normalised `1/w`, rounded half up exactly, most
//!   pixels by a screen-linear shortcut with the same result
//!   ([`perspective`], where its bounds are derived).
//!
//! Both depend on the triangle and the pixel only, so any band height gives
//! the same pixels. Where the exact value lies within those bounds of a
//! rounding tie, a code or channel can differ by one from what the plane
//! path would store.
//!
//! Depth formats wider than 16 bits take the plane path.

use super::precision::Tier;
use super::{
    DEPTH_FRAC, DepthRule, Interpolation, LessWrite, ScreenTriangle, depth_steps, depth_steps_approx,
};
use crate::Interpolate;
use crate::band::BandView;
use crate::depth::{DepthFormat, DepthState};
use crate::edge::small::Small;
use crate::math::divisor::{divrem_small_quotient, mul_u16_u32};

mod fast;
mod perspective;
use fast::FastShade;
use perspective::{PerspFactors, shade_perspective};

/// Triangles with a determinant below this are drawn here (module docs).
const DET_LIMIT: i32 = 1 << 16;

/// Fraction bits of the vertex depths here.
const FRAC: u32 = 8;

/// Whether [`draw`] takes `small`: depth of at most 16 bits, and a
/// determinant below 2^16.
#[inline(always)]
pub(super) fn eligible<F: DepthFormat>(small: &Small) -> bool {
    F::BITS <= 16 && small.det() < DET_LIMIT
}

/// Draws `tri`, whose coverage walk is `small` ([`eligible`]), into the
/// band: each covered centre's depth tested against `depth` with `state`,
/// then its colour (flat, or Gouraud as `M` says; in tier `P`) written
/// where it passes.
#[inline(always)]
pub(super) fn draw<C, F, M, P, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    small: &Small,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    P: Tier,
{
    if F::ENABLED && state == DepthState::LESS_WRITE {
        draw_with::<C, F, M, P, _, S, W>(tri, small, color, depth, LessWrite);
    } else {
        draw_with::<C, F, M, P, _, S, W>(tri, small, color, depth, state);
    }
}

#[inline(always)]
fn draw_with<C, F, M, P, D, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    small: &Small,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: D,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    P: Tier,
    D: DepthRule,
{
    let det = small.det() as u32;
    let bias = small.biases().map(|b| b as u32);
    let dv = tri.v.map(|v| match (F::ENABLED, P::FAST) {
        (false, _) => 0,
        (true, false) => (depth_steps(v.depth, F::MAX) >> (DEPTH_FRAC - FRAC)) as u32,
        // Within 3 units of 2^-16 steps, so each dv within one of the
        // exact tier's: the value moves by at most 2^-8 steps.
        (true, true) => depth_steps_approx(v.depth, F::BITS) >> (DEPTH_FRAC - FRAC),
    });
    let y0 = color.y0();
    // Perspective-correct colour factors (the fast tier: its colour), made
    // at the first pixel that passes its depth test (none for a hidden
    // triangle).
    let mut persp = None;
    let mut fast = None;
    small.for_each_centre(|x, y, e| {
        // Edge i lies opposite vertex i: w_i / det is its barycentric coordinate.
        let w = [0, 1, 2].map(|i| e[i] as u32 + bias[i]);
        let Some(p) = color.row_mut(y).and_then(|r| r.get_mut(x as usize)) else { return };
        if F::ENABLED {
            let Some(slot) = depth.get_mut((y - y0) as usize).and_then(|r| r.get_mut(x as usize)) else {
                return;
            };
            // w_i ≤ det < 2^16: products of a 16- and a 24-bit value (two
            // 32-bit multiplies each on the Cortex-M0, not a library call).
            let n = mul_u16_u32(w[0], dv[0]) + mul_u16_u32(w[1], dv[1]) + mul_u16_u32(w[2], dv[2]);
            let code = depth_code(n, det);
            if !state.test().passes(code, F::to_u32(*slot)) {
                return;
            }
            if state.write() {
                *slot = F::from_u32(code);
            }
        }
        // The fast tier chooses a perspective-correct colour once per
        // triangle; its affine colour is the exact tier's (`fast` docs).
        let how = if P::FAST && M::PERSPECTIVE {
            *fast.get_or_insert_with(|| FastShade::new::<S>(tri))
        } else if M::PERSPECTIVE && !tri.flat {
            FastShade::Perspective
        } else {
            FastShade::Affine
        };
        *p = match how {
            FastShade::Const(c) => c,
            FastShade::Perspective => shade_perspective::<C, S>(
                tri,
                persp.get_or_insert_with(|| PerspFactors::new::<C, S>(tri, det)),
                w,
                det,
            ),
            FastShade::Affine => shade::<C, S>(tri, w, det),
        };
    });
}

/// The colour of `tri` (flat, or affine Gouraud) at the pixel whose
/// barycentric coordinates are `w / det` (module docs). Out of line: inlined into the
/// pixel loop, its work was hoisted into per-triangle set-up (the flat
/// colour, the sums strength-reduced into steps) that costs more than a
/// triangle of one or two pixels uses.
#[inline(never)]
fn shade<C: Interpolate, const S: u32>(tri: &ScreenTriangle<S>, w: [u32; 3], det: u32) -> C {
    if tri.flat {
        return C::from_channels(tri.v[0].color);
    }
    let max = C::CHANNEL_MAX;
    let channel = |k: usize| -> u8 {
        if max[k] == 0 {
            return 0;
        }
        let c = [0, 1, 2].map(|i| tri.v[i].color[k] as u32);
        let n = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
        channel_quotient(2 * n + det, 2 * det, max[k]) as u8
    };
    C::from_channels([channel(0), channel(1), channel(2)])
}

/// The stored depth code `⌊(⌊n / d⌋ + 2^7) / 2^8⌋` (the quotient rounded
/// half up to whole codes) for `0 < d < 2^16` and `n ≤ d·(2^16 − 1)·2^8`
/// (vertex depths of at most 16 bits), by one 16-bit quotient: with nested
/// floors it equals `⌊(n + 2^7·d) / (2^8·d)⌋ = ⌊⌊(n + 2^7·d) / 2^8⌋ / d⌋`,
/// and that inner value is below `d·2^16`. One division on ARMv7-M instead
/// of two; 16 restoring steps on the Cortex-M0 instead of 24.
#[inline(always)]
fn depth_code(n: u64, d: u32) -> u32 {
    let m = ((n + ((d as u64) << (FRAC - 1))) >> FRAC) as u32;
    divrem_small_quotient::<16>(m, d).0
}

/// `(⌊x / d⌋, x mod d)` for a channel of largest value `max`, with
/// `x < d·(max + 1)` and `0 < d < 2^17` (so the quotient is at most
/// `max`). Its restoring steps on the Cortex-M0 are as many as `max` has
/// bits (5 or 6 for RGB565, not 8); `max` is a colour type's constant, so
/// the choice folds away.
#[inline(always)]
fn channel_divrem(x: u32, d: u32, max: u8) -> (u32, u32) {
    match max {
        0..=31 => divrem_small_quotient::<5>(x, d),
        32..=63 => divrem_small_quotient::<6>(x, d),
        _ => divrem_small_quotient::<8>(x, d),
    }
}

/// [`channel_divrem`]'s quotient (the remainder, unused, folds away).
#[inline(always)]
fn channel_quotient(x: u32, d: u32, max: u8) -> u32 {
    channel_divrem(x, d, max).0
}

#[cfg(test)]
mod tests {
    use super::{channel_quotient, depth_code};

    /// The next value of a xorshift sequence.
    pub(super) fn next(seed: &mut u64) -> u64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        *seed
    }

    /// The one-quotient depth code is the floored quotient rounded half up
    /// to whole codes, over the whole range of 16-bit vertex depths.
    #[test]
    fn depth_code_is_the_rounded_quotient() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        for i in 0..300_000u32 {
            let seed = next(&mut seed);
            let d = ((seed >> 40) as u32 & 0xFFFF).max(1);
            let d = [d, 1, 0xFFFF, 2, d & 0xFF | 1][(i % 5) as usize];
            let top = d as u64 * 0xFFFF * 256; // n ≤ d·(2^16 − 1)·2^8
            let n = match i % 4 {
                0 => seed % (top + 1),
                1 => top,
                // Either side of a rounding tie of the quotient.
                2 => ((seed >> 20) % 0xFFFF * 256 + 128) * d as u64 - (seed & 1),
                _ => seed % (d as u64 * 8),
            };
            assert_eq!(depth_code(n, d) as u64, (n / d as u64 + 128) >> 8, "{n} / {d}");
        }
    }

    /// Channel quotients with as few steps as the channel's bits are the
    /// division, for every channel width up to 8 bits and the divisors the
    /// tiny path passes (`2·det`, below 2^17).
    #[test]
    fn channel_quotient_is_the_division() {
        let mut seed = 0x0C0_1022_u64;
        for i in 0..300_000u32 {
            let seed = next(&mut seed);
            let max = [1u8, 31, 63, 255, (seed >> 56) as u8 | 1][(i % 5) as usize];
            let d = ((seed >> 20) as u32 & 0x1FFFF).clamp(1, (1 << 17) - 2);
            let d = [d, 1, 2, (1 << 17) - 2][(i / 5 % 4) as usize];
            let top = d as u64 * (max as u64 + 1) - 1; // x < d·(max + 1)
            let x = match i % 3 {
                0 => seed % (top + 1),
                1 => top,
                _ => (seed >> 8) % (max as u64 + 1) * d as u64,
            } as u32;
            assert_eq!(channel_quotient(x, d, max), x / d, "{x} / {d}, max {max}");
        }
    }
}
