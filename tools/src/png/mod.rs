//! PNG → Rust source for a `static` microraster `Texture` (the `png2rs`
//! binary, and [`convert()`] for build scripts).
//!
//! The output defines `NAME_TEXELS` (a `[[T; W]; H]` array, `T` the
//! format's storage: `u16`, `u8` or `[u8; 3]`) and `NAME: Texture<'static,
//! F>`, `F` one of `Rgb565`, `Gray8`, `Rgb565A8`, `Argb4444`, `A8`. Any PNG the `png`
//! crate reads is accepted (see [`decode`]); rounding and alpha handling are
//! in [`mod@convert`].

pub mod convert;
pub mod decode;
pub mod emit;

use std::path::Path;

pub use convert::{Alpha, Format};

use crate::Error;

/// How [`convert_bytes`] writes its output.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// The texel format.
    pub format: Format,
    /// What to do with alpha in a format without it.
    pub alpha: Alpha,
    /// Path of microraster in the output (`microraster`; `crate` inside it).
    pub krate: String,
    /// Path of the module with `Rgb565` and `Gray8`
    /// (`embedded_graphics::pixelcolor`).
    pub pixelcolor: String,
}

impl Options {
    /// The defaults for `format`: alpha rejected, `microraster` and
    /// `embedded_graphics::pixelcolor` paths.
    pub fn new(format: Format) -> Self {
        Options {
            format,
            alpha: Alpha::Reject,
            krate: emit::DEFAULT_CRATE.to_string(),
            pixelcolor: emit::DEFAULT_PIXELCOLOR.to_string(),
        }
    }
}

/// A conversion: the Rust source and what the report line needs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Converted {
    /// The generated Rust source.
    pub source: String,
    /// Width and height in texels.
    pub size: (u32, u32),
    /// Pixels of the PNG that were not opaque.
    pub translucent: usize,
}

/// Converts the PNG at `path` into Rust source for `static NAME: Texture`
/// (NAME is `name` upper-cased) in `format`, with [`Options::new`].
///
/// # Errors
///
/// The file cannot be read or decoded (a palette index past the palette's
/// last entry included), `name` is not an identifier, or a pixel is not
/// opaque in a format without alpha.
///
/// ```
/// use microraster_tools::png::{Format, convert};
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/bricks.png");
/// let src = convert(path, "bricks", Format::Rgb565)?;
/// assert!(src.contains("pub static BRICKS: microraster::texture::Texture<'static, embedded_graphics::pixelcolor::Rgb565>"));
/// # Ok::<(), microraster_tools::Error>(())
/// ```
pub fn convert(path: impl AsRef<Path>, name: &str, format: Format) -> Result<String, Error> {
    let (file, bytes) = crate::read(path.as_ref())?;
    Ok(convert_bytes(&bytes, name, &file, &Options::new(format))
        .map_err(|e| crate::in_file(path.as_ref(), e))?
        .source)
}

/// Converts PNG `bytes` named `source` in the header comment.
///
/// # Errors
///
/// As [`convert()`], and an invalid [`Options::krate`] or
/// [`Options::pixelcolor`] path.
pub fn convert_bytes(bytes: &[u8], name: &str, source: &str, options: &Options) -> Result<Converted, Error> {
    let image = decode::decode(bytes).map_err(Error)?;
    let (texels, translucent) = convert::convert(&image, options.format, options.alpha).map_err(Error)?;
    let src = emit::rust_source(
        &texels,
        image.width,
        image.height,
        name,
        source,
        &options.krate,
        &options.pixelcolor,
    )
    .map_err(Error)?;
    Ok(Converted { source: src, size: (image.width, image.height), translucent })
}
