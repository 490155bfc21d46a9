//! Property tests (proptest) of the 2D rasterizer at its extremes, overflow
//! checks on: vertices at the ±2^28 range limit, huge and subpixel-tiny
//! triangles, collinear and coincident vertices, vertices and edges exactly
//! on pixel centres, half-subpixel ties in `f32` snapping, NaN and ±inf,
//! clips from 1×1 to the largest frame, bands of 1 row and full.
//!
//! Each property compares with an exact reference (`reference::exact_coverage`,
//! `limits::line_rule`, exact rounding, exact barycentrics) or checks
//! exactly-once coverage; a failure prints the shrunk input. Runs are
//! deterministic (fixed seed) and count their case kinds; `-- --nocapture`
//! prints the counts.

use crate::limits::{LIM, exact_check, fast_threshold_sub, line_rule};
use crate::reference::{Coverage, exact_coverage, spans_coverage};
use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
use microraster::blit::Blitter;
use microraster::edge::{Cull, TriangleSpans};
use microraster::line::{line_pixels, line_rows};
use microraster::{ClipRect, Error, SubPoint, Triangle};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::cell::RefCell;
use std::collections::BTreeMap;

/// A deterministic runner with `cases` cases and no persistence files.
pub fn runner(cases: u32) -> TestRunner {
    let config = Config { cases, failure_persistence: None, max_shrink_iters: 2000, ..Config::default() };
    TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
}

