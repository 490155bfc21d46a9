//! Frames drawn with `embedded-graphics` drawables: a 2D frame of any e-g
//! drawables (and microraster primitives) in one call, and a 3D frame with
//! a 2D overlay (a HUD) drawn over each band after its meshes.
//!
//! Both hand the closure the band being drawn as a [`BandView`]: an e-g
//! `DrawTarget` in frame coordinates, clipped to the band, and a
//! [`Blitter`](crate::blit::Blitter) for microraster's own primitives. The
//! closure runs once per band and draws the whole frame's 2D each time; each
//! band keeps the rows that fall on it, so the image does not depend on the
//! band height. The cost is the drawables' set-up once per band (e-g clips
//! by pixel, so a drawable's pixels outside the band are generated and
//! dropped; skip drawables whose bounding box misses
//! [`BandView::bounding_box`](embedded_graphics::geometry::Dimensions::bounding_box)
//! to avoid that).

use super::Renderer;
use crate::band::{Band, BandView};
use crate::depth::{DepthBand, DepthFormat, DepthState};
use crate::raster3d::{Interpolation, ScreenTriangle};
use crate::{Error, Interpolate, RenderError};
use embedded_graphics_core::prelude::DrawTarget;

impl<C: Interpolate> Renderer<C> {
    /// Renders a frame that `draw` draws into each band, cleared to the
    /// background first: `draw` gets the band as a [`BandView`] and draws the
    /// frame's content in frame coordinates (any `embedded-graphics`
    /// drawable; microraster primitives through
    /// [`Blitter`](crate::blit::Blitter)).
    ///
    /// Errors as for [`Renderer::render`], plus [`RenderError::Input`] with
    /// the first error `draw` returns (the remaining bands are sent cleared).
    /// e-g's draw errors convert with `?` (a band's is `Infallible`).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::prelude::*;
    /// use embedded_graphics::primitives::{Circle, PrimitiveStyle};
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use microraster::{edge::Cull, Band, Renderer, SubPoint, Triangle};
    /// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
    /// let mut band = Band::<BinaryColor, 8, 3>::new(BinaryColor::Off); // 3-row bands
    /// let mut display = MockDisplay::new();
    /// Renderer::new(8, BinaryColor::Off).render_drawables(&mut band, &mut display, |view| {
    ///     Triangle::flat([p(0, 0), p(5, 0), p(0, 5)], BinaryColor::On).draw(view, Cull::None);
    ///     Circle::new(Point::new(4, 4), 4).into_styled(PrimitiveStyle::with_fill(BinaryColor::On)).draw(view)?;
    ///     Ok(())
    /// })?;
    /// display.assert_pattern(&[
    ///     "####....", "###.....", "##......", "#.......",
    ///     ".....##.", "....####", "....####", ".....##.",
    /// ]);
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn render_drawables<D, G, const W: usize, const H: usize>(
        &self,
        band: &mut Band<C, W, H>,
        target: &mut D,
        mut draw: G,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        G: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
    {
        let mut failed = None;
        self.render_with(band, target, |view, _, _| {
            if failed.is_none() {
                failed = draw(view).err();
            }
        })?;
        failed.map_or(Ok(()), |e| Err(RenderError::Input(e)))
    }

    /// [`Renderer::render_3d`] with an overlay: in each band, after the
    /// triangles (depth cleared to far by the renderer, tested and written as
    /// `state` says), `overlay` draws over them — a HUD, in frame coordinates,
    /// with any `embedded-graphics` drawable. The overlay ignores depth. The
    /// image is the 3D frame with the overlay drawn over it, for every band
    /// height. Colour is interpolated as `interp` says
    /// ([`Affine`](crate::raster3d::Affine) or
    /// [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect)).
    ///
    /// With [`Renderer::render_3d_direct`] draw the overlay at the end of its
    /// closure instead (the [`Band3d`](super::Band3d) is a `DrawTarget` too).
    ///
    /// Errors as for [`Renderer::render`], plus [`RenderError::Input`] with
    /// the first error `overlay` returns (later bands get no overlay).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::prelude::*;
    /// use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use microraster::depth::{Depth16, DepthBand, DepthState};
    /// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
    /// use microraster::{Band, Renderer, SubPoint};
    /// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), color: [31, 0, 0], ..Default::default() };
    /// let red = [ScreenTriangle { v: [v(0, 0), v(8, 0), v(0, 8)], flat: true }];
    /// let mut band = Band::<Rgb565, 8, 2>::new(Rgb565::BLACK);
    /// let mut depth = DepthBand::<Depth16, 8, 2>::new();
    /// let mut display = MockDisplay::new();
    /// let hud = PrimitiveStyle::with_fill(Rgb565::WHITE);
    /// Renderer::new(8, Rgb565::BLACK).render_3d_overlay(
    ///     &red, &mut band, &mut depth, DepthState::LESS_WRITE, Affine, &mut display,
    ///     |view| Ok(Rectangle::new(Point::new(0, 0), Size::new(2, 2)).into_styled(hud).draw(view)?),
    /// )?;
    /// assert_eq!(display.get_pixel(Point::new(1, 1)), Some(Rgb565::WHITE)); // the HUD, over
    /// assert_eq!(display.get_pixel(Point::new(3, 1)), Some(Rgb565::RED)); // the triangle
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn render_3d_overlay<D, F, M, O, const S: u32, const W: usize, const H: usize>(
        &self,
        triangles: &[ScreenTriangle<S>],
        band: &mut Band<C, W, H>,
        depth: &mut DepthBand<F, W, H>,
        state: DepthState,
        interp: M,
        target: &mut D,
        mut overlay: O,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        F: DepthFormat,
        M: Interpolation,
        O: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
    {
        let _ = interp; // a value, so the call needs no turbofish
        let mut failed = None;
        self.render_with(band, target, |view, y0, y1| {
            super::band3d::<C, F, M, W, H>(view, depth, state, y0, y1).draw_all(triangles);
            if failed.is_none() {
                failed = overlay(view).err();
            }
        })?;
        failed.map_or(Ok(()), |e| Err(RenderError::Input(e)))
    }
}
