//! The one-call 3D front: a [`Camera`], [`Object`]s (a mesh, a place, a
//! colour, or a colour per vertex or per face) and a [`View3d`] that owns the band buffers and draws a frame
//! into any `embedded-graphics` display with [`View3d::draw`].
//!
//! Defaults, each one call to change: lighting on (ambient plus one light
//! from the upper left behind the viewer, [`DEFAULT_LIGHTING`]), back faces
//! culled (with every mesh's winding checked against its normals, so a mesh
//! wound the wrong way is an error, not a dark inside), Gouraud shading,
//! 16-bit depth, perspective-correct colour, 4 subpixel bits, the `f32`
//! vertex path, the exact accuracy tier ([`Precision::Exact`];
//! [`View3d::set_precision`] for [`Precision::Fast`]). Everything here is built on the explicit API
//! ([`Pipeline`], [`Direct3d`]) and draws the same pixels
//! (`tests/integration/view3d.rs`); use that API for other depth formats,
//! the `Fx` path, fragment shaders or anti-aliasing. A HUD (text, gauges,
//! translucent panels) goes into each band after the meshes with
//! [`View3d::draw_with`].
//!
//! ```
//! use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
//! use microraster::view3d::{CUBE, Camera, Object, View240x240};
//! # use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
//! # use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
//! # let mut display = Framebuffer::<Rgb565, RawU16, LittleEndian, 240, 240, { buffer_size::<Rgb565>(240, 240) }>::new();
//!
//! let mut view = View240x240::new(Rgb565::BLACK); // 240 wide, 16-row bands
//! let camera = Camera::look_at([0.0, 2.0, 5.0], [0.0, 0.0, 0.0]);
//! for frame in 0..3 {
//!     let cube = Object::new(&CUBE, Rgb565::CYAN).rotate_y(frame as f32 * 0.1);
//!     view.draw(&camera, &[cube], &mut display)?;
//! }
//! # use embedded_graphics::{image::GetPixel, prelude::Point};
//! # assert_ne!(display.pixel(Point::new(120, 120)), Some(Rgb565::BLACK));
//! # assert_eq!(display.pixel(Point::new(2, 2)), Some(Rgb565::BLACK));
//! # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
//! ```

mod camera;
mod cube;
mod object;
mod settings;

pub use camera::{Camera, DEFAULT_PROJECTION, Projection};
pub use cube::CUBE;
use object::draw_object;
pub use object::{Colors, Geometry, Object};

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::pixelcolor::Rgb565;

use crate::band::Band;
use crate::band::BandView;
use crate::depth::{Depth16, DepthBand, DepthState};
use crate::edge::Cull;
use crate::light::{Lighting, Viewer};
use crate::math::Vec3;
use crate::pipeline::{ClusterCache, FrameChunks, PerFace, PerVertex, Pipeline, Shade, Uniform};
use crate::raster3d::{PerspectiveCorrect, Precision};
use crate::render::{Direct3d, Pass};
use crate::{Error, Interpolate, MAX_FRAME_DIM, RenderError, Renderer};

/// The front's lighting unless told otherwise: ambient 0.25 and a light of
/// strength 0.75 towards (−0.36, 0.48, 0.8) in eye space (above left,
/// behind the viewer), so the faces of a box turned towards the camera all
/// differ in brightness.
pub const DEFAULT_LIGHTING: Lighting<f32> = Lighting {
    ambient: 0.25,
    direction: Vec3::new(-0.36, 0.48, 0.8),
    diffuse: 0.75,
    specular: None,
    viewer: Viewer::Local,
};

/// A [`View3d`] for 240 × 240 Rgb565 displays (ST7789, GC9A01): 16-row
/// bands, 7,680 B of colour and 7,680 B of depth.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::view3d::View240x240;
/// let view = View240x240::new(Rgb565::BLACK);
/// assert!(core::mem::size_of_val(&view) < 240 * 16 * 4 + 8_400);
/// ```
pub type View240x240 = View3d<Rgb565, 240, 16>;

/// A [`View3d`] for 320 × 240 Rgb565 displays (ILI9341 landscape): 16-row
/// bands.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::view3d::View320x240;
/// let view = View320x240::new(Rgb565::WHITE);
/// assert_eq!(view.background(), Rgb565::WHITE);
/// ```
pub type View320x240 = View3d<Rgb565, 320, 16>;

