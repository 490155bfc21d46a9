//! What the meshlet stage learns about each cluster once per frame instead
//! of once per band: the verdicts that do not depend on the band (outside
//! the view volume, facing away, inside the clip volume) and the frame rows
//! its bounding sphere can reach. Each band then skips a cluster whose rows
//! miss it with two integer comparisons, and runs the `f32` slab test (a
//! library call per operation on the Cortex-M0) only for the few near it.
//!
//! # Same clusters drawn
//! A band still draws exactly the clusters the per-band tests
//! ([`ClusterCull`], [`InsideView`]) keep, except those whose recorded rows
//! miss the band: their sphere, and so every triangle of the cluster
//! (validated to lie inside it), lies above or below the band, so they have
//! nothing in it. The image is the same; `MeshStats::clusters_outside`
//! counts them with the other clusters outside.
//!
//! # The rows of a sphere
//! A conservative interval, widened for rounding, snapping and the
//! top-left rule ([`super::sphere_rows`]). It reaches further than the
//! cluster's triangles (a median of 32 rows on the knot), so a band that
//! finds no vertex of a cluster below it lowers the cluster's last row to
//! what its snapped vertices reach ([`ClusterFrame::narrow`]), and the
//! bands below skip it.
//!
//! # When the record is built
//! A record belongs to a key: the mesh, matrix, clip planes, culling and
//! viewport of the call ([`FrameKey`]). Up to the cache's `MESHES` keys
//! ([`FRAME_MESHES`] unless told) keep records at once, sharing the
//! capacity (the cache's `CLUSTERS`, [`FRAME_CLUSTERS`] unless told), so
//! meshes drawn in turn through one cache (a `View3d` scene's meshlet
//! objects) each get one. A key's first
//! call is tested per band alone; its next call, in a band below, builds
//! its record, and later bands of the frame use it. A call whose band does
//! not start below its key's previous call starts a new frame: every
//! record is dropped, so a stale record is never read. Clusters beyond the
//! capacity are tested per band, as are the meshes of a key that lost its
//! place to another.

use super::cluster::ClusterCull;
use super::inside::InsideView;
use super::sphere_rows::SphereRows;
use crate::clip3d::ClipPlanes;
use crate::edge::Cull;
use crate::math::Vec4;
use crate::mesh::Meshlet;

/// Clusters per mesh whose verdicts a [`ClusterCache`](super::ClusterCache)
/// records unless its type says otherwise (the knot has 216).
pub const FRAME_CLUSTERS: usize = 256;

/// One cluster's record: its frame rows (inclusive) and verdicts.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct ClusterFrame {
    top: i16,
    bottom: i16,
    flags: u8,
}

impl ClusterFrame {
    /// Outside the view volume (as the per-band view test says).
    pub(super) const OUTSIDE: u8 = 1;
    /// Facing away from the eye (its normal cone).
    pub(super) const AWAY: u8 = 2;
    /// Inside the clip volume ([`InsideView::contains`]).
    pub(super) const INSIDE: u8 = 4;

    /// True if the cluster may have a triangle in frame rows `rows`.
    #[inline]
    pub(super) fn reaches(&self, (y0, y1): (i32, i32)) -> bool {
        i32::from(self.bottom) >= y0 && i32::from(self.top) <= y1
    }

    /// The verdict bits.
    #[inline]
    pub(super) fn flags(&self) -> u8 {
        self.flags
    }

    /// Lowers the cluster's last row to `last` where that is below it: the
    /// vertex stage found, drawing the cluster into a band, that none of its
    /// triangles covers a row below `last` (`Pipeline::draw_inside`), and
    /// the bands below then skip it. The record stays conservative: it is
    /// this frame's, for this key's matrix and viewport.
    #[inline]
    pub(super) fn narrow(&mut self, last: i32) {
        if last < i32::from(self.bottom) {
            self.bottom = last.max(i32::from(i16::MIN)) as i16;
        }
    }
}

/// What the record was built for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct FrameKey {
    /// The clusters' address and count.
    pub(super) mesh: (usize, usize),
    /// The model-view-projection matrix's rows, as `f32` bits.
    pub(super) mvp: [[u32; 4]; 4],
    pub(super) planes: ClipPlanes,
    pub(super) cull: Cull,
    pub(super) size: (u32, u32),
    pub(super) origin: (i64, i64),
}

