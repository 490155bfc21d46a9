//! The vertex stage per band over meshlets: for each band, each cluster of a
//! [`MeshletMesh`](crate::mesh::MeshletMesh) is tested against the band's slab, the view volume and
//! (when back faces are culled) its normal cone, all from its bounding
//! sphere and before any vertex work; a surviving cluster's vertices go
//! into a cache of [`MAX_MESHLET_VERTICES`] entries, vertex first when the
//! cluster lies inside the clip volume ([`super::eager`]), else through the
//! cached path with clipping ([`super::cache`]), and its triangles are
//! drawn straight into the band. No frame bins: RAM is the band, its depth rows and one
//! cluster's vertices, whatever the mesh's size.
//!
//! # Same image as the binned path
//! The triangles drawn are exactly those [`Pipeline::draw_valid_mesh`]
//! emits for the mesh with its triangles in cluster order, less the
//! clusters the tests reject. The slab and view-volume tests only reject
//! clusters with no triangle in the band or in view (conservative, with a
//! slack for rounding). The cone test rejects clusters whose every triangle
//! the screen's winding culls in exact arithmetic: each faces away from the
//! eye (module docs of [`crate::mesh::MeshletMesh`]), or towards it where
//! the matrix mirrors (`cull::eye_point`); back-face culling after snapping would
//! drop them too, except a snap-inverted sliver, which on a closed mesh lies
//! behind the front surface. `tests/integration/meshlets.rs` compares the
//! images.

use super::cache::{Slots, VertexCache, VertexSource};
use super::frame_clusters::{ClusterFrame, FrameClusters, FrameKey};
use super::inside::InsideView;
use super::tier::{ExactTier, FastTier, Tier};
use super::{Material, MeshStats, Pipeline, Uniform, rows_f32};
use crate::depth::DepthFormat;
use crate::edge::Cull;
use crate::math::{Mat4, Scalar};
use crate::mesh::{MAX_MESHLET_VERTICES, Mesh, ValidMeshletMesh};
use crate::raster3d::{Interpolation, Precision, ScreenTriangle};
use crate::render::Band3d;
use crate::{Error, Interpolate};

mod cull;

pub(super) use cull::ClusterCull;

/// The cache [`Pipeline::draw_meshlets`] needs: one cluster's vertices
/// (a [`VertexCache`] of [`MAX_MESHLET_VERTICES`], the most a valid cluster
/// has, so [`Error::CapacityExceeded`] cannot come from it, 3,072 bytes for
/// `f32` and `Fx`) and the frame's record of up to `CLUSTERS` clusters (6
/// bytes each; [`FRAME_CLUSTERS`](super::FRAME_CLUSTERS) = 256 unless told)
/// of up to `MESHES` meshes ([`FRAME_MESHES`](super::FRAME_MESHES) = 4
/// unless told; about 130 bytes each for what its record was built for):
/// what their band-independent tests said this frame and which rows they
/// can reach, so that each band skips the clusters it cannot meet with two
/// integer comparisons (`frame_clusters`). Clusters beyond `CLUSTERS` are
/// tested per band; with `CLUSTERS = 0` and `MESHES = 0` all are, in 3 KB.
/// The images are the same whatever `CLUSTERS` and `MESHES` are. Meshes
/// drawn in turn through one cache share the record's capacity, up to
/// `MESHES` of them at once; beyond that, the others are tested per band.
///
/// ```
/// use microraster::pipeline::ClusterCache;
/// let cache = ClusterCache::<f32, 4>::new();
/// assert!(core::mem::size_of_val(&cache) < 5_400);
/// let one = ClusterCache::<f32, 4, 256, 1>::sized(); // the record of one mesh
/// assert!(core::mem::size_of_val(&one) < 4_900);
/// let small = ClusterCache::<f32, 4, 0, 0>::sized(); // no record: per-band tests
/// assert!(core::mem::size_of_val(&small) < 3_300);
/// ```
// `repr(C)`: the vertices first. The vertex stage reaches them by immediate
// offsets from the cache, up to 4,095 bytes in a Thumb-2 load; laid out
// behind the 2 KB record (Rust's order), the Cortex-M4F knot was 2.6 %
// dearer.
#[repr(C)]
pub struct ClusterCache<
    T: Scalar,
    const S: u32,
    const CLUSTERS: usize = { super::FRAME_CLUSTERS },
    const MESHES: usize = { super::FRAME_MESHES },
