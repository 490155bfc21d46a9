//! The band buffer: a few full-width rows of colour, owned by the user.

mod canvas;

use crate::blit::Blitter;
use crate::edge::Span;
use crate::{ClipRect, MAX_FRAME_DIM};
use embedded_graphics_core::prelude::PixelColor;

/// `H` rows of `W` pixels of colour `C`: the only frame memory microraster
/// uses. Its size is `W · H · size_of::<C>()` bytes ([`Band::BYTES`]); for
/// example 320 × 16 rows of `Rgb565` is 10,240 bytes, against 153,600 for a
/// full 320 × 240 framebuffer.
///
/// `W` and `H` must be 1 to [`MAX_FRAME_DIM`]; anything else is a compile
/// error. `new` is a `const fn`, so a band can live in a `static` (behind the
/// user's choice of cell or mutex) or on the stack.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::Band;
/// static BAND: Band<Rgb565, 320, 16> = Band::new(Rgb565::new(0, 0, 0));
/// assert_eq!(Band::<Rgb565, 320, 16>::BYTES, 320 * 16 * 2);
/// assert_eq!(BAND.rows().len(), 16);
/// ```
#[derive(Clone)]
pub struct Band<C, const W: usize, const H: usize> {
    rows: [[C; W]; H],
}

impl<C: PixelColor, const W: usize, const H: usize> Band<C, W, H> {
    const CHECK: () = assert!(
        W >= 1 && H >= 1 && W <= MAX_FRAME_DIM as usize && H <= MAX_FRAME_DIM as usize,
        "band width and height must be 1..=MAX_FRAME_DIM"
    );

    /// Bytes of memory the band occupies.
    pub const BYTES: usize = core::mem::size_of::<Self>();

    /// A band filled with `fill`.
    pub const fn new(fill: C) -> Self {
        let () = Self::CHECK;
        Band { rows: [[fill; W]; H] }
    }

    /// The rows of colour.
    pub fn rows(&self) -> &[[C; W]; H] {
        &self.rows
    }

    /// A view of the first `rows` rows (at most `H`) as frame rows
    /// `y0 .. y0 + rows`, cleared to `background`.
    pub fn view(&mut self, y0: i32, rows: usize, background: C) -> BandView<'_, C, W> {
        let view = self.view_uncleared(y0, rows);
        clear_rows(view.rows, background);
        view
    }

    /// All `H` rows, for the band loop that lends them to a sink
    /// ([`render::link`](crate::render::link)).
    pub(crate) fn rows_mut(&mut self) -> &mut [[C; W]] {
        &mut self.rows
    }

    /// The same view with the rows as they are (see [`LazyClear`]).
    pub(crate) fn view_uncleared(&mut self, y0: i32, rows: usize) -> BandView<'_, C, W> {
        BandView { y0, rows: &mut self.rows[..rows.min(H)], x0: 0, x1: W as i32 }
    }
}

/// Some rows of a [`Band`] placed at frame row `y0`: a [`Blitter`] whose clip
/// is exactly those rows, and an `embedded-graphics`
/// [`DrawTarget`](embedded_graphics::draw_target::DrawTarget) in frame
/// coordinates (any e-g drawable draws into it; pixels outside its rows are
/// dropped).
pub struct BandView<'a, C, const W: usize> {
    y0: i32,
    rows: &'a mut [[C; W]],
    // The clip's columns `x0..x1` (`0..W` but for a damaged frame, see
    // `render::Damage`): shapes that honour `clip()` skip the others.
    x0: i32,
    x1: i32,
}

