//! Typed errors for every fallible entry point.

use core::fmt;

/// What was wrong with an input to microraster.
///
/// Every public function that can receive bad input returns this error (or a
/// [`RenderError`] that wraps it) instead of panicking. Variants carry what
/// a user needs to find the cause: which parameter ([`Param`]), which
/// sizes, which triangle, vertex or index ([`MeshFault`]); the
/// [`Display`](fmt::Display) text says it in words.
///
/// ```
/// use microraster::{Error, Param, SubPoint};
/// assert_eq!(SubPoint::<4>::from_f32(f32::NAN, 0.0), Err(Error::NonFiniteCoordinate));
/// let e = Error::InvalidParameter(Param::NearFar);
/// assert_eq!(e.to_string(), "invalid parameter: near must be positive and far beyond it");
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Error {
    /// A coordinate was NaN or infinite: a vertex, a camera, a light, a
    /// shape's geometry, or an object's transform (a NaN rotation, scale
    /// or translation).
    NonFiniteCoordinate,
    /// A coordinate lies outside the supported range: the subpixel range
    /// (see [`SubPoint::MAX_SUBPIXELS`](crate::SubPoint::MAX_SUBPIXELS)), or
    /// in the [`Fx`](crate::math::Fx) vertex stage a matrix entry or
    /// coordinate that 16.16 cannot hold (docs/limits.md, "The `Fx` range in the vertex stage").
    CoordinateOutOfRange,
    /// A frame or viewport width or height is zero or larger than
    /// [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM).
    InvalidFrameSize,
    /// A mesh is inconsistent: [`MeshFault`] says where (an index out of
    /// range and its triangle, a normal count, a vertex outside the
    /// bounding sphere).
    ///
    /// ```
    /// use microraster::{Error, mesh::{Mesh, MeshFault}};
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// let bad = Mesh::new(&positions, &[], &[[0, 1, 2], [0, 1, 3]], ([0.5, 0.5, 0.0], 0.71));
    /// let e = Error::InvalidMesh(MeshFault::IndexOutOfRange { triangle: 1, index: 3, vertices: 3 });
    /// assert_eq!(bad.validate(), Err(e));
    /// assert_eq!(e.to_string(), "invalid mesh: triangle 1 uses vertex 3 of 3 (indices start at 0)");
    /// ```
    InvalidMesh(MeshFault),
    /// A caller-provided buffer is smaller than the operation needs (a
    /// texture's data, a shape's edge list, a mesh generator's arrays, a band
    /// signature list or a panel's wire buffer; frame bins, vertex caches
    /// and the meshlet builder's buffers report
    /// [`CapacityExceeded`](Error::CapacityExceeded) instead).
    BufferTooSmall,
    /// The frame's bins, a vertex cache or a buffer of the meshlet builder
    /// ([`build_meshlets`](crate::mesh::build_meshlets)) hold fewer entries
    /// than one call needed: `needed` is the length that would have
    /// sufficed (for bins, the triangles already in them plus all that the
    /// mesh emits), `capacity` the buffer's. The bins are left as they were
    /// before the call: no partial mesh is drawn.
    ///
    /// ```
    /// let e = microraster::Error::CapacityExceeded { needed: 300, capacity: 256 };
    /// assert_eq!(e.to_string(), "buffer holds 256 entries, 300 needed");
    /// ```
    CapacityExceeded {
        /// Entries the call needed (already stored plus its own).
        needed: usize,
        /// Entries the buffer holds (its `N` or `V`).
        capacity: usize,
    },
    /// Meshlet data are inconsistent: a cluster's offsets or counts run past
    /// its arrays, it has no triangles or more than
    /// [`MAX_MESHLET_VERTICES`](crate::mesh::MAX_MESHLET_VERTICES) vertices or
    /// [`MAX_MESHLET_TRIANGLES`](crate::mesh::MAX_MESHLET_TRIANGLES)
    /// triangles, a local index is out of range, or its sphere or normal
    /// cone does not contain its positions or face normals.
    InvalidMeshlet,
    /// A triangle's winding disagrees with its vertex normals: the face
    /// normal from the counter-clockwise winding points against the normals
    /// (the mesh is wound clockwise, or its normals point inward).
    WindingMismatch,
    /// The frame (the band width `W` by [`Renderer::height`](crate::Renderer::height)
    /// rows, at [`Renderer::offset`](crate::Renderer::offset)) does not fit in
    /// the `DrawTarget`'s bounding box: a band wider than the display, or a
    /// frame taller than it, would be cut off silently. Both rectangles are
    /// given.
    ///
    /// ```
    /// use microraster::{Error, Region};
    /// let e = Error::FrameOutsideTarget { frame: Region::new(0, 0, 320, 240), target: Region::new(0, 0, 240, 240) };
    /// assert_eq!(e.to_string(), "frame 320 x 240 at (0, 0) does not fit in the draw target's 240 x 240 at (0, 0)");
    /// ```
    FrameOutsideTarget {
        /// The frame: `W` columns by the frame's rows, at its offset.
        frame: Region,
        /// The target's bounding box.
        target: Region,
    },
    /// A parameter is outside its documented range: [`Param`] names it.
    ///
    /// ```
    /// use microraster::{Error, Param, view3d::Camera};
    /// let same = Camera::look_at([1.0, 2.0, 3.0], [1.0, 2.0, 3.0]);
    /// assert_eq!(same.view().err(), Some(Error::InvalidParameter(Param::LookAt)));
    /// ```
    InvalidParameter(Param),
}

