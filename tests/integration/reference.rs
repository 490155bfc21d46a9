//! Independent reference rasterizers, coverage bitmaps, a PRNG and generators.
//!
//! Written from the specification (pixel `(X, Y)` sampled at `(X+0.5, Y+0.5)`,
//! top-left rule of D3D11.3 §3.4.2.1), not from `src/raster/edge.rs`, so agreement
//! between the two means something. Everything here is brute force: one
//! exact `i128` evaluation of each edge function per pixel centre.

use microraster::edge::{Cull, Span, fast_path_extent_px};
use microraster::{ClipRect, SubPoint};

/// SplitMix64: tiny, deterministic, good enough for test-case generation.
#[derive(Clone)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `0..n`, `n > 0`.
    pub fn below(&mut self, n: u64) -> u64 {
        ((self.next_u64() as u128 * n as u128) >> 64) as u64
    }
    /// Uniform in `lo..=hi`.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }
    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + self.unit() * (hi - lo)
    }
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    /// Log-uniform in `[lo, hi)`.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

/// A set of pixels of one clip rectangle, as a row-major bitmap.
#[derive(Clone, PartialEq, Eq)]
pub struct Coverage {
    pub clip: ClipRect,
    w: usize,
    bits: Vec<bool>,
}

impl Coverage {
    pub fn new(clip: ClipRect) -> Self {
        let w = (clip.x1() - clip.x0()).max(0) as usize;
        let h = (clip.y1() - clip.y0()).max(0) as usize;
        Coverage { clip, w, bits: vec![false; w * h] }
    }
    fn index(&self, x: i32, y: i32) -> usize {
        assert!(self.clip.contains(x, y), "pixel ({x}, {y}) outside {:?}", self.clip);
        (y - self.clip.y0()) as usize * self.w + (x - self.clip.x0()) as usize
    }
    pub fn get(&self, x: i32, y: i32) -> bool {
        self.bits[self.index(x, y)]
    }
    /// Marks a pixel; returns whether it was already marked.
    pub fn set(&mut self, x: i32, y: i32) -> bool {
        let i = self.index(x, y);
        std::mem::replace(&mut self.bits[i], true)
    }
    pub fn count(&self) -> usize {
        self.bits.iter().filter(|&&b| b).count()
    }
    pub fn is_empty(&self) -> bool {
        !self.bits.contains(&true)
    }
    /// Covered pixels, row by row.
    pub fn pixels(&self) -> impl Iterator<Item = (i32, i32)> + '_ {
        let (x0, y0, w) = (self.clip.x0(), self.clip.y0(), self.w.max(1));
        let f = move |(i, _): (usize, &bool)| (x0 + (i % w) as i32, y0 + (i / w) as i32);
        self.bits.iter().enumerate().filter(|(_, b)| **b).map(f)
    }
    /// First pixel `(x, y, self, other)` where the two differ.
    pub fn first_difference(&self, other: &Coverage) -> Option<(i32, i32, bool, bool)> {
        assert_eq!(self.clip, other.clip);
        let i = self.bits.iter().zip(&other.bits).position(|(a, b)| a != b)?;
        let (x, y) = (self.clip.x0() + (i % self.w) as i32, self.clip.y0() + (i / self.w) as i32);
        Some((x, y, self.bits[i], other.bits[i]))
    }
}

/// Collects spans into a [`Coverage`], checking the iterator contract: rows
/// strictly top to bottom (a triangle meets a row in one interval), `len ≥ 1`,
/// every pixel inside `clip`, no pixel twice.
pub fn spans_coverage(spans: impl IntoIterator<Item = Span>, clip: ClipRect) -> Coverage {
    let mut cov = Coverage::new(clip);
    let mut prev_y = i32::MIN;
    for s in spans {
        assert!(s.len >= 1, "empty span {s:?}");
        assert!(s.y > prev_y, "span {s:?} not below the previous row {prev_y}");
        prev_y = s.y;
        for x in s.x..s.x + s.len as i32 {
            assert!(clip.contains(x, s.y), "span {s:?} leaves clip {clip:?}");
            assert!(!cov.set(x, s.y), "span {s:?} overlaps an earlier span");
        }
    }
    cov
}

