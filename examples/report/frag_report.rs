//! The fragment-stage options in the report: host time of each
//! configuration of `examples/fw_sweep` (the same code the Cortex-M counts
//! run, timed between its `Meter` brackets), and the accuracy of textures
//! (against f64 sampling of perspective-correct coordinates) and of
//! anti-aliased coverage (against the exact area of the triangle in each
//! pixel).

use std::hint::black_box;

use embedded_graphics_core::pixelcolor::{Gray8, GrayColor, Rgb565, Rgb888, RgbColor};
use embedded_graphics_core::prelude::{DrawTarget, OriginDimensions, Pixel, Size};
use microraster::aa::Antialiased;
use microraster::aa::{Antialias, Msaa, MsaaSparse, Ssaa};
use microraster::depth::{DepthBand, DepthState, NoDepth};
use microraster::fragment::{FragTriangle, Output, Textured, draw_fragment_triangle};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle, ScreenVertex};
use microraster::texture::{Bilinear, Filter, Nearest, Sampler, TexelFormat, Texture, UV_ONE};
use microraster::{Band, Primitive, Renderer, SubPoint, Triangle};

use crate::configs::{Config, Meter};
use crate::frame::FrameBuffer;
use crate::timing::{RUNS, thread_ns};

/// Host time of the timed part of `c`, ns (median of [`RUNS`] batches).
pub fn config_ns(c: &Config) -> f64 {
    struct Clock(f64, f64);
    impl Meter for Clock {
        fn start(&mut self) {
            self.0 = thread_ns();
        }
        fn stop(&mut self) {
            self.1 += thread_ns() - self.0;
        }
    }
    let run = || {
        let mut fb = Box::new(FrameBuffer::new());
        let mut once = |n: usize| {
            let mut clock = Clock(0.0, 0.0);
            for _ in 0..n {
                (c.run)(&mut clock, black_box(&mut fb)).expect("configuration runs");
            }
            clock.1 / n as f64
        };
        let per = once(2);
        let n = ((crate::timing::BATCH_NS / per).ceil() as usize).clamp(1, 200);
        let mut runs: Vec<f64> = (0..RUNS).map(|_| once(n)).collect();
        runs.sort_by(f64::total_cmp);
        runs[RUNS / 2]
    };
    // The configurations keep bands and primitive lists on the stack.
    std::thread::scope(|s| {
        std::thread::Builder::new().stack_size(64 << 20).spawn_scoped(s, run).unwrap().join()
    })
    .expect("timing thread")
}

/// Max and mean error of a textured, receding quad against f64 sampling of
/// exact perspective-correct texture coordinates (8-bit channel steps).
pub fn texture_error<M: Interpolation, Fi: Filter>(sampler: Sampler<Fi>) -> (f64, f64) {
    const W: usize = 128;
    let tex: &Texture<'static, Rgb565> = &crate::fragment::BRICKS;
    // A floor seen at a grazing angle: the far edge 6× farther than the near.
    let v = |x: i32, y: i32, w: f64, u: [f64; 2]| {
        let sv = ScreenVertex {
            pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
            depth: 0,
            inv_w: ((1u64 << 30) as f64 / w) as u32,
            color: [255; 3],
        };
        (sv, u.map(|c| (c * UV_ONE as f64) as i32))
    };
    let quad = [
        v(52, 8, 6.0, [0.0, 0.0]),
        v(76, 8, 6.0, [3.0, 0.0]),
        v(124, 120, 1.0, [3.0, 5.0]),
        v(4, 120, 1.0, [0.0, 5.0]),
    ];
    let tris = [[0, 3, 2], [0, 2, 1]].map(|[a, b, c]| {
        let t = [quad[a], quad[b], quad[c]];
        let mut vary = [[0; 5]; 3];
        for k in 0..3 {
            vary[k] = [t[k].1[0], t[k].1[1], 255, 255, 255];
        }
        FragTriangle { tri: ScreenTriangle { v: t.map(|x| x.0), flat: false }, varyings: vary }
    });
    let mut band = Box::new(Band::<Rgb888, W, W>::new(Rgb888::BLACK));
    let mut depth = DepthBand::<NoDepth, W, W>::new();
    let shader = Textured { texture: tex, sampler };
    {
        let mut view = band.view(0, W, Rgb888::BLACK);
        let out = Output { depth: DepthState::DISABLED, ..Output::OPAQUE };
        for t in &tris {
            draw_fragment_triangle(t, &mut view, &mut depth.rows_mut(W), &shader, out, M::default()).unwrap();
        }
    }
    let texel = |x: i64, y: i64| {
        let (w, h) = (tex.width() as i64, tex.height() as i64);
        Rgb565::expand(tex.data()[(y.rem_euclid(h) * w + x.rem_euclid(w)) as usize]).map(f64::from)
    };
    let (mut max, mut sum, mut n) = (0f64, 0f64, 0usize);
    for t in &tris {
        for y in 0..W as i32 {
            for x in 0..W as i32 {
                let Some((l, det)) = bary(t.tri.v.map(|v| v.pos), x, y) else { continue };
                if !l.iter().all(|&a| if det > 0.0 { a > 0.0 } else { a < 0.0 }) {
                    continue; // interior pixels only: edges belong to one triangle
                }
                let q: [f64; 3] = [0, 1, 2].map(|k| l[k] / det * t.tri.v[k].inv_w as f64);
                let s: f64 = q.iter().sum();
                let uv = [0, 1]
                    .map(|j| (0..3).map(|k| q[k] * t.varyings[k][j] as f64).sum::<f64>() / s / UV_ONE as f64);
                let (tx, ty) = (uv[0] * tex.width() as f64, uv[1] * tex.height() as f64);
                let want = if !Fi::BILINEAR {
                    texel(tx.floor() as i64, ty.floor() as i64)
                } else {
                    let (fx, fy) = (tx - 0.5, ty - 0.5);
                    let (x0, y0) = (fx.floor(), fy.floor());
                    let (ax, ay) = (fx - x0, fy - y0);
                    let (x0, y0) = (x0 as i64, y0 as i64);
                    let (a, b, c, d) =
                        (texel(x0, y0), texel(x0 + 1, y0), texel(x0, y0 + 1), texel(x0 + 1, y0 + 1));
                    [0, 1, 2].map(|k| {
                        (a[k] * (1.0 - ax) + b[k] * ax) * (1.0 - ay) + (c[k] * (1.0 - ax) + d[k] * ax) * ay
                    })
                };
                let got = band.rows()[y as usize][x as usize];
                let got = [got.r(), got.g(), got.b()].map(f64::from);
                for k in 0..3 {
                    let e = (got[k] - want[k]).abs();
                    max = max.max(e);
                    sum += e;
                    n += 1;
                }
            }
        }
    }
    (max, sum / n.max(1) as f64)
}

