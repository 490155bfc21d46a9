//! A whole mesh into the frame's bins: the path without meshlets, triangle
//! by triangle (transform, lighting, clipping, snapping and culling), for
//! [`Triangles3d`](crate::render::Triangles3d): through a vertex cache (the
//! caller's, or 8 entries on the stack), or per corner straight into a band
//! (the `view3d` front).

use super::cache::Cached;
use super::chunked::{SMALL_SLOTS, SlotTable, SmallTable, WideTable};
use super::tier::{ExactTier, FastTier, Tier};
use super::{
    Band, ChunkMemo, Material, MeshSetup, MeshStats, NoMemo, Pipeline, Shade, Uniform, VertexCache, VertexCtx,
};
use super::{bins, cache, channels, inside};
use crate::clip3d::{Class, ClipPlanes, ClipVertex, classify, clip_triangle};
use crate::edge::Cull;
use crate::math::{Mat4, Scalar, Vec3};
use crate::mesh::{Mesh, ValidMesh};
use crate::raster3d::{Precision, ScreenTriangle, ScreenVertex};
use crate::{Error, Interpolate};

impl<T: Scalar, const S: u32> Pipeline<T, S> {
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
        // (The winding is not looked at here.)
        mesh.validate()?;
        self.binned(&ValidMesh::trusted(*mesh, false), model, color, bins)
    }

    /// [`Pipeline::draw_mesh`] for a mesh checked once beforehand
    /// ([`ValidMesh`], possibly at compile time): the same result without the
    /// O(vertices) check on every call (every band, when the vertex stage
    /// runs per band).
    ///
    /// Each vertex is transformed, snapped and lit once per run of
    /// consecutive triangles that share it: the triangles are taken in their
    /// order in chunks of at most 8 vertices, held in a cache on the stack
    /// (about 480 bytes for `f32` and [`Fx`](crate::math::Fx)), as
    /// [`Pipeline::draw_valid_mesh_cached`] does with a cache of 8. Meshes
    /// whose index order keeps neighbours together (strips, grids,
    /// subdivided spheres) share most corners this way (`docs/setup_cost.md`,
    /// twenty-ninth pass). The triangles, their order and the counts are
    /// those of a transform per corner (tested). A larger cache the caller
    /// owns ([`Pipeline::draw_valid_mesh_cached`]) shares more; an empty one
    /// (`VertexCache<T, S, 0>`) takes each corner on its own, with the
    /// least code and stack.
    ///
    /// Errors: first [`Error::WindingMismatch`] if [`Pipeline::cull`] is
    /// not [`Cull::None`] and the mesh is wound against its normals
    /// ([`ValidMesh::winding_agrees`] is false: culling would show its
    /// inside, as the `view3d` front and [`MeshletMesh::validate`](crate::mesh::MeshletMesh::validate) say too;
    /// nothing done); [`Error::CapacityExceeded`] if `bins` fills up, with the
    /// length it needed (the mesh's triangles are counted to the end, and
    /// `bins` is left as it was: on any error no triangle of the mesh is
    /// kept); [`Error::InvalidParameter`] if `model` is singular;
    /// the errors of [`Lighting::validate`](crate::light::Lighting::validate) for the pipeline's lighting; and
    /// for [`Fx`](crate::math::Fx) only, [`Error::CoordinateOutOfRange`] if
    /// `view · model` or `projection · view · model` saturates 16.16, or if
    /// the mesh is not culled whole and one of its model, eye or clip
    /// coordinates (or a partial sum of one) reaches ±32767: 16.16 cannot
    /// hold it, and a saturated coordinate would change what is drawn; for
    /// `f32`, [`Error::CoordinateOutOfRange`] if the mesh is not culled
    /// whole and a vertex one of its triangles uses has a clip coordinate
    /// beyond ±2^64 (or one that overflows `f32`), which the clipper
    /// ([`clip3d`](crate::clip3d)) would discard with its triangle.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::math::{Mat4, Vec3, transform};
    /// use microraster::mesh::{Mesh, ValidMesh};
    /// use microraster::pipeline::Pipeline;
    /// use microraster::{Cull, Error};
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// let up = [[0.0, 0.0, 1.0]; 3];
    /// // Wound clockwise seen from the side its normals point to: inside out.
    /// let inside_out = ValidMesh::new(Mesh::new(&positions, &up, &[[0, 2, 1]], ([0.5, 0.5, 0.0], 0.71)))?;
    /// let eye = transform::look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
    /// let mut pipeline = Pipeline::<f32, 4>::perspective(eye, 1.0, 0.5, 10.0, 64, 64)?;
    /// let mut bins = microraster::heapless::Vec::<_, 8>::new();
    /// let r = pipeline.draw_valid_mesh(&inside_out, &Mat4::IDENTITY, Rgb565::RED, &mut bins);
    /// assert_eq!(r.err(), Some(Error::WindingMismatch));
    /// pipeline.cull = Cull::None; // both sides drawn: the winding does not matter
    /// assert_eq!(pipeline.draw_valid_mesh(&inside_out, &Mat4::IDENTITY, Rgb565::RED, &mut bins)?.emitted, 1);
    /// # Ok::<(), Error>(())
    /// ```
    pub fn draw_valid_mesh<C: Interpolate, const N: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<MeshStats, Error> {
        self.check_winding(mesh)?;
        self.binned(mesh, model, color, bins)
    }

    /// [`Error::WindingMismatch`] if back faces (or front faces) are culled
    /// and `mesh` is wound against its normals: culling would drop the
    /// faces that should show ([`Pipeline::draw_valid_mesh`]).
    pub(super) fn check_winding(&self, mesh: &ValidMesh<'_>) -> Result<(), Error> {
        if self.cull != Cull::None && !mesh.winding_agrees() {
            return Err(Error::WindingMismatch);
        }
        Ok(())
    }

    /// [`Pipeline::draw_valid_mesh`] without the winding test
    /// ([`Pipeline::draw_mesh`] does not look at the winding).
    fn binned<C: Interpolate, const N: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<MeshStats, Error> {
        let mut bins = bins::BinWriter::new(bins);
        let result = self.mesh_into(mesh, model, color, &Uniform, &mut NoMemo, bins.sink());
        bins.finish(result)
    }

    /// [`Pipeline::draw_valid_mesh`]'s triangles, in the same order, handed
    /// to `sink` instead of a bin: with [`Pipeline::rows`] set to a band's
    /// rows, the vertex stage draws straight into that band, no bins (the
    /// `view3d` front). `material` gives each vertex its material colour
    /// ([`Uniform`]: `color`). Through the 8-entry stack cache, except for
    /// a colour per face (one lit colour per vertex cannot hold it): then
    /// per corner. `memo` records the chunks or skips those that miss the
    /// band ([`super::chunk_record`]; [`NoMemo`]: none). Errors: those of
    /// [`Pipeline::draw_valid_mesh`], with `sink`'s in place of a full bin.
    pub(crate) fn mesh_into<C: Interpolate, M: Material<T>>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        material: &M,
        memo: &mut impl ChunkMemo<T>,
        sink: impl FnMut(ScreenTriangle<S>) -> Result<(), Error>,
    ) -> Result<MeshStats, Error> {
        // The tier chosen once per mesh (`tier`): each runs its own code.
        let (cache, table) = (&mut [Cached::EMPTY; SMALL_SLOTS], &mut SmallTable::new());
        match (M::PER_FACE, self.precision) {
            (true, Precision::Exact) => {
                self.valid_mesh_into::<ExactTier, _, _>(mesh, model, color, material, sink)
            }
            (true, Precision::Fast) => {
                self.valid_mesh_into::<FastTier, _, _>(mesh, model, color, material, sink)
            }
            (_, Precision::Exact) => {
                self.cached_into(ExactTier, mesh, model, color, material, memo, cache, table, sink)
            }
            (_, Precision::Fast) => {
                self.cached_into(FastTier, mesh, model, color, material, memo, cache, table, sink)
            }
        }
    }

    /// [`Pipeline::mesh_into`] with each vertex transformed once per
    /// corner (no cache): the empty cache's path, and that of a colour per
    /// face.
    fn valid_mesh_into<R: Tier, C: Interpolate, M: Material<T>>(
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
                        ctx.color::<R>(pos[k], n)
                    } else {
                        ctx.color_of::<R>(pos[k], n, material.base(ctx.base, i, usize::from(idx[k])))
                    }
                };
                // Flat: one lit colour per face, vertex 0 lit with the face normal.
                if self.shade == Shade::Flat { [c(0); 3] } else { [c(0), c(1), c(2)] }
            };
            if class == Class::Inside {
                if let Some(at) = self.snapped_and_kept::<R>(clip, &mut stats) {
                    self.emit(at, colors(), max, &mut sink, &mut stats)?;
                }
                continue;
            }
            let cs = colors();
            let v = [0, 1, 2].map(|k| ClipVertex { pos: clip[k], attr: cs[k] });
            self.clip_and_emit::<R, 3>(v, planes, &mut stats, |at, attr, stats| {
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
    /// An empty cache, `VertexCache<T, S, 0>`, transforms, snaps and lights
    /// each vertex once per triangle corner instead: the same output again,
    /// with neither the cache nor the cached stage's code: the smallest
    /// build, and the least stack.
    ///
    /// Errors: those of [`Pipeline::draw_valid_mesh`] ([`Error::WindingMismatch`]
    /// first), then [`Error::CapacityExceeded`] with `needed` 3 if `0 < V < 3` and the
    /// mesh has more than `V` vertices (nothing done).
    pub fn draw_valid_mesh_cached<C: Interpolate, const V: usize, const N: usize>(
        &self,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        cache: &mut VertexCache<T, S, V>,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<MeshStats, Error> {
        self.check_winding(mesh)?;
        if V == 0 {
            // Per corner (a type's choice: the branch folds away).
            let mut bins = bins::BinWriter::new(bins);
            let result = match self.precision {
                Precision::Exact => {
                    self.valid_mesh_into::<ExactTier, _, _>(mesh, model, color, &Uniform, bins.sink())
                }
                Precision::Fast => {
                    self.valid_mesh_into::<FastTier, _, _>(mesh, model, color, &Uniform, bins.sink())
                }
            };
            return bins.finish(result);
        }
        if mesh.mesh().vertex_count() > V && V < 3 {
            return Err(Error::CapacityExceeded { needed: 3, capacity: V });
        }
        let mut bins = bins::BinWriter::new(bins);
        let (memo, table) = (&mut NoMemo, &mut WideTable::new());
        let result = match self.precision {
            Precision::Exact => self.cached_into(
                ExactTier,
                mesh,
                model,
                color,
                &Uniform,
                memo,
                &mut cache.v,
                table,
                bins.sink(),
            ),
            Precision::Fast => self.cached_into(
                FastTier,
                mesh,
                model,
                color,
                &Uniform,
                memo,
                &mut cache.v,
                table,
                bins.sink(),
            ),
        };
        bins.finish(result)
    }

    /// The cached path over `mesh` with `cache` (at least three entries, or
    /// the whole mesh) and `table` for its chunks' slots, every triangle to
    /// `sink`; `material` is not per face.
    #[allow(clippy::too_many_arguments)]
    fn cached_into<R: Tier, C: Interpolate, M: Material<T>, const B: usize, const K: usize>(
        &self,
        tier: R,
        mesh: &ValidMesh<'_>,
        model: &Mat4<T>,
        color: C,
        material: &M,
        memo: &mut impl ChunkMemo<T>,
        cache: &mut [Cached<T, S>],
        table: &mut SlotTable<B, K>,
        mut sink: impl FnMut(ScreenTriangle<S>) -> Result<(), Error>,
    ) -> Result<MeshStats, Error> {
        let mesh = mesh.mesh();
        let mut stats = MeshStats::default();
        let Some(setup) = self.mesh_setup(mesh, model, color, &mut stats)? else {
            return Ok(stats);
        };
        let inside = inside::InsideView::new(&setup.ctx.mvp, setup.planes).contains(mesh.bounding_sphere);
        if mesh.vertex_count() > cache.len() {
            self.draw_chunked(tier, &setup, mesh, material, memo, cache, table, inside, &mut stats, sink)?;
            return Ok(stats);
        }
        let cache = &mut cache[..mesh.vertex_count()];
        let triangles = mesh.indices.iter().map(|t| t.map(usize::from));
        let cached = cache::Slots { slots: cache, inside };
        self.draw_cached::<R, _, _>(&setup, mesh, material, cached, triangles, &mut stats, |tri, _| {
            sink(tri)
        })?;
        Ok(stats)
    }

    /// Clips a triangle that crosses a plane and hands each piece that
    /// survives snapping and culling to `emit`, with its interpolated
    /// attributes (all counted in `stats`).
    pub(super) fn clip_and_emit<R: Tier, const A: usize>(
        &self,
        v: [ClipVertex<T, A>; 3],
        planes: ClipPlanes,
        stats: &mut MeshStats,
        mut emit: impl FnMut([ScreenVertex<S>; 3], [[T; A]; 3], &mut MeshStats) -> Result<(), Error>,
    ) -> Result<(), Error> {
        stats.clipped += 1;
        for tri in clip_triangle(v, planes).triangles() {
            if let Some(at) = self.snapped_and_kept::<R>(tri.map(|v| v.pos), stats) {
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
pub(super) fn triangle_in_view<T: Scalar>(
    mesh: &Mesh<'_>,
    i: usize,
    ctx: &VertexCtx<T>,
    band: &Band<T>,
    planes: ClipPlanes,
) -> Result<Option<([Vec3<T>; 3], [[T; 4]; 3], Class)>, Error> {
    let pos = mesh.triangle(i).ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?.map(Vec3::from_f32);
    let yw = pos.map(|p| ctx.yw(p));
    if band.excludes(yw) {
        return Ok(None);
    }
    let clip = [0, 1, 2].map(|k| ctx.position(pos[k], yw[k]));
    let class = classify(clip, planes);
    Ok((class != Class::Outside).then_some((pos, clip, class)))
}

#[cfg(test)]
mod tests;
