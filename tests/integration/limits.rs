//! The rows of `docs/limits.md`, each tested at the limit, one subpixel (or
//! one unit) beyond it, and far beyond it. Test names match the table.
//!
//! Triangles are compared with the exact `i128` reference of `reference`;
//! lines with the exact rule of `microraster::line`, evaluated here in
//! `i128` ([`line_rule`]).

use crate::framebuffer::Framebuffer;
use crate::reference::{exact_coverage, spans_coverage};
use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8};
use fixed::FixedI32;
use fixed::types::extra::U0;
use microraster::clip3d::{ClipPlanes, guard_band_for_fast_path, guard_band_for_range};
use microraster::depth::{
    Depth8, Depth16, Depth24, Depth32, DepthBand, DepthFormat, DepthState, quantize_unit,
};
use microraster::edge::{Cull, TriangleSpans, fast_path_extent_px};
use microraster::line::line_pixels;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::{Band, ClipRect, Error, MAX_FRAME_DIM, Primitive, Renderer, SubPoint, Triangle};

/// 2^28: the largest coordinate magnitude in subpixels, for every `S`.
pub const LIM: i64 = 1 << 28;

/// The exact line rule (start inclusive, end exclusive, minor index
/// `floor` of the exact line at the major centre), in `i128`.
pub fn line_rule(a: (i32, i32), b: (i32, i32), s: u32, clip: ClipRect) -> Vec<(i32, i32)> {
    let (dx, dy) = (i128::from(b.0) - i128::from(a.0), i128::from(b.1) - i128::from(a.1));
    let x_major = dx.abs() >= dy.abs();
    let (ua, va, ub, du, dv) = if x_major { (a.0, a.1, b.0, dx, dy) } else { (a.1, a.0, b.1, dy, dx) };
    let (ua, va, ub) = (i128::from(ua), i128::from(va), i128::from(ub));
    let (c0, c1, k0, k1) = if x_major {
        (clip.x0(), clip.x1(), clip.y0(), clip.y1())
    } else {
        (clip.y0(), clip.y1(), clip.x0(), clip.x1())
    };
    let mut out = Vec::new();
    if du == 0 {
        return out;
    }
    let majors: Vec<i32> = if du > 0 { (c0..c1).collect() } else { (c0..c1).rev().collect() };
    for m in majors {
        let c = (2 * i128::from(m) + 1) << s;
        let inside = if du > 0 { 2 * ua <= c && c < 2 * ub } else { 2 * ub < c && c <= 2 * ua };
        if !inside {
            continue;
        }
        let (n, q) = (2 * va * du + dv * (c - 2 * ua), (2 * du) << s);
        let minor = if q < 0 { (-n).div_euclid(-q) } else { n.div_euclid(q) };
        if (i128::from(k0)..i128::from(k1)).contains(&minor) {
            out.push(if x_major { (m, minor as i32) } else { (minor as i32, m) });
        }
    }
    out
}

/// `TriangleSpans` against the exact reference on `clip`; returns (pixels, fast path).
pub fn exact_check<const S: u32>(v: [SubPoint<S>; 3], clip: ClipRect) -> (usize, bool) {
    let spans = TriangleSpans::new(v, clip, Cull::None);
    let fast = spans.is_fast_path();
    let got = spans_coverage(spans, clip);
    let want = exact_coverage(v, clip, Cull::None);
    if let Some((x, y, g, w)) = got.first_difference(&want) {
        let pts: Vec<_> = v.iter().map(|p| (p.x(), p.y())).collect();
        panic!("S={S} {pts:?} {clip:?}: pixel ({x}, {y}) spans={g} reference={w}");
    }
    (want.count(), fast)
}

fn sp<const S: u32>(x: i64, y: i64) -> SubPoint<S> {
    SubPoint::new(x as i32, y as i32).unwrap_or_else(|e| panic!("({x}, {y}) at S={S}: {e:?}"))
}

