extern crate std;
use super::*;
use crate::edge::Span;
use std::vec::Vec;

#[test]
fn div_ceil_rounds_up_for_both_signs() {
    assert_eq!([div_ceil(7, 2), div_ceil(-7, 2), div_ceil(6, 2), div_ceil(-6, 2)], [4, -3, 3, -3]);
    assert_eq!([div_ceil32(7, 2), div_ceil32(-7, 2), div_ceil32(6, 2), div_ceil32(-6, 2)], [4, -3, 3, -3]);
    assert_eq!(div_ceil32(i32::MIN, 1), i32::MIN);
    assert_eq!(div_ceil32(i32::MAX, 2), 1 << 30);
}

#[test]
fn rows_are_the_centres_inside_half_open() {
    let clip = ClipRect::new(0, 0, 100, 100);
    // Edge from y = 1.5 to 3.5 px: centres 1.5 and 2.5 (3.5 is excluded).
    assert_eq!(center_rows(24, 56, clip), (1, 3));
    assert_eq!(center_rows(25, 56, clip), (2, 3));
    assert_eq!(center_rows(-1000, 5000, ClipRect::new(0, 2, 9, 4)), (2, 4));
    // The shift equals the division for negative tops too.
    for y in -100..100 {
        assert_eq!(first_row(y), div_ceil(i64::from(y) - HALF, ONE), "y {y}");
    }
}

use crate::test_rng::Rng;

#[test]
fn remainder_division_is_exact_in_both_widths() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for _ in 0..100_000 {
        let scale = [1 << 8, 1 << 20, 1 << 31, 1 << 40][(rng.next() % 4) as usize];
        let (a, b) = (rng.in_range(scale), 1 + rng.in_range(scale).abs());
        let (q, r) = div_ceil_rem(a, b);
        assert_eq!(q, div_ceil(a, b), "{a} / {b}");
        assert!((0..b).contains(&r) && q * b - r == a, "{a} / {b}: {q} {r}");
    }
}

/// The spans a scan emits, with their alpha.
type Spans = Vec<(Span, u8)>;

/// The spans of `edges` in `clip`, walked and divided.
fn both<const N: usize>(edges: &EdgeList<N>, rule: FillRule, clip: ClipRect) -> (Spans, Spans) {
    let (mut walked, mut divided) = (Vec::new(), Vec::new());
    scan(edges, rule, clip, &mut Runs::new(|s, a| walked.push((s, a))));
    scan_divided(edges, rule, clip, &mut Runs::new(|s, a| divided.push((s, a))));
    (walked, divided)
}

/// Random polygons, near and far (up to the 2^28-subpixel limit), under
/// clips that cut through them: the walked crossings are the divided ones.
#[test]
fn walked_crossings_equal_divided_ones() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let mut spans = 0;
    for case in 0..3000 {
        // Far coordinates: vertices up to ±2^24 px (2^28 subpixels), but
        // edges still crossing the clip through a centre near the screen.
        let reach = [40.0, 400.0, 100_000.0, 16_000_000.0][case % 4];
        let k = 3 + (rng.next() % 9) as usize;
        let mut e = EdgeList::<32>::new();
        let pts: Vec<(f32, f32)> = (0..k)
            .map(|i| {
                let far = i % 2 == 0 && case % 4 >= 2;
                let r = if far { reach } else { 40.0 };
                let x = rng.in_range(1 << 20) as f32 / (1 << 20) as f32 * r as f32 + 30.0;
                let y = rng.in_range(1 << 20) as f32 / (1 << 20) as f32 * r as f32 + 30.0;
                (x, y)
            })
            .collect();
        e.polygon(&pts).unwrap();
        e.sort_by_top();
        let (x0, y0) = (rng.in_range(20) as i32 + 20, rng.in_range(20) as i32 + 20);
        let clip = ClipRect::new(x0, y0, x0 + (rng.next() % 60) as i32, y0 + (rng.next() % 60) as i32);
        let rule = if case % 2 == 0 { FillRule::NonZero } else { FillRule::EvenOdd };
        let (walked, divided) = both(&e, rule, clip);
        assert_eq!(walked, divided, "case {case}: {pts:?} in {clip:?}");
        spans += walked.len();
    }
    assert!(spans > 10_000, "the cases cover pixels: {spans} spans");
}

