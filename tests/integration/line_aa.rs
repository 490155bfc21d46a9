//! Anti-aliased lines against an independent `f64` evaluation of Wu's
//! intensities, per-column sums, band invariance, extreme coordinates.

use embedded_graphics_core::pixelcolor::{Gray8, Rgb565};
use microraster::blend::Additive;
use microraster::line_aa::{LineAa, line_aa_pixels};
use microraster::{Band, ClipRect, SubPoint};
use std::collections::HashMap;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo) as u64) as i64
    }
}

/// Exact Wu intensities (0..=A) of the pixels in `clip`, in `f64`, straight
/// from the definition: per major column M overlapped by the segment, the
/// overlap g, the minor coordinate v at the column centre, and its split
/// between the pixel centres around it. Also returns, per pixel, whether its
/// column is interior (g = 1) and the column's exact total A·g.
fn wu_reference(
    a: (f64, f64),
    b: (f64, f64),
    x_major: bool,
    alpha: f64,
    clip: ClipRect,
) -> HashMap<(i32, i32), (f64, bool, f64)> {
    let (mut ua, mut va, mut ub, mut vb) = if x_major { (a.0, a.1, b.0, b.1) } else { (a.1, a.0, b.1, b.0) };
    if ua > ub {
        std::mem::swap(&mut ua, &mut ub);
        std::mem::swap(&mut va, &mut vb);
    }
    let mut out = HashMap::new();
    if ua == ub {
        return out;
    }
    let (c0, c1, k0, k1) = if x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let first = (ua.floor() as i64).max(c0 as i64);
    let last = (ub.ceil() as i64).min(c1 as i64);
    for m in first..last {
        let mf = m as f64;
        let g = ub.min(mf + 1.0) - ua.max(mf);
        if g <= 0.0 {
            continue;
        }
        let v = va + (vb - va) * (mf + 0.5 - ua) / (ub - ua);
        let t = v - 0.5;
        let j = t.floor();
        let f = t - j;
        for (minor, i) in [(j as i64, alpha * g * (1.0 - f)), (j as i64 + 1, alpha * g * f)] {
            if (k0 as i64..k1 as i64).contains(&minor) {
                let (m, minor) = (m as i32, minor as i32);
                let px = if x_major { (m, minor) } else { (minor, m) };
                out.insert(px, (i, g == 1.0, alpha * g));
            }
        }
    }
    out
}

/// Worst errors seen: [any pixel, interior-column pixel].
fn compare<const S: u32>(
    a: SubPoint<S>,
    b: SubPoint<S>,
    clip: ClipRect,
    alpha: u8,
    worst: &mut [f64; 2],
) -> usize {
    let got: Vec<_> = line_aa_pixels(a, b, clip, alpha).collect();
    let x_major = (b.x() as i64 - a.x() as i64).abs() >= (b.y() as i64 - a.y() as i64).abs();
    let want = wu_reference(a.to_f64(), b.to_f64(), x_major, f64::from(alpha), clip);
    let mut seen = HashMap::new();
    for &(x, y, al) in &got {
        assert!(al > 0, "zero alpha emitted");
        assert!(clip.contains(x, y), "({x}, {y}) outside {clip:?}");
        assert!(seen.insert((x, y), al).is_none(), "pixel ({x}, {y}) emitted twice");
    }
    // Both directions give the same pixels.
    let mut rev: Vec<_> = line_aa_pixels(b, a, clip, alpha).collect();
    let mut fwd = got.clone();
    rev.sort();
    fwd.sort();
    assert_eq!(fwd, rev, "a→b differs from b→a");
    // Every pixel in either set: |ours − exact| < 1, ≤ 1/2 in interior columns.
    let keys: Vec<_> = seen.keys().chain(want.keys()).copied().collect();
    for px in keys {
        let ours = f64::from(*seen.get(&px).unwrap_or(&0));
        let (exact, interior) = want.get(&px).map_or((0.0, false), |w| (w.0, w.1));
        let err = (ours - exact).abs();
        let ctx =
            || format!("S={S} a={a:?} b={b:?} alpha={alpha} {clip:?} px={px:?}: ours {ours}, exact {exact}");
        assert!(err < 1.0, "{}", ctx());
        if interior {
            // 1e-6 absorbs f64 evaluation error (|v| ≤ 2^28 px).
            assert!(err <= 0.5 + 1e-6, "{}", ctx());
            worst[1] = worst[1].max(err);
        }
        worst[0] = worst[0].max(err);
    }
    got.len()
}

/// A random coordinate: near the clip area, on pixel centres or corners, or
/// anywhere in range.
fn coord(rng: &mut Rng, s: u32) -> i64 {
    let one = 1i64 << s;
    match rng.next() % 8 {
        0 | 1 => rng.range(-20 * one, 300 * one),
        2 => rng.range(-20, 300) * one + one / 2,
        3 => rng.range(-20, 300) * one,
        4 => rng.range(-(1 << 28), (1 << 28) + 1),
        5 => [-(1 << 28), 1 << 28][(rng.next() % 2) as usize],
        _ => rng.range(-3000 * one, 3000 * one),
    }
}