/// The exact fast-path threshold: the largest bounding-box side, in
/// subpixels, that takes the `i32` path (`src/raster/edge.rs`: `2·side + 2^(S+1) ≤
/// X` with `X = ⌊√((2^31 − 3)·2^S)⌋`).
pub fn fast_threshold_sub(s: u32) -> i64 {
    let limit = (i128::from(i32::MAX) - 2) << s;
    let x = (limit as f64).sqrt() as i128;
    let x = (x - 2..=x + 2).filter(|v| v * v <= limit).max().unwrap() as i64;
    x / 2 - (1 << s)
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

// ------------------------------------------------------------ frames and bands

#[test]
fn limit_frame_and_band_sizes() {
    // Renderer heights: 1 and 4096 accepted, 0 and 4097 rejected, far beyond too.
    let mut band = Box::new(Band::<BinaryColor, 1, 1>::new(BinaryColor::Off));
    let mut fb = Framebuffer::new(1, 4096, BinaryColor::Off);
    for h in [1, 4096] {
        assert!(Renderer::new(h, BinaryColor::Off).render((), &mut band, &mut fb).is_ok());
    }
    for h in [0, 4097, u32::MAX] {
        let r = Renderer::new(h, BinaryColor::Off).render((), &mut band, &mut fb);
        assert_eq!(r, Err(Error::InvalidFrameSize.into()), "height {h}");
    }
    // Pipeline viewports: 1..=4096 in each direction.
    for (w, h, ok) in [
        (1, 1, true),
        (4096, 4096, true),
        (4096, 1, true),
        (0, 5, false),
        (5, 0, false),
        (4097, 5, false),
        (5, 4097, false),
        (u32::MAX, 1, false),
    ] {
        let r = Pipeline::<f32, 4>::new(Mat4::IDENTITY, Mat4::IDENTITY, 1.0, w, h);
        assert_eq!(r.is_ok(), ok, "viewport {w}×{h}");
        if !ok {
            assert_eq!(r.err(), Some(Error::InvalidFrameSize));
        }
    }
    // Clip rectangles clamp to 0..=4096.
    let c = ClipRect::new(-1, i32::MIN, 4097, i32::MAX);
    assert_eq!((c.x0(), c.y0(), c.x1(), c.y1()), (0, 0, 4096, 4096));
    // The largest frame: a 4096-wide band of 4 rows over 4096 rows, and a
    // 1×1 frame; a triangle with its corner in the last pixel lands there.
    let p = |x: i64, y: i64| SubPoint::<4>::new((x * 16) as i32, (y * 16) as i32).unwrap();
    let tri = Primitive::from(Triangle::flat([p(4095, 4095), p(4097, 4095), p(4095, 4097)], BinaryColor::On));
    let mut fb = Framebuffer::new(4096, 4096, BinaryColor::Off);
    let mut band = Box::new(Band::<BinaryColor, 4096, 4>::new(BinaryColor::Off));
    Renderer::new(MAX_FRAME_DIM, BinaryColor::Off).render(&[tri], &mut band, &mut fb).unwrap();
    assert!(fb.writes.iter().all(|&w| w == 1));
    assert_eq!(fb.pixels.iter().filter(|c| c.is_on()).count(), 1);
    assert!(fb.pixels[4096 * 4096 - 1].is_on());
    assert_eq!(fb.contiguous.len(), 1024);
    let mut fb1 = Framebuffer::new(1, 1, BinaryColor::Off);
    let tri = Primitive::from(Triangle::flat([p(0, 0), p(2, 0), p(0, 2)], BinaryColor::On));
    Renderer::new(1, BinaryColor::Off)
        .render(&[tri], &mut Band::<BinaryColor, 1, 1>::new(BinaryColor::Off), &mut fb1)
        .unwrap();
    assert!(fb1.pixels[0].is_on());
}

// ---------------------------------------------------------------------- depth

/// A full-viewport quad at eye distance `z` through the f32 pipeline
/// (identity view), perspective `near`/`far`, drawn into a 32×24 frame with
/// depth format `F` and test `state`; returns the stored depth codes where
/// drawn (`None` where not).
fn depth_quad<F: DepthFormat>(near: f32, far: f32, z: f32, state: DepthState) -> Vec<Option<u32>> {
    const W: usize = 32;
    const H: usize = 24;
    let p = Pipeline::<f32, 4>::perspective(Mat4::IDENTITY, 1.0, near, far, W as u32, H as u32).unwrap();
    let mut p = p;
    p.shade = Shade::Flat;
    p.cull = Cull::None;
    let s = z * 2.0; // covers the frame (fov 1 rad: half-height 0.55·z)
    let pos = [[-s, -s, -z], [s, -s, -z], [s, s, -z], [-s, s, -z]];
    let mesh = Mesh::new(&pos, &[], &crate::ref3d::QUAD, bounding_sphere(&pos));
    let mut bins = heapless::Vec::<ScreenTriangle<4>, 32>::new();
    p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(200), &mut bins).unwrap();
    let mut band = Box::new(Band::<Gray8, W, H>::new(Gray8::new(0)));
    let mut depth = Box::new(DepthBand::<F, W, H>::new());
    let mut codes = vec![None; W * H];
    {
        let mut view = band.view(0, H, Gray8::new(0));
        let mut rows = depth.rows_mut(H);
        for t in &bins {
            microraster::raster3d::draw_triangle(t, &mut view, &mut rows, state, Affine);
        }
    }
    for y in 0..H {
        for x in 0..W {
            if band.rows()[y][x] == Gray8::new(200) {
                codes[y * W + x] = depth.get(y, x);
            }
        }
    }
    codes
}

