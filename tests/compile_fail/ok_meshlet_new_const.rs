// pass
// The control case of `meshlet_new_const_winding.rs`: wound with its
// normals, the same `static` builds.
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
    triangles: &[[0, 1, 2]],
});

fn main() {
    let _ = TRI.get();
}
