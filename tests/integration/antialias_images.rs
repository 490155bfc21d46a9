//! Anti-aliased images (`microraster::aa`): meshes tiling the screen resolve
//! to a perfectly uniform image (2D and 3D, with a hidden background triangle
//! in 3D); band heights 1, 7 and 16 give the same image; SSAA and MSAA agree
//! on flat fills; `N = 1` is the aliased renderer; MSAA shades like the
//! aliased renderer and SSAA within one step; range errors are typed.

use crate::antialias::{FH, FW, random_tri, render_aa, sample_counts};
use crate::framebuffer::Framebuffer;
use crate::reference::{Rng, random_triangle};
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565};
use embedded_graphics_core::prelude::*;
use microraster::aa::{Antialias, Msaa, MsaaSparse, Ssaa};
use microraster::aa::{Antialiased, Antialiased3d};
use microraster::depth::{Depth16, DepthBand, DepthFormat, DepthState, NoDepth};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle, ScreenVertex};
use microraster::render::Triangles3d;
use microraster::{Band, Error, Interpolate, Line, Primitive, RenderError, Renderer, SubPoint, Triangle};

const BG: Rgb565 = Rgb565::new(0, 0, 0);
const FILL: Rgb565 = Rgb565::new(10, 40, 20);

fn render_3d<
    A: Antialias,
    M: Interpolation,
    F: DepthFormat,
    const H: usize,
    const SW: usize,
    const SH: usize,
>(
    mode: A,
    tris: &[ScreenTriangle<4>],
) -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(FW as u32, FH, BG);
    let mut samples = Band::<Rgb565, SW, SH>::new(BG);
    let mut depth = DepthBand::<F, SW, SH>::new();
    let mut out = Band::<Rgb565, FW, H>::new(BG);
    Renderer::new(FH, BG)
        .render(
            Antialiased3d::new(mode, tris, &mut samples, &mut depth, DepthState::LESS_WRITE, M::default()),
            &mut out,
            &mut fb,
        )
        .unwrap();
    assert!(fb.writes.iter().all(|&w| w == 1));
    fb.pixels
}

fn color(rng: &mut Rng) -> Rgb565 {
    let m = Rgb565::CHANNEL_MAX;
    Rgb565::from_channels([0, 1, 2].map(|k| rng.below(m[k] as u64 + 1) as u8))
}

fn vertex(pos: SubPoint<4>, depth: u32, inv_w: u32, color: Rgb565) -> ScreenVertex<4> {
    ScreenVertex { pos, depth, inv_w, color: color.to_channels() }
}

/// A jittered grid of triangles covering the frame and beyond: each cell split
/// along a random diagonal, random windings.
fn grid_mesh(rng: &mut Rng) -> Vec<[SubPoint<4>; 3]> {
    let step = rng.uniform(1.3, 5.0);
    let (nx, ny) = ((FW as f64 / step) as usize + 3, (FH as f64 / step) as usize + 3);
    let jitter = step * 0.4;
    let pts: Vec<Vec<SubPoint<4>>> = (0..=ny)
        .map(|j| {
            (0..=nx)
                .map(|i| {
                    let x = (i as f64 - 1.0) * step + rng.uniform(-jitter, jitter);
                    let y = (j as f64 - 1.0) * step + rng.uniform(-jitter, jitter);
                    SubPoint::from_f32(x as f32, y as f32).unwrap()
                })
                .collect()
        })
        .collect();
    let mut tris = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (pts[j][i], pts[j][i + 1], pts[j + 1][i + 1], pts[j + 1][i]);
            let pair = if rng.chance(0.5) { [[a, b, c], [a, c, d]] } else { [[a, b, d], [b, c, d]] };
            for t in pair {
                tris.push(if rng.chance(0.5) { t } else { [t[0], t[2], t[1]] });
            }
        }
    }
    tris
}