fn random_lines<const S: u32>(seed: u64, n: usize, worst: &mut [f64; 2]) -> (usize, usize) {
    let mut rng = Rng(seed);
    let (mut lines, mut pixels) = (0, 0);
    while lines < n {
        let a = (coord(&mut rng, S), coord(&mut rng, S));
        let r = rng.range(-(200 << S), 200 << S);
        let b = match rng.next() % 8 {
            0 => (a.0 + r, a.1),
            1 => (a.0, a.1 + r),
            2 => (a.0 + r, a.1 + r),
            3 => (a.0 + r, a.1 - r / 3),
            4 => (a.0 + rng.range(-40, 41), a.1 + rng.range(-40, 41)), // short, sub-pixel
            _ => (coord(&mut rng, S), coord(&mut rng, S)),
        };
        let (Ok(pa), Ok(pb)) =
            (SubPoint::<S>::new(a.0 as i32, a.1 as i32), SubPoint::<S>::new(b.0 as i32, b.1 as i32))
        else {
            continue;
        };
        let (cx, cy) = (((a.0 + b.0) >> (S + 1)) as i32, ((a.1 + b.1) >> (S + 1)) as i32);
        let kind = rng.next() % 4;
        let mut d = || rng.range(-2, 120) as i32;
        let clip = match kind {
            0 => ClipRect::new(0, 0, 4096, 4096),
            1 => ClipRect::new(d(), d(), d() * 3, d() * 3),
            _ => ClipRect::new(cx - d(), cy - d(), cx + d(), cy + d()),
        };
        let alpha = [255u8, 255, 128, 1, 77][(rng.next() % 5) as usize];
        pixels += compare(pa, pb, clip, alpha, worst);
        lines += 1;
    }
    (lines, pixels)
}

#[test]
fn matches_f64_wu_reference() {
    let mut worst = [0.0f64; 2];
    let mut total = (0, 0);
    for (s, (l, p)) in [
        (0, random_lines::<0>(11, 6000, &mut worst)),
        (2, random_lines::<2>(12, 6000, &mut worst)),
        (4, random_lines::<4>(13, 6000, &mut worst)),
        (8, random_lines::<8>(14, 6000, &mut worst)),
    ] {
        println!("S={s}: {l} lines, {p} pixels");
        total = (total.0 + l, total.1 + p);
    }
    println!(
        "worst |alpha − exact Wu intensity|: {:.4} (any pixel), {:.4} (interior columns)",
        worst[0], worst[1]
    );
    assert!(total.1 > 100_000, "too few pixels drawn: {total:?}");
}

#[test]
fn column_alphas_sum_to_the_line_alpha() {
    let mut rng = Rng(99);
    let (mut interior, mut ends) = (0, 0);
    for _ in 0..3000 {
        let s = 4;
        let mut c = || rng.range(16 << s, 900 << s) as i32;
        let (a, b) = (SubPoint::<4>::new(c(), c()).unwrap(), SubPoint::<4>::new(c(), c()).unwrap());
        let alpha = (rng.next() % 256) as u8;
        let clip = ClipRect::new(0, 0, 4096, 4096); // the line is well inside: nothing clipped
        let x_major = (b.x() - a.x()).abs() >= (b.y() - a.y()).abs();
        let mut cols: HashMap<i32, u32> = HashMap::new();
        for (x, y, al) in line_aa_pixels(a, b, clip, alpha) {
            *cols.entry(if x_major { x } else { y }).or_default() += u32::from(al);
        }
        let want = wu_reference(a.to_f64(), b.to_f64(), x_major, f64::from(alpha), clip);
        let mut totals: HashMap<i32, (bool, f64)> = HashMap::new();
        for (&(x, y), &(_, inner, sum)) in &want {
            totals.insert(if x_major { x } else { y }, (inner, sum));
        }
        for (col, (inner, exact)) in totals {
            let got = f64::from(cols.get(&col).copied().unwrap_or(0));
            if inner {
                assert_eq!(got, f64::from(alpha), "interior column {col} of {a:?}→{b:?}");
                interior += 1;
            } else {
                assert!((got - exact).abs() <= 0.5, "end column {col}: {got} vs {exact}");
                ends += 1;
            }
        }
    }
    println!("{interior} interior columns sum exactly to the line alpha; {ends} end columns within 1/2");
    assert!(interior > 100_000 && ends > 3000);
}

/// Draws a few overlapping lines per band, for band heights `H`.
fn render<const H: usize>(lines: &[LineAa<Rgb565, 4>]) -> Vec<Rgb565> {
    const W: usize = 64;
    let (rows, bg) = (64usize, Rgb565::new(3, 9, 4));
    let mut band = Band::<Rgb565, W, H>::new(bg);
    let mut out = Vec::new();
    let mut y0 = 0;
    while y0 < rows {
        let n = H.min(rows - y0);
        let mut view = band.view(y0 as i32, n, bg);
        for (i, l) in lines.iter().enumerate() {
            if i % 2 == 0 { l.draw(&mut view) } else { l.draw_with(&mut view, Additive) }
        }
        out.extend(view.pixels());
        y0 += n;
    }
    out
}

