//! Watertightness under clipping: shapes that enclose the whole screen must
//! hit every screen pixel exactly once.
//!
//! * 2D (huge coordinates, the rasterizer's `i64` path, clipped only by the
//!   scissor): fans whose rim lies on a circle enclosing the screen with the
//!   centre inside it, radius from 1.3× the screen to the ±2^28-subpixel
//!   range limit; rotated quad grids reaching past every screen edge, cells
//!   from 7 px to 2^(26−S) px; both windings; whole screen and 1-row bands.
//! * 3D (the pipeline's homogeneous clipping, then snapping): the same fans
//!   and grids on a plane facing the camera, from just enclosing the view to
//!   10^6 times beyond the guard band; and tilted planes that cross the near
//!   plane (part behind the eye) and the far plane, where every pixel whose
//!   ray clearly hits the shape must be hit once, every pixel whose ray
//!   clearly misses it never, and no pixel twice.

use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::depth::{DepthBand, DepthState, NoDepth};
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::Mat4;
use microraster::mesh::Mesh;
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, ClipRect, Renderer, SubPoint};
use std::f64::consts::TAU;

const W: i32 = 96;
const H: i32 = 72;
const LIM: f64 = (1u64 << 28) as f64;

/// Hits per screen pixel of `tris` (exact spans), drawn over the whole screen
/// and in 1-row bands; both must agree.
fn hits<const S: u32>(tris: &[[SubPoint<S>; 3]]) -> Vec<u32> {
    let screen = ClipRect::new(0, 0, W, H);
    let mut whole = vec![0u32; (W * H) as usize];
    let mut rows = whole.clone();
    for (buf, band_h) in [(&mut whole, H), (&mut rows, 1)] {
        for y0 in (0..H).step_by(band_h as usize) {
            let band = screen.with_rows(y0, y0 + band_h);
            for t in tris {
                for s in TriangleSpans::new(*t, band, Cull::None) {
                    for x in s.x..s.x + s.len as i32 {
                        assert!(band.contains(x, s.y));
                        buf[(s.y * W + x) as usize] += 1;
                    }
                }
            }
        }
    }
    assert!(whole == rows, "S={S}: 1-row bands differ from the whole screen");
    whole
}

fn snap<const S: u32>(x: f64, y: f64) -> SubPoint<S> {
    let one = f64::from(1u32 << S);
    let c = |v: f64| (v * one).round().clamp(-LIM, LIM) as i32;
    SubPoint::new(c(x), c(y)).unwrap()
}

fn flip_some<T>(tris: &mut [[T; 3]], rng: &mut Rng) {
    for t in tris {
        if rng.chance(0.5) {
            t.swap(1, 2);
        }
    }
}

/// A fan of `n` rim points on a circle of radius `r` px around `(cx, cy)`.
fn fan2d<const S: u32>(rng: &mut Rng, cx: f64, cy: f64, r: f64, n: usize) -> Vec<[SubPoint<S>; 3]> {
    let c = snap::<S>(cx, cy);
    let turn = rng.uniform(0.0, TAU);
    let rim: Vec<_> = (0..n)
        .map(|k| {
            let t = turn + TAU * k as f64 / n as f64;
            snap::<S>(cx + r * t.cos(), cy + r * t.sin())
        })
        .collect();
    let mut tris: Vec<_> = (0..n).map(|k| [c, rim[k], rim[(k + 1) % n]]).collect();
    flip_some(&mut tris, rng);
    tris
}

/// A rotated grid of `n × n` cells of `s` px around `(ox, oy)`, quads split
/// along alternating diagonals.
fn grid2d<const S: u32>(
    rng: &mut Rng,
    ox: f64,
    oy: f64,
    s: f64,
    n: usize,
    angle: f64,
) -> Vec<[SubPoint<S>; 3]> {
    let (sin, cos) = angle.sin_cos();
    let at = |i: usize, j: usize| {
        let (u, v) = ((i as f64 - n as f64 / 2.0) * s, (j as f64 - n as f64 / 2.0) * s);
        snap::<S>(ox + u * cos - v * sin, oy + u * sin + v * cos)
    };
    let mut tris = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if (i + j) % 2 == 0 {
                tris.extend([[a, b, c], [a, c, d]])
            } else {
                tris.extend([[b, c, d], [b, d, a]])
            }
        }
    }
    flip_some(&mut tris, rng);
    tris
}

