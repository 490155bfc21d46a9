//! Outlines that every row crosses twice (a disc, an ellipse, a rounded
//! rectangle, a thick line, whole or in a band's window): two chains of
//! edges, walked as two walkers, two steps and one span a row, without the
//! general walk's entering, sorting and dropping.
//!
//! The chains are found in a list sorted by top ([`Chains::sorted`]) or,
//! before any sort, in the order a single contour stored them
//! ([`Chains::in_contour_order`]): a contour that runs down (`dir` +1)
//! stores its edges top to bottom, one that runs up (`dir` −1) bottom to
//! top, so walking the list as a cycle forwards from the +1 chain's top
//! edge, and backwards from the −1 chain's, meets each chain's edges in
//! order of rows, the order the sorted list holds them in. Either way a list
//! is accepted only if each chain is gap-free, and the walk meets the same
//! edges in the same order: the same spans.

use super::{HALF, ONE, Runs, Walker, center_rows};
use crate::ClipRect;
use crate::edge::Span;
use crate::shape::edges::Edge;

/// Where the two chains of an edge list are, and the rows they reach.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Chains {
    /// Rows `lo..hi` to scan (inside the clip).
    pub(crate) rows: (i32, i32),
    /// Per chain (0: direction −1, 1: +1): the index of its top edge, and
    /// whether the list is walked backwards from there.
    start: [usize; 2],
    back: [bool; 2],
}

/// The index after `i` in a list of `len` edges walked as a cycle.
#[inline(always)]
fn next(i: usize, back: bool, len: usize) -> usize {
    match (back, i) {
        (true, 0) => len - 1,
        (true, _) => i - 1,
        (false, _) if i + 1 == len => 0,
        (false, _) => i + 1,
    }
}

impl Chains {
    /// The chains of `list` sorted by top: two chains, one of each
    /// direction, each of edges that follow each other without a gap (`y0`
    /// of one = `y1` of the one before, in subpixels), reaching the same
    /// rows inside `clip`. `None` otherwise.
    ///
    /// Then every row centre of the scan lies on exactly one edge of each
    /// chain (`y0 ≤ yc < y1`), so the general walk would hold two walkers
    /// of opposite directions in every row, and its spans are the columns
    /// between their crossings: winding ±1 there (inside by either rule), 0
    /// elsewhere.
    pub(crate) fn sorted(list: &[Edge], clip: ClipRect) -> Option<Self> {
        // Per direction (index 0: dir −1, 1: dir +1): the first edge's top
        // and the last edge's bottom so far, in one pass.
        let mut reach: [Option<(i32, i32)>; 2] = [None, None];
        for e in list {
            if e.dir.abs() != 1 {
                return None;
            }
            let chain = reach.get_mut(usize::from(e.dir > 0))?;
            *chain = match *chain {
                Some((top, bottom)) if bottom == e.y0 => Some((top, e.y1)),
                Some(_) => return None,
                None => Some((e.y0, e.y1)),
            };
        }
        let [Some(a), Some(b)] = reach else { return None };
        Self::same_rows([a, b], clip, [0, 0], [false, false])
    }

    /// The chains of `list` in the order one contour stored them (module
    /// docs), before sorting; `None` if the list is not two such chains in
    /// that order (then sort it and try [`Self::sorted`]).
    ///
    /// One pass: per chain, consecutive edges (in list order, as a cycle)
    /// link when the later one goes on where the earlier one ended (`y0` =
    /// `y1` going down, `y1` = `y0` going up); a gap-free chain has exactly
    /// one place that does not link, between its last and first edge of
    /// travel, and its top edge is next to it.
    pub(crate) fn in_contour_order(list: &[Edge], clip: ClipRect) -> Option<Self> {
        #[derive(Clone, Copy)]
        struct Run {
            first: usize,
            prev: usize,
            breaks: u32,
            top: usize,
            reach: (i32, i32),
        }
        let linked = |c: usize, p: &Edge, e: &Edge| if c == 1 { e.y0 == p.y1 } else { e.y1 == p.y0 };
        let mut runs: [Option<Run>; 2] = [None, None];
        for (i, e) in list.iter().enumerate() {
            if e.dir.abs() != 1 {
                return None;
            }
            let c = usize::from(e.dir > 0);
            let run = runs.get_mut(c)?;
            match run {
                None => *run = Some(Run { first: i, prev: i, breaks: 0, top: i, reach: (e.y0, e.y1) }),
                Some(r) => {
                    let p = list.get(r.prev)?;
                    if !linked(c, p, e) {
                        r.breaks += 1;
                        r.top = if c == 1 { i } else { r.prev };
                    }
                    r.prev = i;
                    r.reach = (r.reach.0.min(e.y0), r.reach.1.max(e.y1));
                }
            }
        }
        let mut out = [(0, (0, 0)); 2];
        for (c, run) in runs.into_iter().enumerate() {
            let mut r = run?;
            // The cycle closes from the last edge back to the first.
            if !linked(c, list.get(r.prev)?, list.get(r.first)?) {
                r.breaks += 1;
                r.top = if c == 1 { r.first } else { r.prev };
            }
            if r.breaks != 1 {
                return None;
            }
            out[c] = (r.top, r.reach);
        }
        let [(ta, a), (tb, b)] = out;
        Self::same_rows([a, b], clip, [ta, tb], [true, false])
    }

