//! PNG decoding for `png2rs`: any PNG the `png` crate reads, normalised to
//! grey or RGB samples (8 or 16 bits) with an alpha channel.

use ::png::{BitDepth, ColorType, Transformations};

/// The largest width or height accepted (microraster's `MAX_TEXTURE_DIM`).
pub const MAX_DIM: u32 = 4096;

/// A decoded image.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Width in pixels, `1..=MAX_DIM`.
    pub width: u32,
    /// Height in pixels, `1..=MAX_DIM`.
    pub height: u32,
    /// The source was greyscale (then `r = g = b` in every pixel).
    pub gray: bool,
    /// The largest sample value: 255 (8-bit samples) or 65535 (16-bit).
    pub max: u16,
    /// Pixels row by row as `[r, g, b, a]`, each in `0..=max`; `a = max`
    /// where the source has no alpha.
    pub pixels: Vec<[u16; 4]>,
}

/// Decodes a PNG. Palette images become RGB, greyscale below 8 bits
/// becomes 8-bit, and a `tRNS` chunk becomes an alpha channel (the `png`
/// crate's `EXPAND`); 16-bit samples are kept, so the conversion rounds once
/// from the full precision.
///
/// A palette index past the palette's last entry is an error (the PNG
/// specification's rule; the `png` crate's expansion would make it black).
pub fn decode(bytes: &[u8]) -> Result<Image, String> {
    check_palette_indices(bytes)?;
    let mut decoder = ::png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(Transformations::EXPAND);
    let mut reader = decoder.read_info().map_err(|e| format!("not a readable PNG: {e}"))?;
    let (width, height) = (reader.info().width, reader.info().height);
    if !(1..=MAX_DIM).contains(&width) || !(1..=MAX_DIM).contains(&height) {
        return Err(format!("{width}×{height} pixels: width and height must be 1 to {MAX_DIM}"));
    }
    let size = reader.output_buffer_size().ok_or("image too large to decode")?;
    let mut buf = vec![0; size];
    let out = reader.next_frame(&mut buf).map_err(|e| format!("corrupt PNG data: {e}"))?;
    let (channels, gray, alpha) = match out.color_type {
        ColorType::Grayscale => (1, true, false),
        ColorType::GrayscaleAlpha => (2, true, true),
        ColorType::Rgb => (3, false, false),
        ColorType::Rgba => (4, false, true),
        ColorType::Indexed => return Err("palette not expanded (unexpected)".into()),
    };
    let (bytes_per_sample, max) = match out.bit_depth {
        BitDepth::Eight => (1, 255),
        BitDepth::Sixteen => (2, 65535),
        d => return Err(format!("{d:?}-bit samples not expanded (unexpected)")),
    };
    let sample =
        |s: &[u8]| if bytes_per_sample == 1 { u16::from(s[0]) } else { u16::from_be_bytes([s[0], s[1]]) };
    let mut pixels = Vec::with_capacity((width * height) as usize);
    for row in buf[..out.buffer_size()].chunks_exact(out.line_size) {
        for px in row.chunks_exact(channels * bytes_per_sample).take(width as usize) {
            let s: Vec<u16> = px.chunks_exact(bytes_per_sample).map(sample).collect();
            let a = if alpha { s[channels - 1] } else { max };
            pixels.push(if gray { [s[0], s[0], s[0], a] } else { [s[0], s[1], s[2], a] });
        }
    }
    if pixels.len() != (width * height) as usize {
        return Err("truncated image data".into());
    }
    Ok(Image { width, height, gray, max, pixels })
}

/// For a palette image, every pixel's index must name a palette entry. The
/// expanded decode cannot tell, so the indices are read once unexpanded.
fn check_palette_indices(bytes: &[u8]) -> Result<(), String> {
    let mut decoder = ::png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| format!("not a readable PNG: {e}"))?;
    let info = reader.info();
    if info.color_type != ColorType::Indexed {
        return Ok(());
    }
    let (width, height) = (info.width, info.height);
    if !(1..=MAX_DIM).contains(&width) || !(1..=MAX_DIM).contains(&height) {
        return Ok(()); // the expanded decode reports the size
    }
    let entries = info.palette.as_ref().map_or(0, |p| p.len() / 3);
    let size = reader.output_buffer_size().ok_or("image too large to decode")?;
    let mut buf = vec![0; size];
    let out = reader.next_frame(&mut buf).map_err(|e| format!("corrupt PNG data: {e}"))?;
    let bits = out.bit_depth as usize; // 1, 2, 4 or 8 for a palette
    for (y, row) in buf[..out.buffer_size()].chunks_exact(out.line_size).enumerate() {
        // Pixels are packed from the high bits; bits past the width are padding.
        for x in 0..width as usize {
            let (byte, shift) = (x * bits / 8, 8 - bits - x * bits % 8);
            let index = usize::from(row[byte] >> shift) & ((1 << bits) - 1);
            if index >= entries {
                return Err(format!(
                    "palette index {index} at ({x}, {y}) past the palette's {entries} entries"
                ));
            }
        }
    }
    Ok(())
}
