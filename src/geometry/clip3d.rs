//! Clipping in homogeneous clip space, before the perspective divide.
//!
//! Convention (D3D/Vulkan): a point `(x, y, z, w)` is in the view volume when
//! `−w ≤ x ≤ w`, `−w ≤ y ≤ w` and `0 ≤ z ≤ w`; `w = −z_view` for a
//! perspective projection, `w = 1` for an orthographic one.
//!
//! # Planes
//! [`clip_triangle`] and [`clip_line`] clip against up to seven planes
//! ([`ClipPlanes`]): `w ≥ w_min`, the near plane `z ≥ 0`, the far plane
//! `z ≤ w` (optional) and the guard band `|x| ≤ g·w`, `|y| ≤ g·w` with
//! `g ≥ 1`. X and y are clipped only at the guard band, not at the viewport:
//! a triangle partly off screen passes unchanged and the rasterizer's scissor
//! ([`ClipRect`](crate::ClipRect)) drops the hidden pixels; the band only keeps
//! coordinates in range after the divide ([`guard_band_for_range`],
//! [`guard_band_for_fast_path`]).
//!
//! # Guarantees of the output
//! Every output vertex satisfies, **exactly** as evaluated in `T`:
//! `w ≥ w_min > 0`, `0 ≤ z`, `z ≤ w` (far plane on) and `|x|, |y| ≤ g·w`
//! (`g·w` computed in `T`). New vertices are put exactly on their plane
//! (`z = 0` on the near plane, `w = w_min`, `x = ±g·w`, …) and a final clamp
//! removes the rounding drift of later cuts, so the divide gives `|x/w|,
//! |y/w| ≤ g` (`f32`: up to 2 ulp more) and `z/w ∈ [0, 1]`. Nothing behind the
//! eye survives: a triangle with all `w < 0` gives an empty polygon, one
//! crossing `w = 0` is cut at `w_min`/the near plane.
//!
//! Why `w ≥ w_min` on top of `z ≥ 0`: with a proper projection `z ≥ 0` means
//! `w ≥ near > 0`, but for arbitrary clip coordinates it says nothing about
//! `w`, and `0 ≤ z ≤ w` still allows `w = 0` (`0/0`). The guard band alone
//! already bounds `x/w` for any `w > 0`; `w_min` adds `w > 0` strictly and
//! bounds `1/w ≤ 1/w_min` (and `attribute/w`) for perspective-correct
//! interpolation. The default [`ClipPlanes::W_MIN`] `= 2^-16` is the smallest
//! positive [`Fx`](crate::math::Fx) (so there it is exactly `w > 0`); in `f32` it
//! gives `1/w ≤ 65536` and cuts nothing of a projection whose near distance is
//! at least `2^-16`.
//!
//! # Robustness
//! A primitive with any input component (position or attribute) that is NaN,
//! infinite or beyond ±2^64 is discarded (empty polygon / `None`); below that
//! bound no `f32` intermediate can overflow. [`Fx`](crate::math::Fx) inputs
//! are always accepted. Inside/outside tests run in `T` (for Fx a saturated
//! `g·w` acts as the plane `|x| ≤ 32768`); where a plane cuts an edge is
//! computed in `f32` on both paths, so an Fx cut is not thrown off by a
//! saturated distance (on parts without an FPU: a few soft-float operations
//! per cut, none for unclipped triangles). Whatever saturation does to a
//! vertex, the final clamp enforces every inequality above, so `w ≤ 0` never
//! gets through. Nothing here panics.
//!
//! # Watertightness
//! A cut edge's new vertex is always interpolated from its inside end towards
//! its outside end, and every triangle that is not trivially accepted meets
//! the same planes in the same order, so two triangles sharing an edge get
//! bit-identical vertices on it.
//!
//! ```
//! use microraster::clip3d::{ClipPlanes, ClipVertex, clip_triangle};
//! let v = |x: f32, z: f32, w: f32| ClipVertex { pos: [x, 0.5, z, w], attr: [x] };
//! // One vertex behind the eye (w < 0): cut at the near plane into a quad.
//! let poly = clip_triangle([v(0.0, 0.5, 1.0), v(1.0, -3.0, -1.0), v(-1.0, 0.5, 1.0)], ClipPlanes::DEFAULT);
//! assert_eq!(poly.vertices().len(), 4);
//! assert!(poly.vertices().iter().all(|v| v.pos[2] >= 0.0 && v.pos[3] > 0.0));
//! assert_eq!(poly.triangles().count(), 2);
//! ```

