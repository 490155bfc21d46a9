//! The band buffer: a few full-width rows of colour, owned by the user.

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
/// use embedded_graphics_core::pixelcolor::Rgb565;
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
        let n = rows.min(H);
        let rows = &mut self.rows[..n];
        for r in rows.iter_mut() {
            r.fill(background);
        }
        BandView { y0, rows }
    }
}

/// Some rows of a [`Band`] placed at frame row `y0`: a [`Blitter`] whose clip
/// is exactly those rows.
pub struct BandView<'a, C, const W: usize> {
    y0: i32,
    rows: &'a mut [[C; W]],
}

impl<C: PixelColor, const W: usize> BandView<'_, C, W> {
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

    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [C; W]> {
        let i = usize::try_from(y.checked_sub(self.y0)?).ok()?;
        self.rows.get_mut(i)
    }
}

impl<C: PixelColor, const W: usize> Blitter<C> for BandView<'_, C, W> {
    fn clip(&self) -> ClipRect {
        ClipRect::new(0, self.y0, W as i32, self.y0.saturating_add(self.rows.len() as i32))
    }

    #[inline]
    fn set_pixel(&mut self, x: i32, y: i32, color: C) {
        if let Some(p) = self.row_mut(y).and_then(|r| r.get_mut(x as usize)) {
            *p = color;
        }
    }

    #[inline]
    fn fill_span(&mut self, s: Span, color: C) {
        if let Some(px) =
            self.row_mut(s.y).and_then(|r| r.get_mut(s.x as usize..s.x as usize + s.len as usize))
        {
            px.fill(color);
        }
    }

    #[inline]
    fn shade_span<I: Iterator<Item = C>>(&mut self, s: Span, colors: I) {
        if let Some(px) =
            self.row_mut(s.y).and_then(|r| r.get_mut(s.x as usize..s.x as usize + s.len as usize))
        {
            for (p, c) in px.iter_mut().zip(colors) {
                *p = c;
            }
        }
    }
}
