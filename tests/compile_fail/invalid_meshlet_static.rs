// error: invalid meshlets: local index out of range
// A `static` meshlet mesh checked by `ValidMeshletMesh::new` at compile time:
// a local index past the cluster's vertex count is a build error.
use microraster::mesh::{Mesh, Meshlet, MeshletMesh, ValidMeshletMesh};

static POSITIONS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
static CLUSTERS: [Meshlet; 1] = [Meshlet {
    vertex_offset: 0,
    triangle_offset: 0,
    vertex_count: 3,
    triangle_count: 1,
    sphere: ([0.5, 0.5, 0.0], 0.71),
    cone: ([0.0, 0.0, 1.0], 0.0),
}];
static TRI: ValidMeshletMesh<'static> = match ValidMeshletMesh::new(MeshletMesh {
    mesh: Mesh::new(&POSITIONS, &[], &[], ([0.5, 0.5, 0.0], 0.71)),
    meshlets: &CLUSTERS,
    vertices: &[0, 1, 2],
    triangles: &[[0, 1, 3]],
}) {
    Ok(m) => m,
    Err(_) => panic!("invalid meshlets: local index out of range"),
};

fn main() {
    let _ = TRI.get();
}
