//! Unit tests for [`crate::depth`]: quantization against exact and `f64`
//! references, depth tests against their definitions, band behaviour.

extern crate std;
use super::*;
use crate::Error;
use core::mem::size_of;
use std::println;

mod band;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        // splitmix64
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

/// `(BITS, MAX)` of every enabled format, read from the trait.
const FORMATS: [(u32, u32); 4] = [
    (Depth8::BITS, Depth8::MAX),
    (Depth16::BITS, Depth16::MAX),
    (Depth24::BITS, Depth24::MAX),
    (Depth32::BITS, Depth32::MAX),
];

/// `quantize_unit` of format with this `MAX`, through the public generic API.
fn unit(max: u32, u: u64) -> u32 {
    match max {
        0xFF => Depth8::to_u32(quantize_unit::<Depth8>(u)),
        0xFFFF => Depth16::to_u32(quantize_unit::<Depth16>(u)),
        0xFF_FFFF => Depth24::to_u32(quantize_unit::<Depth24>(u)),
        _ => Depth32::to_u32(quantize_unit::<Depth32>(u)),
    }
}

/// `quantize_f32` of format with this `MAX`, through the public generic API.
fn f32q(max: u32, d: f32) -> Result<u32, Error> {
    match max {
        0xFF => quantize_f32::<Depth8>(d).map(Depth8::to_u32),
        0xFFFF => quantize_f32::<Depth16>(d).map(Depth16::to_u32),
        0xFF_FFFF => quantize_f32::<Depth24>(d).map(Depth24::to_u32),
        _ => quantize_f32::<Depth32>(d).map(Depth32::to_u32),
    }
}

/// Exact `round(u · max / 2^32)`, ties up, in `u128`.
fn unit_exact(max: u32, u: u64) -> u32 {
    ((2 * u.min(UNIT_ONE) as u128 * max as u128 + (1u128 << 32)) >> 33) as u32
}

/// `f64` reference `round(d · max)` (correct when the product is exact).
fn f64_ref(max: u32, d: f64) -> u32 {
    (d * max as f64).round() as u32
}

/// True if `r` is exactly `round(d · max)` (ties up) for `0 ≤ d ≤ 1`,
/// checked as `2r − 1 ≤ 2·d·max < 2r + 1` in integers, with `d` decoded from
/// its `f64` form (independently of the `f32` decoding under test).
fn correctly_rounded(d: f32, max: u32, r: u32) -> bool {
    let b = (d as f64).to_bits();
    if b == 0 {
        return r == 0;
    }
    let (mut m, mut e) = (b & ((1 << 52) - 1) | (1 << 52), (b >> 52) as i32 - 1075);
    let tz = m.trailing_zeros();
    m >>= tz;
    e += tz as i32; // d = m · 2^e, m odd
    if e >= 0 {
        return (m << e) as u32 == 1 && r == max; // d = 1
    }
    let twice = 2 * m as u128 * max as u128; // 2 · d · max · 2^-e, below 2^58
    if -e >= 64 {
        return r == 0; // 2 · d · max < 2^58 / 2^64 < 1
    }
    let unit = 1u128 << -e;
    let lo = (2 * r as u128).saturating_sub(1) * unit;
    let hi = (2 * r as u128 + 1) * unit;
    (r == 0 || lo <= twice) && twice < hi
}

#[test]
fn bytes_table_for_320_by_16() {
    fn bytes<F: DepthFormat>() -> usize {
        let b = DepthBand::<F, 320, 16>::BYTES;
        assert_eq!(b, 320 * 16 * size_of::<F::Storage>());
        assert_eq!(b, size_of::<DepthBand<F, 320, 16>>());
        b
    }
    let table = [
        ("NoDepth", bytes::<NoDepth>()),
        ("Depth8", bytes::<Depth8>()),
        ("Depth16", bytes::<Depth16>()),
        ("Depth24", bytes::<Depth24>()),
        ("Depth32", bytes::<Depth32>()),
    ];
    for (name, b) in table {
        println!("{name}: {b} bytes per 320 x 16 band");
    }
    // The numbers in the module docs' table.
    assert_eq!(table.map(|t| t.1), [0, 5120, 10240, 20480, 20480]);
    assert_eq!(size_of::<DepthBand<NoDepth, 320, 16>>(), 0);
    assert_eq!(size_of::<DepthBand<NoDepth, 4096, 4096>>(), 0);
    assert_eq!(size_of::<NoDepth>() + size_of::<Depth8>() + size_of::<Depth32>(), 0);
}

