//! Colour along a span of the 3D fragment loop ([`super::draw_triangle`]'s
//! plane path): flat, or Gouraud from per-triangle planes, affine or
//! perspective-correct. The loop asks a [`Shader`] for a [`ShadeSpan`] at
//! each span's start and steps it pixel by pixel.
//!
//! # Affine channels without a clamp
//! A plane through channel values in `0..=max`, sampled at a covered pixel
//! centre, rounds to a value in `0..=max` ([`channel_in_range`]): a
//! triangle whose vertex channels are all in range ([`channels_in_range`],
//! always so for the pipeline's) takes a loop whose channel is one
//! bit-field extract; a hand-made one with larger channels keeps the
//! per-pixel clamp ([`channel_clamped`]). The same pixels either way.

use super::{DEPTH_FRAC, Interpolation, Q_BITS, ScreenTriangle, normalised_q};
use crate::Interpolate;
use crate::attr::{COLOR_FRAC, COLOR_HALF, Plane, PlaneSetup, channel_clamped, channel_in_range};

/// A way of colouring a triangle's fragments: per span, a [`ShadeSpan`].
pub(super) trait Shader<C> {
    type Span: ShadeSpan<C>;
    /// Perspective-correct: each pixel's colour divides, and its
    /// accumulators are 64-bit.
    const PERSPECTIVE: bool = false;
    fn start(&self, x: i32, y: i32) -> Self::Span;
}

/// Colour along one span: at its current pixel, stepped pixel by pixel,
/// or at any pixel of the span from its start.
pub(super) trait ShadeSpan<C> {
    fn color(&self) -> C;
    fn step(&mut self);
    /// The colour `i` pixels after the span's start (of a span not yet
    /// stepped): the same value `i` steps give, as each accumulator wraps
    /// (`start + i·step` modulo its width is `i` wrapping additions).
    fn color_at(&self, i: u32) -> C;
}

/// Flat shading: the colour itself.
impl<C: Interpolate> Shader<C> for C {
    type Span = C;
    #[inline(always)]
    fn start(&self, _: i32, _: i32) -> C {
        *self
    }
}

impl<C: Interpolate> ShadeSpan<C> for C {
    #[inline(always)]
    fn color(&self) -> C {
        *self
    }
    #[inline(always)]
    fn step(&mut self) {}
    #[inline(always)]
    fn color_at(&self, _: u32) -> C {
        *self
    }
}

/// Whether every vertex channel of `tri` is at most the colour's maximum
/// (always so for the pipeline's triangles; a hand-made triangle may hold
/// more, which the pixels clamp).
#[inline(always)]
pub(super) fn channels_in_range<C: Interpolate, const S: u32>(tri: &ScreenTriangle<S>) -> bool {
    let max = C::CHANNEL_MAX;
    tri.v.iter().all(|v| v.color[0] <= max[0] && v.color[1] <= max[1] && v.color[2] <= max[2])
}

/// Gouraud colour set-up for one triangle: per channel a plane of the
/// colour (affine) or of `c·q`, plus one of `q` (perspective-correct; these
/// scaled by 2^(32 − [`DEPTH_FRAC`]) modulo 2^64, as [`GouraudSpan`] keeps
/// them). Channels the colour type lacks get no plane and stay 0. `CLAMP`: each
/// pixel's channels are clamped to `0..=max`; without it (affine, vertex
/// channels in range: [`channels_in_range`]) they are in range already
/// ([`channel_in_range`]).
pub(super) struct Gouraud<C, M, const CLAMP: bool> {
    pub(super) planes: [Plane; 4],
    pub(super) _m: core::marker::PhantomData<(C, M)>,
}

/// [`Gouraud`] along a span. Affine: `i32` accumulators (a sampled value is
/// within 2^13 units of one in `[0, 255·2^20]`, so the wrapping `i32` sum (with the rounding's half step added, below 2^28) is
/// the exact `i64` one). Perspective-correct: accumulators scaled by 2^32 /
/// 2^[`DEPTH_FRAC`], so the high word is the whole part the division needs
/// (sampled `c·q` in `[−1, 2^31)` and `q` in `[0, 2^23]` after flooring),
/// again exact modulo 2^64.
pub(super) struct GouraudSpan<C, M, const CLAMP: bool> {
    affine: [i32; 3],
    affine_step: [i32; 3],
    persp: [i64; 4],
    persp_step: [i64; 4],
    _m: core::marker::PhantomData<(C, M)>,
}

