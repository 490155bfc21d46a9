//! A mesh in 16.16 (`Mesh::new_fx`, `ValidMeshletMesh::new_fx`): the
//! fixed-point stage draws from it the pixels it draws from the same mesh
//! in `f32`; its checks give the errors the same values in `f32` give; the
//! meshlet builder takes it.

use super::{Clustered, covered, direct, direct_of, pipeline, torus};
use microraster::Error;
use microraster::edge::Cull;
use microraster::math::{Fx, Scalar};
use microraster::mesh::{self, Mesh, Meshlet, MeshletMesh, ValidMeshletMesh, build_meshlets};
use microraster::raster3d::{Affine, PerspectiveCorrect};

/// `c`'s positions and normals in 16.16 (`Fx::from_f32` of each value),
/// with `c`'s clusters (the same triangles in the same order), each sphere
/// grown by 2^-12 to hold the rounded positions and each cone opened to
/// never reject (the per-triangle cull still drops the back faces).
struct FxData {
    positions: Vec<[Fx; 3]>,
    normals: Vec<[Fx; 3]>,
    meshlets: Vec<Meshlet>,
    sphere: ([f32; 3], f32),
}

impl FxData {
    fn of(c: &Clustered) -> Self {
        let fx = |rows: &[[f32; 3]]| rows.iter().map(|r| r.map(Fx::from_f32)).collect::<Vec<_>>();
        let grow = |(centre, r): ([f32; 3], f32)| (centre, r + 1.0 / 4096.0);
        let meshlets =
            c.meshlets.iter().map(|m| Meshlet { sphere: grow(m.sphere), cone: ([0.0, 0.0, 1.0], 1.0), ..*m });
        FxData {
            positions: fx(&c.positions),
            normals: fx(&c.normals),
            meshlets: meshlets.collect(),
            sphere: grow(c.sphere),
        }
    }

    fn mesh<'a>(&'a self, c: &'a Clustered) -> MeshletMesh<'a, Fx> {
        MeshletMesh {
            mesh: Mesh::new_fx(&self.positions, &self.normals, &[], self.sphere),
            meshlets: &self.meshlets,
            vertices: &c.vertices,
            triangles: &c.triangles,
        }
    }

    /// The same values back in `f32` (exact: below 2^8 in magnitude).
    fn as_f32(&self) -> (Vec<[f32; 3]>, Vec<[f32; 3]>) {
        let f = |rows: &[[Fx; 3]]| rows.iter().map(|r| r.map(Fx::to_f32)).collect::<Vec<_>>();
        (f(&self.positions), f(&self.normals))
    }
}

#[test]
fn fx_data_draws_the_pixels_of_f32_data() {
    let c = torus();
    let data = FxData::of(&c);
    let m = ValidMeshletMesh::new_fx(data.mesh(&c)).unwrap();
    let (p32, n32) = data.as_f32();
    let same_f32 = ValidMeshletMesh::new(MeshletMesh {
        mesh: Mesh::new(&p32, &n32, &[], data.sphere),
        meshlets: &data.meshlets,
        vertices: &c.vertices,
        triangles: &c.triangles,
    })
    .unwrap();
    for i in 0..6 {
        let angle = i as f32 * 0.83;
        let eye = [0.4 * i as f32 - 1.5, 1.2, 3.2 + 0.3 * i as f32];
        for cull in [Cull::None, Cull::Clockwise] {
            // The fixed-point stage: 16.16 data against the f32 data it
            // would convert to those values.
            let p = pipeline::<Fx>(cull, eye);
            let want = direct::<Fx, Affine, 16>(&c, &p, angle, Affine);
            assert!(covered(&want) > 1000, "the torus is in view: {}", covered(&want));
            assert_eq!(direct_of::<Fx, Affine, 16, Fx>(&m, &p, angle, Affine).0, want, "Fx {i} {cull:?}");
            assert_eq!(direct_of::<Fx, Affine, 1, Fx>(&m, &p, angle, Affine).0, want, "Fx rows 1 {i}");
            let want = direct::<Fx, PerspectiveCorrect, 16>(&c, &p, angle, PerspectiveCorrect);
            assert_eq!(direct_of::<Fx, _, 16, Fx>(&m, &p, angle, PerspectiveCorrect).0, want, "Fx persp {i}");
            // The f32 stage reads 16.16 data as the f32 values it holds.
            let p = pipeline::<f32>(cull, eye);
            let want = direct_of::<f32, Affine, 16, f32>(&same_f32, &p, angle, Affine).0;
            assert!(covered(&want) > 1000);
            assert_eq!(direct_of::<f32, Affine, 16, Fx>(&m, &p, angle, Affine).0, want, "f32 {i} {cull:?}");
        }
    }
}

