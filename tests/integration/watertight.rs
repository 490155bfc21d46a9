//! Meshes that tile a region must hit every pixel centre inside it exactly once
//! and none outside, also when drawn band by band.
//!
//! Meshes: (a) grids of rotated quads at 16 angles, each quad split around its
//! centre into 4 triangles or along either diagonal; (b) fans whose rim points
//! lie on a circle or a convex polygon, consecutive rim points 0 to 1 px apart
//! (slivers, and zero-area triangles after snapping); (c) every triangle's
//! winding flipped at random; (d) many meshes reach past the screen, and each is
//! drawn whole and in bands of 1, 7 and 16 rows.
//!
//! Per pixel the hit count must (1) equal the sum of the exact reference over
//! all triangles, which itself must never exceed 1 (the snapped mesh really is
//! a tiling); (2) be 1 strictly inside the snapped outline, 0 strictly outside
//! and at most 1 on it (exact integer winding number).

use crate::reference::{ExactTriangle, Rng, TieRule};
use microraster::edge::{Cull, TriangleSpans};
use microraster::{ClipRect, SubPoint};
use std::f64::consts::TAU;

const W: i32 = 64;
const H: i32 = 48;

struct Mesh<const S: u32> {
    tris: Vec<[SubPoint<S>; 3]>,
    /// The snapped outline of the tiled region, in order.
    outline: Vec<SubPoint<S>>,
}

#[derive(Default, Debug)]
struct Counts {
    meshes: usize,
    triangles: usize,
    zero_area: usize,
    inside_pixels: usize,
    full_cover_meshes: usize,
}

fn snap<const S: u32>(x: f64, y: f64) -> SubPoint<S> {
    let one = (1u32 << S) as f64;
    SubPoint::new((x * one).round() as i32, (y * one).round() as i32).unwrap()
}

/// Winding number of `outline` around the centre of pixel `(x, y)`, exact;
/// `None` if the centre lies on the outline.
fn winding<const S: u32>(outline: &[SubPoint<S>], x: i32, y: i32) -> Option<i32> {
    let c = (((2 * x + 1) as i128) << S, ((2 * y + 1) as i128) << S); // units of 2^-(S+1) px
    let p: Vec<(i128, i128)> = outline.iter().map(|q| (2 * q.x() as i128, 2 * q.y() as i128)).collect();
    let mut w = 0;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        let side = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        let within = a.0.min(b.0) <= c.0 && c.0 <= a.0.max(b.0) && a.1.min(b.1) <= c.1 && c.1 <= a.1.max(b.1);
        if side == 0 && within {
            return None;
        }
        if a.1 <= c.1 && b.1 > c.1 && side > 0 {
            w += 1;
        } else if a.1 > c.1 && b.1 <= c.1 && side < 0 {
            w -= 1;
        }
    }
    Some(w)
}

/// Runs every check; returns whether the whole screen was hit exactly once.
fn check_mesh<const S: u32>(mesh: &Mesh<S>, n: &mut Counts) -> bool {
    let screen = ClipRect::new(0, 0, W, H);
    let idx = |x: i32, y: i32| (y * W + x) as usize;
    let mut reference = vec![0u32; (W * H) as usize];
    for t in &mesh.tris {
        let Some(e) = ExactTriangle::new(*t) else {
            n.zero_area += 1;
            continue;
        };
        let (x0, x1, y0, y1) = e.pixel_bounds();
        for y in y0.max(0)..=y1.min(H - 1) {
            for x in x0.max(0)..=x1.min(W - 1) {
                reference[idx(x, y)] += e.covers(x, y, TieRule::TopLeft) as u32;
            }
        }
    }
    let mut all_once = false;
    let region: Vec<Option<i32>> =
        (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).map(|(x, y)| winding(&mesh.outline, x, y)).collect();
    for band_h in [1, 7, 16, H] {
        let mut hits = vec![0u32; (W * H) as usize];
        for y0 in (0..H).step_by(band_h as usize) {
            let band = screen.with_rows(y0, y0 + band_h);
            for t in &mesh.tris {
                for s in TriangleSpans::new(*t, band, Cull::None) {
                    for x in s.x..s.x + s.len as i32 {
                        assert!(band.contains(x, s.y), "S={S} {t:?}: span {s:?} outside {band:?}");
                        hits[idx(x, s.y)] += 1;
                    }
                }
            }
        }
        for (i, (&h, &r)) in hits.iter().zip(&reference).enumerate() {
            let (x, y) = (i as i32 % W, i as i32 / W);
            assert!(r <= 1, "S={S}: reference covers ({x}, {y}) {r} times: the mesh is not a tiling");
            assert_eq!(h, r, "S={S} bands of {band_h}: pixel ({x}, {y}) hit {h}×, reference {r}×");
            match region[i] {
                Some(0) => assert_eq!(h, 0, "S={S}: ({x}, {y}) outside the mesh hit {h}×"),
                Some(_) => assert_eq!(h, 1, "S={S} bands of {band_h}: ({x}, {y}) inside hit {h}×"),
                None => assert!(h <= 1),
            }
        }
        if band_h == H {
            n.inside_pixels += hits.iter().filter(|&&h| h == 1).count();
            all_once = hits.iter().all(|&h| h == 1);
            n.full_cover_meshes += all_once as usize;
        }
    }
    n.meshes += 1;
    n.triangles += mesh.tris.len();
    all_once
}

