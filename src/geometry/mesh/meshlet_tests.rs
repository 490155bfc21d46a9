//! Tests of meshlet validation, the winding check and the meshlet builder.

extern crate std;

use super::*;
use std::vec;
use std::vec::Vec;

/// A generated mesh with owned buffers.
struct Owned {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    indices: Vec<[u16; 3]>,
    sphere: ([f32; 3], f32),
}

impl Owned {
    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.normals, &self.indices, self.sphere)
    }

    fn reversed(&self) -> Owned {
        let indices = self.indices.iter().map(|&[a, b, c]| [a, c, b]).collect();
        Owned { indices, normals: self.normals.clone(), positions: self.positions.clone(), ..*self }
    }
}

fn own(m: Mesh<'_>) -> Owned {
    Owned {
        positions: m.positions.to_vec(),
        normals: m.normals.to_vec(),
        indices: m.indices.to_vec(),
        sphere: m.bounding_sphere,
    }
}

fn make_cube() -> Owned {
    let (mut p, mut n, mut i) = (vec![[0.0; 3]; 24], vec![[0.0; 3]; 24], vec![[0; 3]; 12]);
    own(cube(&mut p, &mut n, &mut i).unwrap())
}

fn make_icosphere(s: u32) -> Owned {
    let (nv, nt) = (icosphere_vertex_count(s), icosphere_triangle_count(s));
    let (mut p, mut n, mut i) = (vec![[0.0; 3]; nv], vec![[0.0; 3]; nv], vec![[0; 3]; nt]);
    own(icosphere(s, &mut p, &mut n, &mut i).unwrap())
}

fn make_torus(m: usize, n: usize) -> Owned {
    let (nv, nt) = (torus_vertex_count(m, n), torus_triangle_count(m, n));
    let (mut p, mut nn, mut i) = (vec![[0.0; 3]; nv], vec![[0.0; 3]; nv], vec![[0; 3]; nt]);
    own(torus(m, n, 1.0, 0.4, &mut p, &mut nn, &mut i).unwrap())
}

/// Builder output with owned buffers.
struct Built {
    meshlets: Vec<Meshlet>,
    vertices: Vec<u16>,
    triangles: Vec<[u8; 3]>,
}

impl Built {
    fn of<'a>(&'a self, mesh: Mesh<'a>) -> MeshletMesh<'a> {
        MeshletMesh { mesh, meshlets: &self.meshlets, vertices: &self.vertices, triangles: &self.triangles }
    }
}

fn build(mesh: Mesh<'_>) -> Built {
    let (nv, nt) = (mesh.vertex_count(), mesh.triangle_count());
    let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
    let mut vertices = vec![u16::MAX; meshlet_vertex_bound(nt)];
    let mut triangles = vec![[u8::MAX; 3]; nt];
    let mut scratch = vec![u32::MAX; meshlet_scratch_len(nv, nt)];
    let m = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch).unwrap();
    Built { meshlets: m.meshlets.to_vec(), vertices: m.vertices.to_vec(), triangles: m.triangles.to_vec() }
}

/// One triangle facing +z as a one-cluster meshlet mesh.
static TRI_POS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
static TRI_UP: [[f32; 3]; 3] = [[0.0, 0.0, 1.0]; 3];
const TRI_SPHERE: ([f32; 3], f32) = ([0.5, 0.5, 0.0], 0.71);
const TRI_CLUSTER: Meshlet = Meshlet {
    vertex_offset: 0,
    triangle_offset: 0,
    vertex_count: 3,
    triangle_count: 1,
    sphere: TRI_SPHERE,
    cone: ([0.0, 0.0, 1.0], 0.0),
};

fn tri_mesh<'a>(meshlets: &'a [Meshlet], vertices: &'a [u16], triangles: &'a [[u8; 3]]) -> MeshletMesh<'a> {
    MeshletMesh { mesh: Mesh::new(&TRI_POS, &TRI_UP, &[], TRI_SPHERE), meshlets, vertices, triangles }
}

fn tri_with(c: Meshlet) -> Result<(), Error> {
    tri_mesh(&[c], &[0, 1, 2], &[[0, 1, 2]]).validate()
}