/// A fan around a random point, rim on a circle far beyond the frame.
fn fan_mesh(rng: &mut Rng) -> Vec<[SubPoint<4>; 3]> {
    let c = SubPoint::from_f32(rng.uniform(0.0, FW as f32 as f64) as f32, rng.uniform(0.0, FH as f64) as f32)
        .unwrap();
    let k = rng.range(12, 40) as usize;
    let phase = rng.uniform(0.0, 1.0);
    let rim: Vec<SubPoint<4>> = (0..k)
        .map(|i| {
            let a = (i as f64 + phase) * std::f64::consts::TAU / k as f64;
            SubPoint::from_f32((8.0 + 40.0 * a.cos()) as f32, (6.0 + 40.0 * a.sin()) as f32).unwrap()
        })
        .collect();
    (0..k).map(|i| [c, rim[i], rim[(i + 1) % k]]).collect()
}

#[test]
fn meshes_tiling_the_screen_resolve_to_a_uniform_image() {
    let mut rng = Rng::new(21);
    let mut meshes = 0;
    for m in 0..40 {
        let mesh = if m % 2 == 0 { grid_mesh(&mut rng) } else { fan_mesh(&mut rng) };
        let flat: Vec<Primitive<Rgb565, 4>> = mesh.iter().map(|&t| Triangle::flat(t, FILL).into()).collect();
        let gouraud: Vec<Primitive<Rgb565, 4>> =
            mesh.iter().map(|&t| Triangle::gouraud(t, [FILL; 3]).into()).collect();
        let uniform = |img: Vec<Rgb565>, what: &str| {
            let bad = img.iter().position(|&c| c != FILL);
            assert!(bad.is_none(), "mesh {m} ({what}): pixel {bad:?} is {:?}", bad.map(|i| img[i]));
        };
        uniform(render_aa::<Ssaa<2>, _, 4, { FW * 2 }, 8>(Ssaa, &flat, BG), "SSAA 2 flat");
        uniform(render_aa::<Ssaa<3>, _, 7, { FW * 3 }, 21>(Ssaa, &gouraud, BG), "SSAA 3 gouraud");
        uniform(render_aa::<Msaa<4>, _, 4, { FW * 4 }, 16>(Msaa, &gouraud, BG), "MSAA 4 gouraud");
        uniform(render_aa::<Msaa<8>, _, 1, { FW * 8 }, 8>(Msaa, &flat, BG), "MSAA 8 flat");
        uniform(render_aa::<MsaaSparse<4>, _, 4, FW, 16>(MsaaSparse, &flat, BG), "sparse 4 flat");
        uniform(render_aa::<MsaaSparse<8>, _, 7, FW, 56>(MsaaSparse, &gouraud, BG), "sparse 8 gouraud");
        // 3D: the mesh on a slanted depth plane, in front of a far triangle
        // covering everything; the far one first, or last (then hidden by depth).
        let (z0, zx, zy) = (rng.uniform(0.2, 0.5), rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01));
        let z = |p: SubPoint<4>| {
            let (x, y) = p.to_f64();
            ((z0 + zx * x + zy * y) * u32::MAX as f64) as u32
        };
        let far = ScreenTriangle {
            v: [(-50, -50), (100, -50), (-50, 100)]
                .map(|(x, y)| vertex(SubPoint::from_pixels(x, y).unwrap(), u32::MAX / 10 * 9, 1 << 28, BG)),
            flat: true,
        };
        let mut tris: Vec<ScreenTriangle<4>> = mesh
            .iter()
            .map(|t| ScreenTriangle { v: t.map(|p| vertex(p, z(p), 1 << 29, FILL)), flat: m % 4 < 2 })
            .collect();
        if m % 3 == 0 {
            tris.push(far);
        } else {
            tris.insert(0, far);
        }
        uniform(
            render_3d::<Ssaa<2>, PerspectiveCorrect, Depth16, 4, { FW * 2 }, 8>(Ssaa, &tris),
            "3D SSAA 2",
        );
        uniform(render_3d::<Msaa<2>, Affine, Depth16, 7, { FW * 2 }, 14>(Msaa, &tris), "3D MSAA 2");
        uniform(
            render_3d::<Msaa<4>, PerspectiveCorrect, Depth16, 4, { FW * 4 }, 16>(Msaa, &tris),
            "3D MSAA 4",
        );
        let sparse = render_3d::<MsaaSparse<4>, PerspectiveCorrect, Depth16, 4, FW, 16>(MsaaSparse, &tris);
        uniform(sparse, "3D sparse 4");
        meshes += 1;
    }
    assert_eq!(meshes, 40);
}

