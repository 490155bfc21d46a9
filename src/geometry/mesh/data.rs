//! Mesh data stored in either number type, read as `f32` by the checks.
//!
//! A [`Mesh`](super::Mesh) holds its positions and normals as `f32` or as
//! 16.16 [`Fx`] (a mesh for the fixed-point vertex stage, which then reads
//! them without a conversion). Validation is a `const fn` (a `static` is
//! checked at compile time), and a `const fn` cannot call trait methods, so
//! the checks run on [`MeshData`]: the same borrowed arrays behind an enum
//! of the two storage types, each row read as `f32` ([`Rows::get`]).
//!
//! An [`Fx`] row reads as the `f32` nearest to it (exact below 2^8 in
//! magnitude, as [`Scalar::to_f32`](crate::math::Scalar::to_f32)), so a
//! mesh in 16.16 passes exactly when the same mesh in `f32`, holding those
//! values, passes.

use super::winding::winding_agrees;
use super::{SPHERE_TOLERANCE, dist2, is_finite3};
use crate::MeshFault;
use crate::error::Error;
#[cfg(feature = "fx")]
use crate::math::Fx;

/// Rows of three values in either storage type.
#[derive(Debug, Clone, Copy)]
pub enum Rows<'a> {
    /// `f32` data.
    F32(&'a [[f32; 3]]),
    /// 16.16 data.
    #[cfg(feature = "fx")]
    Fx(&'a [[Fx; 3]]),
}

impl Rows<'_> {
    /// Number of rows.
    pub(crate) const fn len(&self) -> usize {
        match self {
            Rows::F32(r) => r.len(),
            #[cfg(feature = "fx")]
            Rows::Fx(r) => r.len(),
        }
    }

    pub(crate) const fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Row `i` as `f32` (an [`Fx`] value rounded to nearest: `i32 → f32`
    /// rounds, the division by 2^16 is exact); `i < len()`.
    pub(crate) const fn get(&self, i: usize) -> [f32; 3] {
        match self {
            Rows::F32(r) => r[i],
            #[cfg(feature = "fx")]
            Rows::Fx(r) => {
                let v = r[i];
                [fx_f32(v[0]), fx_f32(v[1]), fx_f32(v[2])]
            }
        }
    }
}

/// `rows` in 16.16, each value [`Fx::const_from_f32`] of it: mesh data for
/// the fixed-point vertex stage made at compile time from `f32` data
/// ([`Mesh::new_fx`](super::Mesh::new_fx)). The `f32` array need not be
/// linked: only the result is, when only it is used at run time.
///
/// ```
/// use microraster::math::{Fx, Scalar};
/// use microraster::mesh::fx_rows;
/// static P: [[f32; 3]; 2] = [[0.5, -1.25, 3.0], [0.1, 0.2, 0.3]];
/// static P_FX: [[Fx; 3]; 2] = fx_rows(&P);
/// assert_eq!(P_FX[1][0], Fx::from_f32(0.1));
/// ```
#[cfg(feature = "fx")]
#[cfg_attr(docsrs, doc(cfg(feature = "fx")))]
pub const fn fx_rows<const N: usize>(rows: &[[f32; 3]; N]) -> [[Fx; 3]; N] {
    let mut out = [[Fx::from_bits(0); 3]; N];
    let mut i = 0;
    while i < N {
        let r = rows[i];
        out[i] = [Fx::const_from_f32(r[0]), Fx::const_from_f32(r[1]), Fx::const_from_f32(r[2])];
        i += 1;
    }
    out
}

/// `v` as the nearest `f32` (what `Fx::to_f32` gives, as a `const fn`).
#[cfg(feature = "fx")]
const fn fx_f32(v: Fx) -> f32 {
    v.to_bits() as f32 / 65_536.0
}

/// A mesh's data as its checks read it ([`Mesh`](super::Mesh) fields).
#[derive(Debug, Clone, Copy)]
pub(crate) struct MeshData<'a> {
    pub(crate) positions: Rows<'a>,
    pub(crate) normals: Rows<'a>,
    pub(crate) indices: &'a [[u16; 3]],
    pub(crate) bounding_sphere: ([f32; 3], f32),
}

