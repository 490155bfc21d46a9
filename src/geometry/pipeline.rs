//! The vertex stage: meshes in, screen-space triangles out.
//!
//! For each mesh: view-volume culling of the whole mesh by its bounding
//! sphere (before any vertex work); per triangle the model-view-projection
//! transform, lighting (flat per face or Gouraud per vertex), homogeneous
//! clipping ([`crate::clip3d`]: near, far and a guard band, so only `w > 0`
//! reaches the divide), the perspective divide and viewport transform straight
//! into snapped [`SubPoint`]s, and back-face culling from the signed area
//! *after* snapping, so culling and coverage always agree (as in D3D11).
//! The result goes into a caller-owned `heapless::Vec` of [`ScreenTriangle`]s
//! (the frame's bins), which [`Triangles3d`](crate::render::Triangles3d)
//! draws band by band.
//!
//! `T` is the numeric path: `f32` (FPU parts) or [`Fx`](crate::math::Fx)
//! (16.16 fixed point, parts without an FPU).

mod bins;
mod cache;
mod chunked;
mod cluster;
mod eager;
mod frame_clusters;
mod inside;
mod material;
mod model_light;
mod presnap;
mod sphere_rows;
#[cfg(feature = "fragment")]
mod varying;

use model_light::ModelLight;

pub use cache::VertexCache;
pub use cluster::ClusterCache;
pub use frame_clusters::{FRAME_CLUSTERS, FRAME_MESHES};
pub(crate) use material::{Material, PerFace, PerVertex, Uniform};

#[cfg(feature = "fragment")]
#[cfg_attr(docsrs, doc(cfg(feature = "fragment")))]
pub use varying::VertexInput;