/// The parameter of an [`Error::InvalidParameter`].
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// A camera's eye equals its target, or its `up` is parallel to the
    /// view direction ([`transform::look_at`](crate::math::transform::look_at)).
    LookAt,
    /// A perspective field of view outside (0, π) radians.
    FieldOfView,
    /// An aspect ratio that is not positive.
    AspectRatio,
    /// `near` not positive (perspective), or `far` not beyond `near`.
    NearFar,
    /// An orthographic view box with `left ≥ right`, `bottom ≥ top`, or a
    /// height that is not positive.
    ViewBox,
    /// [`Pipeline::new`](crate::pipeline::Pipeline::new)'s `w_ref` not positive.
    WRef,
    /// An object's model transform is singular (a zero scale, say).
    Model,
    /// A light direction that is not a unit vector.
    LightDirection,
    /// Per-vertex colours whose count is not the mesh's vertex count.
    VertexColors,
    /// Per-face colours whose count is not the mesh's triangle count, or
    /// per-face colours on a meshlet mesh (or a cached vertex path).
    FaceColors,
    /// A texture width or height of 0 or above
    /// [`MAX_TEXTURE_DIM`](crate::texture::MAX_TEXTURE_DIM), or data longer
    /// than `width · height`.
    TextureSize,
    /// A sprite scale outside
    /// [`SPRITE_SCALE_RANGE`](crate::texture::SPRITE_SCALE_RANGE).
    SpriteScale,
    /// A negative stroke width.
    StrokeWidth,
    /// A miter limit below 1.
    MiterLimit,
    /// A negative shape size (a width, height or radius).
    ShapeSize,
    /// A linear gradient of zero length, or a radial one whose radius is
    /// not positive.
    Gradient,
    /// A mesh generator's subdivisions, segments or radii out of range.
    MeshShape,
    /// More triangles than [`build_meshlets`](crate::mesh::build_meshlets)
    /// can index.
    TriangleCount,
    /// A band sink returned no band where one was lent.
    BandSink,
    /// A parameter of the caller's own code: a [`Pass`](crate::render::Pass)
    /// or drawing closure of your own that refuses its input.
    User,
}

impl Param {
    /// What the parameter must be, for the error's text.
    const fn requirement(self) -> &'static str {
        match self {
            Param::LookAt => {
                "the camera's eye must differ from its target, and up must not be parallel to the view"
            }
            Param::FieldOfView => "the field of view must lie between 0 and pi radians",
            Param::AspectRatio => "the aspect ratio must be positive",
            Param::NearFar => "near must be positive and far beyond it",
            Param::ViewBox => {
                "the orthographic view box must have left < right, bottom < top and a positive height"
            }
            Param::WRef => "w_ref must be positive",
            Param::Model => "the object's transform is singular (a zero scale?)",
            Param::LightDirection => "the light direction must be a unit vector",
            Param::VertexColors => "there must be one vertex colour per mesh vertex",
            Param::FaceColors => {
                "there must be one face colour per mesh triangle (and none on a meshlet mesh)"
            }
            Param::TextureSize => {
                "texture width and height must be 1 to MAX_TEXTURE_DIM, the data width x height"
            }
            Param::SpriteScale => "the sprite scale must lie in SPRITE_SCALE_RANGE",
            Param::StrokeWidth => "the stroke width must not be negative",
            Param::MiterLimit => "the miter limit must be at least 1",
            Param::ShapeSize => "shape sizes and radii must not be negative",
            Param::Gradient => "a linear gradient needs two distinct points, a radial one a positive radius",
            Param::MeshShape => "mesh generator subdivisions, segments or radii out of range",
            Param::TriangleCount => "too many triangles for build_meshlets",
            Param::BandSink => "the band sink returned no band",
            Param::User => "a parameter of the caller's own pass or closure",
        }
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.requirement())
    }
}