impl MeshData<'_> {
    /// [`Mesh::validate`](super::Mesh::validate) (its docs).
    pub(crate) const fn validate(&self) -> Result<(), Error> {
        // A `const fn` (plain loops), so a `static` mesh can be checked at
        // compile time ([`ValidMesh::new`]); the same f32 operations at run time.
        let n = self.positions.len();
        if !self.normals.is_empty() && self.normals.len() != n {
            return Err(Error::InvalidMesh(MeshFault::NormalCount {
                normals: self.normals.len(),
                positions: n,
            }));
        }
        let mut i = 0;
        while i < self.indices.len() {
            let [a, b, c] = self.indices[i];
            // The first index out of range, in corner order.
            let bad = if a as usize >= n {
                Some(a)
            } else if b as usize >= n {
                Some(b)
            } else if c as usize >= n {
                Some(c)
            } else {
                None
            };
            if let Some(index) = bad {
                return Err(Error::InvalidMesh(MeshFault::IndexOutOfRange {
                    triangle: i,
                    index,
                    vertices: n,
                }));
            }
            i += 1;
        }
        let mut i = 0;
        while i < self.normals.len() {
            if !is_finite3(self.normals.get(i)) {
                return Err(Error::NonFiniteCoordinate);
            }
            i += 1;
        }
        let (centre, radius) = self.bounding_sphere;
        if !is_finite3(centre) || !radius.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        if radius < 0.0 {
            return Err(Error::InvalidMesh(MeshFault::NegativeRadius));
        }
        let r = radius * (1.0 + SPHERE_TOLERANCE);
        let r2 = r * r;
        if r2 == f32::INFINITY {
            return Err(Error::CoordinateOutOfRange);
        }
        let mut i = 0;
        while i < n {
            let p = self.positions.get(i);
            if !is_finite3(p) {
                return Err(Error::NonFiniteCoordinate);
            }
            // Finite inputs give no NaN; an overflow to infinity fails.
            if dist2(p, centre) > r2 {
                return Err(Error::InvalidMesh(MeshFault::OutsideSphere { vertex: i }));
            }
            i += 1;
        }
        Ok(())
    }

    /// [`Mesh::check_winding`](super::Mesh::check_winding) for a mesh
    /// already validated.
    pub(crate) const fn check_winding_unvalidated(&self) -> Result<(), Error> {
        if self.normals.is_empty() {
            return Ok(());
        }
        let mut i = 0;
        while i < self.indices.len() {
            let [a, b, c] = self.indices[i];
            let (a, b, c) = (a as usize, b as usize, c as usize);
            let p = [self.positions.get(a), self.positions.get(b), self.positions.get(c)];
            let n = [self.normals.get(a), self.normals.get(b), self.normals.get(c)];
            if !winding_agrees(p, n) {
                return Err(Error::WindingMismatch);
            }
            i += 1;
        }
        Ok(())
    }

    /// [`Mesh::check_winding`](super::Mesh::check_winding).
    pub(crate) const fn check_winding(&self) -> Result<(), Error> {
        if let Err(e) = self.validate() {
            return Err(e);
        }
        self.check_winding_unvalidated()
    }
}

