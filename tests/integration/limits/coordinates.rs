//! The coordinate range, the `i32` fast-path threshold and the guard band,
//! each at every subpixel precision `S`.

use super::{LIM, exact_check, fast_threshold_sub, line_rule};
use embedded_graphics_core::pixelcolor::Gray8;
use fixed::FixedI32;
use fixed::types::extra::U0;
use microraster::clip3d::{ClipPlanes, guard_band_for_fast_path, guard_band_for_range};
use microraster::edge::{Cull, TriangleSpans, fast_path_extent_px};
use microraster::line::line_pixels;
use microraster::math::Mat4;
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::Pipeline;
use microraster::raster3d::ScreenTriangle;
use microraster::{ClipRect, Error, SubPoint};

fn sp<const S: u32>(x: i64, y: i64) -> SubPoint<S> {
    SubPoint::new(x as i32, y as i32).unwrap_or_else(|e| panic!("({x}, {y}) at S={S}: {e:?}"))
}

// ---------------------------------------------------------------- coordinates

fn coordinate_range<const S: u32>() {
    let one = 1i64 << S;
    let px = LIM >> S; // the range in whole pixels
    // At the limit: all four signs accepted, by every constructor.
    for (x, y) in [(LIM, LIM), (-LIM, LIM), (LIM, -LIM), (-LIM, -LIM)] {
        assert!(SubPoint::<S>::new(x as i32, y as i32).is_ok());
        assert!(SubPoint::<S>::from_pixels((x >> S) as i32, (y >> S) as i32).is_ok());
        assert_eq!(
            SubPoint::<S>::from_f32(x as f32 / one as f32, y as f32 / one as f32).map(|p| p.x() as i64),
            Ok(x)
        );
        let fx = FixedI32::<U0>::from_num((x >> S) as i32);
        assert_eq!(SubPoint::<S>::from_fixed(fx, fx).map(|p| p.x() as i64), Ok(x));
    }
    // One subpixel beyond (one pixel for from_pixels): rejected, typed.
    for (x, y) in [(LIM + 1, 0), (0, LIM + 1), (-LIM - 1, 0), (0, -LIM - 1)] {
        assert_eq!(
            SubPoint::<S>::new(x as i32, y as i32),
            Err(Error::CoordinateOutOfRange),
            "S={S} ({x}, {y})"
        );
    }
    assert_eq!(SubPoint::<S>::from_pixels(px as i32 + 1, 0), Err(Error::CoordinateOutOfRange));
    assert_eq!(SubPoint::<S>::from_pixels(0, -(px as i32) - 1), Err(Error::CoordinateOutOfRange));
    let fx = FixedI32::<U0>::from_num(px as i32 + 1);
    assert_eq!(SubPoint::<S>::from_fixed(fx, FixedI32::ZERO), Err(Error::CoordinateOutOfRange));
    // f32: 2^(28−S) px is exact; the next f32 up is 32 subpixels beyond. A
    // value that rounds onto the limit is accepted; half a subpixel past the
    // limit cannot be represented at this magnitude.
    let lim_f = px as f32;
    let next = f32::from_bits(lim_f.to_bits() + 1);
    assert_eq!(((next - lim_f) * one as f32) as i64, 32, "S={S}: f32 spacing above the limit");
    assert_eq!(SubPoint::<S>::from_f32(next, 0.0), Err(Error::CoordinateOutOfRange));
    assert_eq!(SubPoint::<S>::from_f32(0.0, -next), Err(Error::CoordinateOutOfRange));
    let below = f32::from_bits(lim_f.to_bits() - 1); // 16 subpixels below
    assert_eq!(SubPoint::<S>::from_f32(below, 0.0).map(|p| p.x() as i64), Ok(LIM - 16));
    // Far beyond: every input kind gives a typed error, never a wrapped value.
    for v in [i32::MAX, i32::MIN, i32::MIN + 1, 1 << 30] {
        assert_eq!(SubPoint::<S>::new(v, 0), Err(Error::CoordinateOutOfRange));
        assert_eq!(SubPoint::<S>::from_pixels(0, v), Err(Error::CoordinateOutOfRange));
    }
    for v in [f32::MAX, f32::MIN, 1.0e30, -3.0e9, f32::MAX / 16.0] {
        assert_eq!(SubPoint::<S>::from_f32(v, 0.0), Err(Error::CoordinateOutOfRange), "{v}");
    }
    for v in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(SubPoint::<S>::from_f32(0.0, v), Err(Error::NonFiniteCoordinate));
    }
    let big = FixedI32::<U0>::MAX;
    assert_eq!(SubPoint::<S>::from_fixed(big, big), Err(Error::CoordinateOutOfRange));
}

