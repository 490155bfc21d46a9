//! The perspective-correct Gouraud colour of a tiny triangle at a covered
//! centre, from the parent module's barycentric weights `E_i` (summing to
//! `det`): `Σ E_i·c_i·q_i / Σ E_i·q_i` with `q_i` the plane path's
//! normalised `1/w` (below 2^23). The sums are below `2^47` and `2^39`
//! (`u64`) and rounded half up exactly ([`SmallDivisor`]): within `1/2`
//! plus the normalisation's error (`255·ε/(1 − ε)`, `ε` the relative error
//! of the smallest `q_i`), as on the plane path but without its planes'
//! rounding: inside the derived bound of `tests/integration/perspective.rs`.
//!
//! Most pixels take a shortcut with the same result: the screen-linear
//! value `V_a = Σ E_i·c_i / det` lies within
//! `Δ = (c_max − c_min)/2 · (q_max − q_min)/q_min` of the
//! perspective-correct one `V_p` (below), so where `V_a`'s own rounding
//! is more than `Δ` from a tie, `V_p` rounds to the same channel, and that
//! is taken from `V_a`'s one 32-bit quotient ([`PerspFactors::slack`]).
//! Bound: with `b_i = E_i/det` (summing to 1) and `Q = Σ b_j·q_j`,
//! `V_p − V_a = Σ b_i·c_i·(q_i/Q − 1) = Σ b_i·(c_i − c̄)·(q_i/Q − 1)` for
//! any `c̄` (the weights `b_i·(q_i/Q − 1)` sum to 0); with `c̄` the middle
//! of the channel's range and `Q ≥ q_min`, each `|c_i − c̄| ≤ (c_max −
//! c_min)/2` and `|q_i/Q − 1| ≤ (q_max − q_min)/q_min`.
//!
//! A triangle whose three vertices have the same colour `c` (a quarter of
//! the knot's) is that colour at every pixel, with no division:
//! `Σ E_i·c·q_i / Σ E_i·q_i = c` exactly, and the exact sums round it to
//! `⌊(2·c·d + d) / 2d⌋ = c` ([`PerspFactors::uniform`]).
//!
//! Both depend on the triangle and the pixel only, so any band height gives
//! the same pixels.

use super::super::{Q_BITS, ScreenTriangle, normalised_q};
use super::channel_divrem;
use crate::Interpolate;
use crate::math::divisor::{ARMV6M, SmallDivisor};
use crate::math::scalar::HARD_FLOAT;

/// The per-triangle part of the perspective-correct colour: the slack of
/// the screen-linear shortcut (module docs). Made once per triangle, at its
/// first pixel that passes the depth test (none for a hidden triangle).
#[derive(Clone, Copy)]
pub(super) struct PerspFactors {
    /// `T ≥ 2·det·Δ` (module docs) for the shortcut: at a pixel whose
    /// screen-linear numerator `x = 2·Σ w_i·c_i + det` leaves a remainder
    /// `r` by `2·det` with `T ≤ r < 2·det − T`, the channel is `⌊x / 2·det⌋`.
    /// `u32::MAX` where `T` is not below `det` (hardly a pixel could take
    /// it), or where a channel exceeds its type's largest value.
    slack: u32,
    /// The vertices' colours are the same: every pixel is that colour
    /// (module docs).
    uniform: bool,
}

