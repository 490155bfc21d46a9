//! Snapping error against an `f64` point-in-triangle test on the UNSNAPPED
//! vertices, for every `S` in `0..=8`.
//!
//! Bound: `SubPoint::from_f32` rounds each coordinate to the nearest multiple
//! of `2^-S` px, so each vertex moves by at most `d = √2·2^-(S+1)` px. Move the
//! vertices linearly from unsnapped to snapped: every point of every
//! intermediate edge is a convex combination of points within `d` of the
//! unsnapped edge segment, so a centre farther than `d` from all three unsnapped
//! segments is never on the moving boundary; its winding number (±1 inside, 0
//! outside, either orientation, degenerate triangles included) is therefore
//! constant. Such a centre is not on a snapped edge either, so the top-left rule
//! plays no part: rasterizer and float test must agree there. Every mismatch
//! must lie within `d` of an unsnapped edge (plus 1e-9 px for `f64` rounding).
//!
//! Rate: mismatches come from a band along the edges whose width is the
//! perpendicular edge displacement, linear in the vertex error `∝ 2^-S`. So the
//! expected mismatch count halves per extra bit, ≈4× per 2 bits; the test asserts
//! ≥ 2.5× per 2 bits between S = 0 and S = 6 (slack for triangles that collapse
//! at coarse S, whose error is capped by their area, and for sampling noise).

use crate::reference::{Rng, dist_to_edges, float_inside, spans_coverage};
use microraster::edge::{Cull, TriangleSpans};
use microraster::{ClipRect, SubPoint};

const W: i32 = 64;
const H: i32 = 48;
const TRIANGLES: usize = 40_000;

/// Same triangles for every `S`, so rates share the denominator.
fn float_triangles() -> Vec<[(f32, f32); 3]> {
    let mut rng = Rng::new(0xf10a7);
    (0..TRIANGLES)
        .map(|_| {
            let size = rng.log_uniform(0.25, 128.0);
            let (cx, cy) = (rng.uniform(-8.0, W as f64 + 8.0), rng.uniform(-8.0, H as f64 + 8.0));
            [0, 1, 2].map(|_| {
                let x = (cx + rng.uniform(-size, size)) as f32;
                (x, (cy + rng.uniform(-size, size)) as f32)
            })
        })
        .collect()
}

#[derive(Debug, Default, Clone)]
struct Row {
    s: u32,
    triangles: usize,
    tested: usize,
    float_covered: usize,
    mismatches: usize,
    unexplained: usize,
    first_unexplained: Option<String>,
}

impl Row {
    fn rate(&self) -> f64 {
        self.mismatches as f64 / self.float_covered as f64
    }
}

fn measure<const S: u32>(tris: &[[(f32, f32); 3]]) -> Row {
    let clip = ClipRect::new(0, 0, W, H);
    let bound = std::f64::consts::SQRT_2 * 0.5f64.powi(S as i32 + 1) + 1e-9;
    let mut row = Row { s: S, ..Row::default() };
    for t in tris {
        let v = t.map(|(x, y)| SubPoint::<S>::from_f32(x, y).unwrap());
        let vf = t.map(|(x, y)| (x as f64, y as f64));
        let cov = spans_coverage(TriangleSpans::new(v, clip, Cull::None), clip);
        // Window: the unsnapped bbox grown by a pixel holds the snapped one too.
        let lo = |i: fn(&(f64, f64)) -> f64| vf.iter().map(i).fold(f64::INFINITY, f64::min);
        let hi = |i: fn(&(f64, f64)) -> f64| vf.iter().map(i).fold(f64::NEG_INFINITY, f64::max);
        let x0 = (lo(|p| p.0).floor() as i32 - 1).max(0);
        let x1 = (hi(|p| p.0).ceil() as i32 + 1).min(W - 1);
        let y0 = (lo(|p| p.1).floor() as i32 - 1).max(0);
        let y1 = (hi(|p| p.1).ceil() as i32 + 1).min(H - 1);
        let mut in_window = 0;
        for y in y0..=y1 {
            for x in x0..=x1 {
                let c = (x as f64 + 0.5, y as f64 + 0.5);
                let (f, g) = (float_inside(vf, c.0, c.1), cov.get(x, y));
                row.tested += 1;
                row.float_covered += f as usize;
                in_window += g as usize;
                if f != g {
                    row.mismatches += 1;
                    let d = dist_to_edges(vf, c);
                    if d > bound {
                        row.unexplained += 1;
                        row.first_unexplained.get_or_insert_with(|| {
                            format!("S={S} f32 vertices {t:?} pixel ({x}, {y}) float={f} spans={g} dist={d}")
                        });
                    }
                }
            }
        }
        assert_eq!(in_window, cov.count(), "S={S} {t:?}: coverage outside the window");
        row.triangles += 1;
    }
    row
}

#[test]
fn float_mismatches_are_explained_by_snapping_and_shrink_with_s() {
    let tris = float_triangles();
    let rows = [
        measure::<0>(&tris),
        measure::<1>(&tris),
        measure::<2>(&tris),
        measure::<3>(&tris),
        measure::<4>(&tris),
        measure::<5>(&tris),
        measure::<6>(&tris),
        measure::<7>(&tris),
        measure::<8>(&tris),
    ];
    println!(
        "float reference: S | triangles | pixels tested | float-covered | mismatches | rate | rate(S-2)/rate(S)"
    );
    for r in &rows {
        let ratio = match r.s {
            0 | 1 => "-".to_string(),
            s => format!("{:.2}", rows[s as usize - 2].rate() / r.rate()),
        };
        println!(
            "  {} | {} | {} | {} | {} | {:.3e} | {}",
            r.s,
            r.triangles,
            r.tested,
            r.float_covered,
            r.mismatches,
            r.rate(),
            ratio
        );
    }
    for r in &rows {
        assert_eq!(r.triangles, TRIANGLES);
        assert!(r.float_covered >= TRIANGLES * 10, "{r:?}");
        assert_eq!(r.unexplained, 0, "{:?}", r.first_unexplained);
    }
    for s in [0, 2, 4, 6] {
        let (a, b) = (&rows[s], &rows[s + 2]);
        assert!(b.rate() < a.rate(), "rate must fall from S={s} to S={}", s + 2);
        if s + 2 <= 6 {
            let ratio = a.rate() / b.rate();
            assert!(ratio >= 2.5, "S={s}→{}: rate fell only {ratio:.2}×, theory ≈4×", s + 2);
        }
    }
}
