//! The band renderer: a frame drawn band by band into a `DrawTarget`.

use crate::band::Band;
use crate::edge::Cull;

mod band3d;
mod binned;
mod damage;
mod dirty;
pub mod link;
#[cfg(feature = "async")]
mod link_async;
mod pass;
#[cfg(feature = "async")]
mod spi_panel;
#[cfg(feature = "std")]
mod threads;
use crate::{Error, Interpolate, RenderError};
pub use band3d::Band3d;
pub use binned::Binned2d;
pub use damage::Damage;
pub use dirty::{DirtyBands, signature};
use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;
pub use link::{BandSink, Blocking, FrameBands, Lent};
#[cfg(feature = "async")]
pub use link_async::{AsyncBandSink, poll_ready};
pub use pass::{Direct3d, FromFn, Pass, Then, Triangles3d, from_fn};
#[cfg(feature = "async")]
pub use spi_panel::{SpiPanel, SpiPanelError};

/// Renders frames, band by band, to a display.
///
/// For each band of `H` rows (the last may be shorter) the renderer clears the
/// band to the background, lets the frame's [`Pass`] draw what overlaps it
/// (2D [`Primitive`](crate::Primitive)s, 3D triangles, drawables; clipped to
/// the band), and sends the band with one
/// [`DrawTarget::fill_contiguous`] over the band's rectangle. The frame is `W`
/// pixels wide (the band's width) and [`Renderer::height`] rows tall, placed at
/// [`Renderer::offset`] on the target. The image does not depend on `H`.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{Band, Primitive, Renderer, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
/// let mut band = Band::<BinaryColor, 4, 2>::new(BinaryColor::Off);
/// let mut display = MockDisplay::new();
/// Renderer::new(4, BinaryColor::Off).render(&scene, &mut band, &mut display).unwrap();
/// display.assert_pattern(&["###.", "##..", "#...", "...."]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Renderer<C> {
    height: u32,
    offset: Point,
    background: C,
    cull: Cull,
}

impl<C: Interpolate> Renderer<C> {
    /// A renderer for frames `height` rows tall, cleared to `background`,
    /// at the target's origin, culling nothing.
    pub const fn new(height: u32, background: C) -> Self {
        Renderer { height, offset: Point::zero(), background, cull: Cull::None }
    }

    /// The same renderer with another cull mode.
    pub const fn with_cull(self, cull: Cull) -> Self {
        Renderer { cull, ..self }
    }

    /// The same renderer drawing the frame at `offset` on the target.
    pub const fn with_offset(self, offset: Point) -> Self {
        Renderer { offset, ..self }
    }

    /// Frame height in rows.
    pub const fn height(&self) -> u32 {
        self.height
    }

    /// The colour every band is cleared to.
    pub const fn background(&self) -> C {
        self.background
    }

    /// Which screen winding is dropped.
    pub const fn cull(&self) -> Cull {
        self.cull
    }

    /// Where the frame's top-left pixel goes on the target.
    pub const fn offset(&self) -> Point {
        self.offset
    }

    /// Renders the frame `pass` draws through `band` into `target`: for each
    /// band of `H` rows, clear it to the background, let `pass` draw it, send
    /// it with one `fill_contiguous`. `pass` says what the frame is and with
    /// which options ([`render::Pass`](crate::render::Pass)): a slice or array of
    /// 2D [`Primitive`](crate::Primitive)s, `()` for an empty frame,
    /// [`Triangles3d`] and
    /// [`Direct3d`] for 3D,
    /// [`from_fn`] for `embedded-graphics` drawables,
    /// [`Antialiased`](crate::aa::Antialiased) for anti-aliased frames.
    ///
    /// Errors: [`Error::InvalidFrameSize`] if the height is 0 or above
    /// [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM); [`Error::CoordinateOutOfRange`] if the offset puts
    /// the frame beyond `i32` coordinates; [`Error::FrameOutsideTarget`] if the
    /// frame (`W` × height at the offset) does not fit in `target`'s
    /// bounding box; what the pass's [`check`](crate::render::Pass::check)
    /// returns (all before anything is sent); [`RenderError::Input`] with the
    /// first error the pass returns while drawing (the remaining bands are
    /// sent cleared); [`RenderError::Target`] if the
    /// target fails (the remaining bands are not sent).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::{Band, Error, Primitive, Region, Renderer, SubPoint, Triangle};
    /// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
    /// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
    /// let mut band = Band::<BinaryColor, 4, 2>::new(BinaryColor::Off);
    /// let renderer = Renderer::new(4, BinaryColor::Off);
    /// let mut display = MockDisplay::new();
    /// renderer.render(&scene, &mut band, &mut display)?; // a 2D scene
    /// display.assert_pattern(&["###.", "##..", "#...", "...."]);
    /// let mut blank = MockDisplay::new();
    /// renderer.render((), &mut band, &mut blank)?; // nothing: the background
    /// blank.assert_pattern(&["....", "....", "....", "...."]);
    /// // A frame taller than the display is refused before anything is sent.
    /// let tall = Renderer::new(65, BinaryColor::Off).render((), &mut band, &mut MockDisplay::new());
    /// let (frame, target) = (Region::new(0, 0, 4, 65), Region::new(0, 0, 64, 64)); // MockDisplay: 64 x 64
    /// assert_eq!(tall, Err(Error::FrameOutsideTarget { frame, target }.into()));
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn render<P, D, const W: usize, const H: usize>(
        &self,
        pass: P,
        band: &mut Band<C, W, H>,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        P: Pass<C, W, H>,
        D: DrawTarget<Color = C>,
    {
        // Size and offset first (`fits` needs them in range), then the target.
        self.frame_bands::<W, H>()?;
        self.fits::<W>(target.bounding_box())?;
        // The linked loop with one band and a sink that sends before it
        // returns: the plain render-then-send loop.
        link::run(self, pass, core::slice::from_mut(band), &mut link::Blocking(target))
    }

    /// [`Error::FrameOutsideTarget`] unless the frame lies within `display`
    /// (a target's `bounding_box`). Checked before the first band, so a
    /// 320-wide band on a 240-wide display fails instead of drawing a
    /// clipped frame. Call after `frame_bands`, which keeps the frame's
    /// corners within `i32`.
    fn fits<const W: usize>(&self, display: Rectangle) -> Result<(), Error> {
        let frame = Rectangle::new(self.offset, Size::new(W as u32, self.height));
        // The frame is not empty, so both corners inside means contained.
        let inside = |p: Option<Point>| p.is_some_and(|p| display.contains(p));
        if inside(Some(frame.top_left)) && inside(frame.bottom_right()) {
            Ok(())
        } else {
            Err(Error::FrameOutsideTarget { frame: frame.into(), target: display.into() })
        }
    }
}