impl PerspFactors {
    /// The factors of `tri` (twice its area `det`) for colour type `C`.
    ///
    /// `Δ` is bounded from the vertices' `1/w` values `a_i` as they are,
    /// not normalised (only a pixel that misses the shortcut needs the
    /// normalised `q_i`): [`normalised_q`] scales them by `2^-k` (`k`
    /// the bits of the largest beyond 23, else 0, an exact scaling) and
    /// rounds each to within 1/2, so `q_max − q_min ≤ (a_max − a_min +
    /// e)/2^k` and `q_min ≥ (a_min − e/2)/2^k`, with `e = 2^k` for `k > 0`
    /// and 0 for `k = 0`.
    #[inline(never)]
    pub(super) fn new<C: Interpolate, const S: u32>(tri: &ScreenTriangle<S>, det: u32) -> Self {
        let [c0, c1, c2] = tri.v.map(|v| v.color);
        if c0 == c1 && c1 == c2 {
            return PerspFactors { slack: 0, uniform: true };
        }
        let a = tri.v.map(|v| v.inv_w);
        let (a_min, a_max) = (a[0].min(a[1]).min(a[2]), a[0].max(a[1]).max(a[2]));
        let k = (32 - a_max.leading_zeros()).saturating_sub(Q_BITS);
        let e = if k > 0 { 1u32 << k } else { 0 };
        // The widest channel range. On the Cortex-M0 a channel beyond its
        // type's largest value (a hand-made triangle's) turns the shortcut
        // off: its division by steps needs the quotient in range (a
        // hardware division does not).
        let max = C::CHANNEL_MAX;
        let (mut c_range, mut in_range) = (0u32, true);
        for (k, &max) in max.iter().enumerate() {
            let c = tri.v.map(|v| u32::from(v.color[k]));
            let hi = c[0].max(c[1]).max(c[2]);
            c_range = c_range.max(hi - c[0].min(c[1]).min(c[2]));
            in_range &= !ARMV6M || hi <= u32::from(max);
        }
        // 2·det·Δ ≤ det·c_range·(a_max − a_min + e)/(a_min − e/2).
        let den = a_min.saturating_sub(e / 2);
        if !in_range || den == 0 {
            return PerspFactors { slack: u32::MAX, uniform: false };
        }
        let (x, d) = (det * c_range, a_max - a_min);
        let slack = if HARD_FLOAT { slack_float(x, d, e, den, det) } else { slack_int(x, d, e, den, det) };
        PerspFactors { slack, uniform: false }
    }
}

/// A whole `T ≥ x·(d + e)/den`, or `u32::MAX` where it would not be below
/// `det` (`x < 2^24`, `e ≤ 2^9`, `0 < den`): the product, below
/// `2^24·(2^32 + 2^9)`, divided in `u64` by the power of two at or below
/// `den` and rounded up (at most twice the bound).
#[inline(always)]
fn slack_int(x: u32, d: u32, e: u32, den: u32, det: u32) -> u32 {
    let num = u64::from(x) * (u64::from(d) + u64::from(e));
    let k = 31 - den.leading_zeros();
    let t = (num + (1u64 << k) - 1) >> k;
    if t < u64::from(det) { t as u32 } else { u32::MAX }
}

/// [`slack_int`]'s bound with an FPU: the quotient in `f32`, raised by
/// `1 + 2^-20`, then truncated plus one. Five roundings to nearest (`d`,
/// the sum, the product, `den`, the quotient; `x` and `e` are exact) leave
/// the quotient at least `(1 − 2^-24)^5 / (1 + 2^-24) > 1 − 2^-21.4` of
/// `x·(d + e)/den`, and the raise (itself rounded, `1 − 2^-24`) lifts it
/// above: `T > x·(d + e)/den`, within a few units of it.
#[inline(always)]
fn slack_float(x: u32, d: u32, e: u32, den: u32, det: u32) -> u32 {
    const RAISE: f32 = 1.0 + 1.0 / 1_048_576.0;
    let t = x as f32 * (d as f32 + e as f32) / den as f32 * RAISE;
    if t < det as f32 { t as u32 + 1 } else { u32::MAX }
}

