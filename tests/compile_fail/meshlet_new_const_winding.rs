// error: triangles are wound against their normals
// `ValidMeshletMesh::new_const` in a `static`: a cluster triangle wound
// against its normals is a build error whose message names the cause (no
// hand-written `match`, no message of the user's own).
use microraster::mesh::{Mesh, Meshlet, MeshletMesh, ValidMeshletMesh};

static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
static NORMALS: [[f32; 3]; 3] = [[0.0, 0.0, 1.0]; 3];
static CLUSTERS: [Meshlet; 1] = [Meshlet {
    vertex_offset: 0,
    triangle_offset: 0,
    vertex_count: 3,
    triangle_count: 1,
    sphere: ([0.5, 0.5, 0.0], 0.71),
    cone: ([0.0, 0.0, 1.0], 1.0),
}];
static TRI: ValidMeshletMesh<'static> = ValidMeshletMesh::new_const(MeshletMesh {
    mesh: Mesh::new(&POSITIONS, &NORMALS, &[], ([0.5, 0.5, 0.0], 0.71)),
    meshlets: &CLUSTERS,
    vertices: &[0, 1, 2],
    triangles: &[[0, 2, 1]],
});

fn main() {
    let _ = TRI.get();
}