/// Counts of named case kinds, printed and checked at the end of a property.
#[derive(Default)]
pub struct Tally(RefCell<BTreeMap<&'static str, usize>>);

impl Tally {
    pub fn add(&self, k: &'static str) {
        *self.0.borrow_mut().entry(k).or_default() += 1;
    }
    pub fn get(&self, k: &str) -> usize {
        self.0.borrow().get(k).copied().unwrap_or(0)
    }
    pub fn report(&self, name: &str) {
        println!("{name}: {:?}", self.0.borrow());
    }
}

/// A subpixel coordinate of one of several kinds, in `±2^28`.
fn coord(s: u32) -> impl Strategy<Value = i64> {
    let one = 1i64 << s;
    prop_oneof![
        3 => (-40i64..120).prop_map(move |p| p * one + one / 2),        // pixel centres
        2 => (-40i64..120).prop_map(move |p| p * one),                  // pixel corners
        3 => -40 * one..120 * one,                                      // anywhere near the clip
        2 => (0i64..4).prop_flat_map(|d| prop_oneof![Just(LIM - d), Just(d - LIM)]), // at the limit
        1 => -LIM..=LIM,                                                // anywhere in range
        1 => (-1i64..=1).prop_map(move |k| k * (fast_threshold_sub(s) + 64 * one)), // near the fast-path extent
    ]
}

fn point(s: u32) -> impl Strategy<Value = (i64, i64)> {
    (coord(s), coord(s))
}

/// A triangle of one of several shapes: free, collinear (exactly), with
/// coincident vertices, subpixel-tiny, huge (spanning the range limits),
/// axis-aligned with edges on pixel centres.
fn triangle(s: u32) -> impl Strategy<Value = (&'static str, [(i64, i64); 3])> {
    let one = 1i64 << s;
    let clamp = |v: (i64, i64)| (v.0.clamp(-LIM, LIM), v.1.clamp(-LIM, LIM));
    prop_oneof![
        3 => [point(s), point(s), point(s)].prop_map(|v| ("free", v)),
        1 => (point(s), -64i64..64, -64i64..64, -8i64..8, -8i64..8)
            .prop_map(move |(a, dx, dy, k, m)| ("collinear", [a, clamp((a.0 + k * dx, a.1 + k * dy)), clamp((a.0 + m * dx, a.1 + m * dy))])),
        1 => (point(s), point(s)).prop_map(|(a, b)| ("coincident", [a, b, a])),
        1 => (point(s), -3i64..=3, -3i64..=3, -3i64..=3, -3i64..=3)
            .prop_map(move |(a, p, q, r, t)| ("tiny", [a, clamp((a.0 + p, a.1 + q)), clamp((a.0 + r, a.1 + t))])),
        2 => (0usize..4, -60i64..60, -60i64..60).prop_map(move |(k, x, y)| {
            // A vertex at each of three corners of the range, reflected so
            // that an edge passes near pixel (x, y) of the clip area.
            let c = [(LIM, LIM), (-LIM, LIM), (-LIM, -LIM), (LIM, -LIM)];
            let q = (x * one + one / 2, y * one);
            let b = (2 * q.0 - c[k].0, 2 * q.1 - c[k].1);
            ("huge", [c[k], clamp(b), c[(k + 1) % 4]])
        }),
        1 => (-40i64..100, -40i64..100, -30i64..30, -30i64..30).prop_map(move |(x, y, w, h)| {
            let a = (x * one + one / 2, y * one + one / 2);
            ("centres", [a, (a.0 + w * one, a.1), (a.0, a.1 + h * one)])
        }),
    ]
}

fn clip() -> impl Strategy<Value = ClipRect> {
    prop_oneof![
        3 => Just(ClipRect::new(0, 0, 80, 60)),
        1 => (0i32..80, 0i32..60).prop_map(|(x, y)| ClipRect::new(x, y, x + 1, y + 1)), // 1×1
        2 => (0i32..60).prop_map(|y| ClipRect::new(0, y, 80, y + 1)),                 // a 1-row band
        1 => (0i32..4090, 0i32..4090, 1i32..=6, 1i32..=6).prop_map(|(x, y, w, h)| ClipRect::new(x, y, x + w, y + h)),
        1 => Just(ClipRect::new(4000, 4000, 4096, 4096)),                              // the frame's far corner
    ]
}

fn sub<const S: u32>(v: [(i64, i64); 3]) -> [SubPoint<S>; 3] {
    v.map(|(x, y)| SubPoint::new(x as i32, y as i32).unwrap())
}

fn triangles_match_exact<const S: u32>(cases: u32) {
    let tally = Tally::default();
    let r = runner(cases).run(&(triangle(S), clip()), |((kind, v), clip)| {
        let v = sub::<S>(v);
        tally.add(kind);
        // Exact coverage (panics with the input on a mismatch; proptest shrinks it).
        let (n, fast) = exact_check(v, clip);
        if matches!(kind, "collinear" | "coincident") {
            prop_assert_eq!(n, 0, "zero-area triangle drew pixels");
        }
        tally.add(if n == 0 {
            "empty"
        } else if fast {
            "drawn, i32 path"
        } else {
            "drawn, i64 path"
        });
        // The band loop: drawing row by row gives the same pixels.
        let mut rows = Coverage::new(clip);
        for y in clip.y0()..clip.y1() {
            for sp in TriangleSpans::new(v, clip.with_rows(y, y + 1), Cull::None) {
                prop_assert_eq!(sp.y, y);
                for x in sp.x..sp.x + sp.len as i32 {
                    prop_assert!(!rows.set(x, y));
                }
            }
        }
        prop_assert!(rows == exact_coverage(v, clip, Cull::None), "bands of one row differ");
        Ok(())
    });
    tally.report(&format!("props: triangles vs exact, S={S}"));
    r.unwrap();
    for k in
        ["free", "collinear", "coincident", "tiny", "huge", "centres", "drawn, i32 path", "drawn, i64 path"]
    {
        assert!(tally.get(k) >= cases as usize / 40, "S={S}: too few '{k}' cases");
    }
}

#[test]
fn prop_triangles_match_exact_reference() {
    triangles_match_exact::<0>(6000);
    triangles_match_exact::<1>(3000);
    triangles_match_exact::<4>(6000);
    triangles_match_exact::<8>(6000);
}

/// Splitting a triangle at a point exactly on one edge gives two triangles
/// whose coverage is the original's, every pixel exactly once; both
/// windings, at the range limits too.
#[test]
fn prop_split_triangle_covers_exactly_once() {
    fn run<const S: u32>(cases: u32) -> usize {
        let strat = (point(S), point(S), -64i64..64, -64i64..64, 2i64..200, 1i64..200, clip(), any::<bool>());
        let (tally, total) = (Tally::default(), RefCell::new(0));
        runner(cases)
            .run(&strat, |(a, c, dx, dy, m, k, clip, flip)| {
                let k = k % m;
                let b = ((a.0 + m * dx).clamp(-LIM, LIM), (a.1 + m * dy).clamp(-LIM, LIM));
                // P = A + k·(B − A)/m exactly when B was not clamped.
                prop_assume!(b == (a.0 + m * dx, a.1 + m * dy));
                let p = (a.0 + k * dx, a.1 + k * dy);
                let (v, l, r) =
                    if flip { ([a, c, b], [a, c, p], [p, c, b]) } else { ([a, b, c], [a, p, c], [p, b, c]) };
                let whole = exact_coverage(sub::<S>(v), clip, Cull::None);
                let mut both = spans_coverage(TriangleSpans::new(sub::<S>(l), clip, Cull::None), clip);
                for sp in TriangleSpans::new(sub::<S>(r), clip, Cull::None) {
                    for x in sp.x..sp.x + sp.len as i32 {
                        prop_assert!(!both.set(x, sp.y), "pixel ({}, {}) covered by both halves", x, sp.y);
                    }
                }
                prop_assert!(both == whole, "halves differ from the whole");
                tally.add(if whole.is_empty() { "empty" } else { "drawn" });
                *total.borrow_mut() += whole.count();
                Ok(())
            })
            .unwrap();
        tally.report(&format!("props: split triangles S={S}"));
        assert!(tally.get("drawn") >= cases as usize / 10);
        total.into_inner()
    }
    let px = [run::<0>(3000), run::<4>(3000), run::<8>(3000)];
    println!("props: split triangles, pixels per S = 0, 4, 8: {px:?}");
}

/// `from_f32` on any `f32` bit pattern — NaN, ±inf, subnormals, huge values,
/// exact half-subpixel ties — equals exact rounding (ties to even) with the
/// documented errors; `x` is checked before `y`.
#[test]
fn prop_f32_snapping_is_exact_round_half_even() {
    fn expect(v: f32, s: u32) -> Result<i64, Error> {
        if !v.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        let r = (f64::from(v) * f64::from(1u32 << s)).round_ties_even();
        if r.abs() > LIM as f64 { Err(Error::CoordinateOutOfRange) } else { Ok(r as i64) }
    }
    fn run<const S: u32>() {
        let tie =
            (-(1i64 << 20)..(1i64 << 20)).prop_map(|k| ((k as f64 + 0.5) / f64::from(1u32 << S)) as f32);
        let value = prop_oneof![
            2 => any::<u32>().prop_map(f32::from_bits),
            2 => tie,
            1 => prop_oneof![Just(f32::NAN), Just(f32::INFINITY), Just(f32::NEG_INFINITY), Just(f32::MAX), Just(-0.0f32), Just(f32::MIN_POSITIVE / 4.0)],
            1 => (-2i64..=2).prop_map(|d| (LIM >> S) as f32 + d as f32 * 32.0 / f32::from(1u16 << S)),
            2 => -1.0e6f32..1.0e6,
        ];
        let tally = Tally::default();
        runner(4000)
            .run(&(value.clone(), value), |(x, y)| {
                let got = SubPoint::<S>::from_f32(x, y).map(|p| (i64::from(p.x()), i64::from(p.y())));
                let want = expect(x, S).and_then(|a| expect(y, S).map(|b| (a, b)));
                prop_assert_eq!(got, want, "from_f32({:e}, {:e})", x, y);
                let scaled = f64::from(x) * f64::from(1u32 << S);
                if scaled.is_finite() && scaled.fract().abs() == 0.5 {
                    tally.add("tie");
                }
                tally.add(match want {
                    Ok(_) => "ok",
                    Err(Error::NonFiniteCoordinate) => "non-finite",
                    Err(_) => "out of range",
                });
                Ok(())
            })
            .unwrap();
        tally.report(&format!("props: f32 snapping S={S}"));
        assert!(
            tally.get("tie") >= 500 && tally.get("non-finite") >= 100 && tally.get("out of range") >= 300
        );
    }
    run::<0>();
    run::<3>();
    run::<8>();
}

/// Lines against the exact rule: end points at the limits, on pixel
/// centres, coincident (nothing drawn); clips from 1×1 to the whole frame.
#[test]
fn prop_lines_match_exact_rule() {
    fn run<const S: u32>(cases: u32) {
        let full = Just(ClipRect::new(0, 0, 4096, 4096));
        let strat = (point(S), point(S), prop_oneof![3 => clip(), 1 => full], any::<bool>());
        let tally = Tally::default();
        runner(cases)
            .run(&strat, |(a, b, clip, same)| {
                let b = if same { a } else { b };
                let (pa, pb) = (
                    SubPoint::<S>::new(a.0 as i32, a.1 as i32).unwrap(),
                    SubPoint::<S>::new(b.0 as i32, b.1 as i32).unwrap(),
                );
                let got: Vec<_> = line_pixels(pa, pb, clip).collect();
                let want = line_rule((pa.x(), pa.y()), (pb.x(), pb.y()), S, clip);
                prop_assert_eq!(&got, &want);
                if same {
                    prop_assert!(got.is_empty() && line_rows(pa, pb).is_none());
                }
                if let Some((r0, r1)) = line_rows(pa, pb) {
                    prop_assert!(got.iter().all(|p| (r0..=r1).contains(&p.1)));
                } else {
                    prop_assert!(got.is_empty());
                }
                tally.add(if got.is_empty() { "empty" } else { "drawn" });
                Ok(())
            })
            .unwrap();
        tally.report(&format!("props: lines S={S}"));
        assert!(tally.get("drawn") >= cases as usize / 10);
    }
    run::<0>(1500);
    run::<4>(1500);
    run::<8>(1500);
}

/// Gouraud colour at every covered pixel is within 0.5 + 2^-7 of the exact
/// barycentric value (`README`), for huge and tiny triangles alike, and the
/// pixels are exactly the flat coverage.
#[test]
fn prop_gouraud_within_documented_bound() {
    struct Rec {
        clip: ClipRect,
        px: BTreeMap<(i32, i32), Rgb888>,
    }
    impl Blitter<Rgb888> for Rec {
        fn clip(&self) -> ClipRect {
            self.clip
        }
        fn set_pixel(&mut self, x: i32, y: i32, c: Rgb888) {
            assert!(self.clip.contains(x, y) && self.px.insert((x, y), c).is_none(), "({x}, {y})");
        }
    }
    fn run<const S: u32>(cases: u32) -> usize {
        let colours = [any::<(u8, u8, u8)>(), any::<(u8, u8, u8)>(), any::<(u8, u8, u8)>()];
        let worst = RefCell::new(0.0f64);
        runner(cases)
            .run(&(triangle(S), clip(), colours), |((_, v), clip, cs)| {
                let v = sub::<S>(v);
                let cs = cs.map(|(r, g, b)| Rgb888::new(r, g, b));
                let mut rec = Rec { clip, px: BTreeMap::new() };
                Triangle::gouraud(v, cs).draw(&mut rec, Cull::None);
                let want = exact_coverage(v, clip, Cull::None);
                prop_assert_eq!(rec.px.len(), want.count());
                let p = v.map(|q| (2 * i128::from(q.x()), 2 * i128::from(q.y())));
                let cr = |a: (i128, i128), b: (i128, i128), q: (i128, i128)| {
                    (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0)
                };
                for (&(x, y), c) in &rec.px {
                    prop_assert!(want.get(x, y));
                    let q = ((2 * i128::from(x) + 1) << S, (2 * i128::from(y) + 1) << S);
                    let det = cr(p[0], p[1], p[2]) as f64;
                    let l = [
                        cr(p[1], p[2], q) as f64 / det,
                        cr(p[2], p[0], q) as f64 / det,
                        cr(p[0], p[1], q) as f64 / det,
                    ];
                    let ch = |c: Rgb888| [f64::from(c.r()), f64::from(c.g()), f64::from(c.b())];
                    for k in 0..3 {
                        let exact: f64 = (0..3).map(|i| l[i] * ch(cs[i])[k]).sum();
                        let e = (ch(*c)[k] - exact).abs();
                        let w = worst.borrow().max(e);
                        *worst.borrow_mut() = w;
                        prop_assert!(
                            e <= 0.5 + 1.0 / 128.0 + 1e-9,
                            "channel {} at ({}, {}) off by {}",
                            k,
                            x,
                            y,
                            e
                        );
                    }
                }
                Ok(())
            })
            .unwrap();
        println!("props: Gouraud S={S}: worst channel error {:.4}", worst.borrow());
        cases as usize
    }
    run::<0>(2000);
    run::<4>(2000);
    run::<8>(2000);
}
