//! Lines: `line_pixels` against an independent `f64` midpoint reference and
//! against embedded-graphics 0.8's Bresenham `Line`.
//!
//! The exact-arithmetic check of the rule lives in `src/raster/line.rs`; these tests
//! compare with code that shares nothing with it.

use embedded_graphics::geometry::Point;
use embedded_graphics::primitives::{Line, PointsIter};
use microraster::line::{line_pixels, line_rows};
use microraster::{ClipRect, SubPoint};

/// Xorshift64: deterministic test-case generation without dev-dependencies.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// In `lo..hi`, `hi > lo`.
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo) as u64) as i64
    }
}

/// Pixels of one line as a per-major-index table over `c0..c1`, checking that
/// no major index is hit twice and none lies outside.
fn by_major(px: &[(i32, i32)], x_major: bool, c0: i32, c1: i32) -> Vec<Option<i32>> {
    let mut t = vec![None; (c1 - c0).max(0) as usize];
    for &(x, y) in px {
        let (maj, min) = if x_major { (x, y) } else { (y, x) };
        assert!((c0..c1).contains(&maj), "major index {maj} outside {c0}..{c1}");
        let slot = &mut t[(maj - c0) as usize];
        assert!(slot.is_none(), "major index {maj} hit twice");
        *slot = Some(min);
    }
    t
}

/// Totals of the f64 comparison: [lines, pixels, ties seen, tie mismatches, unexplained].
fn float_case<const S: u32>(rng: &mut Rng, totals: &mut [u64; 5]) {
    let one = 1i64 << S;
    // Mostly short lines around the clip area, some long ones. The far end
    // stays within ±2^15 px so that f64 evaluation error (≈ 2^-36 px) is far
    // below the 1e-9 px tie tolerance; the full ±2^28-subpixel range is
    // covered by the exact unit tests.
    let far = (1i64 << 15).min(1 << (28 - S)) * one;
    let coord = |rng: &mut Rng| match rng.next() % 6 {
        0 => rng.range(-far, far + 1),
        1 => rng.range(-20, 420) * one + one / 2, // pixel centre (boundary when S = 0)
        2 => rng.range(-20, 420) * one,           // pixel boundary
        _ => rng.range(-20 * one, 420 * one),
    };
    let (a, b) = loop {
        let a = SubPoint::<S>::new(coord(rng) as i32, coord(rng) as i32);
        let b = SubPoint::<S>::new(coord(rng) as i32, coord(rng) as i32);
        if let (Ok(a), Ok(b)) = (a, b) {
            break (a, b);
        }
    };
    let (x0, y0) = (rng.range(-10, 300) as i32, rng.range(-10, 300) as i32);
    let clip = ClipRect::new(x0, y0, x0 + rng.range(-5, 300) as i32, y0 + rng.range(-5, 300) as i32);
    let got: Vec<_> = line_pixels(a, b, clip).collect();
    if let Some(&(_, y)) = got.iter().find(|p| line_rows(a, b).is_none_or(|(r0, r1)| p.1 < r0 || p.1 > r1)) {
        panic!("row {y} outside line_rows {:?}", line_rows(a, b));
    }

    let ((ax, ay), (bx, by)) = (a.to_f64(), b.to_f64());
    let x_major = (b.x() - a.x()).abs() >= (b.y() - a.y()).abs();
    let (ua, va, ub, vb) = if x_major { (ax, ay, bx, by) } else { (ay, ax, by, bx) };
    let (c0, c1, k0, k1) = if x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let ours = by_major(&got, x_major, c0, c1);
    totals[0] += 1;
    totals[1] += got.len() as u64;
    for (maj, mine) in (c0..c1).zip(ours) {
        let c = f64::from(maj) + 0.5;
        let in_segment = if ub > ua { ua <= c && c < ub } else { ub < c && c <= ua };
        if !in_segment {
            totals[4] += u64::from(mine.is_some());
            continue;
        }
        let v = va + (c - ua) * ((vb - va) / (ub - ua));
        let m = v.floor();
        let r = v.round();
        let tie = (v - r).abs() <= 1e-9;
        totals[2] += u64::from(tie);
        let want = (m >= f64::from(k0) && m < f64::from(k1)).then_some(m as i32);
        if mine == want {
            continue;
        }
        // A tie: v is (within f64 error) on the boundary between rows r-1 and r;
        // the exact rule takes r, if it is visible.
        let exact_pick = (r >= f64::from(k0) && r < f64::from(k1)).then_some(r as i32);
        totals[if tie && mine == exact_pick { 3 } else { 4 }] += 1;
    }
}

#[test]
fn matches_f64_midpoint_reference() {
    let mut rng = Rng(0x5EED_1E55_0F64_0001);
    let mut all = [0u64; 5];
    for s in [0u32, 2, 4, 8] {
        let mut t = [0u64; 5];
        for _ in 0..30_000 {
            match s {
                0 => float_case::<0>(&mut rng, &mut t),
                2 => float_case::<2>(&mut rng, &mut t),
                4 => float_case::<4>(&mut rng, &mut t),
                _ => float_case::<8>(&mut rng, &mut t),
            }
        }
        println!(
            "f64 reference, S={s}: {} lines, {} pixels, {} ties, {} tie mismatches, {} unexplained",
            t[0], t[1], t[2], t[3], t[4]
        );
        all.iter_mut().zip(t).for_each(|(a, t)| *a += t);
    }
    assert!(all[0] >= 100_000 && all[1] > 1_000_000, "too few cases: {all:?}");
    assert!(all[2] > 1000, "ties not exercised: {all:?}");
    assert_eq!(all[4], 0, "unexplained mismatches against the f64 reference");
}

