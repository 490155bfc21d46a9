//! Depth in the 3D fragment loop: the depth rule of a draw (the common
//! [`DepthState::LESS_WRITE`] as a type of its own, so its loop has no
//! per-pixel dispatch), the depth plane stepped along a span, and the
//! conversion of vertex depths into a format's steps.

use super::DEPTH_FRAC;
use crate::attr::Plane;
use crate::depth::{DepthFormat, DepthState, DepthTest};

/// A depth state, known at compile time or not.
pub(super) trait DepthRule: Copy {
    fn test(self) -> DepthTest;
    fn write(self) -> bool;
}

impl DepthRule for DepthState {
    #[inline(always)]
    fn test(self) -> DepthTest {
        self.test
    }
    #[inline(always)]
    fn write(self) -> bool {
        self.write
    }
}

/// [`DepthState::LESS_WRITE`] as a type.
#[derive(Clone, Copy)]
pub(super) struct LessWrite;

impl DepthRule for LessWrite {
    #[inline(always)]
    fn test(self) -> DepthTest {
        DepthTest::Less
    }
    #[inline(always)]
    fn write(self) -> bool {
        true
    }
}

/// The depth plane along a span. Formats of at most 16 bits step in `u32`:
/// a sampled value is within 2^13 units of an exact one in
/// `[0, MAX·2^DEPTH_FRAC]` (`attr`), so value + ½ step lies in
/// `[0, 2^32)` and its wrapping `u32` sum is exact and needs no clamp: the
/// same result as [`depth_value`], which wider formats use on `i64`.
pub(super) struct DepthSpan<F> {
    narrow: (u32, u32),
    wide: (i64, i64),
    _f: core::marker::PhantomData<F>,
}

impl<F: DepthFormat> DepthSpan<F> {
    const NARROW: bool = F::BITS + DEPTH_FRAC <= 32;

    #[inline(always)]
    pub(super) fn new(p: &Plane, x: i32, y: i32) -> Self {
        let (narrow, wide) = if Self::NARROW {
            // Only the low 32 bits are used: `at_low32` gives them.
            ((p.at_low32(x, y).wrapping_add(1 << (DEPTH_FRAC - 1)), p.step_x() as u32), (0, 0))
        } else {
            ((0, 0), (p.at(x, y), p.step_x()))
        };
        DepthSpan { narrow, wide, _f: core::marker::PhantomData }
    }

    #[inline(always)]
    pub(super) fn value(&self) -> u32 {
        if Self::NARROW { self.narrow.0 >> DEPTH_FRAC } else { depth_value::<F>(self.wide.0) }
    }

    #[inline(always)]
    pub(super) fn step(&mut self) {
        if Self::NARROW {
            self.narrow.0 = self.narrow.0.wrapping_add(self.narrow.1);
        } else {
            self.wide.0 = self.wide.0.wrapping_add(self.wide.1);
        }
    }
}

/// A depth-plane value rounded to the nearest step of `F`; the clamp only
/// matters at ± rounding.
#[inline(always)]
pub(crate) fn depth_value<F: DepthFormat>(z: i64) -> u32 {
    ((z.clamp(0, (F::MAX as i64) << DEPTH_FRAC) + (1 << (DEPTH_FRAC - 1))) >> DEPTH_FRAC) as u32
}

/// `depth / (2^32 − 1) · max · 2^DEPTH_FRAC`: a vertex depth in depth steps
/// of a format with largest value `max`, so 0 → 0 and `u32::MAX` → `max`
/// exactly. Division by `2^32 − 1` as the series `y·2^-32·(1 + 2^-32 + 2^-64)`
/// (shifts and adds only; the truncated terms are below one unit).
#[inline]
pub(crate) fn depth_steps(depth: u32, max: u32) -> i64 {
    if max <= 0xFFFF {
        // y < 2^64 − 2^48 and y >> 32 < 2^32: the sum fits a u64 and
        // y >> 64 is 0, so this is the u128 series below without its
        // (library-called) 128-bit arithmetic.
        let y = crate::math::divisor::mul_wide_u32(depth, max) << DEPTH_FRAC;
        return (((y + (y >> 32)) >> 32) + 1).min((max as u64) << DEPTH_FRAC) as i64;
    }
    depth_steps_wide(depth, max)
}

