//! Random triangles against the independent `f64` reference Sutherland–Hodgman
//! clipper (`ref_clip`; `check_tri` clips both windings), and triangles that
//! share an edge.
//!
//! Areas agree within `δ_max` times
//! the sum of both perimeters; convexity holds within `δ_max` per edge.

use super::*;

/// Reference Sutherland–Hodgman in `f64` (exact inputs, no snapping or clamping).
fn ref_clip(tri: [P; 3], g: f64, w_min: f64, far: bool) -> Vec<P> {
    let mut poly = tri.to_vec();
    for k in 0..7 {
        let mut out = vec![];
        for i in 0..poly.len() {
            let (a, b) = (poly[(i + poly.len() - 1) % poly.len()], poly[i]);
            let (da, db) = (dists(&a, g, w_min, far)[k], dists(&b, g, w_min, far)[k]);
            if (da >= 0.0) != (db >= 0.0) {
                out.push(lerp(&a, &b, da / (da - db)));
            }
            if db >= 0.0 {
                out.push(b);
            }
        }
        poly = out;
    }
    if poly.len() < 3 { vec![] } else { poly }
}

fn ndc(p: &P) -> (f64, f64) {
    (p[0] / p[3], p[1] / p[3])
}

/// Signed area and perimeter after the divide.
fn area_perim(poly: &[P]) -> (f64, f64) {
    let (mut a, mut l) = (0.0, 0.0);
    for i in 0..poly.len() {
        let ((x0, y0), (x1, y1)) = (ndc(&poly[i]), ndc(&poly[(i + 1) % poly.len()]));
        a += x0 * y1 - x1 * y0;
        l += (x1 - x0).hypot(y1 - y0);
    }
    (a / 2.0, l)
}

#[derive(Default, Debug)]
struct Stats {
    tris: u64,
    accepted: u64,
    clipped: u64,
    empty: u64,
    max_len: usize,
    worst_area: f64,
    worst_bary: f64,
    worst_convex: f64,
}

/// Clips `tri` in `T`, checks everything against the reference, both windings.
fn check_tri<T: Num>(tri: [P; 3], planes: ClipPlanes, st: &mut Stats) {
    let v: [V<T>; 3] = core::array::from_fn(|i| vert(tri[i], i));
    let exact = v.map(|v| v.pos.map(T::to)); // the inputs as T holds them
    let c = Ctx::<T>::new(planes);
    let (g, wm) = (c.g.to(), c.w_min.to());
    let out = clip_triangle(v, planes);
    let rev = clip_triangle([v[0], v[2], v[1]], planes);
    st.tris += 1;
    let n = out.vertices().len();
    assert!(n == 0 || (3..=MAX_POLYGON_VERTICES).contains(&n));
    assert_eq!(n, rev.vertices().len());
    assert_eq!(out.triangles().len(), n.saturating_sub(2));
    st.max_len = st.max_len.max(n);
    if n == 0 {
        st.empty += 1;
    } else if out.vertices() == &v[..] {
        st.accepted += 1;
    } else {
        st.clipped += 1;
    }
    let m = exact.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let refp = ref_clip(exact, g, wm, planes.far());
    let got: Vec<P> = out.vertices().iter().map(|v| v.pos.map(T::to)).collect();
    let unit = |p: &P| {
        T::U * (m + if T::FX { 1.0 + g } else { 0.0 }) * (1.0 + ndc(p).0.abs().max(ndc(p).1.abs())) / p[3]
    };
    let d1 = got.iter().chain(&refp).map(unit).fold(0.0, f64::max);
    let bits = |p: &Polygon<T, 3>| {
        let mut b: Vec<[u64; 4]> = p.vertices().iter().map(|v| v.pos.map(|c| c.to().to_bits())).collect();
        b.sort();
        b
    };
    assert_eq!(bits(&out), bits(&rev), "the reversed triangle gives the same vertices");
    for o in out.vertices() {
        check_exact(&c, &o.pos);
        let b = o.attr.map(T::to);
        for (k, p) in o.pos.iter().enumerate() {
            let want: f64 = (0..3).map(|i| b[i] * exact[i][k]).sum();
            let err = (p.to() - want).abs() / (T::U * (m + 1.0) * (1.0 + g));
            st.worst_bary = st.worst_bary.max(err);
            assert!(err <= K, "bary {err} {tri:?}");
        }
    }
    let ((ag, pg), (ar, pr)) = (area_perim(&got), area_perim(&refp));
    let err = (ag - ar).abs() / (d1 * (pg + pr) + 1e-300);
    st.worst_area = st.worst_area.max(err);
    assert!(err <= K, "area {ag} vs {ar} ({err}) {tri:?}");
    let arev = area_perim(&rev.vertices().iter().map(|v| v.pos.map(T::to)).collect::<Vec<_>>()).0;
    assert!((arev + ag).abs() <= 1e-9 * (ag.abs() + pg * pg), "reversed winding, opposite area");
    if ar.abs() > K * d1 * (pg + pr) {
        assert_eq!(ag > 0.0, ar > 0.0, "winding {tri:?}");
        if exact.iter().all(|p| p[3] > 0.0) {
            assert_eq!(ar > 0.0, area_perim(&exact).0 > 0.0, "reference keeps the winding");
        }
    }
    for i in 0..n {
        let [a, b, q] = [0, 1, 2].map(|k| ndc(&got[(i + k) % n]));
        let cross = (b.0 - a.0) * (q.1 - b.1) - (b.1 - a.1) * (q.0 - b.0);
        let lens = (b.0 - a.0).hypot(b.1 - a.1) + (q.0 - b.0).hypot(q.1 - b.1);
        let err = -cross * ag.signum() / (d1 * lens + 1e-300);
        st.worst_convex = st.worst_convex.max(err);
        assert!(err <= K, "convex {err} {tri:?}");
    }
}

