//! The 3D fragment loop: coverage from [`TriangleSpans`], then per pixel a
//! depth test against the band's z-buffer and a colour, flat, affine or
//! perspective-correct.
//!
//! # What is interpolated, and how
//! * **Depth** `d = z/w` is linear in screen space, so it is a plane in units
//!   of 2^-16 depth steps ([`DEPTH_FRAC`]); the stored value is that plane
//!   rounded to nearest. Interpolation error is below 2^13 units (see
//!   `attr`), i.e. 1/8 of a depth step, before the final rounding.
//! * **Colour**, affine ([`Affine`]): each channel is a screen-space plane,
//!   exactly as 2D Gouraud (within 0.5 + 2^-7 of the screen-linear value).
//! * **Colour**, perspective-correct ([`PerspectiveCorrect`]): `q = 1/w`
//!   (normalised per triangle to 23 bits) and `c·q` are planes; each pixel
//!   divides `c = (c·q)/q`.
//!
//! # Per-pixel cost (beyond writing the colour)
//! | choice | adds | other |
//! |---|---|---|
//! | no depth ([`NoDepth`](crate::depth::NoDepth)) | 0 | — |
//! | depth | 1 (`i64`) | shift, compare, store |
//! | flat colour | 0 | — |
//! | affine colour | 3 (`i32`) | 3 shifts |
//! | perspective-correct colour | 4 (`i64`) | 3 `u32` divisions |
//!
//! Variants are chosen by type parameters, so the loop a scene does not use is
//! not compiled.

use crate::attr::{COLOR_FRAC, Plane, PlaneFrame, channel};
use crate::band::BandView;
use crate::depth::{DepthFormat, DepthState};
use crate::edge::{Cull, TriangleSpans};
use crate::primitive::{center_rows, reference_pixel};
use crate::{Interpolate, SubPoint};

/// Fixed-point units per depth step in the depth plane.
pub const DEPTH_FRAC: u32 = 16;

/// Bits `q = 1/w` is normalised to within each triangle.
const Q_BITS: u32 = 23;

/// A vertex after the vertex stage, ready for rasterization.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ScreenVertex<const S: u32> {
    /// Snapped screen position.
    pub pos: SubPoint<S>,
    /// Depth `z/w ∈ [0, 1]` as `round(z/w · (2^32 − 1))`: 0 at the near plane,
    /// `u32::MAX` at the far plane.
    pub depth: u32,
    /// `1/w` up to a factor common to the frame (the pipeline uses
    /// `2^30 · n / w` with `n` the near distance); only ratios matter.
    pub inv_w: u32,
    /// Colour channels in the target colour's native depth
    /// ([`Interpolate::to_channels`]).
    pub color: [u8; 3],
}

/// A triangle after the vertex stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ScreenTriangle<const S: u32> {
    /// The vertices, in the winding they had (both windings are drawn here;
    /// culling happened in the vertex stage on the same snapped area).
    pub v: [ScreenVertex<S>; 3],
    /// Use vertex 0's colour for the whole triangle.
    pub flat: bool,
}

impl<const S: u32> ScreenTriangle<S> {
    /// The attribute plane through `values` at the vertices, referenced at a
    /// band-independent pixel (see `attr`); `None` for zero area.
    pub(crate) fn plane(&self, values: [i64; 3]) -> Option<Plane> {
        let frame =
            PlaneFrame { v: self.v.map(|v| (2 * v.pos.x() as i64, 2 * v.pos.y() as i64)), shift: S + 1 };
        let (rx, ry) = reference_pixel(self.v[0].pos);
        Plane::new(&frame, values, rx, ry)
    }

    /// The depth plane in 2^-[`DEPTH_FRAC`] steps of format `F`.
    pub(crate) fn depth_plane<F: DepthFormat>(&self) -> Option<Plane> {
        self.plane(self.v.map(|v| depth_steps(v.depth, F::MAX)))
    }

    /// Inclusive range of pixel rows the triangle can touch.
    pub fn rows(&self) -> (i32, i32) {
        let ys = self.v.map(|v| v.pos.y());
        center_rows::<S>(ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]))
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Affine {}
    impl Sealed for super::PerspectiveCorrect {}
}

/// How per-vertex colour is interpolated: [`Affine`] or [`PerspectiveCorrect`].
pub trait Interpolation: sealed::Sealed + Copy + Default {
    /// True for perspective-correct interpolation.
    const PERSPECTIVE: bool;
}

