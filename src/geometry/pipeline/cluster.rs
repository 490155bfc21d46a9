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
//! faces away from the eye in exact arithmetic (module docs of
//! [`crate::mesh::MeshletMesh`]); back-face culling after snapping would
//! drop them too, except a snap-inverted sliver, which on a closed mesh lies
//! behind the front surface. `tests/integration/meshlets.rs` compares the
//! images.

use super::cache::{Slots, VertexCache, VertexSource};
use super::frame_clusters::{ClusterFrame, FrameClusters, FrameKey};
use super::inside::InsideView;
use super::{Band, Material, MeshStats, Pipeline, Uniform, rows_f32, view_planes};
use crate::depth::DepthFormat;
use crate::edge::Cull;
use crate::math::{Mat4, Scalar, Vec3, Vec4};
use crate::mesh::{MAX_MESHLET_VERTICES, Mesh, Meshlet, ValidMeshletMesh};
use crate::raster3d::{Interpolation, ScreenTriangle};
use crate::render::Band3d;
use crate::{Error, Interpolate};

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
pub(super) struct ClusterSource<'a> {
    pub(super) mesh: &'a Mesh<'a>,
    pub(super) vertices: &'a [u16],
}

impl VertexSource for ClusterSource<'_> {
    #[inline]
    fn position(&self, i: usize) -> Option<[f32; 3]> {
        self.mesh.positions.get(usize::from(*self.vertices.get(i)?)).copied()
    }
    #[inline]
    fn normal(&self, i: usize) -> Option<[f32; 3]> {
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

/// The cluster tests' slack, relative to a sphere's reach `r·|p.xyz|`
/// and absolute: far above their `f32` rounding (`2^-24` relative per
/// operation) and the vertex stage's own (as in [`super::inside`]).
const CULL_SLACK: f32 = 1.0 / 256.0;

/// The per-band, per-mesh cluster tests in model space, in `f32` on both
/// numeric paths: in 16.16 the plane values of a large sphere saturate (the
/// mesh-level tests are `f32` for the same reason), and a handful of
/// products per cluster and band is small beside the vertex work it saves.
pub(super) struct ClusterCull {
    /// Planes `p` with `p · (x, 1) ≥ 0` inside: the view volume and the
    /// band's slab, with `|p.xyz|·(1 + CULL_SLACK)`.
    planes: [(Vec4<f32>, f32); 8], // the slab's two, then the view volume's six
    count: usize,
    /// How many of `planes` are the slab's (0 to 2).
    slab: usize,
    /// The eye as a homogeneous model-space point `(e, ew)`, `ew ≥ 0`
    /// (`ew = 0`: orthographic, `e` points towards the viewer); `None`: no
    /// cone test.
    eye: Option<(Vec3<f32>, f32)>,
}

impl ClusterCull {
    /// The tests for a model-view-projection matrix given by its rows in
    /// `f32` ([`rows_f32`]).
    fn new<T: Scalar>(rows: [Vec4<f32>; 4], far: bool, band: &Band<T>, cone: bool) -> Self {
        let [x, y, z, w] = rows;
        let mut planes = [(Vec4::new(0.0, 0.0, 0.0, 0.0), 0.0); 8];
        let mut count = 0;
        let mut add = |p: Vec4<f32>| {
            planes[count] = (p, p.xyz().length() * (1.0 + CULL_SLACK));
            count += 1;
        };
        // The slab first: it rejects most clusters of a band.
        if let Some(k) = band.above {
            add(w * k.to_f32() - y);
        }
        if let Some(k) = band.below {
            add(y - w * k.to_f32());
        }
        let slab = usize::from(band.above.is_some()) + usize::from(band.below.is_some());
        for p in view_planes(rows, far) {
            add(p);
        }
        ClusterCull { planes, count, slab, eye: if cone { eye_point(x, y, z, w) } else { None } }
    }

    /// Counts and drops a cluster that certainly has no triangle in the band
    /// facing the eye.
    #[inline]
    fn keeps(&self, m: &Meshlet, stats: &mut MeshStats) -> bool {
        if !self.slab_keeps(m) || !self.view_keeps(m) {
            stats.clusters_outside += 1;
            return false;
        }
        let away = self.faces_away(m);
        stats.clusters_back_facing += away as u32;
        !away
    }

    /// False if the cluster's sphere lies beyond one of `planes`.
    #[inline]
    fn within(planes: &[(Vec4<f32>, f32)], (c, r): ([f32; 3], f32)) -> bool {
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        // Written as the rejection, so that NaN keeps the cluster.
        !planes.iter().any(|(p, len)| p.dot(centre) < -(r * *len + CULL_SLACK))
    }

    /// The band's part of [`ClusterCull::keeps`]: false if the cluster lies
    /// wholly above or below the band.
    #[inline]
    pub(super) fn slab_keeps(&self, m: &Meshlet) -> bool {
        Self::within(&self.planes[..self.slab], m.sphere)
    }

    /// The view volume's part of [`ClusterCull::keeps`] (the same for every
    /// band).
    #[inline]
    pub(super) fn view_keeps(&self, m: &Meshlet) -> bool {
        Self::within(&self.planes[self.slab..self.count], m.sphere)
    }

    /// The cone's part of [`ClusterCull::keeps`]: true if every triangle of
    /// the cluster faces away from the eye (the same for every band).
    #[inline]
    pub(super) fn faces_away(&self, m: &Meshlet) -> bool {
        let ((c, r), (axis, cutoff)) = (m.sphere, m.cone);
        match self.eye {
            Some((e, ew)) if cutoff < 1.0 => faces_away(Vec3::from_f32(c), r, axis, cutoff, e, ew),
            _ => false,
        }
    }
}

/// The cone test of [`MeshletMesh`](crate::mesh::MeshletMesh): `axis · v >
/// cutoff · |v| + r · ew · (1 + cutoff)` with `v = c · ew − e`, with a
/// slack of `2^-6` relative to `|v|` and to the right-hand side (`f32`
/// rounding is far below it).
fn faces_away(c: Vec3<f32>, r: f32, axis: [f32; 3], cutoff: f32, e: Vec3<f32>, ew: f32) -> bool {
    const SLACK: f32 = 1.0 / 64.0;
    let v = c * ew - e;
    let len = v.length();
    if !(len > 0.0 && len.is_finite()) {
        return false;
    }
    Vec3::from_f32(axis).dot(v) - (cutoff + SLACK) * len > r * ew * (1.0 + cutoff) * (1.0 + SLACK)
}

/// The centre of projection in model space: the homogeneous point `E` with
/// clip `x = y = w = 0`, the 4D cross product of those rows, signed so that
/// moving towards it decreases depth (`z · E < 0`) and scaled so that its
/// largest component is 1. `None` if the rows are degenerate.
fn eye_point(a: Vec4<f32>, b: Vec4<f32>, zr: Vec4<f32>, c: Vec4<f32>) -> Option<(Vec3<f32>, f32)> {
    let (a, b, c, zr) =
        ([a.x, a.y, a.z, a.w], [b.x, b.y, b.z, b.w], [c.x, c.y, c.z, c.w], [zr.x, zr.y, zr.z, zr.w]);
    let det3 = |i: usize, j: usize, k: usize| {
        a[i] * (b[j] * c[k] - b[k] * c[j]) - a[j] * (b[i] * c[k] - b[k] * c[i])
            + a[k] * (b[i] * c[j] - b[j] * c[i])
    };
    let mut e = [det3(1, 2, 3), -det3(0, 2, 3), det3(0, 1, 3), -det3(0, 1, 2)];
    let depth = zr[0] * e[0] + zr[1] * e[1] + zr[2] * e[2] + zr[3] * e[3];
    if !depth.is_finite() || depth == 0.0 {
        return None;
    }
    if depth > 0.0 {
        e = e.map(|v| -v);
    }
    if e[3] < 0.0 {
        return None; // an eye behind the scene's w: not a camera
    }
    let m = e.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let e = e.map(|v| v / m);
    Some((Vec3::new(e[0], e[1], e[2]), e[3]))
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
    pub fn draw_meshlets<C, F, M, const W: usize, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_>,
        model: &Mat4<T>,
        color: C,
        cache: &mut ClusterCache<T, S, N, K>,
        band: &mut Band3d<'_, '_, C, F, M, W>,
    ) -> Result<MeshStats, Error>
    where
        C: Interpolate,
        F: DepthFormat,
        M: Interpolation,
    {
        self.draw_meshlets_with(mesh, model, color, &Uniform, cache, band)
    }

    /// [`Pipeline::draw_meshlets`] with the vertices coloured by `material`
    /// (per vertex; a per-face material is [`Error::InvalidParameter`]).
    pub(crate) fn draw_meshlets_with<C, F, M, Mat, const W: usize, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_>,
        model: &Mat4<T>,
        color: C,
        material: &Mat,
        cache: &mut ClusterCache<T, S, N, K>,
        band: &mut Band3d<'_, '_, C, F, M, W>,
    ) -> Result<MeshStats, Error>
    where
        C: Interpolate,
        F: DepthFormat,
        M: Interpolation,
        Mat: Material<T>,
    {
        let rows = band.rows();
        // An affine band never reads 1/w.
        self.meshlets_into(mesh, model, color, material, cache, (rows, M::PERSPECTIVE), |tri| band.draw(tri))
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
    pub fn meshlet_triangles<C: Interpolate, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_>,
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
    fn meshlets_into<C: Interpolate, Mat: Material<T>, const N: usize, const K: usize>(
        &self,
        mesh: &ValidMeshletMesh<'_>,
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
        let inside = InsideView::from_rows(rows_f, setup.planes);
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
                let last =
                    pipe.draw_inside(&setup, &src, material, &mut cache.v, vc, triangles, &mut stats, emit);
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
                pipe.draw_cached(
                    &setup,
                    &src,
                    material,
                    Slots { slots, inside: false },
                    tris,
                    &mut stats,
                    emit,
                )
            }
            .map_err(|e| if e == Error::InvalidMesh { Error::InvalidMeshlet } else { e })?;
        }
        Ok(stats)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift in [-1, 1).
    fn rng(seed: &mut u64) -> f64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    fn unit(v: [f64; 3]) -> [f64; 3] {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|x| x / l)
    }

    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// Whenever the cone test rejects, every normal in the cone faces away
    /// from every point of the sphere, in f64, for eyes at finite points and
    /// at infinity.
    #[test]
    fn cone_test_rejects_only_clusters_facing_away() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let (mut rejected, mut cases) = ([0u32; 1], 0u32);
        for i in 0..40_000 {
            let axis = unit([0; 3].map(|_| rng(&mut seed)));
            let alpha = (rng(&mut seed) + 1.0) * 0.75; // up to 86°
            let cutoff = alpha.sin();
            let c = [0; 3].map(|_| rng(&mut seed) * 4.0);
            let r = (rng(&mut seed) + 1.0) * 0.3;
            let ew = if i % 4 == 0 { 0.0 } else { 1.0 };
            let e = if ew == 0.0 {
                unit([0; 3].map(|_| rng(&mut seed)))
            } else {
                [0; 3].map(|_| rng(&mut seed) * 8.0)
            };
            let f = |v: [f64; 3]| v.map(|x| x as f32);
            let verdict = [faces_away(
                Vec3::from_f32(f(c)),
                r as f32,
                f(axis),
                cutoff as f32,
                Vec3::from_f32(f(e)),
                ew as f32,
            )];
            cases += 1;
            for (k, &away) in verdict.iter().enumerate() {
                if !away {
                    continue;
                }
                rejected[k] += 1;
                // Extreme normals of the cone and points of the sphere.
                for _ in 0..64 {
                    let q = unit([0; 3].map(|_| rng(&mut seed)));
                    let perp = unit([0, 1, 2].map(|j| q[j] - dot(q, axis) * axis[j]));
                    let n = [0, 1, 2].map(|j| axis[j] * alpha.cos() + perp[j] * alpha.sin());
                    let d = unit([0; 3].map(|_| rng(&mut seed)));
                    let p = [0, 1, 2].map(|j| c[j] + d[j] * r);
                    let v = if ew == 0.0 { e.map(|x| -x) } else { [0, 1, 2].map(|j| p[j] - e[j]) };
                    assert!(dot(n, v) > 0.0, "case {i} path {k}: a normal faces the eye");
                }
            }
        }
        // The test is not vacuous: it rejects a good share.
        assert!(rejected.iter().all(|&r| r > cases / 10), "{rejected:?} of {cases}");
    }
}
