//! Frame, band and viewport sizes; depth codes at the near and far planes and
//! the far/near ratio.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8};
use microraster::depth::{
    Depth8, Depth16, Depth24, Depth32, DepthBand, DepthFormat, DepthState, quantize_unit,
};
use microraster::edge::Cull;
use microraster::math::{Mat4, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::{Band, ClipRect, Error, MAX_FRAME_DIM, Param, Primitive, Renderer, SubPoint, Triangle};

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
        assert_eq!(ok(n, f).err(), Some(Error::InvalidParameter(Param::NearFar)), "f32 {n}..{f}");
        assert_eq!(okx(n, f).err(), Some(Error::InvalidParameter(Param::NearFar)), "Fx {n}..{f}");
    }
    // One f32 ulp apart is still near < far: accepted, finite.
    let m = ok(1.0, 1.0 + f32::EPSILON).unwrap();
    assert!(m.to_f32().iter().flatten().all(|v| v.is_finite()));
    // Fx cannot resolve 1 + 2^-20: equal after conversion, a typed error; one
    // Fx step apart the entry saturates: also a typed error.
    assert_eq!(okx(1.0, 1.0 + 1.0 / 1048576.0).err(), Some(Error::InvalidParameter(Param::NearFar)));
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