/// Where a mesh is inconsistent ([`Error::InvalidMesh`]).
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFault {
    /// Triangle `triangle` uses vertex `index`, but the mesh has `vertices`.
    IndexOutOfRange {
        /// The triangle (its position in `indices`).
        triangle: usize,
        /// The index out of range.
        index: u16,
        /// The mesh's vertex count.
        vertices: usize,
    },
    /// The mesh has normals, but not one per position.
    NormalCount {
        /// Normals given.
        normals: usize,
        /// Positions given.
        positions: usize,
    },
    /// The bounding sphere's radius is negative.
    NegativeRadius,
    /// Vertex `vertex` lies outside the bounding sphere.
    OutsideSphere {
        /// The vertex (its position in `positions`).
        vertex: usize,
    },
    /// The vertex stage met an index out of range in data that skipped
    /// validation (a cluster's or a cache's); never for a validated mesh.
    Unchecked,
}

impl fmt::Display for MeshFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            MeshFault::IndexOutOfRange { triangle, index, vertices } => {
                write!(f, "triangle {triangle} uses vertex {index} of {vertices} (indices start at 0)")
            }
            MeshFault::NormalCount { normals, positions } => {
                write!(f, "{normals} normals for {positions} positions (give one per position, or none)")
            }
            MeshFault::NegativeRadius => f.write_str("the bounding sphere's radius is negative"),
            MeshFault::OutsideSphere { vertex } => {
                write!(f, "vertex {vertex} lies outside the bounding sphere")
            }
            MeshFault::Unchecked => f.write_str("an index out of range in data that skipped validation"),
        }
    }
}

/// A rectangle of pixels: top-left corner and size (the sizes in
/// [`Error::FrameOutsideTarget`]).
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Region {
    /// Left column.
    pub x: i32,
    /// Top row.
    pub y: i32,
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}

impl Region {
    /// `width × height` pixels from (`x`, `y`).
    pub const fn new(x: i32, y: i32, width: u32, height: u32) -> Self {
        Region { x, y, width, height }
    }
}

impl From<embedded_graphics_core::primitives::Rectangle> for Region {
    fn from(r: embedded_graphics_core::primitives::Rectangle) -> Self {
        Region::new(r.top_left.x, r.top_left.y, r.size.width, r.size.height)
    }
}

impl fmt::Display for Region {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} x {} at ({}, {})", self.width, self.height, self.x, self.y)
    }
}

impl Error {
    /// Panics with a message naming the error: the failure of the `const`
    /// constructors ([`ValidMeshletMesh::new_const`](crate::mesh::ValidMeshletMesh::new_const),
    /// [`ValidMesh::new_const`](crate::mesh::ValidMesh::new_const)), where
    /// a `static`'s panic is a build error that shows this message. (A
    /// constant's panic cannot format, so fields are not shown: call
    /// `new` at run time for them.)
    #[track_caller]
    pub(crate) const fn panic_const(self) -> ! {
        match self {
            Error::NonFiniteCoordinate => {
                panic!("invalid mesh: a position, normal, sphere or cone is NaN or infinite")
            }
            Error::CoordinateOutOfRange => panic!("invalid mesh: the bounding sphere's radius is too large"),
            Error::InvalidMesh(MeshFault::IndexOutOfRange { .. }) => {
                panic!("invalid mesh: a triangle's index is not below the vertex count")
            }
            Error::InvalidMesh(MeshFault::NormalCount { .. }) => {
                panic!("invalid mesh: the mesh has normals, but not one per position")
            }
            Error::InvalidMesh(MeshFault::NegativeRadius) => {
                panic!("invalid mesh: the bounding sphere's radius is negative")
            }
            Error::InvalidMesh(MeshFault::OutsideSphere { .. }) => {
                panic!("invalid mesh: a vertex lies outside the bounding sphere")
            }
            Error::InvalidMeshlet => panic!(
                "invalid meshlets: a cluster's offsets, counts, local indices, sphere or cone are inconsistent"
            ),
            Error::WindingMismatch => panic!(
                "invalid mesh: triangles are wound against their normals (drawn inside out; obj2rs --flip-winding fixes it)"
            ),
            _ => panic!("invalid mesh"),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            Error::NonFiniteCoordinate => "coordinate is NaN or infinite",
            Error::CoordinateOutOfRange => "coordinate outside the supported range",
            Error::InvalidFrameSize => "frame size is zero or too large",
            Error::InvalidMesh(fault) => return write!(f, "invalid mesh: {fault}"),
            Error::BufferTooSmall => "buffer too small",
            Error::CapacityExceeded { needed, capacity } => {
                return write!(f, "buffer holds {capacity} entries, {needed} needed");
            }
            Error::InvalidMeshlet => "meshlet offsets, counts, indices, sphere or cone are inconsistent",
            Error::WindingMismatch => "triangle winding disagrees with the vertex normals",
            Error::FrameOutsideTarget { frame, target } => {
                return write!(f, "frame {frame} does not fit in the draw target's {target}");
            }
            Error::InvalidParameter(param) => return write!(f, "invalid parameter: {param}"),
        };
        f.write_str(text)
    }
}

