use super::*;
use crate::test_rng::Rng;

#[test]
fn fixed_rounds_down_for_both_signs() {
    assert_eq!(fixed(3, 2), 3 * SUB / 2);
    assert_eq!(fixed(-3, 2), -3 * SUB / 2);
    assert_eq!(fixed(1, 3), SUB / 3);
    assert_eq!(fixed(-1, 3), -(SUB / 3) - 1);
}

#[test]
fn fixed_is_the_exact_floor_over_its_range() {
    // ⌊n · 2^FB / d⌋ in i128 against the one-division form, at the
    // range's ends (|n| < 2^60, 0 < d < 2^31) and in between.
    let ns = [0i64, 1, -1, 7, -7, (1 << 59) + 12345, -(1 << 59) - 777, (1 << 60) - 1, -(1 << 60) + 1];
    let ds = [1i64, 2, 3, 16, 255, 65_537, (1 << 29) + 3, (1 << 31) - 1];
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let check = |n: i64, d: i64| {
        let exact = (i128::from(n) << FB).div_euclid(i128::from(d));
        // Where the result fits (`|n / d| < 2^40`: the crossings are
        // coordinates, below 2^30 subpixels).
        if exact.abs() < 1 << 62 {
            assert_eq!(i128::from(fixed(n, d)), exact, "{n} / {d}");
        }
    };
    for &n in &ns {
        for &d in &ds {
            check(n, d);
        }
    }
    for _ in 0..20_000 {
        let x = rng.next();
        let n = (x as i64) >> 4; // |n| < 2^59
        let d = ((x >> 33) as i64 & ((1 << 31) - 1)).max(1) >> (x % 31);
        check(n, d.max(1));
        // The 32-bit path: |n| < 2^31, d < 2^20, and its edges.
        check(n >> 29, (d >> 11).max(1));
        check(n >> 28, (d >> (11 + x % 9)).max(1));
    }
    for (n, d) in [(i64::from(i32::MAX), (1 << 20) - 1), (i64::from(i32::MIN), (1 << 20) - 1), (-1, 1 << 20)]
    {
        check(n, d);
        check(n, d - 1);
    }
}

#[test]
fn stepped_crossings_are_the_divided_ones() {
    // Random edges, near and far, steep and shallow, both directions:
    // each column crossing stepped from the first equals the direct
    // ⌊n · 2^FB / d⌋ at that column.
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let mut rnd = |bits: u32| {
        let x = rng.next();
        ((x >> 11) as i64 & ((1 << bits) - 1)) - (1 << (bits - 1))
    };
    for i in 0..3000 {
        let far = if i % 3 == 0 { 27 } else { 12 };
        let (x0, y0) = (rnd(far) as i32, rnd(far) as i32);
        let (dx, dy) = (rnd(if i % 2 == 0 { 6 } else { far }) as i32, rnd(far).abs().max(1) as i32);
        if dx == 0 {
            continue;
        }
        let e = Edge { x0, y0, x1: x0 + dx, y1: y0 + dy, dir: 1 };
        // A strip the edge crosses, and the columns inside its x extent there.
        let s0 = i64::from(y0) + rnd(far).abs() % i64::from(dy);
        let o = Origin { ox: rnd(far), s0 };
        let direct = |xs: i64| {
            let (rx0, ry0, ddx, ddy) = o.rel(&e);
            let sg = ddx.signum();
            fixed(ry0 * ddx * sg + (xs - rx0) * ddy * sg, ddx * sg)
        };
        let (lo, hi) = (i64::from(x0.min(x0 + dx)) - o.ox, i64::from(x0.max(x0 + dx)) - o.ox);
        let first = lo.div_euclid(16) * 16 + 16;
        let mut c = o.crossings(&e, first);
        let mut xs = first;
        while xs < hi && xs < first + 16 * 40 {
            assert_eq!((c.q, c.r >= 0 && c.r < c.d), (direct(xs), true), "edge {e:?}, x {xs}");
            c.advance();
            xs += 16;
        }
    }
}

#[test]
fn even_odd_folds_the_winding_integral() {
    assert_eq!(alpha(FULL, FillRule::EvenOdd), 255);
    assert_eq!(alpha(2 * FULL, FillRule::EvenOdd), 0);
    assert_eq!(alpha(3 * FULL / 2, FillRule::EvenOdd), 128);
    assert_eq!(alpha(-2 * FULL, FillRule::NonZero), 255);
}
