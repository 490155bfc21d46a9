//! The edge list every shape is turned into: closed contours of snapped
//! straight edges in a fixed-capacity array (no allocation).
//!
//! Points are snapped to [`BITS`] subpixel bits, the same grid as
//! [`SubPoint<4>`](crate::SubPoint), so a shape vertex and a triangle vertex
//! at the same `f32` position are the same point and their shared edges are
//! covered by exactly one of them.

use crate::{Error, SubPoint};

/// Subpixel bits of every shape vertex (1/16 px, as `SubPoint<4>`).
///
/// A vertex moves by at most 1/32 px when snapped, so a rectangle narrower
/// than that can vanish even when it holds a pixel centre:
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use microraster::{SubPoint, shape::{Rect, Shape, ShapeStyle, edges::BITS}};
/// assert_eq!(1 << BITS, 16);
/// let p = SubPoint::<BITS>::from_f32(0.49, 0.51)?;
/// assert_eq!((p.x(), p.y()), (8, 8)); // both 8/16 px
/// let style = ShapeStyle::fill(BinaryColor::On);
/// for (x, w, drawn) in [(0.49, 0.02, false), (0.45, 0.1, true)] {
///     // x 0.49 .. 0.51 snaps to 8/16 .. 8/16: empty; 0.45 .. 0.55 to 7/16 .. 9/16.
///     let mut display = MockDisplay::new();
///     Rect::new(x, 0.0, w, 1.0)?.styled(style)?.draw(&mut display).unwrap();
///     assert_eq!(display.get_pixel(Point::new(0, 0)).is_some(), drawn);
/// }
/// # Ok::<(), microraster::Error>(())
/// ```
pub const BITS: u32 = 4;

/// One non-horizontal edge, stored top to bottom (`y0 < y1`) in subpixel
/// units; `dir` is `+1` if the contour ran downwards, `-1` if upwards.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Edge {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
    pub dir: i32,
}

/// Closed contours as at most `N` edges.
///
/// Horizontal edges are dropped (they never cross a pixel row and enclose no
/// area in a row strip), so a rectangle costs two edges.
///
/// ```
/// use microraster::shape::EdgeList;
/// let mut e = EdgeList::<8>::new();
/// e.polygon(&[(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0)])?;
/// assert_eq!(e.len(), 2); // the two vertical sides
/// # Ok::<(), microraster::Error>(())
/// ```
// `repr(C)`, the edges last: with Rust's field order the list's zeroed
// fields lay on both sides of the uninitialised edges, and LLVM joined
// their stores into one `memset` over the whole capacity (5 KB for
// `MAX_EDGES`, in every draw of every shape).
#[derive(Debug, Clone)]
#[repr(C)]
pub struct EdgeList<const N: usize> {
    len: usize,
    // The contour being built (if `open`): its first and last point.
    open: bool,
    start: (i32, i32),
    last: (i32, i32),
    // Bounding rows in subpixel units of the stored edges (meaningless
    // while `len` is 0).
    y_min: i32,
    y_max: i32,
    // Columns (subpixels) of the edges, kept by a measuring list only.
    x_min: i32,
    x_max: i32,
    // A measuring list ([`EdgeList::measuring`]) stores no edge: it counts
    // them (up to `MAX_EDGES`) and tracks their rows.
    measure: bool,
    // A window ([`EdgeList::window`]): only edges meeting subpixel rows
    // `win.0 .. win.1` are stored; `twice` sums the signed area terms of
    // every edge pushed (stored or not) for [`EdgeList::orient_since`].
    windowed: bool,
    win: (i32, i32),
    twice: i128,
    // The window's rows in `f32` subpixels, widened by one, and whether a
    // chord of a curve may be left unsnapped when its float rows miss them
    // ([`EdgeList::curve_to`]): not while a group orients its members, which
    // needs every edge's area term.
    win_f: (f32, f32),
    cull: bool,
    // The current point as given, and whether `last` is it snapped (a
    // culled chord leaves it to be snapped when an edge needs it).
    last_f: (f32, f32),
    last_snapped: bool,
    // The current point's side of the window (`side`).
    last_side: i8,
    // Written as edges come, never zeroed ahead (a `heapless::Vec`): a list
    // costs what it holds, not its capacity.
    edges: heapless::Vec<Edge, N>,
}