/// The perspective-correct Gouraud colour of `tri` at the pixel whose
/// barycentric coordinates are `w / det`: channel `k` is
/// `Σ w_i·c_ik·q_i / Σ w_i·q_i` rounded half up (module docs). Where every
/// channel's screen-linear rounding is farther than `Δ` from a tie, that
/// rounding (the same channels, module docs); else the sums, below 2^47
/// and 2^39, exactly in `u64` as products of `w_i < 2^16` and `c_ik·q_i`
/// (below 2^31), the three quotients sharing one normalised divisor
/// ([`SmallDivisor`]).
#[inline(never)]
pub(super) fn shade_perspective<C: Interpolate, const S: u32>(
    tri: &ScreenTriangle<S>,
    f: &PerspFactors,
    w: [u32; 3],
    det: u32,
) -> C {
    let max = C::CHANNEL_MAX;
    if f.uniform {
        // A channel the type lacks is 0, as the sums below make it.
        let c = tri.v[0].color;
        return C::from_channels([0, 1, 2].map(|k| if max[k] == 0 { 0 } else { c[k] }));
    }
    let c = |k: usize| tri.v.map(|v| u32::from(v.color[k]));
    if f.slack != u32::MAX {
        let (d2, t) = (2 * det, f.slack);
        let (mut out, mut sure) = ([0u8; 3], true);
        for k in 0..3 {
            if max[k] > 0 {
                // Σ w_i·c_i ≤ det·max < 2^24: as the affine channel.
                let c = c(k);
                let x = 2 * (w[0] * c[0] + w[1] * c[1] + w[2] * c[2]) + det;
                let (q, r) = channel_divrem(x, d2, max[k]);
                sure &= r >= t && r < d2 - t;
                out[k] = q as u8;
            }
        }
        if sure {
            return C::from_channels(out);
        }
    }
    let q = normalised_q(tri, Q_BITS).map(|q| q as u32);
    let dot = |v: [u32; 3]| (0..3).map(|i| w[i] as u64 * v[i] as u64).sum::<u64>();
    let d = dot(q);
    let div = SmallDivisor::new(2 * d);
    let channel = |k: usize| {
        let c = c(k);
        if max[k] == 0 { 0 } else { div.quotient(2 * dot([0, 1, 2].map(|i| c[i] * q[i])) + d) as u8 }
    };
    C::from_channels([channel(0), channel(1), channel(2)])
}

