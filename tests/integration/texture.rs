//! Texture sampling against an f64 reference, and textured triangles
//! (`Varyings<2>` + `draw_fragments`) against an f64 perspective-correct
//! reference per pixel centre.
//!
//! The reference is written from the documented conventions of
//! `src/pixel/texture/mod.rs`, not from its code: `u` in units of 2^-16 of the
//! texture; texel `i` covers `[i, i + 1)` in `p = u·size`; nearest takes
//! texel `⌊p⌋`, bilinear blends texels `⌊p − ½⌋` and `⌊p − ½⌋ + 1` by the
//! fraction of `p − ½`; wrap takes indices modulo the size, clamp clamps them
//! to `[0, size − 1]`; Rgb565 channels widen to 8 bits by bit replication.
//!
//! Stated bounds checked here: nearest exact; bilinear within ½ + 2^-9 of the
//! exact blend. Through a triangle, the `Varyings` bound `δ` on `(u, v)`
//! (src/raster/varyings.rs) adds `255 · size · δ / 2^16` per axis to bilinear's
//! bound (the exact blend changes by at most 255 per texel of motion, and is
//! continuous in both addressing modes), and lets nearest pick any texel
//! within `δ` of the exact coordinate.

mod sampling;
mod triangles;

use microraster::texture::{Address, UV_ONE};

const BILINEAR_BOUND: f64 = 0.5 + 1.0 / 512.0;

/// A texture with its texels widened to 8 bits by the reference rule.
struct RefTexture {
    w: i64,
    h: i64,
    texels: Vec<[f64; 3]>,
}

/// Bit replication, written as the widening it is: `c·2^(8−b) + ⌊c/2^(2b−8)⌋`.
fn widen(c: u16, bits: u32) -> f64 {
    f64::from(c) * 2f64.powi(8 - bits as i32) + (f64::from(c) / 2f64.powi(2 * bits as i32 - 8)).floor()
}

impl RefTexture {
    fn rgb565(raw: &[u16], w: i64, h: i64) -> Self {
        let texels =
            raw.iter().map(|&t| [widen(t >> 11, 5), widen((t >> 5) & 63, 6), widen(t & 31, 5)]).collect();
        RefTexture { w, h, texels }
    }
    fn gray8(raw: &[u8], w: i64, h: i64) -> Self {
        RefTexture { w, h, texels: raw.iter().map(|&t| [f64::from(t); 3]).collect() }
    }
    fn index(n: i64, i: i64, a: Address) -> i64 {
        match a {
            Address::Wrap => i.rem_euclid(n),
            Address::Clamp => i.clamp(0, n - 1),
        }
    }
    fn at(&self, i: i64, j: i64, a: [Address; 2]) -> [f64; 3] {
        let (i, j) = (Self::index(self.w, i, a[0]), Self::index(self.h, j, a[1]));
        self.texels[(j * self.w + i) as usize]
    }
    /// Texel-space position of a coordinate (exact in f64: |u·n| < 2^44).
    fn pos(u: f64, n: i64) -> f64 {
        u / f64::from(UV_ONE) * n as f64
    }
    fn nearest(&self, uv: [f64; 2], a: [Address; 2]) -> [f64; 3] {
        let (p, q) = (Self::pos(uv[0], self.w), Self::pos(uv[1], self.h));
        self.at(p.floor() as i64, q.floor() as i64, a)
    }
    fn bilinear(&self, uv: [f64; 2], a: [Address; 2]) -> [f64; 3] {
        let (p, q) = (Self::pos(uv[0], self.w) - 0.5, Self::pos(uv[1], self.h) - 0.5);
        let (i, j) = (p.floor(), q.floor());
        let (fx, fy) = (p - i, q - j);
        let (i, j) = (i as i64, j as i64);
        let t = [self.at(i, j, a), self.at(i + 1, j, a), self.at(i, j + 1, a), self.at(i + 1, j + 1, a)];
        [0, 1, 2].map(|k| {
            (1.0 - fy) * ((1.0 - fx) * t[0][k] + fx * t[1][k]) + fy * ((1.0 - fx) * t[2][k] + fx * t[3][k])
        })
    }
}