/// Triangles with vertices exactly at ±2^28 (edges crossing a 64×48
/// screen and a clip at the far corner of the 4096 frame): exact coverage,
/// on the `i64` path; one subpixel further they cannot be built.
fn triangle_at_range_limit<const S: u32>() -> usize {
    let one = 1i64 << S;
    let mut pixels = 0;
    for clip in [ClipRect::new(0, 0, 64, 48), ClipRect::new(4032, 4048, 4096, 4096)] {
        let (cx, cy) = ((i64::from(clip.x0()) + 32) * one + one / 2, (i64::from(clip.y0()) + 24) * one);
        // Hypotenuse through (cx, cy) with slope −1, one end on the limit.
        let t = LIM - cx.max(cy);
        for (a, b, c) in [
            ((cx + t, cy - t), (cx - t, cy + t), (-LIM, -LIM)),
            ((cx - t, cy + t), (cx + t, cy - t), (-LIM, -LIM)),
            ((LIM, LIM), (-LIM, LIM), (LIM, -LIM)),
            ((-LIM, -LIM), (LIM, -LIM), (-LIM, LIM)),
            ((-LIM, -LIM), (LIM, LIM), (cx, cy)), // the diagonal through the clip
            ((LIM, -LIM), (-LIM, LIM), (LIM, LIM - 1)),
        ] {
            let v = [sp::<S>(a.0, a.1), sp(b.0, b.1), sp(c.0, c.1)];
            let (n, fast) = exact_check(v, clip);
            assert!(!fast, "S={S}: a 2^29-subpixel triangle cannot take the i32 path");
            pixels += n;
        }
        // Slivers one subpixel wide along the range diagonal.
        let v = [sp::<S>(-LIM, -LIM), sp(LIM, LIM), sp(LIM, LIM - 1)];
        pixels += exact_check(v, clip).0;
    }
    assert!(SubPoint::<S>::new(LIM as i32 + 1, 0).is_err());
    pixels
}

/// The fast path: bounding-box side exactly at the threshold (i32), one
/// subpixel more (i64), and 1000 times more (i64): exact coverage each time,
/// with the clip where the edge functions are largest (the right angle of a
/// right triangle) and at the far vertices.
fn fast_path_threshold<const S: u32>() -> usize {
    let one = 1i64 << S;
    let t = fast_threshold_sub(S);
    let e = fast_path_extent_px(S);
    assert!(e * one <= t && t < (e + 1) * one, "S={S}: documented extent {e} px vs threshold {t} subpixels");
    let mut pixels = 0;
    for (side, want_fast) in [(t, true), (t + 1, false), (t - 1, true), (1000 * t, false)] {
        let side = side.min(LIM / 2);
        let corner = (64 * one, 48 * one); // the right angle, lower right of a 64×48 clip
        for (sx, sy) in [(-1, -1), (1, -1), (-1, 1), (1, 1)] {
            let q = (corner.0 - 32 * one * (1 + sx), corner.1 - 24 * one * (1 + sy));
            let v = [sp::<S>(q.0, q.1), sp(q.0 - sx * side, q.1), sp(q.0, q.1 - sy * side)];
            for clip in [
                ClipRect::new(0, 0, 64, 48),
                ClipRect::new(0, 0, 4096, 8),
                ClipRect::new(4090, 0, 4096, 4096),
            ] {
                let (n, fast) = exact_check(v, clip);
                if n > 0 {
                    assert_eq!(fast, want_fast, "S={S} side {side} (threshold {t}) {clip:?}");
                }
                pixels += n;
            }
        }
    }
    pixels
}

/// Lines from limit to limit in every direction, with the full frame as clip.
fn line_at_range_limit<const S: u32>() -> usize {
    let full = ClipRect::new(0, 0, 4096, 4096);
    let corners =
        [(LIM, LIM), (-LIM, -LIM), (-LIM, LIM), (LIM, -LIM), (LIM, 0), (0, -LIM), (LIM, LIM - 1), (1, -LIM)];
    let mut n = 0;
    for a in corners {
        for b in corners {
            let (pa, pb) = (sp::<S>(a.0, a.1), sp::<S>(b.0, b.1));
            let got: Vec<_> = line_pixels(pa, pb, full).collect();
            assert_eq!(got, line_rule((pa.x(), pa.y()), (pb.x(), pb.y()), S, full), "S={S} {a:?} → {b:?}");
            n += got.len();
        }
    }
    n
}

