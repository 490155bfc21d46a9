//! Tests of `line`: every pixel checked against the rule of its module docs in
//! exact rational arithmetic, plus direction, polyline and degenerate cases.
extern crate std;
use super::*;
use std::vec::Vec;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// Uniform-ish in `lo..hi` (hi > lo).
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo) as u64) as i64
    }
}

fn floor_i128(n: i128, q: i128) -> i128 {
    if q < 0 { (-n).div_euclid(-q) } else { n.div_euclid(q) }
}

/// The rule, evaluated directly in exact i128 rational arithmetic at every
/// major index of the clip rectangle.
fn reference(a: (i32, i32), b: (i32, i32), s: u32, clip: ClipRect) -> Vec<(i32, i32)> {
    let (dx, dy) = (i128::from(b.0) - i128::from(a.0), i128::from(b.1) - i128::from(a.1));
    let x_major = dx.abs() >= dy.abs();
    let (ua, va, ub, du, dv) = if x_major { (a.0, a.1, b.0, dx, dy) } else { (a.1, a.0, b.1, dy, dx) };
    let (ua, va, ub) = (i128::from(ua), i128::from(va), i128::from(ub));
    let (c0, c1, k0, k1) = if x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let majors: Vec<i32> = if du > 0 { (c0..c1).collect() } else { (c0..c1).rev().collect() };
    let mut out = Vec::new();
    for m in majors {
        let c = (2 * i128::from(m) + 1) << s; // doubled centre
        let inside = if du > 0 { 2 * ua <= c && c < 2 * ub } else { 2 * ub < c && c <= 2 * ua };
        if !inside {
            continue;
        }
        let minor = floor_i128(2 * va * du + dv * (c - 2 * ua), (2 * du) << s);
        if (i128::from(k0)..i128::from(k1)).contains(&minor) {
            let minor = minor as i32;
            out.push(if x_major { (m, minor) } else { (minor, m) });
        }
    }
    out
}

/// A random coordinate of one of several kinds (near the clip area, pixel
/// centre, pixel boundary, anywhere in range, moderately far).
fn coord(rng: &mut Rng, s: u32) -> i64 {
    let one = 1i64 << s;
    match rng.next() % 8 {
        0 | 1 => rng.range(-40 * one, 600 * one),
        2 | 3 => rng.range(-40, 600) * one + one / 2,
        4 | 5 => rng.range(-40, 600) * one,
        6 => rng.range(-(1 << 28), (1 << 28) + 1),
        _ => rng.range(-5000 * one, 9000 * one),
    }
}

/// Checks one line; `None` if an end point is out of range, else the pixel count.
fn check<const S: u32>(a: (i64, i64), b: (i64, i64), clip: ClipRect) -> Option<usize> {
    let (Ok(pa), Ok(pb)) =
        (SubPoint::<S>::new(a.0 as i32, a.1 as i32), SubPoint::<S>::new(b.0 as i32, b.1 as i32))
    else {
        return None;
    };
    let got: Vec<_> = line_pixels(pa, pb, clip).collect();
    let want = reference((pa.x(), pa.y()), (pb.x(), pb.y()), S, clip);
    let bad = got.iter().zip(&want).position(|(g, w)| g != w);
    assert!(got == want, "S={S} a={a:?} b={b:?} {clip:?}: first mismatch at {bad:?}");
    assert_eq!(line_pixels(pa, pb, clip).len(), got.len());
    let rows = line_rows(pa, pb);
    for &(_, y) in &got {
        let (r0, r1) = rows.expect("pixels drawn but line_rows is None");
        assert!(r0 <= y && y <= r1, "row {y} outside {rows:?}");
    }
    // Wholly inside the largest frame: line_rows must be exact.
    let frame = 0..(4096i64 << S);
    if [a.0, a.1, b.0, b.1].iter().all(|v| frame.contains(v)) {
        let all = reference((pa.x(), pa.y()), (pb.x(), pb.y()), S, ClipRect::new(0, 0, 4096, 4096));
        let exact = all.iter().map(|p| p.1).min().zip(all.iter().map(|p| p.1).max());
        assert_eq!(rows, exact, "S={S} a={a:?} b={b:?}");
    }
    Some(got.len())
}

