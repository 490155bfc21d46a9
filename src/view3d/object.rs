//! What the front draws: a mesh, where it is (a model transform built from
//! translate, rotate and scale steps) and its material colour, one for the
//! object or one per vertex or per face.

use crate::depth::Depth16;
use crate::math::{Mat4, Vec3, transform};
use crate::mesh::{Mesh, ValidMesh, ValidMeshletMesh};
use crate::pipeline::{ChunkMemo, ClusterCache, Material, Pipeline};
use crate::raster3d::PerspectiveCorrect;
use crate::render::Band3d;
use crate::{Error, Interpolate, Param};

/// The mesh of an [`Object`]. Build it with `into()` from a reference to
/// any of the three mesh types; [`Object::new`] does that for you.
#[derive(Debug, Clone, Copy)]
pub enum Geometry<'a> {
    /// A mesh checked ([`Mesh::check_winding`], which validates it too) at
    /// the start of every frame; the frame fails with its error.
    Mesh(Mesh<'a>),
    /// A mesh validated beforehand. [`ValidMesh::new`] found whether its
    /// winding agrees with its normals ([`ValidMesh::winding_agrees`]); if
    /// not, every frame fails with [`Error::WindingMismatch`].
    Valid(ValidMesh<'a>),
    /// A large mesh in clusters: drawn per band through
    /// [`Pipeline::draw_meshlets`](crate::pipeline::Pipeline::draw_meshlets),
    /// which skips clusters outside the band or facing away before any
    /// vertex work.
    Meshlets(&'a ValidMeshletMesh<'a>),
}

impl<'a> From<&Mesh<'a>> for Geometry<'a> {
    fn from(m: &Mesh<'a>) -> Self {
        Geometry::Mesh(*m)
    }
}

impl<'a> From<&ValidMesh<'a>> for Geometry<'a> {
    fn from(m: &ValidMesh<'a>) -> Self {
        Geometry::Valid(*m)
    }
}

impl<'a> From<&'a ValidMeshletMesh<'a>> for Geometry<'a> {
    fn from(m: &'a ValidMeshletMesh<'a>) -> Self {
        Geometry::Meshlets(m)
    }
}

/// Where an [`Object`]'s material colours come from. Every colour is lit
/// as the object's one colour would be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Colors<'a, C> {
    /// The object's colour ([`Object::color`]) everywhere.
    Material,
    /// One colour per mesh vertex ([`Object::with_vertex_colors`]),
    /// interpolated across each triangle.
    PerVertex(&'a [C]),
    /// One colour per triangle ([`Object::with_face_colors`]).
    PerFace(&'a [C]),
}

/// A mesh placed in the world, in one colour (or a colour per vertex or per
/// face, [`Colors`]). The transform steps apply in
/// the order they are written: `.scale(0.5).rotate_y(a).translate(p)`
/// shrinks the mesh about its origin, turns it, then moves it to `p`.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::math::Vec3;
/// use microraster::view3d::{CUBE, Object};
/// let box1 = Object::new(&CUBE, Rgb565::GREEN).scale(0.5).rotate_y(1.2).translate([1.0, 0.0, -2.0]);
/// // The cube's centre goes where it was moved.
/// let c = box1.model().transform_point(Vec3::new(0.0, 0.0, 0.0)).to_f32();
/// assert!((c[0] - 1.0).abs() < 1e-6 && c[1].abs() < 1e-6 && (c[2] + 2.0).abs() < 1e-6);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Object<'a, C> {
    geometry: Geometry<'a>,
    model: Mat4<f32>,
    color: C,
    colors: Colors<'a, C>,
}

impl<'a, C: Copy> Object<'a, C> {
    /// `geometry` (`&Mesh`, `&ValidMesh` or `&ValidMeshletMesh`) at the
    /// world's origin, untransformed, in material colour `color`.
    pub fn new(geometry: impl Into<Geometry<'a>>, color: C) -> Self {
        Object { geometry: geometry.into(), model: Mat4::IDENTITY, color, colors: Colors::Material }
    }

    /// Then moves it by `offset`.
    pub fn translate(self, offset: [f32; 3]) -> Self {
        self.then(transform::translation(Vec3::from_f32(offset)))
    }

    /// Then turns it `angle` radians about the world's x axis.
    pub fn rotate_x(self, angle: f32) -> Self {
        self.then(transform::rotation_x(angle))
    }

    /// Then turns it `angle` radians about the world's y axis (z towards x).
    pub fn rotate_y(self, angle: f32) -> Self {
        self.then(transform::rotation_y(angle))
    }