impl<'a, C: PixelColor, const W: usize> BandView<'a, C, W> {
    /// `rows` placed at frame row `y0`, cleared to `background` if given.
    /// Once per band. Out of line on the Cortex-M0, as LLVM chose there
    /// before [`clear_rows`] (inlined into the band loop, its band loop
    /// took 10 % more instructions); elsewhere LLVM's choice (on the
    /// Cortex-M4F, out of line cost the 2D and perspective-correct frames
    /// 0.6 to 1.6 %).
    #[cfg_attr(all(target_arch = "arm", not(target_feature = "thumb2")), inline(never))]
    pub(crate) fn from_rows(rows: &'a mut [[C; W]], y0: i32, background: Option<C>) -> Self {
        if let Some(bg) = background {
            clear_rows(rows, bg);
        }
        BandView { y0, rows, x0: 0, x1: W as i32 }
    }

    /// The same view with its [`Blitter::clip`] narrowed to columns
    /// `x0..x1` (within `0..W`): for a damaged frame
    /// ([`Renderer::render_damaged`](crate::Renderer::render_damaged)), whose
    /// other columns are not sent. Pixels of those columns may still be
    /// written (e-g drawables draw the whole row) but are then meaningless.
    pub(crate) fn with_columns(self, x0: i32, x1: i32) -> Self {
        let x1 = x1.clamp(0, W as i32);
        BandView { x0: x0.clamp(0, x1), x1, ..self }
    }

    /// The pixels, row by row, as `fill_contiguous` expects them.
    pub fn pixels(&self) -> impl Iterator<Item = C> + '_ {
        // One flat slice: the nested iterator measured 9× slower on the host.
        self.rows.as_flattened().iter().copied()
    }

    /// Number of rows in the view.
    pub fn height(&self) -> usize {
        self.rows.len()
    }

    /// First frame row of the view.
    pub fn y0(&self) -> i32 {
        self.y0
    }

    /// One past the last frame row of the view: its rows are `y0()..y1()`
    /// (`y0() + height()`).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::{Band, Renderer, render::from_fn};
    /// let mut band = Band::<BinaryColor, 8, 3>::new(BinaryColor::Off); // 3-row bands
    /// let (mut display, mut rows) = (MockDisplay::new(), Vec::new());
    /// let frame = from_fn(|view| {
    ///     rows.push(view.y0()..view.y1());
    ///     Ok(())
    /// });
    /// Renderer::new(8, BinaryColor::Off).render(frame, &mut band, &mut display)?;
    /// assert_eq!(rows, [0..3, 3..6, 6..8]);
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn y1(&self) -> i32 {
        // At most `H` rows: a band of more than `i32::MAX` rows cannot exist.
        self.y0 + self.rows.len() as i32
    }

    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [C; W]> {
        let i = usize::try_from(y.checked_sub(self.y0)?).ok()?;
        self.rows.get_mut(i)
    }
}

impl<C: PixelColor, const W: usize> Blitter<C> for BandView<'_, C, W> {
    fn clip(&self) -> ClipRect {
        ClipRect::new(self.x0, self.y0, self.x1, self.y0.saturating_add(self.rows.len() as i32))
    }

    #[inline]
    fn set_pixel(&mut self, x: i32, y: i32, color: C) {
        if let Some(p) = self.row_mut(y).and_then(|r| r.get_mut(x as usize)) {
            *p = color;
        }
    }

    #[inline]
    fn fill_span(&mut self, s: Span, color: C) {
        if let Some(px) = columns(s).and_then(|(x0, x1)| self.row_mut(s.y)?.get_mut(x0..x1)) {
            fill_run(px, color);
        }
    }

    #[inline]
    fn shade_span<I: Iterator<Item = C>>(&mut self, s: Span, colors: I) {
        if let Some(px) = columns(s).and_then(|(x0, x1)| self.row_mut(s.y)?.get_mut(x0..x1)) {
            for (p, c) in px.iter_mut().zip(colors) {
                *p = c;
            }
        }
    }
}

/// The columns `x0..x1` of a span, if they are non-negative and addressable.
#[inline(always)]
fn columns(s: Span) -> Option<(usize, usize)> {
    let x0 = usize::try_from(s.x).ok()?;
    Some((x0, x0.checked_add(usize::try_from(s.len).ok()?)?))
}

