//! The vertex stage of a cluster inside the view volume, vertex first: when
//! a meshlet's bounding sphere lies inside the clip volume
//! ([`super::inside`]), no vertex needs clipping and none can fail to
//! snap for want of range. So the pass that computes each vertex's clip
//! `y`, `w` and band side also snaps the vertices near the band, and each
//! triangle's back-face and band tests are integer tests on its snapped
//! corners. A vertex beyond the band's margin is snapped only if a triangle
//! across the band needs it.
//!
//! # Why not lazily, as [`super::cache`] does
//! The cached path computes a vertex only as far as a triangle needs it,
//! and pays for that in every triangle: flag tests per corner, outcodes,
//! the floating pre-snap orientation with its margin. On a real mesh
//! (about two triangles per vertex, half of them back faces) nearly every
//! vertex near the band is snapped anyway, so the triangle loop's
//! bookkeeping cost more than the snapping it saved (`docs/setup_cost.md`,
//! sixth pass). Depth and colour stay lazy: only a drawn triangle's
//! vertices need them.
//!
//! # Same triangles as the cached path
//! The snapped position is the same rounding of the same clip position
//! ([`PreSnap::snap_inside`], else [`Pipeline::snap_entry`]), the band
//! sides are the same clip-space test ([`Band`]), and a triangle is drawn
//! exactly when the cached path draws it: not on one side of the band, its
//! vertices snapped, its snapped area non-zero and not culled, its snapped
//! rows meeting the band ([`Pipeline::keep`]).
//! The cached path's pre-snap orientation only decides early what the
//! snapped area decides, so the back faces and degenerate triangles counted
//! in [`MeshStats`] are the same too. Depth, `1/w` and colours come from
//! [`Pipeline::complete`], as there.

use super::cache::{Cached, VertexSource};
use super::presnap::PreSnap;
use super::tier::Tier;
use super::{Band, Material, MeshSetup, MeshStats, Pipeline, Shade, VertexCtx};
use crate::Error;
use crate::math::{Scalar, Vec3};
use crate::mesh::MAX_MESHLET_VERTICES;
use crate::primitive::center_rows;
use crate::raster3d::{ScreenTriangle, ScreenVertex};

