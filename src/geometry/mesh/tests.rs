extern crate std;

use super::*;
use std::collections::HashMap;
use std::vec;
use std::vec::Vec;

mod generators;

/// Generated mesh plus its buffers.
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
}

type Buffers = (Vec<[f32; 3]>, Vec<[f32; 3]>, Vec<[u16; 3]>);

fn buffers(nv: usize, nt: usize) -> Buffers {
    (vec![[f32::NAN; 3]; nv], vec![[f32::NAN; 3]; nv], vec![[u16::MAX; 3]; nt])
}

fn own(m: Mesh<'_>) -> Owned {
    Owned {
        positions: m.positions.to_vec(),
        normals: m.normals.to_vec(),
        indices: m.indices.to_vec(),
        sphere: m.bounding_sphere,
    }
}

fn make_icosphere(s: u32) -> Owned {
    let (mut p, mut n, mut i) = buffers(icosphere_vertex_count(s), icosphere_triangle_count(s));
    own(icosphere(s, &mut p, &mut n, &mut i).unwrap())
}

fn f64v(p: [f32; 3]) -> [f64; 3] {
    p.map(f64::from)
}

fn dot64(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Enclosed volume by the divergence theorem: Σ p0 · (p1 × p2) / 6 over the
/// triangles; positive iff they wind counter-clockwise seen from outside.
fn signed_volume(m: &Mesh<'_>) -> f64 {
    let p = |i: u16| f64v(m.positions[usize::from(i)]);
    m.indices.iter().map(|&[a, b, c]| dot64(p(a), cross64(p(b), p(c)))).sum::<f64>() / 6.0
}

/// Closed, consistently oriented 2-manifold without boundary, every vertex
/// used, and the Euler characteristic `V − E + F` (2 for a sphere, 0 for a
/// torus).
fn assert_closed_manifold(m: &Mesh<'_>, euler: i64) {
    let mut directed: HashMap<(u16, u16), usize> = HashMap::new();
    for &[a, b, c] in m.indices {
        assert!(a != b && b != c && c != a, "degenerate triangle {:?}", [a, b, c]);
        for e in [(a, b), (b, c), (c, a)] {
            *directed.entry(e).or_default() += 1;
        }
    }
    for (&(a, b), &count) in &directed {
        assert_eq!(count, 1, "directed edge {a}→{b} used {count} times (inconsistent winding)");
        assert_eq!(directed.get(&(b, a)), Some(&1), "edge {a}–{b} is not shared by exactly 2 triangles");
    }
    // Each vertex's fan is a single cycle (no pinched vertices).
    let mut next: HashMap<u16, HashMap<u16, u16>> = HashMap::new();
    for &[a, b, c] in m.indices {
        for (v, x, y) in [(a, b, c), (b, c, a), (c, a, b)] {
            assert!(next.entry(v).or_default().insert(x, y).is_none());
        }
    }
    assert_eq!(next.len(), m.positions.len(), "unused vertices");
    for (v, fan) in &next {
        let start = *fan.keys().next().unwrap();
        let (mut x, mut steps) = (start, 0);
        loop {
            x = fan[&x];
            steps += 1;
            if x == start {
                break;
            }
        }
        assert_eq!(steps, fan.len(), "vertex {v} is pinched");
    }
    let (v, e, f) = (m.positions.len() as i64, directed.len() as i64 / 2, m.indices.len() as i64);
    assert_eq!(v - e + f, euler);
}

#[test]
fn validate_accepts_generated_and_rejects_broken_meshes() {
    let o = make_icosphere(1);
    let good = o.mesh();
    assert_eq!(good.validate(), Ok(()));
    // No normals is fine; an empty mesh too.
    assert_eq!(Mesh { normals: &[], ..good }.validate(), Ok(()));
    assert_eq!(Mesh::new(&[], &[], &[], ([0.0; 3], 0.0)).validate(), Ok(()));

    let nv = good.vertex_count() as u16;
    let mut idx = o.indices.clone();
    idx[7][1] = nv;
    let out = |triangle, index, vertices| {
        Err(Error::InvalidMesh(MeshFault::IndexOutOfRange { triangle, index, vertices }))
    };
    assert_eq!(Mesh { indices: &idx, ..good }.validate(), out(7, nv, usize::from(nv)));
    idx[7][1] = nv - 1;
    assert_eq!(Mesh { indices: &idx, ..good }.validate(), Ok(()));
    idx[0][2] = u16::MAX;
    assert_eq!(Mesh { indices: &idx, ..good }.validate(), out(0, u16::MAX, usize::from(nv)));
    assert_eq!(Mesh::new(&[], &[], &[[0, 0, 0]], ([0.0; 3], 0.0)).validate(), out(0, 0, 0));

    // Normals: one per position or none.
    let count = |normals, positions| Err(Error::InvalidMesh(MeshFault::NormalCount { normals, positions }));
    let nv = usize::from(nv);
    assert_eq!(Mesh { normals: &o.normals[1..], ..good }.validate(), count(nv - 1, nv));
    let mut more = o.normals.clone();
    more.push([0.0, 0.0, 1.0]);
    assert_eq!(Mesh { normals: &more, ..good }.validate(), count(nv + 1, nv));

    // Non-finite values anywhere.
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let mut pos = o.positions.clone();
        pos[5][2] = bad;
        assert_eq!(Mesh { positions: &pos, ..good }.validate(), Err(Error::NonFiniteCoordinate));
        let mut nrm = o.normals.clone();
        nrm[3][0] = bad;
        assert_eq!(Mesh { normals: &nrm, ..good }.validate(), Err(Error::NonFiniteCoordinate));
        let ([x, y, z], r) = good.bounding_sphere;
        assert_eq!(
            Mesh { bounding_sphere: ([x, bad, z], r), ..good }.validate(),
            Err(Error::NonFiniteCoordinate)
        );
        assert_eq!(
            Mesh { bounding_sphere: ([x, y, z], bad), ..good }.validate(),
            Err(Error::NonFiniteCoordinate)
        );
    }

    // The bounding sphere must contain the mesh (within SPHERE_TOLERANCE).
    let (c, r) = good.bounding_sphere;
    // Every vertex of the unit icosphere is on the sphere: vertex 0 is the first outside.
    let outside = |vertex| Err(Error::InvalidMesh(MeshFault::OutsideSphere { vertex }));
    assert_eq!(Mesh { bounding_sphere: (c, r * 0.999), ..good }.validate(), outside(0));
    assert_eq!(Mesh { bounding_sphere: (c, r * (1.0 - SPHERE_TOLERANCE / 2.0)), ..good }.validate(), Ok(()));
    let moved = Mesh { bounding_sphere: ([0.1, 0.0, 0.0], r), ..good }.validate();
    assert!(matches!(moved, Err(Error::InvalidMesh(MeshFault::OutsideSphere { .. }))), "{moved:?}");
    let negative = Err(Error::InvalidMesh(MeshFault::NegativeRadius));
    assert_eq!(Mesh { bounding_sphere: (c, -r), ..good }.validate(), negative);
    assert_eq!(Mesh::new(&[], &[], &[], ([0.0; 3], -1.0)).validate(), negative);
    // Huge coordinates whose squared distance overflows are rejected, not accepted.
    let far = [[3e38, 0.0, 0.0], [-3e38, 0.0, 0.0]];
    assert_eq!(Mesh::new(&far, &[], &[], ([0.0; 3], 1e19)).validate(), outside(0));
    // A radius whose square overflows is out of the supported range.
    assert_eq!(Mesh::new(&far, &[], &[], ([0.0; 3], 3e38)).validate(), Err(Error::CoordinateOutOfRange));
    assert_eq!(Mesh::new(&[], &[], &[], ([0.0; 3], 2e19)).validate(), Err(Error::CoordinateOutOfRange));
}