macro_rules! per_s {
    ($name:ident, $f:ident, $min:expr) => {
        #[test]
        fn $name() {
            let counts = [
                $f::<0>(),
                $f::<1>(),
                $f::<2>(),
                $f::<3>(),
                $f::<4>(),
                $f::<5>(),
                $f::<6>(),
                $f::<7>(),
                $f::<8>(),
            ];
            println!("{}: pixels per S = 0..=8: {counts:?}", stringify!($name));
            assert!(counts.iter().all(|&c| c >= $min), "{counts:?}");
        }
    };
}

fn unit<const S: u32>() -> usize {
    coordinate_range::<S>();
    1
}

per_s!(limit_coordinate_range, unit, 1);
per_s!(limit_triangle_at_coordinate_limit, triangle_at_range_limit, 1000);
per_s!(limit_fast_path_threshold, fast_path_threshold, 1000);
per_s!(limit_line_at_coordinate_limit, line_at_range_limit, 4096);

#[test]
fn limit_fast_path_table() {
    // The exact thresholds of docs/limits.md (bounding-box side, subpixels).
    let t: Vec<i64> = (0..=8).map(fast_threshold_sub).collect();
    println!("fast-path threshold (subpixels) S = 0..=8: {t:?}");
    println!("fast_path_extent_px S = 0..=8: {:?}", (0..=8).map(fast_path_extent_px).collect::<Vec<_>>());
    assert_eq!(t, [23169, 32765, 46336, 65527, 92665, 131039, 185299, 262015, 370471]);
}

// ------------------------------------------------------------- guard band

/// A triangle far larger than the guard band through the pipeline at each
/// `S`: with the default guard band every binned triangle takes the i32
/// fast path; with `for_viewport` (the range limit) none is dropped.
#[test]
fn limit_guard_band() {
    fn run<const S: u32>() -> [usize; 2] {
        let (w, h) = (320u32, 240u32);
        let mut out = [0; 2];
        for (k, planes) in [ClipPlanes::for_viewport_fast_path(w, h, S), ClipPlanes::for_viewport(w, h, S)]
            .into_iter()
            .enumerate()
        {
            let mut p = Pipeline::<f32, S>::perspective(Mat4::IDENTITY, 1.0, 0.1, 100.0, w, h).unwrap();
            p.clip = planes;
            p.cull = Cull::None;
            for scale in [0.5f32, 3.0, 30.0, 1.0e3, 1.0e5, 1.0e7] {
                let tri = [[-scale, -scale, -1.0], [scale, -scale * 0.3, -1.5], [0.2, scale, -2.0]];
                let mesh = Mesh::new(&tri, &[], &crate::ref3d::ONE_TRIANGLE, bounding_sphere(&tri));
                let mut bins = heapless::Vec::<ScreenTriangle<S>, 16>::new();
                let st = p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(1), &mut bins).unwrap();
                assert_eq!(st.degenerate, 0, "S={S} scale {scale} {planes:?}: {st:?}");
                assert!(!bins.is_empty());
                for t in &bins {
                    let ext = |f: fn(SubPoint<S>) -> i32| {
                        let c = t.v.map(|v| i64::from(f(v.pos)));
                        c.iter().max().unwrap() - c.iter().min().unwrap()
                    };
                    let side = ext(SubPoint::x).max(ext(SubPoint::y));
                    if k == 0 {
                        assert!(side <= fast_threshold_sub(S), "S={S}: {side} beyond the fast path");
                    }
                    let spans = TriangleSpans::new(
                        t.v.map(|v| v.pos),
                        ClipRect::new(0, 0, w as i32, h as i32),
                        Cull::None,
                    );
                    assert!(k == 1 || spans.is_fast_path() || spans.clone().next().is_none());
                    out[k] += spans.map(|s| s.len as usize).sum::<usize>();
                }
            }
        }
        out
    }
    let n = [run::<0>(), run::<2>(), run::<4>(), run::<6>(), run::<8>()];
    println!("guard band (fast path, range): pixels per S = 0, 2, 4, 6, 8: {n:?}");
    assert!(n.iter().all(|c| c[0] == c[1] && c[0] > 100_000), "{n:?}");
    // The formulas at their limits.
    assert_eq!(guard_band_for_fast_path(8000, 1, 8), 1.0);
    assert!(guard_band_for_range(1, 1, 0) <= ClipPlanes::MAX_GUARD_BAND);
    assert_eq!(ClipPlanes::DEFAULT.with_guard_band(f32::NAN).guard_band(), 1.0);
    assert_eq!(ClipPlanes::DEFAULT.with_guard_band(1.0e30).guard_band(), ClipPlanes::MAX_GUARD_BAND);
    assert_eq!(ClipPlanes::DEFAULT.with_w_min(f32::NAN).w_min(), ClipPlanes::W_MIN);
    assert_eq!(ClipPlanes::DEFAULT.with_w_min(0.0).w_min(), 1.0 / 4294967296.0);
}