impl<C: Interpolate, M: Interpolation, const CLAMP: bool> Gouraud<C, M, CLAMP> {
    /// The planes of `tri`, written in place (channels the colour type
    /// lacks keep theirs).
    #[inline(always)]
    pub(super) fn set_up<const S: u32>(&mut self, tri: &ScreenTriangle<S>, setup: &PlaneSetup) {
        let max = C::CHANNEL_MAX;
        let planes = &mut self.planes;
        if M::PERSPECTIVE {
            // 23 bits keep c·q within u32 for a channel c ≤ 255.
            let q = normalised_q(tri, Q_BITS);
            // Each plane scaled by 2^(32 − DEPTH_FRAC) here, once, for the
            // accumulators (`GouraudSpan`), not at each span's start.
            setup.plane_into(q.map(|q| q << DEPTH_FRAC), &mut planes[3]);
            planes[3].mul_pow2_wrapping(32 - DEPTH_FRAC);
            for (k, p) in planes.iter_mut().take(3).enumerate() {
                if max[k] > 0 {
                    let cq = |i: usize| (tri.v[i].color[k] as i64 * q[i]) << DEPTH_FRAC;
                    setup.plane_into([cq(0), cq(1), cq(2)], p);
                    p.mul_pow2_wrapping(32 - DEPTH_FRAC);
                }
            }
        } else {
            for (k, p) in planes.iter_mut().take(3).enumerate() {
                if max[k] > 0 {
                    setup.plane_into(tri.v.map(|v| (v.color[k] as i64) << COLOR_FRAC), p);
                }
            }
        }
    }
}

impl<C: Interpolate, M: Interpolation, const CLAMP: bool> Shader<C> for Gouraud<C, M, CLAMP> {
    type Span = GouraudSpan<C, M, CLAMP>;
    const PERSPECTIVE: bool = M::PERSPECTIVE;

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> GouraudSpan<C, M, CLAMP> {
        let max = C::CHANNEL_MAX;
        let mut s = GouraudSpan {
            affine: [0; 3],
            affine_step: [0; 3],
            persp: [0; 4],
            persp_step: [0; 4],
            _m: core::marker::PhantomData,
        };
        // Perspective-correct: one offset for the four planes (they share
        // the `q` plane's reference pixel). The affine channels keep
        // `Plane::at_low32`: the shared offset measured no faster there
        // (`docs/setup_cost.md`).
        let (rx, ry) = self.planes[3].reference();
        let (dx, dy) = (x - rx, y - ry);
        for (k, p) in self.planes.iter().enumerate() {
            if k == 3 && !M::PERSPECTIVE || k < 3 && max[k] == 0 {
                continue;
            }
            let d = p.step_x();
            if M::PERSPECTIVE {
                // Scaled by `set_up` already.
                (s.persp[k], s.persp_step[k]) = (p.at_offset(dx, dy), d);
            } else {
                // The `i32` accumulator keeps the low 32 bits only, with
                // the rounding's half step added once (`channel_in_range`).
                (s.affine[k], s.affine_step[k]) =
                    ((p.at_low32(x, y) as i32).wrapping_add(COLOR_HALF), d as i32);
            }
        }
        s
    }
}

impl<C: Interpolate, M: Interpolation, const CLAMP: bool> GouraudSpan<C, M, CLAMP> {
    /// The colour of accumulators `affine` (affine) or `persp`
    /// (perspective-correct; the other is unused).
    #[inline(always)]
    fn color_of(affine: [i32; 3], persp: [i64; 4]) -> C {
        let max = C::CHANNEL_MAX;
        // No array `map` here: it is not always inlined.
        let channel_of = |k: usize| -> u8 {
            if max[k] == 0 {
                0
            } else if M::PERSPECTIVE {
                // q ≤ 2^23 and c·q < 2^31 inside the triangle: 32-bit
                // divisions, which Cortex-M3/M4 do in hardware (the max only
                // guards rounding).
                let q = ((persp[3] >> 32) as i32).max(1) as u32;
                let p = ((persp[k] >> 32) as i32).max(0) as u32;
                ((p + q / 2) / q).min(max[k] as u32) as u8
            } else if CLAMP {
                channel_clamped(affine[k], max[k])
            } else {
                channel_in_range(affine[k], max[k])
            }
        };
        C::from_channels([channel_of(0), channel_of(1), channel_of(2)])
    }
}

impl<C: Interpolate, M: Interpolation, const CLAMP: bool> ShadeSpan<C> for GouraudSpan<C, M, CLAMP> {
    #[inline(always)]
    fn color(&self) -> C {
        Self::color_of(self.affine, self.persp)
    }