/// More edges crossing one row than there are walkers: the scan finishes by
/// division, with the same pixels.
#[test]
fn more_active_edges_than_walkers_fall_back_exactly() {
    // A comb of 2 · 40 slanted teeth: 80 edges cross the rows 2..18.
    let mut e = EdgeList::<{ 4 * WALKERS }>::new();
    for t in 0..40 {
        let x = t as f32 * 3.0;
        e.polygon(&[(x, 0.0), (x + 1.7, 1.0), (x + 2.1, 20.0), (x + 0.3, 19.5)]).unwrap();
    }
    e.sort_by_top();
    assert!(e.len() > WALKERS);
    // A small list (32 edges, 16 walkers): 10 teeth of 2 edges, all 20
    // across rows 1..19.
    let mut small = EdgeList::<{ 2 * SMALL_WALKERS }>::new();
    for t in 0..10 {
        let x = t as f32 * 2.5;
        small.polygon(&[(x, 0.0), (x + 1.1, 20.0), (x + 2.0, 0.0)]).unwrap();
    }
    small.sort_by_top();
    assert!(small.len() > SMALL_WALKERS);
    for clip in [ClipRect::new(0, 0, 130, 24), ClipRect::new(5, 3, 90, 9), ClipRect::new(0, 19, 130, 21)] {
        let (walked, divided) = both(&e, FillRule::NonZero, clip);
        assert!(!walked.is_empty());
        assert_eq!(walked, divided, "{clip:?}");
        let (walked, divided) = both(&small, FillRule::EvenOdd, clip);
        assert!(clip.y0() > 0 || !walked.is_empty());
        assert_eq!(walked, divided, "small {clip:?}");
    }
}