impl core::error::Error for Error {}

/// Drawing into a band cannot fail (its `DrawTarget::Error` is
/// [`Infallible`](core::convert::Infallible)); this lets `?` pass an
/// `embedded-graphics` draw result up from the closures of
/// [`from_fn`](crate::render::from_fn) and
/// friends, which return `Result<(), Error>`.
///
/// ```
/// fn never() -> Result<(), core::convert::Infallible> { Ok(()) }
/// fn pass() -> Result<(), microraster::Error> { never()?; Ok(()) }
/// assert_eq!(pass(), Ok(()));
/// ```
impl From<core::convert::Infallible> for Error {
    fn from(never: core::convert::Infallible) -> Self {
        match never {}
    }
}

/// Error returned by [`Renderer::render`](crate::Renderer::render) and the
/// other band loops: the input's [`Error`] (a bad configuration or scene,
/// found before anything is sent, or the first error of the frame's pass)
/// or the display's own error type `E`.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{Band, Error, RenderError, Renderer};
/// let mut band = Band::<BinaryColor, 4, 2>::new(BinaryColor::Off);
/// // A frame of 0 rows is refused before any band is sent.
/// let r = Renderer::new(0, BinaryColor::Off).render((), &mut band, &mut MockDisplay::new());
/// match r {
///     Err(RenderError::Input(Error::InvalidFrameSize)) => {}
///     other => panic!("{other:?}"),
/// }
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RenderError<E> {
    /// The renderer's configuration or the scene was invalid.
    Input(Error),
    /// The display (the `DrawTarget`) reported an error while a band was sent.
    Target(E),
}

impl<E> From<Error> for RenderError<E> {
    fn from(e: Error) -> Self {
        RenderError::Input(e)
    }
}

/// The input error is the [`source`](core::error::Error::source); a target
/// error is shown with `Debug`, since `DrawTarget::Error` need only be
/// `Debug`. So `?` converts a render result into `Box<dyn Error>`:
///
/// ```
/// # extern crate std;
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use microraster::{Band, Renderer};
/// fn frame() -> Result<(), std::boxed::Box<dyn core::error::Error>> {
///     let mut band = Band::<BinaryColor, 8, 4>::new(BinaryColor::Off);
///     let mut display = MockDisplay::<BinaryColor>::new();
///     Renderer::new(0, BinaryColor::Off).render((), &mut band, &mut display)?;
///     Ok(())
/// }
/// assert_eq!(frame().unwrap_err().to_string(), "invalid input: frame size is zero or too large");
/// ```
impl<E: fmt::Debug> core::error::Error for RenderError<E> {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            RenderError::Input(e) => Some(e),
            RenderError::Target(_) => None,
        }
    }
}

/// With the `defmt` feature, as [`Display`](fmt::Display): the input error,
/// or the target's error through [`defmt::Debug2Format`] (a
/// `DrawTarget::Error` need only be `Debug`).
#[cfg(feature = "defmt")]
#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl<E: fmt::Debug> defmt::Format for RenderError<E> {
    fn format(&self, f: defmt::Formatter<'_>) {
        match self {
            RenderError::Input(e) => defmt::write!(f, "invalid input: {}", e),
            RenderError::Target(e) => defmt::write!(f, "draw target error: {}", defmt::Debug2Format(e)),
        }
    }
}

impl<E: fmt::Debug> fmt::Display for RenderError<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenderError::Input(e) => write!(f, "invalid input: {e}"),
            RenderError::Target(e) => write!(f, "draw target error: {e:?}"),
        }
    }
}