use crate::math::Scalar;
pub use planes::{ClipPlanes, guard_band_for_fast_path, guard_band_for_limit, guard_band_for_range};
use planes::{PLANES, Plane, plane_dist};

mod planes;

/// A clip-space vertex: position `[x, y, z, w]` and `A` attributes, which are
/// interpolated linearly in clip space when an edge is cut.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClipVertex<T: Scalar, const A: usize> {
    /// Homogeneous position `[x, y, z, w]`.
    pub pos: [T; 4],
    /// Attributes (colour, texture coordinates, …).
    pub attr: [T; A],
}

impl<T: Scalar, const A: usize> ClipVertex<T, A> {
    /// `self·(1 − t) + o·t` for `t ∈ [0, 1]`; the two-product form cannot
    /// overflow or saturate beyond the larger end.
    fn lerp(self, o: Self, t: T) -> Self {
        let s = T::ONE - t;
        ClipVertex {
            pos: core::array::from_fn(|i| self.pos[i] * s + o.pos[i] * t),
            attr: core::array::from_fn(|i| self.attr[i] * s + o.attr[i] * t),
        }
    }

    /// [`ClipVertex::lerp`] at a cut `t` computed in `f32`. `Fx` interpolates
    /// in `f32` too, with the same formula as the `f32` path: `t` rounded to
    /// 16.16 first is off by up to 2^-17, which moves a cut of a long edge
    /// by 2^-17 of its length (several pixels for an edge 10^4 long cut near
    /// its inside end; issue 13). `f32` is unchanged.
    fn lerp_at(self, o: Self, t: f32) -> Self {
        if crate::math::vec::is_float::<T>() {
            return self.lerp(o, T::from_f32(t));
        }
        let s = 1.0 - t;
        let mix = |a: T, b: T| T::from_f32(a.to_f32() * s + b.to_f32() * t);
        ClipVertex {
            pos: core::array::from_fn(|i| mix(self.pos[i], o.pos[i])),
            attr: core::array::from_fn(|i| mix(self.attr[i], o.attr[i])),
        }
    }

    fn is_valid(&self) -> bool {
        let lim = T::from_f32(INPUT_LIMIT);
        self.pos.iter().chain(self.attr.iter()).all(|c| c.is_finite() && c.abs() <= lim)
    }
}

/// Largest accepted input magnitude, 2^64 (see the module docs).
const INPUT_LIMIT: f32 = 18446744073709551616.0;

/// Most vertices a clipped triangle can have: each of the 7 planes adds at
/// most one to a convex polygon, so `3 + 7 = 10`.
pub const MAX_POLYGON_VERTICES: usize = 3 + PLANES.len();
const _: () = assert!(MAX_POLYGON_VERTICES == 10);

/// The planes converted to `T`.
struct Ctx<T> {
    g: T,
    w_min: T,
    far: bool,
}

impl<T: Scalar> Ctx<T> {
    fn new(p: ClipPlanes) -> Self {
        let w_min = T::from_f32(p.w_min());
        // Fx truncates values below 2^-16 to 0: use its smallest positive value.
        let w_min = if w_min > T::ZERO { w_min } else { T::from_f32(ClipPlanes::W_MIN) };
        Ctx { g: T::from_f32(p.guard_band()), w_min, far: p.far() }
    }

    /// Signed distance, `≥ 0` inside (exact sign for `f32`; conservative for Fx).
    fn dist(&self, v: &[T; 4], p: Plane) -> T {
        plane_dist(self.g, self.w_min, *v, p)
    }

    /// Where `p` cuts the segment `a → b` (one end inside, one outside), as
    /// `t ∈ [0, 1]` from `a`. Computed in `f32` for both paths: Fx distances
    /// and their difference could saturate (`g·w` beyond 32768, say).
    fn cut(&self, a: &[T; 4], b: &[T; 4], p: Plane) -> T {
        T::from_f32(self.cut_f32(a, b, p))
    }