fn watertight_2d<const S: u32>() -> [usize; 2] {
    let mut rng = Rng::new(0x3a7e + u64::from(S));
    let max_r = LIM / f64::from(1u32 << S) / 1.5; // rim stays inside the range
    let diag = f64::from(W).hypot(f64::from(H));
    let mut n = [0; 2];
    for i in 0..40 {
        let (cx, cy) = (rng.uniform(1.0, f64::from(W) - 1.0), rng.uniform(1.0, f64::from(H) - 1.0));
        let r = rng.log_uniform(1.3 * diag, max_r);
        let k = [5usize, 7, 16, 64, 333][i % 5];
        // The inscribed polygon must still enclose the screen.
        let r = r.max(1.3 * diag / (std::f64::consts::PI / k as f64).cos());
        let h = hits(&fan2d::<S>(&mut rng, cx, cy, r.min(max_r), k));
        assert!(h.iter().all(|&c| c == 1), "S={S} fan r={r} k={k}: hits {:?}", h.iter().max());
        n[0] += 1;
    }
    for i in 0..24 {
        let s = [7.3, 41.0, 1000.0, 1.0e5, max_r / 4.0][i % 5].min(max_r / 4.0);
        let cells = ((2.2 * diag / s).ceil() as usize + 2).clamp(3, 60);
        let (ox, oy) = (rng.uniform(0.0, f64::from(W)), rng.uniform(0.0, f64::from(H)));
        let angle = rng.uniform(0.0, TAU);
        let h = hits(&grid2d::<S>(&mut rng, ox, oy, s, cells, angle));
        assert!(h.iter().all(|&c| c == 1), "S={S} grid s={s}: max hits {:?}", h.iter().max());
        n[1] += 1;
    }
    n
}

#[test]
fn watertight_2d_fans_and_grids_beyond_the_screen() {
    let n = [watertight_2d::<0>(), watertight_2d::<4>(), watertight_2d::<8>()];
    println!("watertight 2D (fans, grids) for S = 0, 4, 8: {n:?}, every screen pixel exactly once");
}

// ---------------------------------------------------------------------- 3D

const FOV: f64 = 1.0;
const NEAR: f32 = 0.1;
const FAR: f32 = 100.0;

fn pipeline() -> Pipeline<f32, 4> {
    let mut p = Pipeline::perspective(Mat4::IDENTITY, FOV as f32, NEAR, FAR, W as u32, H as u32).unwrap();
    p.cull = Cull::None;
    p.shade = Shade::Flat;
    p
}

/// Runs a mesh through the pipeline; returns the bins' hits per pixel, and
/// checks that the band renderer draws exactly the hit pixels.
fn hits_3d(p: &Pipeline<f32, 4>, pos: &[[f32; 3]], idx: &[[u16; 3]]) -> (Vec<u32>, u32) {
    let sphere = crate::ref3d::loose_sphere(pos);
    let mesh = Mesh::new(pos, &[], idx, sphere);
    let mut bins = Box::new(heapless::Vec::<ScreenTriangle<4>, 4096>::new());
    let st = p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(255), &mut bins).unwrap();
    let tris: Vec<_> = bins.iter().map(|t| t.v.map(|v| v.pos)).collect();
    let h = hits(&tris);
    let mut fb = crate::framebuffer::Framebuffer::new(W as u32, H as u32, Gray8::new(0));
    let mut band = Box::new(Band::<Gray8, { W as usize }, 16>::new(Gray8::new(0)));
    let mut depth = Box::new(DepthBand::<NoDepth, { W as usize }, 16>::new());
    Renderer::new(H as u32, Gray8::new(0))
        .render(Triangles3d::new(&bins, &mut depth, DepthState::DISABLED, Affine), &mut band, &mut fb)
        .unwrap();
    for (i, (&c, &px)) in h.iter().zip(&fb.pixels).enumerate() {
        assert_eq!(c > 0, px == Gray8::new(255), "pixel {i}: spans and renderer disagree");
    }
    (h, st.clipped)
}

/// A planar fan (centre + `n` rim points on a circle of radius `r`) in the
/// plane through `o` spanned by the unit vectors `e1`, `e2`.
fn fan3d(
    rng: &mut Rng,
    o: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
    r: f64,
    n: usize,
) -> (Vec<[f32; 3]>, Vec<[u16; 3]>) {
    let turn = rng.uniform(0.0, TAU);
    let at = |a: f64, b: f64| -> [f32; 3] { core::array::from_fn(|i| (o[i] + a * e1[i] + b * e2[i]) as f32) };
    let mut pos = vec![at(0.0, 0.0)];
    pos.extend((0..n).map(|k| {
        let t = turn + TAU * k as f64 / n as f64;
        at(r * t.cos(), r * t.sin())
    }));
    let mut idx: Vec<[u16; 3]> = (0..n).map(|k| [0, 1 + k as u16, 1 + ((k + 1) % n) as u16]).collect();
    flip_some(&mut idx, rng);
    (pos, idx)
}

