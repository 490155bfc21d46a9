//! Varyings: a small fixed-size vector of per-vertex values (normals, texture
//! coordinates, …) interpolated over a screen triangle, affine or
//! perspective-correct, and a depth-tested fragment hook to consume them.
//!
//! [`draw_triangle`](crate::raster3d::draw_triangle) shades with per-vertex
//! colour only; [`Varyings`] and [`draw_fragments`] are for custom passes
//! (inside [`from_fn`](crate::render::from_fn)), and cost
//! nothing when unused.
//!
//! # Range and error
//! Values are integers (any fixed-point scale the caller chooses) with
//! `|v| ≤ 2^23`. Planes are exact to within 2^13 of their own units (`attr`).
//! * Affine: planes in units of 2^-20 of a value unit, so the rounded result
//!   is within **½ + 2^-7** of the screen-linear value.
//! * Perspective-correct: `q = 1/w` (normalised per triangle so the largest
//!   has 30 bits, exactly unless a vertex is nearer than `w_ref`) is a plane
//!   in units of 2^-16 and `v·q` one in units of 2^-3; each pixel divides
//!   `v = (v·q)/q`. With `Q` the pixel's normalised `q` (at least
//!   `2^29 · w_min/w_max` over the triangle's vertices), the result is within
//!   **½ + (2^10 + |v|/8)/(Q − 1/8)** of the exact value: for a triangle whose
//!   depth range is `w_max/w_min ≤ 16`, within ½ + 0.04.

use crate::attr::Plane;
use crate::band::BandView;
use crate::depth::{DepthFormat, DepthRows, DepthState};
use crate::edge::{Cull, TriangleSpans};
use crate::raster3d::{DEPTH_FRAC, Interpolation, ScreenTriangle, depth_value, normalised_q};
use crate::{Error, Interpolate};

/// Largest accepted magnitude of a varying (2^23).
pub const MAX_VARYING: i32 = 1 << 23;

const AFFINE_FRAC: u32 = 20;
const PERSP_FRAC: u32 = 3;
const Q_BITS: u32 = 30;

/// `A` values interpolated over one triangle.
///
/// ```
/// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
/// use microraster::varyings::Varyings;
/// use microraster::SubPoint;
/// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), inv_w: 1 << 30, ..Default::default() };
/// let tri = ScreenTriangle { v: [v(0, 0), v(16, 0), v(0, 16)], flat: false };
/// // u runs 0 → 1600 from left to right.
/// let uv = Varyings::new(&tri, [[0, 0], [1600, 0], [0, 1600]], Affine)?.unwrap();
/// assert_eq!(uv.at(7, 0)[0], 750); // centre x = 7.5 px → 7.5 · 100
/// # Ok::<(), microraster::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Varyings<const A: usize> {
    planes: [Plane; A],
    q: Option<Plane>,
}

impl<const A: usize> Varyings<A> {
    /// Planes through `values[i]` at vertex `i` of `tri`, interpolated as
    /// `interp` says ([`Affine`](crate::raster3d::Affine) or
    /// [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect)).
    /// `Ok(None)` for a zero-area triangle;
    /// [`Error::CoordinateOutOfRange`] for a value beyond [`MAX_VARYING`].
    pub fn new<M: Interpolation, const S: u32>(
        tri: &ScreenTriangle<S>,
        values: [[i32; A]; 3],
        interp: M,
    ) -> Result<Option<Self>, Error> {
        let _ = interp; // a value, so the call needs no turbofish
        if values.iter().flatten().any(|v| v.unsigned_abs() > MAX_VARYING as u32) {
            return Err(Error::CoordinateOutOfRange);
        }
        let Some(setup) = tri.plane_setup() else { return Ok(None) };
        let plane = |vals: [i64; 3]| Some(setup.plane(vals));
        let (q, scale) = if M::PERSPECTIVE {
            let q = normalised_q(tri, Q_BITS);
            let Some(qp) = plane(q.map(|q| q << DEPTH_FRAC)) else { return Ok(None) };
            (Some(qp), q.map(|q| q << PERSP_FRAC))
        } else {
            (None, [1 << AFFINE_FRAC; 3])
        };
        let mut planes = [Plane::default(); A];
        for (k, p) in planes.iter_mut().enumerate() {
            match plane([0, 1, 2].map(|i| values[i][k] as i64 * scale[i])) {
                Some(plane) => *p = plane,
                None => return Ok(None),
            }
        }
        Ok(Some(Varyings { planes, q }))
    }

    /// The values at the centre of pixel `(x, y)`, rounded to nearest.
    #[inline]
    pub fn at(&self, x: i32, y: i32) -> [i32; A] {
        match &self.q {
            None => self.planes.map(|p| round_shift(p.at(x, y), AFFINE_FRAC) as i32),
            Some(q) => {
                let q = q.at(x, y).max(1);
                self.planes.map(|p| div_shift_round(p.at(x, y), q, DEPTH_FRAC - PERSP_FRAC))
            }
        }
    }
}