#[test]
fn hand_made_cluster_validates() {
    assert_eq!(tri_with(TRI_CLUSTER), Ok(()));
    // Tolerances: a cone and sphere right at their bounds pass.
    let edge = Meshlet { cone: ([0.0, 0.6, 0.8], 0.6), ..TRI_CLUSTER };
    assert_eq!(tri_with(edge), Ok(()));
    let never = Meshlet { cone: ([1.0, 0.0, 0.0], 1.0), ..TRI_CLUSTER };
    assert_eq!(tri_with(never), Ok(()));
    assert_eq!(tri_mesh(&[], &[], &[]).validate(), Ok(()));
}

#[test]
fn out_of_range_indices_are_invalid() {
    assert_eq!(tri_mesh(&[TRI_CLUSTER], &[0, 1, 2], &[[0, 1, 3]]).validate(), Err(Error::InvalidMeshlet));
    assert_eq!(tri_mesh(&[TRI_CLUSTER], &[0, 1, 3], &[[0, 1, 2]]).validate(), Err(Error::InvalidMeshlet));
    // A local index within the array but beyond the cluster's count.
    let two = Meshlet { vertex_count: 2, ..TRI_CLUSTER };
    assert_eq!(tri_mesh(&[two], &[0, 1, 2], &[[0, 1, 2]]).validate(), Err(Error::InvalidMeshlet));
}

#[test]
fn bad_counts_and_offsets_are_invalid() {
    for c in [
        Meshlet { vertex_count: 0, ..TRI_CLUSTER },
        Meshlet { triangle_count: 0, ..TRI_CLUSTER },
        Meshlet { vertex_count: 65, ..TRI_CLUSTER },
        Meshlet { triangle_count: 129, ..TRI_CLUSTER },
        Meshlet { vertex_offset: 1, ..TRI_CLUSTER },
        Meshlet { triangle_offset: 1, ..TRI_CLUSTER },
        Meshlet { vertex_offset: u32::MAX, ..TRI_CLUSTER },
        Meshlet { triangle_offset: u32::MAX, triangle_count: 255, ..TRI_CLUSTER },
    ] {
        assert_eq!(tri_with(c), Err(Error::InvalidMeshlet), "{c:?}");
    }
}

#[test]
fn too_many_vertices_per_cluster_is_invalid_even_with_long_arrays() {
    let positions: Vec<[f32; 3]> = (0..66).map(|i| [i as f32, 0.0, 0.0]).collect();
    let mesh = Mesh::new(&positions, &[], &[], ([32.5, 0.0, 0.0], 32.5));
    let vertices: Vec<u16> = (0..66).collect();
    let c = Meshlet {
        vertex_count: 65,
        sphere: mesh.bounding_sphere,
        cone: ([0.0, 0.0, 1.0], 1.0),
        ..TRI_CLUSTER
    };
    let m = MeshletMesh { mesh, meshlets: &[c], vertices: &vertices, triangles: &[[0, 1, 2]] };
    assert_eq!(m.validate(), Err(Error::InvalidMeshlet));
    let ok = Meshlet { vertex_count: 64, ..c };
    assert_eq!(MeshletMesh { meshlets: &[ok], ..m }.validate(), Ok(()));
}

#[test]
fn bad_spheres_are_invalid() {
    for sphere in
        [([0.5, 0.5, 0.0], 0.70), ([0.5, 0.5, 0.0], -1.0), ([5.0, 0.5, 0.0], 0.71), ([0.0; 3], 3.0e19)]
    {
        assert_eq!(tri_with(Meshlet { sphere, ..TRI_CLUSTER }), Err(Error::InvalidMeshlet), "{sphere:?}");
    }
    // Just inside the relative tolerance passes, just outside fails.
    let exact = 0.5f32.hypot(0.5);
    assert_eq!(
        tri_with(Meshlet { sphere: ([0.5, 0.5, 0.0], exact * (1.0 - 5.0e-6)), ..TRI_CLUSTER }),
        Ok(())
    );
    let short = Meshlet { sphere: ([0.5, 0.5, 0.0], exact * (1.0 - 2.0e-5)), ..TRI_CLUSTER };
    assert_eq!(tri_with(short), Err(Error::InvalidMeshlet));
}