/// An `n × n` grid of cells of size `s` in the plane through `o` (`e1`, `e2`).
fn grid3d(
    rng: &mut Rng,
    o: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
    s: f64,
    n: usize,
) -> (Vec<[f32; 3]>, Vec<[u16; 3]>) {
    let at = |a: f64, b: f64| -> [f32; 3] { core::array::from_fn(|i| (o[i] + a * e1[i] + b * e2[i]) as f32) };
    let mut pos = Vec::new();
    for i in 0..=n {
        for j in 0..=n {
            pos.push(at((i as f64 - n as f64 / 2.0) * s, (j as f64 - n as f64 / 2.0) * s));
        }
    }
    let id = |i: usize, j: usize| (i * (n + 1) + j) as u16;
    let mut idx = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if (i + j) % 2 == 0 {
                idx.extend([[a, b, c], [a, c, d]])
            } else {
                idx.extend([[b, c, d], [b, d, a]])
            }
        }
    }
    flip_some(&mut idx, rng);
    (pos, idx)
}

/// Fans and grids on planes facing the camera, enclosing the whole view,
/// up to 10^6 times beyond the guard band: every pixel exactly once.
#[test]
fn watertight_3d_facing_planes_beyond_the_guard_band() {
    let p = pipeline();
    let g = f64::from(p.clip.guard_band());
    let mut rng = Rng::new(0x3d7e);
    let (ty, aspect) = ((FOV / 2.0).tan(), f64::from(W) / f64::from(H));
    let (mut clipped, mut meshes) = (0, 0);
    for i in 0..30 {
        let d = rng.log_uniform(0.2, 80.0);
        let half = d * ty * aspect.hypot(1.0); // the view's corner radius at distance d
        let (cx, cy) = (rng.uniform(-0.9, 0.9) * d * ty * aspect, rng.uniform(-0.9, 0.9) * d * ty);
        let o = [cx, cy, -d];
        let (e1, e2) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        // From just enclosing the view to far beyond the guard band.
        let r = half * [2.5, 1.2 * g, 30.0 * g, 1.0e6 * g][i % 4];
        let k = [7usize, 12, 64, 250][i % 4];
        let (pos, idx) = fan3d(&mut rng, o, e1, e2, r / (std::f64::consts::PI / k as f64).cos(), k);
        let (h, c) = hits_3d(&p, &pos, &idx);
        assert!(
            h.iter().all(|&n| n == 1),
            "fan {i}: d={d} r={r}: max hits {:?}, holes {}",
            h.iter().max(),
            h.iter().filter(|&&n| n == 0).count()
        );
        let s = half * [0.37, 1.0, 0.6 * g, 5.0e5 * g][i % 4];
        let n = ((2.6 * half / s).ceil() as usize + 2).clamp(3, 30);
        let (pos, idx) = grid3d(&mut rng, o, e1, e2, s, n);
        let (h, c2) = hits_3d(&p, &pos, &idx);
        assert!(
            h.iter().all(|&n| n == 1),
            "grid {i}: d={d} s={s}: max hits {:?}, holes {}",
            h.iter().max(),
            h.iter().filter(|&&n| n == 0).count()
        );
        clipped += c + c2;
        meshes += 2;
    }
    println!(
        "watertight 3D facing planes: {meshes} meshes ({clipped} triangles clipped at the guard band), every pixel once"
    );
    assert!(clipped >= 100);
}