/// Discs, ellipses and rounded rectangles (whole, and in windows as a band
/// stores them) are two chains: walked as such, their spans are the
/// general walk's and the division's. A star, a ring and two discs are not.
#[test]
fn two_chains_walk_as_the_general_walk() {
    use crate::shape::{Circle, Ellipse, Rect, RoundedRect, Shape};
    let mut rng = Rng(0x51f1_5e5d_9e1a_c0de);
    let (mut drawn, mut chained, mut spans) = (0, 0, 0);
    for case in 0..1500 {
        let c = (rng.in_range(1 << 12) as f32 / 64.0 + 30.0, rng.in_range(1 << 12) as f32 / 64.0 + 30.0);
        let r = 0.3 + (rng.next() % 4000) as f32 / 64.0;
        let window = match case % 3 {
            0 => None,
            // A band's rows, in subpixels (16 per pixel), across the shape.
            _ => {
                let y0 = (c.1 as i32 + rng.in_range(40) as i32).max(0) * 16;
                Some((y0, y0 + 16 * (1 + (rng.next() % 20) as i32)))
            }
        };
        let mut e = EdgeList::<{ crate::shape::MAX_EDGES }>::new();
        if let Some((lo, hi)) = window {
            e.window(lo, hi);
        }
        match case % 4 {
            0 => Circle::new(c, r).unwrap().fill_contours(&mut e),
            1 => Ellipse::new(c, r, r * 0.37 + 0.2).unwrap().fill_contours(&mut e),
            2 => {
                let rect = Rect::new(c.0 - r, c.1 - r * 0.6, 2.0 * r, 1.2 * r + 0.1).unwrap();
                RoundedRect::new(rect, r * 0.3).unwrap().fill_contours(&mut e)
            }
            _ => Rect::new(c.0, c.1, r, r * 0.5).unwrap().fill_contours(&mut e),
        }
        .unwrap();
        let clip = if case % 5 == 0 { ClipRect::new(35, 20, 70, 80) } else { ClipRect::new(0, 0, 200, 200) };
        let clip = window.map_or(clip, |(lo, hi)| ClipRect::new(clip.x0(), lo / 16, clip.x1(), hi / 16));
        // The chains found before sorting, in the contour's own order.
        let unsorted = Chains::in_contour_order(e.edges(), clip);
        let mut in_order = Vec::new();
        if let Some(ch) = unsorted {
            ch.walk(e.edges(), clip, &mut Runs::new(|s, a| in_order.push((s, a))));
        }
        e.sort_by_top();
        let whole = Chains::sorted(e.edges(), clip);
        // A single contour: found in either order alike, over the same rows.
        assert_eq!(
            unsorted.map(|c| c.rows),
            whole.map(|c| c.rows),
            "case {case}: r {r} at {c:?}, window {window:?}"
        );
        if !e.is_empty() && !clip.is_empty() {
            drawn += 1;
            chained += usize::from(whole.is_some());
        }
        let rule = [FillRule::NonZero, FillRule::EvenOdd][case % 2];
        let (walked, divided) = both(&e, rule, clip);
        let mut general = Vec::new();
        walk::<_, { crate::shape::MAX_EDGES }, WALKERS>(
            &e,
            rule,
            clip,
            &mut Runs::new(|s, a| general.push((s, a))),
        );
        assert_eq!(walked, general, "case {case}: r {r} at {c:?}, window {window:?}");
        assert_eq!(walked, divided, "case {case}: r {r} at {c:?}, window {window:?}");
        if unsorted.is_some() {
            assert_eq!(in_order, general, "case {case}: in contour order, r {r} at {c:?}, window {window:?}");
        }
        spans += walked.len();
    }
    // Nearly every outline here is two chains (not: a snapped kink where
    // a curve turns, a few subpixels long, which the general walk takes).
    assert!(drawn > 900 && chained * 100 >= drawn * 95, "{chained} of {drawn} walked as two chains");
    assert!(spans > 10_000, "the cases cover pixels: {spans} spans");
    // Not two chains: a star (a row crosses four edges), a ring (two
    // contours, nested), two discs side by side.
    let star: Vec<(f32, f32)> = (0..10)
        .map(|i| {
            let (s, c) = (i as f32 * 0.6283).sin_cos();
            let r = if i % 2 == 0 { 20.0 } else { 8.0 };
            (40.0 + r * c, 40.0 + r * s)
        })
        .collect();
    let clip = ClipRect::new(0, 0, 100, 100);
    let mut e = EdgeList::<64>::new();
    e.polygon(&star).unwrap();
    assert_eq!(Chains::in_contour_order(e.edges(), clip), None);
    e.sort_by_top();
    assert_eq!(Chains::sorted(e.edges(), clip), None);
    let mut ring = EdgeList::<{ crate::shape::MAX_EDGES }>::new();
    Circle::new((40.0, 40.0), 20.0).unwrap().fill_contours(&mut ring).unwrap();
    Circle::new((40.0, 40.0), 9.0).unwrap().fill_contours(&mut ring).unwrap();
    assert_eq!(Chains::in_contour_order(ring.edges(), clip), None);
    ring.sort_by_top();
    assert_eq!(Chains::sorted(ring.edges(), clip), None);
    let mut pair = EdgeList::<{ crate::shape::MAX_EDGES }>::new();
    Circle::new((20.0, 40.0), 9.0).unwrap().fill_contours(&mut pair).unwrap();
    Circle::new((60.0, 40.0), 9.0).unwrap().fill_contours(&mut pair).unwrap();
    assert_eq!(Chains::in_contour_order(pair.edges(), clip), None);
    pair.sort_by_top();
    assert_eq!(Chains::sorted(pair.edges(), clip), None);
    // A disc alone is one contour in order: found before the sort.
    let mut disc = EdgeList::<{ crate::shape::MAX_EDGES }>::new();
    Circle::new((40.0, 40.0), 20.0).unwrap().fill_contours(&mut disc).unwrap();
    assert!(Chains::in_contour_order(disc.edges(), clip).is_some());
}
