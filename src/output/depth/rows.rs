//! [`DepthRows`]: a band's depth rows with their format in the type, as the
//! 3D draw calls take them.

use core::ops::{Deref, DerefMut};

use super::{DepthBand, DepthFormat, NoDepth};

/// Rows of `W` depth values in format `F`, borrowed for drawing: what
/// [`draw_triangle`](crate::raster3d::draw_triangle) and the other 3D draw
/// calls take. The format is part of the type, so those calls infer it from
/// this argument (no turbofish); a slice of `F::Storage` could not tell them
/// `F` (16-bit storage is both a format and a `u16`).
///
/// Obtained from [`DepthBand::rows_mut`], from a caller's own storage with
/// [`DepthRows::new`], or as [`DepthRows::none`] for drawing without depth.
/// Row `i` holds the depth of the `i`-th row of the colour view drawn with
/// it; a row beyond the last is not drawn (except with [`NoDepth`], which
/// draws every row). Dereferences to the slice of rows.
///
/// ```
/// use microraster::depth::{Depth16, DepthBand, DepthRows, NoDepth};
/// let mut z = DepthBand::<Depth16, 8, 4>::new();
/// let mut rows = z.rows_mut(3); // DepthRows<'_, Depth16, 8>: the first 3 rows
/// assert_eq!(rows.len(), 3);
/// rows[0][5] = 7;
/// assert_eq!(z.get(0, 5), Some(7));
/// let none: DepthRows<'_, NoDepth, 8> = DepthRows::none();
/// assert!(none.is_empty());
/// ```
pub struct DepthRows<'a, F: DepthFormat, const W: usize> {
    rows: &'a mut [[F::Storage; W]],
}

impl<'a, F: DepthFormat, const W: usize> DepthRows<'a, F, W> {
    /// Depth rows in the caller's own storage (a frame-sized buffer, say).
    /// `F` is not implied by the storage type, so name it here if nothing
    /// else does.
    ///
    /// ```
    /// use microraster::depth::{Depth16, DepthFormat, DepthRows};
    /// let mut store = [[Depth16::FAR; 8]; 2];
    /// let rows = DepthRows::<Depth16, 8>::new(&mut store);
    /// assert_eq!(rows.len(), 2);
    /// ```
    pub fn new(rows: &'a mut [[F::Storage; W]]) -> Self {
        DepthRows { rows }
    }

    /// The same rows, borrowed again for a shorter time (to hand to a call
    /// that takes them by value while keeping these).
    ///
    /// ```
    /// use microraster::depth::{Depth8, DepthBand};
    /// let mut z = DepthBand::<Depth8, 4, 2>::new();
    /// let mut rows = z.rows_mut(2);
    /// rows.reborrow()[1][0] = 3;
    /// assert_eq!(rows[1][0], 3);
    /// ```
    pub fn reborrow(&mut self) -> DepthRows<'_, F, W> {
        DepthRows { rows: self.rows }
    }

    /// The rows as a plain slice, for the whole borrow.
    ///
    /// ```
    /// use microraster::depth::{Depth16, DepthBand};
    /// let mut z = DepthBand::<Depth16, 4, 2>::new();
    /// let slice: &mut [[u16; 4]] = z.rows_mut(1).into_slice();
    /// assert_eq!(slice.len(), 1);
    /// ```
    pub fn into_slice(self) -> &'a mut [[F::Storage; W]] {
        self.rows
    }
}

impl<const W: usize> DepthRows<'_, NoDepth, W> {
    /// No depth at all: for drawing without a depth band (every fragment
    /// passes, as with any [`NoDepth`] rows).
    ///
    /// ```
    /// use microraster::depth::DepthRows;
    /// assert_eq!(DepthRows::<_, 16>::none().len(), 0);
    /// ```
    pub fn none() -> Self {
        DepthRows { rows: &mut [] }
    }
}

impl<F: DepthFormat, const W: usize> Deref for DepthRows<'_, F, W> {
    type Target = [[F::Storage; W]];

    #[inline(always)]
    fn deref(&self) -> &Self::Target {
        self.rows
    }
}

impl<F: DepthFormat, const W: usize> DerefMut for DepthRows<'_, F, W> {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut Self::Target {
        self.rows
    }
}

impl<F: DepthFormat, const W: usize> core::fmt::Debug for DepthRows<'_, F, W> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("DepthRows").field("rows", &self.rows.len()).finish()
    }
}

impl<F: DepthFormat, const W: usize, const H: usize> DepthBand<F, W, H> {
    /// The first `rows` rows (at most `H`) for drawing, as
    /// [`draw_triangle`](crate::raster3d::draw_triangle) takes them (the
    /// format comes along in the type).
    ///
    /// ```
    /// use microraster::depth::{Depth16, DepthBand};
    /// let mut z = DepthBand::<Depth16, 8, 4>::new();
    /// assert_eq!(z.rows_mut(9).len(), 4); // clamped to H
    /// ```
    pub fn rows_mut(&mut self, rows: usize) -> DepthRows<'_, F, W> {
        DepthRows { rows: &mut self.rows[..rows.min(H)] }
    }
}