/// Reverses the winding of about half the triangles (Cull::None draws both).
fn mix_windings<const S: u32>(tris: &mut [[SubPoint<S>; 3]], rng: &mut Rng) {
    for t in tris {
        if rng.chance(0.5) {
            t.swap(1, 2);
        }
    }
}

/// An `n × n` grid of `spacing`-px quads rotated by `angle` about `(ox, oy)`.
fn grid<const S: u32>(rng: &mut Rng, angle: f64, spacing: f64, n: usize, ox: f64, oy: f64) -> Mesh<S> {
    let (sin, cos) = angle.sin_cos();
    let at = |i: f64, j: f64| {
        let (u, v) = ((i - n as f64 / 2.0) * spacing, (j - n as f64 / 2.0) * spacing);
        snap::<S>(ox + u * cos - v * sin, oy + u * sin + v * cos)
    };
    let pt: Vec<Vec<SubPoint<S>>> =
        (0..=n).map(|i| (0..=n).map(|j| at(i as f64, j as f64)).collect()).collect();
    let mut tris = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (pt[i][j], pt[i + 1][j], pt[i + 1][j + 1], pt[i][j + 1]);
            match (i + 2 * j) % 3 {
                0 => {
                    let m = at(i as f64 + 0.5, j as f64 + 0.5);
                    tris.extend([[a, b, m], [b, c, m], [c, d, m], [d, a, m]]);
                }
                1 => tris.extend([[a, b, c], [a, c, d]]),
                _ => tris.extend([[b, c, d], [b, d, a]]),
            }
        }
    }
    mix_windings(&mut tris, rng);
    let mut outline: Vec<_> = (0..n).map(|i| pt[i][0]).collect();
    outline.extend((0..n).map(|j| pt[n][j]));
    outline.extend((1..=n).rev().map(|i| pt[i][n]));
    outline.extend((1..=n).rev().map(|j| pt[0][j]));
    Mesh { tris, outline }
}