/// A [`BandView`] whose rows are cleared to the background on first use
/// rather than up front: a row's first span is written together with the
/// background around it, in one pass over the row instead of two, and
/// [`LazyClear::finish`] clears the rows nothing touched. The pixels are the
/// same as clearing first.
pub(crate) struct LazyClear<'v, 'a, C, const W: usize, const H: usize> {
    view: &'v mut BandView<'a, C, W>,
    background: C,
    cleared: [bool; H],
    // Rows of the view not cleared yet.
    pending: usize,
}

impl<'v, 'a, C: PixelColor, const W: usize, const H: usize> LazyClear<'v, 'a, C, W, H> {
    /// `view`'s rows, none cleared yet (`view` has at most `H` rows).
    pub(crate) fn new(view: &'v mut BandView<'a, C, W>, background: C) -> Self {
        let pending = view.rows.len().min(H);
        LazyClear { view, background, cleared: [false; H], pending }
    }

    /// Row `y`, cleared if it is not yet.
    #[inline(always)]
    fn touch(&mut self, y: i32) -> Option<&mut [C; W]> {
        let i = usize::try_from(y.checked_sub(self.view.y0)?).ok()?;
        let (row, done) = (self.view.rows.get_mut(i)?, self.cleared.get_mut(i)?);
        if !*done {
            clear_row(row, self.background);
            *done = true;
            self.pending -= 1;
        }
        Some(row)
    }

    /// Clears frame rows `y_lo..=y_hi` of the view that are not yet, for a
    /// writer that then goes straight to [`LazyClear::view`].
    pub(crate) fn clear_rows(&mut self, y_lo: i32, y_hi: i32) {
        if self.pending == 0 {
            return;
        }
        let (y0, n) = (self.view.y0, self.view.rows.len().min(H));
        let index = |y: i32| y.saturating_sub(y0).clamp(0, n as i32) as usize;
        for i in index(y_lo)..index(y_hi.saturating_add(1)) {
            if !self.cleared[i] {
                fill_run(&mut self.view.rows[i], self.background);
                self.cleared[i] = true;
                self.pending -= 1;
            }
        }
    }

    /// The view itself: only rows already cleared may be written through it.
    pub(crate) fn view(&mut self) -> &mut BandView<'a, C, W> {
        self.view
    }

    /// Clears the rows nothing was written to.
    pub(crate) fn finish(self) {
        if self.pending == 0 {
            return;
        }
        for (row, done) in self.view.rows.iter_mut().zip(self.cleared) {
            if !done {
                fill_run(row, self.background);
            }
        }
    }
}

impl<C: PixelColor, const W: usize, const H: usize> Blitter<C> for LazyClear<'_, '_, C, W, H> {
    fn clip(&self) -> ClipRect {
        self.view.clip()
    }

    #[inline]
    fn set_pixel(&mut self, x: i32, y: i32, color: C) {
        if let Some(p) = usize::try_from(x).ok().and_then(|x| self.touch(y)?.get_mut(x)) {
            *p = color;
        }
    }

    #[inline(always)]
    fn fill_span(&mut self, s: Span, color: C) {
        let Some(i) = s.y.checked_sub(self.view.y0).and_then(|i| usize::try_from(i).ok()) else { return };
        let (Some(row), Some(done)) = (self.view.rows.get_mut(i), self.cleared.get_mut(i)) else { return };
        let Some((x0, x1)) = columns(s) else { return };
        if *done {
            if let Some(px) = row.get_mut(x0..x1) {
                fill_run(px, color);
            }
        } else {
            *done = true;
            self.pending -= 1;
            first_fill(row, x0, x1, color, self.background);
        }
    }

    #[inline]
    fn shade_span<I: Iterator<Item = C>>(&mut self, s: Span, colors: I) {
        if let Some(px) = columns(s).and_then(|(x0, x1)| self.touch(s.y)?.get_mut(x0..x1)) {
            for (p, c) in px.iter_mut().zip(colors) {
                *p = c;
            }
        }
    }
}

