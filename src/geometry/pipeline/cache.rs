//! The cached vertex path: each vertex of a mesh (or of one meshlet) is
//! transformed, classified, snapped and lit at most once, however many
//! triangles share it, and only as far as its triangles need: clip `y` and
//! `w` first (enough to reject a triangle outside the band), the rest of the
//! clip position and its outcode when a triangle needs them, the snapped
//! position when a triangle lies inside the clip volume, the colour when a
//! triangle survives back-face culling.
//!
//! [`Pipeline::draw_valid_mesh_cached`] runs it over a whole mesh into the
//! frame's bins (or over chunks of its triangles, [`super::chunked`], when
//! the cache is smaller than the mesh),
//! [`Pipeline::draw_meshlets`](super::Pipeline::draw_meshlets)
//! over each surviving meshlet straight into a band. Both give the triangles
//! of [`Pipeline::draw_valid_mesh`], bit for bit, in the same order.

use super::presnap::{PreSnap, orientation};
use super::tier::Tier;
use super::{Material, MeshSetup, MeshStats, Pipeline, Shade, channels, finite_color};
use crate::Error;
use crate::clip3d::{Class, ClipVertex, VertexClass};
use crate::edge::Cull;
use crate::math::{Scalar, Vec3};
use crate::raster3d::{ScreenTriangle, ScreenVertex};

mod entry;

/// Caller-owned storage for [`Pipeline::draw_valid_mesh_cached`]: the
/// per-vertex results of one mesh of up to `V` vertices (reused mesh after
/// mesh); a larger mesh is drawn in chunks of up to `min(V, 64)` vertices.
/// Size: `V ×` about 50 bytes for `f32` and [`Fx`](crate::math::Fx)
/// (clip position, snapped screen vertex, pre-snap quotients, state),
/// `size_of` tells exactly.
///
/// ```
/// use microraster::pipeline::VertexCache;
/// let cache = VertexCache::<f32, 4, 392>::new();
/// assert!(core::mem::size_of_val(&cache) <= 392 * 52);
/// ```
pub struct VertexCache<T: Scalar, const S: u32, const V: usize> {
    pub(super) v: [Cached<T, S>; V],
}

impl<T: Scalar, const S: u32, const V: usize> VertexCache<T, S, V> {
    /// An empty cache (its contents are rebuilt on every draw).
    pub const fn new() -> Self {
        VertexCache { v: [Cached::EMPTY; V] }
    }
}

impl<T: Scalar, const S: u32, const V: usize> Default for VertexCache<T, S, V> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Scalar, const S: u32, const V: usize> core::fmt::Debug for VertexCache<T, S, V> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "VertexCache<{V}>")
    }
}

/// One vertex of a [`VertexCache`].
#[derive(Clone, Copy)]
pub(crate) struct Cached<T, const S: u32> {
    /// Clip position (only y and w until `CLIP` is set).
    pub(super) clip: [T; 4],
    /// `Band` side bits and the flags below.
    pub(super) state: u8,
    /// Clip outcode (valid with `CLIP`).
    pub(super) code: u8,
    /// Snapped vertex (valid with `SNAP` and `SNAPPED`; its depth and
    /// `1/w` with `DEPTH`, before which its depth field holds the clip
    /// `w`'s divisor word, `Pipeline::snap_deferred`; its colour with
    /// `LIT`). Not an `Option`: its unwrapping cost loads and branches in
    /// the triangle loop.
    pub(super) screen: ScreenVertex<S>,
    /// What snapping rounds, for the pre-snap back-face test (valid with
    /// `QUO`; NaN where the test cannot use the vertex).
    pub(super) q: [f32; 2],
}

impl<T: Scalar, const S: u32> Cached<T, S> {
    pub(super) const CLIP: u8 = 1;
    pub(super) const SNAP: u8 = 2;
    pub(super) const LIT: u8 = 4;
    /// The snapped vertex's depth and `1/w` are set (with `SNAP`).
    pub(super) const DEPTH: u8 = 8;
    /// `q` is set.
    pub(super) const QUO: u8 = 16;
    /// Snapping succeeded (with `SNAP`): `screen` holds the vertex.
    pub(super) const SNAPPED: u8 = 32;
    pub(super) const EMPTY: Self = Cached {
        clip: [T::ZERO; 4],
        state: 0,
        code: 0,
        screen: ScreenVertex { pos: crate::SubPoint::ORIGIN, depth: 0, inv_w: 0, color: [0; 3] },
        q: [0.0; 2],
    };
}

