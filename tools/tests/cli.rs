//! The two converters as a user runs them: `--help` explains every option
//! with an example, both take `--name NAME` and `--out FILE` (stdout
//! without), the old positional NAME of `obj2rs` still works with a
//! deprecation warning, bad arguments are clear errors with exit status 2,
//! and `png2rs --format rgb565a8` writes a texture that compiles
//! (`assets/glow.rs`) and keeps 256 alpha levels.

mod common;

use std::path::PathBuf;
use std::process::{Command, Output};

use common::encode;
use png::{BitDepth, ColorType};

/// The committed `png2rs --format rgb565a8` output for [`glow_png`],
/// compiled as part of this test. Regenerate after changing the emitter:
/// `PNG2RS_WRITE_GLOW=1 cargo test -p microraster-tools --test cli glow`.
mod generated {
    include!("../../assets/glow.rs");
}

const TETRA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/tetra.obj");

fn run(bin: &str, args: &[&str]) -> Output {
    Command::new(bin).args(args).output().unwrap()
}
fn obj2rs(args: &[&str]) -> Output {
    run(env!("CARGO_BIN_EXE_obj2rs"), args)
}
fn png2rs(args: &[&str]) -> Output {
    run(env!("CARGO_BIN_EXE_png2rs"), args)
}
fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A scratch directory of this test process.
fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("microraster-cli-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A 16 × 16 RGBA icon whose alpha takes every level once (`16·y + x`),
/// over a colour ramp.
fn glow_png() -> Vec<u8> {
    let data: Vec<u8> = (0..256u32)
        .flat_map(|i| [(i % 16) as u8 * 17, (i / 16) as u8 * 17, 255 - (i % 16) as u8 * 8, i as u8])
        .collect();
    encode(16, 16, ColorType::Rgba, BitDepth::Eight, &data, None, None)
}

#[test]
fn help_explains_every_option_with_an_example() {
    let cases: [(&str, &[&str]); 2] = [
        (
            env!("CARGO_BIN_EXE_obj2rs"),
            &[
                "--name",
                "--out",
                "--plain",
                "--fx",
                "--flip-winding",
                "--mesh-type",
                "--meshlets",
                "-h, --help",
            ],
        ),
        (
            env!("CARGO_BIN_EXE_png2rs"),
            &[
                "--name",
                "--out",
                "--format",
                "rgb565",
                "gray8",
                "rgb565a8",
                "argb4444",
                "a8",
                "--ignore-alpha",
                "--crate",
                "--pixelcolor",
                "-h, --help",
            ],
        ),
    ];
    for (bin, options) in cases {
        for flag in ["--help", "-h"] {
            let out = run(bin, &[flag]);
            let help = text(&out.stdout);
            assert_eq!(out.status.code(), Some(0), "{bin} {flag}");
            assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
            for o in options {
                // Each option starts a line of the options list, followed by what it does.
                let line = help
                    .lines()
                    .find(|l| l.trim_start().starts_with(o))
                    .unwrap_or_else(|| panic!("{bin}: {o}"));
                assert!(line.trim_start().len() > o.len() + 10, "{bin}: `{o}` is explained: {line:?}");
            }
            let tool = if bin.contains("obj2rs") { "obj2rs" } else { "png2rs" };
            assert!(help.contains("Examples:") && help.contains(&format!("  {tool} ")), "{help}");
            assert!(help.contains("Exit status"), "{help}");
        }
    }
}

#[test]
fn obj2rs_name_and_out_and_the_deprecated_positional_name() {
    let golden = include_str!("../../assets/tetra.rs");
    // --name, to stdout; the `=` form too.
    for args in
        [&[TETRA, "--name", "TETRA"][..], &["--name=TETRA", TETRA], &[TETRA, "--name", "TETRA", "--out", "-"]]
    {
        let out = obj2rs(args);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", text(&out.stderr));
        assert_eq!(text(&out.stdout), golden, "{args:?}");
        assert!(!text(&out.stderr).contains("warning"), "{}", text(&out.stderr));
    }
    // --out FILE: nothing on stdout.
    let dir = scratch("obj");
    let file = dir.join("tetra.rs");
    let out = obj2rs(&[TETRA, "--name", "TETRA", "--out", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&file).unwrap(), golden);
    // The old form: the same output, and a warning saying what to write.
    let out = obj2rs(&[TETRA, "TETRA"]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(text(&out.stdout), golden);
    let err = text(&out.stderr);
    assert!(err.contains("deprecated") && err.contains("--name TETRA"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_arguments_are_clear_errors_with_status_2() {
    let obj_cases: [(&[&str], &str); 10] = [
        (&[TETRA, "--name"], "--name needs a value"),
        (&[TETRA, "--name", "--out", "x.rs"], "--name needs a value (found the option `--out`)"),
        (&[TETRA, "--name", "T", "--out"], "--out needs a value"),
        (&[TETRA, "--name", "T", "--bogus"], "unknown option `--bogus`"),
        (&[TETRA, "--name", "T", "-x"], "unknown option `-x`"),
        (&[TETRA, "--name", "T", "--plain=yes"], "--plain takes no value"),
        (&[TETRA, "--name", "T", "--name", "U"], "--name given twice"),
        (&[TETRA, "T", "--name", "U"], "unexpected argument `T`"),
        (&[TETRA], "expected --name NAME"),
        (&[TETRA, "--name", "T", "--fx", "--plain"], "--fx needs the clusters"),
    ];
    for (args, msg) in obj_cases {
        let out = obj2rs(args);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(err.starts_with(&format!("obj2rs: {msg}")), "{args:?}: {err}");
        assert!(err.contains("usage: obj2rs") && err.contains("obj2rs --help"), "{err}");
    }
    let png_cases: [(&[&str], &str); 7] = [
        (&["x.png", "--name", "x", "--format"], "--format needs a value"),
        (
            &["x.png", "--name", "x", "--format", "rgb888"],
            "unknown format `rgb888` (one of rgb565, gray8, rgb565a8",
        ),
        (&["x.png", "--format", "rgb565"], "expected --name NAME"),
        (&["x.png", "--name", "x"], "expected --format FORMAT"),
        (&["--name", "x", "--format", "a8"], "expected INPUT"),
        (&["x.png", "--name", "2x", "--format", "a8"], "`2x` is not a valid Rust identifier"),
        (&["x.png", "--name", "x", "--format", "a8", "--colour", "red"], "unknown option `--colour`"),
    ];
    for (args, msg) in png_cases {
        let out = png2rs(args);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with(&format!("png2rs: {msg}")), "{args:?}: {err}");
        assert!(err.contains("usage: png2rs") && err.contains("png2rs --help"), "{err}");
    }
    // A missing file is bad input, not a bad argument: status 1.
    let out = obj2rs(&["/nonexistent/x.obj", "--name", "x"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).starts_with("obj2rs: /nonexistent/x.obj: "), "{}", text(&out.stderr));
}

#[test]
fn png2rs_on_an_rgba_image_names_the_formats_that_keep_alpha() {
    let dir = scratch("alpha");
    let png = dir.join("glow.png");
    std::fs::write(&png, glow_png()).unwrap();
    let path = png.to_str().unwrap();
    for format in ["rgb565", "gray8"] {
        let out = png2rs(&[path, "--name", "glow", "--format", format]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{err}");
        assert!(out.stdout.is_empty());
        assert!(err.contains("--format rgb565a8, argb4444 or a8") && err.contains("--ignore-alpha"), "{err}");
    }
    let out = png2rs(&[path, "--name", "glow", "--format", "rgb565", "--ignore-alpha"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(text(&out.stderr).contains("255 pixels were not opaque: alpha ignored"), "{}", text(&out.stderr));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `png2rs glow.png --name glow --format rgb565a8` is the committed
/// `assets/glow.rs`, whose `GLOW` compiles and holds each pixel's colour at
/// Rgb565 and its alpha at 8 bits: every one of the 256 levels.
#[test]
fn glow_rgb565a8_output_is_current_and_keeps_256_alpha_levels() {
    use microraster::texture::TexelFormat;
    let dir = scratch("glow");
    let png = dir.join("glow.png");
    std::fs::write(&png, glow_png()).unwrap();
    let out_file = dir.join("glow.rs");
    let out = png2rs(&[
        png.to_str().unwrap(),
        "--name",
        "glow",
        "--format",
        "rgb565a8",
        "--out",
        out_file.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty());
    let src = std::fs::read_to_string(&out_file).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    if std::env::var_os("PNG2RS_WRITE_GLOW").is_some() {
        std::fs::write(concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/glow.rs"), &src).unwrap();
    }
    assert_eq!(src, include_str!("../../assets/glow.rs"), "regenerate (see `mod generated`)");
    let tex = &generated::GLOW;
    assert_eq!((tex.width(), tex.height()), (16, 16));
    for (i, &texel) in tex.data().iter().enumerate() {
        let (x, y) = ((i % 16) as f64, (i / 16) as f64);
        let q = |v: f64, m: f64| (v * m / 255.0).round() as u16;
        let rgb = (q(x * 17.0, 31.0) << 11) | (q(y * 17.0, 63.0) << 5) | q(255.0 - x * 8.0, 31.0);
        assert_eq!(texel, [(rgb >> 8) as u8, rgb as u8, i as u8], "texel {i}");
        assert_eq!(microraster::texture::Rgb565A8::alpha(texel), i as u8);
    }
}