#[test]
fn band_invariance() {
    let mut rng = Rng(7);
    let mut lit = 0;
    for _ in 0..300 {
        let lines: Vec<_> = (0..4)
            .map(|_| {
                let mut c = || rng.range(-40 << 4, 104 << 4) as i32;
                let (a, b) = (SubPoint::<4>::new(c(), c()).unwrap(), SubPoint::<4>::new(c(), c()).unwrap());
                let color =
                    Rgb565::new((rng.next() % 32) as u8, (rng.next() % 64) as u8, (rng.next() % 32) as u8);
                LineAa::new(a, b, color).with_alpha((rng.next() % 256) as u8)
            })
            .collect();
        let full = render::<64>(&lines);
        assert_eq!(render::<1>(&lines), full);
        assert_eq!(render::<7>(&lines), full);
        assert_eq!(render::<16>(&lines), full);
        lit += full.iter().filter(|&&c| c != Rgb565::new(3, 9, 4)).count();
    }
    assert!(lit > 10_000, "scenes too empty: {lit}");
}

#[test]
fn extreme_coordinates_do_not_panic() {
    fn run<const S: u32>() -> usize {
        let lim = 1i32 << 28;
        let vals = [-lim, -lim + 1, -1, 0, 1, 7, 1 << (S + 8), lim - 1, lim];
        let clips =
            [ClipRect::new(0, 0, 4096, 4096), ClipRect::new(0, 100, 4096, 101), ClipRect::new(5, 5, 5, 9)];
        let mut n = 0;
        for &ax in &vals {
            for &ay in &vals {
                for &bx in &vals {
                    for &by in &vals {
                        let (a, b) =
                            (SubPoint::<S>::new(ax, ay).unwrap(), SubPoint::<S>::new(bx, by).unwrap());
                        for clip in clips {
                            for (x, y, _) in line_aa_pixels(a, b, clip, 255) {
                                assert!(clip.contains(x, y));
                                n += 1;
                            }
                        }
                    }
                }
            }
        }
        // A few against the reference (visible part only).
        let mut worst = [0.0; 2];
        let p = |x, y| SubPoint::<S>::new(x, y).unwrap();
        for (a, b) in
            [(p(-lim, -lim), p(lim, lim)), (p(-lim, lim), p(lim, -lim + 3)), (p(lim, 5), p(-lim, 1 << S))]
        {
            compare(a, b, ClipRect::new(0, 0, 4096, 4096), 200, &mut worst);
        }
        n
    }
    let n = run::<0>() + run::<3>() + run::<8>();
    assert!(n > 1000, "{n}");
}

#[test]
fn zero_length_and_tiny_segments() {
    let clip = ClipRect::new(0, 0, 64, 64);
    let p = |x, y| SubPoint::<4>::new(x, y).unwrap();
    for a in [p(0, 0), p(24, 24), p(100, 37)] {
        assert_eq!(line_aa_pixels(a, a, clip, 255).count(), 0);
    }
    // A horizontal segment from x = 1.5 to 1.75 on row centre y = 2.5: one
    // column, g = 1/4, the line exactly on the row's centre: alpha round(255/4) = 64.
    let px: Vec<_> = line_aa_pixels(p(24, 40), p(28, 40), clip, 255).collect();
    assert_eq!(px, [(1, 2, 64)]);
    // Straddling a column boundary: x = 1.75 .. 2.25 gives 1/4 to each column.
    let px: Vec<_> = line_aa_pixels(p(28, 40), p(36, 40), clip, 255).collect();
    assert_eq!(px, [(1, 2, 64), (2, 2, 64)]);
    // Zero alpha or an empty clip draws nothing.
    assert_eq!(line_aa_pixels(p(0, 0), p(500, 300), clip, 0).count(), 0);
    assert_eq!(line_aa_pixels(p(0, 0), p(500, 300), ClipRect::new(9, 9, 3, 40), 255).count(), 0);
}

#[test]
fn drawn_colour_is_the_mix_with_coverage() {
    // White on black Gray8: mix gives exactly the alpha.
    let p = |x: f32, y: f32| SubPoint::<6>::from_f32(x, y).unwrap();
    let (a, b) = (p(2.3, 40.1), p(30.9, 3.7));
    let mut band = Band::<Gray8, 48, 48>::new(Gray8::new(0));
    let mut view = band.view(0, 48, Gray8::new(0));
    LineAa::new(a, b, Gray8::new(255)).with_alpha(180).draw(&mut view);
    let mut expect = [[0u8; 48]; 48];
    for (x, y, al) in line_aa_pixels(a, b, ClipRect::new(0, 0, 48, 48), 180) {
        expect[y as usize][x as usize] = al;
    }
    for (y, row) in band.rows().iter().enumerate() {
        let got: Vec<u8> = row.iter().map(embedded_graphics_core::pixelcolor::GrayColor::luma).collect();
        assert_eq!(got, expect[y], "row {y}");
    }
}