#[test]
fn format_constants() {
    fn check<F: DepthFormat>(bits: u32) {
        assert_eq!(F::BITS, bits);
        assert_eq!(F::ENABLED, bits > 0);
        assert_eq!(F::MAX as u64, (1u64 << bits) - 1);
        assert_eq!(F::to_u32(F::FAR), F::MAX);
        assert_eq!(F::to_u32(F::from_u32(u32::MAX)), F::MAX); // clamps
        assert_eq!(F::to_u32(F::from_u32(0)), 0);
        assert_eq!(F::to_u32(F::from_u32(F::MAX / 3)), F::MAX / 3);
        assert!(bits == 0 || F::from_u32(F::MAX - 1) < F::FAR);
        assert_eq!(DepthBand::<F, 2, 2>::new().get(1, 1), Some(F::MAX));
    }
    check::<NoDepth>(0);
    check::<Depth8>(8);
    check::<Depth16>(16);
    check::<Depth24>(24);
    check::<Depth32>(32);
}

#[test]
fn quantize_unit_every_code_boundary() {
    // For 8, 16 and 24 bits, every code k and the first u rounding to k + 1:
    // t = ceil((2k + 1) · 2^31 / MAX). q(t − 1) = k and q(t) = k + 1 for all k,
    // with monotonicity (checked below) proves every input correct.
    let mut rng = Rng(7);
    for (bits, max) in FORMATS {
        let (codes, sampled): (u64, bool) = if bits <= 24 { (max as u64, false) } else { (1_000_000, true) };
        let mut checked = 0u64;
        for i in 0..codes {
            let k = if sampled { rng.below(max as u64) } else { i };
            let num = (2 * k as u128 + 1) << 31;
            let t = num.div_ceil(max as u128) as u64;
            assert_eq!(unit(max, t - 1), k as u32, "bits {bits} k {k}");
            assert_eq!(unit(max, t), k as u32 + 1, "bits {bits} k {k}");
            checked += 1;
        }
        println!("quantize_unit {bits}-bit: {checked} code boundaries exact ({})", {
            if sampled { "random codes" } else { "all codes" }
        });
    }
}

#[test]
fn quantize_unit_random_sweep_and_endpoints() {
    let mut rng = Rng(42);
    for (bits, max) in FORMATS {
        let mut f64_equal = 0u64;
        const N: u64 = 1_000_000;
        for _ in 0..N {
            let u = rng.below(UNIT_ONE + 1);
            let q = unit(max, u);
            assert_eq!(q, unit_exact(max, u), "bits {bits} u {u}");
            let r = f64_ref(max, u as f64 / UNIT_ONE as f64);
            assert!(q.abs_diff(r) <= 1, "bits {bits} u {u}: {q} vs f64 {r}");
            f64_equal += u64::from(q == r);
        }
        // Monotonic over a dense sweep (step 4093, about 1.05 million points).
        let (mut prev, mut n, mut u) = (0, 0u64, 0u64);
        while u <= UNIT_ONE {
            let q = unit(max, u);
            assert!(q >= prev, "bits {bits} not monotonic at {u}");
            (prev, n, u) = (q, n + 1, u + 4093);
        }
        assert_eq!((unit(max, 0), unit(max, UNIT_ONE)), (0, max));
        assert_eq!((unit(max, UNIT_ONE + 1), unit(max, u64::MAX)), (max, max)); // clamp
        println!(
            "quantize_unit {bits}-bit: {N} random = exact u128, {f64_equal} equal to f64 round \
             (rest within 1 LSB); {n} sweep points monotonic"
        );
    }
    let () = quantize_unit::<NoDepth>(UNIT_ONE / 2);
}

/// Checks `quantize_f32` at `d` for every format: exact, within 1 LSB of
/// `f64` (equal for ≤ 24 bits, where the `f64` product is exact), and not
/// below `prev` (monotonic). Returns whether the 32-bit result equalled `f64`.
fn check_f32(d: f32, prev: &mut [u32; 4]) -> bool {
    let mut equal32 = true;
    for (i, (bits, max)) in FORMATS.into_iter().enumerate() {
        let q = f32q(max, d).unwrap();
        assert!(correctly_rounded(d, max, q), "bits {bits} d {d:e} -> {q}");
        let r = f64_ref(max, d as f64);
        if bits <= 24 {
            assert_eq!(q, r, "bits {bits} d {d:e}");
        } else {
            assert!(q.abs_diff(r) <= 1);
            equal32 = q == r;
        }
        assert!(q >= prev[i], "bits {bits} not monotonic at {d:e}");
        prev[i] = q;
    }
    equal32
}

