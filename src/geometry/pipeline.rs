//! The vertex stage: meshes in, screen-space triangles out.
//!
//! For each mesh: view-volume culling of the whole mesh by its bounding
//! sphere (before any vertex work); per triangle the model-view-projection
//! transform, lighting (flat per face or Gouraud per vertex), homogeneous
//! clipping ([`crate::clip3d`]: near, far and a guard band, so only `w > 0`
//! reaches the divide), the perspective divide and viewport transform straight
//! into snapped [`SubPoint`](crate::SubPoint)s, and back-face culling from the signed area
//! *after* snapping, so culling and coverage always agree (as in D3D11).
//! The result goes into a caller-owned `heapless::Vec` of [`ScreenTriangle`]s
//! (the frame's bins), which [`Triangles3d`](crate::render::Triangles3d)
//! draws band by band.
//!
//! `T` is the numeric path: `f32` (FPU parts) or [`Fx`](crate::math::Fx)
//! (16.16 fixed point, parts without an FPU).

mod band;
mod bins;
mod cache;
mod chunked;
mod cluster;
mod eager;
mod frame_clusters;
mod inside;
mod material;
mod mesh_setup;
mod model_light;
mod presnap;
mod snap;
mod sphere_rows;
#[cfg(feature = "fragment")]
mod varying;
mod vertex_ctx;

use band::Band;
use mesh_setup::{row_f32, rows_f32, view_planes};
use vertex_ctx::{MeshSetup, VertexCtx, channels, finite_color};

pub use cache::VertexCache;
pub use cluster::ClusterCache;
pub use frame_clusters::{FRAME_CLUSTERS, FRAME_MESHES};
pub(crate) use material::{Material, PerFace, PerVertex, Uniform};

#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub use varying::VertexInput;