/// [`depth_steps`] for a format of `bits ≤ 16` bits (`max = 2^bits − 1`)
/// within 3 units (the fast tier's): `depth·max·2^16/(2^32 − 1)` is
/// `depth·2^(bits − 16)·(1 − 2^-bits)·(1 + 2^-32 + …)`, and the two
/// shifts' floors and the dropped factor cost at most a unit each. Two
/// shifts and a subtraction instead of a 64-bit product and sum; at most
/// `max·2^16` (the two terms' floors only lower the first less than the
/// second's exact value at `u32::MAX`).
#[inline(always)]
pub(crate) fn depth_steps_approx(depth: u32, bits: u32) -> u32 {
    debug_assert!((1..=16).contains(&bits));
    (depth >> (16 - bits)) - (depth >> 16)
}

/// [`depth_steps`] in `u128`, for any `max`.
fn depth_steps_wide(depth: u32, max: u32) -> i64 {
    let y = (depth as u128 * max as u128) << DEPTH_FRAC;
    // Rounding up by one unit makes u32::MAX land on max·2^16 exactly.
    (((y + (y >> 32) + (y >> 64)) >> 32) + 1).min((max as u128) << DEPTH_FRAC) as i64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `u64` form of 16-bit formats equals the `u128` series.
    #[test]
    fn narrow_depth_steps_equal_the_wide_series() {
        let mut seed = 0x0005_DEEC_E66D_u64;
        for i in 0..300_000u32 {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let (d, m) = ((seed >> 32) as u32, (seed >> 16) as u32 & 0xFFFF);
            let d = [d, 0, u32::MAX, u32::MAX - 1, 1][(i % 5) as usize];
            for max in [m, 0xFFFF, 0xFF, 1, 0] {
                assert_eq!(depth_steps(d, max), depth_steps_wide(d, max), "{d} {max}");
            }
        }
    }

    /// The fast tier's form is within 3 units of the exact one, for every
    /// format of up to 16 bits, at both ends and in between.
    #[test]
    fn approximate_depth_steps_are_within_three_units() {
        let mut seed = 0x00DE_9745_u64;
        for i in 0..400_000u32 {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let d =
                [(seed >> 32) as u32, 0, u32::MAX, u32::MAX - 1, 1, (seed >> 48) as u32][(i % 6) as usize];
            for bits in [1, 8, 12, 16] {
                let max = (1u32 << bits) - 1;
                let (exact, approx) = (depth_steps(d, max), i64::from(depth_steps_approx(d, bits)));
                assert!((exact - approx).abs() <= 3, "{d} at {bits} bits: {exact} vs {approx}");
                assert!(approx <= i64::from(max) << DEPTH_FRAC);
            }
        }
    }

    #[test]
    fn depth_steps_maps_ends_exactly_and_is_monotonic() {
        for max in [0xFF, 0xFFFF, 0xFF_FFFF, u32::MAX] {
            assert_eq!(depth_steps(0, max), 1.min((max as i64) << DEPTH_FRAC));
            assert_eq!(depth_steps(u32::MAX, max), (max as i64) << DEPTH_FRAC);
            let mut last = 0;
            for i in 0..=4096u64 {
                let d = (i * (u32::MAX as u64) / 4096) as u32;
                let v = depth_steps(d, max);
                // Exact value d·max·2^16/(2^32−1), within one unit (plus the +1).
                let exact = (d as f64) * (max as f64) * 65536.0 / (u32::MAX as f64);
                assert!((v as f64 - exact).abs() <= 2.0 + exact * 1e-15, "{d} {max}: {v} vs {exact}");
                assert!(v >= last);
                last = v;
            }
        }
    }
}