#[test]
fn quantize_f32_dense_and_random() {
    // Every 97th f32 bit pattern in [0, 1], in increasing order: ~11 million values.
    let (mut prev, mut n, mut eq32) = ([0; 4], 0u64, 0u64);
    let one = 1.0f32.to_bits();
    let mut b = 0u32;
    while b <= one + 97 {
        eq32 += u64::from(check_f32(f32::from_bits(b.min(one)), &mut prev));
        (n, b) = (n + 1, b + 97);
    }
    assert_eq!(prev, FORMATS.map(|f| f.1));
    // 10^6 uniform random d (24 random bits) and 10^6 random bit patterns.
    let mut rng = Rng(3);
    let mut r = 0u64;
    for i in 0..2_000_000u64 {
        let d = if i & 1 == 0 {
            rng.below(1 << 24) as f32 / (1 << 24) as f32
        } else {
            f32::from_bits(rng.below(one as u64 + 1) as u32)
        };
        eq32 += u64::from(check_f32(d, &mut [0; 4]));
        r += 1;
    }
    println!(
        "quantize_f32: {n} swept + {r} random values, all 4 formats exactly rounded, \
         8/16/24-bit equal to f64 round, 32-bit equal to f64 in {eq32} of {} (rest within 1 LSB)",
        n + r
    );
}

#[test]
fn quantize_f32_around_every_code_boundary() {
    // Each boundary (k + 1/2) / MAX and the two f32 values either side, for
    // every code of 8 and 16 bits and 10^6 random codes of 24 and 32 bits
    // (where one f32 step near 1 is 1 and 256 codes: only exactness and order
    // are checked there).
    let mut rng = Rng(11);
    for (bits, max) in FORMATS {
        let (mut n, codes) = (0u64, if bits <= 16 { max as u64 } else { 1_000_000 });
        for i in 0..codes {
            let k = if bits <= 16 { i } else { rng.below(max as u64) };
            let mid = ((k as f64 + 0.5) / max as f64) as f32;
            let mut prev = 0;
            for b in mid.to_bits() - 2..=mid.to_bits() + 2 {
                let q = f32q(max, f32::from_bits(b)).unwrap();
                assert!(correctly_rounded(f32::from_bits(b), max, q), "bits {bits} k {k}");
                assert!(q >= prev && (bits > 16 || q.abs_diff(k as u32) <= 1));
                (prev, n) = (q, n + 1);
            }
        }
        println!("quantize_f32 {bits}-bit: {n} values next to code boundaries exact");
    }
}

#[test]
fn quantize_f32_endpoints_clamping_and_errors() {
    for (_, max) in FORMATS {
        for bad in [f32::NAN, -f32::NAN, f32::from_bits(0x7FC0_1234), f32::INFINITY, f32::NEG_INFINITY] {
            assert_eq!(f32q(max, bad), Err(Error::NonFiniteCoordinate));
        }
        for low in [0.0, -0.0, -1e-45, -0.5, -1.0, f32::MIN, 1e-45, 1e-30] {
            assert_eq!(f32q(max, low), Ok(0), "{low:e}");
        }
        for high in [1.0, 1.0 + f32::EPSILON, 2.0, f32::MAX] {
            assert_eq!(f32q(max, high), Ok(max), "{high:e}");
        }
        // Where d is a multiple of 2^-32, quantize_f32(d) = quantize_unit(d · 2^32).
        let mut rng = Rng(max as u64);
        for _ in 0..1000 {
            let u = rng.below(1 << 24) << rng.below(9); // ≤ 24 significant bits: exact in f32
            assert_eq!(f32q(max, u as f32 / UNIT_ONE as f32), Ok(unit(max, u)));
        }
    }
    assert_eq!(quantize_f32::<Depth8>(0.5), Ok(128)); // 127.5: ties up
    assert_eq!(quantize_f32::<Depth24>(1.0 - f32::EPSILON / 2.0), Ok(0xFF_FFFE));
    assert_eq!(quantize_f32::<Depth32>(1.0 - f32::EPSILON / 2.0), Ok(u32::MAX - 0x100));
    assert!(quantize_f32::<NoDepth>(0.5).is_ok());
    assert_eq!(quantize_f32::<NoDepth>(f32::NAN), Err(Error::NonFiniteCoordinate));
}

/// Every one of the 1,065,353,217 `f32` values in `[0, 1]`, every format:
/// exact and monotonic. Slow; run with `cargo test -- --ignored`.
#[test]
#[ignore]
fn quantize_f32_exhaustive() {
    let mut prev = [0; 4];
    let mut eq32 = 0u64;
    for b in 0..=1.0f32.to_bits() {
        eq32 += u64::from(check_f32(f32::from_bits(b), &mut prev));
    }
    println!("quantize_f32 exhaustive: {} values; 32-bit equal to f64 in {eq32}", 1.0f32.to_bits() + 1);
}