fn random_scene(rng: &mut Rng, n: usize, lines: bool, gouraud: bool) -> Vec<Primitive<Rgb565, 4>> {
    (0..n)
        .map(|i| match i % 3 {
            0 if lines => Line::new(random_tri(rng)[0], random_tri(rng)[1], color(rng)).into(),
            1 if gouraud => Triangle::gouraud(random_tri(rng), [color(rng), color(rng), color(rng)]).into(),
            _ => Triangle::flat(random_tri(rng), color(rng)).into(),
        })
        .collect()
}

fn random_3d(rng: &mut Rng, n: usize, flat: bool) -> Vec<ScreenTriangle<4>> {
    (0..n)
        .map(|_| ScreenTriangle {
            v: random_tri(rng).map(|p| {
                vertex(
                    p,
                    rng.range(0, u32::MAX as i64 - 1) as u32,
                    rng.range(1 << 26, 1 << 30) as u32,
                    color(rng),
                )
            }),
            flat,
        })
        .collect()
}

#[test]
fn bands_of_1_7_16_rows_give_the_same_image() {
    let mut rng = Rng::new(31);
    for _ in 0..30 {
        let scene = random_scene(&mut rng, 12, true, true);
        let a = render_aa::<Ssaa<2>, _, 16, { FW * 2 }, 32>(Ssaa, &scene, BG);
        assert_eq!(render_aa::<Ssaa<2>, _, 1, { FW * 2 }, 2>(Ssaa, &scene, BG), a);
        assert_eq!(render_aa::<Ssaa<2>, _, 7, { FW * 2 }, 14>(Ssaa, &scene, BG), a);
        let b = render_aa::<Msaa<4>, _, 16, { FW * 4 }, 64>(Msaa, &scene, BG);
        assert_eq!(render_aa::<Msaa<4>, _, 1, { FW * 4 }, 4>(Msaa, &scene, BG), b);
        assert_eq!(render_aa::<Msaa<4>, _, 7, { FW * 4 }, 28>(Msaa, &scene, BG), b);
        let tris = random_3d(&mut rng, 10, false);
        let c = render_3d::<Msaa<2>, PerspectiveCorrect, Depth16, 16, { FW * 2 }, 32>(Msaa, &tris);
        assert_eq!(render_3d::<Msaa<2>, PerspectiveCorrect, Depth16, 1, { FW * 2 }, 2>(Msaa, &tris), c);
        assert_eq!(render_3d::<Msaa<2>, PerspectiveCorrect, Depth16, 7, { FW * 2 }, 14>(Msaa, &tris), c);
        let e = render_3d::<MsaaSparse<4>, Affine, Depth16, 16, FW, 64>(MsaaSparse, &tris);
        assert_eq!(render_3d::<MsaaSparse<4>, Affine, Depth16, 1, FW, 4>(MsaaSparse, &tris), e);
        assert_eq!(render_3d::<MsaaSparse<4>, Affine, Depth16, 7, FW, 28>(MsaaSparse, &tris), e);
        let f = render_aa::<MsaaSparse<8>, _, 16, FW, 128>(MsaaSparse, &scene, BG);
        assert_eq!(render_aa::<MsaaSparse<8>, _, 1, FW, 8>(MsaaSparse, &scene, BG), f);
        assert_eq!(render_aa::<MsaaSparse<8>, _, 7, FW, 56>(MsaaSparse, &scene, BG), f);
        let d = render_3d::<Ssaa<3>, Affine, Depth16, 16, { FW * 3 }, 48>(Ssaa, &tris);
        assert_eq!(render_3d::<Ssaa<3>, Affine, Depth16, 1, { FW * 3 }, 3>(Ssaa, &tris), d);
        assert_eq!(render_3d::<Ssaa<3>, Affine, Depth16, 7, { FW * 3 }, 21>(Ssaa, &tris), d);
    }
}