fn depth_limits<F: DepthFormat>() -> usize {
    let (near, far) = (0.5f32, 20.0f32);
    let le = DepthState::LESS_EQUAL_WRITE;
    // Exactly at the near plane: code 0 everywhere.
    let at_near = depth_quad::<F>(near, far, near, le);
    assert!(at_near.iter().all(|&c| c == Some(0)), "{}: at near {at_near:?}", F::BITS);
    // Exactly at the far plane: code MAX; with LESS it loses against the
    // cleared buffer (FAR = MAX), with LESS_EQUAL it is drawn.
    let at_far = depth_quad::<F>(near, far, far, le);
    assert!(at_far.iter().all(|&c| c == Some(F::MAX)), "{}: at far", F::BITS);
    assert!(depth_quad::<F>(near, far, far, DepthState::LESS_WRITE).iter().all(Option::is_none));
    // Just inside (0.1 % of the distance): drawn; its code is MAX − 1 or MAX
    // (at 8 bits it rounds to MAX, so LESS hides it: geometry within
    // half a code step of far needs LESS_EQUAL); just outside: clipped away;
    // far beyond: nothing.
    let inside = depth_quad::<F>(near, far, far * 0.999, le);
    assert!(inside.iter().all(|c| c.is_some_and(|c| c + 2 >= F::MAX.min(1 << 20) || c > F::MAX - 4096)));
    let hidden = depth_quad::<F>(near, far, far * 0.999, DepthState::LESS_WRITE).iter().all(Option::is_none);
    assert_eq!(hidden, F::BITS == 8, "{} bits", F::BITS);
    for z in [near * 0.999, far * 1.001, far * 1.0e6, near * 1.0e-6] {
        assert!(depth_quad::<F>(near, far, z, le).iter().all(Option::is_none), "{} z={z}", F::BITS);
    }
    // The quantization endpoints themselves.
    assert_eq!(F::to_u32(quantize_unit::<F>(0)), 0);
    assert_eq!(F::to_u32(quantize_unit::<F>(1 << 32)), F::MAX);
    assert_eq!(F::to_u32(quantize_unit::<F>(u64::MAX)), F::MAX);
    inside.len()
}