/// A [`View3d`] for 160 × 128 Rgb565 displays (ST7735): 8-row bands.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::{Cull, view3d::View160x128};
/// let mut view = View160x128::new(Rgb565::BLACK);
/// view.set_cull(Cull::None); // an open mesh, seen from both sides
/// assert_eq!(view.cull(), Cull::None);
/// ```
pub type View160x128 = View3d<Rgb565, 160, 8>;

/// The buffers and settings of 3D frames `W` pixels wide drawn in bands of
/// `H` rows: the colour [`Band`], its 16-bit [`DepthBand`], the
/// [`ClusterCache`] of meshlet meshes and a record of plain meshes' chunks. The frame is as tall as the display
/// ([`View3d::set_height`] to use fewer rows); rows, not columns, are
/// banded, so `W` must not exceed the display's width.
///
/// Size: `W × H × 4` bytes plus about 8.3 KB: the cluster cache (5.1 KB:
/// one cluster's vertices and the frame's cluster record, which up to four
/// meshlet objects share) and the frame's chunk record (3.1 KB: for each
/// chunk of up to 8 vertices of the first 8 plain-mesh objects, up to 256
/// chunks in all, its triangle count and rows, so the bands it misses skip
/// it).
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::view3d::{CUBE, Camera, Object, View3d};
/// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
/// let mut display = MockDisplay::new();
/// display.set_allow_overdraw(true);
/// let camera = Camera::look_at([3.0, 3.0, 3.0], [0.0, 0.0, 0.0]);
/// view.draw(&camera, &[Object::new(&CUBE, Rgb565::RED)], &mut display)?;
/// assert_ne!(display.get_pixel(embedded_graphics::prelude::Point::new(32, 32)), Some(Rgb565::BLACK));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub struct View3d<C, const W: usize, const H: usize> {
    band: Band<C, W, H>,
    depth: DepthBand<Depth16, W, H>,
    cache: ClusterCache<f32, 4>,
    chunks: FrameChunks,
    background: C,
    height: Option<u32>,
    lighting: Option<Lighting<f32>>,
    cull: Cull,
    shade: Shade,
    precision: Precision,
}

impl<C: Interpolate, const W: usize, const H: usize> View3d<C, W, H> {
    /// Buffers for frames cleared to `background`, with the defaults of the
    /// [module docs](self).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::Cull;
    /// use microraster::view3d::{DEFAULT_LIGHTING, View3d};
    /// // `const`: it can be a `static` in firmware (W × H × 4 bytes plus about 8.3 KB).
    /// static VIEW: View3d<Rgb565, 320, 16> = View3d::new(Rgb565::BLACK);
    /// let view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLUE);
    /// assert_eq!(view.background(), Rgb565::BLUE);
    /// assert_eq!((view.lighting(), view.cull()), (Some(DEFAULT_LIGHTING), Cull::Clockwise));
    /// # let _ = &VIEW;
    /// ```
    pub const fn new(background: C) -> Self {
        View3d {
            band: Band::new(background),
            depth: DepthBand::new(),
            cache: ClusterCache::new(),
            chunks: FrameChunks::new(),
            background,
            height: None,
            lighting: Some(DEFAULT_LIGHTING),
            cull: Cull::Clockwise,
            shade: Shade::Gouraud,
            precision: Precision::Exact,
        }
    }

    /// The same view drawing in accuracy tier `precision` (a `const fn`,
    /// for a `static` view; [`View3d::set_precision`] changes a view in
    /// place). [`Precision::Exact`] by default.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::raster3d::Precision;
    /// use microraster::view3d::View3d;
    /// static VIEW: View3d<Rgb565, 320, 16> = View3d::new(Rgb565::BLACK).with_precision(Precision::Fast);
    /// assert_eq!(VIEW.precision(), Precision::Fast);
    /// ```
    pub const fn with_precision(self, precision: Precision) -> Self {
        let mut view = self;
        view.precision = precision;
        view
    }

