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