#[test]
fn limit_depth_at_near_and_far() {
    let n = [
        depth_limits::<Depth8>(),
        depth_limits::<Depth16>(),
        depth_limits::<Depth24>(),
        depth_limits::<Depth32>(),
    ];
    println!("depth at near/far: pixels per format (8, 16, 24, 32 bits): {n:?}");
    assert!(n.iter().all(|&n| n == 32 * 24));
}

#[test]
fn limit_near_far_ratio() {
    // Accepted from far/near just above 1 to 10^7 and beyond; near = far,
    // far < near and near ≤ 0 are typed errors (f32 and Fx).
    use microraster::math::{Fx, Scalar};
    let ok = |n: f32, f: f32| transform::perspective(1.0f32, 1.0, n, f);
    let okx = |n: f32, f: f32| transform::perspective(Fx::ONE, Fx::ONE, Fx::from_f32(n), Fx::from_f32(f));
    for (n, f) in [(1.0, 1.0001), (0.1, 1.0e6), (1.0e-3, 1.0e4), (1.0, 1.0e7)] {
        assert!(ok(n, f).is_ok(), "f32 {n}..{f}");
    }
    for (n, f) in [(1.0, 1.0001), (0.01, 100.0), (1.0 / 16.0, 4096.0), (0.0033, 32767.0)] {
        assert!(okx(n, f).is_ok(), "Fx {n}..{f}");
    }
    for (n, f) in [(1.0, 1.0), (2.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-0.0, 5.0)] {
        assert_eq!(ok(n, f).err(), Some(Error::InvalidParameter), "f32 {n}..{f}");
        assert_eq!(okx(n, f).err(), Some(Error::InvalidParameter), "Fx {n}..{f}");
    }
    // One f32 ulp apart is still near < far: accepted, finite.
    let m = ok(1.0, 1.0 + f32::EPSILON).unwrap();
    assert!(m.to_f32().iter().flatten().all(|v| v.is_finite()));
    // Fx cannot resolve 1 + 2^-20: equal after conversion, a typed error; one
    // Fx step apart the entry saturates: also a typed error.
    assert_eq!(okx(1.0, 1.0 + 1.0 / 1048576.0).err(), Some(Error::InvalidParameter));
    assert_eq!(okx(1.0, 1.0 + 1.0 / 65536.0).err(), Some(Error::CoordinateOutOfRange));
    for v in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(ok(v, 10.0).err(), Some(Error::NonFiniteCoordinate));
        assert_eq!(ok(0.1, v).err(), Some(Error::NonFiniteCoordinate));
    }
    // Depth codes stay ordered at 10^7: two quads at 2·near and 4·near get
    // codes about 1/2 and 3/4 of the range.
    let a = depth_quad::<Depth16>(0.001, 10000.0, 0.002, DepthState::LESS_WRITE);
    let b = depth_quad::<Depth16>(0.001, 10000.0, 0.004, DepthState::LESS_WRITE);
    let (a, b) = (a[300].unwrap(), b[300].unwrap());
    println!("far/near = 1e7, Depth16: code at 2·near {a}, at 4·near {b}");
    assert!(a.abs_diff(32768) < 64 && b.abs_diff(49151) < 64 && a < b);
}

// ------------------------------------------------------------ vertex stage