#[cfg(test)]
mod tests {
    use super::super::tests::next;
    use super::{PerspFactors, shade_perspective, slack_float, slack_int};
    use crate::raster3d::{ScreenTriangle, ScreenVertex, normalised_q};
    use crate::{Interpolate, SubPoint};
    use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};

    /// Both slack forms bound `x·(d + e)/den` from above (the shortcut's
    /// proof needs that) and stay close to it: the float form within two
    /// units, the power-of-two form within twice the bound plus one. The
    /// quotients are put just above whole numbers, where the float form's
    /// roundings would fall below the bound without its raise.
    #[test]
    fn slack_bounds_the_quotient_from_above() {
        let mut seed = 0x51AC_C0DE_u64;
        let mut checked = 0;
        for i in 0..1_000_000u32 {
            let det = ((next(&mut seed) >> 48) as u32).max(2);
            let x = ((next(&mut seed) >> 40) as u32).max(1); // below 2^24
            let e = if i % 3 == 0 { 0 } else { 1u32 << (1 + i % 9) };
            let n = (next(&mut seed) >> 40) % u64::from(det) + 1;
            let den = (next(&mut seed) >> 32).max(1 << 12);
            // y = d + e, the smallest with x·y ≥ n·den: the quotient just above n.
            let y = (n * den).div_ceil(u64::from(x));
            let Some(d) = y.checked_sub(u64::from(e)).and_then(|d| u32::try_from(d).ok()) else { continue };
            let (num, den) = (u128::from(x) * (u128::from(d) + u128::from(e)), den as u32);
            let det_u = u128::from(det);
            let float = slack_float(x, d, e, den, det);
            if float == u32::MAX {
                assert!(num > (det_u - 1) * u128::from(den), "{x} {d} {e} {den} {det}");
            } else {
                let t = u128::from(float);
                assert!(
                    t * u128::from(den) >= num && t.saturating_sub(2) * u128::from(den) <= num,
                    "{x} {d} {e} {den} {det}: {t}"
                );
            }
            let int = slack_int(x, d, e, den, det);
            if int == u32::MAX {
                assert!(2 * num > (det_u - 1) * u128::from(den), "{x} {d} {e} {den} {det}");
            } else {
                let t = u128::from(int);
                assert!(
                    t * u128::from(den) >= num && t.saturating_sub(1) * u128::from(den) <= 2 * num,
                    "{x} {d} {e} {den}: {t}"
                );
            }
            checked += (float != u32::MAX) as u32;
        }
        assert!(checked > 100_000, "{checked} bounds below det");
    }

    /// A vertex of `1/w` `inv_w` and colour `color` (position and depth
    /// do not enter the colour).
    fn vertex(inv_w: u32, color: [u8; 3]) -> ScreenVertex<4> {
        ScreenVertex { pos: SubPoint::ORIGIN, depth: 0, inv_w, color }
    }

    /// The perspective-correct colour by the per-pixel formula: `Σ w_i·c_i·q_i
    /// / Σ w_i·q_i` with the normalised `q_i`, rounded half up by a plain
    /// `u64` division.
    fn reference<C: Interpolate>(tri: &ScreenTriangle<4>, w: [u32; 3]) -> C {
        let q = normalised_q(tri, super::super::super::Q_BITS).map(|q| q as u64);
        let w = w.map(|w| w as u64);
        let d = w[0] * q[0] + w[1] * q[1] + w[2] * q[2];
        let channel = |k: usize| {
            if C::CHANNEL_MAX[k] == 0 {
                return 0;
            }
            let c = [0, 1, 2].map(|i| tri.v[i].color[k] as u64);
            let n = w[0] * c[0] * q[0] + w[1] * c[1] * q[1] + w[2] * c[2] * q[2];
            ((2 * n + d) / (2 * d)) as u8
        };
        C::from_channels([channel(0), channel(1), channel(2)])
    }

    /// The perspective-correct colour from the triangle's factors is the
    /// per-pixel formula it replaced: `Σ w_i·c_ik·q_i / Σ w_i·q_i` with the
    /// normalised `q_i`, rounded half up by a plain `u64` division, for
    /// `1/w` of every magnitude (rounded or not by the normalisation) and
    /// weights up to a determinant below 2^16.
    #[test]
    fn perspective_factors_give_the_per_pixel_formula() {
        let mut seed = 0x05EE_D0FC_0105_u64;
        let (mut rounded, mut uniform) = (0, 0);
        for i in 0..200_000u32 {
            let r = next(&mut seed);
            let inv_w = [0u32, 1, 2].map(|k| {
                let v = (next(&mut seed) >> (33 + (k + i) % 31)) as u32;
                [v.max(1), u32::MAX, 1, v | 1 << 31][((i / 7 + k) % 4) as usize]
            });
            // One triangle in five of one colour (the uniform case).
            let v = |k: u32| {
                let c = if i % 5 == 0 { 0 } else { k };
                vertex(
                    inv_w[k as usize],
                    [(r >> (8 * c)) as u8, (r >> (8 * c + 24)) as u8, (r >> (8 * c + 40)) as u8],
                )
            };
            let tri = ScreenTriangle { v: [v(0), v(1), v(2)], flat: false };
            rounded += (tri.v.iter().map(|v| v.inv_w).max().unwrap_or(0) >= 1 << 23) as u32;
            // Weights of a centre: non-negative, summing to det in 1..2^16.
            let det = (next(&mut seed) >> 48) as u32 % 0xFFFF + 1;
            let a = (next(&mut seed) >> 40) as u32 % (det + 1);
            let b = (next(&mut seed) >> 40) as u32 % (det - a + 1);
            let w = [[a, b, det - a - b], [det, 0, 0], [0, 0, det]][(i % 3) as usize];
            let f = PerspFactors::new::<Rgb888, 4>(&tri, det);
            assert_eq!(
                shade_perspective::<Rgb888, 4>(&tri, &f, w, det),
                reference::<Rgb888>(&tri, w),
                "{tri:?} {w:?}"
            );
            let f = PerspFactors::new::<Rgb565, 4>(&tri, det);
            assert_eq!(
                shade_perspective::<Rgb565, 4>(&tri, &f, w, det),
                reference::<Rgb565>(&tri, w),
                "{tri:?} {w:?}"
            );
            uniform += f.uniform as u32;
        }
        assert!(rounded > 20_000, "{rounded} triangles with 1/w rounded by the normalisation");
        // Uniform triangles, their channels above Rgb565's largest included.
        assert!(uniform > 30_000, "{uniform} triangles of one colour");
    }

    /// The screen-linear shortcut gives the perspective-correct channels
    /// (the per-pixel formula), for `1/w` that differ by up to a few
    /// percent (as across a mesh's tiny triangles) and every kind of
    /// colour: taken at most pixels, and near enough to ties that a bound
    /// any smaller would show.
    #[test]
    fn screen_linear_shortcut_gives_the_perspective_channels() {
        /// Whether the pixel's channels differ between the screen-linear and
        /// the perspective-correct rounding.
        fn differs(tri: &ScreenTriangle<4>, w: [u32; 3], det: u32) -> bool {
            let q = normalised_q(tri, super::super::super::Q_BITS).map(|q| q as u64);
            let w = w.map(|w| w as u64);
            let d = w[0] * q[0] + w[1] * q[1] + w[2] * q[2];
            (0..3).any(|k| {
                let c = [0, 1, 2].map(|i| tri.v[i].color[k] as u64);
                let n = w[0] * c[0] * q[0] + w[1] * c[1] * q[1] + w[2] * c[2] * q[2];
                let a = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
                (2 * n + d) / (2 * d) != (2 * a + det as u64) / (2 * det as u64)
            })
        }
        let mut seed = 0x54C0_7C07_u64;
        let (mut taken, mut samples, mut differ) = (0u32, 0u32, 0u32);
        for i in 0..300_000u32 {
            // 1/w of any magnitude, the three within 2^-(4..20) of each other.
            let base = (next(&mut seed) >> (33 + i % 20)) as u32 | 1 << 8;
            let spread = 4 + (i / 3) % 17;
            let inv_w = [0u32; 3].map(|_| base + ((next(&mut seed) >> 40) as u32 % ((base >> spread) + 1)));
            let r = next(&mut seed);
            let rgb888 = i % 2 == 0;
            let max = if rgb888 { [255u64; 3] } else { [31, 63, 31] };
            // One triangle in seven of one colour (the uniform case).
            let v = |k: u32| {
                let c = if i % 7 == 0 { 0 } else { k };
                vertex(
                    inv_w[k as usize],
                    [0, 1, 2].map(|ch| ((r >> (8 * c + 24 * ch as u32 / 2)) % (max[ch] + 1)) as u8),
                )
            };
            let tri = ScreenTriangle { v: [v(0), v(1), v(2)], flat: false };
            let det = [(next(&mut seed) >> 48) as u32 % 0xFFFF + 1, 2 + i % 60][(i % 2) as usize];
            let a = (next(&mut seed) >> 40) as u32 % (det + 1);
            let b = (next(&mut seed) >> 40) as u32 % (det - a + 1);
            let w = [[a, b, det - a - b], [det, 0, 0], [a, det - a, 0]][(i % 3) as usize];
            let (slack, ok) = if rgb888 {
                let f = PerspFactors::new::<Rgb888, 4>(&tri, det);
                (f.slack, shade_perspective::<Rgb888, 4>(&tri, &f, w, det) == reference::<Rgb888>(&tri, w))
            } else {
                let f = PerspFactors::new::<Rgb565, 4>(&tri, det);
                (f.slack, shade_perspective::<Rgb565, 4>(&tri, &f, w, det) == reference::<Rgb565>(&tri, w))
            };
            assert!(ok, "{tri:?} {w:?} det {det}");
            samples += 1;
            taken += (slack != u32::MAX) as u32;
            differ += differs(&tri, w, det) as u32;
        }
        // Most triangles allow the shortcut, and the screen-linear rounding
        // alone is wrong often enough that the tie test must hold it back.
        assert!(taken > samples / 2 && differ > samples / 200, "{taken} of {samples}, {differ} differ");
    }
}
