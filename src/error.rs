//! Typed errors for every fallible entry point.

use core::fmt;

/// What was wrong with an input to microraster.
///
/// Every public function that can receive bad input returns this error (or a
/// [`RenderError`] that wraps it) instead of panicking.
///
/// ```
/// use microraster::{Error, SubPoint};
/// assert_eq!(SubPoint::<4>::from_f32(f32::NAN, 0.0), Err(Error::NonFiniteCoordinate));
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Error {
    /// A coordinate was NaN or infinite.
    NonFiniteCoordinate,
    /// A coordinate lies outside the supported range: the subpixel range
    /// (see [`SubPoint::MAX_SUBPIXELS`](crate::SubPoint::MAX_SUBPIXELS)), or
    /// in the [`Fx`](crate::math::Fx) vertex stage a matrix entry or
    /// coordinate that 16.16 cannot hold (docs/limits.md, "The `Fx` range in the vertex stage").
    CoordinateOutOfRange,
    /// A frame or viewport width or height is zero or larger than
    /// [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM).
    InvalidFrameSize,
    /// A mesh index is out of range, the normals do not match the positions,
    /// or the bounding sphere does not contain the mesh.
    InvalidMesh,
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
    /// frame taller than it, would be cut off silently.
    FrameOutsideTarget,
    /// A parameter is outside its documented range (for example near ≥ far,
    /// a zero aspect ratio, or too few mesh segments).
    InvalidParameter,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            Error::NonFiniteCoordinate => "coordinate is NaN or infinite",
            Error::CoordinateOutOfRange => "coordinate outside the supported range",
            Error::InvalidFrameSize => "frame size is zero or too large",
            Error::InvalidMesh => "mesh indices, normals or bounding sphere are inconsistent",
            Error::BufferTooSmall => "buffer too small",
            Error::CapacityExceeded { needed, capacity } => {
                return write!(f, "buffer holds {capacity} entries, {needed} needed");
            }
            Error::InvalidMeshlet => "meshlet offsets, counts, indices, sphere or cone are inconsistent",
            Error::WindingMismatch => "triangle winding disagrees with the vertex normals",
            Error::FrameOutsideTarget => "frame does not fit in the draw target's bounding box",
            Error::InvalidParameter => "parameter outside its documented range",
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
