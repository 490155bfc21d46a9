//! Indexed triangle meshes in borrowed (typically flash-resident) data, and
//! allocation-free generators of demo shapes.
//!
//! A [`Mesh`] borrows its vertex and index arrays, so a model converted ahead
//! of time (with the `obj2rs` converter of `tools/`: `cargo run -p
//! microraster-tools --bin obj2rs -- model.obj NAME > model.rs`, or
//! `microraster_tools::obj::convert` in a build script) lives in `static`
//! arrays in flash and costs no RAM. The generators [`cube`](fn@cube), [`icosphere`](fn@icosphere) and [`torus`](fn@torus) write into
//! caller-provided buffers whose exact sizes are given by `const fn`s
//! ([`cube_vertex_count`], [`icosphere_triangle_count`], …), so the buffers
//! can be plain arrays.
//!
//! A [`MeshletMesh`] adds clusters of at most 64 vertices, each with a
//! bounding sphere and a normal cone, so whole clusters are rejected before
//! any vertex work; [`build_meshlets`] makes them without allocating (the
//! `obj2rs` converter emits them as statics by default), and
//! [`MeshletMesh::validate`] / [`ValidMeshletMesh`] check them, at compile
//! time for statics. [`Mesh::check_winding`] is the opt-in check that
//! windings agree with the normals.
//!
//! # Conventions
//!
//! * Right-handed coordinates.
//! * Triangles wind **counter-clockwise when seen from outside** the solid
//!   (from the side the normals point to); all generated meshes are closed,
//!   2-manifold and consistently oriented.
//! * Normals are per vertex, of unit length and point outward. A mesh may have
//!   no normals at all (an empty slice); the 3D pipeline then computes flat
//!   per-face normals ([`Mesh::face_normal`]).
//! * The bounding sphere contains every position; the 3D pipeline uses it to
//!   cull whole meshes against the view volume before any vertex work.
//!
//! The generators use `micromath` for `sin`/`cos` and a Newton-refined
//! `micromath` square root, so they produce bit-identical results on the host
//! and on Cortex-M targets.

pub(crate) mod cube;
mod data;
mod icosphere;
mod meshlet;
mod meshlet_adjacency;
mod meshlet_build;
mod sphere;
mod torus;
mod winding;

#[cfg(test)]
mod meshlet_tests;
#[cfg(test)]
mod tests;

pub use cube::{cube, cube_triangle_count, cube_vertex_count};
pub use icosphere::{
    ICOSPHERE_MAX_SUBDIVISIONS, icosphere, icosphere_triangle_count, icosphere_vertex_count,
};
pub use meshlet::{
    CONE_TOLERANCE, MAX_MESHLET_TRIANGLES, MAX_MESHLET_VERTICES, Meshlet, MeshletMesh, ValidMeshletMesh,
};
pub use meshlet_adjacency::meshlet_scratch_len;
pub use meshlet_build::{build_meshlets, meshlet_bound, meshlet_vertex_bound};
pub use sphere::bounding_sphere;
use sphere::sphere_about_origin;
pub use torus::{torus, torus_triangle_count, torus_vertex_count};
pub use winding::DEGENERATE_SIN2;

use crate::error::Error;
pub use crate::error::MeshFault;
#[cfg(feature = "fx")]
use crate::math::Fx;
use crate::math::Scalar;
#[cfg(feature = "fx")]
pub use data::fx_rows;
pub(crate) use data::{MeshData, Rows};

/// A caller-provided buffer is smaller than the generator needs.
const BUFFER_TOO_SMALL: Error = Error::BufferTooSmall;
/// A generator parameter (subdivisions, segments, radii) is out of range.
const INVALID_PARAMETER: Error = Error::InvalidParameter(crate::Param::MeshShape);

/// Most vertices a mesh can index with `u16` indices (65536).
pub const MAX_VERTICES: usize = u16::MAX as usize + 1;

/// Relative tolerance on the bounding-sphere radius used by [`Mesh::validate`].
pub const SPHERE_TOLERANCE: f32 = 1.0e-5;

