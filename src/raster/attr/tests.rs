//! Tests of the plane set-up (`attr`): planes through the vertex values,
//! the wide and narrow frames, the fast and split `i64` paths against the
//! `i128` division, and planes set up for one span.

use super::*;

/// xorshift64: a closure giving `bits`-bit signed values (`bits ≥ 1`).
fn signed_bits(mut seed: u64) -> impl FnMut(u32) -> i64 {
    move |bits| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> (64 - bits)) as i64 - (1 << (bits - 1))
    }
}

#[test]
fn plane_hits_vertex_values_and_steps_linearly() {
    // A right triangle 8 px wide at S = 0 (internal unit = 1/2 px);
    // pixel centres (0.5, 0.5) etc. Reference pixel (0, 0).
    let frame = PlaneFrame { v: [(0, 0), (16, 0), (0, 16)], shift: 1 };
    let f = 1i64 << COLOR_FRAC;
    let p = Plane::new(&frame, [0, 255 * f, 100 * f], 0, 0).unwrap();
    // 255 levels over 8 px in x, 100 over 8 px in y.
    assert_eq!(p.step_x(), 255 * f / 8);
    assert_eq!(p.at(0, 1) - p.at(0, 0), 100 * f / 8);
    // At centre (0.5, 0.5): 255·0.5/8 + 100·0.5/8 = 22.1875 exactly.
    assert_eq!(p.at(0, 0), (22.1875 * f as f64) as i64);
    assert!(Plane::new(&PlaneFrame { v: [(0, 0), (4, 4), (8, 8)], shift: 1 }, [0; 3], 0, 0).is_none());
}

#[test]
fn wide_setup_agrees_with_narrow_and_wraps_correctly() {
    // A huge sliver: gradients overflow i64, values inside stay exact.
    let frame = PlaneFrame { v: [(1, 1), (1 << 30, 3), (5, (1 << 30) + 7)], shift: 9 };
    let vals = [1i64 << 56, 0, -(1 << 56)];
    let p = Plane::new(&frame, vals, 3, 2).unwrap();
    // f64 barycentric value at pixel (3, 2)'s centre, internal (1792, 1280).
    let [(x0, y0), (x1, y1), (x2, y2)] = frame.v.map(|(x, y)| (x as f64, y as f64));
    let (px, py) = (1792.0, 1280.0);
    let det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    let l1 = ((px - x0) * (y2 - y0) - (py - y0) * (x2 - x0)) / det;
    let l2 = ((x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)) / det;
    let v = vals.map(|v| v as f64);
    let exact = v[0] + l1 * (v[1] - v[0]) + l2 * (v[2] - v[0]);
    // Bound 2^13 units (module docs) plus f64's own rounding at 2^56 (2^5).
    assert!((p.at(3, 2) as f64 - exact).abs() <= 8192.0 + 64.0);
    assert!((p.at(4, 2) as f64 - exact - p.step_x() as f64).abs() <= 8192.0 + 64.0);
}

/// The `i64`/reciprocal path gives exactly the `i128` division's planes.
#[test]
fn fast_setup_is_exact() {
    let mut next = signed_bits(0x2545_f491_4f6c_dd1du64);
    for i in 0..200_000 {
        let cb = 2 + (i % 29) as u32;
        let v = [0; 3].map(|_| (next(cb), next(cb)));
        let frame = PlaneFrame { v, shift: 1 + (i % 9) as u32 };
        let vb = 2 + (i % 56) as u32;
        let vals = [0; 3].map(|_| next(vb));
        let (rx, ry) = ((next(12) & 4095) as i32, (next(12) & 4095) as i32);
        let Some(p) = Plane::new(&frame, vals, rx, ry) else { continue };
        // Reference: everything in i128.
        let [(x0, y0), (x1, y1), (x2, y2)] = v.map(|(x, y)| (x as i128, y as i128));
        let det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        let (d1, d2) = ((vals[1] - vals[0]) as i128, (vals[2] - vals[0]) as i128);
        let (nx, ny) = (d1 * (y2 - y0) - d2 * (y1 - y0), d2 * (x1 - x0) - d1 * (x2 - x0));
        let one = 1i128 << frame.shift;
        let (px, py) = (rx as i128 * one + one / 2 - x0, ry as i128 * one + one / 2 - y0);
        assert_eq!(p.gx, div_round_i128(nx * one, det) as i64, "{frame:?} {vals:?}");
        assert_eq!(p.gy, div_round_i128(ny * one, det) as i64, "{frame:?} {vals:?}");
        let off = div_round_i128(nx * px + ny * py, det) as i64;
        assert_eq!(p.base, vals[0].wrapping_add(off), "{frame:?} {vals:?}");
    }
}