    /// The vertex stage and renderer this view draws a `W × rows` frame
    /// with: the explicit-API equivalent of a [`View3d::draw`] call, for
    /// drawing more into the same frame through
    /// [`Direct3d`], or for comparing.
    ///
    /// Errors: [`Error::InvalidFrameSize`] for 0 or more than
    /// [`MAX_FRAME_DIM`] rows, then the lighting's ([`Lighting::validate`]),
    /// then those of the camera ([`Camera::view`] and its lens, as
    /// [`Pipeline::perspective`] and
    /// [`transform::orthographic`](crate::math::transform::orthographic)).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::{Camera, View240x240};
    /// let view = View240x240::new(Rgb565::BLACK);
    /// let (pipeline, renderer) = view.pipeline(&Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]), 240)?;
    /// assert_eq!((renderer.height(), pipeline.lighting.is_some()), (240, true));
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn pipeline(&self, camera: &Camera, rows: u32) -> Result<(Pipeline<f32, 4>, Renderer<C>), Error> {
        // Size first: a zero-size display is a frame-size error, not a lens one.
        if rows == 0 || rows > MAX_FRAME_DIM || W as u32 > MAX_FRAME_DIM {
            return Err(Error::InvalidFrameSize);
        }
        // Checked here as well as by the vertex stage, so that a bad light
        // fails every frame, one without objects too, before any band.
        // Before the camera: after it, the check cost `draw` 384 B of
        // stack (a second copy of the pipeline; `fw_bench` row 30).
        if let Some(light) = &self.lighting {
            light.validate()?;
        }
        let mut p = camera.pipeline(W as u32, rows, self.lighting)?;
        (p.cull, p.shade, p.precision) = (self.cull, self.shade, self.precision);
        Ok((p, Renderer::new(rows, self.background)))
    }

