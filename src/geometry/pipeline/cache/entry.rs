//! The steps that fill one [`VertexCache`](super::VertexCache) entry on
//! demand, each at most once per vertex: snapping, the deferred depth and
//! `1/w`, and the lit colour (with the face normal where it lights).

use super::super::presnap::{PreSnap, depth_f32};
use super::super::tier::Tier;
use super::super::{Material, Pipeline, Shade, VertexCtx, channels};
use super::{Cached, VertexSource};
use crate::Error;
use crate::math::{Scalar, Vec3};
use crate::raster3d::ScreenVertex;

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// The screen vertices of a triangle that will be drawn (snapped,
    /// `SNAPPED`, inside the clip volume): each vertex's depth and `1/w`
    /// (deferred past culling, `snap_deferred`) and, with vertex normals,
    /// its lit colour are computed once and kept in `cache`. Inlined into
    /// its two callers' triangle loops (sixth pass: out of line, with seven
    /// arguments to marshal, the f32 knot was 2 % dearer).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(in crate::geometry::pipeline) fn complete<R: Tier, Src: VertexSource, M: Material<T>>(
        &self,
        ctx: &VertexCtx<T>,
        src: &Src,
        material: &M,
        max: [u8; 3],
        cache: &mut [Cached<T, S>],
        idx: [usize; 3],
        at: &mut [ScreenVertex<S>; 3],
    ) -> Result<(), Error> {
        let per_face = self.shade == Shade::Flat || !src.has_normals();
        for (k, &j) in idx.iter().enumerate() {
            let e = cache.get_mut(j).ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?;
            if e.state & Cached::<T, S>::DEPTH == 0 {
                self.depth_entry::<R>(e);
            }
            if !per_face && e.state & Cached::<T, S>::LIT == 0 {
                e.screen.color =
                    channels(self.vertex_light_raw::<R, _, _>(ctx, src, material, j, None)?, max);
                e.state |= Cached::<T, S>::LIT;
            }
            // Field by field: a whole-struct copy here became a `memcpy` call.
            let v = &mut at[k];
            (v.pos, v.depth, v.inv_w, v.color) =
                (e.screen.pos, e.screen.depth, e.screen.inv_w, e.screen.color);
        }
        if per_face {
            // Lit with the face normal: per triangle, not per vertex.
            let face_n = self.face_normal(src, idx)?;
            let c0 = channels(self.vertex_light_raw::<R, _, _>(ctx, src, material, idx[0], face_n)?, max);
            for (k, v) in at.iter_mut().enumerate() {
                v.color = if self.shade == Shade::Flat {
                    c0
                } else {
                    channels(self.vertex_light_raw::<R, _, _>(ctx, src, material, idx[k], face_n)?, max)
                };
            }
        }
        Ok(())
    }

    /// The face normal of triangle `idx` where it lights the vertices (flat
    /// shading, or a mesh without normals), as `Mesh::face_normal`; `None`
    /// otherwise. Positions are read only for a triangle that needs
    /// colours: most rejected ones (back faces) never get here.
    #[inline]
    pub(super) fn face_normal<Src: VertexSource>(
        &self,
        src: &Src,
        idx: [usize; 3],
    ) -> Result<Option<[f32; 3]>, Error> {
        if self.shade != Shade::Flat && src.has_normals() {
            return Ok(None);
        }
        let [Some(ra), Some(rb), Some(rc)] = idx.map(|j| src.position(j).map(|p| p.map(Src::Coord::to_f32)))
        else {
            return Err(Error::InvalidMesh(crate::MeshFault::Unchecked));
        };
        Ok(crate::mesh::face_normal_of([ra, rb, rc]))
    }

    /// The lit colour of slot `j`: with the face normal `face_n` where
    /// [`Pipeline::face_normal`] gives one, else with the vertex's normal.
    /// Not clamped to finite values ([`VertexCtx::color`] clamps): a colour
    /// that goes straight to [`channels`] needs no clamp, as `to_channel`
    /// maps +infinity to full intensity and NaN and −infinity to 0, as the
    /// clamp does. Inlined (sixth pass: f32 knot −0.8 %, Fx +0.3 %).
    #[inline(always)]
    pub(super) fn vertex_light_raw<R: Tier, Src: VertexSource, M: Material<T>>(
        &self,
        ctx: &VertexCtx<T>,
        src: &Src,
        material: &M,
        j: usize,
        face_n: Option<[f32; 3]>,
    ) -> Result<[T; 3], Error> {
        let flat = self.shade == Shade::Flat || !src.has_normals();
        // Normals go to the lighting as `f32`: a 16.16 normal (of length
        // about 1, below 2^8) converts exactly, and back to the same 16.16
        // value. Passing the mesh's type through instead (the lighting
        // generic over it) cost the f32 knot 1.5 % on the Cortex-M4F, code
        // generation unchanged in its operations.
        let n = if flat { face_n } else { src.normal(j).map(|n| n.map(Src::Coord::to_f32)) };
        let p =
            src.position(j).map(Vec3::from_data).ok_or(Error::InvalidMesh(crate::MeshFault::Unchecked))?;
        Ok(if M::UNIFORM {
            ctx.lit::<R>(p, n, |ctx: &VertexCtx<T>| ctx.base)
        } else {
            let base = material.base(ctx.base, 0, src.vertex(j));
            ctx.lit::<R>(p, n, move |_: &VertexCtx<T>| base)
        })
    }
}

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// Snaps cache entry `e` (its `SNAP` step). With usable quotients
    /// (`presnap`, `QUO`), snapping is their rounding, its depth deferred as
    /// [`Pipeline::snap_deferred`] does. Out of line: it runs once per
    /// vertex, the triangle loop around it per corner, and the loop keeps
    /// fewer values live without it (measured: Fx knot −2 %, f32 unchanged;
    /// the quotients' step out of line as well cost f32 +1.4 %).
    #[inline(never)]
    pub(in crate::geometry::pipeline) fn snap_entry<R: Tier>(
        &self,
        e: &mut Cached<T, S>,
        presnap: &PreSnap,
        presnapped: bool,
    ) {
        let screen = if presnapped && e.state & Cached::<T, S>::QUO != 0 && !e.q[0].is_nan() {
            let pos = presnap.snap(e.q);
            pos.map(|pos| ScreenVertex { pos, depth: 0, inv_w: 0, color: [0; 3] })
        } else {
            self.snap_deferred::<R>(e.clip)
        };
        e.state |= Cached::<T, S>::SNAP;
        if let Some(s) = screen {
            e.screen = s;
            e.state |= Cached::<T, S>::SNAPPED | if s.inv_w != 0 { Cached::<T, S>::DEPTH } else { 0 };
        }
    }

    /// The deferred depth and `1/w` of snapped entry `e` (its `DEPTH` step).
    /// Inline since [`Pipeline::complete`] is (sixth pass: out of line, the
    /// Fx knot was 0.6 % dearer, f32 the same).
    fn depth_entry<R: Tier>(&self, e: &mut Cached<T, S>) {
        let d = if crate::math::vec::is_float::<T>() {
            depth_f32::<R>(
                e.clip[2].to_f32(),
                e.clip[3].to_f32(),
                self.with_inv_w.then(|| self.w_ref.to_f32()),
            )
            .or_else(|| self.depth_general_cold::<R>(e))
        } else {
            self.depth_general::<R>(e)
        };
        if let Some((depth, inv_w)) = d {
            (e.screen.depth, e.screen.inv_w) = (depth, inv_w);
        }
        e.state |= Cached::<T, S>::DEPTH;
    }

    /// [`Pipeline::depth_entry`]'s depth and `1/w` by [`Pipeline::snap_depth`],
    /// the divisor rebuilt from the word `snap_deferred` kept in the depth:
    /// `Fx`'s only path, inline.
    #[inline(always)]
    fn depth_general<R: Tier>(&self, e: &Cached<T, S>) -> Option<(u32, u32)> {
        e.clip[3].divisor_from_word(e.screen.depth).and_then(|w| self.snap_depth::<R>(e.clip, w))
    }

    /// [`Pipeline::depth_general`] out of line, for `f32`, which takes it
    /// only where the fast quotients leave their range (`w_ref/w` beyond
    /// 2^10): inlined, its saturating depth cost the `f32` knot 0.1 %.
    #[cold]
    #[inline(never)]
    fn depth_general_cold<R: Tier>(&self, e: &Cached<T, S>) -> Option<(u32, u32)> {
        self.depth_general::<R>(e)
    }

    /// [`Pipeline::snap_vertex`] with the depth and `1/w` left for later
    /// (`inv_w` 0, which a snapped vertex never has) where they cannot
    /// fail: a back face needs neither, and they are two of its four
    /// divisions. They fail only for a non-finite `z` (`1/w` never; a depth
    /// beyond the quotient's range saturates, [`Pipeline::snap_depth`]).
    /// They are deferred with `z` finite and `|z| ≤ 128·w` (the domain of
    /// [`depth_f32`]; for `f32`, `128·w`
    /// exact, or infinite only for `w > 2^121`, where `|z/w| < 2^7` anyway;
    /// for `Fx`, saturated only for `w ≥ 2^8`, where `|z/w| < 2^7` too);
    /// otherwise computed now, so a vertex fails here exactly when
    /// [`Pipeline::snap_vertex`] fails.
    /// Until then the depth field holds [`Scalar::divisor_word`] of `w`
    /// (`Fx`: its reciprocal), so `Fx` does not prepare its divisor twice.
    fn snap_deferred<R: Tier>(&self, c: [T; 4]) -> Option<ScreenVertex<S>> {
        if !self.depth_deferrable(c) {
            return self.snap_vertex::<R>(c);
        }
        let w = c[3].divisor()?;
        let pos = self.snap_xy::<R>(c, w)?;
        Some(ScreenVertex { pos, depth: T::divisor_word(w), inv_w: 0, color: [0; 3] })
    }
}

impl<T: Scalar, const S: u32> Pipeline<T, S> {
    /// Whether [`Pipeline::snap_deferred`] leaves the depth of clip position
    /// `c` for later (its depth cannot fail): then snapping fails only where
    /// its position does.
    #[inline]
    pub(in crate::geometry::pipeline) fn depth_deferrable(&self, c: [T; 4]) -> bool {
        let (z, w) = (c[2], c[3]);
        z.is_finite() && z.abs() <= w * T::from_f32(128.0)
    }
}