    /// [`Ctx::cut`] before its conversion to `T`.
    fn cut_f32(&self, a: &[T; 4], b: &[T; 4], p: Plane) -> f32 {
        let (g, w_min) = (self.g.to_f32(), self.w_min.to_f32());
        let da = plane_dist(g, w_min, a.map(T::to_f32), p);
        let t = da / (da - plane_dist(g, w_min, b.map(T::to_f32), p));
        if t >= 0.0 { t.min(1.0) } else { 0.0 } // NaN (0/0) → 0
    }

    fn active(&self, p: Plane) -> bool {
        self.far || p != Plane::Far
    }

    fn outcode(&self, v: &[T; 4]) -> u8 {
        let mut code = 0;
        for (i, &p) in PLANES.iter().enumerate() {
            if self.active(p) && self.dist(v, p) < T::ZERO {
                code |= 1 << i;
            }
        }
        code
    }

    /// Puts a new vertex exactly on the plane `p` it was cut at.
    fn snap(&self, v: &mut [T; 4], p: Plane) {
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
    fn settle(&self, v: &mut [T; 4]) {
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

/// A clipped triangle: a convex polygon of 0 or 3 to [`MAX_POLYGON_VERTICES`]
/// vertices in the input's winding order, stored inline (no allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Polygon<T: Scalar, const A: usize> {
    verts: [ClipVertex<T, A>; MAX_POLYGON_VERTICES],
    len: usize,
}

impl<T: Scalar, const A: usize> Polygon<T, A> {
    const ZERO_VERTEX: ClipVertex<T, A> = ClipVertex { pos: [T::ZERO; 4], attr: [T::ZERO; A] };

    fn empty() -> Self {
        Polygon { verts: [Self::ZERO_VERTEX; MAX_POLYGON_VERTICES], len: 0 }
    }

    /// Appends `v`; false if full (only a numerically non-convex sliver can get there).
    fn push(&mut self, v: ClipVertex<T, A>) -> bool {
        let Some(slot) = self.verts.get_mut(self.len) else { return false };
        *slot = v;
        self.len += 1;
        true
    }

    /// The vertices, in the input triangle's winding order.
    pub fn vertices(&self) -> &[ClipVertex<T, A>] {
        &self.verts[..self.len]
    }

    /// True if nothing is left after clipping.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The polygon as a fan of triangles `(0, i, i + 1)`, each with the
    /// input's winding.
    pub fn triangles(&self) -> Triangles<'_, T, A> {
        Triangles { poly: self, next: 1 }
    }
}

/// Iterator over the fan triangles of a [`Polygon`] ([`Polygon::triangles`]).
#[derive(Debug, Clone)]
pub struct Triangles<'a, T: Scalar, const A: usize> {
    poly: &'a Polygon<T, A>,
    next: usize,
}

impl<T: Scalar, const A: usize> Iterator for Triangles<'_, T, A> {
    type Item = [ClipVertex<T, A>; 3];

    fn next(&mut self) -> Option<Self::Item> {
        let v = self.poly.vertices();
        let i = self.next;
        if i + 1 >= v.len() {
            return None;
        }
        self.next += 1;
        Some([v[0], v[i], v[i + 1]])
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.poly.len.saturating_sub(self.next + 1);
        (n, Some(n))
    }
}

impl<T: Scalar, const A: usize> ExactSizeIterator for Triangles<'_, T, A> {}

/// What clipping would do to a triangle, from its positions alone.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// Inside every plane: [`clip_triangle`] returns it unchanged.
    Inside,
    /// Outside one plane, or invalid (NaN, infinity, beyond ±2^64):
    /// [`clip_triangle`] returns nothing.
    Outside,
    /// Crosses a plane: [`clip_triangle`] cuts it.
    Crossing,
}

/// Classifies a triangle by its clip-space positions exactly as
/// [`clip_triangle`] does, so a caller can skip per-vertex work (lighting)
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

