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
use outcode::Ctx;
pub(crate) use outcode::VertexClass;
pub use outcode::{Class, classify};
pub use planes::{ClipPlanes, guard_band_for_fast_path, guard_band_for_limit, guard_band_for_range};
use planes::{PLANES, Plane};

mod outcode;
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

/// Largest accepted input magnitude, 2^64 (see the module docs). The
/// vertex stage returns [`Error::CoordinateOutOfRange`](crate::Error) for a
/// visible mesh with a clip coordinate beyond it, rather than let a
/// triangle be discarded here.
pub(crate) const INPUT_LIMIT: f32 = 18446744073709551616.0;

/// Most vertices a clipped triangle can have: each of the 7 planes adds at
/// most one to a convex polygon, so `3 + 7 = 10`.
pub const MAX_POLYGON_VERTICES: usize = 3 + PLANES.len();
const _: () = assert!(MAX_POLYGON_VERTICES == 10);

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
