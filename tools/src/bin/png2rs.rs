//! png2rs: converts a PNG image into Rust source for a `static`
//! [`microraster::texture::Texture`] (texels in flash, no RAM).
//!
//! ```text
//! png2rs INPUT.png --name NAME --format rgb565|gray8|argb4444|a8 [--out FILE]
//!     [--ignore-alpha] [--crate PATH] [--pixelcolor PATH]
//! ```
//!
//! Writes `NAME_TEXELS` (a `[[u16 or u8; W]; H]` array) and
//! `NAME: Texture<'static, Rgb565, Gray8, Argb4444 or A8>` (NAME upper-cased;
//! the last two keep the PNG's alpha) to `FILE`, or
//! to standard output; `INPUT` `-` reads standard input. `--crate` sets the
//! path of microraster in the output (default `microraster`; `crate` inside
//! it), `--pixelcolor` that of the module with `Rgb565` and `Gray8` (default
//! `embedded_graphics::pixelcolor`). Any PNG the `png` crate reads is
//! accepted: palette, grey, RGB, with or without alpha, 1 to 16 bits (see
//! `png::decode`; a palette index past the palette is an error); rounding and alpha handling are described in
//! `png::convert`. Installed by `cargo install --path tools`;
//! `microraster_tools::png` is the same conversion for build scripts.
//! Errors exit with status 1 (2 for bad arguments).

use std::io::{Read, Write};
use std::path::Path;
use std::process::ExitCode;

use microraster_tools::png::{Alpha, Format, Options as Conversion, convert_bytes, emit};

const USAGE: &str = "usage: png2rs INPUT.png --name NAME --format rgb565|gray8|argb4444|a8 [--out FILE] \
                     [--ignore-alpha] [--crate PATH] [--pixelcolor PATH]   (INPUT `-` = stdin)";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => {
            report(&format!("{msg}\n{USAGE}"));
            ExitCode::from(2)
        }
        Err(Failure::Input(msg)) => {
            report(&msg);
            ExitCode::FAILURE
        }
    }
}

enum Failure {
    Usage(String),
    Input(String),
}

/// Writes to stderr, ignoring failure (a broken stderr must not panic).
fn report(msg: &str) {
    let _ = writeln!(std::io::stderr(), "png2rs: {msg}");
}

struct Options {
    input: String,
    name: String,
    format: Format,
    out: Option<String>,
    alpha: Alpha,
    krate: String,
    pixelcolor: String,
}

fn parse_args(args: &[String]) -> Result<Option<Options>, Failure> {
    let mut input = None;
    let (mut name, mut format, mut out) = (None, None, None);
    let mut alpha = Alpha::Reject;
    let mut krate = emit::DEFAULT_CRATE.to_string();
    let mut pixelcolor = emit::DEFAULT_PIXELCOLOR.to_string();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value =
            |opt: &str| it.next().cloned().ok_or_else(|| Failure::Usage(format!("{opt} needs a value")));
        match a.as_str() {
            "-h" | "--help" => return Ok(None),
            "--name" => name = Some(value("--name")?),
            "--format" => {
                let f = value("--format")?;
                format = Some(Format::parse(&f).ok_or_else(|| {
                    Failure::Usage(format!("unknown format `{f}` (rgb565, gray8, argb4444 or a8)"))
                })?);
            }
            "--out" => out = Some(value("--out")?),
            "--crate" => krate = value("--crate")?,
            "--pixelcolor" => pixelcolor = value("--pixelcolor")?,
            "--ignore-alpha" => alpha = Alpha::Ignore,
            s if s.starts_with("--") => return Err(Failure::Usage(format!("unknown option `{s}`"))),
            s => {
                if input.replace(s.to_string()).is_some() {
                    return Err(Failure::Usage("more than one INPUT".into()));
                }
            }
        }
    }
    let input = input.ok_or_else(|| Failure::Usage("expected INPUT".into()))?;
    let name = name.ok_or_else(|| Failure::Usage("expected --name NAME".into()))?;
    let format = format.ok_or_else(|| Failure::Usage("expected --format rgb565|gray8|argb4444|a8".into()))?;
    emit::static_name(&name).map_err(Failure::Usage)?;
    for p in [&krate, &pixelcolor] {
        if !emit::is_path(p) {
            return Err(Failure::Usage(format!("`{p}` is not a valid path")));
        }
    }
    Ok(Some(Options { input, name, format, out, alpha, krate, pixelcolor }))
}

fn run(args: &[String]) -> Result<(), Failure> {
    let Some(o) = parse_args(args)? else {
        let _ = writeln!(std::io::stdout(), "{USAGE}");
        return Ok(());
    };
    let mut bytes = Vec::new();
    let (read, source) = if o.input == "-" {
        (std::io::stdin().read_to_end(&mut bytes).map(|_| ()), "<stdin>".to_string())
    } else {
        let file_name = Path::new(&o.input).file_name().map(|f| f.to_string_lossy().into_owned());
        (std::fs::read(&o.input).map(|b| bytes = b), file_name.unwrap_or_else(|| o.input.clone()))
    };
    let shown = if o.input == "-" { "<stdin>" } else { o.input.as_str() };
    read.map_err(|e| Failure::Input(format!("{shown}: {e}")))?;

    let conversion =
        Conversion { format: o.format, alpha: o.alpha, krate: o.krate, pixelcolor: o.pixelcolor };
    let converted = convert_bytes(&bytes, &o.name, &source, &conversion)
        .map_err(|e| Failure::Input(format!("{shown}: {e}")))?;
    let (src, translucent, (width, height)) = (converted.source, converted.translucent, converted.size);
    match &o.out {
        Some(path) => std::fs::write(path, &src).map_err(|e| Failure::Input(format!("{path}: {e}")))?,
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout
                .write_all(src.as_bytes())
                .and_then(|()| stdout.flush())
                .map_err(|e| Failure::Input(format!("stdout: {e}")))?;
        }
    }
    report(&format!(
        "{shown}: {width}×{height} {} texels{}",
        match o.format {
            Format::Rgb565 => "Rgb565",
            Format::Gray8 => "Gray8",
            Format::Argb4444 => "Argb4444",
            Format::A8 => "A8",
        },
        match translucent {
            0 => String::new(),
            n if o.format.has_alpha() => format!(" ({n} pixels not opaque: alpha kept)"),
            n => format!(" ({n} pixels were not opaque: alpha ignored)"),
        }
    ));
    Ok(())
}