    /// Draws one frame of `objects` seen by `camera` into `display`, band
    /// by band: each band is cleared, every object's triangles that touch
    /// it are drawn straight into it (no bins: the vertex stage runs per
    /// band, [`Pipeline::rows`] set to the band's rows, a plain mesh's
    /// vertices through the 8-entry stack cache of
    /// [`Pipeline::draw_valid_mesh`] unless it has a colour per face, its
    /// chunks recorded in the first band that reaches them and skipped by
    /// the bands they miss;
    /// meshlet meshes go through [`Pipeline::draw_meshlets`]), and the band is sent with one
    /// `fill_contiguous`. The image does not depend on `H`. Text or panels
    /// over the frame: [`View3d::draw_with`], in the same pass.
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, prelude::Point};
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// let camera = Camera::look_at([3.0, 2.0, 4.0], [0.0; 3]);
    /// // A spinning cube: three frames, each turned a little further.
    /// for frame in 0..3 {
    ///     let cube = Object::new(&CUBE, Rgb565::RED).rotate_y(0.2 * frame as f32);
    ///     let mut display = MockDisplay::new();
    ///     view.draw(&camera, &[cube], &mut display)?;
    ///     assert_ne!(display.get_pixel(Point::new(32, 32)), Some(Rgb565::BLACK));
    ///     assert_eq!(display.get_pixel(Point::new(0, 0)), Some(Rgb565::BLACK));
    /// }
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    ///
    /// Errors (nothing is sent unless stated): [`Error::InvalidFrameSize`]
    /// for a display (or [`View3d::set_height`]) of 0 rows or more than
    /// [`MAX_FRAME_DIM`]; the light's, then the camera's
    /// ([`View3d::pipeline`]); then object by object, a mesh's
    /// ([`Mesh::check_winding`](crate::mesh::Mesh::check_winding), including
    /// [`Error::WindingMismatch`]), [`Error::InvalidParameter`] for
    /// per-vertex or per-face colours that do not match its mesh
    /// ([`Object::with_vertex_colors`], [`Object::with_face_colors`]), and
    /// the vertex stage's errors that do not depend on the band
    /// ([`Pipeline::draw_valid_mesh`]: [`Error::InvalidParameter`] for a
    /// singular model, [`Error::CoordinateOutOfRange`] for a mesh in view
    /// with a clip coordinate beyond ±2^64); [`Error::FrameOutsideTarget`]
    /// if `W` columns or the frame's rows do not fit the display; all
    /// these before the first band. Should the vertex stage still fail in
    /// a band ([`Error::InvalidMeshlet`], say), the frame goes on as
    /// [`Renderer::render`] documents: the bands before it are sent as
    /// drawn, that band as far as it was drawn, the remaining bands
    /// cleared to the background, and the result is that error. Last,
    /// [`RenderError::Target`] from the display.
    pub fn draw<D>(
        &mut self,
        camera: &Camera,
        objects: &[Object<'_, C>],
        display: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
    {
        self.draw_with(camera, objects, display, |_| Ok(()))
    }

    /// [`View3d::draw`] with a HUD: in every band, after the meshes, `hud`
    /// draws into the band's colour rows ([`BandView`], in frame
    /// coordinates), so text, gauges and translucent panels go out with the
    /// frame, each pixel sent once (drawing on the display after
    /// [`View3d::draw`] sends those pixels twice a frame, which flickers on
    /// a panel without a framebuffer, and cannot blend over the meshes). The
    /// HUD ignores depth. e-g drawables draw with
    /// [`BandView::draw_visible`] (skipped in the bands they miss) or their
    /// own `draw`; microraster's [`Styled`](crate::shape::Styled) shapes
    /// with `draw_on`, blending over the meshes. The frame equals the
    /// meshes drawn into a framebuffer and the HUD drawn over them, for
    /// every `H` (`tests/integration/view3d_hud.rs`).
    ///
    /// ```
    /// use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use embedded_graphics::{mock_display::MockDisplay, prelude::*, text::Text};
    /// use microraster::shape::{Rect, Shape, ShapeStyle};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// let camera = Camera::look_at([3.0, 2.0, 4.0], [0.0; 3]);
    /// let mut display = MockDisplay::new();
    /// let label = Text::new("HI", Point::new(2, 8), MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE));
    /// let panel = Rect::new(0.0, 48.0, 64.0, 16.0)?.styled(ShapeStyle::fill(Rgb565::BLUE).with_opacity(128))?;
    /// view.draw_with(&camera, &[Object::new(&CUBE, Rgb565::RED)], &mut display, |hud| {
    ///     hud.draw_visible(&label)?;
    ///     panel.draw_on(hud); // half-transparent: blends over the cube
    ///     Ok(())
    /// })?;
    /// assert_eq!(display.get_pixel(Point::new(4, 5)), Some(Rgb565::WHITE)); // the bar of "H"
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    ///
    /// Errors: those of [`View3d::draw`], then the first error `hud`
    /// returns (the frame goes on as for a band that fails in the vertex
    /// stage).
    pub fn draw_with<D, F>(
        &mut self,
        camera: &Camera,
        objects: &[Object<'_, C>],
        display: &mut D,
        hud: F,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        F: FnMut(&mut BandView<'_, C, W>) -> Result<(), Error>,
    {
        let rows = self.height.unwrap_or(display.bounding_box().size.height);
        let (pipe, renderer) = self.pipeline(camera, rows)?;
        // Whole-mesh checks once per frame, before any band is sent, with
        // what the vertex stage would find in every band (singular model).
        for o in objects {
            let mesh = match o.geometry() {
                Geometry::Mesh(m) => {
                    m.check_winding()?;
                    m
                }
                // Validated already, and its winding found then.
                Geometry::Valid(m) if m.winding_agrees() => *m.mesh(),
                Geometry::Valid(m) => m.mesh().const_data().check_winding_unvalidated().map(|_| *m.mesh())?,
                Geometry::Meshlets(m) => m.get().mesh,
            };
            o.check_colors()?;
            pipe.check_mesh(&mesh, &o.model())?;
        }
        let (cache, chunks) = (&mut self.cache, &mut self.chunks);
        chunks.clear();
        let frame = Direct3d::new(&mut self.depth, DepthState::LESS_WRITE, PerspectiveCorrect, |band| {
            let mut banded = pipe;
            banded.rows = Some(band.rows());
            for (i, o) in objects.iter().enumerate() {
                let memo = &mut chunks.object(i);
                // The colour source is a type, chosen once per object.
                match o.colors() {
                    Colors::Material => draw_object(&banded, o, &Uniform, cache, memo, band)?,
                    Colors::PerVertex(c) => draw_object(&banded, o, &PerVertex(c), cache, memo, band)?,
                    Colors::PerFace(c) => draw_object(&banded, o, &PerFace(c), cache, memo, band)?,
                }
            }
            Ok(())
        });
        renderer.render(frame.then(hud), &mut self.band, display)
    }
}
