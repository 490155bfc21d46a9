//! What the `png2rs` tests share: PNGs encoded with the `png` crate, a
//! deterministic generator and the reference Rgb565 rounding.

use png::{BitDepth, ColorType};

/// An encoded PNG.
pub fn encode(
    w: u32,
    h: u32,
    color: ColorType,
    depth: BitDepth,
    data: &[u8],
    plte: Option<&[u8]>,
    trns: Option<&[u8]>,
) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut e = png::Encoder::new(&mut out, w, h);
        e.set_color(color);
        e.set_depth(depth);
        if let Some(p) = plte {
            e.set_palette(p.to_vec());
        }
        if let Some(t) = trns {
            e.set_trns(t.to_vec());
        }
        let mut writer = e.write_header().unwrap();
        writer.write_image_data(data).unwrap();
    }
    out
}

/// A tiny deterministic generator (SplitMix64).
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    #[allow(dead_code)] // not every includer draws random bytes
    pub fn bytes(&mut self, n: usize) -> Vec<u8> {
        (0..n).map(|_| self.next() as u8).collect()
    }
}

/// The reference Rgb565 texel of a colour with channels in `0..=max`:
/// each channel rounded to nearest in f64, packed red-high.
#[allow(dead_code)] // not every includer converts to Rgb565
pub fn ref_rgb565(rgb: [f64; 3], max: f64) -> u16 {
    let q = |v: f64, m: f64| (v * m / max).round() as u16;
    q(rgb[0], 31.0) * 2048 + q(rgb[1], 63.0) * 32 + q(rgb[2], 31.0)
}
