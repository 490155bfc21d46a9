//! Tests of `clip3d` against an independent `f64` reference clipper.
//!
//! Tolerances: a clipped vertex may move by `δ = K·U·(M + c)·(1 + |ndc|)/w` in
//! NDC, where `U` is the unit of the type (`2^-24` for `f32`, `2^-16` for Fx),
//! `M` the largest input magnitude, `c = 1 + g` for Fx (its errors are
//! absolute) and 0 for `f32`, and `K = 8`. Areas agree within `δ_max` times
//! the sum of both perimeters; convexity holds within `δ_max` per edge.
extern crate std;
use super::*;
use crate::edge::{Cull, TriangleSpans};
use crate::math::Fx;
use crate::{ClipRect, MAX_FRAME_DIM, SubPoint};
use std::{println, vec, vec::Vec};

const K: f64 = 8.0;
type P = [f64; 4];
type V<T> = ClipVertex<T, 3>;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let z = (self.0 ^ (self.0 >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        let z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn r(&mut self, lo: f64, hi: f64) -> f64 {
        lo + self.unit() * (hi - lo)
    }
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

trait Num: Scalar {
    const U: f64;
    const FX: bool;
    fn of(v: f64) -> Self;
    fn to(self) -> f64;
}
impl Num for f32 {
    const U: f64 = 1.0 / 16777216.0;
    const FX: bool = false;
    fn of(v: f64) -> Self {
        v as f32
    }
    fn to(self) -> f64 {
        self as f64
    }
}
impl Num for Fx {
    const U: f64 = 1.0 / 65536.0;
    const FX: bool = true;
    fn of(v: f64) -> Self {
        Fx::from_bits((v * 65536.0).round().clamp(i32::MIN as f64, i32::MAX as f64) as i32)
    }
    fn to(self) -> f64 {
        self.to_bits() as f64 / 65536.0
    }
}

/// The plane distances in `f64`, in the clipper's order.
fn dists(p: &P, g: f64, w_min: f64, far: bool) -> Vec<f64> {
    let [x, y, z, w] = *p;
    let mut d = vec![w - w_min, z, w - z, g * w + x, g * w - x, g * w + y, g * w - y];
    if !far {
        d[2] = 1.0;
    }
    d
}

fn lerp(a: &P, b: &P, t: f64) -> P {
    core::array::from_fn(|i| a[i] + (b[i] - a[i]) * t)
}

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

fn vert<T: Num>(p: P, i: usize) -> V<T> {
    ClipVertex { pos: p.map(T::of), attr: core::array::from_fn(|j| if i == j { T::ONE } else { T::ZERO }) }
}

/// Checks the exact guarantees of one output vertex in `T`.
fn check_exact<T: Num>(c: &Ctx<T>, v: &[T; 4]) {
    let [x, y, z, w] = *v;
    assert!(w >= c.w_min && c.w_min > T::ZERO, "w {v:?}");
    assert!(z >= T::ZERO && (!c.far || z <= w), "z {v:?}");
    let gw = c.g * w;
    assert!(x <= gw && -gw <= x && y <= gw && -gw <= y, "xy {v:?}");
    assert!(v.iter().all(|c| c.to().is_finite()));
    let lim = c.g.to() * if T::FX { 1.0 } else { 1.0 + 3.0 * T::U };
    assert!((x.to() / w.to()).abs() <= lim && (y.to() / w.to()).abs() <= lim);
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

/// A camera-made triangle: view-space points through a D3D perspective matrix.
fn camera(r: &mut Rng, zmin: f64, zmax: f64) -> [P; 3] {
    let n = r.log(0.01, 1.0);
    let f = n * r.log(10.0, 1e4);
    let (a, s) = (f / (n - f), r.r(0.5, 3.0));
    core::array::from_fn(|_| {
        let zv = -r.r(zmin, zmax) * n;
        let (x, y) = (r.r(-2.0, 2.0) * zv.abs().max(n), r.r(-2.0, 2.0) * zv.abs().max(n));
        [x * s, y * s, a * zv + a * n, -zv]
    })
}

/// Random clip-space vertices at scale `s` (`w` of either sign).
fn raw(r: &mut Rng, s: f64) -> [P; 3] {
    core::array::from_fn(|_| core::array::from_fn(|_| r.r(-s, s)))
}

/// A vertex with `w → 0+` inside near/far, the others ordinary.
fn w_tiny(r: &mut Rng, g: f64) -> [P; 3] {
    let mut t = raw(r, 10.0);
    let w = r.log(1e-30, 1e-3);
    t[0] = [r.r(-2.0, 2.0) * g * w, r.r(-2.0, 2.0) * g * w, r.unit() * w, w];
    t[1][3] = t[1][3].abs();
    t
}

/// Triangles beyond the guard band: `|x|` up to `10^big · w`.
fn huge(r: &mut Rng, big: f64, cap: f64) -> [P; 3] {
    core::array::from_fn(|_| {
        let w = r.log(0.01, 10.0);
        let k = 10f64.powf(r.r(0.0, big));
        let c = |v: f64| v.clamp(-cap, cap);
        [c(r.r(-k, k) * w), c(r.r(-k, k) * w), r.unit() * w, w]
    })
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
fn near_plane_cut_is_exact_and_behind_eye_is_empty() {
    fn go<T: Num>() {
        let v = |x: f64, z: f64, w: f64, i| vert::<T>([x, 0.3, z, w], i);
        let p = clip_triangle(
            [v(0.1, 0.7, 1.3, 0), v(0.9, -0.7, 0.1, 1), v(-0.3, 0.2, 0.9, 2)],
            ClipPlanes::DEFAULT,
        );
        assert_eq!(p.vertices().len(), 4);
        assert_eq!(p.vertices().iter().filter(|v| v.pos[2] == T::ZERO).count(), 2);
        let behind = [v(0.0, -0.5, -1.0, 0), v(1.0, -3.0, -2.0, 1), v(-1.0, -2.0, -0.1, 2)];
        assert!(clip_triangle(behind, ClipPlanes::NO_FAR).is_empty());
        assert_eq!(clip_line(behind[0], behind[1], ClipPlanes::NO_FAR), None);
    }
    go::<f32>();
    go::<Fx>();
}

#[test]
fn non_finite_and_huge_f32_inputs_are_discarded() {
    let mut n = 0;
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e30, -1e20] {
        for k in 0..15 {
            let mut v = [[0.1f32, 0.2, 0.5, 1.0], [0.3, 0.1, 0.5, 1.0], [0.2, 0.4, 0.5, 1.0]]
                .map(|pos| ClipVertex { pos, attr: [0.5f32; 1] });
            let (i, c) = (k / 5, k % 5);
            if c < 4 {
                v[i].pos[c] = bad
            } else {
                v[i].attr[0] = bad
            }
            assert!(clip_triangle(v, ClipPlanes::DEFAULT).is_empty());
            assert_eq!(clip_line(v[i], v[(i + 1) % 3], ClipPlanes::DEFAULT), None);
            n += 1;
        }
    }
    println!("clip3d non-finite cases: {n}");
}

#[test]
fn saturated_fx_never_lets_w_nonpositive_through() {
    let mut r = Rng(3);
    let vals = [Fx::MIN, Fx::MAX, Fx::ZERO, Fx::from_bits(1), Fx::from_bits(-1), Fx::from_f32(-30000.0)];
    let (mut tris, mut kept) = (0, 0);
    for i in 0..100_000u64 {
        let planes = if i % 2 == 0 { ClipPlanes::DEFAULT } else { ClipPlanes::NO_FAR.with_guard_band(1.0) };
        let c = Ctx::<Fx>::new(planes);
        let pick = |r: &mut Rng| {
            if r.unit() < 0.7 { vals[(r.next() % 6) as usize] } else { Fx::from_bits(r.next() as i32) }
        };
        let v: [ClipVertex<Fx, 2>; 3] = core::array::from_fn(|_| ClipVertex {
            pos: core::array::from_fn(|_| pick(&mut r)),
            attr: [pick(&mut r); 2],
        });
        let p = clip_triangle(v, planes);
        p.vertices().iter().for_each(|v| check_exact(&c, &v.pos));
        if let Some((a, b)) = clip_line(v[0], v[1], planes) {
            check_exact(&c, &a.pos);
            check_exact(&c, &b.pos);
        }
        tris += 1;
        kept += !p.is_empty() as u64;
    }
    println!("clip3d saturated Fx: {tris} triangles, {kept} non-empty");
}

/// Reference parametric line clip in `f64`: `(t0, t1)` and their tolerances.
fn ref_line(a: &P, b: &P, g: f64, wm: f64, far: bool, tol: f64, u: f64) -> Option<(f64, f64, f64)> {
    let (mut t0, mut t1, mut slack) = (0.0f64, 1.0f64, K * u);
    for (da, db) in dists(a, g, wm, far).into_iter().zip(dists(b, g, wm, far)) {
        if da < 0.0 && db < 0.0 {
            return None;
        }
        if da < 0.0 || db < 0.0 {
            let t = da / (da - db);
            slack = slack.max(tol / (da - db).abs());
            if da < 0.0 { t0 = t0.max(t) } else { t1 = t1.min(t) }
        }
    }
    if t0 > t1 + slack { None } else { Some((t0, t1, slack)) }
}

fn lines<T: Num>(count: u64, cap: f64, seed: u64) -> (u64, u64) {
    let mut r = Rng(seed);
    let (mut kept, mut worst) = (0, 0.0f64);
    for i in 0..count {
        let planes = if i % 2 == 0 { ClipPlanes::DEFAULT } else { ClipPlanes::NO_FAR.with_guard_band(2.0) };
        let tri = match i % 3 {
            0 => camera(&mut r, -3.0, 30.0),
            1 => huge(&mut r, 6.0, cap),
            _ => raw(&mut r, cap.min(100.0)),
        };
        let [a, b] = [0, 1].map(|k| ClipVertex { pos: tri[k].map(T::of), attr: [T::of(k as f64)] });
        let (ea, eb) = (a.pos.map(T::to), b.pos.map(T::to));
        let c = Ctx::<T>::new(planes);
        let m = ea.iter().chain(&eb).fold(0.0f64, |m, x| m.max(x.abs()));
        let g = c.g.to();
        let dtol = K * T::U * if T::FX { 2.0 } else { m * (1.0 + g) };
        let tol = K * T::U * (m + 1.0) * (1.0 + g);
        let re = ref_line(&ea, &eb, g, c.w_min.to(), planes.far(), dtol, T::U);
        match (clip_line(a, b, planes), re) {
            (Some((p, q)), re) => {
                kept += 1;
                let (s0, s1) = (p.attr[0].to(), q.attr[0].to());
                for (v, s) in [(p, s0), (q, s1)] {
                    check_exact(&c, &v.pos);
                    let e = (0..4).map(|k| (v.pos[k].to() - lerp(&ea, &eb, s)[k]).abs()).fold(0.0, f64::max);
                    assert!(e <= tol, "line end off the segment: {e} > {tol}");
                }
                match re {
                    Some((t0, t1, sl)) => {
                        worst = worst.max((s0 - t0).abs().max((s1 - t1).abs()) / sl * K);
                        assert!((s0 - t0).abs() <= sl && (s1 - t1).abs() <= sl, "{s0} {s1} vs {t0} {t1}");
                    }
                    None => assert!(s1 - s0 <= 1e-3, "kept a segment the reference drops"),
                }
            }
            (None, Some((t0, t1, sl))) => assert!(t1 - t0 <= 2.0 * sl, "dropped {t0}..{t1}"),
            (None, None) => {}
        }
    }
    println!(
        "clip3d lines {}: {count}, {kept} kept, worst t error {worst:.2} (limit {K})",
        if T::FX { "Fx" } else { "f32" }
    );
    (count, kept)
}

#[test]
fn random_lines_f32_and_fx() {
    assert!(lines::<f32>(100_000, 1e12, 4).1 > 10_000);
    assert!(lines::<Fx>(100_000, 30000.0, 5).1 > 10_000);
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

#[test]
fn guard_band_formulas() {
    const FAST8: f32 = guard_band_for_fast_path(320, 240, 8);
    let vals = [
        guard_band_for_range(320, 240, 4),
        guard_band_for_range(320, 240, 8),
        guard_band_for_fast_path(320, 240, 4),
        FAST8,
        guard_band_for_range(4096, 4096, 8),
        guard_band_for_limit(320, 240, 32767),
    ];
    println!("clip3d guard bands (range S4, S8, fast S4, S8, range 4096² S8, Fx 320): {vals:?}");
    let want = [104730.6, 6522.6, 18.08, 4.514, 510.5, 180.0];
    assert!(vals.iter().zip(want).all(|(v, w)| (*v as f64 - w).abs() <= w * 2e-3));
    assert_eq!(guard_band_for_fast_path(4096, 4096, 8), 1.0);
    assert_eq!(ClipPlanes::DEFAULT.with_guard_band(f32::NAN).guard_band(), 1.0);
}

fn end_to_end<const S: u32>(r: &mut Rng, w: u32, h: u32, fast: bool) -> u64 {
    let planes =
        if fast { ClipPlanes::for_viewport_fast_path(w, h, S) } else { ClipPlanes::for_viewport(w, h, S) };
    let g = planes.guard_band() as f64;
    let (x0, y0) = (r.r(0.0, (MAX_FRAME_DIM - w) as f64) as f32, r.r(0.0, (MAX_FRAME_DIM - h) as f64) as f32);
    let mut n = 0;
    for _ in 0..20_000 {
        let t = huge(r, (g * 100.0).log10(), 1e15).map(|p| vert::<f32>(p, 0));
        for tri in clip_triangle(t, planes).triangles() {
            let sp = tri.map(|v| {
                let (nx, ny) = (v.pos[0] / v.pos[3], v.pos[1] / v.pos[3]);
                let p = SubPoint::<S>::from_f32(
                    x0 + (1.0 + nx) * w as f32 / 2.0,
                    y0 + (1.0 - ny) * h as f32 / 2.0,
                );
                p.expect("guard band keeps the rasterizer's range")
            });
            if fast {
                let spans = TriangleSpans::new(sp, ClipRect::new(0, 0, 4096, 4096), Cull::None);
                assert!(spans.is_fast_path() || spans.clone().next().is_none(), "{sp:?}");
            }
            n += 1;
        }
    }
    n
}

#[test]
fn guard_bands_keep_range_and_fast_path_end_to_end() {
    let mut r = Rng(7);
    let mut n = 0;
    for (w, h) in [(320, 240), (128, 160), (4096, 4096), (1, 1)] {
        n += end_to_end::<0>(&mut r, w, h, false) + end_to_end::<4>(&mut r, w, h, false);
        n += end_to_end::<8>(&mut r, w, h, false);
        if w < 1000 {
            n += end_to_end::<4>(&mut r, w, h, true) + end_to_end::<8>(&mut r, w, h, true);
        }
    }
    println!("clip3d end-to-end fan triangles: {n}");
}
