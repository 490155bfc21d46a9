//! A [`View3d`]'s settings: frame height, lighting, culling, shading,
//! accuracy tier and background, each one call to change.

use super::View3d;
use crate::Interpolate;
use crate::edge::Cull;
use crate::light::Lighting;
use crate::pipeline::Shade;
use crate::raster3d::Precision;

impl<C: Interpolate, const W: usize, const H: usize> View3d<C, W, H> {
    /// Frames of `rows` rows from the display's top (`None`, the default:
    /// as tall as the display).
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, prelude::Point};
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_height(Some(20));
    /// let (camera, cube) = (Camera::look_at([3.0, 3.0, 3.0], [0.0; 3]), Object::new(&CUBE, Rgb565::RED));
    /// let mut display = MockDisplay::new();
    /// view.draw(&camera, &[cube], &mut display)?;
    /// // Rows 0–19 are sent; the rest of the 64-row display is not touched.
    /// assert!(display.get_pixel(Point::new(0, 19)).is_some());
    /// assert!(display.get_pixel(Point::new(0, 20)).is_none());
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn set_height(&mut self, rows: Option<u32>) {
        self.height = rows;
    }

    /// The lighting (`None`: material colours unlit). A bad light (a
    /// non-finite factor, a direction that is not a unit vector) fails the
    /// frame before any band is sent, as [`Lighting::validate`] fails. For
    /// a highlight: `view.set_lighting(Some(DEFAULT_LIGHTING.with_specular(0.5, 16)))`.
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, prelude::Point};
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_lighting(None);
    /// let (camera, cube) = (Camera::look_at([3.0, 3.0, 3.0], [0.0; 3]), Object::new(&CUBE, Rgb565::RED));
    /// let mut display = MockDisplay::new();
    /// view.draw(&camera, &[cube], &mut display)?;
    /// // Unlit: every face is the material colour itself.
    /// assert_eq!(display.get_pixel(Point::new(32, 32)), Some(Rgb565::RED));
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn set_lighting(&mut self, lighting: Option<Lighting<f32>>) {
        self.lighting = lighting;
    }

    /// Which screen winding is dropped ([`Cull::Clockwise`], back faces, by
    /// default; [`Cull::None`] for open meshes seen from both sides).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::{Cull, view3d::View3d};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_cull(Cull::None);
    /// assert_eq!(view.cull(), Cull::None);
    /// ```
    pub fn set_cull(&mut self, cull: Cull) {
        self.cull = cull;
    }

    /// Gouraud (the default) or flat shading.
    pub fn set_shade(&mut self, shade: Shade) {
        self.shade = shade;
    }

    /// The accuracy tier the next frames are drawn in: [`Precision::Exact`]
    /// (the default, the explicit API's reference pixels) or
    /// [`Precision::Fast`] (cheaper arithmetic within the error bounds
    /// [`Precision`] states; coverage exact for its own snapped vertices).
    /// The frame is the explicit API's with
    /// [`Pipeline::with_precision`](crate::pipeline::Pipeline::with_precision) ([`View3d::pipeline`] hands it out).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::raster3d::Precision;
    /// use microraster::view3d::{Camera, View3d};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_precision(Precision::Fast);
    /// let (pipeline, _) = view.pipeline(&Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]), 64)?;
    /// assert_eq!((view.precision(), pipeline.precision), (Precision::Fast, Precision::Fast));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn set_precision(&mut self, precision: Precision) {
        self.precision = precision;
    }

    /// The accuracy tier.
    pub fn precision(&self) -> Precision {
        self.precision
    }

    /// The colour the next frames are cleared to.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::View3d;
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_background(Rgb565::BLUE); // night mode
    /// assert_eq!(view.background(), Rgb565::BLUE);
    /// ```
    pub fn set_background(&mut self, background: C) {
        self.background = background;
    }

    /// The colour frames are cleared to.
    pub fn background(&self) -> C {
        self.background
    }

    /// The lighting.
    pub fn lighting(&self) -> Option<Lighting<f32>> {
        self.lighting
    }

    /// The cull mode.
    pub fn cull(&self) -> Cull {
        self.cull
    }
}

impl<C: core::fmt::Debug, const W: usize, const H: usize> core::fmt::Debug for View3d<C, W, H> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("View3d")
            .field("size", &(W, H))
            .field("background", &self.background)
            .field("height", &self.height)
            .field("lighting", &self.lighting)
            .field("cull", &self.cull)
            .field("shade", &self.shade)
            .field("precision", &self.precision)
            .finish_non_exhaustive()
    }
}
