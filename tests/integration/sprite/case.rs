//! The sprite tests' reference: a recorder of what a sprite blends, the
//! formats with alpha by their documented widening, and random cases with
//! the exact pixel-to-texel map and bilinear blend in `f64`.

use crate::reference::Rng;
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::Rgb888;
use microraster::ClipRect;
use microraster::blend::{Blend, BlendTarget};
use microraster::texture::{Argb4444, Filter, Rgb565A8, Sprite, TexelFormat, Texture};
use std::collections::HashMap;

/// Records what a sprite blends: colour (Rgb888 keeps the 8-bit channels
/// exactly) and alpha per pixel.
pub(super) struct Recorder {
    pub(super) clip: ClipRect,
    pub(super) seen: HashMap<(i32, i32), [u8; 4]>,
}

impl BlendTarget<Rgb888> for Recorder {
    fn clip(&self) -> ClipRect {
        self.clip
    }
    fn blend_pixel<B: Blend>(&mut self, _: B, x: i32, y: i32, c: Rgb888, a: u8) {
        assert!(self.seen.insert((x, y), [c.r(), c.g(), c.b(), a]).is_none(), "({x}, {y}) blended twice");
    }
}

/// What `s` blends into a 200 × 200 recorder.
pub(super) fn record<F: TexelFormat, Fi: Filter>(
    s: &Sprite<'_, F, Rgb888, Fi>,
) -> HashMap<(i32, i32), [u8; 4]> {
    let mut r = Recorder { clip: ClipRect::new(0, 0, 200, 200), seen: HashMap::new() };
    s.blend_into(&mut r).unwrap();
    r.seen
}

/// A format with alpha under test: a random texel from one `u64`, and the
/// texel as 8-bit `[r, g, b, a]` by the documented widening.
pub(super) trait AlphaFormat: TexelFormat {
    fn random(bits: u64) -> Self::Storage;
    fn rgba(t: Self::Storage) -> [f64; 4];
}

impl AlphaFormat for Argb4444 {
    fn random(bits: u64) -> u16 {
        bits as u16
    }
    fn rgba(t: u16) -> [f64; 4] {
        let n = |s: u32| ((t >> s) & 0xF) as f64 * 17.0;
        [n(8), n(4), n(0), n(12)]
    }
}

impl AlphaFormat for Rgb565A8 {
    fn random(bits: u64) -> [u8; 3] {
        [bits as u8, (bits >> 8) as u8, (bits >> 16) as u8]
    }
    fn rgba(t: [u8; 3]) -> [f64; 4] {
        // Bit replication: c·2^(8−b) + ⌊c·2^(8−b)/2^b⌋ for a b-bit channel.
        let c = u32::from(t[0]) << 8 | u32::from(t[1]);
        let widen = |v: u32, b: u32| (v << (8 - b)) as f64 + ((v << (8 - b)) >> b) as f64;
        [widen(c >> 11, 5), widen((c >> 5) & 63, 6), widen(c & 31, 5), f64::from(t[2])]
    }
}

pub(super) struct Case<F: AlphaFormat> {
    pub(super) texels: Vec<F::Storage>,
    pub(super) w: u32,
    pub(super) h: u32,
    pub(super) at: Point,
    pub(super) scale: f32,
    pub(super) angle: f32,
}

impl<F: AlphaFormat> Case<F> {
    pub(super) fn random(rng: &mut Rng, axis_aligned: bool) -> Self {
        let dim =
            |rng: &mut Rng| if rng.chance(0.4) { 1 << rng.range(0, 5) } else { rng.range(1, 37) as u32 };
        let (w, h) = (dim(rng), dim(rng));
        let texels = (0..w * h).map(|_| F::random(rng.next_u64())).collect();
        let at = Point::new(rng.range(-20, 120) as i32, rng.range(-20, 120) as i32);
        let (scale, angle) = if axis_aligned {
            (rng.range(1, 6) as f32, 0.0)
        } else {
            let a = if rng.chance(0.2) {
                rng.range(-4, 4) as f64 * std::f64::consts::FRAC_PI_2
            } else {
                rng.uniform(-7.0, 7.0)
            };
            (rng.log_uniform(0.3, 9.0) as f32, a as f32)
        };
        Case { texels, w, h, at, scale, angle }
    }

    pub(super) fn texture(&self) -> Texture<'_, F> {
        Texture::new(&self.texels, self.w, self.h).unwrap()
    }

    /// The exact texel-space point of pixel `(x, y)`'s centre.
    pub(super) fn texel_point(&self, x: i32, y: i32) -> (f64, f64) {
        let (s, a) = (self.scale as f64, self.angle as f64);
        let (w, h) = (self.w as f64, self.h as f64);
        let (cx, cy) = (self.at.x as f64 + w * s / 2.0, self.at.y as f64 + h * s / 2.0);
        let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
        let (sin, cos) = a.sin_cos();
        ((cos * dx + sin * dy) / s + w / 2.0, (cos * dy - sin * dx) / s + h / 2.0)
    }

    pub(super) fn delta(&self) -> f64 {
        let size = self.w.max(self.h) as f64;
        size / 65536.0 + size * 4e-7 + 1e-6
    }

    pub(super) fn rgba(&self, i: usize, j: usize) -> [f64; 4] {
        F::rgba(self.texels[j * self.w as usize + i])
    }

    /// The exact bilinear blend (edges clamped) at texel-space `(tx, ty)`.
    pub(super) fn bilinear(&self, tx: f64, ty: f64) -> [f64; 4] {
        let axis = |t: f64, n: u32| {
            let p = (t - 0.5).clamp(0.0, n as f64 - 1.0);
            let i0 = p.floor() as usize;
            (i0, (i0 + 1).min(n as usize - 1), p - i0 as f64)
        };
        let ((x0, x1, fx), (y0, y1, fy)) = (axis(tx, self.w), axis(ty, self.h));
        let [a, b, c, d] = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].map(|(i, j)| self.rgba(i, j));
        [0, 1, 2, 3]
            .map(|k| (a[k] * (1.0 - fx) + b[k] * fx) * (1.0 - fy) + (c[k] * (1.0 - fx) + d[k] * fx) * fy)
    }
}

/// Distance from `t` to the nearest integer.
pub(super) fn border(t: f64) -> f64 {
    (t - t.round()).abs()
}
