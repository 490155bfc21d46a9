//! `obj2rs`'s default output: the mesh's clusters ([`build_meshlets`]) as
//! Rust statics, validated at compile time, and the winding check behind
//! the converter's warning.

use std::fmt::Write;

use microraster::math::{Fx, Scalar};
use microraster::mesh::{
    Mesh, Meshlet, bounding_sphere, build_meshlets, meshlet_bound, meshlet_scratch_len, meshlet_vertex_bound,
};

use super::emit::{fx_positions, static_name, type_paths};
use super::parse::ObjMesh;

/// The clusters of a mesh, in owned buffers.
pub struct Clusters {
    pub meshlets: Vec<Meshlet>,
    pub vertices: Vec<u16>,
    pub triangles: Vec<[u8; 3]>,
}

/// Splits the mesh into clusters.
pub fn build(mesh: &ObjMesh) -> Result<Clusters, String> {
    build_of(mesh.mesh())
}

/// Splits the mesh, its positions and normals in 16.16 (`obj2rs --fx`:
/// [`fx_positions`]), into clusters whose
/// spheres and cones hold those values.
pub fn build_fx(mesh: &ObjMesh) -> Result<Clusters, String> {
    let (p, sphere) = fx_positions(mesh);
    let n: Vec<[Fx; 3]> = mesh.normals.iter().map(|r| r.map(Fx::from_f32)).collect();
    build_of(Mesh::new_fx(&p, &n, &mesh.indices, sphere))
}

fn build_of<P: Scalar>(mesh: Mesh<'_, P>) -> Result<Clusters, String> {
    let (nv, nt) = (mesh.positions.len(), mesh.indices.len());
    let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
    let mut vertices = vec![0; meshlet_vertex_bound(nt)];
    let mut triangles = vec![[0; 3]; nt];
    let mut scratch = vec![0; meshlet_scratch_len(nv, nt)];
    let m = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch)
        .map_err(|e| format!("building meshlets: {e}"))?;
    Ok(Clusters {
        meshlets: m.meshlets.to_vec(),
        vertices: m.vertices.to_vec(),
        triangles: m.triangles.to_vec(),
    })
}

/// Triangles wound against their vertex normals, by the rule of
/// [`Mesh::check_winding`] (applied to each triangle on its own).
pub fn winding_mismatches(mesh: &ObjMesh) -> usize {
    mesh.indices.iter().filter(|t| disagrees(mesh, t)).count()
}

/// Whether triangle `t` of `mesh` is wound against its normals.
fn disagrees(mesh: &ObjMesh, t: &[u16; 3]) -> bool {
    let p = t.map(|k| mesh.positions[usize::from(k)]);
    let n = t.map(|k| mesh.normals[usize::from(k)]);
    Mesh::new(&p, &n, &[[0, 1, 2]], bounding_sphere(&p)).check_winding().is_err()
}

/// Reverses the winding of every triangle that disagrees with its normals
/// ([`winding_mismatches`]), so that the mesh passes
/// [`Mesh::check_winding`]; returns how many were reversed. For a mesh
/// exported clockwise, or a few faces flipped by mistake; when the normals
/// are what points the wrong way, fix them in the modeller instead.
pub fn flip_mismatches(mesh: &mut ObjMesh) -> usize {
    let flip: Vec<bool> = mesh.indices.iter().map(|t| disagrees(mesh, t)).collect();
    for (t, _) in mesh.indices.iter_mut().zip(&flip).filter(|(_, f)| **f) {
        t.swap(1, 2);
    }
    flip.iter().filter(|&&f| f).count()
}

/// The converter's warning when triangles disagree with their normals.
pub fn winding_warning(mesh: &ObjMesh, meshlets: bool) -> Option<String> {
    let n = winding_mismatches(mesh);
    (n > 0).then(|| {
        format!(
            "warning: {n} of {} triangles are wound clockwise seen from the side their normals point to \
             (back-face culling hides them from the front; `obj2rs --flip-winding` reverses them){}",
            mesh.indices.len(),
            if meshlets {
                "; the clusters fail validation at compile time, a build error (`--plain` writes the plain mesh \
                 alone) (WindingMismatch)"
            } else {
                ""
            }
        )
    })
}

/// How the clustered output's `static NAME` is validated when the firmware
/// compiles. Either way an invalid mesh (one wound against its normals:
/// [`winding_warning`]) is a build error; they differ in what it says.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Validation {
    /// `match ValidMeshletMesh::new(..) { Ok(m) => m, Err(_) => panic!(..) }`
    /// (`new_fx` for 16.16): works with every microraster since clusters
    /// are validated, but the build error names the static, not the cause.
    Match,
    /// `ValidMeshletMesh::new_const(..)` (`new_fx_const` for 16.16): the
    /// constructor panics at compile time naming the cause
    /// (`WindingMismatch`, …); no `match` in the output.
    NewConst,
}

/// The validation [`rust_source`] writes: [`Validation::NewConst`], whose
/// build error names the cause. [`Validation::Match`] stays for a firmware
/// pinned to a microraster without `new_const`.
pub const VALIDATION: Validation = Validation::NewConst;