impl<const N: usize> Default for EdgeList<N> {
    fn default() -> Self {
        Self::new()
    }
}

/// Snaps `(x, y)` pixels to the shape grid.
pub(crate) fn snap(x: f32, y: f32) -> Result<(i32, i32), Error> {
    let p = SubPoint::<BITS>::from_f32(x, y)?;
    Ok((p.x(), p.y()))
}

impl<const N: usize> EdgeList<N> {
    /// An empty list.
    ///
    /// ```
    /// let e = microraster::shape::EdgeList::<4>::new();
    /// assert!(e.is_empty());
    /// ```
    pub const fn new() -> Self {
        EdgeList {
            edges: heapless::Vec::new(),
            len: 0,
            open: false,
            start: (0, 0),
            last: (0, 0),
            y_min: 0,
            x_min: 0,
            x_max: 0,
            y_max: 0,
            measure: false,
            windowed: false,
            win: (0, 0),
            twice: 0,
            win_f: (0.0, 0.0),
            cull: false,
            last_f: (0.0, 0.0),
            last_snapped: true,
            last_side: 0,
        }
    }

    /// Empties the list, as [`EdgeList::new`] would: the stored edges are
    /// only forgotten (making or emptying a list costs a few stores, whatever
    /// its capacity; its storage is written as edges come).
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<4>::new();
    /// e.move_to(0.0, 0.0)?;
    /// e.line_to(3.0, 6.0)?;
    /// e.clear(); // the open contour goes too
    /// assert!(e.is_empty());
    /// e.close()?; // nothing to close
    /// assert!(e.is_empty());
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn clear(&mut self) {
        self.len = 0;
        self.edges.clear();
        self.open = false;
        (self.y_min, self.y_max) = (0, 0);
        self.twice = 0;
    }

    /// Number of stored edges.
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<4>::new();
    /// e.polygon(&[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)])?;
    /// assert_eq!(e.len(), 2); // the top edge is horizontal: dropped
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const fn len(&self) -> usize {
        self.len
    }

