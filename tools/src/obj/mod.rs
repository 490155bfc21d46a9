//! Wavefront OBJ → Rust source for a `static` mesh in clusters
//! ([`ValidMeshletMesh`](microraster::mesh::ValidMeshletMesh)) or a plain
//! [`Mesh`](microraster::mesh::Mesh) (the `obj2rs` binary, and [`convert`]
//! for build scripts).
//!
//! By default ([`Options::meshlets`]) the output defines `NAME_POSITIONS`,
//! `NAME_NORMALS`, `NAME_INDICES`, the plain `NAME_MESH: Mesh<'static>`,
//! the clusters (`NAME_MESHLETS`, `NAME_MESHLET_VERTICES`,
//! `NAME_MESHLET_TRIANGLES`) and `NAME: ValidMeshletMesh<'static>`, checked
//! at compile time: `Object::new(&NAME, colour)` in a `View3d` scene, or
//! `Pipeline::draw_meshlets`, draws it cluster by cluster, skipping the
//! clusters outside each band or facing away before any vertex work.
//! Without clusters (`obj2rs --plain`) `NAME` is the plain `Mesh<'static>`.
//! See [`parse`] for the OBJ subset understood.

pub mod emit;
pub mod meshlets;
pub mod parse;

use std::path::Path;

use crate::{Error, in_file};

/// How [`convert_bytes`] writes its output.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// Path of `Mesh` in the output (default `microraster::mesh::Mesh`;
    /// `crate::mesh::Mesh` inside microraster).
    pub mesh_type: String,
    /// Write the clusters and make `NAME` the validated
    /// `ValidMeshletMesh` (the default; `false` is `obj2rs --plain`: `NAME`
    /// is the plain `Mesh`).
    pub meshlets: bool,
    /// Reverse the triangles wound against their normals before writing
    /// (`--flip-winding`, [`meshlets::flip_mismatches`]).
    pub flip_winding: bool,
    /// Positions and normals in 16.16 (`--fx`, for the fixed-point vertex
    /// stage, which then reads them without a conversion;
    /// [`emit::rust_source_with`]). Needs [`Options::meshlets`] (not
    /// `--plain`): 16.16 data is drawn through the meshlet path.
    pub fx: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            mesh_type: emit::DEFAULT_MESH_TYPE.to_string(),
            meshlets: true,
            flip_winding: false,
            fx: false,
        }
    }
}

/// A conversion: the Rust source, the mesh it describes, and the warning
/// when triangles are wound against their normals (see
/// [`meshlets::winding_warning`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Converted {
    /// The generated Rust source.
    pub source: String,
    /// The converted mesh (counts and statistics for a report).
    pub mesh: parse::ObjMesh,
    /// `Some` when some triangle's winding disagrees with its normals
    /// (drawn inside out with back faces culled); always `None` with
    /// [`Options::flip_winding`].
    pub winding_warning: Option<String>,
    /// Triangles reversed by [`Options::flip_winding`] (0 without it).
    pub flipped: usize,
}

/// Converts the OBJ file at `path` into Rust source for `static NAME:
/// ValidMeshletMesh` (NAME is `name` upper-cased) and the plain `NAME_MESH`,
/// with the default [`Options`].
///
/// Meant for `build.rs`, where nobody reads warnings: a winding that
/// disagrees with the file's normals is an error here (the `obj2rs` binary
/// only warns); use [`convert_bytes`] to accept it.
///
/// # Errors
///
/// The file cannot be read or parsed, `name` is not an identifier, or the
/// winding disagrees with the normals.
///
/// ```
/// let src = microraster_tools::obj::convert(concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/tetra.obj"), "tetra")?;
/// assert!(src.contains("pub static TETRA: microraster::mesh::ValidMeshletMesh<'static>"));
/// assert!(src.contains("pub static TETRA_MESH: microraster::mesh::Mesh<'static>"));
/// # Ok::<(), microraster_tools::Error>(())
/// ```
pub fn convert(path: impl AsRef<Path>, name: &str) -> Result<String, Error> {
    let (file, bytes) = crate::read(path.as_ref())?;
    let c = convert_bytes(&bytes, name, &file, &Options::default()).map_err(|e| in_file(path.as_ref(), e))?;
    match c.winding_warning {
        Some(w) => Err(in_file(path.as_ref(), Error(w))),
        None => Ok(c.source),
    }
}

/// Converts OBJ text (`bytes`; only comments and names may be non-ASCII)
/// named `source` in the header comment.
///
/// # Errors
///
/// A parse error (with its line), an invalid `name` or
/// [`Options::mesh_type`], or a mesh the cluster builder rejects.
///
/// ```
/// use microraster_tools::obj::{Options, convert_bytes};
/// // One triangle whose normal points against its winding.
/// let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -1\nf 1//1 2//1 3//1\n";
/// let c = convert_bytes(obj, "tri", "tri.obj", &Options::default())?;
/// assert!(c.source.contains("pub static TRI_INDICES"));
/// // `NAME` is the mesh in clusters unless told otherwise.
/// assert!(c.source.contains("pub static TRI: microraster::mesh::ValidMeshletMesh<'static>"));
/// let plain = Options { meshlets: false, ..Options::default() };
/// let c = convert_bytes(obj, "tri", "tri.obj", &plain)?;
/// assert!(c.source.contains("pub static TRI: microraster::mesh::Mesh<'static>"));
/// assert!(c.winding_warning.is_some());
/// // Reversed on request: the mesh then passes `Mesh::check_winding`.
/// let flip = Options { flip_winding: true, ..Options::default() };
/// let c = convert_bytes(obj, "tri", "tri.obj", &flip)?;
/// assert_eq!((c.flipped, c.winding_warning, c.mesh.indices[0]), (1, None, [0, 2, 1]));
/// # Ok::<(), microraster_tools::Error>(())
/// ```
pub fn convert_bytes(bytes: &[u8], name: &str, source: &str, options: &Options) -> Result<Converted, Error> {
    if options.fx && !options.meshlets {
        return Err(Error(
            "16.16 output (`--fx`) needs the clusters (not `--plain`): it is drawn through the meshlet path"
                .into(),
        ));
    }
    let text = String::from_utf8_lossy(bytes);
    let mut mesh = parse::parse_obj(&text).map_err(|e| Error(e.to_string()))?;
    let flipped = if options.flip_winding { meshlets::flip_mismatches(&mut mesh) } else { 0 };
    let (ty, fx) = (&options.mesh_type, options.fx);
    let mut out = emit::mesh_source(&mesh, name, source, ty, fx, options.meshlets).map_err(Error)?;
    if options.meshlets {
        let clusters =
            if options.fx { meshlets::build_fx(&mesh) } else { meshlets::build(&mesh) }.map_err(Error)?;
        out += &meshlets::rust_source_with(&clusters, name, &options.mesh_type, options.fx).map_err(Error)?;
    }
    let winding_warning = meshlets::winding_warning(&mesh, options.meshlets);
    Ok(Converted { source: out, mesh, winding_warning, flipped })
}
