//! Meshlet validation and the meshlet builder on arbitrary data.
//!
//! A mesh of 3–66 vertices and 1–100 triangles (positions on a small grid or
//! raw `f32`s with NaN, ±inf, huge and tiny values; normals absent, outward,
//! inward or raw; indices sometimes out of range; an exact, loose, short or
//! raw bounding sphere), then:
//! * arbitrary clusters (offsets and counts anywhere, including past the
//!   arrays and `u32::MAX`; spheres and cones computed, perturbed or raw;
//!   local and global indices sometimes out of range):
//!   `MeshletMesh::validate` never panics, fails only with its documented
//!   errors, and when it succeeds every cluster is in bounds and its sphere
//!   contains its positions (checked here in `f64`);
//! * `build_meshlets` with the documented buffer sizes: fails exactly when
//!   the mesh is invalid (or with `CoordinateOutOfRange`), and otherwise
//!   returns clusters that pass validation exactly when the mesh passes
//!   `check_winding`, hold every triangle once with its winding, and number
//!   at most `meshlet_bound`;
//! * the clusters over the mesh's values in 16.16 (`Mesh::new_fx`): its
//!   `validate` gives the verdict the same values in `f32` get.
#![no_main]

use libfuzzer_sys::fuzz_target;
use microraster::Error;
use microraster::math::{Fx, Scalar};
use microraster::mesh::{
    Mesh, Meshlet, MeshletMesh, bounding_sphere, build_meshlets, meshlet_bound, meshlet_scratch_len,
    meshlet_vertex_bound,
};
use microraster_fuzz::Input;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let nv = 3 + usize::from(inp.u8()) % 64;
    let raw = inp.u8().is_multiple_of(4);
    let positions: Vec<[f32; 3]> = (0..nv)
        .map(|_| [(); 3].map(|()| if raw { inp.f32() } else { f32::from(inp.u8() as i8) / 16.0 }))
        .collect();
    let normals: Vec<[f32; 3]> = match inp.u8() % 4 {
        0 => Vec::new(),
        // From the centre outward, or inward.
        k @ (1 | 2) => {
            let (c, _) = bounding_sphere(&positions);
            let s = if k == 1 { 1.0 } else { -1.0 };
            positions.iter().map(|p| [0, 1, 2].map(|i| s * (p[i] - c[i]))).collect()
        }
        _ => (0..nv).map(|_| [inp.f32(), inp.f32(), inp.f32()]).collect(),
    };
    let bad = inp.u8().is_multiple_of(8);
    let range = nv as u16 + if bad { 2 } else { 0 };
    let nt = 1 + usize::from(inp.u8()) % 100;
    let indices: Vec<[u16; 3]> = (0..nt).map(|_| [(); 3].map(|()| inp.u16() % range)).collect();
    let exact = bounding_sphere(&positions);
    let sphere = match inp.u8() % 4 {
        0 | 1 => exact,
        2 => (exact.0, exact.1 * 0.999),
        _ => ([inp.f32(), inp.f32(), inp.f32()], inp.f32()),
    };
    let mesh = Mesh::new(&positions, &normals, &indices, sphere);

    arbitrary_clusters(&mut inp, mesh);
    built_clusters(mesh);
});