/// Meshes (keys) whose records a [`ClusterCache`](super::ClusterCache)
/// keeps at once unless its type says otherwise.
pub const FRAME_MESHES: usize = 4;

/// One key's place in the record.
#[derive(Clone, Copy)]
struct Slot {
    key: Option<FrameKey>,
    /// Whether `entries[start..start + len]` hold `key`'s record for this
    /// frame.
    built: bool,
    /// First row of the band `key` was last drawn in.
    last_row: i32,
    start: usize,
    len: usize,
}

impl Slot {
    const FREE: Slot = Slot { key: None, built: false, last_row: i32::MAX, start: 0, len: 0 };
}

/// The per-frame record of a [`ClusterCache`](super::ClusterCache).
pub(super) struct FrameClusters<const N: usize, const M: usize> {
    slots: [Slot; M],
    /// Entries taken by this frame's records.
    used: usize,
    /// The slot a new key takes when none is free (in turn).
    next: usize,
    entries: [ClusterFrame; N],
}

impl<const N: usize, const M: usize> FrameClusters<N, M> {
    pub(super) const EMPTY: Self = FrameClusters {
        slots: [Slot::FREE; M],
        used: 0,
        next: 0,
        entries: [ClusterFrame { top: 0, bottom: 0, flags: 0 }; N],
    };

    /// The record for `key` in the band starting at `first_row`: empty (test
    /// every cluster per band) on a key's first call or a new frame, built
    /// on the key's next call, then reused (module docs).
    pub(super) fn prepare(
        &mut self,
        key: FrameKey,
        first_row: i32,
        meshlets: &[Meshlet],
        rows: [Vec4<f32>; 4],
        cull: &ClusterCull,
        inside: &InsideView,
    ) -> &mut [ClusterFrame] {
        if N == 0 || M == 0 {
            return &mut [];
        }
        let Some(i) = self.slot_for(key, first_row) else { return &mut [] };
        if !self.slots[i].built {
            let (start, len) = self.claim(i, meshlets.len());
            let reach = SphereRows::new(rows, key.size.1, key.origin.1);
            for (e, m) in self.entries[start..start + len].iter_mut().zip(meshlets) {
                let outside = !cull.view_keeps(m);
                let away = !outside && cull.faces_away(m);
                let within = !outside && !away && inside.contains(m.sphere);
                // A cluster outside the view is skipped in every band whatever
                // its rows; one facing away needs them (a band counts it
                // outside or facing away as the per-band tests would).
                let rows = if outside { None } else { reach.rows(m.sphere) };
                let (top, bottom) = rows.unwrap_or((i16::MIN, i16::MAX));
                let flags = (outside as u8 * ClusterFrame::OUTSIDE)
                    | (away as u8 * ClusterFrame::AWAY)
                    | (within as u8 * ClusterFrame::INSIDE);
                *e = ClusterFrame { top, bottom, flags };
            }
        }
        let (start, len) = (self.slots[i].start, self.slots[i].len);
        self.entries.get_mut(start..start + len).unwrap_or(&mut [])
    }

    /// The slot whose record serves `key` in the band starting at
    /// `first_row` (built now if it is not yet), or `None`: that band tests
    /// its clusters alone (module docs).
    fn slot_for(&mut self, key: FrameKey, first_row: i32) -> Option<usize> {
        match self.slots.iter().position(|s| s.key == Some(key)) {
            Some(i) if first_row > self.slots[i].last_row => {
                self.slots[i].last_row = first_row;
                Some(i)
            }
            Some(i) => {
                // Not below this key's last band: a new frame, in which
                // every record is stale.
                for s in &mut self.slots {
                    s.built = false;
                }
                self.used = 0;
                self.slots[i].last_row = first_row;
                None
            }
            None => {
                // A key not seen lately: a free slot, else the next in
                // turn; a record only if it is drawn again in a band below.
                let i = self.slots.iter().position(|s| s.key.is_none()).unwrap_or(self.next);
                let slot = self.slots.get_mut(i)?; // none when M = 0
                *slot = Slot { key: Some(key), last_row: first_row, ..Slot::FREE };
                self.next = (i + 1) % M.max(1);
                None
            }
        }
    }