/// An indexed triangle list in borrowed data.
///
/// The fields are public so meshes can be built in any way; the constructor is
/// a `const fn` so a mesh can be a `static`. Nothing is checked on
/// construction. [`validate`](Mesh::validate) checks every invariant
/// documented on the fields; the 3D pipeline calls it on every
/// [`draw_mesh`](crate::pipeline::Pipeline::draw_mesh) (O(vertices)), so a
/// bad mesh is an error, never a silent cull. A mesh checked once
/// ([`ValidMesh`], at compile time for a `static`) skips that cost
/// ([`draw_valid_mesh`](crate::pipeline::Pipeline::draw_valid_mesh)).
///
/// # Positions and normals in 16.16
/// `P` is the type the positions and normals are stored in: `f32` (the
/// default, [`Mesh::new`]) or [`Fx`] ([`Mesh::new_fx`]). A part without an
/// FPU draws with [`Pipeline<Fx, _>`](crate::pipeline::Pipeline), which
/// reads `f32` data by converting every coordinate of every vertex it
/// visits (`Fx::from_f32`, several dozen instructions each on a
/// Cortex-M0); data in 16.16 it reads as it is. Converted with
/// [`Fx::const_from_f32`] (at compile time), the data are the values the
/// conversion would give, so the fixed-point stage draws the same pixels
/// from either. Checks and culling read `Fx` data as the nearest `f32`
/// (exact below 2^8 in magnitude); the bounding spheres stay `f32`. The
/// meshlet path ([`MeshletMesh`], [`build_meshlets`],
/// [`Pipeline::draw_meshlets`](crate::pipeline::Pipeline::draw_meshlets))
/// takes either type, with either scalar of the pipeline; the
/// whole-mesh paths ([`ValidMesh`], `view3d`) take `f32` data.
///
/// ```
/// use microraster::math::Fx;
/// use microraster::mesh::{Mesh, bounding_sphere, fx_rows};
/// static P: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.25]];
/// static P_FX: [[Fx; 3]; 3] = fx_rows(&P);
/// let mesh = Mesh::new_fx(&P_FX, &[], &[[0, 1, 2]], bounding_sphere(&P));
/// assert_eq!(mesh.validate(), Ok(()));
/// ```
///
/// ```
/// use microraster::mesh::{Mesh, bounding_sphere};
///
/// // A tetrahedron: counter-clockwise seen from outside, no normals.
/// static POSITIONS: [[f32; 3]; 4] =
///     [[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
/// static INDICES: [[u16; 3]; 4] = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];
/// static TETRA: Mesh<'static> = Mesh::new(&POSITIONS, &[], &INDICES, ([0.0; 3], 1.7320508));
///
/// TETRA.validate()?;
/// assert_eq!((TETRA.vertex_count(), TETRA.triangle_count()), (4, 4));
/// assert!(!TETRA.has_normals());
/// assert_eq!(bounding_sphere(&POSITIONS), TETRA.bounding_sphere);
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mesh<'a, P = f32> {
    /// Vertex positions (finite).
    pub positions: &'a [[P; 3]],
    /// Unit vertex normals, one per position, or empty (the pipeline then uses
    /// flat per-face normals). Finite.
    pub normals: &'a [[P; 3]],
    /// Triangles as indices into `positions`, counter-clockwise when seen from
    /// outside (from the front).
    pub indices: &'a [[u16; 3]],
    /// `(centre, radius)` of a sphere containing every position (within
    /// [`SPHERE_TOLERANCE`]); see [`bounding_sphere`].
    pub bounding_sphere: ([f32; 3], f32),
}

impl<'a> Mesh<'a> {
    /// A mesh from its parts (unchecked; see [`validate`](Mesh::validate)).
    pub const fn new(
        positions: &'a [[f32; 3]],
        normals: &'a [[f32; 3]],
        indices: &'a [[u16; 3]],
        bounding_sphere: ([f32; 3], f32),
    ) -> Self {
        Mesh { positions, normals, indices, bounding_sphere }
    }
}

#[cfg(feature = "fx")]
#[cfg_attr(docsrs, doc(cfg(feature = "fx")))]
impl<'a> Mesh<'a, Fx> {
    /// A mesh from its parts in 16.16 (unchecked; see
    /// [`validate`](Mesh::validate)): for the fixed-point vertex stage,
    /// which reads them without a conversion (the [`Mesh`] docs).
    pub const fn new_fx(
        positions: &'a [[Fx; 3]],
        normals: &'a [[Fx; 3]],
        indices: &'a [[u16; 3]],
        bounding_sphere: ([f32; 3], f32),
    ) -> Self {
        Mesh { positions, normals, indices, bounding_sphere }
    }
}

