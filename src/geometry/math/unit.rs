//! Unit vectors for shading in 16.16 without a division: the `Fx` side of
//! [`Vec3::normalize_fast`](super::Vec3::normalize_fast).
//!
//! [`Vec3::normalize`](super::Vec3::normalize) divides each component twice
//! and takes a square root by bits, about 1,700 instructions on the
//! Cortex-M0; here the components are scaled by a power of two, their exact
//! sum of squares taken in 64 bits, its reciprocal square root found from a
//! 48-entry table and two Newton steps in 32-bit fixed point, and each
//! component multiplied by it: about a quarter of that, and more accurate
//! (within `2^-16` of the exact unit vector per component, against `8·2^-16`;
//! derivation at [`unit_bits`], tested against f64).

use super::Vec3;
use super::divisor::mul_wide_u32;

/// [`Vec3::normalize_fast`] for `f32`: `v · ρ` with `ρ ≈ 1/√(v·v)` from the
/// bit-pattern estimate (within 3.5 % relative) and three Newton steps
/// `ρ ← ρ(3/2 − (s/2)ρ²)`, which leave `3.4·10^-11` of the method's error
/// (the relative error goes `e → 1.5e²`); what remains is rounding: `s`
/// within `3·2^-24` relative (so `1/√s` within `1.5·2^-24`), the last step
/// within `2.5·2^-24`, the product `2^-24`: within `5·2^-24`, bound stated
/// as `6·2^-24` and tested against f64. The squares keep that relative
/// precision only while `s` is a normal number far from overflow: outside
/// `[2^-100, 2^100]` (and for NaN, zero and infinity) this is
/// [`Vec3::normalize`].
pub(crate) fn unit_f32(v: Vec3<f32>) -> Vec3<f32> {
    let s = v.x * v.x + v.y * v.y + v.z * v.z;
    let Some(r) = rsqrt_f32(s) else { return v.normalize() };
    Vec3::new(v.x * r, v.y * r, v.z * r)
}

/// Whether `s` lies in [`rsqrt_f32`]'s domain, `[2^-100, 2^100]` (about;
/// NaN does not).
#[inline]
pub(crate) fn in_rsqrt_domain(s: f32) -> bool {
    (7.9e-31..=1.2e30).contains(&s)
}

/// `1/√s` for `s` in `[2^-100, 2^100]` (about; `None` outside, NaN
/// included, [`in_rsqrt_domain`]), within `5·2^-24` relative: the
/// bit-pattern estimate and three Newton steps of [`unit_f32`] (its
/// derivation).
#[inline]
pub(crate) fn rsqrt_f32(s: f32) -> Option<f32> {
    if !in_rsqrt_domain(s) {
        return None;
    }
    // The classic estimate of 1/√s from the exponent and mantissa bits.
    let mut r = f32::from_bits(0x5F37_59DF - (s.to_bits() >> 1));
    let half = 0.5 * s; // exact: s is normal
    for _ in 0..3 {
        r = r * (1.5 - half * r * r);
    }
    Some(r)
}

/// [`rsqrt_f32`] with two Newton steps instead of three, for the fast
/// tier's lighting: the method's error `1.5·(1.5·0.035²)²` ≈ `4.8·10^-6`
/// relative, plus the rounding (`5·2^-24`): within `5.2·10^-6`.
#[inline]
pub(crate) fn rsqrt_f32_fast(s: f32) -> Option<f32> {
    if !in_rsqrt_domain(s) {
        return None;
    }
    let mut r = f32::from_bits(0x5F37_59DF - (s.to_bits() >> 1));
    let half = 0.5 * s;
    for _ in 0..2 {
        r = r * (1.5 - half * r * r);
    }
    Some(r)
}

/// `Y₀(i) ≈ 2^29/√ν` at the midpoint `ν = (i + ½)/64` of table cell `i`
/// (`16 ≤ i < 64`, so `ν ∈ [¼, 1)`): `2^32/√(i + ½) = √(2^65/(2i + 1))`.
const RSQRT_TABLE: [u32; 48] = {
    let mut t = [0u32; 48];
    let mut i = 0;
    while i < 48 {
        t[i] = isqrt_u64((1u64 << 63) / (2 * (i as u64 + 16) + 1) * 4) as u32;
        i += 1;
    }
    t
};

/// `⌊√n⌋` (compile time only: the table).
const fn isqrt_u64(n: u64) -> u64 {
    let (mut lo, mut hi) = (0u64, 1u64 << 32);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if mid as u128 * mid as u128 <= n as u128 { lo = mid } else { hi = mid }
    }
    lo
}

