//! The cached vertex path with a cache smaller than the mesh: the mesh's
//! triangles are taken in their own order, in chunks whose vertices fit the
//! cache, each chunk through [`Pipeline::draw_cached`] with its vertices in
//! local slots. RAM is the cache the caller gives, whatever the mesh's size.
//!
//! # Same triangles, same order
//! A vertex's transformed, snapped and lit values depend on the vertex
//! alone, not on the triangle or the slot it is cached in (which is why the
//! whole-mesh cache gives [`Pipeline::draw_valid_mesh`]'s triangles). The
//! chunks keep the index order, so the bins receive the same triangles in
//! the same order as with a cache for every vertex; a vertex shared by two
//! chunks is computed once in each.
//!
//! # Slots
//! A chunk grows triangle by triangle while its new vertices fit the
//! table's slots ([`CHUNK_SLOTS`] for a caller's cache, [`SMALL_SLOTS`] for
//! [`Pipeline::draw_valid_mesh`]'s own) or the cache, if smaller. Its mesh
//! vertices map to local slots through a table of twice as many buckets
//! with linear probing, at most half full, so a lookup ends after a few
//! probes. Each triangle's local slots are kept as it joins (a chunk of `C`
//! slots takes at most `2·C` triangles, more than a closed mesh's `2·C − 4`),
//! so drawing the chunk looks nothing up again. The table, the slot list
//! and the triangles live on the stack (about 650 bytes for 64 slots, 90
//! for 8).

use super::cache::{Cached, Slots};
use super::cluster::ClusterSource;
use super::tier::Tier;
use super::{ChunkMemo, Material, MeshSetup, MeshStats, Pipeline};
use crate::Error;
use crate::math::Scalar;
use crate::mesh::{MAX_MESHLET_VERTICES, Mesh};
use crate::raster3d::ScreenTriangle;

/// Most vertices of one chunk: a cluster's ([`ClusterCache`](super::ClusterCache)'s size).
pub(super) const CHUNK_SLOTS: usize = MAX_MESHLET_VERTICES;

/// The vertices of one chunk of [`Pipeline::draw_valid_mesh`], whose
/// cache is on the stack: at most 8.
pub(super) const SMALL_SLOTS: usize = 8;

/// Mesh vertex → local slot of the chunk being built or drawn: `C` slots
/// and `B` buckets (`B = 2·C`, a power of two, so the table is at most
/// half full).
pub(super) struct SlotTable<const B: usize, const C: usize> {
    /// Slot + 1 per bucket, 0 for an empty bucket.
    bucket: [u8; B],
    /// The mesh vertex of each slot.
    vertex: [u16; C],
    /// Slots in use.
    len: usize,
    /// The local slots of the chunk's triangles (`B` = 2·`C` at most).
    triangles: [[u8; 3]; B],
    /// Triangles in the chunk.
    count: usize,
}

/// The table of chunks of up to [`CHUNK_SLOTS`] vertices (a caller's cache).
pub(super) type WideTable = SlotTable<{ 2 * CHUNK_SLOTS }, CHUNK_SLOTS>;
/// The table of chunks of up to [`SMALL_SLOTS`] vertices.
pub(super) type SmallTable = SlotTable<{ 2 * SMALL_SLOTS }, SMALL_SLOTS>;

impl<const B: usize, const C: usize> SlotTable<B, C> {
    // Slots + 1 are stored as `u8`; the probe masks with `B − 1`.
    const SIZES: () = assert!(B.is_power_of_two() && B == 2 * C && C < 256);

    pub(super) fn new() -> Self {
        let () = Self::SIZES;
        SlotTable { bucket: [0; B], vertex: [0; C], len: 0, triangles: [[0; 3]; B], count: 0 }
    }

    fn clear(&mut self) {
        self.bucket = [0; B];
        self.len = 0;
        self.count = 0;
    }

    /// The bucket holding `v`, or the empty one where it would go: the
    /// table is never full (at most `C` of `B` used), so the probe ends.
    #[inline]
    fn find(&self, v: u16) -> usize {
        let mut h = usize::from(v) & (B - 1);
        loop {
            match self.bucket[h] {
                0 => return h,
                s if self.vertex[usize::from(s - 1)] == v => return h,
                _ => h = (h + 1) & (B - 1),
            }
        }
    }

    /// Adds triangle `t` and its vertices not yet held if, with them, at
    /// most `cap` slots and `B` triangles are used; else changes nothing and
    /// returns false.
    // Inlined: called once per triangle, and the Cortex-M0 build left it a
    // call once it kept the slots (+0.8 % on its per-band scene).
    #[inline(always)]
    fn add(&mut self, t: [u16; 3], cap: usize) -> bool {
        if self.count == B {
            return false;
        }
        let mut local = [0u8; 3];
        let mut added = [usize::MAX; 3];
        for (k, &v) in t.iter().enumerate() {
            let h = self.find(v);
            if self.bucket[h] != 0 {
                local[k] = self.bucket[h] - 1;
                continue;
            }
            if self.len == cap {
                // Undo this triangle's additions (in reverse: probes stay valid).
                for &b in added[..k].iter().rev().filter(|&&b| b != usize::MAX) {
                    self.bucket[b] = 0;
                    self.len -= 1;
                }
                return false;
            }
            self.vertex[self.len] = v;
            local[k] = self.len as u8;
            self.len += 1;
            self.bucket[h] = self.len as u8;
            added[k] = h;
        }
        self.triangles[self.count] = local;
        self.count += 1;
        true
    }
}

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// [`Pipeline::draw_cached`] over the whole of `mesh` with `cache`
    /// smaller than its vertex count, chunk by chunk (module docs), with
    /// `table` for its slots; every triangle goes to `sink` in the mesh's
    /// order, coloured by `material` (not per face). `memo` skips the
    /// chunks a record says miss the band, and records the others
    /// ([`super::chunk_record`]; `NoMemo` for none). `cache` has at least
    /// three entries.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn draw_chunked<R: Tier, M: Material<T>, const B: usize, const C: usize>(
        &self,
        _tier: R,
        setup: &MeshSetup<T>,
        mesh: &Mesh<'_>,
        material: &M,
        memo: &mut impl ChunkMemo<T>,
        cache: &mut [Cached<T, S>],
        table: &mut SlotTable<B, C>,
        inside: bool,
        stats: &mut MeshStats,
        mut sink: impl FnMut(ScreenTriangle<S>) -> Result<(), Error>,
    ) -> Result<(), Error> {
        let cap = cache.len().min(C);
        let mut rest = mesh.indices;
        while !rest.is_empty() {
            if let Some(n) = memo.skip(&setup.band) {
                rest = rest.get(n..).unwrap_or(&[]);
                continue;
            }
            table.clear();
            // A triangle has at most three new vertices and cap ≥ 3: every
            // chunk takes at least one triangle.
            let n = rest.iter().take_while(|&&t| table.add(t, cap)).count();
            rest = &rest[n..];
            let src = ClusterSource { mesh, vertices: &table.vertex[..table.len] };
            let triangles = table.triangles[..table.count].iter().map(|t| t.map(usize::from));
            let slots = Slots { slots: &mut cache[..table.len], inside };
            self.draw_cached::<R, _, _>(setup, &src, material, slots, triangles, stats, |tri, _| sink(tri))?;
            memo.drawn(n, &cache[..table.len], &setup.band);
        }
        Ok(())
    }
}