> {
    vertices: VertexCache<T, S, MAX_MESHLET_VERTICES>,
    frame: FrameClusters<CLUSTERS, MESHES>,
}

impl<T: Scalar, const S: u32> ClusterCache<T, S> {
    /// An empty cache recording [`FRAME_CLUSTERS`](super::FRAME_CLUSTERS)
    /// clusters (its type is then inferred from its use, no turbofish).
    pub const fn new() -> Self {
        Self::sized()
    }
}

impl<T: Scalar, const S: u32, const CLUSTERS: usize, const MESHES: usize>
    ClusterCache<T, S, CLUSTERS, MESHES>
{
    /// An empty cache recording `CLUSTERS` clusters of up to `MESHES`
    /// meshes, as its type says (`ClusterCache::<f32, 4, 0, 0>::sized()`:
    /// none).
    pub const fn sized() -> Self {
        ClusterCache { vertices: VertexCache::new(), frame: FrameClusters::EMPTY }
    }
}

impl<T: Scalar, const S: u32, const CLUSTERS: usize, const MESHES: usize> Default
    for ClusterCache<T, S, CLUSTERS, MESHES>
{
    fn default() -> Self {
        Self::sized()
    }
}

impl<T: Scalar, const S: u32, const CLUSTERS: usize, const MESHES: usize> core::fmt::Debug
    for ClusterCache<T, S, CLUSTERS, MESHES>
{
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "ClusterCache<{CLUSTERS}, {MESHES}>")
    }
}

/// A cluster's vertices: local slot → the mesh's arrays (also a chunk's,
/// [`super::chunked`]).
pub(super) struct ClusterSource<'a, P = f32> {
    pub(super) mesh: &'a Mesh<'a, P>,
    pub(super) vertices: &'a [u16],
}

