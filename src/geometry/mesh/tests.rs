extern crate std;

use super::*;
use std::collections::HashMap;
use std::vec;
use std::vec::Vec;

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

fn make_cube() -> Owned {
    let (mut p, mut n, mut i) = buffers(cube_vertex_count(), cube_triangle_count());
    own(cube(&mut p, &mut n, &mut i).unwrap())
}

fn make_icosphere(s: u32) -> Owned {
    let (mut p, mut n, mut i) = buffers(icosphere_vertex_count(s), icosphere_triangle_count(s));
    own(icosphere(s, &mut p, &mut n, &mut i).unwrap())
}

fn make_torus(m: usize, n: usize, big_r: f32, r: f32) -> Owned {
    let (mut p, mut nn, mut i) = buffers(torus_vertex_count(m, n), torus_triangle_count(m, n));
    own(torus(m, n, big_r, r, &mut p, &mut nn, &mut i).unwrap())
}

fn f64v(p: [f32; 3]) -> [f64; 3] {
    p.map(f64::from)
}

fn len64(v: [f32; 3]) -> f64 {
    let v = f64v(v);
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn dot64(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn sub64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
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

/// Normals are unit length and on the outer side of every triangle using
/// them; the bounding sphere holds every position.
fn assert_normals_and_sphere(m: &Mesh<'_>) {
    assert_eq!(m.normals.len(), m.positions.len());
    for &n in m.normals {
        assert!((len64(n) - 1.0).abs() < 1e-6, "normal {n:?} not unit");
    }
    for &[a, b, c] in m.indices {
        let p = |i: u16| f64v(m.positions[usize::from(i)]);
        let g = cross64(sub64(p(b), p(a)), sub64(p(c), p(a)));
        for i in [a, b, c] {
            assert!(dot64(g, f64v(m.normals[usize::from(i)])) > 0.0, "normal {i} points inward");
        }
    }
    let (c, r) = m.bounding_sphere;
    for &p in m.positions {
        assert!(dist2(p, c) <= r * r, "{p:?} outside sphere");
    }
    assert_eq!(m.validate(), Ok(()));
}

#[test]
fn cube_is_a_closed_outward_manifold_of_volume_8() {
    let o = make_cube();
    let m = o.mesh();
    assert_eq!((m.vertex_count(), m.triangle_count()), (24, 12));
    // Per-face vertices are not shared, so check the topology on the 8
    // distinct corners.
    let corner = |p: [f32; 3]| p.iter().fold(0u16, |acc, &x| acc * 2 + u16::from(x > 0.0));
    let welded: Vec<[u16; 3]> =
        m.indices.iter().map(|t| t.map(|i| corner(m.positions[usize::from(i)]))).collect();
    let corners: Vec<[f32; 3]> = (0..8)
        .map(|k| [(k >> 2) & 1, (k >> 1) & 1, k & 1].map(|b| if b == 1 { 1.0 } else { -1.0 }))
        .collect();
    assert_closed_manifold(&Mesh::new(&corners, &[], &welded, ([0.0; 3], 2.0)), 2);
    assert_eq!(signed_volume(&m), 8.0);
    assert_normals_and_sphere(&m);
    for (i, &[a, b, c]) in m.indices.iter().enumerate() {
        // Flat faces: the vertex normals are the face normal exactly.
        assert_eq!(m.face_normal(i), Some(m.normals[usize::from(a)]));
        assert_eq!(m.normals[usize::from(a)], m.normals[usize::from(b)]);
        assert_eq!(m.normals[usize::from(a)], m.normals[usize::from(c)]);
    }
    for p in m.positions {
        assert!(p.iter().all(|x| x.abs() == 1.0));
    }
    assert_eq!(m.bounding_sphere.0, [0.0; 3]);
    let r = m.bounding_sphere.1;
    assert!(r * r >= 3.0 && r.next_down() * r.next_down() < 3.0);
}

#[test]
fn icosahedron_has_the_exact_volume() {
    let o = make_icosphere(0);
    let m = o.mesh();
    // Circumradius 1: edge a = 1/sin(2π/5), volume 5/12·(3 + √5)·a³.
    let a = 1.0 / (2.0 * core::f64::consts::PI / 5.0).sin();
    let exact = 5.0 / 12.0 * (3.0 + 5f64.sqrt()) * a * a * a;
    assert!((signed_volume(&m) - exact).abs() < 1e-5, "{} vs {exact}", signed_volume(&m));
}

#[test]
fn icospheres_are_closed_outward_manifolds_converging_to_the_ball() {
    let ball = 4.0 / 3.0 * core::f64::consts::PI;
    let mut last_err = f64::INFINITY;
    for s in 0..=ICOSPHERE_MAX_SUBDIVISIONS {
        let o = make_icosphere(s);
        let m = o.mesh();
        assert_eq!(m.vertex_count(), 10 * 4usize.pow(s) + 2);
        assert_eq!(m.triangle_count(), 20 * 4usize.pow(s));
        assert_closed_manifold(&m, 2);
        assert_normals_and_sphere(&m);
        for (&p, &n) in m.positions.iter().zip(m.normals) {
            assert!((len64(p) - 1.0).abs() < 1e-6);
            assert_eq!(p, n);
        }
        // Deduplication: no two vertices coincide (the closest pair of a
        // 4ⁿ-refined icosahedron is ~1.1/2ⁿ apart; brute force up to n = 4).
        if s <= 4 {
            let min_gap = 0.5 / (1u32 << s) as f32;
            for (i, &a) in m.positions.iter().enumerate() {
                for &b in &m.positions[..i] {
                    assert!(dist2(a, b) > min_gap * min_gap);
                }
            }
        }
        // Inscribed polyhedron: the volume grows towards 4π/3 from below and
        // the deficit shrinks about 4× per level (≥ 3× asserted).
        let v = signed_volume(&m);
        let err = ball - v;
        assert!(err > 0.0 && err * 3.0 < last_err, "level {s}: volume {v}, deficit {err}");
        last_err = err;
    }
    // Stated tolerances: 4π/3 within 1 % at 3 subdivisions (0.86 % measured),
    // 0.02 % at 6 (0.0135 %).
    let v3 = signed_volume(&make_icosphere(3).mesh());
    assert!((ball - v3) / ball < 0.01, "{v3}");
    assert!(last_err / ball < 0.0002, "{last_err}");
}

#[test]
fn toruses_are_closed_outward_manifolds_of_the_right_volume() {
    use core::f64::consts::PI;
    for (m_seg, n_seg, big_r, r) in [
        (3, 3, 1.0, 0.5),
        (4, 3, 2.0, 0.1),
        (12, 6, 1.0, 0.4),
        (48, 24, 1.0, 0.25),
        (64, 32, 3.0, 1.0),
        (24, 96, 2.0, 1.5),
    ] {
        let o = make_torus(m_seg, n_seg, big_r, r);
        let m = o.mesh();
        assert_eq!((m.vertex_count(), m.triangle_count()), (m_seg * n_seg, 2 * m_seg * n_seg));
        assert_closed_manifold(&m, 0);
        assert_normals_and_sphere(&m);
        for (&p, &n) in m.positions.iter().zip(m.normals) {
            // On the tube: distance from the ring circle is r, along the normal.
            let ring = len64([p[0], 0.0, p[2]]);
            let centre = [p[0] as f64 * f64::from(big_r) / ring, 0.0, p[2] as f64 * f64::from(big_r) / ring];
            let d = sub64(f64v(p), centre);
            let dl = dot64(d, d).sqrt();
            assert!((dl - f64::from(r)).abs() < 1e-5 * f64::from(big_r));
            assert!(dot64(d, f64v(n)) / dl > 1.0 - 1e-5, "normal {n:?} at {p:?}");
        }
        let sphere_r = f64::from(m.bounding_sphere.1);
        assert!(sphere_r <= f64::from(big_r + r) * (1.0 + 1e-5));
        // 2π²Rr² for the smooth torus. The polyhedron is inscribed, so its
        // volume is smaller, to second order by the factor of inscribed
        // polygons, 1 − ((2π/M)² + (2π/N)²)/6. Stated tolerance: the relative
        // deficit is positive, at most 1.5× that estimate, and within 2 % of
        // it once M, N ≥ 24.
        let exact = 2.0 * PI * PI * f64::from(big_r) * f64::from(r) * f64::from(r);
        let v = signed_volume(&m);
        let a = |k: usize| (2.0 * PI / k as f64).powi(2);
        let (deficit, estimate) = ((exact - v) / exact, (a(m_seg) + a(n_seg)) / 6.0);
        assert!(deficit > 0.0 && deficit <= 1.5 * estimate, "{m_seg}×{n_seg}: {v} vs {exact}");
        if m_seg >= 24 && n_seg >= 24 {
            assert!((deficit / estimate - 1.0).abs() < 0.02, "{m_seg}×{n_seg}: {deficit} vs {estimate}");
        }
    }
    // Fine tessellation: within 1 %.
    let v = signed_volume(&make_torus(96, 48, 1.0, 0.3).mesh());
    let exact = 2.0 * PI * PI * 0.3 * 0.3;
    assert!((exact - v).abs() / exact < 0.01);
}

#[test]
fn counts_are_const_and_exact() {
    const V: usize = icosphere_vertex_count(3);
    const T: usize = icosphere_triangle_count(3);
    assert_eq!((V, T), (642, 1280));
    assert_eq!((torus_vertex_count(8, 5), torus_triangle_count(8, 5)), (40, 80));
    assert_eq!(icosphere_vertex_count(40), usize::MAX);
    assert_eq!(icosphere_triangle_count(u32::MAX), usize::MAX);
    assert_eq!(torus_triangle_count(usize::MAX, 2), usize::MAX);
    assert!(icosphere_vertex_count(ICOSPHERE_MAX_SUBDIVISIONS) <= MAX_VERTICES);
    assert!(icosphere_vertex_count(ICOSPHERE_MAX_SUBDIVISIONS + 1) > MAX_VERTICES);

    // Exactly sized buffers work, one entry less in any buffer fails, larger
    // ones are fine and only their prefix is used.
    let (mut p, mut n, mut i) = ([[0.0; 3]; V], [[0.0; 3]; V], [[0; 3]; T]);
    assert!(icosphere(3, &mut p, &mut n, &mut i).is_ok());
    assert_eq!(icosphere(3, &mut p[..V - 1], &mut n, &mut i), Err(BUFFER_TOO_SMALL));
    assert_eq!(icosphere(3, &mut p, &mut n[..V - 1], &mut i), Err(BUFFER_TOO_SMALL));
    assert_eq!(icosphere(3, &mut p, &mut n, &mut i[..T - 1]), Err(BUFFER_TOO_SMALL));
    assert_eq!(icosphere(2, &mut p, &mut n, &mut i).map(|m| m.vertex_count()), Ok(162));

    let (mut p, mut n, mut i) = ([[0.0; 3]; 24], [[0.0; 3]; 24], [[0; 3]; 12]);
    assert_eq!(cube(&mut p[..23], &mut n, &mut i), Err(BUFFER_TOO_SMALL));
    assert_eq!(cube(&mut p, &mut n[..23], &mut i), Err(BUFFER_TOO_SMALL));
    assert_eq!(cube(&mut p, &mut n, &mut i[..11]), Err(BUFFER_TOO_SMALL));
    assert!(cube(&mut p, &mut n, &mut i).is_ok());

    let (mut p, mut n, mut i) = buffers(60, 120);
    assert!(torus(10, 6, 1.0, 0.5, &mut p, &mut n, &mut i).is_ok());
    assert_eq!(torus(10, 6, 1.0, 0.5, &mut p[..59], &mut n, &mut i), Err(BUFFER_TOO_SMALL));
    assert_eq!(torus(10, 6, 1.0, 0.5, &mut p, &mut n[..59], &mut i), Err(BUFFER_TOO_SMALL));
    assert_eq!(torus(10, 6, 1.0, 0.5, &mut p, &mut n, &mut i[..119]), Err(BUFFER_TOO_SMALL));
}

#[test]
fn bad_parameters_are_rejected_without_touching_buffers() {
    let (mut p, mut n, mut i) = buffers(70_000, 140_000);
    let untouched = |p: &[[f32; 3]], i: &[[u16; 3]]| p[0][0].is_nan() && i[0] == [u16::MAX; 3];
    assert_eq!(icosphere(ICOSPHERE_MAX_SUBDIVISIONS + 1, &mut p, &mut n, &mut i), Err(INVALID_PARAMETER));
    assert_eq!(icosphere(u32::MAX, &mut p, &mut n, &mut i), Err(INVALID_PARAMETER));
    for (ms, ns, big_r, r, err) in [
        (2, 8, 1.0, 0.5, INVALID_PARAMETER),
        (8, 2, 1.0, 0.5, INVALID_PARAMETER),
        (0, 0, 1.0, 0.5, INVALID_PARAMETER),
        (257, 256, 1.0, 0.5, INVALID_PARAMETER),
        (usize::MAX, usize::MAX, 1.0, 0.5, INVALID_PARAMETER),
        (8, 8, 1.0, 1.0, INVALID_PARAMETER),
        (8, 8, 1.0, 2.0, INVALID_PARAMETER),
        (8, 8, 1.0, 0.0, INVALID_PARAMETER),
        (8, 8, -1.0, -0.5, INVALID_PARAMETER),
        (8, 8, f32::NAN, 0.5, Error::NonFiniteCoordinate),
        (8, 8, 1.0, f32::NAN, Error::NonFiniteCoordinate),
        (8, 8, f32::INFINITY, 0.5, Error::NonFiniteCoordinate),
        (8, 8, 3e38, 2e38, Error::NonFiniteCoordinate),
    ] {
        assert_eq!(torus(ms, ns, big_r, r, &mut p, &mut n, &mut i), Err(err), "{ms} {ns} {big_r} {r}");
        if err != Error::NonFiniteCoordinate || big_r.is_nan() || r.is_nan() {
            assert!(untouched(&p, &i));
        }
    }
    // The largest torus that u16 indices allow.
    assert!(torus(256, 256, 1.0, 0.5, &mut p, &mut n, &mut i).is_ok());
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
    assert_eq!(Mesh { indices: &idx, ..good }.validate(), Err(INVALID_MESH));
    idx[7][1] = nv - 1;
    assert_eq!(Mesh { indices: &idx, ..good }.validate(), Ok(()));
    idx[0][2] = u16::MAX;
    assert_eq!(Mesh { indices: &idx, ..good }.validate(), Err(INVALID_MESH));
    assert_eq!(Mesh::new(&[], &[], &[[0, 0, 0]], ([0.0; 3], 0.0)).validate(), Err(INVALID_MESH));

    // Normals: one per position or none.
    assert_eq!(Mesh { normals: &o.normals[1..], ..good }.validate(), Err(INVALID_MESH));
    let mut more = o.normals.clone();
    more.push([0.0, 0.0, 1.0]);
    assert_eq!(Mesh { normals: &more, ..good }.validate(), Err(INVALID_MESH));

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
    assert_eq!(Mesh { bounding_sphere: (c, r * 0.999), ..good }.validate(), Err(INVALID_MESH));
    assert_eq!(Mesh { bounding_sphere: (c, r * (1.0 - SPHERE_TOLERANCE / 2.0)), ..good }.validate(), Ok(()));
    assert_eq!(Mesh { bounding_sphere: ([0.1, 0.0, 0.0], r), ..good }.validate(), Err(INVALID_MESH));
    assert_eq!(Mesh { bounding_sphere: (c, -r), ..good }.validate(), Err(INVALID_MESH));
    assert_eq!(Mesh::new(&[], &[], &[], ([0.0; 3], -1.0)).validate(), Err(INVALID_MESH));
    // Huge coordinates whose squared distance overflows are rejected, not accepted.
    let far = [[3e38, 0.0, 0.0], [-3e38, 0.0, 0.0]];
    assert_eq!(Mesh::new(&far, &[], &[], ([0.0; 3], 1e19)).validate(), Err(INVALID_MESH));
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