#[test]
fn bad_cones_are_invalid() {
    for cone in [
        ([0.0, 0.0, -1.0], 0.0),  // points away
        ([0.0, 0.6, 0.8], 0.59),  // too narrow for a 36.9° tilt
        ([0.0, 0.0, 2.0], 0.0),   // not unit
        ([0.0, 0.0, 1.0], -0.1),  // negative cutoff
        ([0.0, 0.0, 0.5], 1.0),   // never rejects, but not unit
        ([0.0, 1.0, 0.0], 0.999), // 90°: cutoff < 1
    ] {
        assert_eq!(tri_with(Meshlet { cone, ..TRI_CLUSTER }), Err(Error::InvalidMeshlet), "{cone:?}");
    }
}

#[test]
fn non_finite_values_are_errors() {
    let nan = f32::NAN;
    for c in [
        Meshlet { sphere: ([nan, 0.5, 0.0], 0.71), ..TRI_CLUSTER },
        Meshlet { sphere: (TRI_SPHERE.0, f32::INFINITY), ..TRI_CLUSTER },
        Meshlet { cone: ([0.0, 0.0, nan], 0.0), ..TRI_CLUSTER },
        Meshlet { cone: ([0.0, 0.0, 1.0], nan), ..TRI_CLUSTER },
    ] {
        assert_eq!(tri_with(c), Err(Error::NonFiniteCoordinate), "{c:?}");
    }
    let positions = [[0.0, 0.0, nan], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let m = MeshletMesh {
        mesh: Mesh::new(&positions, &[], &[], TRI_SPHERE),
        ..tri_mesh(&[TRI_CLUSTER], &[0, 1, 2], &[[0, 1, 2]])
    };
    assert_eq!(m.validate(), Err(Error::NonFiniteCoordinate));
}

#[test]
fn cluster_wound_against_normals_is_a_winding_mismatch() {
    let c = Meshlet { cone: ([0.0, 0.0, -1.0], 0.0), ..TRI_CLUSTER };
    assert_eq!(tri_mesh(&[c], &[0, 1, 2], &[[0, 2, 1]]).validate(), Err(Error::WindingMismatch));
    // Without normals the same cluster is fine.
    let cs = [c];
    let m = MeshletMesh {
        mesh: Mesh::new(&TRI_POS, &[], &[], TRI_SPHERE),
        ..tri_mesh(&cs, &[0, 1, 2], &[[0, 2, 1]])
    };
    assert_eq!(m.validate(), Ok(()));
    // The mesh's own indices are checked too.
    let m = MeshletMesh {
        mesh: Mesh::new(&TRI_POS, &TRI_UP, &[[0, 2, 1]], TRI_SPHERE),
        ..tri_mesh(&[], &[], &[])
    };
    assert_eq!(m.validate(), Err(Error::WindingMismatch));
}

#[test]
fn valid_meshlet_mesh_wraps_only_valid_meshes() {
    let ok = tri_mesh(&[TRI_CLUSTER], &[0, 1, 2], &[[0, 1, 2]]);
    assert_eq!(ValidMeshletMesh::new(ok).map(|v| *v.get()), Ok(ok));
    let bad = tri_mesh(&[TRI_CLUSTER], &[0, 1, 2], &[[0, 1, 3]]);
    assert_eq!(ValidMeshletMesh::new(bad), Err(Error::InvalidMeshlet));
}

#[test]
fn generated_meshes_pass_the_winding_check_and_fail_reversed() {
    for m in [make_cube(), make_icosphere(3), make_torus(48, 24)] {
        assert_eq!(m.mesh().check_winding(), Ok(()));
        assert_eq!(m.reversed().mesh().check_winding(), Err(Error::WindingMismatch));
        // Without normals there is nothing to disagree with.
        let rev = m.reversed();
        let bare = Mesh { normals: &[], ..rev.mesh() };
        assert_eq!(bare.check_winding(), Ok(()));
    }
}

#[test]
fn winding_check_skips_degenerate_triangles_and_validates_first() {
    let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
    let up = [[0.0, 0.0, 1.0]; 3];
    let line = Mesh::new(&positions, &up, &[[0, 2, 1]], ([1.0, 0.0, 0.0], 1.0));
    assert_eq!(line.check_winding(), Ok(()));
    let bad = Mesh::new(&positions, &up, &[[0, 2, 3]], ([1.0, 0.0, 0.0], 1.0));
    assert_eq!(
        bad.check_winding(),
        Err(Error::InvalidMesh(MeshFault::IndexOutOfRange { triangle: 0, index: 3, vertices: 3 }))
    );
}

/// The triangle up to rotation of its corners (keeps the winding).
fn canonical([a, b, c]: [u16; 3]) -> [u16; 3] {
    let m = a.min(b).min(c);
    if m == a {
        [a, b, c]
    } else if m == b {
        [b, c, a]
    } else {
        [c, a, b]
    }
}

fn area64(p: [[f32; 3]; 3]) -> f64 {
    let [a, b, c] = p.map(|v| v.map(f64::from));
    let (e, f) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
    let n = [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]];
    (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() / 2.0
}

/// Checks a built meshlet mesh against its source and returns (clusters,
/// mean vertices, mean triangles, mean radius / disk radius of the mean
/// cluster area, fraction of clusters with ≥ 60 vertices).
fn check_built(src: &Owned) -> (usize, f64, f64, f64, f64) {
    let mesh = src.mesh();
    let built = build(mesh);
    let m = built.of(mesh);
    assert_eq!(m.validate(), Ok(()));
    assert!(m.meshlets.len() <= meshlet_bound(mesh.triangle_count()));
    // Triangle multiset, winding kept (up to rotation).
    let mut expect: Vec<[u16; 3]> = mesh.indices.iter().map(|&t| canonical(t)).collect();
    let mut got = Vec::new();
    for c in m.meshlets {
        let verts = &m.vertices[c.vertex_offset as usize..][..usize::from(c.vertex_count)];
        for t in &m.triangles[c.triangle_offset as usize..][..usize::from(c.triangle_count)] {
            got.push(canonical(t.map(|k| verts[usize::from(k)])));
        }
    }
    expect.sort_unstable();
    got.sort_unstable();
    assert_eq!(got, expect);
    let n = m.meshlets.len() as f64;
    let area: f64 = (0..mesh.triangle_count()).map(|i| area64(mesh.triangle(i).unwrap())).sum();
    let disk = (area / n / core::f64::consts::PI).sqrt();
    let mean = |f: &dyn Fn(&Meshlet) -> f64| m.meshlets.iter().map(f).sum::<f64>() / n;
    (
        m.meshlets.len(),
        mean(&|c| f64::from(c.vertex_count)),
        mean(&|c| f64::from(c.triangle_count)),
        mean(&|c| f64::from(c.sphere.1)) / disk,
        mean(&|c| f64::from(u8::from(c.vertex_count >= 60))),
    )
}

/// On closed meshes the clusters are nearly all full (≥ 60 of 64 vertices,
/// about 94 triangles) and compact: the mean cluster radius is at most 1.5
/// times the radius of a disk with the mean cluster area (a perfectly round
/// flat cluster has 1.0; greedy growth gets 1.28 to 1.36).
#[test]
fn built_meshlets_keep_every_triangle_and_are_compact() {
    for src in [make_icosphere(4), make_torus(96, 48)] {
        let (_, verts, tris, radius, full) = check_built(&src);
        assert!(verts > 61.0 && tris > 85.0, "{verts} {tris}");
        assert!(full > 0.95, "{full}");
        assert!(radius < 1.5, "{radius}");
    }
    // Separate faces (the cube) and a triangle soup: no adjacency to grow over.
    assert_eq!(check_built(&make_cube()).0, 1);
    let soup = make_soup(300);
    let (clusters, verts, ..) = check_built(&soup);
    assert_eq!(clusters, 300usize.div_ceil(21));
    assert!(verts > 55.0, "{verts}");
}

/// `n` separate triangles along a helix, each with its own vertices, one of
/// them degenerate (a repeated corner).
fn make_soup(n: usize) -> Owned {
    let mut positions = Vec::new();
    let mut indices = Vec::new();
    for i in 0..n {
        let a = i as f32 * 0.37;
        let p = [micromath::F32Ext::cos(a) * 5.0, i as f32 * 0.05, micromath::F32Ext::sin(a) * 5.0];
        let v = positions.len() as u16;
        positions.extend([p, [p[0] + 0.1, p[1], p[2]], [p[0], p[1] + 0.1, p[2]]]);
        indices.push(if i == 7 { [v, v, v + 1] } else { [v, v + 1, v + 2] });
    }
    let sphere = bounding_sphere(&positions);
    Owned { positions, normals: Vec::new(), indices, sphere }
}

/// The cones are tight: shrinking each by 1 % (of cutoffs above 0.05) makes
/// validation fail, and every cluster of a fine sphere spans less than 37°.
#[test]
fn built_cones_are_tight() {
    let src = make_icosphere(4);
    let built = build(src.mesh());
    let (mut shrunk, mut max_cutoff) = (0, 0.0f32);
    for i in 0..built.meshlets.len() {
        let c = built.meshlets[i];
        max_cutoff = max_cutoff.max(c.cone.1);
        if c.cone.1 > 0.05 {
            let mut b = Built { meshlets: built.meshlets.clone(), ..build(src.mesh()) };
            b.meshlets[i].cone.1 = c.cone.1 * 0.99 - CONE_TOLERANCE;
            assert_eq!(b.of(src.mesh()).validate(), Err(Error::InvalidMeshlet));
            shrunk += 1;
        }
    }
    assert!(shrunk > built.meshlets.len() / 2);
    assert!(max_cutoff < 0.6, "{max_cutoff}");
}

#[test]
fn builder_reports_short_buffers_and_bad_meshes() {
    let src = make_icosphere(2);
    let mesh = src.mesh();
    let (nv, nt) = (mesh.vertex_count(), mesh.triangle_count());
    let clusters = build(mesh).meshlets.len();
    let run = |m: usize, v: usize, t: usize, s: usize| {
        let mut meshlets = vec![Meshlet::default(); m];
        let (mut vertices, mut triangles, mut scratch) = (vec![0; v], vec![[0; 3]; t], vec![0; s]);
        build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch)
            .map(|m| m.meshlets.len())
    };
    let (mb, vb, sl) = (meshlet_bound(nt), meshlet_vertex_bound(nt), meshlet_scratch_len(nv, nt));
    assert_eq!(run(mb, vb, nt, sl), Ok(clusters));
    // Exactly as many clusters as needed suffice.
    assert_eq!(run(clusters, vb, nt, sl), Ok(clusters));
    // A short buffer says how much suffices; retrying with that succeeds.
    let short = |needed, capacity| Err(Error::CapacityExceeded { needed, capacity });
    assert_eq!(run(clusters - 1, vb, nt, sl), short(clusters, clusters - 1));
    assert_eq!(run(1, vb, nt, sl), short(clusters, 1));
    assert_eq!(run(0, vb, nt, sl), short(clusters, 0));
    assert_eq!(run(mb, 10, nt, sl), short(vb, 10));
    assert_eq!(run(mb, vb, nt - 1, sl), short(nt, nt - 1));
    assert_eq!(run(mb, vb, nt, sl - 1), short(sl, sl - 1));
    let bad_idx = [[0, 1, 500]];
    let bad = Mesh { indices: &bad_idx, ..mesh };
    let (mut m, mut v, mut t, mut s) =
        (vec![Meshlet::default(); 1], vec![0; 3], vec![[0; 3]; 1], vec![0; sl]);
    let fault = MeshFault::IndexOutOfRange { triangle: 0, index: 500, vertices: mesh.vertex_count() };
    assert_eq!(build_meshlets(bad, &mut m, &mut v, &mut t, &mut s), Err(Error::InvalidMesh(fault)));
    let empty = Mesh { indices: &[], ..mesh };
    assert_eq!(build_meshlets(empty, &mut [], &mut [], &mut [], &mut s).map(|m| m.meshlets.len()), Ok(0));
}