/// How embedded-graphics breaks ties, found by reading its
/// `primitives/line/bresenham.rs` and confirmed by this test: it starts at the
/// start point with error 0, adds `2·minor_delta` per major step and takes a
/// minor step only when the error *exceeds* `major_delta`. So at an exact tie
/// (the line passes through the boundary midway between two candidate pixel
/// centres) it keeps the pixel nearer the start point's minor coordinate.
/// microraster takes the larger index instead, so the two differ exactly at
/// ties on lines whose minor coordinate increases from start to end; on lines
/// whose minor coordinate decreases both pick the same pixel. (It also makes
/// y the major axis when `|dy| = |dx|`; an exact diagonal has no ties, so that
/// does not change any pixel.)
///
/// Totals: [lines, compared picks, tie differences, ties that agree].
fn eg_case<const S: u32>(p0: (i32, i32), p1: (i32, i32), totals: &mut [u64; 4]) {
    let (a, b) = (SubPoint::<S>::pixel_center(p0.0, p0.1), SubPoint::<S>::pixel_center(p1.0, p1.1));
    let (a, b) = (a.expect("in range"), b.expect("in range"));
    let clip = ClipRect::new(0, 0, 4096, 4096);
    let ours: Vec<_> = line_pixels(a, b, clip).collect();
    let eg: Vec<_> =
        Line::new(Point::new(p0.0, p0.1), Point::new(p1.0, p1.1)).points().map(|p| (p.x, p.y)).collect();
    let (dx, dy) = (p1.0 - p0.0, p1.1 - p0.1);
    let x_major = dx.abs() >= dy.abs();
    let (u0, du, dv) = if x_major { (p0.0, dx, dy) } else { (p0.1, dy, dx) };
    totals[0] += 1;
    if du == 0 {
        // Zero length: embedded-graphics draws the single point, we draw nothing.
        assert_eq!((ours.len(), eg.len()), (0, 1));
        return;
    }
    // One pick per major index on both sides: eg over u0..=u1, ours over the
    // half-open u0..u1, so eg has exactly one extra pick, the end pixel.
    let lo = u0.min(u0 + du);
    let (mine, theirs) =
        (by_major(&ours, x_major, lo, lo + du.abs() + 1), by_major(&eg, x_major, lo, lo + du.abs() + 1));
    assert_eq!(eg.len(), ours.len() + 1);
    assert_eq!(eg.last(), Some(&p1), "embedded-graphics ends at the end point");
    assert!(!ours.contains(&p1), "half-open: the end pixel is not drawn");
    for k in 0..du.abs() {
        let i = (u0 + k * du.signum() - lo) as usize;
        let (m, t) = (mine[i].expect("ours: one pick per index"), theirs[i].expect("eg: one pick per index"));
        // Exact minor offset from the start centre is dv·k/|du|; a tie is an
        // offset of (j + 1/2) pixels, i.e. 2·|dv|·k ≡ |du| (mod 2|du|).
        let tie = (2 * i64::from(dv.abs()) * i64::from(k)) % (2 * i64::from(du.abs())) == i64::from(du.abs());
        totals[1] += 1;
        if m == t {
            totals[3] += u64::from(tie);
        } else {
            assert!(
                tie && dv > 0 && t == m - 1,
                "non-tie difference {p0:?}->{p1:?} at k={k}: ours {m}, eg {t}"
            );
            totals[2] += 1;
        }
    }
}

fn eg_suite<const S: u32>(rng: &mut Rng) -> [u64; 4] {
    let mut t = [0u64; 4];
    // Every pair of end points in a 9×9 grid: all octants, all slopes up to 8.
    let grid: Vec<(i32, i32)> = (0..81).map(|i| (20 + i % 9, 30 + i / 9)).collect();
    for &p0 in &grid {
        for &p1 in &grid {
            eg_case::<S>(p0, p1, &mut t);
        }
    }
    // Random lines within ±300 px of a point well inside the frame.
    for _ in 0..20_000 {
        let p0 = (rng.range(400, 700) as i32, rng.range(400, 700) as i32);
        let p1 = (p0.0 + rng.range(-300, 301) as i32, p0.1 + rng.range(-300, 301) as i32);
        eg_case::<S>(p0, p1, &mut t);
    }
    t
}

#[test]
fn matches_embedded_graphics_except_end_pixel_and_ties() {
    let mut rng = Rng(0x00E6_0802);
    for (s, t) in [(1, eg_suite::<1>(&mut rng)), (4, eg_suite::<4>(&mut rng)), (8, eg_suite::<8>(&mut rng))] {
        println!(
            "embedded-graphics, S={s}: {} lines, {} picks compared, {} tie differences, {} ties agreeing",
            t[0], t[1], t[2], t[3]
        );
        assert_eq!(t[0], 81 * 81 + 20_000);
        assert!(t[1] > 1_000_000, "too few picks compared");
        // Both tie cases must actually occur for the test to mean anything.
        assert!(t[2] > 1000 && t[3] > 1000, "ties not exercised: {t:?}");
    }
}