/// A row's first write, once per row (out of line): background, the span
/// `x0..x1`, background, in one pass; the whole row to background if the span
/// is outside it.
#[inline(never)]
fn first_fill<C: Copy>(row: &mut [C], x0: usize, x1: usize, color: C, background: C) {
    match (row.get(..x0).is_some(), row.get(x0..x1).is_some()) {
        (true, true) => {
            let (head, rest) = row.split_at_mut(x0);
            let (span, tail) = rest.split_at_mut(x1 - x0);
            fill_run(head, background);
            fill_run(span, color);
            fill_run(tail, background);
        }
        _ => fill_run(row, background),
    }
}

/// Out of line: once per row, from per-pixel writers.
#[inline(never)]
fn clear_row<C: Copy>(row: &mut [C], background: C) {
    fill_run(row, background);
}

/// Whether whole bands are cleared by [`clear_run`]: on ARMv7-M (the
/// Cortex-M3/M4/M7). Cleared row by row, as elsewhere, a value that is one
/// byte repeated (black, the far depth) becomes a `memset` call, and
/// `compiler_builtins`' `memset` there takes about nine instructions per 16
/// bytes where `clear_run`'s blocks take about four (`fw_bench` on the
/// Cortex-M4F: the band loop −13 %, the 3D frames −0.2 to −1.5 %). The
/// Cortex-M0 keeps its row-by-row fills (the blocks made its 3D frames
/// dearer, by 0.06 %, and `fill` out of line its band loop, by 15 %), and
/// so does the host, whose `memset` is not `compiler_builtins`'.
pub(crate) const BLOCK_CLEAR: bool = cfg!(all(target_arch = "arm", target_feature = "thumb2"));

/// Whole rows cleared to `v`: one [`clear_run`] over all of them where
/// [`BLOCK_CLEAR`], else row by row with [`fill_run`].
#[inline(always)]
pub(crate) fn clear_rows<T: Copy, const W: usize>(rows: &mut [[T; W]], v: T) {
    if BLOCK_CLEAR {
        clear_run(rows.as_flattened_mut(), v);
    } else {
        for r in rows {
            fill_run(r, v);
        }
    }
}

/// `px.fill(v)` in blocks of 16 values, then the rest ([`BLOCK_CLEAR`]).
/// Out of line, so the loop is compiled for a value it does not know and
/// stays a loop (for a known one-byte value it would become `memset`).
#[inline(never)]
pub(crate) fn clear_run<T: Copy>(px: &mut [T], v: T) {
    let block = [v; 16];
    let mut chunks = px.chunks_exact_mut(16);
    for ch in &mut chunks {
        ch.copy_from_slice(&block);
    }
    chunks.into_remainder().fill(v);
}

/// `px.fill(c)` with few branches: runs of 8 or more pixels are written in
/// 8-pixel blocks, the last block overlapping the one before it, shorter runs
/// as two overlapping 4-, 2- or 1-pixel blocks. Every pixel gets `c`, as with
/// `fill`; only the number of (predictable) branches per run changes, which is
/// what a span fill pays for beside the stores.
#[inline(always)]
pub(crate) fn fill_run<C: Copy>(px: &mut [C], c: C) {
    let n = px.len();
    if n >= 8 {
        let block = [c; 8];
        let mut chunks = px.chunks_exact_mut(8);
        for ch in &mut chunks {
            ch.copy_from_slice(&block);
        }
        // The last 8 again (overlapping, or the same block): no branch.
        px[n - 8..].copy_from_slice(&block);
    } else if n >= 4 {
        px[..4].copy_from_slice(&[c; 4]);
        px[n - 4..].copy_from_slice(&[c; 4]);
    } else if n >= 2 {
        px[..2].copy_from_slice(&[c; 2]);
        px[n - 2..].copy_from_slice(&[c; 2]);
    } else if let Some(p) = px.first_mut() {
        *p = c;
    }
}

#[cfg(test)]
mod tests;