    /// True if no edge is stored.
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<4>::new();
    /// e.polygon(&[(0.0, 2.0), (9.0, 2.0)])?; // a flat contour: no area, no edge
    /// assert!(e.is_empty());
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }

    pub(crate) fn edges(&self) -> &[Edge] {
        // `len ≤ N` but in a measuring list, which stores none.
        &self.edges
    }

    /// Columns (subpixel units) spanned by the edges of a measuring list
    /// ([`EdgeList::measuring`]): `x_min > x_max` if empty.
    pub(crate) fn x_range(&self) -> (i32, i32) {
        if self.len == 0 { (i32::MAX, i32::MIN) } else { (self.x_min, self.x_max) }
    }

    /// Rows (subpixel units) spanned by the edges: `y_min > y_max` if empty.
    pub(crate) fn y_range(&self) -> (i32, i32) {
        if self.len == 0 { (i32::MAX, i32::MIN) } else { (self.y_min, self.y_max) }
    }

    /// Starts a new contour at `(x, y)` pixels, closing the previous one.
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<8>::new();
    /// e.move_to(0.0, 0.0)?;
    /// e.line_to(4.0, 4.0)?;
    /// e.move_to(10.0, 0.0)?; // closes the first contour (back to (0, 0))
    /// assert_eq!(e.len(), 2);
    /// assert!(e.move_to(f32::NAN, 0.0).is_err());
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn move_to(&mut self, x: f32, y: f32) -> Result<(), Error> {
        let p = snap(x, y)?;
        self.close()?;
        (self.open, self.start, self.last) = (true, p, p);
        (self.last_f, self.last_snapped, self.last_side) = ((x, y), true, self.side(x, y));
        Ok(())
    }

    /// Adds an edge from the current point to `(x, y)`; without a current
    /// contour this starts one.
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<1>::new();
    /// e.line_to(0.0, 0.0)?; // starts the contour
    /// e.line_to(0.0, 5.0)?; // one edge
    /// assert_eq!(e.len(), 1);
    /// assert!(e.line_to(3.0, 9.0).is_err()); // a second edge does not fit in 1
    /// # Ok::<(), microraster::Error>(())
    /// ```
    #[inline(always)]
    pub fn line_to(&mut self, x: f32, y: f32) -> Result<(), Error> {
        let p = snap(x, y)?;
        if !self.open {
            (self.open, self.start) = (true, p);
        } else {
            let last = self.last_point()?;
            self.push(last, p)?;
        }
        // Side 0: the next chord from here is not culled.
        (self.last, self.last_f, self.last_snapped, self.last_side) = (p, (x, y), true, 0);
        Ok(())
    }

    /// Closes the current contour back to its first point.
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<4>::new();
    /// e.move_to(0.0, 0.0)?;
    /// e.line_to(3.0, 6.0)?;
    /// e.close()?; // the edge back to (0, 0)
    /// assert_eq!(e.len(), 2);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn close(&mut self) -> Result<(), Error> {
        if self.open {
            self.open = false;
            let last = self.last_point()?;
            self.push(last, self.start)?;
        }
        Ok(())
    }

    /// Adds a closed polygon through `points` (pixels).
    ///
    /// ```
    /// let mut e = microraster::shape::EdgeList::<8>::new();
    /// e.polygon(&[(0.0, 0.0), (6.0, 1.0), (3.0, 5.0)])?;
    /// assert_eq!(e.len(), 3);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn polygon(&mut self, points: &[(f32, f32)]) -> Result<(), Error> {
        self.close()?;
        for &(x, y) in points {
            self.line_to(x, y)?;
        }
        self.close()
    }

    /// One edge from `a` to `b` (pixels), outside the contour being built:
    /// callers keep their edges closed cycles. `flip` reverses it. Culled
    /// unsnapped where a windowed list would drop it (`curve.rs`).
    pub(crate) fn edge(&mut self, a: (f32, f32), b: (f32, f32), flip: bool) -> Result<(), Error> {
        if self.cull {
            let side = self.side(a.0, a.1);
            if side != 0 && side == self.side(b.0, b.1) {
                return Ok(());
            }
        }
        let (a, b) = (snap(a.0, a.1)?, snap(b.0, b.1)?);
        if flip { self.push(b, a) } else { self.push(a, b) }
    }

    /// Where the contour being added starts, for [`Self::orient_since`].
    /// Needs every edge's area term from now on, so [`Self::curve_to`]
    /// culls no more chords.
    pub(crate) fn mark(&mut self) -> (usize, i128) {
        self.cull = false;
        (self.len, self.twice)
    }

    /// Reverses the edges added since `mark` if the winding number they
    /// enclose integrates to less than zero (`∫w = −Σ dir·(x0 + x1)·(y1 − y0)/2`
    /// over closed contours), so every group member adds coverage with the
    /// same sign. `i128`: each term is below 2^59, their sum is not. A
    /// windowed list sums the terms as edges are pushed, the ones it drops
    /// too, so its members turn as the whole list's would.
    pub(crate) fn orient_since(&mut self, (from, twice): (usize, i128)) {
        let end = self.edges.len();
        let edges = &mut self.edges[from.min(end)..];
        let twice = if self.windowed { self.twice - twice } else { edges.iter().map(area_term).sum() };
        if twice < 0 {
            edges.iter_mut().for_each(|e| e.dir = -e.dir);
        }
    }

    /// From now on, stores only the edges that meet subpixel rows
    /// `lo .. hi` (`y0 < hi` and `y1 > lo`): the only ones that cross a
    /// pixel row (or row centre) in them, so a scan of those rows gives the
    /// same coverage with fewer edges. Length and rows count the stored ones.
    pub(crate) fn window(&mut self, lo: i32, hi: i32) {
        (self.windowed, self.win) = (true, (lo, hi));
        // Rows as `f32` exactly below 2^24 subpixels (a band's are); a
        // chord culled by `curve_to` has both ends' `16·y` at least 1 past
        // them, and snapping moves `16·y` by 1/2 at most.
        const EXACT: i32 = 1 << 24;
        self.cull = lo > -EXACT && hi < EXACT && lo <= hi;
        self.win_f = (lo as f32 - 1.0, hi as f32 + 1.0);
    }

    /// Sorts the edges by their top, which the scan's active-edge list
    /// needs (`core`'s unstable sort: no allocation).
    pub(crate) fn sort_by_top(&mut self) {
        self.edges.sort_unstable_by_key(|e| e.y0);
    }

    fn push(&mut self, a: (i32, i32), b: (i32, i32)) -> Result<(), Error> {
        if a.1 == b.1 {
            return Ok(());
        }
        let e = if a.1 < b.1 {
            Edge { x0: a.0, y0: a.1, x1: b.0, y1: b.1, dir: 1 }
        } else {
            Edge { x0: b.0, y0: b.1, x1: a.0, y1: a.1, dir: -1 }
        };
        if self.windowed {
            self.twice += area_term(&e);
            if e.y1 <= self.win.0 || e.y0 >= self.win.1 {
                return Ok(());
            }
        }
        if self.measure {
            if self.len >= crate::shape::MAX_EDGES {
                return Err(Error::BufferTooSmall);
            }
            let (l, r) = (e.x0.min(e.x1), e.x0.max(e.x1));
            (self.x_min, self.x_max) =
                if self.len == 0 { (l, r) } else { (self.x_min.min(l), self.x_max.max(r)) };
        } else {
            self.edges.push(e).map_err(|_| Error::BufferTooSmall)?;
        }
        (self.y_min, self.y_max) =
            if self.len == 0 { (e.y0, e.y1) } else { (self.y_min.min(e.y0), self.y_max.max(e.y1)) };
        self.len += 1;
        Ok(())
    }
}

