//! obj2rs: converts a Wavefront OBJ file into Rust source for a `static`
//! mesh in clusters, [`microraster::mesh::ValidMeshletMesh`], checked at
//! compile time (arrays in flash, no RAM).
//!
//! ```text
//! obj2rs INPUT.obj NAME [--plain | --fx] [--mesh-type PATH] [--flip-winding] > out.rs
//! ```
//!
//! Writes `NAME_POSITIONS`, `NAME_NORMALS`, `NAME_INDICES`, the plain
//! `NAME_MESH: Mesh<'static>`, the clusters (`NAME_MESHLETS`,
//! `NAME_MESHLET_VERTICES`, `NAME_MESHLET_TRIANGLES`, see `obj::meshlets`)
//! and `NAME: ValidMeshletMesh<'static>` (NAME upper-cased) to standard
//! output: `Object::new(&NAME, colour)` draws it in a `View3d` at the
//! meshlet path's speed. `INPUT` `-` reads standard input. `--plain` writes
//! the plain mesh alone, as `NAME: Mesh<'static>` (`--meshlets`, the
//! default, is still accepted). `--mesh-type` sets the path of `Mesh` in
//! the output (default `microraster::mesh::Mesh`; `crate::mesh::Mesh`
//! inside microraster); the cluster types come from its module. `--fx`
//! stores positions and normals in 16.16 (`ValidMeshletMesh<'static, Fx>`,
//! converted at compile time from the same `f32` literals), for the
//! fixed-point vertex stage of a part without an FPU, which then reads them
//! without a conversion.
//! See `obj::parse` for the OBJ subset understood. Installed by
//! `cargo install --path tools`; `microraster_tools::obj` is the same
//! conversion for build scripts. Errors name the line and
//! exit with status 1 (2 for bad arguments). Triangles wound against the
//! file's normals are reported with a warning on stderr (not an error: the
//! output is still written, but its clusters fail their compile-time
//! check), with their count; `--flip-winding` reverses them (reported on
//! stderr too).

use std::io::{Read, Write};
use std::path::Path;
use std::process::ExitCode;

use microraster_tools::obj::{Options, convert_bytes, emit};

const USAGE: &str = "usage: obj2rs INPUT.obj NAME [--plain | --fx] [--mesh-type PATH] [--flip-winding] > out.rs   (INPUT `-` = stdin)";

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
    let _ = writeln!(std::io::stderr(), "obj2rs: {msg}");
}

fn run(args: &[String]) -> Result<(), Failure> {
    let mut positional = Vec::new();
    let mut mesh_type = emit::DEFAULT_MESH_TYPE.to_string();
    let mut with_meshlets = true;
    let mut flip_winding = false;
    let mut fx = false;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "-h" | "--help" => {
                let _ = writeln!(std::io::stdout(), "{USAGE}");
                return Ok(());
            }
            "--mesh-type" => {
                mesh_type =
                    it.next().ok_or_else(|| Failure::Usage("--mesh-type needs a value".into()))?.clone();
            }
            // The default since clusters are what a `View3d` draws fastest.
            "--meshlets" => {}
            "--plain" => with_meshlets = false,
            "--flip-winding" => flip_winding = true,
            "--fx" => fx = true,
            s if s.starts_with("--") => return Err(Failure::Usage(format!("unknown option `{s}`"))),
            _ => positional.push(a.as_str()),
        }
    }
    let [input, name] = positional[..] else {
        return Err(Failure::Usage("expected INPUT and NAME".into()));
    };
    emit::static_name(name).map_err(Failure::Usage)?;
    if !emit::is_type_path(&mesh_type) {
        return Err(Failure::Usage(format!("`{mesh_type}` is not a valid type path")));
    }

    let mut bytes = Vec::new();
    let (read, source) = if input == "-" {
        (std::io::stdin().read_to_end(&mut bytes).map(|_| ()), "<stdin>".to_string())
    } else {
        let file_name = Path::new(input).file_name().map(|f| f.to_string_lossy().into_owned());
        (std::fs::read(input).map(|b| bytes = b), file_name.unwrap_or_else(|| input.to_string()))
    };
    let shown = if input == "-" { "<stdin>" } else { input };
    read.map_err(|e| Failure::Input(format!("{shown}: {e}")))?;
    let options = Options { mesh_type, meshlets: with_meshlets, flip_winding, fx };
    let converted = convert_bytes(&bytes, name, &source, &options)
        .map_err(|e| Failure::Input(format!("{shown}: {e}")))?;
    if let Some(warning) = &converted.winding_warning {
        report(&format!("{shown}: {warning}"));
    }
    if converted.flipped > 0 {
        report(&format!("{shown}: reversed {} triangles wound against their normals", converted.flipped));
    }
    let (mesh, out) = (&converted.mesh, &converted.source);
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_all(out.as_bytes())
        .and_then(|()| stdout.flush())
        .map_err(|e| Failure::Input(format!("stdout: {e}")))?;
    report(&format!(
        "{shown}: {} vertices, {} triangles; {} normals computed{}{}",
        mesh.positions.len(),
        mesh.indices.len(),
        mesh.computed_normals,
        match mesh.arbitrary_normals {
            0 => String::new(),
            n => format!(" ({n} without any non-degenerate triangle set to +z)"),
        },
        match mesh.dropped_triangles {
            0 => String::new(),
            n => format!(", {n} degenerate triangles dropped"),
        },
    ));
    Ok(())
}