/// Which samples lying exactly on an edge count as covered.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum TieRule {
    /// D3D11.3: on a top or left edge.
    TopLeft,
    /// The mirror image: on a bottom or right edge (what tiny-skia does).
    BottomRight,
}

#[derive(Clone, Copy, Debug)]
struct RefEdge {
    /// The edge function `ex·cx + ey·cy + k` at `(cx, cy)`: a cross product
    /// with the edge, sign chosen so that it is positive inside.
    ex: i128,
    ey: i128,
    k: i128,
    top_left: bool,
    bottom_right: bool,
}

impl RefEdge {
    fn tie(&self, rule: TieRule) -> bool {
        match rule {
            TieRule::TopLeft => self.top_left,
            TieRule::BottomRight => self.bottom_right,
        }
    }
}

/// One non-degenerate snapped triangle, in units of `2^-(S+1)` px so that pixel
/// centres `(2X+1)·2^S` are integers for every `S`, including 0.
#[derive(Clone, Debug)]
pub struct ExactTriangle {
    edges: [RefEdge; 3],
    /// Screen-clockwise (y down): `cross(v1 − v0, v2 − v0) > 0`.
    pub clockwise: bool,
    half: i128,
    bbox: [i128; 4],
}

fn cross(u: (i128, i128), v: (i128, i128)) -> i128 {
    u.0 * v.1 - u.1 * v.0
}