/// The cache slots of one call of [`Pipeline::draw_cached`], and whether
/// their vertices lie inside the clip volume ([`super::inside`]).
pub(super) struct Slots<'a, T, const S: u32> {
    pub(super) slots: &'a mut [Cached<T, S>],
    pub(super) inside: bool,
}

/// Where the cached path reads its vertices: model positions and normals by
/// cache slot (a mesh vertex, or a meshlet's local vertex).
pub(super) trait VertexSource {
    /// The number type the mesh stores its positions and normals in.
    type Coord: Scalar;
    /// The model-space position of slot `i` (`None` out of range).
    fn position(&self, i: usize) -> Option<[Self::Coord; 3]>;
    /// The unit normal of slot `i`, if the mesh has normals.
    fn normal(&self, i: usize) -> Option<[Self::Coord; 3]>;
    /// Whether the mesh has per-vertex normals.
    fn has_normals(&self) -> bool;
    /// The mesh vertex of slot `i` (for its [`Material`] colour; `usize::MAX`
    /// out of range).
    fn vertex(&self, i: usize) -> usize;
}

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// The cached vertex path over `triangles` (cache slots, counter-clockwise
    /// from outside): every triangle [`Pipeline::draw_valid_mesh`] would emit
    /// for them goes to `sink`, in order, with the same vertices and colours.
    /// `cache` holds one entry per slot of `src` and is overwritten.
    /// `material` colours the vertices ([`super::Uniform`]: the mesh's
    /// colour); it cannot be per face (one lit colour is cached per vertex).
    /// `cache.inside` says the vertices' bounding sphere lies inside the
    /// clip volume ([`super::inside`]): their outcodes are 0, not computed.
    ///
    /// Errors: [`Error::InvalidParameter`] for a per-face `material`;
    /// [`Error::InvalidMesh`] for a slot beyond `cache` or `src`
    /// (validated meshes have none; not looked for when every vertex lies
    /// on one side of the band), and whatever `sink` returns.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn draw_cached<R: Tier, Src: VertexSource, M: Material<T>>(
        &self,
        setup: &MeshSetup<T>,
        src: &Src,
        material: &M,
        cache: Slots<'_, T, S>,
        triangles: impl Iterator<Item = [usize; 3]>,
        stats: &mut MeshStats,
        mut sink: impl FnMut(ScreenTriangle<S>, &mut MeshStats) -> Result<(), Error>,
    ) -> Result<(), Error> {
        if M::PER_FACE {
            return Err(Error::InvalidParameter(crate::Param::FaceColors));
        }
        let Slots { slots: cache, inside } = cache;
        let MeshSetup { ctx, planes, band, max } = setup;
        let (planes, max) = (*planes, *max);
        let coder = VertexClass::<T>::new(planes);
        let flat_shade = self.shade == Shade::Flat;
        let position = |i: usize| {
            src.position(i).map(Vec3::from_data).ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))
        };
        let presnap = PreSnap::new::<T>(self.size, self.origin, S);
        let cull_sign = match self.cull {
            Cull::Clockwise if presnap.active() => 1,
            Cull::CounterClockwise if presnap.active() => -1,
            _ => 0,
        };

        // Clip y and w and the band test of every vertex; the rest on demand.
        let mut all_sides = super::Band::<T>::ABOVE | super::Band::<T>::BELOW;
        for (i, c) in cache.iter_mut().enumerate() {
            let (y, w) = ctx.yw(position(i)?);
            c.clip = [T::ZERO, y, T::ZERO, w];
            c.state = band.side((y, w));
            all_sides &= c.state;
        }
        // Every vertex on one side of the band: so is every triangle, which
        // the per-triangle test below would drop one by one (a meshlet whose
        // bounding sphere reaches the band while its vertices do not).
        if all_sides != 0 {
            return Ok(());
        }
        for idx in triangles {
            let [a, b, c] = idx;
            let (Some(&sa), Some(&sb), Some(&sc)) = (cache.get(a), cache.get(b), cache.get(c)) else {
                return Err(Error::InvalidMesh(crate::MeshFault::Unchecked));
            };
            if sa.state & sb.state & sc.state & (super::Band::<T>::ABOVE | super::Band::<T>::BELOW) != 0 {
                continue;
            }
            let mut codes = [0u8; 3];
            for (k, &j) in idx.iter().enumerate() {
                let e = &mut cache[j];
                if e.state & Cached::<T, S>::CLIP == 0 {
                    e.clip = ctx.position(position(j)?, (e.clip[1], e.clip[3]));
                    e.code = if inside { 0 } else { coder.code(&e.clip) };
                    e.state |= Cached::<T, S>::CLIP;
                }
                codes[k] = e.code;
            }
            let class = VertexClass::<T>::class(codes);
            if class == Class::Outside {
                continue;
            }
            if class == Class::Inside {
                // A certain back face (`presnap`) needs no snapping: counted
                // as the exact test would count it.
                if cull_sign != 0 {
                    let mut q = [[0.0; 2]; 3];
                    for (k, &j) in idx.iter().enumerate() {
                        let e = &mut cache[j];
                        if e.state & Cached::<T, S>::QUO == 0 {
                            let usable = self.depth_deferrable(e.clip);
                            e.q =
                                presnap.quotients::<T, R>(e.clip).filter(|_| usable).unwrap_or([f32::NAN; 2]);
                            e.state |= Cached::<T, S>::QUO;
                        }
                        q[k] = e.q;
                    }
                    if orientation(q) == cull_sign {
                        stats.back_faces += 1;
                        continue;
                    }
                }
                let mut at = [ScreenVertex::default(); 3];
                let mut ok = true;
                for (k, &j) in idx.iter().enumerate() {
                    let e = &mut cache[j];
                    if e.state & Cached::<T, S>::SNAP == 0 {
                        self.snap_entry::<R>(e, &presnap, cull_sign != 0);
                    }
                    if e.state & Cached::<T, S>::SNAPPED != 0 {
                        at[k] = e.screen;
                    } else {
                        ok = false;
                    }
                }
                if !ok {
                    stats.degenerate += 1;
                    continue;
                }
                if !self.keep(at.map(|v| v.pos), stats) {
                    continue;
                }
                self.complete::<R, _, _>(ctx, src, material, max, cache, idx, &mut at)?;
                sink(ScreenTriangle { v: at, flat: flat_shade }, stats)?;
                stats.emitted += 1;
                continue;
            }
            let face_n = self.face_normal(src, idx)?;
            // Clamped to finite values as `VertexCtx::color` clamps: the clipper
            // interpolates these.
            let light = |k: usize| {
                self.vertex_light_raw::<R, _, _>(ctx, src, material, idx[k], face_n).map(finite_color)
            };
            let cs = if flat_shade { [light(0)?; 3] } else { [light(0)?, light(1)?, light(2)?] };
            let clip = idx.map(|j| cache[j].clip);
            let vs = [0, 1, 2].map(|k| ClipVertex { pos: clip[k], attr: cs[k] });
            self.clip_and_emit::<R, 3>(vs, planes, stats, |mut at, attr, stats| {
                for (v, c) in at.iter_mut().zip(attr) {
                    v.color = channels(c, max);
                }
                sink(ScreenTriangle { v: at, flat: flat_shade }, stats)?;
                stats.emitted += 1;
                Ok(())
            })?;
        }
        Ok(())
    }
}

impl VertexSource for crate::mesh::Mesh<'_> {
    type Coord = f32;
    fn position(&self, i: usize) -> Option<[f32; 3]> {
        self.positions.get(i).copied()
    }
    fn normal(&self, i: usize) -> Option<[f32; 3]> {
        self.normals.get(i).copied()
    }
    fn has_normals(&self) -> bool {
        !self.normals.is_empty()
    }
    #[inline]
    fn vertex(&self, i: usize) -> usize {
        i
    }
}
