extern crate std;
use super::*;
use crate::shape::MAX_EDGES;
use std::vec::Vec;

/// A zigzag polygon of `n` points spread over `h` px: `n` slanted edges.
fn zigzag<const N: usize>(e: &mut EdgeList<N>, n: usize, h: f32) -> Result<(), Error> {
    e.close()?;
    for i in 0..n {
        e.line_to(i as f32 * 0.75 - 3.0, (i % 2) as f32 * h + (i / 7) as f32 * 0.3)?;
    }
    e.close()
}

#[test]
fn measuring_counts_and_bounds_as_a_full_list_does() {
    for n in [0, 1, 2, 3, 31, 32, 33, 200, MAX_EDGES, MAX_EDGES + 1, MAX_EDGES + 2, 400] {
        let (mut full, mut m) = (EdgeList::<MAX_EDGES>::new(), EdgeList::measuring());
        let (a, b) = (zigzag(&mut full, n, 5.0), zigzag(&mut m, n, 5.0));
        assert_eq!(a, b, "{n} points");
        assert_eq!((full.len(), full.y_range()), (m.len(), m.y_range()), "{n} points");
        assert!(m.edges().is_empty());
    }
    // A coordinate beyond the snapping range: the same error.
    let mut m = EdgeList::measuring();
    assert_eq!(m.polygon(&[(0.0, 0.0), (1.0e12, 3.0), (0.0, 5.0)]), Err(Error::CoordinateOutOfRange));
}

#[test]
fn a_window_keeps_exactly_the_edges_meeting_its_rows() {
    let mut full = EdgeList::<64>::new();
    zigzag(&mut full, 60, 40.0).unwrap();
    for (lo, hi) in [(0, 16), (-100, 3), (30, 31), (160, 400), (641, 700), (-50, 9000)] {
        let mut w = EdgeList::<64>::new();
        w.window(lo, hi);
        zigzag(&mut w, 60, 40.0).unwrap();
        let kept: Vec<_> = full.edges().iter().filter(|e| e.y0 < hi && e.y1 > lo).copied().collect();
        assert_eq!(w.edges(), &kept[..], "rows {lo}..{hi}");
        // The same orientation sum as the whole list's.
        let all = full.edges().iter().map(area_term).sum::<i128>();
        assert_eq!(w.twice, all);
    }
}

#[test]
fn a_windowed_group_member_turns_as_the_whole_one_does() {
    // A triangle enclosing winding −1: reversed. Each window below holds
    // its vertical edge and one slanted one, whose own sum is positive:
    // orienting by the stored edges alone would leave them as they are.
    let tri = [(100.0, 0.0), (150.0, 60.0), (100.0, 100.0)];
    let mut full = EdgeList::<8>::new();
    let mark = full.mark();
    full.polygon(&tri).unwrap();
    full.orient_since(mark);
    let vertical = full.edges().iter().find(|e| e.x0 == e.x1).unwrap();
    assert_eq!(vertical.dir, 1, "the upward vertical edge, reversed");
    for (lo, hi) in [(0, 16), (1500, 1600)] {
        let mut w = EdgeList::<8>::new();
        w.window(lo, hi);
        w.polygon(&tri).unwrap();
        assert!(w.edges().iter().map(area_term).sum::<i128>() > 0, "rows {lo}..{hi}");
    }
    for (lo, hi) in [(0, 16), (900, 1000), (1500, 1600)] {
        let mut w = EdgeList::<8>::new();
        w.window(lo, hi);
        let mark = w.mark();
        w.polygon(&tri).unwrap();
        w.orient_since(mark);
        let kept: Vec<_> = full.edges().iter().filter(|e| e.y0 < hi && e.y1 > lo).copied().collect();
        assert_eq!(w.edges(), &kept[..], "rows {lo}..{hi}");
    }
}

/// One step of a contour for [`curve_to_stores_what_line_to_stores`].
#[derive(Clone, Copy, Debug)]
enum Step {
    Move(f32, f32),
    Curve(f32, f32),
    Line(f32, f32),
    Edge((f32, f32), (f32, f32), bool),
    Close,
}