    /// The same chains over `clip`'s rows, for chains found over a clip
    /// whose rows hold `clip`'s ([`ClipRect`]s lie within
    /// `0..=MAX_FRAME_DIM`, so one found over all of those serves every
    /// clip): the rows `same_rows` would find for `clip`, as the found rows
    /// are the chains' rows clamped to the larger clip.
    pub(crate) fn within(self, clip: ClipRect) -> Self {
        let (lo, hi) = self.rows;
        let lo = lo.max(clip.y0());
        Chains { rows: (lo, hi.min(clip.y1()).max(lo)), ..self }
    }

    /// The chains whose subpixel rows are `reach`, if both reach the same
    /// pixel rows inside `clip`.
    fn same_rows(reach: [(i32, i32); 2], clip: ClipRect, start: [usize; 2], back: [bool; 2]) -> Option<Self> {
        let [a, b] = reach;
        let (ra, rb) = (center_rows(a.0, a.1, clip), center_rows(b.0, b.1, clip));
        (ra == rb && !clip.is_empty()).then_some(Chains { rows: ra, start, back })
    }

    /// The spans of the two chains of `list` (as found by [`Self::sorted`]
    /// or [`Self::in_contour_order`] on this list): per row, the edge of
    /// each chain that crosses its centre, its crossing walked as the
    /// general walk walks it.
    pub(crate) fn walk<F: FnMut(Span, u8)>(&self, list: &[Edge], clip: ClipRect, runs: &mut Runs<F>) {
        let (lo, hi) = self.rows;
        let (cx0, cx1) = (clip.x0(), clip.x1());
        // Per chain (0: direction −1, 1: +1): where its search goes on in
        // `list` and how many edges it has left to look at, and its walker
        // at row `y`.
        let mut at = self.start;
        let mut left = [list.len(); 2];
        let mut w = [Walker::default(); 2];
        let mut y = lo;
        let mut need = [true, true];
        while y < hi {
            let yc = i64::from(y) * ONE + HALF;
            for c in 0..2 {
                if need[c] {
                    // The chain's edge whose rows hold this centre: the
                    // next of its direction ending below it (it has one:
                    // the chain is gap-free over the rows).
                    let dir = if c == 0 { -1 } else { 1 };
                    let mut e = None;
                    while left[c] > 0 {
                        let Some(cand) = list.get(at[c]) else { return runs.flush() };
                        at[c] = next(at[c], self.back[c], list.len());
                        left[c] -= 1;
                        if cand.dir == dir && i64::from(cand.y1) > yc {
                            e = Some(cand);
                            break;
                        }
                    }
                    let Some(e) = e else { return runs.flush() };
                    w[c] = Walker::new(e, y);
                    need[c] = false;
                }
            }
            // Rows until either edge ends: two steps and a span each.
            let stop = w[0].end.min(w[1].end).min(hi);
            let [mut a, mut b] = w;
            while y < stop {
                let (l, r) = if a.q <= b.q { (a.q, b.q) } else { (b.q, a.q) };
                let (l, r) = (l.clamp(cx0, cx1), r.clamp(cx0, cx1));
                if r > l {
                    runs.emit(Span { y, x: l, len: (r - l) as u32 });
                }
                a.next();
                b.next();
                y += 1;
            }
            w = [a, b];
            need = [w[0].end <= y, w[1].end <= y];
        }
        runs.flush();
    }
}