impl<P> Mesh<'_, P> {
    /// Number of vertices (positions).
    pub const fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub const fn triangle_count(&self) -> usize {
        self.indices.len()
    }

    /// Whether the mesh has per-vertex normals.
    pub const fn has_normals(&self) -> bool {
        !self.normals.is_empty()
    }
}

impl<'a, P: Scalar> Mesh<'a, P> {
    /// Position `v` as `f32` (exact for 16.16 data below 2^8; `v` in range).
    pub(crate) fn point_f32(&self, v: u16) -> [f32; 3] {
        self.positions[usize::from(v)].map(P::to_f32)
    }

    /// The data as the checks read it (`f32` rows of either storage type).
    pub(crate) fn data(&self) -> MeshData<'a> {
        MeshData {
            positions: P::rows(self.positions),
            normals: P::rows(self.normals),
            indices: self.indices,
            bounding_sphere: self.bounding_sphere,
        }
    }
}

impl Mesh<'_> {
    /// The positions of triangle `i`, or `None` if `i` or one of its indices
    /// is out of range.
    pub fn triangle(&self, i: usize) -> Option<[[f32; 3]; 3]> {
        let [a, b, c] = *self.indices.get(i)?;
        let p = |k: u16| self.positions.get(usize::from(k)).copied();
        Some([p(a)?, p(b)?, p(c)?])
    }

    /// The unit normal of triangle `i` from its winding (the flat normal, the
    /// side from which the triangle is seen counter-clockwise), or `None` if
    /// `i` is out of range or the triangle is degenerate (zero area).
    ///
    /// ```
    /// use microraster::mesh::Mesh;
    /// let positions = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
    /// let mesh = Mesh::new(&positions, &[], &[[0, 1, 2]], ([1.0, 1.0, 0.0], 1.5));
    /// assert_eq!(mesh.face_normal(0), Some([0.0, 0.0, 1.0]));
    /// ```
    pub fn face_normal(&self, i: usize) -> Option<[f32; 3]> {
        face_normal_of(self.triangle(i)?)
    }
}

/// The unit normal of the triangle `[a, b, c]` from its winding (seen
/// counter-clockwise from the side it points to); `None` for zero area.
pub(crate) fn face_normal_of([a, b, c]: [[f32; 3]; 3]) -> Option<[f32; 3]> {
    let n = cross(sub(b, a), sub(c, a));
    let len = sqrt(dot(n, n));
    if len > 0.0 && len.is_finite() { Some(n.map(|x| x / len)) } else { None }
}

/// A [`Mesh`] that passed [`Mesh::validate`], so
/// [`Pipeline::draw_valid_mesh`](crate::pipeline::Pipeline::draw_valid_mesh)
/// draws it without checking it again (the check is O(vertices) and, once
/// per band when the vertex stage runs per band, costs as much as the rest
/// of the work on a part without an FPU). The mesh data are shared
/// references, so they cannot change afterwards.
///
/// [`ValidMesh::new`] is a `const fn`: a `static` mesh can be checked at
/// compile time, where an invalid mesh is a build error.
///
/// ```
/// use microraster::mesh::{Mesh, ValidMesh};
/// static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// static INDICES: [[u16; 3]; 1] = [[0, 1, 2]];
/// static TRI: ValidMesh<'static> =
///     match ValidMesh::new(Mesh::new(&POSITIONS, &[], &INDICES, ([0.5, 0.5, 0.0], 0.71))) {
///         Ok(m) => m,
///         Err(_) => panic!("invalid mesh"), // at compile time: a build error
///     };
/// assert_eq!(TRI.mesh().triangle_count(), 1);
/// let bad = Mesh::new(&POSITIONS, &[], &[[0, 1, 3]], ([0.5, 0.5, 0.0], 0.71));
/// assert!(ValidMesh::new(bad).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValidMesh<'a> {
    mesh: Mesh<'a>,
    /// [`Mesh::check_winding`] passes (known to the front, which then
    /// skips it; false where not looked at).
    wound: bool,
}

impl<'a> ValidMesh<'a> {
    /// `mesh` if it passes [`Mesh::validate`], else that error. Whether its
    /// winding agrees with its normals is found here too, once
    /// ([`ValidMesh::winding_agrees`]; O(triangles)), so the `view3d`
    /// front need not check it every frame.
    pub const fn new(mesh: Mesh<'a>) -> Result<Self, Error> {
        match mesh.validate() {
            Ok(()) => Ok(ValidMesh { mesh, wound: mesh.const_data().check_winding_unvalidated().is_ok() }),
            Err(e) => Err(e),
        }
    }