/// A vertex with `w → 0+` inside near/far, the others ordinary.
fn w_tiny(r: &mut Rng, g: f64) -> [P; 3] {
    let mut t = raw(r, 10.0);
    let w = r.log(1e-30, 1e-3);
    t[0] = [r.r(-2.0, 2.0) * g * w, r.r(-2.0, 2.0) * g * w, r.unit() * w, w];
    t[1][3] = t[1][3].abs();
    t
}

fn run<T: Num>(count: u64, cap: f64, seed: u64) -> Stats {
    let mut r = Rng(seed);
    let mut st = Stats::default();
    for i in 0..count {
        let planes = match i % 4 {
            0 => ClipPlanes::DEFAULT,
            1 => ClipPlanes::NO_FAR.with_guard_band(r.r(1.0, 20.0) as f32),
            2 => ClipPlanes::for_viewport_fast_path(320, 240, 8),
            _ => ClipPlanes::DEFAULT.with_guard_band(1.0).with_w_min(0.25),
        };
        let g = planes.guard_band() as f64;
        let tri = match i % 9 {
            0 => camera(&mut r, 0.5, 20.0),   // mostly in front
            1 => camera(&mut r, -3.0, 30.0),  // crossing the near plane and w = 0
            2 => camera(&mut r, -50.0, -1.0), // entirely behind the eye
            3 => raw(&mut r, 1.0),
            4 => raw(&mut r, cap.min(1e4)),
            5 => w_tiny(&mut r, g),
            6 => huge(&mut r, 6.0, cap),
            7 => raw(&mut r, 1e-3).map(|p| [p[0] + 3.0 * g, p[1], p[2].abs(), 1.0]), // outside x
            _ => raw(&mut r, 30.0).map(|mut p| {
                p[3] = p[3].abs() + 1.0;
                p[2] = r.unit() * p[3];
                p
            }),
        };
        check_tri::<T>(tri, planes, &mut st);
        if i % 9 == 2 || i % 9 == 7 {
            assert!(clip_triangle(tri.map(|p| vert::<T>(p, 0)), planes).is_empty());
        }
    }
    st
}

#[test]
fn random_triangles_f32() {
    let st = run::<f32>(200_000, 1e12, 1);
    println!("clip3d f32: {st:?}");
    assert!(st.accepted > 10_000 && st.clipped > 10_000 && st.empty > 10_000);
}

#[test]
fn random_triangles_fx() {
    let st = run::<Fx>(200_000, 30000.0, 2);
    println!("clip3d Fx: {st:?}");
    assert!(st.accepted > 10_000 && st.clipped > 10_000 && st.empty > 10_000);
}

#[test]
fn shared_edges_get_identical_vertices() {
    let mut r = Rng(6);
    let mut shared = 0;
    for i in 0..50_000 {
        let q = if i % 2 == 0 { camera(&mut r, -3.0, 30.0) } else { huge(&mut r, 4.0, 1e9) };
        let d = raw(&mut r, 10.0)[0].map(|x| x * 0.3);
        let d = core::array::from_fn(|k| q[0][k] + q[2][k] - q[1][k] + d[k]);
        let (t1, t2) = (
            [vert::<f32>(q[0], 0), vert(q[1], 1), vert(q[2], 2)],
            [vert(q[0], 0), vert(q[2], 2), vert(d, 1)],
        );
        let on_ac = |p: &Polygon<f32, 3>| {
            let mut v: Vec<[u32; 4]> =
                p.vertices().iter().filter(|v| v.attr[1] == 0.0).map(|v| v.pos.map(f32::to_bits)).collect();
            v.sort();
            v
        };
        let (a, b) = (clip_triangle(t1, ClipPlanes::DEFAULT), clip_triangle(t2, ClipPlanes::DEFAULT));
        if !a.is_empty() && !b.is_empty() {
            assert_eq!(on_ac(&a), on_ac(&b));
            shared += 1;
        }
    }
    assert!(shared > 10_000);
}
