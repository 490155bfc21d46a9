//! Random clips and snapped triangles for the reference comparisons.

use super::Rng;
use microraster::edge::fast_path_extent_px;
use microraster::{ClipRect, SubPoint};

/// A random clip inside a `w × h` screen: often the whole screen, else bands
/// (heights 1, 7, 16 or random), random sub-rectangles or single columns.
pub fn random_clip(rng: &mut Rng, w: i32, h: i32) -> ClipRect {
    match rng.below(20) {
        0..=9 => ClipRect::new(0, 0, w, h),
        10..=15 => {
            let bh = [1, 7, 16, rng.range(1, h as i64) as i32][rng.below(4) as usize];
            let y0 = rng.range(0, (h - 1) as i64) as i32;
            ClipRect::new(0, y0, w, y0 + bh)
        }
        16..=18 => {
            let (x0, y0) = (rng.range(0, w as i64 - 1) as i32, rng.range(0, h as i64 - 1) as i32);
            let (x1, y1) =
                (rng.range(x0 as i64 + 1, w as i64) as i32, rng.range(y0 as i64 + 1, h as i64) as i32);
            ClipRect::new(x0, y0, x1, y1)
        }
        _ => {
            let x0 = rng.range(0, w as i64 - 1) as i32;
            ClipRect::new(x0, 0, x0 + 1, h)
        }
    }
}

/// Largest coordinate magnitude in subpixels.
pub const MAX_SUB: i64 = 1 << 28;

fn point<const S: u32>(x: i64, y: i64) -> SubPoint<S> {
    SubPoint::new(x.clamp(-MAX_SUB, MAX_SUB) as i32, y.clamp(-MAX_SUB, MAX_SUB) as i32).unwrap()
}

/// A random snapped triangle around a `w × h` screen. Mixes: log-uniform sizes
/// from slivers far below a pixel to far beyond the screen; vertices on pixel
/// centres, corners and half-pixel grids (so many centres lie exactly on edges);
/// axis-aligned edges; near-collinear slivers; right triangles sized around
/// `fast_path_extent_px(S)` with the screen where edge functions are largest;
/// and huge triangles whose edges still cross the screen (the `i64` path).
/// Both windings.
pub fn random_triangle<const S: u32>(rng: &mut Rng, w: i32, h: i32) -> [SubPoint<S>; 3] {
    let one = 1i64 << S;
    let (wf, hf) = (w as f64, h as f64);
    // A uniform point near the screen, in subpixels.
    let near = |rng: &mut Rng| {
        let x = rng.uniform(-0.1 * wf, 1.1 * wf);
        let y = rng.uniform(-0.1 * hf, 1.1 * hf);
        ((x * one as f64) as i64, (y * one as f64) as i64)
    };
    // A grid step: whole pixels, or half pixels when S ≥ 1 (then centres are on it).
    let step = if S >= 1 && rng.chance(0.7) { one / 2 } else { one };
    let grid = |rng: &mut Rng, k: i64| (rng.range(-k, k) * step, rng.range(-k, k) * step);
    let mut v: [(i64, i64); 3] = match rng.below(16) {
        0..=5 => {
            let size = rng.log_uniform(1.0 / 32.0, 4096.0) * one as f64;
            let (cx, cy) = near(rng);
            let mut off = || (rng.uniform(-size, size) as i64, rng.uniform(-size, size) as i64);
            [0, 1, 2].map(|_| {
                let (dx, dy) = off();
                (cx + dx, cy + dy)
            })
        }
        6..=8 => {
            // Coarse grid: many centres exactly on edges and vertices.
            let k = [2, 4, 16, 64][rng.below(4) as usize];
            let (cx, cy) = near(rng);
            let base = (cx.div_euclid(step) * step, cy.div_euclid(step) * step);
            [0, 1, 2].map(|_| {
                let (dx, dy) = grid(rng, k);
                (base.0 + dx, base.1 + dy)
            })
        }
        9 | 10 => {
            // Axis-aligned right triangle with legs on the grid.
            let (cx, cy) = near(rng);
            let a = (cx.div_euclid(step) * step, cy.div_euclid(step) * step);
            let k = [1, 3, 10, 40][rng.below(4) as usize];
            let (dx, dy) = (rng.range(-k, k) * step, rng.range(-k, k) * step);
            let mut v = [a, (a.0 + dx, a.1), (a.0, a.1 + dy)];
            v.swap(0, rng.below(3) as usize);
            v
        }
        11 => {
            // Near-collinear sliver: third vertex a few subpixels off a long edge.
            let (a, b) = (near(rng), near(rng));
            let t = rng.unit();
            let off = (rng.range(-3, 3), rng.range(-3, 3));
            let c = (
                a.0 + ((b.0 - a.0) as f64 * t) as i64 + off.0,
                a.1 + ((b.1 - a.1) as f64 * t) as i64 + off.1,
            );
            [a, b, c]
        }
        12 | 13 => {
            // Right triangle with the screen near its right angle, far from the
            // hypotenuse: the largest edge-function values for its size. Legs
            // straddle the fast-path limit, so both paths run near their maximum.
            let fast_sub = (fast_path_extent_px(S) * one) as f64;
            let (q, r) = (near(rng), rng.log_uniform(fast_sub / 4.0, fast_sub * 4.0) as i64);
            let (sx, sy) = (if rng.chance(0.5) { r } else { -r }, if rng.chance(0.5) { r } else { -r });
            [q, (q.0 + sx, q.1), (q.0, q.1 + sy)]
        }
        _ => {
            // Huge: far vertices, reflected through points near the screen so that
            // edges still cross it. Far enough for the i64 path.
            let fast_sub = (fast_path_extent_px(S) + 2) * one;
            let far = |rng: &mut Rng| {
                let r = rng.log_uniform(fast_sub as f64, MAX_SUB as f64);
                let t = rng.uniform(0.0, std::f64::consts::TAU);
                ((r * t.cos()) as i64, (r * t.sin()) as i64)
            };
            let a = far(rng);
            let q1 = near(rng);
            let b = (2 * q1.0 - a.0, 2 * q1.1 - a.1);
            let c = if rng.chance(0.5) {
                near(rng)
            } else {
                let q2 = near(rng);
                (2 * q2.0 - b.0, 2 * q2.1 - b.1)
            };
            [a, b, c]
        }
    };
    if rng.chance(0.5) {
        v.swap(1, 2); // the other winding
    }
    v.map(|(x, y)| point::<S>(x, y))
}