    /// Then turns it `angle` radians about the world's z axis.
    pub fn rotate_z(self, angle: f32) -> Self {
        self.then(transform::rotation_z(angle))
    }

    /// Then scales it by `factor` about the world's origin. A zero factor
    /// makes the model singular: the frame fails with
    /// [`Error::InvalidParameter`]`(`[`Param::Model`]`)` before any band is
    /// sent. A NaN or infinite step (here or in a rotation or translation)
    /// fails it with [`Error::NonFiniteCoordinate`].
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::{Rgb565, RgbColor}};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// use microraster::{Error, Param};
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// let camera = Camera::look_at([3.0, 2.0, 4.0], [0.0; 3]);
    /// let mut draw = |o: Object<'_, Rgb565>| view.draw(&camera, &[o], &mut MockDisplay::new());
    /// assert_eq!(draw(Object::new(&CUBE, Rgb565::RED).scale(0.0)), Err(Error::InvalidParameter(Param::Model).into()));
    /// assert_eq!(draw(Object::new(&CUBE, Rgb565::RED).rotate_y(f32::NAN)), Err(Error::NonFiniteCoordinate.into()));
    /// ```
    pub fn scale(self, factor: f32) -> Self {
        self.scale_xyz([factor; 3])
    }

    /// Then scales it by a factor per axis.
    pub fn scale_xyz(self, factors: [f32; 3]) -> Self {
        self.then(transform::scaling(Vec3::from_f32(factors)))
    }

    /// Then applies `m` (any affine matrix, for steps the helpers lack).
    pub fn then(self, m: Mat4<f32>) -> Self {
        Object { model: m * self.model, ..self }
    }

    /// The same object in another colour (where per-vertex or per-face
    /// colours are set, they still apply).
    pub fn with_color(self, color: C) -> Self {
        Object { color, ..self }
    }

    /// The same object with a colour per mesh vertex, `colors[i]` for vertex
    /// `i`, in place of its one colour: interpolated across each triangle
    /// with Gouraud shading (the default; with flat shading a triangle takes
    /// its first vertex's colour), and lit as the one colour would be. For a
    /// meshlet mesh, the vertices of the mesh the clusters were built from.
    ///
    /// Errors, at [`View3d::draw`](super::View3d::draw), before any band is
    /// sent: [`Error::InvalidParameter`] if `colors.len()` is not the mesh's
    /// vertex count.
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// // The cube's 24 vertices, red on top (y = 1), blue below.
    /// let mut colors = [Rgb565::BLUE; 24];
    /// for (c, p) in colors.iter_mut().zip(CUBE.mesh().positions) {
    ///     if p[1] > 0.0 { *c = Rgb565::RED; }
    /// }
    /// let cube = Object::new(&CUBE, Rgb565::WHITE).with_vertex_colors(&colors);
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_lighting(None);
    /// let mut display = MockDisplay::new();
    /// display.set_allow_overdraw(true);
    /// view.draw(&Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]), &[cube], &mut display)?;
    /// // The front face shades from red at its top to blue at its bottom.
    /// let at = |y| display.get_pixel(embedded_graphics::prelude::Point::new(32, y)).unwrap();
    /// assert!(at(22).r() > at(22).b() && at(42).b() > at(42).r());
    /// // The wrong number of colours is an error.
    /// let short = Object::new(&CUBE, Rgb565::WHITE).with_vertex_colors(&colors[..8]);
    /// let err = view.draw(&Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]), &[short], &mut display);
    /// assert_eq!(err, Err(microraster::Error::InvalidParameter(microraster::Param::VertexColors).into()));
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn with_vertex_colors(self, colors: &'a [C]) -> Self {
        Object { colors: Colors::PerVertex(colors), ..self }
    }

    /// The same object with a colour per triangle, `colors[i]` for the
    /// mesh's triangle `i`, in place of its one colour: the same colour at
    /// the triangle's three corners, lit as the one colour would be (so with
    /// lighting off, or flat normals, one colour across the triangle).
    ///
    /// Errors, at [`View3d::draw`](super::View3d::draw), before any band is
    /// sent: [`Error::InvalidParameter`] if `colors.len()` is not the mesh's
    /// triangle count, or if the mesh is a meshlet mesh (its triangles are
    /// reordered into clusters).
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::view3d::{CUBE, Camera, Object, View3d};
    /// // The cube's 12 triangles, two per face: each face its own colour.
    /// let faces = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE, Rgb565::CYAN, Rgb565::MAGENTA, Rgb565::YELLOW];
    /// let colors: [Rgb565; 12] = core::array::from_fn(|t| faces[t / 2]);
    /// let cube = Object::new(&CUBE, Rgb565::WHITE).with_face_colors(&colors);
    /// let mut view = View3d::<Rgb565, 64, 8>::new(Rgb565::BLACK);
    /// view.set_lighting(None);
    /// let mut display = MockDisplay::new();
    /// display.set_allow_overdraw(true);
    /// view.draw(&Camera::look_at([0.0, 0.0, 4.0], [0.0; 3]), &[cube], &mut display)?;
    /// // Unlit, the face towards the camera shows exactly one of the colours.
    /// let c = display.get_pixel(embedded_graphics::prelude::Point::new(32, 32)).unwrap();
    /// assert!(faces.contains(&c));
    /// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
    /// ```
    pub fn with_face_colors(self, colors: &'a [C]) -> Self {
        Object { colors: Colors::PerFace(colors), ..self }
    }

    /// Where the material colours come from.
    pub fn colors(&self) -> Colors<'a, C> {
        self.colors
    }

    /// [`Error::InvalidParameter`] if the per-vertex or per-face colours do
    /// not match the mesh, or are per face on a meshlet mesh.
    pub(crate) fn check_colors(&self) -> Result<(), Error> {
        let (vertices, triangles) = match self.geometry {
            Geometry::Mesh(m) => (m.vertex_count(), Some(m.triangle_count())),
            Geometry::Valid(m) => (m.mesh().vertex_count(), Some(m.mesh().triangle_count())),
            Geometry::Meshlets(m) => (m.get().mesh.vertex_count(), None),
        };
        match self.colors {
            Colors::PerVertex(c) if c.len() != vertices => Err(Error::InvalidParameter(Param::VertexColors)),
            Colors::PerFace(c) if Some(c.len()) != triangles => {
                Err(Error::InvalidParameter(Param::FaceColors))
            }
            _ => Ok(()),
        }
    }

    /// The model matrix: object space to world space.
    pub fn model(&self) -> Mat4<f32> {
        self.model
    }

    /// The material colour.
    pub fn color(&self) -> C {
        self.color
    }

    /// The mesh.
    pub fn geometry(&self) -> Geometry<'a> {
        self.geometry
    }
}

