//! Interpenetrating triangles: which one wins each pixel, against the f64
//! depths at the pixel centre (`ref3d::depth_code`), through
//! `Triangles3d` (bands of 16 rows) with `LESS` and depth writes.
//!
//! Derived window (see `depth3d`): each stored code is `round(exact + e)`
//! with `|e| ≤ E = 1/8 + 2^-16`. `A` is drawn first, then `B` passes iff
//! `code_B < code_A`. Rounding is monotone, so `B` surely wins where
//! `d_B < d_A − 1 − 2E` and surely loses where `d_B > d_A + 2E` (then
//! `code_B ≥ code_A`; ties go to `A`). In between, either may win: a window of
//! `1 + 4E` codes around the intersection line, asymmetric because `LESS`
//! gives ties to the first triangle.

use crate::framebuffer::Framebuffer;
use crate::ref3d::depth_code;
use crate::reference::{Rng, exact_coverage};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthBand, DepthFormat, DepthState};
use microraster::edge::Cull;
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle, ScreenVertex};
use microraster::render::Triangles3d;
use microraster::{Band, ClipRect, Renderer, SubPoint};

const W: usize = 80;
const H: usize = 61;
const E: f64 = 0.125 + 1.0 / 65536.0;
const BG: Gray8 = Gray8::new(0);
const COL: [u8; 2] = [100, 200];

/// A point within `k` frame sizes of the frame, in 1/16 px.
fn point(rng: &mut Rng, k: f64) -> SubPoint<4> {
    let (w, h) = (W as f64 * 16.0, H as f64 * 16.0);
    let x = rng.uniform(-k * w, (1.0 + k) * w) as i32;
    let y = rng.uniform(-k * h, (1.0 + k) * h) as i32;
    SubPoint::new(x, y).unwrap()
}

fn triangle(pos: [SubPoint<4>; 3], depth: [f64; 3], color: u8, rng: &mut Rng) -> ScreenTriangle<4> {
    let v = |i: usize, rng: &mut Rng| ScreenVertex {
        pos: pos[i],
        depth: (depth[i].clamp(0.05, 0.95) * 4294967295.0) as u32,
        inv_w: rng.range(1 << 20, 1 << 30) as u32,
        color: [color, 0, 0],
    };
    ScreenTriangle { v: [v(0, rng), v(1, rng), v(2, rng)], flat: true }
}

/// A random pair: `A` with random depths; `B` with its vertices offset from
/// `A`'s depth plane (extended) by 2 codes to 0.2, not all to the same
/// side, so the planes cross inside `B`.
fn pair<F: DepthFormat>(rng: &mut Rng) -> [ScreenTriangle<4>; 2] {
    // A often covers the frame, B mostly lies on it.
    let pa = [point(rng, 1.0), point(rng, 1.0), point(rng, 1.0)];
    let da = [0, 1, 2].map(|_| rng.uniform(0.2, 0.8));
    let pb = [point(rng, 0.25), point(rng, 0.25), point(rng, 0.25)];
    let p = pa.map(|q| (q.x() as f64, q.y() as f64));
    let det = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    let plane = |q: SubPoint<4>| {
        let (x, y) = (q.x() as f64, q.y() as f64);
        let l1 = ((x - p[0].0) * (p[2].1 - p[0].1) - (y - p[0].1) * (p[2].0 - p[0].0)) / det;
        let l2 = ((p[1].0 - p[0].0) * (y - p[0].1) - (p[1].1 - p[0].1) * (x - p[0].0)) / det;
        da[0] + l1 * (da[1] - da[0]) + l2 * (da[2] - da[0])
    };
    let lsb = 1.0 / F::MAX as f64;
    let front = rng.below(3) as usize;
    let sign = if rng.chance(0.5) { 1.0 } else { -1.0 };
    let db = [0, 1, 2].map(|i| {
        let s = if i == front { sign } else { -sign };
        plane(pb[i]) + s * rng.log_uniform(2.0 * lsb, 0.2)
    });
    [triangle(pa, da, COL[0], rng), triangle(pb, db, COL[1], rng)]
}

#[derive(Default)]
struct Stats {
    pairs: usize,
    crossing: usize,
    both: usize,
    decided: usize,
    window: usize,
}

fn check_pairs<F: DepthFormat>(rng: &mut Rng, pairs: usize) -> Stats {
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let mut st = Stats::default();
    while st.pairs < pairs {
        let t = pair::<F>(rng);
        let cov = t.map(|t| exact_coverage(t.v.map(|v| v.pos), clip, Cull::None));
        if !cov[0].pixels().any(|(x, y)| cov[1].get(x, y)) {
            continue;
        }
        st.pairs += 1;
        let mut fb = Framebuffer::new(W as u32, H as u32, BG);
        let mut band = Box::new(Band::<Gray8, W, 16>::new(BG));
        let mut depth = Box::new(DepthBand::<F, W, 16>::new());
        Renderer::new(H as u32, BG)
            .render(
                Triangles3d::new(&t, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
                &mut band,
                &mut fb,
            )
            .unwrap();
        let mut winners = [false; 2];
        for y in 0..H as i32 {
            for x in 0..W as i32 {
                let got = fb.pixels[y as usize * W + x as usize].luma();
                let want = match (cov[0].get(x, y), cov[1].get(x, y)) {
                    (false, false) => Some(0),
                    (true, false) => Some(COL[0]),
                    (false, true) => Some(COL[1]),
                    (true, true) => {
                        st.both += 1;
                        let (a, b) = (
                            depth_code::<F, 4>(&t[0], x, y).unwrap(),
                            depth_code::<F, 4>(&t[1], x, y).unwrap(),
                        );
                        winners[usize::from(got == COL[1])] = true;
                        if b < a - 1.0 - 2.0 * E - 1e-6 {
                            Some(COL[1])
                        } else if b > a + 2.0 * E + 1e-6 {
                            Some(COL[0])
                        } else {
                            st.window += 1;
                            assert!(COL.contains(&got), "({x},{y}): {got} is neither triangle");
                            None
                        }
                    }
                };
                if let Some(want) = want {
                    st.decided += usize::from(cov[0].get(x, y) && cov[1].get(x, y));
                    assert_eq!(got, want, "{}-bit ({x},{y}) in {t:?}", F::BITS);
                }
            }
        }
        st.crossing += usize::from(winners[0] && winners[1]);
    }
    st
}

#[test]
fn interpenetrating_triangles_resolve_like_f64_depths() {
    let mut rng = Rng::new(0x1e7e_9e7e);
    let n = 1500;
    let runs = [
        (8, check_pairs::<Depth8>(&mut rng, n)),
        (16, check_pairs::<Depth16>(&mut rng, n)),
        (24, check_pairs::<Depth24>(&mut rng, n)),
        (32, check_pairs::<Depth32>(&mut rng, n)),
    ];
    for (bits, st) in runs {
        println!(
            "interpenetration {bits:2}-bit: {} pairs ({} with both winning somewhere), {} pixels covered by both, \
             {} decided by the reference, {} inside the {:.2}-code window",
            st.pairs,
            st.crossing,
            st.both,
            st.decided,
            st.window,
            1.0 + 4.0 * E
        );
        assert_eq!(st.pairs, n);
        assert!(st.crossing >= n / 5, "{bits}-bit: only {} pairs actually interpenetrate", st.crossing);
        assert!(st.decided >= 300_000, "{bits}-bit: only {} pixels decided", st.decided);
        assert!(st.window * 5 < st.decided, "{bits}-bit: the window dominates");
    }
}