/// `round(p · 2^s / q)` (ties away from zero) clamped to ±[`MAX_VARYING`],
/// for any `p`, `q ≥ 1` and `s ≤ 13`; for `q < 2^50` (every fragment) in two
/// `u64` divisions (`p·2^s` can exceed 64 bits; the remainder times `2^s`
/// cannot): `p·2^s = q1·q·2^s + r1·2^s`, and `q1·q·2^s` is a multiple of `q`.
#[inline]
fn div_shift_round(p: i64, q: i64, s: u32) -> i32 {
    if !(1..1 << 50).contains(&q) {
        // Outside the range of the fast form (not reached by fragments of a
        // triangle, whose q stays within its vertices'): the i128 quotient.
        let (n, q) = ((p as i128) << s, q.max(1) as i128);
        let r = if n >= 0 { (n + q / 2) / q } else { -((-n + q / 2) / q) };
        return r.clamp(-(MAX_VARYING as i128), MAX_VARYING as i128) as i32;
    }
    let (pa, q) = (p.unsigned_abs(), q as u64);
    let (q1, r1) = (pa / q, pa % q);
    let max = MAX_VARYING as u64;
    let r = if q1 > max { max } else { ((q1 << s) + ((r1 << s) + q / 2) / q).min(max) };
    if p < 0 { -(r as i32) } else { r as i32 }
}

fn round_shift(v: i64, s: u32) -> i64 {
    (v + (1 << (s - 1))) >> s
}

/// Rasterizes `tri` with the depth test of `state`, calling
/// `shade(x, y)` for every fragment that passes; the returned colour (if any)
/// is written, and then its depth (if `state.write`). `None` discards the
/// fragment: neither colour nor depth is written, so it does not occlude.
/// `depth` as for [`draw_triangle`](crate::raster3d::draw_triangle); every
/// parameter is inferred from the arguments.
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
/// use microraster::depth::{DepthRows, DepthState};
/// use microraster::raster3d::{ScreenTriangle, ScreenVertex};
/// use microraster::varyings::draw_fragments;
/// use microraster::{Band, SubPoint};
/// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), ..Default::default() };
/// let tri = ScreenTriangle { v: [v(0, 0), v(4, 0), v(0, 4)], flat: true };
/// let mut band = Band::<Gray8, 4, 4>::new(Gray8::BLACK);
/// let mut view = band.view(0, 4, Gray8::BLACK);
/// // No depth; column 0 discarded.
/// draw_fragments(&tri, &mut view, &mut DepthRows::none(), DepthState::DISABLED, |x, _| {
///     (x > 0).then_some(Gray8::WHITE)
/// });
/// assert_eq!(view.pixels().take(3).collect::<Vec<_>>(), [Gray8::BLACK, Gray8::WHITE, Gray8::WHITE]);
/// ```
pub fn draw_fragments<C, F, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    depth: &mut DepthRows<'_, F, W>,
    state: DepthState,
    mut shade: impl FnMut(i32, i32) -> Option<C>,
) where
    C: Interpolate,
    F: DepthFormat,
{
    for_each_fragment::<C, F, S, W>(tri, color, &mut *depth, state, |x, y, p| {
        shade(x, y).map(|c| *p = c).is_some()
    });
}

/// The depth-tested fragment loop of the fragment stage: like
/// [`draw_fragments`], but `visit(x, y, pixel)` gets the band's pixel to
/// read and write (for blending).
pub(crate) fn for_each_fragment<C, F, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
    mut visit: impl FnMut(i32, i32, &mut C) -> bool,
) where
    C: Interpolate,
    F: DepthFormat,
{
    use crate::blit::Blitter;
    let spans = TriangleSpans::new(tri.v.map(|v| v.pos), color.clip(), Cull::None);
    let zplane = if F::ENABLED {
        match tri.plane_setup() {
            Some(setup) => Some(setup.plane(tri.depth_values::<F>())),
            None => return,
        }
    } else {
        None
    };
    let y0 = color.y0();
    for span in spans {
        let (x0, len) = (span.x as usize, span.len as usize);
        let Some(cspan) = color.row_mut(span.y).and_then(|r| r.get_mut(x0..x0 + len)) else { continue };
        let mut drow = depth.get_mut((span.y - y0) as usize).and_then(|r| r.get_mut(x0..x0 + len));
        let (mut z, dz) = zplane.map_or((0, 0), |p| (p.at(span.x, span.y), p.step_x()));
        for (i, p) in cspan.iter_mut().enumerate() {
            match (&mut drow, F::ENABLED) {
                (Some(d), true) => {
                    let zq = depth_value::<F>(z);
                    let slot = &mut d[i];
                    // Depth after the visit: a discarded fragment (false)
                    // leaves it, and does not occlude.
                    if state.test.passes(zq, F::to_u32(*slot))
                        && visit(span.x + i as i32, span.y, p)
                        && state.write
                    {
                        *slot = F::from_u32(zq);
                    }
                }
                (None, true) => {}
                (_, false) => {
                    visit(span.x + i as i32, span.y, p);
                }
            }
            z = z.wrapping_add(dz);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reference(p: i64, q: i64, s: u32) -> i32 {
        let (n, q) = ((p as i128) << s, q.max(1) as i128);
        let r = if n >= 0 { (n + q / 2) / q } else { -((-n + q / 2) / q) };
        r.clamp(-(MAX_VARYING as i128), MAX_VARYING as i128) as i32
    }

    #[test]
    fn div_shift_round_equals_the_i128_quotient() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let edges = [0, 1, -1, i64::MAX, i64::MIN, 1 << 50, -(1 << 56), (1 << 56) + 12345];
        let mut n = 0;
        for i in 0..400_000 {
            let p = if i < 64 { edges[i % edges.len()] } else { (next() as i64) >> (next() % 64) };
            let q = if i % 7 == 0 {
                1 + (next() % 64) as i64
            } else {
                1 + ((next() >> (next() % 64)) as i64 & (i64::MAX - 1))
            };
            let s = (next() % 14) as u32;
            assert_eq!(div_shift_round(p, q, s), reference(p, q, s), "p {p} q {q} s {s}");
            n += 1;
        }
        assert_eq!(n, 400_000);
    }
}