/// Each check's verdict on a mesh in 16.16 is the verdict on the same
/// values in `f32`, and a bad cluster is a typed error, not a panic.
#[test]
fn fx_data_is_checked_as_f32_data() {
    let c = torus();
    let data = FxData::of(&c);
    let (p32, n32) = data.as_f32();
    let verdicts = |m: MeshletMesh<'_, Fx>| {
        let f = MeshletMesh {
            mesh: Mesh::new(
                &p32[..m.mesh.positions.len()],
                &n32[..m.mesh.normals.len()],
                &[],
                m.mesh.bounding_sphere,
            ),
            meshlets: m.meshlets,
            vertices: m.vertices,
            triangles: m.triangles,
        };
        let fx = ValidMeshletMesh::new_fx(m).map(|_| ());
        assert_eq!(fx, f.validate(), "16.16 and f32 verdicts differ");
        assert_eq!(fx, m.validate());
        fx
    };
    let ok = data.mesh(&c);
    assert_eq!(verdicts(ok), Ok(()));
    let mut vertices = c.vertices.clone();
    vertices[3] = c.positions.len() as u16;
    assert_eq!(
        verdicts(MeshletMesh { vertices: &vertices, ..ok }),
        Err(Error::InvalidMeshlet),
        "vertex beyond"
    );
    let mut triangles = c.triangles.clone();
    triangles[0][1] = 64;
    assert_eq!(
        verdicts(MeshletMesh { triangles: &triangles, ..ok }),
        Err(Error::InvalidMeshlet),
        "local index"
    );
    let mut meshlets = data.meshlets.clone();
    meshlets[0].vertex_count = 65;
    assert_eq!(
        verdicts(MeshletMesh { meshlets: &meshlets, ..ok }),
        Err(Error::InvalidMeshlet),
        "65 vertices"
    );
    let mut meshlets = data.meshlets.clone();
    meshlets[2].sphere.1 *= 0.5;
    assert_eq!(
        verdicts(MeshletMesh { meshlets: &meshlets, ..ok }),
        Err(Error::InvalidMeshlet),
        "small sphere"
    );
    let flipped: Vec<[Fx; 3]> = data.normals.iter().map(|n| n.map(|v| -v)).collect();
    let mesh = Mesh { normals: &flipped, ..ok.mesh };
    assert_eq!(ValidMeshletMesh::new_fx(MeshletMesh { mesh, ..ok }).map(|_| ()), Err(Error::WindingMismatch));
    let mesh = Mesh { normals: &data.normals[1..], ..ok.mesh };
    let (normals, positions) = (data.normals.len() - 1, data.normals.len());
    let short = Error::InvalidMesh(microraster::MeshFault::NormalCount { normals, positions });
    assert_eq!(verdicts(MeshletMesh { mesh, ..ok }), Err(short), "one normal short");
    let mesh = Mesh { bounding_sphere: (data.sphere.0, data.sphere.1 * 0.9), ..ok.mesh };
    let small = verdicts(MeshletMesh { mesh, ..ok });
    assert!(
        matches!(small, Err(Error::InvalidMesh(microraster::MeshFault::OutsideSphere { .. }))),
        "mesh sphere: {small:?}"
    );
    let mesh = Mesh { bounding_sphere: ([f32::NAN, 0.0, 0.0], 1.0), ..ok.mesh };
    assert_eq!(verdicts(MeshletMesh { mesh, ..ok }), Err(Error::NonFiniteCoordinate));
}

