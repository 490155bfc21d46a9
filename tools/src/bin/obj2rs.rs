//! obj2rs: converts a Wavefront OBJ file into Rust source for a `static`
//! mesh, by default in clusters
//! ([`microraster::mesh::ValidMeshletMesh`]) checked when the firmware
//! compiles (arrays in flash, no RAM). `obj2rs --help` says what each option
//! does (the text is `HELP` below); `microraster_tools::obj` is the same
//! conversion for build scripts.

use microraster_tools::cli::{self, Arg, Args, Failure};
use microraster_tools::obj::{Options, convert_bytes, emit};

const USAGE: &str = "usage: obj2rs INPUT.obj --name NAME [--out FILE] [--plain | --fx] [--flip-winding] \
                     [--mesh-type PATH]";

/// What `obj2rs --help` prints.
const HELP: &str = "\
obj2rs: converts a Wavefront OBJ file into Rust source for a `static`
microraster mesh (arrays in flash, no RAM). By default the mesh is split
into clusters and validated when the firmware compiles: an inconsistent mesh
is a build error naming the cause.

Usage:
  obj2rs INPUT.obj --name NAME [--out FILE] [options]

Arguments:
  INPUT.obj           the OBJ file, `-` for standard input: `v`, `vn` and
                      `f` (triangles; polygons as fans; negative indices);
                      other statements are ignored. Normals missing from the
                      file are computed (area-weighted).

Options (`--opt VALUE` or `--opt=VALUE`, in any order):
  --name NAME         required: names the statics. NAME upper-cased is the
                      mesh to draw; NAME_POSITIONS, NAME_NORMALS,
                      NAME_INDICES, NAME_MESH and NAME_MESHLETS... hold its
                      data (`--name teapot` gives TEAPOT, TEAPOT_MESH...).
  --out FILE          write the source to FILE (default, or `-`: standard
                      output).
  --plain             write the plain mesh alone: NAME is a `Mesh<'static>`
                      (no cluster arrays in flash; drawn without the
                      per-cluster culling). Default: NAME
                      is a `ValidMeshletMesh<'static>`, the fastest path in a
                      `View3d`, and NAME_MESH the plain mesh.
  --fx                positions and normals in 16.16 fixed point
                      (`ValidMeshletMesh<'static, Fx>`), for the fixed-point
                      vertex stage of a part without an FPU. Not with
                      --plain.
  --flip-winding      reverse the triangles wound against their normals.
                      Without it they are reported with a warning, and the
                      clusters fail their compile-time check.
  --mesh-type PATH    path of `Mesh` in the output (default
                      `microraster::mesh::Mesh`; `crate::mesh::Mesh` inside
                      microraster itself); the cluster types come from its
                      module.
  --meshlets          the default (accepted for old scripts).
  -h, --help          print this help.

Examples:
  obj2rs teapot.obj --name teapot --out src/teapot.rs
      then `mod teapot;` and, in a `View3d` scene,
      `Object::new(&teapot::TEAPOT, Rgb565::CYAN)`
  obj2rs knot.obj --name knot --fx --flip-winding > src/knot.rs

In a build script: `microraster_tools::obj::convert(path, name)`.
The NAME as a second argument (`obj2rs teapot.obj TEAPOT`) still works in
this release, with a deprecation warning; it will be removed.
Exit status: 0 converted (warnings on stderr), 1 the input could not be read
or converted (parse errors name the line), 2 bad arguments.
";

fn main() -> std::process::ExitCode {
    cli::main("obj2rs", USAGE, run)
}

struct Parsed<'a> {
    input: &'a str,
    name: &'a str,
    out: Option<&'a str>,
    options: Options,
}

fn parse_args(args: &[String]) -> Result<Option<Parsed<'_>>, Failure> {
    let mut positional = Vec::new();
    let (mut name, mut out, mut mesh_type) = (None, None, None);
    let mut options = Options::default();
    let mut it = Args::new(args);
    while let Some(a) = it.next_arg()? {
        match a {
            Arg::Opt("-h" | "--help") => return Ok(None),
            Arg::Opt(o @ "--name") => cli::once(&mut name, o, it.value(o)?)?,
            Arg::Opt(o @ "--out") => cli::once(&mut out, o, it.value(o)?)?,
            Arg::Opt(o @ "--mesh-type") => cli::once(&mut mesh_type, o, it.value(o)?)?,
            // The default since clusters are what a `View3d` draws fastest.
            Arg::Opt("--meshlets") => {}
            Arg::Opt("--plain") => options.meshlets = false,
            Arg::Opt("--flip-winding") => options.flip_winding = true,
            Arg::Opt("--fx") => options.fx = true,
            Arg::Opt(o) => return Err(Failure::Usage(format!("unknown option `{o}`"))),
            Arg::Positional(p) => positional.push(p),
        }
    }
    let input = match positional[..] {
        [] => return Err(Failure::Usage("expected INPUT (an OBJ file, or `-`)".into())),
        [input] => input,
        // The form before `--name`: kept for one release.
        [input, old_name] if name.is_none() => {
            cli::report(
                "obj2rs",
                &format!(
                    "warning: NAME as the second argument is deprecated and will be removed; \
                     write `--name {old_name}`"
                ),
            );
            name = Some(old_name);
            input
        }
        [_, extra, ..] => return Err(Failure::Usage(format!("unexpected argument `{extra}`"))),
    };
    let name = name.ok_or_else(|| Failure::Usage("expected --name NAME".into()))?;
    emit::static_name(name).map_err(Failure::Usage)?;
    if let Some(t) = mesh_type {
        if !emit::is_type_path(t) {
            return Err(Failure::Usage(format!("`{t}` is not a valid type path")));
        }
        options.mesh_type = t.to_string();
    }
    if options.fx && !options.meshlets {
        return Err(Failure::Usage("--fx needs the clusters: it cannot be combined with --plain".into()));
    }
    Ok(Some(Parsed { input, name, out: out.filter(|&o| o != "-"), options }))
}

fn run(args: &[String]) -> Result<(), Failure> {
    let Some(p) = parse_args(args)? else {
        cli::print(HELP);
        return Ok(());
    };
    let input = cli::read_input(p.input)?;
    let shown = &input.shown;
    let converted = convert_bytes(&input.bytes, p.name, &input.source, &p.options)
        .map_err(|e| Failure::Input(format!("{shown}: {e}")))?;
    let report = |msg: String| cli::report("obj2rs", &format!("{shown}: {msg}"));
    if let Some(warning) = &converted.winding_warning {
        report(warning.clone());
    }
    if converted.flipped > 0 {
        report(format!("reversed {} triangles wound against their normals", converted.flipped));
    }
    cli::write_output(p.out, &converted.source)?;
    let mesh = &converted.mesh;
    report(format!(
        "{} vertices, {} triangles; {} normals computed{}{}",
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
