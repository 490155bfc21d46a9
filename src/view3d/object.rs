//! What the front draws: a mesh, where it is (a model transform built from
//! translate, rotate and scale steps) and its material colour.

use crate::math::{Mat4, Vec3, transform};
use crate::mesh::{Mesh, ValidMesh, ValidMeshletMesh};

/// The mesh of an [`Object`]. Build it with `into()` from a reference to
/// any of the three mesh types; [`Object::new`] does that for you.
#[derive(Debug, Clone, Copy)]
pub enum Geometry<'a> {
    /// A mesh checked ([`Mesh::check_winding`], which validates it too) at
    /// the start of every frame; the frame fails with its error.
    Mesh(Mesh<'a>),
    /// A mesh validated beforehand; its winding is still checked against its
    /// normals at the start of every frame ([`Mesh::check_winding`]).
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

/// A mesh placed in the world, in one colour. The transform steps apply in
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
}

impl<'a, C: Copy> Object<'a, C> {
    /// `geometry` (`&Mesh`, `&ValidMesh` or `&ValidMeshletMesh`) at the
    /// world's origin, untransformed, in material colour `color`.
    pub fn new(geometry: impl Into<Geometry<'a>>, color: C) -> Self {
        Object { geometry: geometry.into(), model: Mat4::IDENTITY, color }
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
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter).
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

    /// The same object in another colour.
    pub fn with_color(self, color: C) -> Self {
        Object { color, ..self }
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