/// A plane's numerator `nx` (`gx = nx·2^shift/det`) in `i128`, the tests' reference.
fn exact_nx(setup: &PlaneSetup, d1: i64, d2: i64) -> i128 {
    d1 as i128 * setup.ex.0 as i128 - d2 as i128 * setup.ex.1 as i128
}

/// The split `i64` set-up gives the `i128` one's planes wherever it
/// applies, and applies to the deep-subpixel planes it is for.
#[test]
fn split_setup_is_exact() {
    let mut next = signed_bits(0x6A09_E667_F3BC_C908u64);
    let (mut split, mut deep) = (0u32, 0u32);
    for i in 0..200_000 {
        let cb = 2 + (i % 27) as u32;
        let v = [0; 3].map(|_| (next(cb), next(cb)));
        let frame = PlaneFrame { v, shift: 1 + (i % 9) as u32 };
        let (d1, d2) = (next(2 + (i % 58) as u32), next(2 + (i % 57) as u32));
        let (rx, ry) = ((next(12) & 4095) as i32, (next(12) & 4095) as i32);
        let Some(setup) = PlaneSetup::new(&frame, rx, ry) else { continue };
        let Some(got) = setup.plane_split(d1, d2) else { continue };
        assert_eq!(got, setup.plane_wide(d1, d2), "{frame:?} {d1} {d2} {rx} {ry}");
        split += 1;
        // Beyond the fast path's reach: its products would overflow.
        deep += u32::from(exact_nx(&setup, d1, d2).unsigned_abs() << setup.shift > i64::MAX as u128);
    }
    assert!(split > 50_000 && deep > 4_000, "{split} split, {deep} beyond the fast path");
    // Every frame of coordinates 0..=3 and small value differences: the
    // ties (a quotient of exactly ±½, ±1½, ...) of small determinants.
    let mut ties = 0u32;
    for code in 0..4096u32 {
        let c = |k: u32| i64::from((code >> (2 * k)) & 3);
        let v = [(c(0), c(1)), (c(2), c(3)), (c(4), c(5))];
        for shift in 1..=2 {
            let Some(setup) = PlaneSetup::new(&PlaneFrame { v, shift }, 0, 0) else { continue };
            for (d1, d2) in (-4..=4).flat_map(|a| (-4..=4).map(move |b| (a, b))) {
                let got = setup.plane_split(d1, d2).expect("small values split");
                assert_eq!(got, setup.plane_wide(d1, d2), "{v:?} {shift} {d1} {d2}");
                let nx = exact_nx(&setup, d1, d2);
                ties += u32::from((2 * (nx << shift)).rem_euclid(2 * setup.det as i128) == setup.det as i128);
            }
        }
    }
    assert!(ties > 1_000, "{ties} ties");
}

/// Planes set up for one span sample it exactly as full planes do:
/// at its start, and stepped along it.
#[test]
fn span_only_planes_sample_the_span_exactly() {
    let mut next = signed_bits(0x1234_5678_9ABC_DEF1u64);
    let mut skipped = [0; 2];
    for i in 0..100_000 {
        let v = [0; 3].map(|_| (next(8) + 64, next(8) + 64));
        let frame = PlaneFrame { v, shift: 4 };
        let vals = [0; 3].map(|_| next(2 + (i % 33)));
        let (rx, ry) = ((v[0].0 >> 4) as i32, (v[0].1 >> 4) as i32);
        let Some(full) = PlaneSetup::new(&frame, rx, ry) else { continue };
        // Spans at and around the reference pixel, one pixel or longer.
        let (x, y) = (rx + (next(3) as i32 / 2), ry + (next(3) as i32 / 2));
        let len = 1 + (next(3) & 3) as u32 * (i % 2);
        let mut only = full;
        only.sampled_only_on(x, y, len);
        skipped[0] += !only.need.0 as u32;
        skipped[1] += !only.need.1 as u32;
        let (a, b) = (full.plane(vals), only.plane(vals));
        let (mut va, mut vb) = (a.at(x, y), b.at(x, y));
        for _ in 0..len {
            assert_eq!(va, vb, "{frame:?} {vals:?} {x} {y} {len}");
            assert_eq!(a.at_low32(x + 9, y - 7), a.at(x + 9, y - 7) as u32);
            (va, vb) = (va.wrapping_add(a.step_x()), vb.wrapping_add(b.step_x()));
        }
    }
    assert!(skipped[0] > 5_000 && skipped[1] > 5_000, "{skipped:?}");
}