fn build<const N: usize>(e: &mut EdgeList<N>, steps: &[Step], curves: bool) -> Result<(), Error> {
    for &s in steps {
        match s {
            Step::Move(x, y) => e.move_to(x, y)?,
            Step::Curve(x, y) if curves => e.curve_to(x, y)?,
            Step::Curve(x, y) | Step::Line(x, y) => e.line_to(x, y)?,
            Step::Edge(a, b, flip) => e.edge(a, b, flip)?,
            Step::Close => e.close()?,
        }
    }
    e.close()
}

/// A windowed list given a curve's points by `curve_to` and lone edges by
/// `edge` (both cull what misses the window before snapping it) holds
/// exactly the edges, rows and errors of one that culls nothing (`line_to`,
/// and `edge` after `mark`), for contours that wander in and out of the
/// window, end points on the rows where the culling test changes its
/// answer, lines between curves, and bad points after culled ones.
#[test]
fn curve_to_stores_what_line_to_stores() {
    let mut rng = crate::test_rng::Rng(0x5EED_C0DE_2026_1207);
    let windows = [(0, 16), (160, 176), (-40, 8), (1000, 1016), (37, 38), (5, 5)];
    for case in 0..4_000 {
        let (lo, hi) = windows[case % windows.len()];
        // y in px around the window, some exactly where 16·y sits 1 past
        // its rows or half a subpixel from them.
        let y = |rng: &mut crate::test_rng::Rng| match rng.next() % 6 {
            0 => (lo as f32 - 1.0) / 16.0,
            1 => (hi as f32 + 1.0) / 16.0,
            2 => (lo as f32 - 0.5) / 16.0,
            3 => (hi as f32 + 0.5) / 16.0,
            _ => (lo as f32 + rng.unit(80.0)) / 16.0,
        };
        let mut steps = Vec::new();
        for _ in 0..(3 + case % 40) {
            let p = (rng.unit(40.0), y(&mut rng));
            steps.push(match rng.next() % 13 {
                0 => Step::Move(p.0, p.1),
                12 => Step::Edge(p, (rng.unit(40.0), y(&mut rng)), rng.next().is_multiple_of(2)),
                1 | 2 => Step::Line(p.0, p.1),
                3 => Step::Close,
                _ => Step::Curve(p.0, p.1),
            });
        }
        if case % 97 == 0 {
            steps.push(Step::Curve(f32::NAN, 1.0));
        }
        if case % 101 == 0 {
            steps.push(Step::Curve(3.0e12, 1.0e12));
        }
        let (mut a, mut b) = (EdgeList::<64>::new(), EdgeList::<64>::new());
        a.window(lo, hi);
        b.window(lo, hi);
        let _ = b.mark(); // culls nothing from here
        assert!(a.culls() && !b.culls());
        let (ra, rb) = (build(&mut a, &steps, true), build(&mut b, &steps, false));
        assert_eq!(ra, rb, "case {case}: {steps:?}");
        assert_eq!(a.edges(), b.edges(), "case {case} rows {lo}..{hi}: {steps:?}");
        assert_eq!((a.len(), a.y_range()), (b.len(), b.y_range()), "case {case}");
    }
}

/// A group member (`mark`) needs every edge's area term: `curve_to` culls
/// nothing there, and the windowed member turns as the whole one does.
#[test]
fn curve_to_culls_nothing_in_a_group_member() {
    let steps: Vec<_> = (0..=40)
        .map(|k| {
            let a = k as f32 * core::f32::consts::TAU / 40.0;
            Step::Curve(50.0 + 30.0 * a.cos(), 50.0 - 30.0 * a.sin())
        })
        .collect();
    let mut full = EdgeList::<64>::new();
    build(&mut full, &steps, false).unwrap();
    let mut w = EdgeList::<64>::new();
    w.window(0, 400);
    let mark = w.mark();
    build(&mut w, &steps, true).unwrap();
    assert_eq!(w.twice, full.edges().iter().map(area_term).sum::<i128>());
    w.orient_since(mark);
    let kept: Vec<_> = full.edges().iter().filter(|e| e.y0 < 400 && e.y1 > 0).copied().collect();
    assert_eq!(w.edges().len(), kept.len());
}
