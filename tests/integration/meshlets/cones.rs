//! Normal cones and needle triangles: a cluster with a degenerate triangle
//! (`mesh::DEGENERATE_SIN2`) has no cone, since its face normal is rounding
//! noise while its image can still cover pixel centres.
//!
//! Found by the `closed` fuzz target (2026-12-02): a tetrahedron with a
//! corner 32,768 units away has three needle faces; the cone was built from
//! the fourth face alone, and seen from where that face looks away the
//! cone test rejected the cluster, so the needles facing the eye, which
//! the binned path draws, were lost. Corpus:
//! `fuzz/corpus/closed/regression-needle-cone`.

use microraster::Error;
use microraster::mesh::{
    DEGENERATE_SIN2, Mesh, Meshlet, MeshletMesh, bounding_sphere, build_meshlets, meshlet_bound,
    meshlet_scratch_len, meshlet_vertex_bound,
};

/// The fuzz case's tetrahedron: faces at corner 0 are needles.
const NEEDLES: [[f32; 3]; 4] =
    [[-32768.0, -10.75, -5.5], [1.3125, -2.5625, 0.0625], [-2.5625, -2.5625, -2.5625], [-6.75, -5.5, -1.375]];
const FACES: [[u16; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Face `f` of [`NEEDLES`] in `f64`: its edges from the first corner and
/// their cross product (the face normal).
fn face(f: [u16; 3]) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let p = f.map(|i| NEEDLES[usize::from(i)].map(f64::from));
    let (e1, e2) = ([0, 1, 2].map(|k| p[1][k] - p[0][k]), [0, 1, 2].map(|k| p[2][k] - p[0][k]));
    let n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    (e1, e2, n)
}

/// Whether face `f` of [`NEEDLES`] is degenerate by the documented rule.
fn degenerate(f: [u16; 3]) -> bool {
    let (e1, e2, n) = face(f);
    dot(n, n) <= f64::from(DEGENERATE_SIN2) * dot(e1, e1) * dot(e2, e2)
}

#[test]
fn a_cluster_with_a_needle_has_no_cone() {
    // The premise: some faces are needles, one is not (a cone from it alone
    // would be narrow).
    assert!(FACES.iter().any(|&f| degenerate(f)) && !degenerate(FACES[2]));
    let mesh = Mesh::new(&NEEDLES, &[], &FACES, bounding_sphere(&NEEDLES));
    let mut meshlets = [Meshlet::default(); meshlet_bound(4)];
    let mut vertices = [0; meshlet_vertex_bound(4)];
    let (mut triangles, mut scratch) = ([[0; 3]; 4], [0; meshlet_scratch_len(4, 4)]);
    let m = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch).unwrap();
    assert_eq!(m.meshlets.len(), 1);
    assert!(
        m.meshlets[0].cone.1 >= 1.0,
        "a cone that cannot vouch for the needles: {:?}",
        m.meshlets[0].cone
    );
    m.validate().unwrap();

    // The narrow cone of the one proper face is not valid for the cluster.
    let (_, _, n) = face(FACES[2]);
    let len = dot(n, n).sqrt();
    let narrow = Meshlet { cone: (n.map(|x| (x / len) as f32), 0.01), ..m.meshlets[0] };
    let cluster = [narrow];
    let with_cone = MeshletMesh { meshlets: &cluster, ..m };
    assert_eq!(with_cone.validate(), Err(Error::InvalidMeshlet));
}