/// `build_meshlets` on data in 16.16: clusters that pass its checks and
/// hold every triangle of the mesh once, with its winding.
#[test]
fn meshlets_built_from_fx_data_hold_every_triangle_once() {
    let (m, n) = (40, 18);
    let mut p = vec![[0.0; 3]; mesh::torus_vertex_count(m, n)];
    let mut nn = vec![[0.0; 3]; p.len()];
    let mut idx = vec![[0u16; 3]; mesh::torus_triangle_count(m, n)];
    mesh::torus(m, n, 1.0, 0.42, &mut p, &mut nn, &mut idx).unwrap();
    let fx = |rows: &[[f32; 3]]| rows.iter().map(|r| r.map(Fx::from_f32)).collect::<Vec<_>>();
    let (pf, nf) = (fx(&p), fx(&nn));
    let sphere = mesh::bounding_sphere(&pf.iter().map(|r| r.map(Fx::to_f32)).collect::<Vec<_>>());
    let torus = Mesh::new_fx(&pf, &nf, &idx, sphere);
    assert_eq!(torus.check_winding(), Ok(()));
    let nt = idx.len();
    let mut meshlets = vec![Meshlet::default(); mesh::meshlet_bound(nt)];
    let mut vertices = vec![0; mesh::meshlet_vertex_bound(nt)];
    let mut triangles = vec![[0; 3]; nt];
    let mut scratch = vec![0; mesh::meshlet_scratch_len(pf.len(), nt)];
    let built = build_meshlets(torus, &mut meshlets, &mut vertices, &mut triangles, &mut scratch).unwrap();
    assert_eq!(ValidMeshletMesh::new_fx(built).map(|_| ()), Ok(()));
    // Every triangle once, each as a rotation of the mesh's own.
    let canonical = |t: [u16; 3]| {
        let k = (0..3).min_by_key(|&k| t[k]).unwrap_or(0);
        [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
    };
    let mut got = Vec::new();
    for c in built.meshlets {
        let local = &built.vertices[c.vertex_offset as usize..][..usize::from(c.vertex_count)];
        for t in &built.triangles[c.triangle_offset as usize..][..usize::from(c.triangle_count)] {
            got.push(canonical(t.map(|k| local[usize::from(k)])));
        }
    }
    let mut want: Vec<_> = idx.iter().map(|&t| canonical(t)).collect();
    got.sort_unstable();
    want.sort_unstable();
    assert!(built.meshlets.len() > 4);
    assert_eq!(got, want);
}

/// The compile-time conversion is the run-time one, bit for bit, over the
/// whole `f32` range (special values and saturation included).
#[test]
fn const_conversion_is_the_runtime_one() {
    let mut seed = 0x5EED_F1C5_u64;
    for i in 0..200_000u32 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let bits = match i % 4 {
            0 => seed as u32,
            // Mesh-sized values: exponents 2^-20 to 2^9.
            1 => (seed as u32 & 0x807F_FFFF) | ((107 + (seed >> 40) as u32 % 30) << 23),
            2 => [0, 0x8000_0000, 0x7F80_0000, 0xFF80_0000, 0x7FC0_0000, 0x4700_0000, 0xC700_0000]
                [(i / 4 % 7) as usize],
            _ => (i / 4).wrapping_mul(0x9E37_79B9),
        };
        let v = f32::from_bits(bits);
        assert_eq!(Fx::const_from_f32(v), Fx::from_f32(v), "{v:e} ({bits:#x})");
    }
    const ROWS: [[Fx; 3]; 2] = mesh::fx_rows(&[[0.5, -1.25, 1.0e-6], [3.0e9, -7.5e-3, 255.999]]);
    assert_eq!(ROWS[0], [0.5, -1.25, 1.0e-6].map(Fx::from_f32));
    assert_eq!(ROWS[1], [3.0e9, -7.5e-3, 255.999].map(Fx::from_f32));
}