#[test]
fn static_meshes_and_accessors() {
    static P: [[f32; 3]; 4] = [[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
    static I: [[u16; 3]; 4] = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];
    static TETRA: Mesh<'static> = Mesh::new(&P, &[], &I, ([0.0; 3], 1.7320509));
    assert_eq!(TETRA.validate(), Ok(()));
    assert!(!TETRA.has_normals());
    assert_closed_manifold(&TETRA, 2);
    assert!((signed_volume(&TETRA) - 8.0 / 3.0).abs() < 1e-12);
    assert_eq!(TETRA.triangle(3), Some([P[1], P[3], P[2]]));
    assert_eq!(TETRA.triangle(4), None);
    let s = 1.0 / 3f32.sqrt();
    for (k, n) in [[s, s, -s], [-s, s, s], [s, -s, s], [-s, -s, -s]].iter().enumerate() {
        let f = TETRA.face_normal(k).unwrap();
        assert!((0..3).all(|c| (f[c] - n[c]).abs() < 1e-6), "{f:?} vs {n:?}");
    }
    assert_eq!(TETRA.face_normal(4), None);
    let flat = Mesh::new(&P, &[], &[[0, 0, 1]], TETRA.bounding_sphere);
    assert_eq!(flat.face_normal(0), None);
    let broken = Mesh::new(&P, &[], &[[0, 9, 1]], TETRA.bounding_sphere);
    assert_eq!((broken.triangle(0), broken.face_normal(0)), (None, None));
}

#[test]
fn bounding_sphere_is_tight_and_contains_every_point() {
    assert_eq!(bounding_sphere(&[]), ([0.0; 3], 0.0));
    assert_eq!(bounding_sphere(&[[1.0, 2.0, 3.0]]), ([1.0, 2.0, 3.0], 0.0));
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 40) as f32 / (1u64 << 24) as f32 * 200.0 - 100.0
    };
    for _ in 0..200 {
        let pts: Vec<[f32; 3]> = (0..17).map(|_| [rnd(), rnd() * 0.01, rnd() * 1e-3 + 7.0]).collect();
        let (c, r) = bounding_sphere(&pts);
        let max_d2 = pts.iter().map(|&p| dist2(p, c)).fold(0.0, f32::max);
        assert!(r * r >= max_d2 && r.next_down() * r.next_down() < max_d2);
        assert_eq!(Mesh::new(&pts, &[], &[], (c, r)).validate(), Ok(()));
    }
    let (_, r) = bounding_sphere(&[[3e38, 0.0, 0.0], [-3e38, 0.0, 0.0]]);
    assert_eq!(r, f32::INFINITY);
}

