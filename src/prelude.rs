//! The names most programs need, in one `use microraster::prelude::*;`
//! (the two common programs, a lit mesh with a HUD and a 2D dashboard,
//! need nothing else from this crate):
//!
//! - the 3D front: [`View3d`] (and [`View240x240`], [`View320x240`] for
//!   the common ST7789 and ILI9341 displays), [`Camera`], [`Object`], the
//!   built-in [`CUBE`], the default light [`DEFAULT_LIGHTING`];
//! - the band renderer, what a frame draws ([`Pass`]: a slice of 2D
//!   primitives, [`Triangles3d`], [`Direct3d`], [`from_fn`] for any e-g
//!   drawable) and the 2D scene: [`Band`], [`Renderer`], [`Primitive`],
//!   [`Triangle`], [`Line`], [`SubPoint`], [`Cull`];
//! - errors: [`Error`], [`RenderError`];
//! - the explicit 3D API's usual choices: [`Pipeline`], [`DepthBand`],
//!   [`DepthState`], [`Depth16`], and the interpolations [`Affine`] and
//!   [`PerspectiveCorrect`] (values handed to [`Triangles3d::new`]);
//! - with the `shapes` feature, 2D shapes ([`Shape`], [`ShapeStyle`],
//!   [`Rect`], [`RoundedRect`], [`Circle`], [`Arc`], [`Polygon`],
//!   [`Polyline`]) and their paints ([`LinearGradient`],
//!   [`RadialGradient`]);
//! - with the `textures` feature, sprites ([`Sprite`], [`Texture`], the
//!   alpha format [`A8`] and the [`Bilinear`] filter).
//!
//! Everything else stays in its module. `embedded_graphics::prelude` also
//! exports a trait named `Primitive`: glob-importing both preludes is
//! fine (e-g's trait methods still work), but write `microraster::Primitive`
//! to name the scene type.
//!
//! ```
//! use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
//! use microraster::prelude::*;
//! # let mut display = embedded_graphics::mock_display::MockDisplay::new();
//! # display.set_allow_overdraw(true);
//! let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
//! let camera = Camera::look_at([0.0, 2.0, 5.0], [0.0, 0.0, 0.0]);
//! view.draw(&camera, &[Object::new(&CUBE, Rgb565::GREEN).rotate_y(0.5)], &mut display)?;
//! # Ok::<(), RenderError<core::convert::Infallible>>(())
//! ```

pub use crate::depth::{Depth16, DepthBand, DepthState};
pub use crate::pipeline::Pipeline;
pub use crate::raster3d::{Affine, PerspectiveCorrect};
pub use crate::render::{Direct3d, Pass, Triangles3d, from_fn};
#[cfg(feature = "shapes")]
pub use crate::shape::{
    Arc, Circle, LinearGradient, Polygon, Polyline, RadialGradient, Rect, RoundedRect, Shape, ShapeStyle,
};
#[cfg(feature = "textures")]
pub use crate::texture::{A8, Bilinear, Sprite, Texture};
pub use crate::view3d::{CUBE, Camera, DEFAULT_LIGHTING, Object, View3d, View240x240, View320x240};
pub use crate::{Band, Cull, Error, Line, Primitive, RenderError, Renderer, SubPoint, Triangle};