/// Screen-space (affine) interpolation: cheaper, skews on slanted surfaces.
#[derive(Debug, Clone, Copy, Default)]
pub struct Affine;

/// Perspective-correct interpolation: one division per channel and pixel.
#[derive(Debug, Clone, Copy, Default)]
pub struct PerspectiveCorrect;

impl Interpolation for Affine {
    const PERSPECTIVE: bool = false;
}
impl Interpolation for PerspectiveCorrect {
    const PERSPECTIVE: bool = true;
}

/// Rasterizes `tri` into a band's colour and depth rows. `depth` holds the
/// depth rows of the view's rows, first to last; a row the slice lacks is not
/// drawn (for [`NoDepth`](crate::depth::NoDepth) pass any slice).
pub fn draw_triangle<C, F, M, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    use crate::blit::Blitter;
    let spans = TriangleSpans::new(tri.v.map(|v| v.pos), color.clip(), Cull::None);
    let plane = |values: [i64; 3]| tri.plane(values);
    let y0 = color.y0();
    let zplane = if F::ENABLED {
        match tri.depth_plane::<F>() {
            Some(p) => Some(p),
            None => return,
        }
    } else {
        None
    };
    let max = C::CHANNEL_MAX;
    let shading = Shading::<M>::new(tri, max, &plane);

    for span in spans {
        let (x0, len) = (span.x as usize, span.len as usize);
        let Some(cspan) = color.row_mut(span.y).and_then(|r| r.get_mut(x0..x0 + len)) else { continue };
        let mut shade = shading.start(span.x, span.y);
        match zplane {
            Some(zp) => {
                let drow = depth.get_mut((span.y - y0) as usize).and_then(|r| r.get_mut(x0..x0 + len));
                let Some(dspan) = drow else { continue };
                let (mut z, dz) = (zp.at(span.x, span.y), zp.step_x());
                for (p, slot) in cspan.iter_mut().zip(dspan.iter_mut()) {
                    let zq = depth_value::<F>(z);
                    if state.test.passes(zq, F::to_u32(*slot)) {
                        if state.write {
                            *slot = F::from_u32(zq);
                        }
                        *p = C::from_channels(shade.color(max));
                    }
                    z = z.wrapping_add(dz);
                    shade.step();
                }
            }
            None => {
                for p in cspan.iter_mut() {
                    *p = C::from_channels(shade.color(max));
                    shade.step();
                }
            }
        }
    }
}

/// A depth-plane value rounded to the nearest step of `F`; the clamp only
/// matters at ± rounding.
#[inline(always)]
pub(crate) fn depth_value<F: DepthFormat>(z: i64) -> u32 {
    ((z.clamp(0, (F::MAX as i64) << DEPTH_FRAC) + (1 << (DEPTH_FRAC - 1))) >> DEPTH_FRAC) as u32
}

/// `depth / (2^32 − 1) · max · 2^DEPTH_FRAC`: a vertex depth in depth steps
/// of a format with largest value `max`, so 0 → 0 and `u32::MAX` → `max`
/// exactly. Division by `2^32 − 1` as the series `y·2^-32·(1 + 2^-32 + 2^-64)`
/// (shifts and adds only; the truncated terms are below one unit).
pub(crate) fn depth_steps(depth: u32, max: u32) -> i64 {
    let y = (depth as u128 * max as u128) << DEPTH_FRAC;
    // Rounding up by one unit makes u32::MAX land on max·2^16 exactly.
    (((y + (y >> 32) + (y >> 64)) >> 32) + 1).min((max as u128) << DEPTH_FRAC) as i64
}

/// The triangle's `1/w` values scaled by a common power of two so the largest
/// has `bits` bits (rounding only if a value must shift right): ratios are all
/// that matter, and the products with interpolated values stay bounded.
pub(crate) fn normalised_q<const S: u32>(tri: &ScreenTriangle<S>, bits: u32) -> [i64; 3] {
    let qmax = tri.v.iter().map(|v| v.inv_w).max().unwrap_or(0).max(1);
    let shift = bits as i32 - (32 - qmax.leading_zeros()) as i32;
    tri.v.map(|v| {
        let q = v.inv_w as u64;
        let q = if shift >= 0 { q << shift } else { (q + (1 << (-shift - 1))) >> -shift };
        q.max(1) as i64
    })
}