/// Rust source defining `NAME_MESHLETS`, `NAME_MESHLET_VERTICES`,
/// `NAME_MESHLET_TRIANGLES` and `NAME: ValidMeshletMesh<'static>`, the
/// clusters around the `NAME_MESH` static ([`emit::mesh_source`] with
/// `clustered`), validated at compile time: an invalid mesh (one wound
/// against its normals: [`winding_warning`]) is a build error naming it.
/// `Meshlet`, `MeshletMesh` and `ValidMeshletMesh` are taken from the module
/// of `mesh_type`.
///
/// [`emit::mesh_source`]: super::emit::mesh_source
pub fn rust_source(c: &Clusters, name: &str, mesh_type: &str) -> Result<String, String> {
    rust_source_with(c, name, mesh_type, false)
}

/// [`rust_source`]; with `fx` around a mesh in 16.16 (`ValidMeshletMesh<'static,
/// Fx>`, `obj2rs --fx`).
pub fn rust_source_with(c: &Clusters, name: &str, mesh_type: &str, fx: bool) -> Result<String, String> {
    rust_source_validated(c, name, mesh_type, fx, VALIDATION)
}

/// [`rust_source_with`], validated as `validation` says.
///
/// ```
/// use microraster_tools::obj::meshlets::{Clusters, Validation, rust_source_validated};
/// let c = Clusters { meshlets: vec![], vertices: vec![], triangles: vec![] };
/// let src = rust_source_validated(&c, "knot", "microraster::mesh::Mesh", false, Validation::NewConst).unwrap();
/// assert!(src.contains(
///     "pub static KNOT: microraster::mesh::ValidMeshletMesh<'static> = \
///      microraster::mesh::ValidMeshletMesh::new_const(microraster::mesh::MeshletMesh {"
/// ));
/// ```
pub fn rust_source_validated(
    c: &Clusters,
    name: &str,
    mesh_type: &str,
    fx: bool,
    validation: Validation,
) -> Result<String, String> {
    let name = static_name(name)?;
    let (module, root) = type_paths(mesh_type);
    let (storage, new) = if fx { (format!(", {root}math::Fx"), "new_fx") } else { (String::new(), "new") };
    let (nc, nl, nt) = (c.meshlets.len(), c.vertices.len(), c.triangles.len());
    let mut s = String::new();
    let w = &mut s;
    let _ = writeln!(w, "\n/// The clusters of [`{name}`]: offsets, counts, sphere and normal cone.");
    // Spheres and cones are data: one may happen to read like `LN_2`.
    let _ = writeln!(w, "#[rustfmt::skip]\n#[allow(clippy::approx_constant)]");
    let _ = writeln!(w, "pub static {name}_MESHLETS: [{module}Meshlet; {nc}] = [");
    for m in &c.meshlets {
        let (([x, y, z], r), ([a, b, d], k)) = (m.sphere, m.cone);
        let _ = writeln!(
            w,
            "    {module}Meshlet {{ vertex_offset: {}, triangle_offset: {}, vertex_count: {}, triangle_count: {}, \
             sphere: ([{x:?}, {y:?}, {z:?}], {r:?}), cone: ([{a:?}, {b:?}, {d:?}], {k:?}) }},",
            m.vertex_offset, m.triangle_offset, m.vertex_count, m.triangle_count
        );
    }
    let _ = writeln!(w, "];\n\n/// Mesh vertex of each cluster-local vertex of [`{name}_MESHLETS`].");
    let _ = writeln!(w, "#[rustfmt::skip]\npub static {name}_MESHLET_VERTICES: [u16; {nl}] = [");
    for chunk in c.vertices.chunks(16) {
        let row: Vec<String> = chunk.iter().map(u16::to_string).collect();
        let _ = writeln!(w, "    {},", row.join(", "));
    }
    let _ = writeln!(w, "];\n\n/// Cluster-local triangles of [`{name}_MESHLETS`].");
    let _ = writeln!(w, "#[rustfmt::skip]\npub static {name}_MESHLET_TRIANGLES: [[u8; 3]; {nt}] = [");
    for chunk in c.triangles.chunks(8) {
        let row: Vec<String> = chunk.iter().map(|[a, b, d]| format!("[{a}, {b}, {d}]")).collect();
        let _ = writeln!(w, "    {},", row.join(", "));
    }
    let _ = writeln!(w, "];\n");
    let _ = writeln!(w, "/// [`{name}_MESH`] in clusters, validated at compile time: draw it with `View3d`");
    let _ = writeln!(w, "/// (`Object::new(&{name}, colour)`) or `Pipeline::draw_meshlets`.");
    // A big mesh's checks run for seconds of constant evaluation.
    let _ = writeln!(w, "#[allow(long_running_const_eval)]\n#[rustfmt::skip]");
    let ty = format!("{module}ValidMeshletMesh<'static{storage}>");
    let fields = format!(
        "    mesh: {name}_MESH,\n    meshlets: &{name}_MESHLETS,\n    vertices: &{name}_MESHLET_VERTICES,\n    \
         triangles: &{name}_MESHLET_TRIANGLES,"
    );
    match validation {
        Validation::NewConst => {
            let _ = writeln!(
                w,
                "pub static {name}: {ty} = {module}ValidMeshletMesh::{new}_const({module}MeshletMesh {{\n{fields}\n}});"
            );
        }
        Validation::Match => {
            let _ = writeln!(
                w,
                "pub static {name}: {ty} = match {module}ValidMeshletMesh::{new}({module}MeshletMesh {{\n{fields}"
            );
            let _ = writeln!(w, "}}) {{\n    Ok(m) => m,");
            let _ = writeln!(
                w,
                "    Err(_) => panic!(\"{name}: the mesh fails validation (triangles wound against their normals? see obj2rs's warning)\"),"
            );
            let _ = writeln!(w, "}};");
        }
    }
    Ok(s)
}