/// `−dir·(x0 + x1)·(y1 − y0)`: twice the integral of the winding number the
/// edge adds, over closed contours. Below 2^59 in magnitude (coordinates
/// within ±2^28 subpixels, `y1 − y0` below 2^29): an `i64` product, summed
/// in `i128`.
fn area_term(e: &Edge) -> i128 {
    let x = i64::from(e.x0) + i64::from(e.x1);
    i128::from(-i64::from(e.dir) * x * (i64::from(e.y1) - i64::from(e.y0)))
}

impl EdgeList<0> {
    /// A list that stores no edge but measures them: its length, rows and
    /// errors are those of an `EdgeList<MAX_EDGES>` given the same contours
    /// (more than [`MAX_EDGES`](crate::shape::MAX_EDGES) edges is
    /// [`Error::BufferTooSmall`]). What [`Styled::new`](crate::shape::Styled::new)
    /// needs to check a shape and find its rows, without writing (or
    /// zeroing) a list of edges.
    pub(crate) const fn measuring() -> Self {
        let mut e = EdgeList::new();
        e.measure = true;
        e
    }
}

/// The edges a row (or row strip) can cross, over edges sorted by top:
/// entered once their top is reached, dropped once their bottom is passed,
/// so each row looks at its own edges only.
pub(crate) struct Active<const N: usize> {
    // Indices of the active edges, written as they enter (not zeroed ahead).
    idx: heapless::Vec<u32, N>,
    next: usize,
}

impl<const N: usize> Active<N> {
    pub(crate) fn new() -> Self {
        Active { idx: heapless::Vec::new(), next: 0 }
    }

    /// Enters edges with `y0 < top_below` and drops those with `y1 <= bottom_above`.
    pub(crate) fn advance(&mut self, edges: &[Edge], top_below: i64, bottom_above: i64) {
        while self.next < edges.len() && i64::from(edges[self.next].y0) < top_below {
            // Fits: at most N edges exist (a list of capacity N).
            let _ = self.idx.push(self.next as u32);
            self.next += 1;
        }
        self.idx.retain(|&i| i64::from(edges[i as usize].y1) > bottom_above);
    }

    /// How many edges have entered so far: every active index is below it.
    pub(crate) fn entered(&self) -> usize {
        self.next
    }

    pub(crate) fn edges<'e>(&self, edges: &'e [Edge]) -> impl Iterator<Item = &'e Edge> + use<'_, 'e, N> {
        self.idx.iter().map(move |&i| &edges[i as usize])
    }

    /// [`Self::edges`] with each edge's index in `edges`.
    pub(crate) fn indexed<'e>(
        &self,
        edges: &'e [Edge],
    ) -> impl Iterator<Item = (u32, &'e Edge)> + use<'_, 'e, N> {
        self.idx.iter().map(move |&i| (i, &edges[i as usize]))
    }
}

mod curve;

#[cfg(test)]
mod tests;
