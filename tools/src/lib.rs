//! Asset converters for [microraster](https://docs.rs/microraster): Wavefront
//! OBJ to a `static` [`Mesh`](microraster::mesh::Mesh) ([`obj`]) and PNG to
//! a `static` `Texture` ([`png`]), as Rust source whose arrays stay in flash.
//!
//! Two routes, same output:
//!
//! - **Command line**: `cargo install --path tools` (from a checkout of
//!   microraster) installs `obj2rs` and `png2rs`; `--help` says what each
//!   option does. Both take the input, `--name NAME` and `--out FILE`
//!   (standard output without it), and exit with status 2 on bad arguments
//!   ([`cli`]):
//!
//!   ```text
//!   obj2rs teapot.obj --name teapot --out src/teapot.rs
//!   png2rs icon.png --name icon --format rgb565a8 --out src/icon.rs
//!   ```
//! - **Build script**: keep the assets as files and convert them in
//!   `build.rs` with [`obj::convert`] and [`png::convert()`], writing into
//!   `OUT_DIR` and `include!`-ing the result:
//!
//! ```no_run
//! // build.rs of a firmware crate, with `microraster-tools` as a build-dependency.
//! use std::{env, fs, path::Path};
//!
//! fn main() -> Result<(), Box<dyn std::error::Error>> {
//!     let out = Path::new(&env::var("OUT_DIR")?).join("assets.rs");
//!     let mut src = microraster_tools::obj::convert("assets/teapot.obj", "TEAPOT")?;
//!     src += &microraster_tools::png::convert("assets/bricks.png", "BRICKS", microraster_tools::png::Format::Rgb565)?;
//!     fs::write(out, src)?;
//!     println!("cargo:rerun-if-changed=assets");
//!     Ok(())
//! }
//! // and in the crate: include!(concat!(env!("OUT_DIR"), "/assets.rs"));
//! ```
//!
//! The generated code names `microraster::…` and `embedded_graphics::…`
//! paths, so it compiles in a crate that depends on those two.

pub mod cli;
pub mod obj;
pub mod png;

use std::fmt;

/// Why a conversion failed: the input's name and what is wrong with it
/// (for OBJ parse errors, the line).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error(pub String);

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Error {}

/// The file name of `path` for the generated header comment (not the full
/// path, so the output does not depend on where the checkout lives), and the
/// file's bytes.
fn read(path: &std::path::Path) -> Result<(String, Vec<u8>), Error> {
    let bytes = std::fs::read(path).map_err(|e| Error(format!("{}: {e}", path.display())))?;
    let name =
        path.file_name().map_or_else(|| path.display().to_string(), |f| f.to_string_lossy().into_owned());
    Ok((name, bytes))
}

/// `e` prefixed with the input's path, as the binaries print it.
fn in_file(path: &std::path::Path, e: Error) -> Error {
    Error(format!("{}: {}", path.display(), e.0))
}