impl ExactTriangle {
    /// `None` for zero area.
    pub fn new<const S: u32>(v: [SubPoint<S>; 3]) -> Option<Self> {
        let p = v.map(|q| (2 * q.x() as i128, 2 * q.y() as i128));
        let sub = |u: (i128, i128), w: (i128, i128)| (u.0 - w.0, u.1 - w.1);
        let area2 = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        if area2 == 0 {
            return None;
        }
        let edges = [0, 1, 2].map(|i| {
            let (a, b, c) = (p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
            let d = sub(b, a);
            let horizontal = d.1 == 0;
            // Horizontal: top if the third vertex is below it (y grows downwards).
            let (top, bottom) = (horizontal && c.1 > a.1, horizontal && c.1 < a.1);
            // Otherwise `dd / d.y` is how far right of the edge line the third vertex
            // lies at its own height; the edge is a left edge if that is positive.
            let dd = (c.0 - a.0) * d.1 - d.0 * (c.1 - a.1);
            let left = !horizontal && (dd > 0) == (d.1 > 0);
            let right = !horizontal && !left;
            // inside · cross(d, q − a), expanded in q.
            let inside = cross(d, sub(c, a)).signum();
            RefEdge {
                ex: -inside * d.1,
                ey: inside * d.0,
                k: inside * (d.1 * a.0 - d.0 * a.1),
                top_left: top || left,
                bottom_right: bottom || right,
            }
        });
        let xs = p.map(|q| q.0);
        let ys = p.map(|q| q.1);
        let min = |a: [i128; 3]| a[0].min(a[1]).min(a[2]);
        let max = |a: [i128; 3]| a[0].max(a[1]).max(a[2]);
        Some(ExactTriangle {
            edges,
            clockwise: area2 > 0,
            half: 1i128 << S,
            bbox: [min(xs), max(xs), min(ys), max(ys)],
        })
    }

    fn centre(&self, x: i32) -> i128 {
        (2 * x as i128 + 1) * self.half
    }

    /// Whether the centre of pixel `(x, y)` is covered.
    pub fn covers(&self, x: i32, y: i32, rule: TieRule) -> bool {
        let (cx, cy) = (self.centre(x), self.centre(y));
        self.edges.iter().all(|e| {
            let v = e.ex * cx + e.ey * cy + e.k;
            v > 0 || (v == 0 && e.tie(rule))
        })
    }

    /// A pixel rectangle `(x0, x1, y0, y1)`, inclusive, holding every pixel
    /// whose centre can be inside (padded by one pixel: it need not be tight).
    pub fn pixel_bounds(&self) -> (i32, i32, i32, i32) {
        let one = 2 * self.half; // one pixel is 2^(S+1) units
        let f = |v: i128| (v.div_euclid(one)).clamp(-(1 << 30), 1 << 30) as i32;
        let [x0, x1, y0, y1] = self.bbox;
        (f(x0) - 1, f(x1) + 1, f(y0) - 1, f(y1) + 1)
    }
}

/// True if `cull` drops a triangle of this winding (y pointing down).
pub fn culled(cull: Cull, clockwise: bool) -> bool {
    match cull {
        Cull::None => false,
        Cull::Clockwise => clockwise,
        Cull::CounterClockwise => !clockwise,
    }
}

/// Brute-force coverage of one triangle inside `clip` under `rule`, and the
/// number of pixels the tie rule decided (centre on an edge, inside the others).
pub fn coverage_and_ties<const S: u32>(
    v: [SubPoint<S>; 3],
    clip: ClipRect,
    cull: Cull,
    rule: TieRule,
) -> (Coverage, usize) {
    let (mut cov, mut ties) = (Coverage::new(clip), 0);
    let Some(t) = ExactTriangle::new(v) else { return (cov, 0) };
    if culled(cull, t.clockwise) || clip.is_empty() {
        return (cov, 0);
    }
    let (bx0, bx1, by0, by1) = t.pixel_bounds();
    let tie = t.edges.map(|e| e.tie(rule));
    for y in by0.max(clip.y0())..=by1.min(clip.y1() - 1) {
        // Same evaluation as `covers`, with the row's terms computed once.
        let cy = t.centre(y);
        let row = t.edges.map(|e| e.ey * cy + e.k);
        for x in bx0.max(clip.x0())..=bx1.min(clip.x1() - 1) {
            let cx = t.centre(x);
            let v = [0, 1, 2].map(|i| t.edges[i].ex * cx + row[i]);
            if v.iter().all(|&e| e >= 0) && v.contains(&0) {
                ties += 1;
            }
            if (0..3).all(|i| v[i] > 0 || (v[i] == 0 && tie[i])) {
                cov.set(x, y);
            }
        }
    }
    (cov, ties)
}

/// [`coverage_and_ties`] without the tie count.
pub fn coverage_with<const S: u32>(
    v: [SubPoint<S>; 3],
    clip: ClipRect,
    cull: Cull,
    rule: TieRule,
) -> Coverage {
    coverage_and_ties(v, clip, cull, rule).0
}

/// The exact reference for [`microraster::edge::TriangleSpans`].
pub fn exact_coverage<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect, cull: Cull) -> Coverage {
    coverage_with(v, clip, cull, TieRule::TopLeft)
}

/// Point-in-triangle on unsnapped `f64` vertices, either winding, boundary excluded.
pub fn float_inside(v: [(f64, f64); 3], px: f64, py: f64) -> bool {
    let e = |a: (f64, f64), b: (f64, f64)| (b.0 - a.0) * (py - a.1) - (b.1 - a.1) * (px - a.0);
    let (e0, e1, e2) = (e(v[0], v[1]), e(v[1], v[2]), e(v[2], v[0]));
    (e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0)
}

/// Euclidean distance from `p` to the segment `ab`.
pub fn dist_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Smallest distance from `p` to the three edges of `v`.
pub fn dist_to_edges(v: [(f64, f64); 3], p: (f64, f64)) -> f64 {
    (0..3).map(|i| dist_to_segment(p, v[i], v[(i + 1) % 3])).fold(f64::INFINITY, f64::min)
}

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