impl<P: Scalar> VertexSource for ClusterSource<'_, P> {
    type Coord = P;
    #[inline]
    fn position(&self, i: usize) -> Option<[P; 3]> {
        self.mesh.positions.get(usize::from(*self.vertices.get(i)?)).copied()
    }
    #[inline]
    fn normal(&self, i: usize) -> Option<[P; 3]> {
        self.mesh.normals.get(usize::from(*self.vertices.get(i)?)).copied()
    }
    fn has_normals(&self) -> bool {
        !self.mesh.normals.is_empty()
    }
    #[inline]
    fn vertex(&self, i: usize) -> usize {
        self.vertices.get(i).map_or(usize::MAX, |&v| usize::from(v))
    }
}

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// Draws `mesh` placed by `model`, in material colour `color`, into the
    /// band being rendered by
    /// [`Direct3d`](crate::render::Direct3d),
    /// cluster by cluster (module docs): clusters outside the band, outside
    /// the view volume or (with [`Cull::Clockwise`], the default) facing away
    /// are skipped before any vertex work. [`Pipeline::rows`] is ignored: the
    /// band's rows apply.
    ///
    /// The mesh is a [`ValidMeshletMesh`]: the cluster tests rely on each
    /// cluster's sphere and cone containing its triangles.
    ///
    /// Errors: [`Error::InvalidParameter`] if `model` is singular; the errors
    /// of [`Lighting::validate`](crate::light::Lighting::validate); for
    /// [`Fx`](crate::math::Fx), [`Error::CoordinateOutOfRange`] as for
    /// [`Pipeline::draw_valid_mesh`].
    pub fn draw_meshlets<P, C, F, M, const W: usize, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_, P>,
        model: &Mat4<T>,
        color: C,
        cache: &mut ClusterCache<T, S, N, K>,
        band: &mut Band3d<'_, '_, C, F, M, W>,
    ) -> Result<MeshStats, Error>
    where
        P: Scalar,
        C: Interpolate,
        F: DepthFormat,
        M: Interpolation,
    {
        self.draw_meshlets_with(mesh, model, color, &Uniform, cache, band)
    }

    /// [`Pipeline::draw_meshlets`] with the vertices coloured by `material`
    /// (per vertex; a per-face material is [`Error::InvalidParameter`]).
    pub(crate) fn draw_meshlets_with<P, C, F, M, Mat, const W: usize, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_, P>,
        model: &Mat4<T>,
        color: C,
        material: &Mat,
        cache: &mut ClusterCache<T, S, N, K>,
        band: &mut Band3d<'_, '_, C, F, M, W>,
    ) -> Result<MeshStats, Error>
    where
        P: Scalar,
        C: Interpolate,
        F: DepthFormat,
        M: Interpolation,
        Mat: Material<T>,
    {
        let rows = band.rows();
        // An affine band never reads 1/w.
        self.meshlets_into(mesh, model, color, material, cache, (rows, M::PERSPECTIVE), |tri| {
            band.draw_in(tri, self.precision)
        })
    }

    /// The triangles [`Pipeline::draw_meshlets`] would draw into the band of
    /// frame rows `rows` (first and last, inclusive), handed to `sink` in
    /// the same order instead: for a rasterizer of one's own, or to time the
    /// vertex stage alone. Same errors as [`Pipeline::draw_meshlets`].
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use microraster::math::{Vec3, transform};
    /// use microraster::mesh::*;
    /// use microraster::pipeline::{ClusterCache, Pipeline};
    /// let (mut p, mut n, mut i) = ([[0.0; 3]; 42], [[0.0; 3]; 42], [[0; 3]; 80]);
    /// let mesh = icosphere(1, &mut p, &mut n, &mut i)?;
    /// let (mut meshlets, mut vertices) = ([Meshlet::default(); meshlet_bound(80)], [0; meshlet_vertex_bound(80)]);
    /// let (mut triangles, mut scratch) = ([[0; 3]; 80], [0; meshlet_scratch_len(42, 80)]);
    /// let m = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch)?;
    /// let m = ValidMeshletMesh::new(m)?;
    /// let eye = transform::look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
    /// let pipeline = Pipeline::<f32, 4>::perspective(eye, 0.8, 1.0, 10.0, 64, 64)?;
    /// let (mut cache, mut front) = (ClusterCache::new(), 0);
    /// let model = transform::rotation_y(0.0);
    /// let stats = pipeline.meshlet_triangles(&m, &model, Rgb565::new(31, 0, 0), &mut cache, (0, 63), |_| front += 1)?;
    /// // The sphere's front half, all rows: about half of its 80 triangles.
    /// assert!(front > 20 && front < 60 && stats.emitted == front);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn meshlet_triangles<P: Scalar, C: Interpolate, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_, P>,
        model: &Mat4<T>,
        color: C,
        cache: &mut ClusterCache<T, S, N, K>,
        rows: (i32, i32),
        sink: impl FnMut(&ScreenTriangle<S>),
    ) -> Result<MeshStats, Error> {
        self.meshlets_into(mesh, model, color, &Uniform, cache, (rows, true), sink)
    }

    /// [`Pipeline::meshlet_triangles`] with the vertices coloured by
    /// `material` ([`Pipeline::draw_meshlets_with`]); without `with_inv_w`
    /// each vertex's `1/w` is left at 1 (for an affine band).
    #[allow(clippy::too_many_arguments)]
    fn meshlets_into<P: Scalar, C: Interpolate, Mat: Material<T>, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_, P>,
        model: &Mat4<T>,
        color: C,
        material: &Mat,
        cache: &mut ClusterCache<T, S, N, K>,
        rows: ((i32, i32), bool),
        sink: impl FnMut(&ScreenTriangle<S>),
    ) -> Result<MeshStats, Error> {
        // The tier chosen once per mesh: each runs its own instance.
        match self.precision {
            Precision::Exact => self.meshlets_in(ExactTier, mesh, model, color, material, cache, rows, sink),
            Precision::Fast => self.meshlets_in(FastTier, mesh, model, color, material, cache, rows, sink),
        }
    }

    /// [`Pipeline::meshlets_into`] in tier `R`.
    #[allow(clippy::too_many_arguments)]
    fn meshlets_in<R: Tier, P: Scalar, C: Interpolate, Mat: Material<T>, const N: usize, const K: usize>(
        &self,
        _tier: R,
        mesh: &ValidMeshletMesh<'_, P>,
        model: &Mat4<T>,
        color: C,
        material: &Mat,
        cache: &mut ClusterCache<T, S, N, K>,
        (rows, with_inv_w): ((i32, i32), bool),
        mut sink: impl FnMut(&ScreenTriangle<S>),
    ) -> Result<MeshStats, Error> {
        // Validated: the culling relies on each cluster's sphere and cone.
        let mesh = mesh.get();
        let pipe = Pipeline { rows: Some(rows), with_inv_w, ..*self };
        let mut stats = MeshStats::default();
        let Some(setup) = pipe.mesh_setup(&mesh.mesh, model, color, &mut stats)? else {
            return Ok(stats);
        };
        // The matrix's rows in `f32` once, for the cluster tests, the inside
        // test and the record's key.
        let rows_f = rows_f32(&setup.ctx.mvp);
        let cull = ClusterCull::new(rows_f, pipe.clip.far(), &setup.band, pipe.cull == Cull::Clockwise);
        let inside = InsideView::from_rows::<T>(rows_f, setup.planes);
        let key = FrameKey {
            mesh: (mesh.meshlets.as_ptr() as usize, mesh.meshlets.len()),
            mvp: rows_f.map(|r| [r.x, r.y, r.z, r.w].map(f32::to_bits)),
            planes: setup.planes,
            cull: pipe.cull,
            size: pipe.size,
            origin: pipe.origin,
        };
        let ClusterCache { vertices: cache, frame } = cache;
        let record = frame.prepare(key, rows.0, mesh.meshlets, rows_f, &cull, &inside);
        for (i, m) in mesh.meshlets.iter().enumerate() {
            // The band-independent verdicts from the frame's record where it
            // has the cluster, in the per-band tests' order (same counts).
            let flags = record.get(i).map(|r| (r.reaches(rows), r.flags()));
            let inside_view = match flags {
                Some((reaches, f)) => {
                    if !reaches || f & ClusterFrame::OUTSIDE != 0 || !cull.slab_keeps(m) {
                        stats.clusters_outside += 1;
                        continue;
                    }
                    if f & ClusterFrame::AWAY != 0 {
                        stats.clusters_back_facing += 1;
                        continue;
                    }
                    f & ClusterFrame::INSIDE != 0
                }
                None => {
                    if !cull.keeps(m, &mut stats) {
                        continue;
                    }
                    inside.contains(m.sphere)
                }
            };
            let (vo, vc) = (m.vertex_offset as usize, usize::from(m.vertex_count));
            let (to, tc) = (m.triangle_offset as usize, usize::from(m.triangle_count));
            let vertices = mesh.vertices.get(vo..vo + vc).ok_or(Error::InvalidMeshlet)?;
            let triangles = mesh.triangles.get(to..to + tc).ok_or(Error::InvalidMeshlet)?;
            let slots = cache.v.get_mut(..vc).ok_or(Error::InvalidMeshlet)?;
            let src = ClusterSource { mesh: &mesh.mesh, vertices };
            if inside_view {
                let emit = |tri: &ScreenTriangle<S>, _: &mut MeshStats| {
                    sink(tri);
                    Ok(())
                };
                let last = pipe.draw_inside::<R, _, _>(
                    &setup,
                    &src,
                    material,
                    &mut cache.v,
                    vc,
                    triangles,
                    &mut stats,
                    emit,
                );
                // What this band shows of the cluster's last row narrows the
                // record for the bands below (`ClusterFrame::narrow`).
                if let (Ok(Some(last)), Some(r)) = (&last, record.get_mut(i)) {
                    r.narrow(*last);
                }
                last.map(|_| ())
            } else {
                let emit = |tri: ScreenTriangle<S>, _: &mut MeshStats| {
                    sink(&tri);
                    Ok(())
                };
                let tris = triangles.iter().map(|t| t.map(usize::from));
                pipe.draw_cached::<R, _, _>(
                    &setup,
                    &src,
                    material,
                    Slots { slots, inside: false },
                    tris,
                    &mut stats,
                    emit,
                )
            }
            .map_err(|e| if matches!(e, Error::InvalidMesh(_)) { Error::InvalidMeshlet } else { e })?;
        }
        Ok(stats)
    }
}