use crate::clip3d::{Class, ClipPlanes, ClipVertex, classify, clip_triangle};
use crate::edge::Cull;
use crate::light::Lighting;
use crate::math::{Mat4, Scalar, Vec3, transform};
use crate::mesh::{Mesh, ValidMesh};
use crate::raster3d::{ScreenTriangle, ScreenVertex};
use crate::{Error, Interpolate, MAX_FRAME_DIM};

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
    /// ([`PerBand3d`](crate::render::PerBand3d))
    /// so the bins only need to hold one band's triangles.
    pub rows: Option<(i32, i32)>,
    /// Whether snapped vertices get their `1/w` (only perspective-correct
    /// interpolation reads it); false leaves it at 1. Cleared only where
    /// the consumer is known to be affine (meshlets drawn into an
    /// [`Affine`](crate::raster3d::Affine) band): one exact division per
    /// vertex saved.
    with_inv_w: bool,
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
            return Err(Error::InvalidParameter);
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

    /// The view matrix.
    pub fn view(&self) -> Mat4<T> {
        self.view
    }

    /// Transforms, lights, clips, snaps and culls `mesh` placed by `model`,
    /// with material colour `color`, appending the visible triangles to `bins`.
    ///
    /// Errors: the errors of [`Mesh::validate`] (out-of-range index, normals
    /// that do not match, a bounding sphere that does not contain the mesh,
    /// non-finite data), then those of [`Pipeline::draw_valid_mesh`].
    pub fn draw_mesh<C: Interpolate, const N: usize>(
        &self,
        mesh: &Mesh<'_>,
        model: &Mat4<T>,
        color: C,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<MeshStats, Error> {
        // A bad mesh is an error, never a silent cull or an out-of-range index.
        self.draw_valid_mesh(&ValidMesh::new(*mesh)?, model, color, bins)
    }

    /// [`Pipeline::draw_mesh`] for a mesh checked once beforehand
    /// ([`ValidMesh`], possibly at compile time): the same result without the
    /// O(vertices) check on every call (every band, when the vertex stage
    /// runs per band).
    ///
    /// Errors: [`Error::CapacityExceeded`] if `bins` fills up, with the
    /// length it needed (the mesh's triangles are counted to the end, and
    /// `bins` is left as it was: on any error no triangle of the mesh is
    /// kept); [`Error::InvalidParameter`] if `model` is singular;
    /// the errors of [`Lighting::validate`] for the pipeline's lighting; and
    /// for [`Fx`](crate::math::Fx) only, [`Error::CoordinateOutOfRange`] if
    /// `view · model` or `projection · view · model` saturates 16.16, or if
    /// the mesh is not culled whole and one of its model, eye or clip
    /// coordinates (or a partial sum of one) reaches ±32767: 16.16 cannot
    /// hold it, and a saturated coordinate would change what is drawn.
    pub fn draw_valid_mesh<C: Interpolate, const N: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<MeshStats, Error> {
        let mut bins = bins::BinWriter::new(bins);
        let result = self.valid_mesh_into(mesh, model, color, &Uniform, |tri| {
            bins.push(tri);
            Ok(())
        });
        bins.finish(result)
    }

    /// [`Pipeline::draw_valid_mesh`] handing each triangle to `sink` instead
    /// of a bin, in the same order (the binned path is this with a
    /// [`bins::BinWriter`]): with [`Pipeline::rows`] set to a band's rows, the
    /// vertex stage draws straight into that band, no bins (the `view3d`
    /// front). `material` gives each vertex its material colour
    /// ([`Uniform`]: `color`). Errors: those of
    /// [`Pipeline::draw_valid_mesh`], with `sink`'s in place of a full bin.
    pub(crate) fn valid_mesh_into<C: Interpolate, M: Material<T>>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        material: &M,
        mut sink: impl FnMut(ScreenTriangle<S>) -> Result<(), Error>,
    ) -> Result<MeshStats, Error> {
        let mesh = mesh.mesh();
        let mut stats = MeshStats::default();
        let Some(MeshSetup { ctx, planes, band, max }) = self.mesh_setup(mesh, model, color, &mut stats)?
        else {
            return Ok(stats);
        };

        let flat = self.shade == Shade::Flat || mesh.normals.is_empty();
        for (i, idx) in mesh.indices.iter().enumerate() {
            let Some((pos, clip, class)) = triangle_in_view(mesh, i, &ctx, &band, planes)? else { continue };
            // Colours are computed only for triangles that survive culling.
            let face_n = if flat { mesh.face_normal(i) } else { None };
            let colors = || -> [[T; 3]; 3] {
                let c = |k: usize| {
                    let n = if flat { face_n } else { mesh.normals.get(idx[k] as usize).copied() };
                    if M::UNIFORM {
                        ctx.color(pos[k], n)
                    } else {
                        ctx.color_of(pos[k], n, material.base(ctx.base, i, usize::from(idx[k])))
                    }
                };
                // Flat: one lit colour per face, vertex 0 lit with the face normal.
                if self.shade == Shade::Flat { [c(0); 3] } else { [c(0), c(1), c(2)] }
            };
            if class == Class::Inside {
                if let Some(at) = self.snapped_and_kept(clip, &mut stats) {
                    self.emit(at, colors(), max, &mut sink, &mut stats)?;
                }
                continue;
            }
            let cs = colors();
            let v = [0, 1, 2].map(|k| ClipVertex { pos: clip[k], attr: cs[k] });
            self.clip_and_emit(v, planes, &mut stats, |at, attr, stats| {
                self.emit(at, attr, max, &mut sink, stats)
            })?;
        }
        Ok(stats)
    }

    /// [`Pipeline::draw_valid_mesh`] with a vertex cache: each mesh vertex
    /// is transformed, classified, snapped and lit at most once instead of
    /// once per triangle corner (about six times). Bit-identical output.
    ///
    /// A cache with fewer entries than the mesh has vertices works too: the
    /// triangles are then taken in their order in chunks of at most
    /// `min(V, 64)` vertices, and a vertex is computed once per chunk that
    /// uses it. The same output again, with RAM that does not grow with
    /// the mesh (a 64-entry cache, `VertexCache<T, S, 64>`, is 3,072 bytes
    /// for `f32` and [`Fx`](crate::math::Fx)).
    ///
    /// Errors: those of [`Pipeline::draw_valid_mesh`], and first
    /// [`Error::CapacityExceeded`] with `needed` 3 if `V < 3` and the mesh
    /// has more than `V` vertices (nothing done).
    pub fn draw_valid_mesh_cached<C: Interpolate, const V: usize, const N: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        cache: &mut VertexCache<T, S, V>,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<MeshStats, Error> {
        let mesh = mesh.mesh();
        let whole = mesh.vertex_count() <= V;
        if !whole && V < 3 {
            return Err(Error::CapacityExceeded { needed: 3, capacity: V });
        }
        let mut bins = bins::BinWriter::new(bins);
        let mut run = || {
            let mut stats = MeshStats::default();
            let Some(setup) = self.mesh_setup(mesh, model, color, &mut stats)? else {
                return Ok(stats);
            };
            let inside = inside::InsideView::new(&setup.ctx.mvp, setup.planes).contains(mesh.bounding_sphere);
            if !whole {
                self.draw_chunked(&setup, mesh, &mut cache.v, inside, &mut stats, |tri| {
                    bins.push(tri);
                    Ok(())
                })?;
                return Ok(stats);
            }
            let cache = &mut cache.v[..mesh.vertex_count()];
            let triangles = mesh.indices.iter().map(|t| t.map(usize::from));
            let cached = cache::Slots { slots: cache, inside };
            self.draw_cached(&setup, mesh, &Uniform, cached, triangles, &mut stats, |tri, _| {
                bins.push(tri);
                Ok(())
            })?;
            Ok(stats)
        };
        let result = run();
        bins.finish(result)
    }

    /// Clips a triangle that crosses a plane and hands each piece that
    /// survives snapping and culling to `emit`, with its interpolated
    /// attributes (all counted in `stats`).
    fn clip_and_emit<const A: usize>(
        &self,
        v: [ClipVertex<T, A>; 3],
        planes: ClipPlanes,
        stats: &mut MeshStats,
        mut emit: impl FnMut([ScreenVertex<S>; 3], [[T; A]; 3], &mut MeshStats) -> Result<(), Error>,
    ) -> Result<(), Error> {
        stats.clipped += 1;
        for tri in clip_triangle(v, planes).triangles() {
            if let Some(at) = self.snapped_and_kept(tri.map(|v| v.pos), stats) {
                emit(at, tri.map(|v| v.attr), stats)?;
            }
        }
        Ok(())
    }

    /// Colours the vertices and hands the triangle to `sink` (counted in
    /// `stats.emitted` once the sink takes it; a [`bins::BinWriter`] takes
    /// every triangle, counting those that do not fit).
    fn emit(
        &self,
        mut v: [ScreenVertex<S>; 3],
        colors: [[T; 3]; 3],
        max: [u8; 3],
        sink: &mut impl FnMut(ScreenTriangle<S>) -> Result<(), Error>,
        stats: &mut MeshStats,
    ) -> Result<(), Error> {
        for (v, c) in v.iter_mut().zip(colors) {
            v.color = channels(c, max);
        }
        sink(ScreenTriangle { v, flat: self.shade == Shade::Flat })?;
        stats.emitted += 1;
        Ok(())
    }
}

/// Triangle `i` of `mesh` in clip space and its class against `planes`;
/// `None` when it lies outside the band ([`Pipeline::rows`]) or the view
/// volume. Clip y and w come first: with `rows` set most triangles lie
/// outside the band and need nothing else.
#[allow(clippy::type_complexity)]
fn triangle_in_view<T: Scalar>(
    mesh: &Mesh<'_>,
    i: usize,
    ctx: &VertexCtx<T>,
    band: &Band<T>,
    planes: ClipPlanes,
) -> Result<Option<([Vec3<T>; 3], [[T; 4]; 3], Class)>, Error> {
    let pos = mesh.triangle(i).ok_or(Error::InvalidMesh)?.map(Vec3::from_f32);
    let yw = pos.map(|p| ctx.yw(p));
    if band.excludes(yw) {
        return Ok(None);
    }
    let clip = [0, 1, 2].map(|k| ctx.position(pos[k], yw[k]));
    let class = classify(clip, planes);
    Ok((class != Class::Outside).then_some((pos, clip, class)))
}
