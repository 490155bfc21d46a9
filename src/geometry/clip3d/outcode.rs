//! Per-vertex plane tests in the clipper's scalar type: [`Ctx`] (the planes in
//! `T`: distances, outcodes, cut points, snapping and the final clamp) and the
//! classification of a triangle by its vertices' outcodes.

use super::planes::{PLANES, Plane, plane_dist};
use super::{ClipPlanes, INPUT_LIMIT};
use crate::math::Scalar;

/// The planes converted to `T`.
pub(super) struct Ctx<T> {
    pub(super) g: T,
    pub(super) w_min: T,
    pub(super) far: bool,
}

impl<T: Scalar> Ctx<T> {
    pub(super) fn new(p: ClipPlanes) -> Self {
        let w_min = T::from_f32(p.w_min());
        // Fx truncates values below 2^-16 to 0: use its smallest positive value.
        let w_min = if w_min > T::ZERO { w_min } else { T::from_f32(ClipPlanes::W_MIN) };
        Ctx { g: T::from_f32(p.guard_band()), w_min, far: p.far() }
    }

    /// Signed distance, `≥ 0` inside (exact sign for `f32`; conservative for Fx).
    pub(super) fn dist(&self, v: &[T; 4], p: Plane) -> T {
        plane_dist(self.g, self.w_min, *v, p)
    }

    /// Where `p` cuts the segment `a → b` (one end inside, one outside), as
    /// `t ∈ [0, 1]` from `a`. Computed in `f32` for both paths: Fx distances
    /// and their difference could saturate (`g·w` beyond 32768, say).
    pub(super) fn cut(&self, a: &[T; 4], b: &[T; 4], p: Plane) -> T {
        T::from_f32(self.cut_f32(a, b, p))
    }

    /// [`Ctx::cut`] before its conversion to `T`.
    pub(super) fn cut_f32(&self, a: &[T; 4], b: &[T; 4], p: Plane) -> f32 {
        let (g, w_min) = (self.g.to_f32(), self.w_min.to_f32());
        let da = plane_dist(g, w_min, a.map(T::to_f32), p);
        let t = da / (da - plane_dist(g, w_min, b.map(T::to_f32), p));
        if t >= 0.0 { t.min(1.0) } else { 0.0 } // NaN (0/0) → 0
    }

    pub(super) fn active(&self, p: Plane) -> bool {
        self.far || p != Plane::Far
    }

    pub(super) fn outcode(&self, v: &[T; 4]) -> u8 {
        let mut code = 0;
        for (i, &p) in PLANES.iter().enumerate() {
            if self.active(p) && self.dist(v, p) < T::ZERO {
                code |= 1 << i;
            }
        }
        code
    }

    /// Puts a new vertex exactly on the plane `p` it was cut at.
    pub(super) fn snap(&self, v: &mut [T; 4], p: Plane) {
        let gw = self.g * v[3];
        match p {
            Plane::W => v[3] = self.w_min,
            Plane::Near => v[2] = T::ZERO,
            Plane::Far => v[2] = v[3],
            Plane::XNeg => v[0] = -gw,
            Plane::XPos => v[0] = gw,
            Plane::YNeg => v[1] = -gw,
            Plane::YPos => v[1] = gw,
        }
    }

    /// Clamps away the rounding drift of later cuts: a no-op for a vertex
    /// inside every plane, and afterwards every inequality holds exactly.
    pub(super) fn settle(&self, v: &mut [T; 4]) {
        let clamp = |c: T, lo: T, hi: T| {
            if c < lo {
                lo
            } else if c > hi {
                hi
            } else {
                c
            }
        };
        if v[3] < self.w_min {
            v[3] = self.w_min;
        }
        if v[2] < T::ZERO {
            v[2] = T::ZERO;
        } else if self.far && v[2] > v[3] {
            v[2] = v[3];
        }
        let gw = self.g * v[3];
        v[0] = clamp(v[0], -gw, gw);
        v[1] = clamp(v[1], -gw, gw);
    }
}

/// What clipping would do to a triangle, from its positions alone.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// Inside every plane: [`clip_triangle`](super::clip_triangle) returns it unchanged.
    Inside,
    /// Outside one plane, or invalid (NaN, infinity, beyond ±2^64):
    /// [`clip_triangle`](super::clip_triangle) returns nothing.
    Outside,
    /// Crosses a plane: [`clip_triangle`](super::clip_triangle) cuts it.
    Crossing,
}

/// Classifies a triangle by its clip-space positions exactly as
/// [`clip_triangle`](super::clip_triangle) does, so a caller can skip per-vertex work (lighting)
/// for triangles that need no clipping and turn out to be back faces.
pub fn classify<T: Scalar>(pos: [[T; 4]; 3], planes: ClipPlanes) -> Class {
    let lim = T::from_f32(INPUT_LIMIT);
    if !pos.iter().flatten().all(|c| c.is_finite() && c.abs() <= lim) {
        return Class::Outside;
    }
    let c = Ctx::new(planes);
    let codes = pos.map(|p| c.outcode(&p));
    if codes[0] & codes[1] & codes[2] != 0 {
        Class::Outside
    } else if codes[0] | codes[1] | codes[2] == 0 {
        Class::Inside
    } else {
        Class::Crossing
    }
}

/// Per-vertex form of [`classify`], for callers that share vertices between
/// triangles: [`VertexClass::code`] of each vertex, then
/// [`VertexClass::class`] of three codes gives exactly [`classify`]'s result.
pub(crate) struct VertexClass<T>(Ctx<T>);

/// Set in a [`VertexClass::code`] for a vertex that makes its triangle
/// invalid (NaN, infinity, beyond ±2^64).
const INVALID: u8 = 0x80;
const _: () = assert!(PLANES.len() < 8);

impl<T: Scalar> VertexClass<T> {
    pub(crate) fn new(planes: ClipPlanes) -> Self {
        VertexClass(Ctx::new(planes))
    }

    /// The outcode of `pos` (bit `i`: outside `PLANES[i]`), or `INVALID`.
    pub(crate) fn code(&self, pos: &[T; 4]) -> u8 {
        let lim = T::from_f32(INPUT_LIMIT);
        if !pos.iter().all(|c| c.is_finite() && c.abs() <= lim) {
            return INVALID;
        }
        self.0.outcode(pos)
    }

    /// The class of a triangle from its vertices' codes.
    pub(crate) fn class(codes: [u8; 3]) -> Class {
        if (codes[0] | codes[1] | codes[2]) & INVALID != 0 || codes[0] & codes[1] & codes[2] != 0 {
            Class::Outside
        } else if codes[0] | codes[1] | codes[2] == 0 {
            Class::Inside
        } else {
            Class::Crossing
        }
    }
}
