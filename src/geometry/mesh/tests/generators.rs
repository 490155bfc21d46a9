//! Tests of the generators (`cube`, `icosphere`, `torus`): closed outward
//! manifolds of the right volume, exact counts, buffer sizes and parameters.

use super::*;

fn make_cube() -> Owned {
    let (mut p, mut n, mut i) = buffers(cube_vertex_count(), cube_triangle_count());
    own(cube(&mut p, &mut n, &mut i).unwrap())
}

fn make_torus(m: usize, n: usize, big_r: f32, r: f32) -> Owned {
    let (mut p, mut nn, mut i) = buffers(torus_vertex_count(m, n), torus_triangle_count(m, n));
    own(torus(m, n, big_r, r, &mut p, &mut nn, &mut i).unwrap())
}

fn len64(v: [f32; 3]) -> f64 {
    let v = f64v(v);
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn sub64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
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
