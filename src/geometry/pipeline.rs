//! The vertex stage: meshes in, screen-space triangles out.
//!
//! For each mesh: view-volume culling of the whole mesh by its bounding
//! sphere (before any vertex work); per triangle the model-view-projection
//! transform, lighting (flat per face or Gouraud per vertex), homogeneous
//! clipping ([`crate::clip3d`]: near, far and a guard band, so only `w > 0`
//! reaches the divide), the perspective divide and viewport transform straight
//! into snapped [`SubPoint`](crate::SubPoint)s, and back-face culling from the signed area
//! *after* snapping, so culling and coverage always agree (as in D3D11).
//! The result goes into a caller-owned `heapless::Vec` of [`ScreenTriangle`](crate::raster3d::ScreenTriangle)s
//! (the frame's bins), which [`Triangles3d`](crate::render::Triangles3d)
//! draws band by band.
//!
//! `T` is the numeric path: `f32` (FPU parts) or [`Fx`](crate::math::Fx)
//! (16.16 fixed point, parts without an FPU).
//!
//! # Where the code is, in the order a vertex meets it
//! * per mesh: `mesh_setup` (matrices, whole-mesh culls, `Fx` range
//!   checks), `model_light` (lighting moved into model space), `band` (the
//!   clip-space test of the rows being drawn);
//! * meshlets per band: `frame_clusters` and `sphere_rows` (what a frame
//!   learns about each cluster), `cluster` (the band loop over clusters and
//!   their culls), `inside` (no clipping needed), then `eager` (a cluster
//!   inside the view, vertex first) or `cache` (lazily, vertex by vertex;
//!   `chunked` with a cache smaller than the mesh);
//! * per vertex: `vertex_ctx` (clip position, lit colour), `material`
//!   (where its colour comes from), `presnap` and `snap` (back faces before
//!   snapping, then the snapped position, depth and `1/w` and the
//!   snapped-area tests);
//! * whole meshes without meshlets: `mesh_bins` into the frame's bins
//!   (`bins`) or `mesh_band` straight into a band (which 3D path to use:
//!   its docs), `varying` for the fragment stage.

mod band;
mod bins;
mod cache;
mod chunk_record;
mod chunked;
mod cluster;
mod eager;
mod frame_clusters;
mod inside;
mod material;
mod mesh_band;
mod mesh_bins;
mod mesh_setup;
mod model_light;
mod presnap;
mod snap;
mod sphere_rows;
mod tier;
#[cfg(feature = "fragment")]
mod varying;
mod vertex_ctx;

use band::Band;
use mesh_setup::{row_f32, rows_f32, view_planes};
use vertex_ctx::{MeshSetup, VertexCtx, channels, finite_color};

pub use cache::VertexCache;
pub(crate) use chunk_record::{ChunkMemo, FrameChunks, NoMemo};
pub use cluster::ClusterCache;
pub use frame_clusters::{FRAME_CLUSTERS, FRAME_MESHES};
pub(crate) use material::{Material, PerFace, PerVertex, Uniform};

#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub use varying::VertexInput;

use crate::clip3d::ClipPlanes;
use crate::edge::Cull;
use crate::light::Lighting;
use crate::math::{Mat4, Scalar, transform};
use crate::raster3d::Precision;
use crate::{Error, MAX_FRAME_DIM};

/// Per-face or per-vertex lighting.
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Shade {
    /// One colour per triangle, lit with the face normal.
    Flat,
    /// A colour per vertex, lit with the vertex normals (face normals when the
    /// mesh has none) and interpolated across the triangle.
    #[default]
    Gouraud,
}