/// A vertex's band sides ([`Band`]): either bit set puts it beyond the band.
const SIDES: u8 = Band::<f32>::ABOVE | Band::<f32>::BELOW;

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// [`Pipeline::draw_cached`] for the slots of one cluster whose vertices
    /// all lie inside the clip volume (module docs): the same triangles to
    /// `sink`, in order, with the same vertices and colours. The first
    /// `count` entries of `cache` hold the slots of `src` and are
    /// overwritten.
    ///
    /// Returns the last frame row any of the cluster's triangles can cover
    /// where this band shows it ([`Pipeline::last_row`]), else `None`.
    ///
    /// Errors: [`Error::InvalidParameter`] for a per-face `material`;
    /// [`Error::InvalidMesh`] for a slot beyond `cache` or `src` (one below
    /// 64 may instead drop its triangle, see the `states` comment), and
    /// whatever `sink` returns.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn draw_inside<R: Tier, Src: VertexSource, M: Material<T>>(
        &self,
        setup: &MeshSetup<T>,
        src: &Src,
        material: &M,
        cache: &mut [Cached<T, S>; MAX_MESHLET_VERTICES],
        count: usize,
        triangles: &[[u8; 3]],
        stats: &mut MeshStats,
        mut sink: impl FnMut(&ScreenTriangle<S>, &mut MeshStats) -> Result<(), Error>,
    ) -> Result<Option<i32>, Error> {
        if M::PER_FACE {
            return Err(Error::InvalidParameter(crate::Param::FaceColors));
        }
        let MeshSetup { ctx, max, band, .. } = setup;
        let presnap = PreSnap::new::<T>(self.size, self.origin, S);

        // Clip y and w and the band test of every vertex (as the cached
        // path); a vertex near the band is snapped now, one beyond its
        // margin only if a triangle reaching into the band needs it.
        //
        // The vertices' band sides and snap flags again, in a local array
        // indexed by a masked slot: the triangle loop, which runs over every
        // triangle of the cluster in every band it reaches, reads three of
        // them without bounds checks. A validated mesh has no slot beyond
        // its cluster. One would read another slot's flags here (0 below 64,
        // so its triangle goes on to the snapping): at 64 or beyond it is
        // reported as `InvalidMesh`; below 64 the slot's entry is left from
        // an earlier cluster, and its triangle is either `InvalidMesh` (the
        // entry not snapped: `src` has no such slot) or dropped as
        // degenerate (its flags here never show a snap). Nothing is drawn
        // from another cluster's entry.
        let mut states = [0u8; MAX_MESHLET_VERTICES];
        let (mut all_sides, mut any_side) = (SIDES, 0);
        let slots = cache.get_mut(..count).ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?;
        for (i, e) in slots.iter_mut().enumerate() {
            let p = src
                .position(i)
                .map(Vec3::from_data)
                .ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?;
            let yw = ctx.yw(p);
            let side = band.side(yw);
            e.state = side;
            all_sides &= side;
            any_side |= side;
            if side == 0 {
                // Inlined in `f32`, a call in `Fx`: the knot's cheapest
                // layout for both (Cortex-M4F, `fw_bench`; inlined in both,
                // `Fx` +1.5 %; left to LLVM, `f32` +1.1 %).
                if crate::math::vec::is_float::<T>() {
                    self.snap_slot_inlined::<R>(ctx, &presnap, e, p, yw);
                } else {
                    self.snap_slot::<R>(ctx, &presnap, e, p, yw);
                }
            } else {
                e.clip = [T::ZERO, yw.0, T::ZERO, yw.1];
            }
            states[i % MAX_MESHLET_VERTICES] = e.state;
        }
        // Only a band with rows of the viewport below it has a use for it.
        let below =
            self.rows.is_some_and(|(_, y1)| i64::from(y1) + 1 < self.origin.1 + i64::from(self.size.1));
        let last = if below && any_side & Band::<f32>::BELOW == 0 { self.last_row(slots) } else { None };
        if all_sides != 0 {
            return Ok(last);
        }
        let flat = self.shade == Shade::Flat;
        for t in triangles {
            let idx = t.map(usize::from);
            let state = |s: &[u8; MAX_MESHLET_VERTICES], j: usize| s[j % MAX_MESHLET_VERTICES];
            let mut shared = state(&states, idx[0]) & state(&states, idx[1]) & state(&states, idx[2]);
            if shared & SIDES != 0 {
                continue;
            }
            if shared & Cached::<T, S>::SNAP == 0 {
                // A corner beyond the band's margin, of a triangle across it.
                for &j in &idx {
                    let e = cache.get_mut(j).ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?;
                    if e.state & Cached::<T, S>::SNAP == 0 {
                        let p = src
                            .position(j)
                            .map(Vec3::from_data)
                            .ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?;
                        self.snap_slot::<R>(ctx, &presnap, e, p, (e.clip[1], e.clip[3]));
                        states[j % MAX_MESHLET_VERTICES] = e.state;
                    }
                }
                shared = state(&states, idx[0]) & state(&states, idx[1]) & state(&states, idx[2]);
            }
            if shared & Cached::<T, S>::SNAPPED == 0 {
                stats.degenerate += 1;
                continue;
            }
            // A corner that got here has a snapped state, so its slot is
            // below `count`; one beyond 64 would have read another slot's
            // state above. One test for the three, then no bounds checks.
            if (idx[0] | idx[1] | idx[2]) >= MAX_MESHLET_VERTICES {
                return Err(Error::InvalidMesh(crate::MeshFault::Unchecked));
            }
            let idx = idx.map(|j| j % MAX_MESHLET_VERTICES);
            let pos = idx.map(|j| cache[j].screen.pos);
            if !self.keep(pos, stats) {
                continue;
            }
            // Filled in place and lent to the sink: no copies of the triangle.
            let mut tri = ScreenTriangle { v: [ScreenVertex::default(); 3], flat };
            self.complete::<R, _, _>(ctx, src, material, *max, cache.as_mut_slice(), idx, &mut tri.v)?;
            sink(&tri, stats)?;
            stats.emitted += 1;
        }
        Ok(last)
    }

    /// The last frame row a triangle of the cluster in `cache` can cover,
    /// after its `y`/`w` pass found no vertex below the band's margin: every
    /// vertex is then above the band (its screen `y` below `y0 − 0.9`,
    /// [`Band`]'s margin less its error) or snapped, and a triangle covers
    /// no row whose centre lies below its lowest vertex. `None` if a vertex
    /// in the band did not snap, or without band rows.
    fn last_row(&self, cache: &[Cached<T, S>]) -> Option<i32> {
        let (y0, _) = self.rows?;
        // The band's first row is at most 2^12, a snapped `y` at most 2^28
        // in magnitude: `i32::MIN` is below every row's `y`.
        let mut lowest = i32::MIN;
        for e in cache.iter().filter(|e| e.state & SIDES == 0) {
            if e.state & Cached::<T, S>::SNAPPED == 0 {
                return None;
            }
            lowest = lowest.max(e.screen.pos.y());
        }
        Some(if lowest == i32::MIN { y0 - 1 } else { center_rows::<S>(lowest, lowest).1.max(y0 - 1) })
    }

    /// Transforms and snaps cache entry `e` of model position `p` (clip
    /// `yw` known): its whole clip position (outcode 0: inside the clip
    /// volume) and its snapped position, by [`PreSnap::snap_inside`] where
    /// it applies, else as [`Pipeline::snap_entry`] snaps (the same
    /// position; depth and `1/w` deferred where they cannot fail).
    #[inline(never)]
    fn snap_slot<R: Tier>(
        &self,
        ctx: &VertexCtx<T>,
        presnap: &PreSnap,
        e: &mut Cached<T, S>,
        p: Vec3<T>,
        yw: (T, T),
    ) {
        self.snap_slot_inlined::<R>(ctx, presnap, e, p, yw)
    }

    /// [`Pipeline::snap_slot`], always inlined.
    #[inline(always)]
    fn snap_slot_inlined<R: Tier>(
        &self,
        ctx: &VertexCtx<T>,
        presnap: &PreSnap,
        e: &mut Cached<T, S>,
        p: Vec3<T>,
        yw: (T, T),
    ) {
        e.clip = ctx.position(p, yw);
        e.code = 0;
        if let Some(pos) = presnap.snap_inside::<T, S, R>(e.clip) {
            e.screen = ScreenVertex { pos, depth: 0, inv_w: 0, color: [0; 3] };
            e.state |= Cached::<T, S>::CLIP | Cached::<T, S>::SNAP | Cached::<T, S>::SNAPPED;
        } else {
            e.state |= Cached::<T, S>::CLIP;
            self.snap_entry::<R>(e, presnap, false);
        }
    }
}