#[test]
fn sqrt_is_accurate_and_total() {
    assert_eq!(sqrt(0.0), 0.0);
    assert_eq!(sqrt(-4.0), 0.0);
    assert_eq!(sqrt(f32::NAN), 0.0);
    assert_eq!(sqrt(f32::INFINITY), f32::INFINITY);
    for x in [1e-44f32, 1e-39, 1.2e-38, 1e-30, 0.5, 1.0, 2.0, 3.0, 10.0, 12345.678, 1e30, f32::MAX] {
        let y = sqrt(x);
        let exact = f64::from(x).sqrt();
        assert!(((f64::from(y) - exact) / exact).abs() < 2.5e-7, "sqrt({x}) = {y}, not {exact}");
    }
    let mut x = 1e-6f32;
    while x < 1e6 {
        let e = f64::from(x).sqrt();
        assert!(((f64::from(sqrt(x)) - e) / e).abs() < 2e-7, "{x}");
        x *= 1.0137;
    }
    for a in (0..1000).map(|k| k as f32 * 0.0129 - 6.4) {
        let (c, s) = cos_sin(a);
        assert!((f64::from(c * c + s * s) - 1.0).abs() < 1e-6);
        assert!((f64::from(c) - f64::from(a).cos()).abs() < 2e-3);
        assert!((f64::from(s) - f64::from(a).sin()).abs() < 2e-3);
    }
}