    /// `mesh`, validated and its winding checked at compile time when it
    /// initialises a `static` or `const`: an invalid mesh, or one wound
    /// against its normals, is a build error whose message names the cause
    /// (at run time, a panic; [`ValidMesh::new`] returns the error instead,
    /// and accepts a mesh wound against its normals, for drawing with
    /// [`Cull::None`](crate::Cull::None)). What `obj2rs --plain` output can
    /// be wrapped in, with no hand-written `match`.
    ///
    /// ```
    /// use microraster::mesh::{Mesh, ValidMesh};
    /// static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// static TRI: ValidMesh<'static> = ValidMesh::new_const(Mesh::new(&POSITIONS, &[], &[[0, 1, 2]], ([0.5, 0.5, 0.0], 0.71)));
    /// assert!(TRI.winding_agrees());
    /// ```
    ///
    /// A bad mesh does not build (the message: "invalid mesh: a triangle's
    /// index is not below the vertex count"):
    ///
    /// ```compile_fail
    /// use microraster::mesh::{Mesh, ValidMesh};
    /// static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// static TRI: ValidMesh<'static> = ValidMesh::new_const(Mesh::new(&POSITIONS, &[], &[[0, 1, 3]], ([0.5, 0.5, 0.0], 0.71)));
    /// ```
    #[track_caller]
    pub const fn new_const(mesh: Mesh<'a>) -> Self {
        match ValidMesh::new(mesh) {
            Ok(m) if m.wound => m,
            Ok(_) => Error::WindingMismatch.panic_const(),
            Err(e) => e.panic_const(),
        }
    }

    /// The mesh.
    pub const fn mesh(&self) -> &Mesh<'a> {
        &self.mesh
    }

    /// Whether [`Mesh::check_winding`] passes: every triangle is wound
    /// counter-clockwise seen from the side its vertex normals point to (a
    /// mesh without normals passes). Found by [`ValidMesh::new`].
    ///
    /// ```
    /// use microraster::mesh::{Mesh, ValidMesh};
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// let up = [[0.0, 0.0, 1.0]; 3];
    /// let sphere = ([0.5, 0.5, 0.0], 0.71);
    /// let good = ValidMesh::new(Mesh::new(&positions, &up, &[[0, 1, 2]], sphere)).unwrap();
    /// let inside_out = ValidMesh::new(Mesh::new(&positions, &up, &[[0, 2, 1]], sphere)).unwrap();
    /// assert!(good.winding_agrees() && !inside_out.winding_agrees());
    /// ```
    pub const fn winding_agrees(&self) -> bool {
        self.wound
    }

    /// `mesh`, which the caller has just checked ([`Mesh::validate`], and
    /// [`Mesh::check_winding`] if `wound`): [`Pipeline::draw_mesh`]
    /// validates on every call; the `view3d` front checks a plain mesh once
    /// per frame, not once per band.
    ///
    /// [`Pipeline::draw_mesh`]: crate::pipeline::Pipeline::draw_mesh
    pub(crate) const fn trusted(mesh: Mesh<'a>, wound: bool) -> Self {
        ValidMesh { mesh, wound }
    }
}

const fn is_finite3(v: [f32; 3]) -> bool {
    v[0].is_finite() && v[1].is_finite() && v[2].is_finite()
}

const fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

const fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

const fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

const fn dist2(a: [f32; 3], b: [f32; 3]) -> f32 {
    let d = sub(a, b);
    dot(d, d)
}

/// `v / |v|` (unchanged if `|v|` is zero).
fn normalize(v: [f32; 3]) -> [f32; 3] {
    let len = sqrt(dot(v, v));
    if len > 0.0 { v.map(|x| x / len) } else { v }
}

use crate::math::scalar::sqrt_f32 as sqrt;

/// Unit vector `(cos a, sin a)`: `micromath`'s estimates (error ≤ 0.002)
/// renormalised, so the point lies on the unit circle to within rounding.
fn cos_sin(a: f32) -> (f32, f32) {
    let (c, s) = (micromath::F32Ext::cos(a), micromath::F32Ext::sin(a));
    let len = sqrt(c * c + s * s);
    (c / len, s / len)
}