/// Checks `lines` lines; returns (lines, lines with pixels, pixels).
fn run<const S: u32>(seed: u64, lines: usize) -> (usize, usize, usize) {
    let (mut rng, mut done, lim) = (Rng(seed), std::vec![], 1i64 << 28);
    // Extremes: longest lines in every direction, over the whole frame.
    let full = ClipRect::new(0, 0, 4096, 4096);
    for a in [(-lim, -lim), (lim, lim), (-lim, lim), (0, 0), (lim, 0), (1, -lim)] {
        for b in [(lim, lim), (-lim, lim - 1), (lim - 1, -lim), (3, 5), (-lim, 1), (0, 0)] {
            done.extend(check::<S>(a, b, full));
        }
    }
    while done.len() < lines {
        let a = (coord(&mut rng, S), coord(&mut rng, S));
        let r = rng.range(-(300 << S), 300 << S);
        let b = match rng.next() % 8 {
            0 => (a.0 + r, a.1),                // horizontal
            1 => (a.0, a.1 + r),                // vertical
            2 => (a.0 + r, a.1 + r),            // diagonal
            3 => (a.0 + r, a.1 - r),            // anti-diagonal
            4 => (a.0 + r, a.1 + r / 7),        // shallow
            5 => (a.0 + r / 5, a.1 + r),        // steep
            6 => (a.0 + rng.range(-3, 4), a.1), // tiny, often zero-length
            _ => (coord(&mut rng, S), coord(&mut rng, S)),
        };
        // Mostly a box around the segment's middle, so that many lines are visible.
        let (cx, cy) = (((a.0 + b.0) >> (S + 1)) as i32, ((a.1 + b.1) >> (S + 1)) as i32);
        let kind = rng.next() % 8;
        let mut d = || rng.range(-2, 200) as i32;
        let clip = match kind {
            0 => full,
            1 => ClipRect::new(50, 60, 50 - d() % 3, 90), // empty
            2 | 3 => ClipRect::new(d() * 2, d() * 2, d() * 4, d() * 4), // anywhere, may miss
            _ => ClipRect::new(cx - d(), cy - d(), cx + d(), cy + d()),
        };
        done.extend(check::<S>(a, b, clip));
    }
    (done.len(), done.iter().filter(|&&n| n > 0).count(), done.iter().sum())
}

#[test]
fn matches_exact_rational_rule() {
    for (s, (n, drawn, px)) in [
        (0, run::<0>(1, 25_000)),
        (2, run::<2>(2, 25_000)),
        (4, run::<4>(3, 25_000)),
        (8, run::<8>(4, 25_000)),
    ] {
        std::println!("S={s}: {n} lines ({drawn} visible, {px} pixels) match the exact rule");
    }
}

#[test]
fn direction_polyline_and_degenerate_cases() {
    let clip = ClipRect::new(0, 0, 64, 64);
    let p = |x, y| SubPoint::<4>::new(x, y).unwrap();
    // Off-centre end points: a→b and b→a light exactly the same pixels.
    let (a, b) = (p(20, 30), p(500, 211));
    let fwd: Vec<_> = line_pixels(a, b, clip).collect();
    let mut back: Vec<_> = line_pixels(b, a, clip).collect();
    back.reverse();
    assert_eq!(fwd, back);
    // On pixel centres the end-point rule shows: each direction drops its end.
    let (a, b, c) = (p(24, 24), p(488, 200), p(90, 700)); // centres (1,1), (30,12)
    let mut fwd: Vec<_> = line_pixels(a, b, clip).collect();
    let mut back: Vec<_> = line_pixels(b, a, clip).collect();
    back.reverse();
    assert_eq!(fwd.remove(0), (1, 1));
    assert_eq!(back.pop(), Some((30, 12)));
    assert_eq!(fwd, back);
    // Polyline: the shared vertex pixel appears exactly once.
    let joined: Vec<_> = line_pixels(a, b, clip).chain(line_pixels(b, c, clip)).collect();
    assert_eq!(joined.iter().filter(|&&q| q == (30, 12)).count(), 1);
    // Zero length and sub-pixel segments between centres draw nothing.
    assert_eq!(line_pixels(a, a, clip).count(), 0);
    assert_eq!(line_rows(a, a), None);
    assert_eq!(line_pixels(p(9, 9), p(20, 9), clip).count(), 0); // no centre in [9/16, 20/16)
    assert_eq!(line_pixels(a, b, ClipRect::new(9, 9, 3, 40)).count(), 0);
}
