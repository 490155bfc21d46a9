//! Pixel conversion for `png2rs`, every value rounded once to nearest from
//! the source's full precision.
//!
//! * `rgb565`: each channel `round(v·m/max)` with `m` 31, 63, 31 and `max`
//!   255 or 65535 (odd, so there are no ties), packed as `embedded-graphics`'
//!   raw `Rgb565` bits (red 15–11, green 10–5, blue 4–0).
//! * `gray8`: a grey source keeps its level, `round(v·255/max)`; a colour
//!   source becomes its Rec. 601 luma `0.299 r + 0.587 g + 0.114 b` (on the
//!   channels scaled to 0–255), computed exactly in integers and rounded
//!   half up.
//! * `argb4444`: every channel and alpha `round(v·15/max)`, packed
//!   `0xARGB` (microraster's `texture::Argb4444`).
//! * `a8`: the alpha channel alone, `round(a·255/max)` (`texture::A8`, an
//!   alpha mask; the colour is dropped). An image without alpha is opaque.
//! * `rgb565a8`: the colour as `rgb565`, the alpha as `a8`, stored
//!   `[colour high byte, colour low byte, alpha]` (`texture::Rgb565A8`): 256
//!   alpha levels where `argb4444` has 16.
//! * Alpha in `rgb565` and `gray8`: they have none. Images whose every pixel
//!   is opaque convert; any other pixel is an error (naming the formats that
//!   keep alpha) unless alpha is ignored (`--ignore-alpha`), which keeps each
//!   pixel's colour and drops its alpha. The alpha formats keep it
//!   (straight, not premultiplied).

use super::decode::Image;

/// The texel format to emit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// `u16` raw Rgb565 bits.
    Rgb565,
    /// `u8` grey levels.
    Gray8,
    /// `u16` colour and alpha, 4 bits each.
    Argb4444,
    /// `u8` alpha.
    A8,
    /// `[u8; 3]`: Rgb565 colour bits big-endian, then 8-bit alpha.
    Rgb565A8,
}

impl Format {
    /// Every format, in the order the command line lists them.
    pub const ALL: [Format; 5] =
        [Format::Rgb565, Format::Gray8, Format::Rgb565A8, Format::Argb4444, Format::A8];

    /// The format named on the command line (`rgb565`, `gray8`,
    /// `rgb565a8`, `argb4444`, `a8`).
    pub fn parse(s: &str) -> Option<Format> {
        Format::ALL.into_iter().find(|f| f.name() == s)
    }

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Rgb565 => "rgb565",
            Format::Gray8 => "gray8",
            Format::Argb4444 => "argb4444",
            Format::A8 => "a8",
            Format::Rgb565A8 => "rgb565a8",
        }
    }

    /// The texel format's type name in microraster or embedded-graphics.
    pub fn type_name(self) -> &'static str {
        match self {
            Format::Rgb565 => "Rgb565",
            Format::Gray8 => "Gray8",
            Format::Argb4444 => "Argb4444",
            Format::A8 => "A8",
            Format::Rgb565A8 => "Rgb565A8",
        }
    }

    /// Whether the format keeps alpha.
    pub fn has_alpha(self) -> bool {
        matches!(self, Format::Argb4444 | Format::A8 | Format::Rgb565A8)
    }
}

/// Converted texels.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Texels {
    /// Raw Rgb565 bits, row by row.
    Rgb565(Vec<u16>),
    /// Grey levels, row by row.
    Gray8(Vec<u8>),
    /// `0xARGB` nibbles, row by row.
    Argb4444(Vec<u16>),
    /// Alpha, row by row.
    A8(Vec<u8>),
    /// `[colour high byte, colour low byte, alpha]`, row by row.
    Rgb565A8(Vec<[u8; 3]>),
}

/// How pixels that are not fully opaque are handled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Alpha {
    /// They are an error.
    Reject,
    /// Their alpha is dropped.
    Ignore,
}

/// `round(v·m/max)` for `v ≤ max`, `max` odd (no ties).
fn scale(v: u16, m: u32, max: u16) -> u32 {
    let (v, max) = (u32::from(v), u32::from(max));
    (2 * v * m + max) / (2 * max)
}

/// Converts `image` to `format`; the second value counts pixels that were
/// not fully opaque (0 unless alpha is ignored or kept).
pub fn convert(image: &Image, format: Format, alpha: Alpha) -> Result<(Texels, usize), String> {
    let translucent = image.pixels.iter().filter(|p| p[3] != image.max).count();
    if translucent > 0 && alpha == Alpha::Reject && !format.has_alpha() {
        let first = image.pixels.iter().position(|p| p[3] != image.max).unwrap_or(0);
        let (x, y) = (first as u32 % image.width, first as u32 / image.width);
        return Err(format!(
            "{translucent} pixels are not fully opaque (the first at x {x}, y {y}); {} textures have no \
             alpha: to keep it use --format rgb565a8, argb4444 or a8; to drop it pass --ignore-alpha",
            format.name()
        ));
    }
    let max = image.max;
    let rgb565 = |r, g, b| ((scale(r, 31, max) << 11) | (scale(g, 63, max) << 5) | scale(b, 31, max)) as u16;
    let texels = match format {
        Format::Rgb565 => Texels::Rgb565(image.pixels.iter().map(|&[r, g, b, _]| rgb565(r, g, b)).collect()),
        Format::Rgb565A8 => Texels::Rgb565A8(
            image
                .pixels
                .iter()
                .map(|&[r, g, b, a]| {
                    let [hi, lo] = rgb565(r, g, b).to_be_bytes();
                    [hi, lo, scale(a, 255, max) as u8]
                })
                .collect(),
        ),
        Format::Gray8 => Texels::Gray8(
            image
                .pixels
                .iter()
                .map(|&[r, g, b, _]| {
                    if image.gray {
                        scale(r, 255, max) as u8
                    } else {
                        // Exactly, in integers: 255·(299 r + 587 g + 114 b)/(1000·max).
                        let [r, g, b, max] = [r, g, b, max].map(u64::from);
                        let num = 255 * (299 * r + 587 * g + 114 * b);
                        ((2 * num + 1000 * max) / (2000 * max)) as u8
                    }
                })
                .collect(),
        ),
        Format::Argb4444 => Texels::Argb4444(
            image
                .pixels
                .iter()
                .map(|&[r, g, b, a]| [a, r, g, b].iter().fold(0, |t, &v| (t << 4) | scale(v, 15, max) as u16))
                .collect(),
        ),
        Format::A8 => Texels::A8(image.pixels.iter().map(|&[_, _, _, a]| scale(a, 255, max) as u8).collect()),
    };
    Ok((texels, translucent))
}