/// What happened to one mesh's triangles.
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct MeshStats {
    /// The whole mesh was outside the view volume (no vertex work done).
    pub mesh_culled: bool,
    /// Triangles that crossed a clip plane and were clipped (triangles wholly
    /// outside are dropped without being counted).
    pub clipped: u32,
    /// Triangles (after clipping) dropped as back faces.
    pub back_faces: u32,
    /// Triangles dropped because they had zero area after snapping.
    pub degenerate: u32,
    /// Screen triangles written to the bins (or drawn into the band).
    pub emitted: u32,
    /// Meshlets skipped whole, before any vertex work, as outside the band
    /// or the view volume ([`Pipeline::draw_meshlets`]).
    pub clusters_outside: u32,
    /// Meshlets skipped whole as facing away (their normal cone).
    pub clusters_back_facing: u32,
}

/// The vertex-stage settings of a frame: camera, viewport, clipping, culling
/// and lighting. `S` is the subpixel precision of the output.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use microraster::math::{Vec3, transform};
/// use microraster::{light::Lighting, pipeline::Pipeline, view3d::CUBE};
/// let eye = transform::look_at(Vec3::new(0.0, 2.0, 5.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
/// let pipeline = Pipeline::<f32, 4>::perspective(eye, 0.9, 0.5, 50.0, 240, 240)?
///     .with_lighting(Lighting::new(0.2, Vec3::new(0.0, 0.5, 1.0), 0.8));
/// let mut bins = microraster::heapless::Vec::<_, 16>::new();
/// let stats = pipeline.draw_valid_mesh(&CUBE, &transform::rotation_y(0.5), Rgb565::RED, &mut bins)?;
/// // Three faces of the cube seen from above and in front, two triangles each.
/// assert_eq!((stats.emitted, bins.len()), (6, 6));
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pipeline<T: Scalar, const S: u32> {
    view: Mat4<T>,
    projection: Mat4<T>,
    w_ref: T,
    origin: (i64, i64),
    size: (u32, u32),
    /// Clip planes (default: a guard band that keeps every triangle in the
    /// rasterizer's `i32` fast path, [`ClipPlanes::for_viewport_fast_path`]).
    pub clip: ClipPlanes,
    /// Which screen winding to drop. Front faces (counter-clockwise seen from
    /// outside) still run counter-clockwise as seen on screen, so back faces
    /// are the clockwise ones: the default is [`Cull::Clockwise`].
    pub cull: Cull,
    /// Lighting; `None` shows material colours unlit. The vertex stage
    /// checks it ([`Lighting::validate`]) before each mesh. A lighting result
    /// that overflows `f32` is clamped: +infinity to full intensity (as `Fx`
    /// saturates), NaN to channel 0.
    pub lighting: Option<Lighting<T>>,
    /// Flat or Gouraud.
    pub shade: Shade,
    /// Keep only triangles that touch these frame rows (inclusive); `None`
    /// keeps all. Set per band when the vertex stage runs once per band
    /// (in a [`Direct3d`](crate::render::Direct3d) pass, to
    /// [`Band3d::rows`](crate::render::Band3d::rows))
    /// so the bins only need to hold one band's triangles.
    pub rows: Option<(i32, i32)>,
    /// Whether snapped vertices get their `1/w` (only perspective-correct
    /// interpolation reads it); false leaves it at 1. Cleared only where
    /// the consumer is known to be affine (meshlets drawn into an
    /// [`Affine`](crate::raster3d::Affine) band): one exact division per
    /// vertex saved.
    with_inv_w: bool,
    /// The accuracy tier ([`Precision::Exact`] unless told).
    pub precision: Precision,
}

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// A pipeline with the given view and projection matrices and a viewport
    /// of `width × height` pixels at the frame's origin. `w_ref` is a clip `w`
    /// that no visible vertex goes below (the near distance for a perspective
    /// projection, 1 for orthographic); it scales the `1/w` values passed to
    /// perspective-correct interpolation.
    ///
    /// Errors: [`Error::InvalidFrameSize`] for a zero or too large viewport,
    /// [`Error::InvalidParameter`] for `w_ref ≤ 0`,
    /// [`Error::NonFiniteCoordinate`] for a NaN or infinite matrix entry.
    pub fn new(view: Mat4<T>, projection: Mat4<T>, w_ref: T, width: u32, height: u32) -> Result<Self, Error> {
        if width == 0 || height == 0 || width > MAX_FRAME_DIM || height > MAX_FRAME_DIM {
            return Err(Error::InvalidFrameSize);
        }
        if !w_ref.is_finite() || w_ref <= T::ZERO {
            return Err(Error::InvalidParameter(crate::Param::WRef));
        }
        if !view.cols.iter().chain(projection.cols.iter()).flatten().all(|v| v.is_finite()) {
            return Err(Error::NonFiniteCoordinate);
        }
        Ok(Pipeline {
            view,
            projection,
            w_ref,
            origin: (0, 0),
            size: (width, height),
            clip: ClipPlanes::for_viewport_fast_path(width, height, S),
            cull: Cull::Clockwise,
            lighting: None,
            shade: Shade::Gouraud,
            rows: None,
            with_inv_w: true,
            precision: Precision::Exact,
        })
    }

    /// A perspective camera: `view` (for example from
    /// [`transform::look_at`]), vertical field of view `fov_y` in radians and
    /// near/far distances, with the aspect ratio of the viewport.
    ///
    /// Errors: [`Error::NonFiniteCoordinate`] for a NaN or infinite
    /// `fov_y`, `near` or `far`; then [`Error::InvalidFrameSize`] for a zero
    /// or too large viewport; then those of [`transform::perspective`] and
    /// [`Pipeline::new`].
    pub fn perspective(
        view: Mat4<T>,
        fov_y: T,
        near: T,
        far: T,
        width: u32,
        height: u32,
    ) -> Result<Self, Error> {
        // Non-finite input first (as `transform::perspective`), then the
        // viewport as in `Pipeline::new` (a zero size would otherwise give a
        // zero or infinite aspect ratio and `InvalidParameter`).
        if ![fov_y, near, far].iter().all(|v| v.is_finite()) {
            return Err(Error::NonFiniteCoordinate);
        }
        if width == 0 || height == 0 || width > MAX_FRAME_DIM || height > MAX_FRAME_DIM {
            return Err(Error::InvalidFrameSize);
        }
        let aspect = T::from_f32(width as f32 / height as f32);
        let projection = transform::perspective(fov_y, aspect, near, far)?;
        Self::new(view, projection, near, width, height)
    }

    /// The same pipeline with the viewport's top-left corner at pixel `(x, y)`
    /// of the frame, confined to the viewport ([`Pipeline::confined`]).
    /// Coordinates are clamped to `±MAX_FRAME_DIM` (a viewport may hang off
    /// the frame's edges; what lies outside the frame is never drawn).
    pub fn with_origin(self, x: i32, y: i32) -> Self {
        let c = |v: i32| v.clamp(-(MAX_FRAME_DIM as i32), MAX_FRAME_DIM as i32) as i64;
        Pipeline { origin: (c(x), c(y)), ..self }.confined()
    }

    /// The same pipeline clipping x and y exactly at the viewport's edges
    /// (guard band 1) instead of at the guard band, so nothing is drawn
    /// outside a viewport smaller than the frame. More triangles are clipped;
    /// the rasterizer's scissor to the frame makes this unnecessary when the
    /// viewport is the whole frame (the default).
    pub fn confined(self) -> Self {
        Pipeline { clip: self.clip.with_guard_band(1.0), ..self }
    }

    /// The same pipeline with lighting. Vertices are lit with
    /// [`Lighting::shade`]'s formula; where the model-view matrix is a
    /// rotation times a uniform scale it is evaluated in model space (fewer
    /// operations per vertex, the same values up to rounding: within about
    /// `2^-15` of full intensity in `f32`, see the README's "Lighting").
    pub fn with_lighting(self, lighting: Lighting<T>) -> Self {
        Pipeline { lighting: Some(lighting), ..self }
    }

    /// The same pipeline in accuracy tier `precision`.
    pub fn with_precision(self, precision: Precision) -> Self {
        Pipeline { precision, ..self }
    }

    /// The view matrix.
    pub fn view(&self) -> Mat4<T> {
        self.view
    }
}