/// A fan around `(cx, cy)`: rim points on a circle (`sides == 0`) or on a regular
/// polygon, consecutive ones 0..1 px apart. Snapping may make a rim point step
/// backwards; such points are dropped so the snapped fan still tiles.
fn fan<const S: u32>(rng: &mut Rng, cx: f64, cy: f64, r: f64, sides: usize) -> Mesh<S> {
    let c = snap::<S>(cx, cy);
    let turn = rng.uniform(0.0, TAU);
    let corner = |k: usize| {
        let t = turn + TAU * k as f64 / sides as f64;
        (cx + r * t.cos(), cy + r * t.sin())
    };
    let mut rim = Vec::new();
    if sides == 0 {
        let mut t = 0.0;
        while t < TAU {
            rim.push(snap::<S>(cx + r * (turn + t).cos(), cy + r * (turn + t).sin()));
            t += 2.0 * (rng.unit() / (2.0 * r)).asin(); // chord length in [0, 1)
        }
    } else {
        for k in 0..sides {
            let (p, q) = (corner(k), corner(k + 1));
            let len = ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt();
            let mut u = 0.0;
            while u < len {
                rim.push(snap::<S>(p.0 + (q.0 - p.0) * u / len, p.1 + (q.1 - p.1) * u / len));
                u += rng.unit();
            }
        }
    }
    // Keep the rim turning one way around c (zero-area steps allowed).
    let rel = |p: SubPoint<S>| (p.x() as i64 - c.x() as i64, p.y() as i64 - c.y() as i64);
    let forward = |p: SubPoint<S>, q: SubPoint<S>| {
        let (u, v) = (rel(p), rel(q));
        u.0 * v.1 - u.1 * v.0 >= 0 && u.0 * v.0 + u.1 * v.1 > 0
    };
    let mut kept: Vec<SubPoint<S>> = Vec::new();
    for p in rim {
        if kept.last().is_none_or(|&l| forward(l, p)) {
            kept.push(p);
        }
    }
    while kept.len() > 2 && !forward(kept[kept.len() - 1], kept[0]) {
        kept.pop();
    }
    let mut tris: Vec<_> = (0..kept.len()).map(|i| [c, kept[i], kept[(i + 1) % kept.len()]]).collect();
    mix_windings(&mut tris, rng);
    Mesh { tris, outline: kept }
}

fn grids<const S: u32>(n: &mut Counts) {
    let mut rng = Rng::new(0x9e1d + S as u64);
    for k in 0..16 {
        // 16 angles over a quarter turn (the grid's symmetry), jittered except 0 and 45°.
        let jitter = if k % 8 == 0 { 0.0 } else { rng.uniform(-0.02, 0.02) };
        let angle = (k as f64 / 16.0 + jitter) * TAU / 4.0;
        let off = |rng: &mut Rng| rng.uniform(0.0, 1.0);
        // Covering the whole screen (spacing ≥ 3 px keeps the snapped grid unfolded).
        let spacing = rng.uniform(3.0, 10.0);
        let cells = (90.0 / spacing).ceil() as usize;
        let (ox, oy) = (W as f64 / 2.0 + off(&mut rng), H as f64 / 2.0 + off(&mut rng));
        let m = grid::<S>(&mut rng, angle, spacing, cells, ox, oy);
        assert!(check_mesh(&m, n), "S={S} angle {angle}: the covering grid left pixels unhit");
        // Smaller, anywhere: inside, across a screen edge or corner.
        let (ox, oy) = (rng.uniform(-10.0, W as f64 + 10.0), rng.uniform(-10.0, H as f64 + 10.0));
        let (cells, spacing) = (rng.range(1, 10) as usize, rng.uniform(3.0, 12.0));
        let m = grid::<S>(&mut rng, angle, spacing, cells, ox, oy);
        check_mesh(&m, n);
    }
}

fn fans<const S: u32>(n: &mut Counts) {
    let mut rng = Rng::new(0xfa2 + S as u64);
    for i in 0..24 {
        let (cx, cy) = (rng.uniform(-10.0, W as f64 + 10.0), rng.uniform(-10.0, H as f64 + 10.0));
        let r = rng.log_uniform(3.0, 80.0);
        let sides = [0, 3, 4, 5, 6, 8][i % 6];
        check_mesh(&fan::<S>(&mut rng, cx, cy, r, sides), n);
    }
}

macro_rules! watertight_tests {
    ($($name:ident => $s:literal),* $(,)?) => {$(
        #[test]
        fn $name() {
            let (mut g, mut f) = (Counts::default(), Counts::default());
            grids::<$s>(&mut g);
            fans::<$s>(&mut f);
            println!("watertight S={}: grids {g:?}\n                fans {f:?}", $s);
            assert_eq!((g.meshes, f.meshes), (32, 24));
            assert!(g.full_cover_meshes >= 16, "every full grid must cover the whole screen: {g:?}");
            assert!(g.triangles >= 16 * 300 && f.triangles >= 24 * 20, "{g:?} {f:?}");
            assert!(g.inside_pixels >= 16 * (W * H) as usize && f.inside_pixels >= 24 * 20, "{g:?} {f:?}");
        }
    )*};
}

watertight_tests!(
    watertight_s0 => 0, watertight_s2 => 2, watertight_s4 => 4, watertight_s6 => 6, watertight_s8 => 8,
);