/// Colour set-up for one triangle.
enum Shading<M> {
    Flat([u8; 3]),
    Planes { planes: [Option<Plane>; 4], _m: core::marker::PhantomData<M> },
}

/// Colour state along one span.
struct ShadeSpan<M> {
    flat: Option<[u8; 3]>,
    acc: [i64; 4],
    step: [i64; 4],
    _m: core::marker::PhantomData<M>,
}

impl<M: Interpolation> Shading<M> {
    fn new<const S: u32>(
        tri: &ScreenTriangle<S>,
        max: [u8; 3],
        plane: &impl Fn([i64; 3]) -> Option<Plane>,
    ) -> Self {
        if tri.flat {
            return Shading::Flat(tri.v[0].color);
        }
        let mut planes = [None; 4];
        if M::PERSPECTIVE {
            // 23 bits keep c·q within u32 for a channel c ≤ 255.
            let q = normalised_q(tri, Q_BITS);
            planes[3] = plane(q.map(|q| q << DEPTH_FRAC));
            for (k, p) in planes.iter_mut().take(3).enumerate() {
                if max[k] > 0 {
                    *p = plane([0, 1, 2].map(|i| (tri.v[i].color[k] as i64 * q[i]) << DEPTH_FRAC));
                }
            }
        } else {
            for (k, p) in planes.iter_mut().take(3).enumerate() {
                if max[k] > 0 {
                    *p = plane(tri.v.map(|v| (v.color[k] as i64) << COLOR_FRAC));
                }
            }
        }
        Shading::Planes { planes, _m: core::marker::PhantomData }
    }

    #[inline]
    fn start(&self, x: i32, y: i32) -> ShadeSpan<M> {
        let mut s = ShadeSpan { flat: None, acc: [0; 4], step: [0; 4], _m: core::marker::PhantomData };
        match self {
            Shading::Flat(c) => s.flat = Some(*c),
            Shading::Planes { planes, .. } => {
                for ((acc, step), p) in s.acc.iter_mut().zip(s.step.iter_mut()).zip(planes) {
                    if let Some(p) = p {
                        (*acc, *step) = (p.at(x, y), p.step_x());
                    }
                }
            }
        }
        s
    }
}

impl<M: Interpolation> ShadeSpan<M> {
    #[inline(always)]
    fn color(&self, max: [u8; 3]) -> [u8; 3] {
        if let Some(c) = self.flat {
            return c;
        }
        if M::PERSPECTIVE {
            // q < 2^24 and c·q < 2^31 inside the triangle: 32-bit divisions,
            // which Cortex-M3/M4 do in hardware (the clamps only guard rounding).
            let q = (self.acc[3] >> DEPTH_FRAC).clamp(1, 1 << 24) as u32;
            [0, 1, 2].map(|k| {
                let p = (self.acc[k] >> DEPTH_FRAC).clamp(0, 1 << 31) as u32;
                ((p + q / 2) / q).min(max[k] as u32) as u8
            })
        } else {
            [0, 1, 2].map(|k| channel(self.acc[k].clamp(i32::MIN as i64, i32::MAX as i64) as i32, max[k]))
        }
    }

    #[inline(always)]
    fn step(&mut self) {
        if self.flat.is_none() {
            for (acc, step) in self.acc.iter_mut().zip(self.step) {
                *acc = acc.wrapping_add(step);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_steps_maps_ends_exactly_and_is_monotonic() {
        for max in [0xFF, 0xFFFF, 0xFF_FFFF, u32::MAX] {
            assert_eq!(depth_steps(0, max), 1.min((max as i64) << DEPTH_FRAC));
            assert_eq!(depth_steps(u32::MAX, max), (max as i64) << DEPTH_FRAC);
            let mut last = 0;
            for i in 0..=4096u64 {
                let d = (i * (u32::MAX as u64) / 4096) as u32;
                let v = depth_steps(d, max);
                // Exact value d·max·2^16/(2^32−1), within one unit (plus the +1).
                let exact = (d as f64) * (max as f64) * 65536.0 / (u32::MAX as f64);
                assert!((v as f64 - exact).abs() <= 2.0 + exact * 1e-15, "{d} {max}: {v} vs {exact}");
                assert!(v >= last);
                last = v;
            }
        }
    }
}
