//! Gouraud colour accumulators: the fixed-point scale of a channel
//! ([`COLOR_FRAC`]) and the conversions of a sampled plane value to a channel
//! that the span loops use. "Module docs" below are those of `attr` (the
//! planes' error bound).

/// Fixed-point units per Gouraud channel step.
pub(crate) const COLOR_FRAC: u32 = 20;

/// A colour accumulator (channel · 2^COLOR_FRAC) as a channel in `0..=max`,
/// rounded half up: the definition the span loops' biased forms
/// ([`channel_clamped`], [`channel_in_range`]) are tested against.
#[cfg(test)]
fn channel(acc: i32, max: u8) -> u8 {
    let v = (acc >> COLOR_FRAC) + ((acc >> (COLOR_FRAC - 1)) & 1); // round half up
    v.clamp(0, max as i32) as u8
}

/// Half a channel step in accumulator units: the bias of
/// [`channel_clamped`] and [`channel_in_range`] (a span loop adds it once
/// at the span's start).
pub(crate) const COLOR_HALF: i32 = 1 << (COLOR_FRAC - 1);

/// A colour accumulator (channel · 2^COLOR_FRAC) that holds the
/// [`COLOR_HALF`] bias as a channel in `0..=max`, rounded half up
/// (`(acc + ½) >> F` is `acc >> F` plus its bit `F − 1`).
#[inline(always)]
pub(crate) fn channel_clamped(acc: i32, max: u8) -> u8 {
    (acc >> COLOR_FRAC).clamp(0, max as i32) as u8
}

/// [`channel_clamped`] for a plane through channel values in `0..=max`,
/// sampled at a covered pixel centre: no clamp is needed. The exact value
/// lies in `[0, max·2^F]` (a convex combination of the vertices' values)
/// and the sample within `2^13 < 2^(F−1)` units of it (module docs), so the
/// biased value shifted down is in `0..=max`. Every colour type's `max` is
/// `2^k − 1`, so a mask (one bit-field extract) keeps it as it is; for any
/// other `max` the clamp stays.
#[inline(always)]
pub(crate) fn channel_in_range(acc: i32, max: u8) -> u8 {
    let v = acc >> COLOR_FRAC;
    debug_assert!((0..=max as i32).contains(&v), "{v} beyond 0..={max}");
    if max & max.wrapping_add(1) == 0 { (v & max as i32) as u8 } else { v.clamp(0, max as i32) as u8 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channel_rounds_and_clamps() {
        let half = 1 << (COLOR_FRAC - 1);
        assert_eq!(channel(half - 1, 255), 0);
        assert_eq!(channel(half, 255), 1);
        assert_eq!(channel(-5 << COLOR_FRAC, 31), 0);
        assert_eq!(channel(40 << COLOR_FRAC, 31), 31);
    }

    /// The biased forms are `channel` with the half step added first, and
    /// the unclamped one agrees wherever the value is in range, for masks
    /// (`2^k − 1`) and other maxima alike.
    #[test]
    fn biased_channels_equal_channel() {
        for max in [1u8, 3, 15, 31, 63, 255, 100, 200] {
            let top = ((max as i32 + 2) << COLOR_FRAC) as i64;
            for acc in (-(1i64 << 22)..top).step_by(4093).chain([COLOR_HALF as i64 - 1, COLOR_HALF as i64]) {
                let acc = acc as i32;
                let want = channel(acc, max);
                assert_eq!(channel_clamped(acc + COLOR_HALF, max), want, "{acc} {max}");
                if (0..=max as i32).contains(&((acc + COLOR_HALF) >> COLOR_FRAC)) {
                    assert_eq!(channel_in_range(acc + COLOR_HALF, max), want, "{acc} {max}");
                }
            }
        }
    }
}
