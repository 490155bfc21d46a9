//! Attribute planes: Gouraud colour interpolated across a triangle.
//!
//! A channel value `c` is a plane over the triangle:
//! `c(p) = c₀ + λ₁(c₁ − c₀) + λ₂(c₂ − c₀)`, with the barycentric weights taken
//! from the same snapped coordinates as coverage. We keep the plane's exact
//! integer numerators and evaluate it:
//!
//! * at the first pixel of every span, exactly (rounded to nearest in 16.16
//!   fixed point, in `i128`, because a far-away vertex makes the numerators
//!   up to 2^86);
//! * then along the span by adding a 16.16 step per pixel in `i32`.
//!
//! # Error bound
//! The span start is within 2^-17 of the exact value and each step adds at
//! most 2^-17, so after `k` pixels the 16.16 value is within `(k+1)·2^-17` of
//! exact: with spans at most [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM) = 4096
//! pixels that is below 0.032 of a channel step. The final rounding adds 0.5,
//! so every output channel is within **0.532** of the exact value (and clamped
//! to the channel's range, which the exact value never leaves inside the
//! triangle).
//!
//! # Overflow
//! Channel values are at most 255, internal coordinates differ by at most
//! 2^30: the numerators `gx`, `gy` stay below 2^40 and the per-span products
//! below 2^71 (with the 2^16 scale, 2^87) — well inside `i128`. A step larger
//! than `i32` only occurs when the gradient exceeds 255 levels per pixel, in
//! which case no span can contain two pixels and the saturated step is never
//! used.

/// One interpolated channel.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plane {
    c0: i64,
    gx: i64,
    gy: i64,
    det: i64,
    /// 16.16 increment per pixel to the right (saturated, see module docs).
    step_x: i32,
}

const FRAC: u32 = 16;

/// Vertex positions in internal units (`1/2^(S+1)` px) and the pixel-centre geometry.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneFrame {
    /// Internal coordinates of the three vertices.
    pub v: [(i64, i64); 3],
    /// `log2` of one pixel in internal units (`S + 1`).
    pub shift: u32,
}

impl PlaneFrame {
    /// Twice the signed area (non-zero for any triangle that covers a pixel).
    fn det(&self) -> i64 {
        crate::edge::signed_area2(self.v)
    }
}

impl Plane {
    /// The plane through the values `c` at the vertices of `frame`.
    /// Returns `None` for a degenerate (zero-area) triangle.
    pub fn new(frame: &PlaneFrame, c: [u8; 3]) -> Option<Plane> {
        let det = frame.det();
        if det == 0 {
            return None;
        }
        let [(x0, y0), (x1, y1), (x2, y2)] = frame.v;
        let (d1, d2) = (c[1] as i64 - c[0] as i64, c[2] as i64 - c[0] as i64);
        // Cramer's rule: ∂c/∂x = gx/det and ∂c/∂y = gy/det per internal unit.
        let gx = d1 * (y2 - y0) - d2 * (y1 - y0);
        let gy = d2 * (x1 - x0) - d1 * (x2 - x0);
        let step = div_round((gx as i128) << (frame.shift + FRAC), det as i128);
        let step_x = step.clamp(i32::MIN as i128, i32::MAX as i128) as i32;
        Some(Plane { c0: c[0] as i64, gx, gy, det, step_x })
    }

    /// The 16.16 value at the pixel centre `(px, py)` given in internal units,
    /// relative to vertex 0, rounded to nearest.
    #[inline]
    pub fn at(&self, dx: i64, dy: i64) -> i32 {
        let num = (dx as i128 * self.gx as i128 + dy as i128 * self.gy as i128) << FRAC;
        let v = ((self.c0 as i128) << FRAC) + div_round(num, self.det as i128);
        v.clamp(i32::MIN as i128, i32::MAX as i128) as i32
    }

    /// 16.16 increment per pixel along a row.
    #[inline]
    pub fn step_x(&self) -> i32 {
        self.step_x
    }
}

/// A 16.16 accumulator converted to a channel value in `0..=max`.
#[inline(always)]
pub(crate) fn channel(acc: i32, max: u8) -> u8 {
    let v = (acc >> FRAC) + ((acc >> (FRAC - 1)) & 1); // round half up
    v.clamp(0, max as i32) as u8
}

/// `n / d` rounded to nearest (ties away from zero); `d != 0`.
fn div_round(n: i128, d: i128) -> i128 {
    let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
    if n >= 0 { (n + d / 2) / d } else { -((-n + d / 2) / d) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_hits_vertex_values_and_steps_linearly() {
        // A right triangle 8 px wide at S = 0 (internal unit = 1/2 px).
        let frame = PlaneFrame { v: [(0, 0), (16, 0), (0, 16)], shift: 1 };
        let p = Plane::new(&frame, [0, 255, 100]).unwrap();
        assert_eq!(channel(p.at(0, 0), 255), 0);
        assert_eq!(channel(p.at(16, 0), 255), 255);
        assert_eq!(channel(p.at(0, 16), 255), 100);
        // 255 levels over 8 px: 31.875 per px, exactly representable in 16.16.
        assert_eq!(p.step_x(), (31.875 * 65536.0) as i32);
        assert!(Plane::new(&PlaneFrame { v: [(0, 0), (4, 4), (8, 8)], shift: 1 }, [0; 3]).is_none());
    }

    #[test]
    fn channel_rounds_and_clamps() {
        assert_eq!(channel(0x7FFF, 255), 0);
        assert_eq!(channel(0x8000, 255), 1);
        assert_eq!(channel(-5 << 16, 31), 0);
        assert_eq!(channel(40 << 16, 31), 31);
    }
}