use crate::clip3d::{Class, ClipPlanes, ClipVertex, classify, clip_triangle, guard_band_for_range};
use crate::edge::Cull;
use crate::light::Lighting;
use crate::math::{Mat3, Mat4, Scalar, Vec3, Vec4, transform};
use crate::mesh::{Mesh, ValidMesh};
use crate::primitive::center_rows;
use crate::raster3d::{ScreenTriangle, ScreenVertex};
use crate::{Error, Interpolate, MAX_FRAME_DIM, SubPoint};

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

    /// Snapped positions of a triangle inside the clip volume, if it passes
    /// [`Pipeline::keep`]; a triangle that cannot be snapped counts as
    /// degenerate.
    fn snapped_and_kept(&self, clip: [[T; 4]; 3], stats: &mut MeshStats) -> Option<[ScreenVertex<S>; 3]> {
        let Some(at) = self.snap_positions(clip) else {
            stats.degenerate += 1;
            return None;
        };
        self.keep(at.map(|v| v.pos), stats).then_some(at)
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

    /// The per-mesh part of the vertex stage: the matrices, the whole-mesh
    /// culls (view volume, then [`Pipeline::rows`]) and the clip planes;
    /// `None` when the mesh is culled (counted in `stats`).
    fn mesh_setup<C: Interpolate>(
        &self,
        mesh: &Mesh<'_>,
        model: &Mat4<T>,
        color: C,
        stats: &mut MeshStats,
    ) -> Result<Option<MeshSetup<T>>, Error> {
        if let Some(l) = &self.lighting {
            l.validate()?;
        }
        let fx = !crate::math::vec::is_float::<T>();
        // Fx: a matrix product that saturates changes what is drawn.
        if fx
            && !(fx_product_fits(&self.view, model)
                && fx_product_fits(&self.projection, &(self.view * *model)))
        {
            return Err(Error::CoordinateOutOfRange);
        }
        let model_view = self.view * *model;
        let mvp = self.projection * model_view;
        let band = self.band_bounds();
        if !self.sphere_visible(&mvp, mesh.bounding_sphere) {
            stats.mesh_culled = true;
            return Ok(None);
        }
        // Fx: a visible mesh whose coordinates 16.16 cannot hold is an error
        // (checked before the band test, so every band agrees).
        if fx && !fx_coordinates_fit(mesh, &model_view, &mvp) {
            return Err(Error::CoordinateOutOfRange);
        }
        if !band.sphere_touches(&mvp, mesh.bounding_sphere) {
            return Ok(None);
        }
        let normal_matrix = model_view.normal_matrix().ok_or(Error::InvalidParameter)?;
        // A guard band beyond what snapping can represent would drop visible
        // triangles; clamp it (the `clip` field is public).
        let range = guard_band_for_range(self.size.0, self.size.1, S);
        let planes = self.clip.with_guard_band(self.clip.guard_band().min(range));
        let max = C::CHANNEL_MAX;
        let base = material::base_of(color);
        let model_light = match &self.lighting {
            Some(l) => ModelLight::new(l, &model_view),
            _ => None,
        };
        let ctx =
            VertexCtx { mv: model_view, mvp, nm: normal_matrix, base, lighting: self.lighting, model_light };
        Ok(Some(MeshSetup { ctx, planes, band, max }))
    }

    /// False if the sphere lies entirely outside one plane of the view volume.
    ///
    /// Evaluated in `f32` on both paths (bit-identical for `f32`): in `Fx`
    /// the plane values of a large sphere saturate and would cull a visible
    /// mesh (one `f32` test per mesh, a few soft-float operations on parts
    /// without an FPU).
    fn sphere_visible(&self, mvp: &Mat4<T>, (c, r): ([f32; 3], f32)) -> bool {
        let planes = view_planes(rows_f32(mvp), self.clip.far());
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        planes.iter().all(|p| p.dot(centre) >= -(r * p.xyz().length()))
    }

    /// The clip-space test of [`Pipeline::rows`] ([`Band`]).
    fn band_bounds(&self) -> Band<T> {
        let Some((y0, y1)) = self.rows else { return Band::all() };
        let (h, oy) = (self.size.1 as f32, self.origin.1);
        // Pixel row `r` lies at NDC y = 1 − 2·(r − oy)/h (y flipped). The
        // bounds are used only where they are small, so their Fx rounding
        // (2^-17) stays far below the margin.
        let k = |row: i64| {
            let k = 1.0 - 2.0 * ((row - oy) as f32) / h;
            if k.abs() <= 4.0 { Some(T::from_f32(k)) } else { None }
        };
        Band::new(k(y0 as i64 - 1), k(y1 as i64 + 2), T::from_f32(0.125))
    }

    /// Clip space to snapped screen positions, depth and `1/w` (colour left
    /// 0); `None` if a coordinate is out of the rasterizer's range (the guard
    /// band prevents this) or not finite.
    fn snap_positions(&self, clip: [[T; 4]; 3]) -> Option<[ScreenVertex<S>; 3]> {
        let mut out = [ScreenVertex::default(); 3];
        for (o, c) in out.iter_mut().zip(clip) {
            *o = self.snap_vertex(c)?;
        }
        Some(out)
    }

    /// One vertex of [`Pipeline::snap_positions`].
    /// `w` is prepared once for the four quotients ([`Scalar::divisor`]:
    /// for [`Fx`](crate::math::Fx) one reciprocal, each quotient still exact).
    fn snap_vertex(&self, c: [T; 4]) -> Option<ScreenVertex<S>> {
        let w = c[3].divisor()?;
        let (depth, inv_w) = self.snap_depth(c, w)?;
        Some(ScreenVertex { pos: self.snap_xy(c, w)?, depth, inv_w, color: [0; 3] })
    }

    /// The snapped position of [`Pipeline::snap_vertex`] (all that culling
    /// needs).
    #[inline]
    fn snap_xy(&self, [x, y, _, _]: [T; 4], w: T::Divisor) -> Option<SubPoint<S>> {
        let px = self.ndc_to_sub(x, w, self.size.0, self.origin.0, false)?;
        let py = self.ndc_to_sub(y, w, self.size.1, self.origin.1, true)?;
        SubPoint::new(i32::try_from(px).ok()?, i32::try_from(py).ok()?).ok()
    }

    /// The depth and `1/w` of [`Pipeline::snap_vertex`].
    #[inline]
    fn snap_depth(&self, [_, _, z, _]: [T; 4], w: T::Divisor) -> Option<(u32, u32)> {
        Some((
            z.div_scaled_by(w, u32::MAX as i64)?.clamp(0, u32::MAX as i64) as u32,
            // Only ratios of 1/w matter; a vertex nearer than w_ref/4 (which
            // the w_ref contract excludes) saturates rather than vanishing.
            if self.with_inv_w {
                self.w_ref.div_scaled_by(w, 1 << 30).unwrap_or(i64::MAX).clamp(1, u32::MAX as i64) as u32
            } else {
                1
            },
        ))
    }

    /// The snapped-area tests on a triangle's snapped positions: zero area
    /// and back faces are dropped (and counted), as are triangles outside
    /// [`Pipeline::rows`]. In 32-bit differences (`|coordinate| ≤ 2^28`, so
    /// they cannot overflow) and 64-bit products; the rows as
    /// [`ScreenTriangle::rows`] computes them.
    #[inline]
    fn keep(&self, p: [SubPoint<S>; 3], stats: &mut MeshStats) -> bool {
        let (e1x, e1y) = (p[1].x() - p[0].x(), p[1].y() - p[0].y());
        let (e2x, e2y) = (p[2].x() - p[0].x(), p[2].y() - p[0].y());
        let det = signed_area2(e1x, e1y, e2x, e2y);
        if det == 0 {
            stats.degenerate += 1;
            return false;
        }
        let culled = match self.cull {
            Cull::None => false,
            Cull::Clockwise => det > 0,
            Cull::CounterClockwise => det < 0,
        };
        if culled {
            stats.back_faces += 1;
            return false;
        }
        let (y0, y1, y2) = (p[0].y(), p[1].y(), p[2].y());
        let (lo, hi) = center_rows::<S>(y0.min(y1).min(y2), y0.max(y1).max(y2));
        self.rows.is_none_or(|(r0, r1)| lo <= r1 && hi >= r0)
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

    /// `origin + (1 ± ndc)·size/2` in subpixels, `ndc = c/w` (y flipped).
    fn ndc_to_sub(&self, c: T, w: T::Divisor, size: u32, origin: i64, flip: bool) -> Option<i64> {
        let full = (size as i64) << S; // viewport extent in subpixels
        let c = if flip { -c } else { c };
        // Halve exactly when possible; only S = 0 with an odd size rounds twice.
        let t =
            if full % 2 == 0 { c.div_scaled_by(w, full / 2)? } else { (c.div_scaled_by(w, full)? + 1) >> 1 };
        Some((origin << S) + full / 2 + t)
    }
}

/// Row `i` of `m` in `f32` (exact for `f32`; `Fx` rounds to 24 bits).
fn row_f32<T: Scalar>(m: &Mat4<T>, i: usize) -> Vec4<f32> {
    let c = &m.cols;
    Vec4::new(c[0][i].to_f32(), c[1][i].to_f32(), c[2][i].to_f32(), c[3][i].to_f32())
}

/// The four rows `x, y, z, w` of `m` in `f32` ([`row_f32`]).
fn rows_f32<T: Scalar>(m: &Mat4<T>) -> [Vec4<f32>; 4] {
    [0, 1, 2, 3].map(|i| row_f32(m, i))
}

/// The view-volume planes from the rows of a model-view-projection matrix,
/// `p · (x, 1) ≥ 0` inside: left, right, bottom, top, near, and far (near
/// again when there is no far plane). Also of the rows' values at a point
/// (`f32`): then the planes' values there.
fn view_planes<V: Copy + core::ops::Add<Output = V> + core::ops::Sub<Output = V>>(
    [x, y, z, w]: [V; 4],
    far: bool,
) -> [V; 6] {
    [w + x, w - x, w + y, w - y, z, if far { w - z } else { z }]
}

/// The largest magnitude an `Fx` sum of products may reach without
/// saturating (2^15 less one unit: a margin for the `f32` bound's rounding).
const FX_LIMIT: f32 = 32767.0;

/// `Fx`: true if no partial sum of `a · b` can saturate (`Σ|a_ik·b_kj|`
/// within [`FX_LIMIT`] for every entry, in `f32`), and no entry of `a` or
/// `b` is itself saturated.
fn fx_product_fits<T: Scalar>(a: &Mat4<T>, b: &Mat4<T>) -> bool {
    // Quick accept, in `T` (integer compares for `Fx`): every partial sum is
    // at most 4·max|a|·max|b| (ordinary matrices: entries below ~90).
    let max =
        |m: &Mat4<T>| m.cols.iter().flatten().fold(T::ZERO, |m, &v| if v.abs() > m { v.abs() } else { m });
    if 4.0 * max(a).to_f32() * max(b).to_f32() < FX_LIMIT {
        return true;
    }
    let (a, b) = (a.to_f32(), b.to_f32());
    let ok = |v: f32| v.abs() < FX_LIMIT;
    if !a.iter().chain(&b).flatten().all(|&v| ok(v)) {
        return false;
    }
    // Entry (r, c) = Σ_k a[k][r]·b[c][k] (column-major).
    (0..4).all(|r| (0..4).all(|c| ok((0..4).map(|k| (a[k][r] * b[c][k]).abs()).sum::<f32>())))
}

/// `e1x·e2y − e2x·e1y` exactly, for differences of snapped coordinates
/// (`|e| ≤ 2^29`). On the Cortex-M0, where a 64-bit product is a library
/// call, in 32 bits when every difference is below 2^15 (products below
/// 2^30, their difference below 2^31): a small triangle's, most of a mesh's.
#[inline(always)]
fn signed_area2(e1x: i32, e1y: i32, e2x: i32, e2y: i32) -> i64 {
    if crate::math::divisor::ARMV6M {
        if let Some(det) = signed_area2_small(e1x, e1y, e2x, e2y) {
            return det;
        }
    }
    i64::from(e1x) * i64::from(e2y) - i64::from(e2x) * i64::from(e1y)
}

/// [`signed_area2`] in 32 bits where every difference is below 2^15
/// (tested on every target).
#[inline(always)]
fn signed_area2_small(e1x: i32, e1y: i32, e2x: i32, e2y: i32) -> Option<i64> {
    let small = |v: i32| v.unsigned_abs() < 1 << 15;
    (small(e1x) && small(e1y) && small(e2x) && small(e2y)).then(|| i64::from(e1x * e2y - e2x * e1y))
}

/// `Fx`: true if every model, eye and clip coordinate of the mesh fits
/// 16.16 without saturating any partial sum of
/// `row · (p, 1)`. A bound over the bounding sphere decides at once for
/// nearly every mesh; only a mesh whose sphere reaches beyond the range has
/// the vertices of its triangles checked one by one.
fn fx_coordinates_fit<T: Scalar>(mesh: &Mesh<'_>, mv: &Mat4<T>, mvp: &Mat4<T>) -> bool {
    let (mv, mvp) = (mv.to_f32(), mvp.to_f32());
    // `Σ_i |m_ri|·e_i + |m_r3|` for each row of both matrices, where `e`
    // bounds `|p_i|`; every partial sum of the row's `Fx` evaluation is at
    // most this.
    let fits = |e: [f32; 3]| {
        e.iter().all(|&v| v < FX_LIMIT)
            && [&mv, &mvp].iter().all(|m| {
                (0..4).all(|r| (0..3).map(|i| m[i][r].abs() * e[i]).sum::<f32>() + m[3][r].abs() < FX_LIMIT)
            })
    };
    let (c, radius) = mesh.bounding_sphere;
    // The sphere contains the mesh up to `SPHERE_TOLERANCE` (validated).
    let r = radius * (1.0 + 2.0 * crate::mesh::SPHERE_TOLERANCE);
    // Otherwise the vertices that triangles use (an unused vertex is never
    // transformed for drawing).
    // A meshlet mesh keeps its triangles in its clusters (no `indices`):
    // then every vertex counts.
    let fits_at = |p: &[f32; 3]| fits(p.map(f32::abs));
    fits(c.map(|c| c.abs() + r))
        || if mesh.indices.is_empty() {
            mesh.positions.iter().all(fits_at)
        } else {
            mesh.indices.iter().flatten().all(|&i| mesh.positions.get(usize::from(i)).is_none_or(fits_at))
        }
}

/// Colour channels from intensities.
fn channels<T: Scalar>(c: [T; 3], max: [u8; 3]) -> [u8; 3] {
    [0, 1, 2].map(|k| c[k].to_channel(max[k]))
}

/// The rows of [`Pipeline::rows`] as a division-free test in clip space,
/// with a margin of a pixel above and two below the band (so the snapping
/// of the exact test cannot disagree).
///
/// A vertex with `w > 0` lies above pixel row `y0 − 1` when `y > above·w`
/// and below row `y1 + 2` when `y < below·w`. A triangle is dropped early
/// only if all three vertices have `w ≥ w_min` (1/8) and all lie on the same
/// side. Error: `above`/`below` are within 2^-17 of the exact NDC bound
/// (Fx rounding; f32 within 2^-21) and `k·w` is within 2^-16 (Fx truncation;
/// f32 relative 2^-24), so the test is off by at most `2^-17 + 2^-16/w ≤
/// 2^-12.9` in NDC, that is below 0.06 px for any viewport height up to
/// [`MAX_FRAME_DIM`], against a margin of a pixel; the snapped position
/// rounds by at most half a subpixel. So a triangle dropped here has no row
/// in the band, exactly as the test after snapping would find. (With `y`
/// and `w` as evaluated: clipping only moves vertices along the triangle, a
/// convex combination that stays on the same side.)
#[derive(Clone, Copy)]
struct Band<T> {
    above: Option<T>,
    below: Option<T>,
    w_min: T,
    /// `above` and `below` as `f32` bounds that a missing side turns into
    /// ±∞, which no `y` passes (not read for `Fx`, which has no infinity).
    bounds: (T, T),
}

impl<T: Scalar> Band<T> {
    /// No band: every triangle passes.
    fn all() -> Self {
        Band::new(None, None, T::ZERO)
    }

    fn new(above: Option<T>, below: Option<T>, w_min: T) -> Self {
        let bounds =
            (above.unwrap_or(T::from_f32(f32::INFINITY)), below.unwrap_or(T::from_f32(f32::NEG_INFINITY)));
        Band { above, below, w_min, bounds }
    }

    /// [`Band::excludes`] per vertex: `ABOVE` or `BELOW` if the vertex has
    /// `w ≥ w_min` and lies on that side; a triangle whose three vertices
    /// share a bit is excluded.
    const ABOVE: u8 = 1 << 6;
    const BELOW: u8 = 1 << 7;

    #[inline]
    fn side(&self, (y, w): (T, T)) -> u8 {
        if w < self.w_min {
            return 0;
        }
        let (above, below) = if crate::math::vec::is_float::<T>() {
            // With `w ≥ w_min ≥ 0`, ±∞·w is ±∞, or NaN where `w` is 0 or
            // NaN: no `y` passes either, so a missing side needs no branch
            // (the `y`/`w` pass runs this for every vertex of every cluster
            // visit; tested against the `Option` form).
            (y > self.bounds.0 * w, y < self.bounds.1 * w)
        } else {
            (self.above.is_some_and(|k| y > k * w), self.below.is_some_and(|k| y < k * w))
        };
        (if above { Self::ABOVE } else { 0 }) | (if below { Self::BELOW } else { 0 })
    }

    /// True if the triangle (clip `(y, w)` of its vertices) is certainly
    /// outside the band.
    #[inline]
    fn excludes(&self, yw: [(T, T); 3]) -> bool {
        if self.above.is_none() && self.below.is_none() {
            return false;
        }
        if !yw.iter().all(|&(_, w)| w >= self.w_min) {
            return false;
        }
        let above = self.above.is_some_and(|k| yw.iter().all(|&(y, w)| y > k * w));
        above || self.below.is_some_and(|k| yw.iter().all(|&(y, w)| y < k * w))
    }

    /// False if the mesh's bounding sphere lies entirely above or below the
    /// band (planes `above·w − y ≥ 0` and `y − below·w ≥ 0`), with a slack of
    /// `2^-8·(1 + r·|plane|)` in clip units for the rounding of the test.
    ///
    /// Evaluated in `f32` on both paths (bit-identical for `f32`): in `Fx`
    /// `plane · centre` and `r·|plane|` both saturate for a large sphere
    /// (a far vertex, a narrow field of view), and the saturated test
    /// rejected visible meshes (issue 13). `f32` rounding (relative 2^-22
    /// here) is far inside the slack.
    fn sphere_touches(&self, mvp: &Mat4<T>, (c, r): ([f32; 3], f32)) -> bool {
        let (y, w) = (row_f32(mvp, 1), row_f32(mvp, 3));
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        let slack = 1.0f32 / 256.0;
        let outside = |p: Vec4<f32>| {
            let reach = r * p.xyz().length();
            p.dot(centre) < -(reach + reach * slack + slack)
        };
        let k = |k: T| k.to_f32();
        !(self.above.is_some_and(|a| outside(w * k(a) - y))
            || self.below.is_some_and(|b| outside(y - w * k(b))))
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

/// What [`Pipeline::mesh_setup`] prepares for one mesh.
struct MeshSetup<T: Scalar> {
    ctx: VertexCtx<T>,
    planes: ClipPlanes,
    band: Band<T>,
    max: [u8; 3],
}

/// Per-mesh constants of the vertex computation.
struct VertexCtx<T: Scalar> {
    mv: Mat4<T>,
    mvp: Mat4<T>,
    nm: Mat3<T>,
    base: [T; 3],
    lighting: Option<Lighting<T>>,
    /// `lighting` in model space, where it applies (a similarity; module
    /// docs of `model_light`).
    model_light: Option<ModelLight<T>>,
}

impl<T: Scalar> VertexCtx<T> {
    /// Row `r` of `mvp · (p, 1)`, bit-identical to
    /// [`Mat4::transform_point`] (`d·1` is exact). For `Fx` without the
    /// saturation ([`Scalar::row_in_range`]): `mesh_setup` accepts a mesh
    /// only if no partial sum of these rows can saturate
    /// (`fx_coordinates_fit`).
    #[inline]
    fn row(&self, r: usize, p: Vec3<T>) -> T {
        let [a, b, c, d] = &self.mvp.cols;
        T::row_in_range([a[r], b[r], c[r]], [p.x, p.y, p.z], d[r])
    }

    /// Clip `(y, w)` of `p`.
    #[inline]
    fn yw(&self, p: Vec3<T>) -> (T, T) {
        (self.row(1, p), self.row(3, p))
    }

    /// The clip position of `p`, given its [`VertexCtx::yw`].
    #[inline]
    fn position(&self, p: Vec3<T>, (y, w): (T, T)) -> [T; 4] {
        [self.row(0, p), y, self.row(2, p), w]
    }

    /// The lit colour of a vertex. Documented clamp: a lighting result that
    /// overflows `f32` to +infinity (huge finite factors) is full intensity,
    /// as `Fx` saturates; NaN (`0·∞`) and −infinity are channel 0. The
    /// clipper would otherwise take a non-finite value for a reason to
    /// discard the triangle.
    fn color(&self, p: Vec3<T>, normal: Option<[f32; 3]>) -> [T; 3] {
        finite_color(self.lit(p, normal, |ctx: &Self| ctx.base))
    }

    /// [`VertexCtx::color`] of material `base` instead of the mesh's
    /// colour (per-vertex and per-face colours, [`Material`]).
    fn color_of(&self, p: Vec3<T>, normal: Option<[f32; 3]>, base: [T; 3]) -> [T; 3] {
        finite_color(self.lit(p, normal, move |_: &Self| base))
    }

    /// The lit colour of material `base`: a function, so the one-colour
    /// path (`|ctx| ctx.base`, zero-sized) passes no argument; a pointer
    /// argument cost 2 Cortex-M4F instructions per lit vertex.
    fn lit(&self, p: Vec3<T>, normal: Option<[f32; 3]>, base: impl FnOnce(&Self) -> [T; 3]) -> [T; 3] {
        match (self.lighting, normal, &self.model_light) {
            (Some(_), Some(n), Some(m)) => m.shade(n, p, base(self)),
            (Some(l), Some(n), None) => {
                let n_eye = (self.nm * Vec3::from_f32(n)).normalize_fast();
                // mv·(p, 1) without its w (the same sums as transform_point).
                let [a, b, c, d] = &self.mv.cols;
                let p_eye = Vec3::new(
                    a[0] * p.x + b[0] * p.y + c[0] * p.z + d[0],
                    a[1] * p.x + b[1] * p.y + c[1] * p.z + d[1],
                    a[2] * p.x + b[2] * p.y + c[2] * p.z + d[2],
                );
                l.shade(n_eye, p_eye, base(self))
            }
            // No light, or a degenerate face without a normal: ambient only.
            (Some(l), None, _) => base(self).map(|b| b * l.ambient),
            (None, _, _) => base(self),
        }
    }
}

/// The clamp of [`VertexCtx::color`]: +infinity is full intensity, NaN and
/// −infinity channel 0.
#[inline]
fn finite_color<T: Scalar>(c: [T; 3]) -> [T; 3] {
    c.map(|c| {
        if c.is_finite() {
            c
        } else if c > T::ZERO {
            T::ONE
        } else {
            T::ZERO
        }
    })
}

#[cfg(test)]
mod tests {
    use super::Band;

    /// `Band::side` in `f32`, where a missing side is an infinite bound, is
    /// the test of the type's docs (a side that is `None` never holds), at
    /// zero, infinite and NaN `y` and `w` too, for every set of sides.
    #[test]
    fn band_side_with_infinite_bounds_is_the_option_test() {
        let reference = |b: &Band<f32>, (y, w): (f32, f32)| -> u8 {
            if w < b.w_min {
                return 0;
            }
            let above = b.above.is_some_and(|k| y > k * w);
            let below = b.below.is_some_and(|k| y < k * w);
            (if above { Band::<f32>::ABOVE } else { 0 }) | (if below { Band::<f32>::BELOW } else { 0 })
        };
        let values = [
            f32::NEG_INFINITY,
            -1e30,
            -3.0,
            -0.5,
            -0.0,
            0.0,
            1e-30,
            0.125,
            0.3,
            0.5,
            1.0,
            2.0,
            1e30,
            f32::INFINITY,
            f32::NAN,
        ];
        let bands = [
            Band::all(),
            Band::new(None, None, 0.125),
            Band::new(Some(0.5), None, 0.125),
            Band::new(None, Some(-0.25), 0.125),
            Band::new(Some(0.5), Some(-0.25), 0.125),
            Band::new(Some(-4.0), Some(4.0), 0.125),
        ];
        let mut sides = 0;
        for b in &bands {
            for &y in &values {
                for &w in &values {
                    let got = b.side((y, w));
                    assert_eq!(got, reference(b, (y, w)), "y {y}, w {w}");
                    sides += (got != 0) as u32;
                }
            }
        }
        // Both sides and neither occur.
        assert!(sides > 100, "{sides}");
    }

    /// The 32-bit area of small differences is the 64-bit one, and larger
    /// differences are left to it.
    #[test]
    fn small_area_is_the_wide_area() {
        let mut rng = crate::math::vec::tests::Rng(0xA2EA);
        let mut small = 0;
        for i in 0..200_000u32 {
            let e = [0; 4].map(|_| (rng.next() as i32) >> (2 + i % 20));
            let wide = i64::from(e[0]) * i64::from(e[3]) - i64::from(e[2]) * i64::from(e[1]);
            match super::signed_area2_small(e[0], e[1], e[2], e[3]) {
                Some(det) => {
                    assert_eq!(det, wide, "{e:?}");
                    small += 1;
                }
                None => assert!(e.iter().any(|v| v.unsigned_abs() >= 1 << 15), "{e:?}"),
            }
            assert_eq!(super::signed_area2(e[0], e[1], e[2], e[3]), wide, "{e:?}");
        }
        assert!(small > 50_000, "{small}");
        let max = (1 << 15) - 1;
        assert_eq!(super::signed_area2_small(max, -max, max, max), Some(2 * max as i64 * max as i64));
    }
}