    /// Marks slot `i` built with room for up to `clusters` entries, what is
    /// left of the capacity (clusters beyond it are tested per band), and
    /// returns that room as `(start, len)`.
    fn claim(&mut self, i: usize, clusters: usize) -> (usize, usize) {
        let start = self.used.min(N);
        let len = clusters.min(N - start);
        self.used = start + len;
        let slot = &mut self.slots[i];
        (slot.built, slot.start, slot.len) = (true, start, len);
        (start, len)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `narrow` only ever lowers the last row (a band's finding cannot
    /// widen the bound), saturates below `i16`, and the cluster then stops
    /// reaching the bands below that row.
    #[test]
    fn narrowing_only_lowers_the_last_row() {
        let mut f = ClusterFrame { top: 10, bottom: 60, flags: 0 };
        assert!(f.reaches((48, 63)));
        f.narrow(47);
        assert_eq!((f.top, f.bottom), (10, 47));
        assert!(!f.reaches((48, 63)) && f.reaches((32, 47)));
        f.narrow(55); // a later, looser finding changes nothing
        assert_eq!(f.bottom, 47);
        f.narrow(i32::MIN);
        assert_eq!(f.bottom, i16::MIN);
        assert!(!f.reaches((0, 15)));
    }

    /// The record's bookkeeping over bands: one key records from its
    /// second band; keys drawn in turn each record, sharing the capacity;
    /// a band not below a key's last starts a new frame and drops every
    /// record; a fifth key takes a place in turn.
    #[test]
    fn keys_in_turn_each_record_until_a_new_frame() {
        let key = |k: usize| FrameKey {
            mesh: (0x1000 * k, 216),
            mvp: [[k as u32; 4]; 4],
            planes: ClipPlanes::for_viewport_fast_path(320, 240, 4),
            cull: Cull::Clockwise,
            size: (320, 240),
            origin: (0, 0),
        };
        let mut f = FrameClusters::<256, 4>::EMPTY;
        // What a band gets for key k: Some((start, len)) of its record.
        let band = |f: &mut FrameClusters<256, 4>, k: usize, row: i32| {
            let i = f.slot_for(key(k), row)?;
            if !f.slots[i].built {
                f.claim(i, 100);
            }
            Some((f.slots[i].start, f.slots[i].len))
        };
        for frame in 0..3 {
            // Two meshes in turn: both record from the second band, the
            // second with what the first left (56 of its 100).
            assert_eq!((band(&mut f, 1, 0), band(&mut f, 2, 0)), (None, None), "frame {frame}");
            assert!(!f.slots.iter().any(|s| s.built), "frame {frame}: last frame's records dropped");
            for row in [16, 32, 224] {
                assert_eq!(band(&mut f, 1, row), Some((0, 100)), "frame {frame}");
                assert_eq!(band(&mut f, 2, row), Some((100, 100)), "frame {frame}");
            }
        }
        // A third mesh appears mid-frame: the rest of the capacity.
        let _ = (band(&mut f, 1, 0), band(&mut f, 2, 0), band(&mut f, 3, 0));
        assert_eq!((band(&mut f, 1, 16), band(&mut f, 2, 16), band(&mut f, 3, 16)).2, Some((200, 56)));
        // Five keys in turn: each takes another's place, none records.
        for row in [32, 48, 64] {
            for k in 4..9 {
                assert_eq!(band(&mut f, k, row), None, "{k} {row}");
            }
        }
        // One key drawn twice per band: its second call is not below the
        // first, so it starts a new frame, and the next band's first call
        // builds the record again (correct; the same mesh and matrix twice
        // per band is best drawn once).
        let mut g = FrameClusters::<256, 4>::EMPTY;
        assert_eq!((band(&mut g, 1, 0), band(&mut g, 1, 0)), (None, None));
        for row in [16, 32] {
            assert_eq!((band(&mut g, 1, row), band(&mut g, 1, row)), (Some((0, 100)), None));
            assert!(!g.slots.iter().any(|s| s.built), "dropped");
        }
    }
}