/// Clips a triangle against `planes` (Sutherland–Hodgman; see the module docs
/// for the guarantees). Inside all planes: returned unchanged; outside one
/// plane, with invalid input (NaN, infinity, beyond ±2^64) or degenerate
/// after clipping: empty.
pub fn clip_triangle<T: Scalar, const A: usize>(
    v: [ClipVertex<T, A>; 3],
    planes: ClipPlanes,
) -> Polygon<T, A> {
    let mut poly = Polygon::empty();
    if !v.iter().all(ClipVertex::is_valid) {
        return poly;
    }
    let c = Ctx::new(planes);
    let codes = v.map(|v| c.outcode(&v.pos));
    if codes[0] & codes[1] & codes[2] != 0 {
        return poly;
    }
    poly.verts[..3].copy_from_slice(&v);
    poly.len = 3;
    if codes[0] | codes[1] | codes[2] == 0 {
        return poly;
    }
    let mut next = Polygon::empty();
    for p in PLANES {
        if !c.active(p) {
            continue;
        }
        if !clip_polygon(&c, p, &poly, &mut next) || next.len < 3 {
            return Polygon::empty();
        }
        core::mem::swap(&mut poly, &mut next);
    }
    for v in &mut poly.verts[..poly.len] {
        c.settle(&mut v.pos);
    }
    poly
}

/// One Sutherland–Hodgman step of `src` against `p` into `dst`; false on overflow.
fn clip_polygon<T: Scalar, const A: usize>(
    c: &Ctx<T>,
    p: Plane,
    src: &Polygon<T, A>,
    dst: &mut Polygon<T, A>,
) -> bool {
    dst.len = 0;
    let v = src.vertices();
    let Some(&last) = v.last() else { return true };
    let (mut prev, mut dp) = (last, c.dist(&last.pos, p));
    for &cur in v {
        let dc = c.dist(&cur.pos, p);
        let (pin, cin) = (dp >= T::ZERO, dc >= T::ZERO);
        if pin != cin {
            // Always from the inside end: shared edges give identical vertices.
            let (a, b) = if pin { (prev, cur) } else { (cur, prev) };
            let mut x = a.lerp_at(b, c.cut_f32(&a.pos, &b.pos, p));
            c.snap(&mut x.pos, p);
            if !dst.push(x) {
                return false;
            }
        }
        if cin && !dst.push(cur) {
            return false;
        }
        (prev, dp) = (cur, dc);
    }
    true
}

/// Clips the segment `a → b` against `planes` (parametric, Liang–Barsky).
/// `None` if nothing is left or the input is invalid (NaN, infinity, beyond
/// ±2^64); otherwise the clipped ends in the same direction, with the same
/// guarantees as [`clip_triangle`].
pub fn clip_line<T: Scalar, const A: usize>(
    a: ClipVertex<T, A>,
    b: ClipVertex<T, A>,
    planes: ClipPlanes,
) -> Option<(ClipVertex<T, A>, ClipVertex<T, A>)> {
    if !a.is_valid() || !b.is_valid() {
        return None;
    }
    let c = Ctx::new(planes);
    let (ca, cb) = (c.outcode(&a.pos), c.outcode(&b.pos));
    if ca & cb != 0 {
        return None;
    }
    if ca | cb == 0 {
        return Some((a, b));
    }
    let (mut t0, mut p0, mut t1, mut p1) = (T::ZERO, None, T::ONE, None);
    for p in PLANES {
        let (da, db) = (c.dist(&a.pos, p), c.dist(&b.pos, p));
        if !c.active(p) || (da >= T::ZERO && db >= T::ZERO) {
            continue;
        }
        // One end outside (both outside was rejected above): t ∈ [0, 1].
        let t = c.cut(&a.pos, &b.pos, p);
        if da < T::ZERO {
            if p0.is_none() || t > t0 {
                (t0, p0) = (t, Some(p));
            }
        } else if p1.is_none() || t < t1 {
            (t1, p1) = (t, Some(p));
        }
    }
    if t0 > t1 {
        return None;
    }
    let end = |t: T, p: Option<Plane>, v: ClipVertex<T, A>| {
        let mut v = if let Some(p) = p {
            let mut x = a.lerp(b, t);
            c.snap(&mut x.pos, p);
            x
        } else {
            v
        };
        c.settle(&mut v.pos);
        v
    };
    Some((end(t0, p0, a), end(t1, p1, b)))
}

#[cfg(test)]
mod tests;