#[test]
fn ssaa_and_msaa_agree_on_flat_fills_and_n1_is_the_aliased_renderer() {
    let mut rng = Rng::new(41);
    for _ in 0..40 {
        let scene = random_scene(&mut rng, 15, true, false);
        let ssaa = render_aa::<Ssaa<4>, _, 4, { FW * 4 }, 16>(Ssaa, &scene, BG);
        assert_eq!(render_aa::<Msaa<4>, _, 4, { FW * 4 }, 16>(Msaa, &scene, BG), ssaa);
        let tris = random_3d(&mut rng, 12, true);
        let ssaa = render_3d::<Ssaa<2>, Affine, Depth16, 4, { FW * 2 }, 8>(Ssaa, &tris);
        assert_eq!(render_3d::<Msaa<2>, PerspectiveCorrect, Depth16, 4, { FW * 2 }, 8>(Msaa, &tris), ssaa);
        // N = 1: one sample at the pixel centre, exactly the aliased renderer.
        let scene = random_scene(&mut rng, 15, true, true);
        let mut fb = Framebuffer::new(FW as u32, FH, BG);
        Renderer::new(FH, BG).render(&scene[..], &mut Band::<_, FW, 4>::new(BG), &mut fb).unwrap();
        assert_eq!(render_aa::<Ssaa<1>, _, 4, FW, 4>(Ssaa, &scene, BG), fb.pixels);
        assert_eq!(render_aa::<Msaa<1>, _, 4, FW, 4>(Msaa, &scene, BG), fb.pixels);
        let tris = random_3d(&mut rng, 12, false);
        let mut fb = Framebuffer::new(FW as u32, FH, BG);
        let (mut band, mut depth) = (Band::<_, FW, 4>::new(BG), DepthBand::<Depth16, FW, 4>::new());
        Renderer::new(FH, BG)
            .render(Triangles3d::new(&tris, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
            .unwrap();
        assert_eq!(render_3d::<Ssaa<1>, Affine, Depth16, 4, FW, 4>(Ssaa, &tris), fb.pixels);
    }
}

#[test]
fn msaa_shades_like_the_aliased_renderer_and_ssaa_within_one_step() {
    let mut rng = Rng::new(51);
    let mut interior = 0;
    for _ in 0..600 {
        let v = random_tri(&mut rng);
        let cs = [color(&mut rng), color(&mut rng), color(&mut rng)];
        let scene = [Primitive::from(Triangle::gouraud(v, cs))];
        let mut fb = Framebuffer::new(FW as u32, FH, BG);
        Renderer::new(FH, BG).render(&scene, &mut Band::<_, FW, 4>::new(BG), &mut fb).unwrap();
        let msaa = render_aa::<Msaa<4>, _, 4, { FW * 4 }, 16>(Msaa, &scene, BG);
        let ssaa = render_aa::<Ssaa<4>, _, 4, { FW * 4 }, 16>(Ssaa, &scene, BG);
        let white = [Primitive::from(Triangle::flat(v, Gray8::WHITE))];
        let k = sample_counts(&render_aa::<Ssaa<4>, _, 4, { FW * 4 }, 16>(Ssaa, &white, Gray8::BLACK), 16);
        for i in (0..k.len()).filter(|&i| k[i] == 16) {
            assert_eq!(msaa[i], fb.pixels[i], "pixel {i} of {v:?}");
            let (s, a) = (ssaa[i].to_channels(), fb.pixels[i].to_channels());
            assert!((0..3).all(|c| s[c].abs_diff(a[c]) <= 1), "pixel {i}: SSAA {s:?}, aliased {a:?}");
            interior += 1;
        }
    }
    assert!(interior > 2000, "{interior}");
}

#[test]
fn range_errors_are_typed_and_extremes_do_not_panic() {
    let bg = Gray8::BLACK;
    let run = |scene: &[Primitive<Gray8, 4>], height: u32| {
        let mut fb = Framebuffer::new(FW as u32, height.clamp(1, 1024), bg);
        let mut samples = Band::<Gray8, { FW * 4 }, 16>::new(bg);
        let mut out = Band::<Gray8, FW, 4>::new(bg);
        let r = Renderer::new(height, bg).render(
            Antialiased::new(Msaa::<4>, scene, &mut samples),
            &mut out,
            &mut fb,
        );
        (r, fb)
    };
    let limit = (1 << 28) / 4; // subpixels, for N = 4
    let p = |x: i32, y: i32| SubPoint::<4>::new(x, y).unwrap();
    let huge = [p(-limit, -limit), p(limit, 0), p(0, limit)];
    let (r, fb) = run(&[Triangle::flat(huge, Gray8::WHITE).into()], FH);
    assert_eq!(r, Ok(()));
    assert!(fb.pixels.iter().all(|&c| c == Gray8::WHITE), "a triangle at the range limit covers the frame");
    let beyond = [p(-limit, -limit), p(limit + 1, -limit), p(-limit, limit)];
    let (r, fb) = run(&[Triangle::flat(beyond, Gray8::WHITE).into()], FH);
    assert_eq!(r, Err(RenderError::Input(Error::CoordinateOutOfRange)));
    assert!(fb.contiguous.is_empty(), "nothing sent before the error");
    for (height, ok) in [(0, false), (1024, true), (1025, false), (u32::MAX, false)] {
        let r = run(&[], height).0;
        assert_eq!(r.is_ok(), ok, "height {height}: {r:?}");
    }
    // The reference generator's extreme triangles (up to 2^28 subpixels):
    // accepted exactly when every coordinate times N stays in range.
    let mut rng = Rng::new(61);
    let (mut accepted, mut rejected) = (0, 0);
    for _ in 0..3000 {
        let v = random_triangle::<4>(&mut rng, FW as i32, FH as i32);
        let fits = v.iter().all(|q| q.x().abs() <= limit && q.y().abs() <= limit);
        let scene = [Triangle::flat(v, Gray8::WHITE).into(), Line::new(v[0], v[1], Gray8::new(9)).into()];
        match run(&scene, FH).0 {
            Ok(()) => accepted += 1,
            Err(e) => {
                assert_eq!(e, RenderError::Input(Error::CoordinateOutOfRange));
                rejected += 1;
            }
        }
        assert_eq!(run(&scene, FH).0.is_ok(), fits, "{v:?}");
    }
    println!("extremes: {accepted} accepted, {rejected} rejected");
    assert!(accepted > 1000 && rejected > 50);
    let _ = NoDepth;
}

#[test]
fn cull_mode_and_offset_apply_as_in_the_aliased_renderer() {
    use microraster::edge::Cull;
    let mut rng = Rng::new(81);
    for _ in 0..20 {
        let scene = random_scene(&mut rng, 15, true, true);
        for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
            let r = Renderer::new(FH, BG).with_cull(cull).with_offset(Point::new(3, 2));
            let mut fb = Framebuffer::new(FW as u32 + 3, FH + 2, FILL);
            r.render(&scene[..], &mut Band::<_, FW, 4>::new(BG), &mut fb).unwrap();
            let mut aa = Framebuffer::new(FW as u32 + 3, FH + 2, FILL);
            let (mut samples, mut out) = (Band::<_, FW, 4>::new(BG), Band::<_, FW, 4>::new(BG));
            r.render(Antialiased::new(Msaa::<1>, &scene, &mut samples), &mut out, &mut aa).unwrap();
            assert_eq!(aa.pixels, fb.pixels, "{cull:?}");
            // With N = 2 the culled windings still vanish: only one winding's triangles.
            let keep = |t: &Triangle<Rgb565, 4>| {
                let v = t.vertices().map(|p| (p.x() as i64, p.y() as i64));
                let det = (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[2].0 - v[0].0) * (v[1].1 - v[0].1);
                match cull {
                    Cull::None => true,
                    Cull::Clockwise => det < 0,
                    Cull::CounterClockwise => det > 0,
                }
            };
            let kept: Vec<Primitive<Rgb565, 4>> = scene
                .iter()
                .filter(|p| match p {
                    Primitive::Triangle(t) => keep(t),
                    Primitive::Line(_) => true,
                })
                .copied()
                .collect();
            let with_cull = {
                let mut fb = Framebuffer::new(FW as u32, FH, BG);
                let (mut s, mut o) = (Band::<_, { FW * 2 }, 8>::new(BG), Band::<_, FW, 4>::new(BG));
                Renderer::new(FH, BG)
                    .with_cull(cull)
                    .render(Antialiased::new(Ssaa::<2>, &scene, &mut s), &mut o, &mut fb)
                    .unwrap();
                fb.pixels
            };
            assert_eq!(with_cull, render_aa::<Ssaa<2>, _, 4, { FW * 2 }, 8>(Ssaa, &kept, BG), "{cull:?}");
        }
    }
}