fn arbitrary_clusters(inp: &mut Input<'_>, mesh: Mesh<'_>) {
    let nv = mesh.positions.len();
    let vertices: Vec<u16> = (0..usize::from(inp.u8())).map(|_| inp.u16() % (nv as u16 + 2)).collect();
    let triangles: Vec<[u8; 3]> =
        (0..usize::from(inp.u8())).map(|_| [(); 3].map(|()| inp.u8() % 70)).collect();
    let meshlets: Vec<Meshlet> = (0..inp.u8() % 4)
        .map(|_| {
            let offset = |inp: &mut Input<'_>| match inp.u8() % 8 {
                0 => u32::MAX - u32::from(inp.u8()),
                _ => u32::from(inp.u8()),
            };
            let (vertex_offset, triangle_offset) = (offset(inp), offset(inp));
            let (vertex_count, triangle_count) = (inp.u8(), inp.u8());
            let members: Vec<[f32; 3]> = vertices
                .iter()
                .skip(vertex_offset as usize)
                .take(usize::from(vertex_count))
                .filter_map(|&v| mesh.positions.get(usize::from(v)).copied())
                .collect();
            let sphere = match inp.u8() % 3 {
                0 => bounding_sphere(&members),
                1 => mesh.bounding_sphere,
                _ => ([inp.f32(), inp.f32(), inp.f32()], inp.f32()),
            };
            let cone = match inp.u8() % 3 {
                0 => ([0.0, 0.0, 1.0], 1.0),
                1 => (
                    inp.pick(&[[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]]),
                    inp.pick(&[0.0, 0.5, 0.99]),
                ),
                _ => ([inp.f32(), inp.f32(), inp.f32()], inp.f32()),
            };
            Meshlet { vertex_offset, triangle_offset, vertex_count, triangle_count, sphere, cone }
        })
        .collect();
    let m = MeshletMesh { mesh, meshlets: &meshlets, vertices: &vertices, triangles: &triangles };
    match m.validate() {
        Ok(()) => {
            assert_eq!(mesh.validate(), Ok(()));
            for c in &meshlets {
                let (vo, vc) = (c.vertex_offset as usize, usize::from(c.vertex_count));
                let (to, tc) = (c.triangle_offset as usize, usize::from(c.triangle_count));
                assert!((1..=64).contains(&vc) && (1..=128).contains(&tc));
                assert!(vo + vc <= vertices.len() && to + tc <= triangles.len());
                assert!(triangles[to..to + tc].iter().flatten().all(|&k| usize::from(k) < vc));
                let (centre, r) = c.sphere;
                for &v in &vertices[vo..vo + vc] {
                    let p = mesh.positions[usize::from(v)];
                    let d2: f64 = (0..3).map(|k| (f64::from(p[k]) - f64::from(centre[k])).powi(2)).sum();
                    let r = f64::from(r) * (1.0 + 1.0e-5) * (1.0 + 1.0e-6);
                    assert!(d2 <= r * r, "{p:?} outside {:?}", c.sphere);
                }
            }
        }
        Err(
            Error::InvalidMesh(_)
            | Error::NonFiniteCoordinate
            | Error::CoordinateOutOfRange
            | Error::InvalidMeshlet
            | Error::WindingMismatch,
        ) => {}
        Err(e) => panic!("undocumented error {e:?}"),
    }
    // The same clusters over the mesh's values in 16.16 (saturated, NaN
    // as 0): the checks give the verdict they give those values in f32.
    let fx = |rows: &[[f32; 3]]| rows.iter().map(|r| r.map(Fx::from_f32)).collect::<Vec<_>>();
    let (pf, nf) = (fx(mesh.positions), fx(mesh.normals));
    let back = |rows: &[[Fx; 3]]| rows.iter().map(|r| r.map(Fx::to_f32)).collect::<Vec<_>>();
    let (pb, nb) = (back(&pf), back(&nf));
    let in_fx = MeshletMesh {
        mesh: Mesh::new_fx(&pf, &nf, mesh.indices, mesh.bounding_sphere),
        meshlets: &meshlets,
        vertices: &vertices,
        triangles: &triangles,
    };
    let in_f32 = MeshletMesh { mesh: Mesh::new(&pb, &nb, mesh.indices, mesh.bounding_sphere), ..m };
    assert_eq!(in_fx.validate(), in_f32.validate());
}

fn built_clusters(mesh: Mesh<'_>) {
    let (nv, nt) = (mesh.positions.len(), mesh.indices.len());
    let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
    let mut vertices = vec![0; meshlet_vertex_bound(nt)];
    let mut triangles = vec![[0; 3]; nt];
    let mut scratch = vec![0; meshlet_scratch_len(nv, nt)];
    let built = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch);
    let m = match (mesh.validate(), built) {
        (Ok(()), Ok(m)) => m,
        (Ok(()), Err(Error::CoordinateOutOfRange)) => return,
        (Err(e), Err(f)) if e == f => return,
        (v, b) => panic!("mesh {v:?}, builder {:?}", b.map(|m| m.meshlets.len())),
    };
    assert_eq!(m.validate(), mesh.check_winding());
    assert!(m.meshlets.len() <= meshlet_bound(nt));
    let rot = |t: [u16; 3]| (0..3).map(|r| [t[r], t[(r + 1) % 3], t[(r + 2) % 3]]).min().unwrap();
    let mut got = Vec::new();
    for c in m.meshlets {
        let local = &m.vertices[c.vertex_offset as usize..][..usize::from(c.vertex_count)];
        for t in &m.triangles[c.triangle_offset as usize..][..usize::from(c.triangle_count)] {
            got.push(rot(t.map(|k| local[usize::from(k)])));
        }
    }
    let mut expect: Vec<[u16; 3]> = mesh.indices.iter().map(|&t| rot(t)).collect();
    got.sort_unstable();
    expect.sort_unstable();
    assert_eq!(got, expect);
}
