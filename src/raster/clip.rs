//! Clip rectangles in whole pixels.

/// The largest frame width or height microraster accepts, in pixels.
///
/// Pixel indices stay below 2^12, which the overflow proofs in
/// [`crate::edge`] rely on.
pub const MAX_FRAME_DIM: u32 = 4096;

/// A half-open rectangle of pixels: columns `x0..x1`, rows `y0..y1`.
///
/// Rasterizers emit only pixels inside it. Construct with [`ClipRect::new`],
/// which clamps to `0..=MAX_FRAME_DIM` so every pixel index is small.
///
/// ```
/// use microraster::ClipRect;
/// let c = ClipRect::new(0, 0, 320, 16);
/// assert!(c.contains(319, 15) && !c.contains(320, 0));
/// assert!(ClipRect::new(5, 5, 2, 9).is_empty());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ClipRect {
    x0: i32,
    y0: i32,
    x1: i32,
    y1: i32,
}

impl ClipRect {
    /// Columns `x0..x1`, rows `y0..y1`, each clamped to `0..=MAX_FRAME_DIM`.
    /// An inverted rectangle is empty.
    pub const fn new(x0: i32, y0: i32, x1: i32, y1: i32) -> Self {
        const fn clamp(v: i32) -> i32 {
            if v < 0 {
                0
            } else if v > MAX_FRAME_DIM as i32 {
                MAX_FRAME_DIM as i32
            } else {
                v
            }
        }
        ClipRect { x0: clamp(x0), y0: clamp(y0), x1: clamp(x1), y1: clamp(y1) }
    }

    /// First column.
    pub const fn x0(&self) -> i32 {
        self.x0
    }
    /// First row.
    pub const fn y0(&self) -> i32 {
        self.y0
    }
    /// One past the last column.
    pub const fn x1(&self) -> i32 {
        self.x1
    }
    /// One past the last row.
    pub const fn y1(&self) -> i32 {
        self.y1
    }

    /// True if no pixel is inside.
    pub const fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    /// True if pixel `(x, y)` is inside.
    pub const fn contains(&self, x: i32, y: i32) -> bool {
        x >= self.x0 && x < self.x1 && y >= self.y0 && y < self.y1
    }

    /// The rows `y0..y1` of this rectangle that also lie in `rows`.
    pub const fn with_rows(self, y0: i32, y1: i32) -> Self {
        let ny0 = if y0 > self.y0 { y0 } else { self.y0 };
        let ny1 = if y1 < self.y1 { y1 } else { self.y1 };
        ClipRect { x0: self.x0, y0: ny0, x1: self.x1, y1: ny1 }
    }
}
