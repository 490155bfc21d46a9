//! A plain mesh straight into the band being rendered: the per-band call
//! for a mesh without clusters, as [`Pipeline::draw_meshlets`] is for one
//! with them. No bins: the vertex stage runs in each band, and the
//! triangles that touch the band are drawn as they come.

use super::{MeshStats, NoMemo, Pipeline, Uniform};
use crate::depth::DepthFormat;
use crate::math::{Mat4, Scalar};
use crate::mesh::ValidMesh;
use crate::raster3d::Interpolation;
use crate::render::Band3d;
use crate::{Error, Interpolate};

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// Draws `mesh` placed by `model`, in material colour `color`, into the
    /// band being rendered by [`Direct3d`](crate::render::Direct3d): the
    /// triangles of [`Pipeline::draw_valid_mesh`] that touch the band, in
    /// the same order, drawn as they come instead of binned (which path to use:
    /// below). [`Pipeline::rows`] is ignored: the band's rows apply. The frame does not depend on the band height, and is that of
    /// [`Pipeline::draw_valid_mesh`] into bins drawn by
    /// [`Triangles3d`](crate::render::Triangles3d)
    /// (`tests/integration/per_band_mesh.rs`).
    ///
    /// Which 3D path to use (RAM for a 320 × 240 frame in 16-row bands, the
    /// README's table has the instruction counts):
    /// * a [`View3d`](crate::view3d::View3d) with a HUD
    ///   ([`View3d::draw_with`](crate::view3d::View3d::draw_with)): the least
    ///   code, any of the three mesh types, bands plus about 8.3 KB;
    /// * meshlets per band ([`Pipeline::draw_meshlets`] in a
    ///   [`Direct3d`](crate::render::Direct3d) pass): the fastest on large
    ///   meshes (clusters outside the band or facing away are skipped before
    ///   any vertex work), bands plus a 5.1 KB cluster cache;
    /// * a plain mesh per band (this call): no clusters and no cache, the
    ///   bands alone; every band runs the vertex stage over the whole mesh (through an
    ///   8-vertex cache on the stack), so on large meshes it is several times
    ///   slower than meshlets: for small meshes, or a mesh converted with
    ///   `obj2rs --plain`;
    /// * full-frame bins ([`Pipeline::draw_valid_mesh`] then
    ///   [`Triangles3d`](crate::render::Triangles3d)): each triangle
    ///   transformed once a frame, bins of 64 B per triangle; pays on scenes of
    ///   many small meshes.
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use embedded_graphics::prelude::*;
    /// use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
    /// use microraster::depth::{Depth16, DepthBand, DepthState};
    /// use microraster::math::{Mat4, Vec3, transform};
    /// use microraster::pipeline::Pipeline;
    /// use microraster::raster3d::PerspectiveCorrect;
    /// use microraster::render::{Direct3d, Pass};
    /// use microraster::view3d::CUBE;
    /// use microraster::{Band, Renderer};
    /// let eye = transform::look_at(Vec3::new(2.0, 2.0, 3.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
    /// let pipeline = Pipeline::<f32, 4>::perspective(eye, 1.0, 1.0, 10.0, 32, 32)?;
    /// let mut band = Band::<Rgb565, 32, 8>::new(Rgb565::BLACK);
    /// let mut depth = DepthBand::<Depth16, 32, 8>::new();
    /// let hud = PrimitiveStyle::with_fill(Rgb565::WHITE);
    /// let frame = Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |band| {
    ///     pipeline.draw_valid_mesh_in(&CUBE, &Mat4::IDENTITY, Rgb565::RED, band)?;
    ///     Ok(())
    /// })
    /// .then(|view| Ok(view.draw_visible(&Rectangle::new(Point::zero(), Size::new(4, 4)).into_styled(hud))?.unwrap_or(())));
    /// let mut display = MockDisplay::new();
    /// Renderer::new(32, Rgb565::BLACK).render(frame, &mut band, &mut display)?;
    /// assert_ne!(display.get_pixel(Point::new(16, 16)), Some(Rgb565::BLACK)); // the cube
    /// assert_eq!(display.get_pixel(Point::new(1, 1)), Some(Rgb565::WHITE)); // the HUD
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    ///
    /// Errors: those of [`Pipeline::draw_valid_mesh`]
    /// ([`Error::WindingMismatch`] first) but a full bin, which cannot
    /// happen here.
    pub fn draw_valid_mesh_in<C, F, M, const W: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        band: &mut Band3d<'_, '_, C, F, M, W>,
    ) -> Result<MeshStats, Error>
    where
        C: Interpolate,
        F: DepthFormat,
        M: Interpolation,
    {
        self.check_winding(mesh)?;
        let mut banded = *self;
        let (y0, y1) = band.rows();
        banded.rows = Some((y0, y1));
        banded.mesh_into(mesh, model, color, &Uniform, &mut NoMemo, |t| {
            band.draw_in(&t, banded.precision);
            Ok(())
        })
    }
}