/// Barycentric sub-areas at the centre of pixel `(x, y)` and their sum.
fn bary(v: [SubPoint<4>; 3], x: i32, y: i32) -> Option<([f64; 3], f64)> {
    let p = v.map(|q| (q.x() as f64 / 16.0, q.y() as f64 / 16.0));
    let c = (x as f64 + 0.5, y as f64 + 0.5);
    let cross =
        |a: (f64, f64), b: (f64, f64), q: (f64, f64)| (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0);
    let det = cross(p[0], p[1], p[2]);
    (det != 0.0).then(|| ([cross(p[1], p[2], c), cross(p[2], p[0], c), cross(p[0], p[1], c)], det))
}

/// Area of the triangle `t` (pixels) inside the unit square at `(x, y)`.
fn area_in_pixel(t: [(f64, f64); 3], x: f64, y: f64) -> f64 {
    let mut poly: Vec<(f64, f64)> = t.to_vec();
    // Sutherland–Hodgman against the four sides.
    let sides: [(usize, f64, bool); 4] =
        [(0, x, true), (0, x + 1.0, false), (1, y, true), (1, y + 1.0, false)];
    for (axis, at, keep_above) in sides {
        let inside = |p: (f64, f64)| {
            let c = if axis == 0 { p.0 } else { p.1 };
            if keep_above { c >= at } else { c <= at }
        };
        let mut out = Vec::new();
        for i in 0..poly.len() {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            if inside(a) {
                out.push(a);
            }
            if inside(a) != inside(b) {
                let (ca, cb) = if axis == 0 { (a.0, b.0) } else { (a.1, b.1) };
                let s = (at - ca) / (cb - ca);
                out.push((a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1)));
            }
        }
        poly = out;
        if poly.is_empty() {
            return 0.0;
        }
    }
    let n = poly.len();
    (0..n).map(|i| poly[i].0 * poly[(i + 1) % n].1 - poly[(i + 1) % n].0 * poly[i].1).sum::<f64>().abs() / 2.0
}

/// Max and mean |coverage − exact area| over the pixels an edge crosses, for
/// 400 random triangles (2 to 40 px) each drawn alone white on black.
pub fn coverage_error(mode: &str) -> (f64, f64) {
    match mode {
        "aliased" => coverage::<Ssaa<1>, 48, 48>(),
        "ssaa2" => coverage::<Ssaa<2>, 96, 96>(),
        "msaa2" => coverage::<Msaa<2>, 96, 96>(),
        "sparse4" => coverage::<MsaaSparse<4>, 48, 192>(),
        "ssaa4" => coverage::<Ssaa<4>, 192, 192>(),
        _ => (f64::NAN, f64::NAN),
    }
}