/// Screen positions through the pipeline against an f64 projection of the
/// same `f32` points, inside the documented `Fx` envelope (model coordinates
/// within ±4, eye within ±256, target within ±64, fov 20°..120°, near ≥
/// 1/16, far ≤ 4096), bucketed by clip `w` as in the table of
/// `src/geometry/math/transform.rs`: the error must stay below the documented bound
/// plus half a subpixel of snapping (`S = 8`). Beyond the envelope `Fx`
/// constructors report saturation as a typed error.
#[test]
fn limit_vertex_path_error() {
    use microraster::math::{Fx, Scalar};
    /// Worst error per `w` bucket (`< 1`, `1..4`, `≥ 4`) and point counts.
    fn worst<T: Scalar>(
        eye: [f32; 3],
        target: [f32; 3],
        fov: f32,
        near: f32,
        far: f32,
    ) -> ([f64; 3], [usize; 3]) {
        let (w, h) = (320u32, 240u32);
        let f = |v: [f32; 3]| Vec3::<T>::from_f32(v);
        let view = transform::look_at(f(eye), f(target), f([0.0, 1.0, 0.0])).unwrap();
        let mut p =
            Pipeline::<T, 8>::perspective(view, T::from_f32(fov), T::from_f32(near), T::from_f32(far), w, h)
                .unwrap();
        p.cull = Cull::None;
        // Reference: f64 look_at and perspective from the same f32 inputs.
        let e = eye.map(f64::from);
        let d: Vec<f64> = (0..3).map(|i| f64::from(target[i]) - e[i]).collect();
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let fw = [d[0] / len, d[1] / len, d[2] / len];
        let sl = fw[0].hypot(fw[2]);
        let side = [-fw[2] / sl, 0.0, fw[0] / sl]; // fw × (0, 1, 0), normalised
        let up = [
            side[1] * fw[2] - side[2] * fw[1],
            side[2] * fw[0] - side[0] * fw[2],
            side[0] * fw[1] - side[1] * fw[0],
        ];
        let ty = (f64::from(fov) / 2.0).tan();
        let aspect = f64::from(w) / f64::from(h);
        let (mut worst, mut n) = ([0.0f64; 3], [0usize; 3]);
        let grid = [-4.0f32, -2.9, -1.7, -0.6, 0.0, 0.45, 1.3, 2.6, 3.5, 4.0];
        let mut points = Vec::new();
        for x in grid {
            for y in grid {
                points.extend(grid.map(|z| [x, y, z]));
            }
        }
        // And points close to the eye (w < 1), where the error is largest.
        for dist in [0.07f64, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9] {
            for u in [-0.9, -0.5, 0.0, 0.4, 0.85] {
                for v in [-0.85, -0.3, 0.2, 0.9] {
                    let q: [f64; 3] = core::array::from_fn(|i| {
                        e[i] + dist * (fw[i] + u * ty * aspect * side[i] + v * ty * up[i])
                    });
                    if q.iter().all(|c| c.abs() <= 4.0) {
                        points.push(q.map(|c| c as f32));
                    }
                }
            }
        }
        for q in points {
            {
                {
                    let [x, y, z] = q;
                    let rel: Vec<f64> = (0..3).map(|i| f64::from(q[i]) - e[i]).collect();
                    let dot = |a: [f64; 3]| rel.iter().zip(a).map(|(r, b)| r * b).sum::<f64>();
                    let (xs, ys, dist) = (dot(side), dot(up), dot(fw));
                    let (u, v) = (xs / (dist * ty * aspect), ys / (dist * ty));
                    if dist < f64::from(near) * 1.01
                        || dist > f64::from(far) * 0.99
                        || u.abs() > 0.95
                        || v.abs() > 0.95
                    {
                        continue;
                    }
                    let (sx, sy) = (f64::from(w) / 2.0 * (1.0 + u), f64::from(h) / 2.0 * (1.0 - v));
                    // A tiny triangle whose first vertex is the point.
                    let k = 0.002 * dist as f32;
                    let tri = [q, [x + k, y, z], [x, y + k, z]];
                    let mesh = Mesh::new(&tri, &[], &crate::ref3d::ONE_TRIANGLE, bounding_sphere(&tri));
                    let mut bins = heapless::Vec::<ScreenTriangle<8>, 8>::new();
                    p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(1), &mut bins).unwrap();
                    let Some(t) = bins.first() else { continue };
                    let got = (f64::from(t.v[0].pos.x()) / 256.0, f64::from(t.v[0].pos.y()) / 256.0);
                    let b = if dist < 1.0 {
                        0
                    } else if dist < 4.0 {
                        1
                    } else {
                        2
                    };
                    worst[b] = worst[b].max((got.0 - sx).abs().max((got.1 - sy).abs()));
                    n[b] += 1;
                }
            }
        }
        (worst, n)
    }
    let snap = 1.0 / 512.0;
    let (fx_bound, f32_bound) = ([0.48, 0.10, 0.15], [0.036, 0.018, 0.0045]);
    /// Eye, target, fov, near, far.
    type Camera = ([f32; 3], [f32; 3], f32, f32, f32);
    let cases: [Camera; 7] = [
        ([0.3, -0.2, 4.3], [0.0, 0.0, 0.0], 2.094, 1.0 / 16.0, 4096.0),
        ([-4.5, 0.2, 0.1], [0.0, 0.0, 0.0], 1.5, 1.0 / 16.0, 100.0),
        ([0.0, 1.0, 5.0], [0.0, 0.0, 0.0], 1.0, 1.0 / 16.0, 100.0),
        ([256.0, 200.0, -256.0], [64.0, -64.0, 64.0], 0.349, 1.0 / 16.0, 4096.0), // 20°
        ([-256.0, -256.0, 256.0], [-64.0, 64.0, -64.0], 2.094, 1.0 / 16.0, 4096.0), // 120°
        ([3.0, 2.0, 4.5], [0.0, 0.0, 0.0], 2.094, 1.0 / 16.0, 4096.0),
        ([-2.0, 0.5, 4.2], [1.0, 0.0, -1.0], 0.349, 1.0 / 16.0, 50.0),
    ];
    let mut total = [0usize; 3];
    for (eye, target, fov, near, far) in cases {
        let (ef, nf) = worst::<f32>(eye, target, fov, near, far);
        let (ex, nx) = worst::<Fx>(eye, target, fov, near, far);
        println!(
            "vertex error eye {eye:?} fov {fov}: w<1, 1..4, ≥4: f32 {ef:.4?} px {nf:?}, Fx {ex:.4?} px {nx:?}"
        );
        for b in 0..3 {
            assert!(
                ef[b] <= f32_bound[b] + snap,
                "f32 error {} px beyond {} + snapping",
                ef[b],
                f32_bound[b]
            );
            assert!(ex[b] <= fx_bound[b] + snap, "Fx error {} px beyond {} + snapping", ex[b], fx_bound[b]);
            total[b] += nf[b].min(nx[b]);
        }
    }
    println!("vertex error: points per w bucket {total:?}");
    assert!(total.iter().all(|&n| n >= 50), "points per w bucket: {total:?}");
    // Beyond the Fx envelope: saturation is reported, not hidden.
    let f = |v: [f32; 3]| Vec3::<Fx>::from_f32(v);
    assert_eq!(
        transform::look_at(f([30000.0, 0.0, 0.0]), f([-30000.0, 0.0, 0.0]), f([0.0, 1.0, 0.0])).err(),
        Some(Error::CoordinateOutOfRange)
    );
    assert_eq!(
        transform::perspective(Fx::ONE, Fx::from_bits(1), Fx::ONE, Fx::from_f32(10.0)).err(),
        Some(Error::CoordinateOutOfRange)
    );
    // f32 far beyond: inputs up to f32::MAX/16 never give NaN or inf.
    let g = |v: [f32; 3]| Vec3::<f32>::from_f32(v);
    let big = f32::MAX / 16.0;
    let results = [
        transform::look_at(g([big, 0.0, 0.0]), g([-big, 1.0, 0.0]), g([0.0, 1.0, 0.0])),
        transform::look_at(g([big, big, big]), g([0.0, 0.0, 0.0]), g([0.0, 1.0, 0.0])),
        transform::perspective(1.0, 1.0, 1.0e-30, big),
        transform::orthographic(-big, big, -big, big, -big, big),
    ];
    for m in results.into_iter().flatten() {
        assert!(m.to_f32().iter().flatten().all(|v| v.is_finite()), "{m:?}");
    }
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