/// `ρ·2^29` with `ρ = 1/√ν`, `ν = n/2^32`, for `n ∈ [2^30, 2^32)`
/// (`ρ ∈ (1, 2]`). The table is within `2^-6` relative; Newton's step
/// `ρ ← ρ(3 − νρ²)/2` squares the relative error (times 3/2): `1.5·2^-12`,
/// then `2^-21.8`, plus at most `2^-27` of truncation, so the result is within
/// `2^-21` of `ρ·2^29` relative (tested).
fn rsqrt_q29(n: u32) -> u32 {
    let mut y = RSQRT_TABLE[(n >> 26) as usize - 16];
    for _ in 0..2 {
        // y ≤ 2^30: y²/2^29 ≤ 2^31; ν·ρ²·2^29 ≈ 2^29; (3 − νρ²)·2^29 < 2^31.
        let t = (mul_wide_u32(y, y) >> 29) as u32;
        let e = (mul_wide_u32(t, n) >> 32) as u32;
        let f = (3u32 << 29).saturating_sub(e);
        y = (mul_wide_u32(y, f) >> 30) as u32;
    }
    y
}

/// The unit vector of the raw 16.16 components `v`, as raw 16.16, or `None`
/// for the zero vector.
///
/// Error: with `X` the components shifted left so the largest has bit 30
/// set (exact; a component of `2^31` is halved, losing at most `2^-30`
/// relative), `N = ΣX²` is exact in 64 bits and `n` its top 32 or 30 bits
/// (`2^-30` relative), `ρ` is within `2^-21` relative, and the product
/// `X·ρ` rounds once to 16.16 (`2^-17`). So each component is within
/// `2^-17 + 2^-20.9 < 2^-16` of the exact unit vector's.
#[inline(never)] // inlined, its 64-bit temporaries would grow the callers' stack frames
pub(crate) fn unit_bits(v: [i32; 3]) -> Option<[i32; 3]> {
    let a = v.map(i32::unsigned_abs);
    let m = a[0].max(a[1]).max(a[2]);
    if m == 0 {
        return None;
    }
    // Largest component in [2^30, 2^31).
    let x = match super::divisor::leading_zeros_u32(m) {
        0 => a.map(|c| c >> 1),
        k => a.map(|c| c << (k - 1)),
    };
    // N ∈ [2^60, 3·2^62): no overflow.
    let big = x.map(|c| mul_wide_u32(c, c)).iter().sum::<u64>();
    // n = N / 2^s ∈ [2^30, 2^32) with s even, so √N = √n · 2^(s/2). The
    // shifts by words: a 64-bit shift by a variable amount is a library
    // call on the Cortex-M0 (`__aeabi_llsr`).
    let (hi, lo) = ((big >> 32) as u32, big as u32);
    let (n, half_s) = if hi >= 1 << 30 { (hi, 16) } else { ((hi << 2) | (lo >> 30), 15) };
    let y = rsqrt_q29(n);
    // u = X/√N = X·ρ·2^-16·2^-(s/2); in 16.16: X·y / 2^(29 + s/2), rounded:
    // with sh = 29 + s/2 ≥ 44, ⌊(P + 2^(sh−1)) / 2^sh⌋ is the high word of
    // P + 2^(sh−1) shifted by sh − 32.
    let sh = 29 + half_s - 32;
    let unit = |k: usize| {
        let p = mul_wide_u32(x[k], y) + ((1u64 << 32) << (sh - 1));
        let u = ((p >> 32) as u32 >> sh) as i32; // ≤ 2^16 + 1
        if v[k] < 0 { -u } else { u }
    };
    Some([unit(0), unit(1), unit(2)])
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::math::vec::tests::{Rng, U};

    /// The word shifts of `unit_bits` against the same steps with `u64`
    /// shifts, over vectors of every magnitude (both scalings of `N`).
    #[test]
    fn unit_bits_shifts_by_words_as_u64() {
        /// The unit vector, and whether `N` took the wider scaling.
        fn by_u64(v: [i32; 3]) -> (Option<[i32; 3]>, bool) {
            let a = v.map(i32::unsigned_abs);
            let m = a[0].max(a[1]).max(a[2]);
            if m == 0 {
                return (None, false);
            }
            let x = match m.leading_zeros() {
                0 => a.map(|c| c >> 1),
                k => a.map(|c| c << (k - 1)),
            };
            let big = x.map(|c| c as u64 * c as u64).iter().sum::<u64>();
            let (n, half_s) =
                if big >= 1 << 62 { ((big >> 32) as u32, 16) } else { ((big >> 30) as u32, 15) };
            let y = rsqrt_q29(n);
            let sh = 29 + half_s;
            let u = |k: usize| {
                let u = ((x[k] as u64 * y as u64 + (1 << (sh - 1))) >> sh) as i32;
                if v[k] < 0 { -u } else { u }
            };
            (Some([u(0), u(1), u(2)]), big >= 1 << 62)
        }
        let mut rng = Rng(0x0B17_5E75);
        let (mut wide, mut narrow) = (0, 0);
        for i in 0..200_000u32 {
            let r = rng.next();
            let shift = i % 31;
            let v = [r as i32 >> shift, (r >> 21) as i32 >> shift, (r >> 42) as i32 >> (shift / 2)];
            let v = if i % 7 == 0 { [v[0], 0, 0] } else { v };
            let (want, is_wide) = by_u64(v);
            assert_eq!(unit_bits(v), want, "{v:?}");
            // Both scalings of N must be covered (the zero vector has none).
            match (want, is_wide) {
                (None, _) => {}
                (Some(_), true) => wide += 1,
                (Some(_), false) => narrow += 1,
            }
        }
        assert!(wide > 1000 && narrow > 1000, "{wide} {narrow}");
    }

    #[test]
    fn reciprocal_square_root_within_bound() {
        let mut worst = 0.0f64;
        let mut n = (1u64 << 30) as u32;
        while n < u32::MAX - 4093 {
            let exact = (2f64.powi(32) / f64::from(n)).sqrt() * 2f64.powi(29);
            let got = f64::from(rsqrt_q29(n));
            worst = worst.max((got - exact).abs() / exact);
            n += 4093;
        }
        assert!(worst <= 2f64.powi(-21), "relative {worst:e}");
        assert!(worst > 0.0);
    }

    #[test]
    fn unit_vectors_within_one_step_of_f64() {
        let mut rng = Rng(0x0417);
        let mut worst = 0.0f64;
        for i in 0..300_000u32 {
            let r = rng.next();
            // Lengths from 2^-16 to 2^15 and every ratio of components.
            let v =
                [r as i32 >> (i % 31), (r >> 32) as i32 >> (i / 31 % 31), (rng.next() as i32) >> (i % 17)];
            let v = if i % 97 == 0 { [i32::MIN, v[1], 0] } else { v };
            let Some(u) = unit_bits(v) else {
                assert_eq!(v, [0; 3]);
                continue;
            };
            let l = v.iter().map(|&c| f64::from(c).powi(2)).sum::<f64>().sqrt();
            for k in 0..3 {
                let err = (f64::from(u[k]) * U - f64::from(v[k]) / l).abs();
                worst = worst.max(err);
                assert!(err < U, "{v:?}: {u:?}");
            }
        }
        assert!(worst > U / 4.0, "{worst:e}"); // the test can see an error
        for (v, want) in [([0i32, 0, 0], None), ([0, 0, -5], Some([0, 0, -65536]))] {
            assert_eq!(unit_bits(v), want);
        }
    }

    #[test]
    fn f32_unit_vectors_within_bound_of_f64() {
        let mut rng = Rng(0x0418);
        let bound = 6.0 * 2f64.powi(-24);
        let mut worst = 0.0f64;
        for i in 0..400_000u32 {
            let scale = 2f64.powi((i % 96) as i32 - 48);
            let v = rng.vec3(1.0).map(|c| (f64::from(c) * scale) as f32);
            let u = unit_f32(Vec3::new(v[0], v[1], v[2]));
            let l = v.iter().map(|&c| f64::from(c).powi(2)).sum::<f64>().sqrt();
            if l == 0.0 {
                continue;
            }
            for (k, got) in [u.x, u.y, u.z].into_iter().enumerate() {
                let err = (f64::from(got) - f64::from(v[k]) / l).abs();
                worst = worst.max(err);
                assert!(err <= bound, "{v:?}: {u:?} ({err:e})");
            }
        }
        std::println!("f32 unit vectors: worst {:.2}·2^-24", worst / 2f64.powi(-24));
        assert!(worst > bound / 8.0);
        // Outside the range of the fast form: normalize's answer.
        for v in [[1e-30f32, 0.0, 2e-30], [3e19, -4e19, 0.0], [0.0; 3], [f32::NAN, 1.0, 0.0]] {
            let v = Vec3::new(v[0], v[1], v[2]);
            let (a, b) = (unit_f32(v), v.normalize());
            assert!(a == b || a.x.is_nan() && b.x.is_nan(), "{v:?}");
        }
    }
}