fn coverage<A: Antialias, const SW: usize, const SH: usize>() -> (f64, f64) {
    const W: usize = 48;
    let mut rng = 0x2545_F491_4F6C_DD1Du64;
    let mut next = |lo: f64, hi: f64| {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        lo + (hi - lo) * (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut max, mut sum, mut n) = (0f64, 0f64, 0usize);
    for _ in 0..400 {
        let size = next(2.0, 40.0);
        let (cx, cy) = (next(4.0, 44.0), next(4.0, 44.0));
        let mut p = || {
            SubPoint::<4>::from_f32(
                cx as f32 + (next(-0.5, 0.5) * size) as f32,
                cy as f32 + (next(-0.5, 0.5) * size) as f32,
            )
            .unwrap()
        };
        let v = [p(), p(), p()];
        let prim: [Primitive<Gray8, 4>; 1] = [Triangle::flat(v, Gray8::WHITE).into()];
        let mut samples = Box::new(Band::<Gray8, SW, SH>::new(Gray8::BLACK));
        let mut out = Box::new(Band::<Gray8, W, W>::new(Gray8::BLACK));
        let mut frame = GrayFrame::<W>::default();
        Renderer::new(W as u32, Gray8::BLACK)
            .render(Antialiased::new(A::default(), &prim, &mut samples), &mut out, &mut frame)
            .unwrap();
        let t = v.map(|q| (q.x() as f64 / 16.0, q.y() as f64 / 16.0));
        for y in 0..W {
            for x in 0..W {
                let a = area_in_pixel(t, x as f64, y as f64);
                if a <= 0.0 || a >= 1.0 - 1e-12 {
                    continue; // not crossed by an edge
                }
                let e = (frame.px[y * W + x].luma() as f64 / 255.0 - a).abs();
                max = max.max(e);
                sum += e;
                n += 1;
            }
        }
    }
    (max, sum / n.max(1) as f64)
}

/// The accuracy column of each fragment-stage configuration key.
pub fn accuracy(key: &str) -> String {
    let tex =
        |(max, mean): (f64, f64)| format!("texture error vs f64: max {max:.2}, mean {mean:.3} (8-bit steps)");
    let cov = |(max, mean): (f64, f64)| format!("coverage error vs exact area: max {max:.3}, mean {mean:.4}");
    match key {
        "mesh3d/frag/texture-nearest-affine" => tex(texture_error::<Affine, Nearest>(Sampler::NEAREST_WRAP)),
        "mesh3d/frag/texture-nearest-persp" => {
            tex(texture_error::<PerspectiveCorrect, Nearest>(Sampler::NEAREST_WRAP))
        }
        "mesh3d/frag/texture-bilinear-persp" => {
            tex(texture_error::<PerspectiveCorrect, Bilinear>(Sampler::BILINEAR_WRAP))
        }
        "mesh3d/aa/ssaa2" => cov(coverage_error("ssaa2")),
        "mesh3d/aa/msaa2" => cov(coverage_error("msaa2")),
        "mesh3d/aa/sparse4" => cov(coverage_error("sparse4")),
        "mesh3d/frag/colour" => "same pixels as draw_triangle's colour, 8-bit varyings".into(),
        "mesh3d/frag/phong" => {
            "per-pixel Blinn–Phong (tests/integration/fragment.rs: within 0.75 of f64)".into()
        }
        "mesh3d/frag/translucent" => "exact blend equation (tests/integration/blend.rs)".into(),
        "lines/aa/band16/S4" => "Wu coverage (tests/integration/line_aa.rs: within 1 alpha step)".into(),
        _ => String::new(),
    }
}

/// The aliased renderer's coverage error, for comparison.
pub fn aliased_coverage() -> (f64, f64) {
    coverage_error("aliased")
}

/// A `W × W` Gray8 framebuffer.
struct GrayFrame<const W: usize> {
    px: Vec<Gray8>,
}

impl<const W: usize> Default for GrayFrame<W> {
    fn default() -> Self {
        GrayFrame { px: vec![Gray8::BLACK; W * W] }
    }
}

impl<const W: usize> OriginDimensions for GrayFrame<W> {
    fn size(&self) -> Size {
        Size::new(W as u32, W as u32)
    }
}

impl<const W: usize> DrawTarget for GrayFrame<W> {
    type Color = Gray8;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if (0..W as i32).contains(&p.x) && (0..W as i32).contains(&p.y) {
                self.px[p.y as usize * W + p.x as usize] = c;
            }
        }
        Ok(())
    }
}