    #[inline(always)]
    fn step(&mut self) {
        let max = C::CHANNEL_MAX;
        if M::PERSPECTIVE {
            for (k, (acc, step)) in self.persp.iter_mut().zip(self.persp_step).enumerate() {
                if k == 3 || max[k] > 0 {
                    *acc = acc.wrapping_add(step);
                }
            }
        } else {
            for ((acc, step), m) in self.affine.iter_mut().zip(self.affine_step).zip(max) {
                if m > 0 {
                    *acc = acc.wrapping_add(step);
                }
            }
        }
    }

    #[inline(always)]
    fn color_at(&self, i: u32) -> C {
        let max = C::CHANNEL_MAX;
        let (mut affine, mut persp) = (self.affine, self.persp);
        if M::PERSPECTIVE {
            for k in 0..4 {
                if k == 3 || max[k] > 0 {
                    persp[k] = persp[k].wrapping_add(self.persp_step[k].wrapping_mul(i64::from(i)));
                }
            }
        } else {
            for k in 0..3 {
                if max[k] > 0 {
                    affine[k] = affine[k].wrapping_add(self.affine_step[k].wrapping_mul(i as i32));
                }
            }
        }
        Self::color_of(affine, persp)
    }
}

#[cfg(test)]
mod tests {
    use super::{GouraudSpan, ScreenTriangle, ShadeSpan, normalised_q};
    use crate::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenVertex};
    use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};

    /// A span's colour at an index is the colour after as many steps, for
    /// accumulators and steps anywhere in their range (so that both wrap),
    /// affine and perspective-correct, for colour types with and without
    /// 8-bit channels.
    #[test]
    fn color_at_is_the_stepped_color() {
        fn check<C: crate::Interpolate + PartialEq + core::fmt::Debug, M: Interpolation>(
            rng: &mut impl FnMut() -> u64,
        ) {
            for _ in 0..2_000 {
                let mut s = GouraudSpan::<C, M, true> {
                    affine: [0; 3].map(|_| rng() as i32),
                    affine_step: [0; 3].map(|_| (rng() as i32) >> (rng() % 32)),
                    persp: [0; 4].map(|_| rng() as i64),
                    persp_step: [0; 4].map(|_| (rng() as i64) >> (rng() % 64)),
                    _m: core::marker::PhantomData,
                };
                let start = GouraudSpan::<C, M, true> { _m: core::marker::PhantomData, ..s };
                for i in 0..70 {
                    assert_eq!(start.color_at(i), s.color(), "pixel {i}");
                    s.step();
                }
            }
        }
        let mut rng = crate::math::vec::tests::Rng(0x0C01_04A7);
        let mut next = || rng.next();
        check::<Rgb565, Affine>(&mut next);
        check::<Rgb565, PerspectiveCorrect>(&mut next);
        check::<Rgb888, Affine>(&mut next);
        check::<Rgb888, PerspectiveCorrect>(&mut next);
    }

    /// `normalised_q` in `u32` is the `u64` form it replaced,
    /// `(q + 2^(k−1)) >> k` for a right shift, for `1/w` of every
    /// magnitude (including `u32::MAX`, whose rounding carries into a
    /// 33rd bit there) and the normalisations the crate uses.
    #[test]
    fn normalised_q_is_the_u64_form() {
        fn reference(inv_w: [u32; 3], bits: u32) -> [i64; 3] {
            let qmax = inv_w.iter().copied().max().unwrap_or(0).max(1);
            let shift = bits as i32 - (32 - qmax.leading_zeros()) as i32;
            inv_w.map(|q| {
                let q = q as u64;
                let q = if shift >= 0 { q << shift } else { (q + (1 << (-shift - 1))) >> -shift };
                q.max(1) as i64
            })
        }
        let mut rng = crate::math::vec::tests::Rng(0x0051_F7ED);
        let mut next = || rng.next();
        let (mut right, mut left) = (0, 0);
        for i in 0..200_000u32 {
            let inv_w = [0u32; 3].map(|_| {
                let r = next();
                let v = (r >> (32 + (r as u32 % 32))) as u32;
                [v, u32::MAX, 0, 1, v | 1 << 31, (1 << 23) - 1][(r >> 8) as usize % 6]
            });
            let tri = ScreenTriangle::<4> {
                v: inv_w.map(|inv_w| ScreenVertex { inv_w, ..Default::default() }),
                flat: false,
            };
            let bits = [23, 30, 1, 31][(i % 4) as usize];
            assert_eq!(normalised_q(&tri, bits), reference(inv_w, bits), "{inv_w:?} to {bits} bits");
            let top = 32 - inv_w.iter().max().unwrap_or(&0).max(&1).leading_zeros();
            (right, left) = if top > bits { (right + 1, left) } else { (right, left + 1) };
        }
        assert!(right > 50_000 && left > 20_000, "{right} shifted right, {left} left");
    }
}
