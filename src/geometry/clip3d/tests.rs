//! Tests of `clip3d` against an independent `f64` reference clipper.
//!
//! Tolerances: a clipped vertex may move by `δ = K·U·(M + c)·(1 + |ndc|)/w` in
//! NDC, where `U` is the unit of the type (`2^-24` for `f32`, `2^-16` for Fx),
//! `M` the largest input magnitude, `c = 1 + g` for Fx (its errors are
//! absolute) and 0 for `f32`, and `K = 8`.
extern crate std;
use super::*;
use crate::edge::{Cull, TriangleSpans};
use crate::math::Fx;
use crate::{ClipRect, MAX_FRAME_DIM, SubPoint};
use std::{println, vec, vec::Vec};

mod triangles;

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

/// Triangles beyond the guard band: `|x|` up to `10^big · w`.
fn huge(r: &mut Rng, big: f64, cap: f64) -> [P; 3] {
    core::array::from_fn(|_| {
        let w = r.log(0.01, 10.0);
        let k = 10f64.powf(r.r(0.0, big));
        let c = |v: f64| v.clamp(-cap, cap);
        [c(r.r(-k, k) * w), c(r.r(-k, k) * w), r.unit() * w, w]
    })
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