/// One object into a band: through the vertex stage straight into it
/// (its chunks through the frame's record, `memo`), or cluster by cluster
/// for a meshlet mesh ([`Pipeline::rows`] of `banded` set to the band's
/// rows).
pub(super) fn draw_object<C: Interpolate, Mat: Material<f32>, const W: usize>(
    banded: &Pipeline<f32, 4>,
    o: &Object<'_, C>,
    material: &Mat,
    cache: &mut ClusterCache<f32, 4>,
    memo: &mut impl ChunkMemo<f32>,
    band: &mut Band3d<'_, '_, C, Depth16, PerspectiveCorrect, W>,
) -> Result<(), Error> {
    let (model, color) = (o.model(), o.color());
    let mut into_band = |t| {
        band.draw_in(&t, banded.precision);
        Ok(())
    };
    match o.geometry() {
        Geometry::Mesh(m) => {
            banded.mesh_into(&ValidMesh::trusted(m, true), &model, color, material, memo, &mut into_band)?
        }
        Geometry::Valid(m) => banded.mesh_into(&m, &model, color, material, memo, &mut into_band)?,
        Geometry::Meshlets(m) => banded.draw_meshlets_with(m, &model, color, material, cache, band)?,
    };
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view3d::CUBE;
    use embedded_graphics_core::pixelcolor::BinaryColor;

    /// Steps compose in the order written: scale, then rotate, then move.
    #[test]
    fn steps_apply_in_order() {
        let o = Object::new(&CUBE, BinaryColor::On)
            .scale(2.0)
            .rotate_z(core::f32::consts::FRAC_PI_2)
            .translate([10.0, 0.0, 0.0]);
        // (1, 0, 0) → (2, 0, 0) → (0, 2, 0) → (10, 2, 0).
        let p = o.model().transform_point(Vec3::new(1.0, 0.0, 0.0)).to_f32();
        assert!((p[0] - 10.0).abs() < 1e-5 && (p[1] - 2.0).abs() < 1e-5 && p[2].abs() < 1e-5, "{p:?}");
        assert!(matches!(o.geometry(), Geometry::Valid(_)));
        assert_eq!(o.with_color(BinaryColor::Off).color(), BinaryColor::Off);
    }
}
