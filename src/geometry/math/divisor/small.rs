//! A divisor below 2^48 prepared once for several small quotients (the
//! perspective-correct colour of a tiny triangle divides three channel sums
//! by one sum of weights), with one 32-bit division each.

/// A divisor `0 < y < 2^48` of quotients below 2^9, prepared once for
/// several: `y`'s top 16 bits plus one (so the estimate is not above the
/// quotient) divide `x` shifted alike, which is within `513 / 2^15` of
/// `x / y` below it, and one correction step finishes.
#[derive(Clone, Copy)]
pub(crate) struct SmallDivisor {
    y: u64,
    s: u32,
    yh: u32,
}

impl SmallDivisor {
    #[inline(always)]
    pub(crate) fn new(y: u64) -> Self {
        let s = (64 - y.leading_zeros()).saturating_sub(16);
        SmallDivisor { y, s, yh: (y >> s) as u32 + (s > 0) as u32 }
    }

    /// `⌊x / y⌋` for `x / y < 2^9`, exactly.
    #[inline(always)]
    pub(crate) fn quotient(&self, x: u64) -> u32 {
        // y >> s < 2^16, and x >> s < 2^9·((y >> s) + 1) ≤ 2^25.
        let q = (x >> self.s) as u32 / self.yh;
        // q ≤ x / y, so x − q·y ≥ 0, and below 2y.
        if x - q as u64 * self.y >= self.y { q + 1 } else { q }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::vec::tests::Rng;

    #[test]
    fn small_quotient_is_the_u64_division() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for i in 0..300_000u32 {
            let seed = rng.next();
            // Divisors of every size up to 2^48, quotients up to 2^9 − 1.
            let y = (seed >> (16 + i % 48)).max(1);
            let y = [y, 1, (1 << 48) - 1, 1 << 16, (1 << 16) - 1, (1 << 16) + 1][(i % 6) as usize];
            let q = (seed >> 7) % 512;
            let x = match i % 3 {
                0 => q * y + (seed >> 11) % y,
                1 => q * y + y - 1,
                _ => q * y,
            };
            assert_eq!(SmallDivisor::new(y).quotient(x) as u64, x / y, "{x} / {y}");
        }
    }
}