/// What [`Mesh`](super::Mesh) and [`MeshletMesh`](super::MeshletMesh)
/// offer for each storage type as `const fn`s (a `const fn` cannot be
/// generic over the trait that reads the data): their [`MeshData`], and
/// the public checks on it.
macro_rules! storage_impls {
    ($p:ty, $rows:ident, $new:ident, $new_doc:literal, $new_const:ident, $const_doc:literal) => {
        impl<'a> super::Mesh<'a, $p> {
            /// The data as the checks read it.
            pub(crate) const fn const_data(&self) -> MeshData<'a> {
                MeshData {
                    positions: Rows::$rows(self.positions),
                    normals: Rows::$rows(self.normals),
                    indices: self.indices,
                    bounding_sphere: self.bounding_sphere,
                }
            }

            /// Checks the invariants the 3D pipeline relies on, in
            /// O(vertices + triangles) without allocating:
            ///
            /// * every index is less than the number of positions,
            /// * `normals` is empty or exactly as long as `positions`,
            /// * every position, normal and the bounding sphere are finite,
            /// * the radius is non-negative, its square is finite (the
            ///   radius is below about 1.8·10¹⁹), and every position lies
            ///   within `radius · (1 + SPHERE_TOLERANCE)` of the centre.
            ///
            /// Normals are not checked for unit length. Data in 16.16 is
            /// read as the nearest `f32` (the module docs of
            /// [`Mesh`](super::Mesh)). How large a mesh the 3D pipeline can
            /// draw also depends on the camera and the model: a vertex whose
            /// clip coordinate lies beyond ±2^64 (the clipper's input range)
            /// is [`Error::CoordinateOutOfRange`] when the mesh is drawn
            /// ([`Pipeline::draw_valid_mesh`](crate::pipeline::Pipeline::draw_valid_mesh)).
            ///
            /// # Errors
            ///
            /// [`Error::NonFiniteCoordinate`] if a value is NaN or infinite;
            /// [`Error::InvalidMesh`] for inconsistent indices, normals or
            /// sphere; [`Error::CoordinateOutOfRange`] for a radius too large
            /// to square.
            ///
            /// ```
            /// use microraster::{Error, mesh::Mesh};
            /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
            /// let sphere = ([0.5, 0.5, 0.0], 0.71);
            /// assert!(Mesh::new(&positions, &[], &[[0, 1, 2]], sphere).validate().is_ok());
            /// assert!(Mesh::new(&positions, &[], &[[0, 1, 3]], sphere).validate().is_err());
            /// let nan = [[0.0, 0.0, f32::NAN], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
            /// assert_eq!(
            ///     Mesh::new(&nan, &[], &[[0, 1, 2]], sphere).validate(),
            ///     Err(Error::NonFiniteCoordinate)
            /// );
            /// ```
            pub const fn validate(&self) -> Result<(), Error> {
                self.const_data().validate()
            }

            /// Checks that every triangle is wound counter-clockwise seen
            /// from the side its vertex normals point to: for each
            /// non-degenerate triangle (see
            /// [`DEGENERATE_SIN2`](super::DEGENERATE_SIN2)) the face normal
            /// `(b − a) × (c − a)` must not point against the sum of its
            /// three vertex normals (their dot product is `≥ 0`). A mesh
            /// without normals passes. Opt-in (O(triangles)), because
            /// `validate` does not need it; a mesh with the wrong winding is
            /// drawn inside out (culled from the front), which this check
            /// catches at build time. A `const fn`, like `validate`.
            ///
            /// # Errors
            ///
            /// The errors of `validate`, which runs first; then
            /// [`Error::WindingMismatch`] for the first disagreeing triangle.
            ///
            /// ```
            /// use microraster::{Error, mesh::Mesh};
            /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
            /// let up = [[0.0, 0.0, 1.0]; 3];
            /// let sphere = ([0.5, 0.5, 0.0], 0.71);
            /// assert_eq!(Mesh::new(&positions, &up, &[[0, 1, 2]], sphere).check_winding(), Ok(()));
            /// assert_eq!(
            ///     Mesh::new(&positions, &up, &[[0, 2, 1]], sphere).check_winding(),
            ///     Err(Error::WindingMismatch)
            /// );
            /// ```
            pub const fn check_winding(&self) -> Result<(), Error> {
                self.const_data().check_winding()
            }
        }

        impl<'a> super::MeshletMesh<'a, $p> {
            /// The clusters and their mesh as the checks read them.
            pub(crate) const fn const_data(&self) -> MeshletData<'a> {
                MeshletData {
                    mesh: self.mesh.const_data(),
                    meshlets: self.meshlets,
                    vertices: self.vertices,
                    triangles: self.triangles,
                }
            }

            /// Checks the invariants the meshlet renderer relies on (the
            /// list is in the [`MeshletMesh`](super::MeshletMesh) docs), in
            /// O(vertices + triangles) without allocating.
            ///
            /// # Errors
            ///
            /// The errors of the inner mesh's `validate`; then
            /// [`Error::NonFiniteCoordinate`] for a NaN or infinite sphere or
            /// cone, [`Error::InvalidMeshlet`] for any other cluster
            /// inconsistency, and [`Error::WindingMismatch`] for a triangle
            /// wound against its normals.
            ///
            /// ```
            /// use microraster::{Error, mesh::{Mesh, Meshlet, MeshletMesh}};
            /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
            /// let mesh = Mesh::new(&positions, &[], &[], ([0.5, 0.5, 0.0], 0.71));
            /// let cluster = Meshlet {
            ///     vertex_count: 3,
            ///     triangle_count: 1,
            ///     sphere: ([0.5, 0.5, 0.0], 0.71),
            ///     cone: ([0.0, 0.0, 1.0], 0.0), // one flat triangle facing +z
            ///     ..Meshlet::default()
            /// };
            /// let m = MeshletMesh { mesh, meshlets: &[cluster], vertices: &[0, 1, 2], triangles: &[[0, 1, 2]] };
            /// assert_eq!(m.validate(), Ok(()));
            /// let facing_down = MeshletMesh { triangles: &[[0, 2, 1]], ..m };
            /// assert_eq!(facing_down.validate(), Err(Error::InvalidMeshlet));
            /// ```
            pub const fn validate(&self) -> Result<(), Error> {
                self.const_data().validate()
            }
        }

        impl<'a> super::ValidMeshletMesh<'a, $p> {
            #[doc = $new_doc]
            pub const fn $new(mesh: super::MeshletMesh<'a, $p>) -> Result<Self, Error> {
                match mesh.validate() {
                    Ok(()) => Ok(super::ValidMeshletMesh(mesh)),
                    Err(e) => Err(e),
                }
            }

            #[doc = $const_doc]
            ///
            /// `mesh` validated at compile time when it initialises a
            /// `static` or `const` (what `obj2rs` writes): a mesh that fails
            /// its `validate` is a build error whose message names the
            /// cause ("triangles are wound against their normals", "a vertex
            /// lies outside the bounding sphere", ...), with no
            /// hand-written `match`. At run time, a panic: call the
            /// fallible constructor there for the error and its fields.
            #[track_caller]
            pub const fn $new_const(mesh: super::MeshletMesh<'a, $p>) -> Self {
                match mesh.validate() {
                    Ok(()) => super::ValidMeshletMesh(mesh),
                    Err(e) => e.panic_const(),
                }
            }
        }
    };
}

storage_impls!(
    f32,
    F32,
    new,
    "`mesh` if it passes its `validate`, else that error.",
    new_const,
    "[`ValidMeshletMesh::new`](super::ValidMeshletMesh::new) for a `static`: \
     `static KNOT: ValidMeshletMesh<'static> = ValidMeshletMesh::new_const(MeshletMesh { .. });`"
);
// A name of its own: two `new`s would make `ValidMeshletMesh::new(m)`
// ambiguous (a path in an expression does not default `P`).
#[cfg(feature = "fx")]
storage_impls!(
    Fx,
    Fx,
    new_fx,
    "`mesh`, in 16.16, if it passes its `validate`, else that error \
     ([`ValidMeshletMesh::new`](super::ValidMeshletMesh::new) for `f32` data).",
    new_fx_const,
    "[`ValidMeshletMesh::new_fx`](super::ValidMeshletMesh::new_fx) for a `static` \
     ([`ValidMeshletMesh::new_const`](super::ValidMeshletMesh::new_const) for `f32` data)."
);

pub(crate) use super::meshlet::MeshletData;