/// Planes tilted through the near (and far) plane: part of the mesh is
/// behind the eye. Pixels whose centre ray clearly hits the shape between
/// near and far are hit once; clear misses never; no pixel twice.
#[test]
fn watertight_3d_planes_crossing_near_and_far() {
    let p = pipeline();
    let mut rng = Rng::new(0x7117);
    let (ty, aspect) = ((FOV / 2.0).tan(), f64::from(W) / f64::from(H));
    let (mut inside, mut outside, mut meshes) = (0usize, 0usize, 0usize);
    for i in 0..30 {
        // A plane through a point in front of the camera, tilted so that it
        // passes behind the eye; large fans and grids on it.
        let d = rng.log_uniform(0.5, 20.0);
        let o = [rng.uniform(-0.5, 0.5) * d, rng.uniform(-0.5, 0.5) * d, -d];
        let (a, b) = (rng.uniform(0.3, 1.4), rng.uniform(0.0, TAU));
        let e1 = [b.cos(), b.sin(), 0.0];
        let e2 = [-b.sin() * a.cos(), b.cos() * a.cos(), a.sin()]; // tilted towards +z (behind the eye)
        let normal =
            [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
        let r = [50.0 * d, 1.0e4 * d, 3.0e3][i % 3];
        let (pos, idx, poly): (_, _, Vec<(f64, f64)>) = if i % 2 == 0 {
            let k = [16usize, 64, 9][i % 3];
            let (pos, idx) = fan3d(&mut rng, o, e1, e2, r, k);
            let poly = pos[1..].iter().map(|q| plane_uv(q, o, e1, e2)).collect();
            (pos, idx, poly)
        } else {
            let n = 8;
            let s = 2.0 * r / n as f64;
            let (pos, idx) = grid3d(&mut rng, o, e1, e2, s, n);
            let h = r;
            (pos, idx, vec![(-h, -h), (h, -h), (h, h), (-h, h)])
        };
        let (h, _) = hits_3d(&p, &pos, &idx);
        assert!(h.iter().all(|&n| n <= 1), "plane {i}: a pixel hit twice");
        for y in 0..H {
            for x in 0..W {
                let u = (2.0 * (f64::from(x) + 0.5) / f64::from(W) - 1.0) * ty * aspect;
                let v = (1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(H)) * ty;
                let px = 2.0 * ty / f64::from(H); // one pixel, in view units at distance 1
                let got = h[(y * W + x) as usize];
                // Clear only if the centre and the points 2 px away agree.
                let at = |du: f64, dv: f64| {
                    ray_hit([u + du * px, v + dv * px, -1.0], o, normal, e1, e2, &poly, px)
                };
                let c = at(0.0, 0.0);
                let clear =
                    [(2.0, 0.0), (-2.0, 0.0), (0.0, 2.0), (0.0, -2.0)].iter().all(|&(a, b)| at(a, b) == c);
                match if clear { c } else { None } {
                    Some(true) => {
                        assert_eq!(got, 1, "plane {i}: pixel ({x}, {y}) clearly inside but hit {got}×");
                        inside += 1;
                    }
                    Some(false) => {
                        assert_eq!(got, 0, "plane {i}: pixel ({x}, {y}) clearly outside but hit");
                        outside += 1;
                    }
                    None => {}
                }
            }
        }
        meshes += 1;
    }
    println!(
        "watertight 3D planes through near/far: {meshes} meshes, {inside} pixels clearly inside (hit once), {outside} clearly outside (never hit)"
    );
    assert!(inside >= 30 * 1000 && outside >= 3000);
}

fn plane_uv(q: &[f32; 3], o: [f64; 3], e1: [f64; 3], e2: [f64; 3]) -> (f64, f64) {
    let r: Vec<f64> = (0..3).map(|i| f64::from(q[i]) - o[i]).collect();
    ((0..3).map(|i| r[i] * e1[i]).sum(), (0..3).map(|i| r[i] * e2[i]).sum())
}

/// Where the ray `t·dir` (t > 0, eye at the origin) meets the plane: `Some(true)`
/// if it hits the polygon between near and far with a margin of two pixels
/// (measured at the hit distance), `Some(false)` if it clearly misses
/// (outside the polygon, or beyond near/far, by the margin), `None` if close.
fn ray_hit(
    dir: [f64; 3],
    o: [f64; 3],
    n: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
    poly: &[(f64, f64)],
    px: f64,
) -> Option<bool> {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let den = dot(n, dir);
    if den.abs() < 1e-12 {
        return None;
    }
    let t = dot(n, o) / den; // eye distance along −z (dir.z = −1)
    let (near, far) = (f64::from(NEAR), f64::from(FAR));
    if t <= 0.0 || t < near * 0.98 || t > far * 1.02 {
        return Some(false);
    }
    if t < near * 1.02 || t > far * 0.98 {
        return None;
    }
    let q = [t * dir[0], t * dir[1], t * dir[2]];
    let (u, v) = plane_uv(&q.map(|c| c as f32), o, e1, e2);
    // Margin: two pixels at distance t, stretched by the plane's slant.
    let slant = (dot(n, dir).abs() / dot(dir, dir).sqrt()).max(1e-3);
    let m = 2.0 * px * t / slant + 1e-6 * (u.abs() + v.abs());
    let k = poly.len();
    let mut inside = true;
    let mut min_d = f64::INFINITY;
    let area: f64 = (0..k).map(|i| poly[i].0 * poly[(i + 1) % k].1 - poly[(i + 1) % k].0 * poly[i].1).sum();
    for i in 0..k {
        let (a, b) = (poly[i], poly[(i + 1) % k]);
        let (ex, ey) = (b.0 - a.0, b.1 - a.1);
        let sd = (ex * (v - a.1) - ey * (u - a.0)) / ex.hypot(ey) * area.signum();
        inside &= sd > 0.0;
        min_d = min_d.min(sd.abs());
    }
    if min_d < m { None } else { Some(inside) }
}
