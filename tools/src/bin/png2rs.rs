//! png2rs: converts a PNG image into Rust source for a `static`
//! [`microraster::texture::Texture`] (texels in flash, no RAM). `png2rs
//! --help` says what each option does (the text is `HELP` below);
//! `microraster_tools::png` is the same conversion for build scripts.

use microraster_tools::cli::{self, Arg, Args, Failure};
use microraster_tools::png::{Alpha, Format, Options as Conversion, convert_bytes, emit};

const USAGE: &str = "usage: png2rs INPUT.png --name NAME --format FORMAT [--out FILE] [--ignore-alpha] \
                     [--crate PATH] [--pixelcolor PATH]";

/// What `png2rs --help` prints.
const HELP: &str = "\
png2rs: converts a PNG image into Rust source for a `static` microraster
texture: the texels in a `static` array (flash, no RAM) and a
`Texture<'static, F>` over it, its size checked when the firmware compiles.

Usage:
  png2rs INPUT.png --name NAME --format FORMAT [--out FILE] [options]

Arguments:
  INPUT.png           the image, `-` for standard input. Any PNG: palette,
                      grey or RGB, with or without alpha, 1 to 16 bits a
                      sample, 1 to 4096 pixels each way.

Options (`--opt VALUE` or `--opt=VALUE`, in any order):
  --name NAME         required: names the statics. NAME upper-cased is the
                      texture, NAME_TEXELS its texels (`--name icon` gives
                      ICON and ICON_TEXELS).
  --format FORMAT     required: the texel format.
                        rgb565    colour, 2 bytes a texel, no alpha
                        gray8     grey (a colour image's Rec. 601 luma),
                                  1 byte, no alpha
                        rgb565a8  colour and 256-level alpha, 3 bytes: icons
                                  with soft edges, fades, glows
                        argb4444  colour and alpha at 4 bits each, 2 bytes:
                                  alpha in 16 steps (gradients show bands)
                        a8        alpha alone, 1 byte: a mask tinted by the
                                  colour it is drawn in (glyphs, symbols)
  --out FILE          write the source to FILE (default, or `-`: standard
                      output).
  --ignore-alpha      with rgb565 or gray8: drop the alpha of pixels that are
                      not opaque, keeping their colour. Without it such
                      pixels are an error naming the formats that keep alpha.
  --crate PATH        path of microraster in the output (default
                      `microraster`; `crate` inside microraster itself).
  --pixelcolor PATH   path of the module with `Rgb565` and `Gray8` (default
                      `embedded_graphics::pixelcolor`).
  -h, --help          print this help.

Every channel is rounded once to the nearest level of the format, from the
PNG's own precision (16-bit samples are not truncated to 8 first).
Alpha is straight (not premultiplied).

Examples:
  png2rs icon.png --name icon --format rgb565a8 --out src/icon.rs
      then `mod icon;` and, in a band pass,
      `Sprite::new(&icon::ICON).at(Point::new(8, 8)).blend_into(view)?`
  png2rs bricks.png --name bricks --format rgb565 > src/bricks.rs

In a build script: `microraster_tools::png::convert(path, name, format)`.
Exit status: 0 converted, 1 the input could not be read or converted,
2 bad arguments.
";

fn main() -> std::process::ExitCode {
    cli::main("png2rs", USAGE, run)
}

struct Options<'a> {
    input: &'a str,
    name: &'a str,
    format: Format,
    out: Option<&'a str>,
    alpha: Alpha,
    krate: String,
    pixelcolor: String,
}

fn parse_args(args: &[String]) -> Result<Option<Options<'_>>, Failure> {
    let (mut input, mut name, mut format, mut out) = (None, None, None, None);
    let (mut krate, mut pixelcolor) = (None, None);
    let mut alpha = Alpha::Reject;
    let mut it = Args::new(args);
    while let Some(a) = it.next_arg()? {
        match a {
            Arg::Opt("-h" | "--help") => return Ok(None),
            Arg::Opt(o @ "--name") => cli::once(&mut name, o, it.value(o)?)?,
            Arg::Opt(o @ "--format") => {
                let f = it.value(o)?;
                let known = Format::parse(f).ok_or_else(|| {
                    let names: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
                    Failure::Usage(format!("unknown format `{f}` (one of {})", names.join(", ")))
                })?;
                cli::once(&mut format, o, known)?;
            }
            Arg::Opt(o @ "--out") => cli::once(&mut out, o, it.value(o)?)?,
            Arg::Opt(o @ "--crate") => cli::once(&mut krate, o, it.value(o)?)?,
            Arg::Opt(o @ "--pixelcolor") => cli::once(&mut pixelcolor, o, it.value(o)?)?,
            Arg::Opt("--ignore-alpha") => alpha = Alpha::Ignore,
            Arg::Opt(o) => return Err(Failure::Usage(format!("unknown option `{o}`"))),
            Arg::Positional(p) => {
                if input.replace(p).is_some() {
                    return Err(Failure::Usage(format!("more than one INPUT (`{p}`)")));
                }
            }
        }
    }
    let input = input.ok_or_else(|| Failure::Usage("expected INPUT (a PNG file, or `-`)".into()))?;
    let name = name.ok_or_else(|| Failure::Usage("expected --name NAME".into()))?;
    let format = format.ok_or_else(|| {
        Failure::Usage("expected --format FORMAT (rgb565, gray8, rgb565a8, argb4444 or a8)".into())
    })?;
    emit::static_name(name).map_err(Failure::Usage)?;
    let krate = krate.unwrap_or(emit::DEFAULT_CRATE).to_string();
    let pixelcolor = pixelcolor.unwrap_or(emit::DEFAULT_PIXELCOLOR).to_string();
    for p in [&krate, &pixelcolor] {
        if !emit::is_path(p) {
            return Err(Failure::Usage(format!("`{p}` is not a valid path")));
        }
    }
    let out = out.filter(|&o| o != "-");
    Ok(Some(Options { input, name, format, out, alpha, krate, pixelcolor }))
}

fn run(args: &[String]) -> Result<(), Failure> {
    let Some(o) = parse_args(args)? else {
        cli::print(HELP);
        return Ok(());
    };
    let input = cli::read_input(o.input)?;
    let shown = &input.shown;
    let conversion =
        Conversion { format: o.format, alpha: o.alpha, krate: o.krate, pixelcolor: o.pixelcolor };
    let converted = convert_bytes(&input.bytes, o.name, &input.source, &conversion)
        .map_err(|e| Failure::Input(format!("{shown}: {e}")))?;
    cli::write_output(o.out, &converted.source)?;
    let (width, height) = converted.size;
    cli::report(
        "png2rs",
        &format!(
            "{shown}: {width}×{height} {} texels{}",
            o.format.type_name(),
            match converted.translucent {
                0 => String::new(),
                n if o.format.has_alpha() => format!(" ({n} pixels not opaque: alpha kept)"),
                n => format!(" ({n} pixels were not opaque: alpha ignored)"),
            }
        ),
    );
    Ok(())
}
