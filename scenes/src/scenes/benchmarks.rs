//! The 2D benchmark scenes (1, 2, 3 and 5) and the unsnapped geometry of
//! scene 1: every vertex on a pixel centre so that peer rasterizers get the
//! same input, which sets them apart from the demo scenes; with their tests.

use microraster::{Error, Interpolate, Line, SubPoint, Triangle};

use super::helpers::{Q14, XorShift, check_frame, cos64, hue, pastel, rgb, shade, sin64};
use super::{Scene, Sink};

// ---------------------------------------------------------------------------
// Benchmark scenes (issue 5): shared by the benchmarks (`benches/`), the
// report (`cargo run --release --example report`), the tests and firmware.
// ---------------------------------------------------------------------------

/// Number of triangles [`scatter`] and [`scatter_gouraud`] emit (benchmark scene 1).
pub const SCATTER_LEN: usize = 1000;
/// Number of triangles [`large`] emits (benchmark scene 2).
pub const LARGE_LEN: usize = 8;
/// Number of triangles [`tiny`] emits (benchmark scene 3).
pub const TINY_LEN: usize = 10_000;
/// Number of lines [`lines`] emits (benchmark scene 5).
pub const LINES_LEN: usize = 1000;

/// The 2D benchmark scenes with their names and primitive counts: (1)
/// [`scatter`], (2) [`large`], (3) [`tiny`], (5) [`lines`]. Scene (4) is the
/// standard 3D scene, [`crate::scenes3d`].
///
/// # How peers get the same geometry
/// Every vertex and line end point of these scenes is a **pixel centre**:
/// `SubPoint::pixel_center(x, y)` = `(x + 0.5, y + 0.5)` px, exact for every
/// `S >= 1`, with `(x, y)` = [`center_pixel`]`(p)`. So
/// * embedded-graphics gets `Point::new(x, y)` (it addresses pixels by index
///   and rasterizes through their centres);
/// * tiny-skia gets `(x + 0.5, y + 0.5)` as `f32` (exact), i.e.
///   [`SubPoint::to_f64`];
/// * the f64 reference gets the same `(x + 0.5, y + 0.5)`.
///
/// The three fill rules differ only on pixel centres lying exactly on an
/// edge (microraster: top-left rule; tiny-skia: bottom-right; e-g: its
/// scanline intersections, which include the edges), and lines differ at the
/// end point (microraster's lines are half-open, e-g's include the end
/// pixel).
pub fn benchmarks<C: Interpolate, const S: u32>() -> [(&'static str, Scene<C, S>, usize); 4] {
    [
        ("scatter", scatter, SCATTER_LEN),
        ("large", large, LARGE_LEN),
        ("tiny", tiny, TINY_LEN),
        ("lines", lines, LINES_LEN),
    ]
}

/// The pixel whose centre `p` is (rounding down for points that are not
/// centres): `(x, y)` with `p ≈ (x + 0.5, y + 0.5)` px.
pub fn center_pixel<const S: u32>(p: SubPoint<S>) -> (i32, i32) {
    (p.x() >> S, p.y() >> S)
}

/// One pixel in [`FineTriangle`] coordinates (1/65536 px units).
pub const FINE_ONE: i64 = 1 << 16;

/// A benchmark triangle before snapping: vertices in 1/65536 px
/// ([`FINE_ONE`] per pixel, inside the frame: `0 <= x < width · FINE_ONE`),
/// one 8-bit RGB colour per vertex (flat shading uses the first).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FineTriangle {
    /// Vertices in 1/65536 px.
    pub v: [(i64, i64); 3],
    /// Vertex colours, 8-bit RGB.
    pub rgb: [[u8; 3]; 3],
}

/// Scene 1's geometry before snapping ([`SCATTER_LEN`] triangles at
/// 1/65536 px): what the subpixel-precision sweep of the report snaps to `S`
/// bits and compares with an f64 rasterizer. [`scatter`] is the same scene
/// with every vertex moved to the centre of the pixel holding it.
///
/// Four size classes of 250 triangles each, in order, from large to tiny
/// (diameter 32..128, 12..32, 4..12 and 1..4 px); vertices roughly a third of
/// a turn apart round a random centre, so few are slivers. Fixed-seed
/// xorshift: the scene never changes.
pub fn scatter_fine(width: u32, height: u32, emit: &mut dyn FnMut(FineTriangle)) -> Result<(), Error> {
    check_frame(width, height, (1, 1))?;
    let (w, h) = (width as i64 * FINE_ONE, height as i64 * FINE_ONE);
    let mut rng = XorShift(0x2545_F491);
    for i in 0..SCATTER_LEN {
        let (lo, hi) = [(32, 128), (12, 32), (4, 12), (1, 4)][i * 4 / SCATTER_LEN];
        // Size in 1/256 px, then everything in 1/65536 px.
        let size = (lo * 256 + rng.below((hi - lo) * 256)) * 256;
        let (cx, cy) = (rng.below(w), rng.below(h));
        let turn = rng.below(64) as usize;
        let mut vertex = |k: usize| {
            let a = turn + k * 21 + rng.below(9) as usize;
            let r = size / 4 + rng.below(size / 4 + 1);
            let x = cx + r * cos64(a) / Q14 + rng.below(256);
            let y = cy + r * sin64(a) / Q14 + rng.below(256);
            (x.clamp(0, w - 1), y.clamp(0, h - 1))
        };
        let v = [vertex(0), vertex(1), vertex(2)];
        let mut color = || shade(hue(rng.below(1536) as u32), 90 + rng.below(166) as u32);
        emit(FineTriangle { v, rgb: [color(), color(), color()] });
    }
    Ok(())
}

/// Benchmark scene 1: [`SCATTER_LEN`] flat triangles of mixed sizes (see
/// [`scatter_fine`]), every vertex on a pixel centre.
pub fn scatter<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    scatter_shaded(width, height, false, sink)
}

/// Scene 1 with Gouraud shading: the geometry of [`scatter`], a colour per
/// vertex.
pub fn scatter_gouraud<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    scatter_shaded(width, height, true, sink)
}

fn scatter_shaded<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    gouraud: bool,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    let mut failed = None;
    scatter_fine(width, height, &mut |t| {
        let centre = |(x, y): (i64, i64)| SubPoint::<S>::pixel_center((x >> 16) as i32, (y >> 16) as i32);
        match (centre(t.v[0]), centre(t.v[1]), centre(t.v[2])) {
            (Ok(a), Ok(b), Ok(c)) => sink(if gouraud {
                Triangle::gouraud([a, b, c], t.rgb.map(rgb)).into()
            } else {
                Triangle::flat([a, b, c], rgb(t.rgb[0])).into()
            }),
            (Err(e), _, _) | (_, Err(e), _) | (_, _, Err(e)) => failed = failed.or(Some(e)),
        }
    })?;
    failed.map_or(Ok(()), Err)
}

/// Per-mille vertex positions of [`large`]'s triangles after the two that
/// cover the frame.
const LARGE_POS: [[(i64, i64); 3]; LARGE_LEN - 2] = [
    [(40, 30), (960, 150), (420, 980)],
    [(980, 920), (20, 640), (620, 20)],
    [(90, 990), (280, 10), (990, 520)],
    [(10, 400), (700, 60), (860, 990)],
    [(500, 0), (999, 999), (0, 999)],
    [(999, 0), (300, 990), (0, 200)],
];

/// Benchmark scene 2, fill-rate bound: [`LARGE_LEN`] large flat triangles,
/// two covering the whole frame (a quad through the corner pixels' centres)
/// and six overlapping ones of about a third to a half of the frame each, so
/// every pixel is written about four times. Vertices on pixel centres.
pub fn large<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    check_frame(width, height, (1, 1))?;
    let (w, h) = (width as i64 - 1, height as i64 - 1);
    let at = |x: i64, y: i64| SubPoint::<S>::pixel_center(x as i32, y as i32);
    let corners = [at(0, 0)?, at(w, 0)?, at(w, h)?, at(0, h)?];
    let mut k = 0;
    let mut color = || {
        k += 1;
        rgb::<C>(shade(hue(k * 1536 / LARGE_LEN as u32), 120 + 16 * k))
    };
    sink(Triangle::flat([corners[0], corners[1], corners[2]], color()).into());
    sink(Triangle::flat([corners[0], corners[2], corners[3]], color()).into());
    for pos in LARGE_POS {
        let p = |i: usize| at(w * pos[i].0 / 999, h * pos[i].1 / 999);
        sink(Triangle::flat([p(0)?, p(1)?, p(2)?], color()).into());
    }
    Ok(())
}

/// Benchmark scene 3, setup bound: [`TINY_LEN`] tiny flat triangles, each
/// with its vertices on pixel centres within a 4 × 4 pixel box (0 to about 4
/// pixels covered), never of zero area (frames at least 4 × 4 px).
pub fn tiny<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    check_frame(width, height, (4, 4))?;
    let mut rng = XorShift(0x6A09_E667);
    for _ in 0..TINY_LEN {
        let (x0, y0) = (rng.below(width as i64 - 3), rng.below(height as i64 - 3));
        let mut v = [(0, 0), (3, 0), (0, 3)]; // fallback: never reached in practice
        for _ in 0..16 {
            let mut p = || (rng.below(4), rng.below(4));
            let c = [p(), p(), p()];
            let area = (c[1].0 - c[0].0) * (c[2].1 - c[0].1) - (c[2].0 - c[0].0) * (c[1].1 - c[0].1);
            if area != 0 {
                v = c;
                break;
            }
        }
        let at = |(dx, dy): (i64, i64)| SubPoint::<S>::pixel_center((x0 + dx) as i32, (y0 + dy) as i32);
        let color = rgb::<C>(shade(hue(rng.below(1536) as u32), 120 + rng.below(136) as u32));
        sink(Triangle::flat([at(v[0])?, at(v[1])?, at(v[2])?], color).into());
    }
    Ok(())
}

/// Benchmark scene 5: [`LINES_LEN`] lines between pixel centres, alternately
/// long (both ends anywhere in the frame) and short (up to 32 px each way),
/// each its own light colour.
pub fn lines<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    check_frame(width, height, (1, 1))?;
    let (w, h) = (width as i64, height as i64);
    let mut rng = XorShift(0xBB67_AE85);
    for i in 0..LINES_LEN {
        let a = (rng.below(w), rng.below(h));
        let b = if i % 2 == 0 {
            (rng.below(w), rng.below(h))
        } else {
            ((a.0 + rng.below(65) - 32).clamp(0, w - 1), (a.1 + rng.below(65) - 32).clamp(0, h - 1))
        };
        let at = |(x, y): (i64, i64)| SubPoint::<S>::pixel_center(x as i32, y as i32);
        let c = rgb(pastel(hue(rng.below(1536) as u32)));
        sink(Line::new(at(a)?, at(b)?, c).into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888};
    use microraster::edge::{Cull, TriangleSpans};
    use microraster::{ClipRect, Primitive, Shading, heapless};

    /// Twice the signed area of a triangle (zero: degenerate).
    fn signed_area2(p: [(i64, i64); 3]) -> i64 {
        (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
    }

    /// Every benchmark scene: its count, every vertex on a pixel centre inside
    /// the frame, and too-small frames refused.
    fn check_benchmarks<C: Interpolate + core::fmt::Debug, const S: u32>(w: u32, h: u32) {
        let centre = |p: SubPoint<S>| {
            let (x, y) = center_pixel(p);
            p == SubPoint::pixel_center(x, y).unwrap()
                && (0..w as i32).contains(&x)
                && (0..h as i32).contains(&y)
        };
        for (name, scene, len) in benchmarks::<C, S>() {
            let mut n = 0;
            let r = scene(w, h, &mut |p: Primitive<C, S>| {
                n += 1;
                let ok = match p {
                    Primitive::Triangle(t) => t.vertices().iter().all(|&v| centre(v)),
                    Primitive::Line(l) => centre(l.start()) && centre(l.end()),
                };
                assert!(ok, "{name} {w}x{h}: {p:?}");
            });
            if name == "tiny" && (w < 4 || h < 4) {
                assert_eq!((r, n), (Err(Error::InvalidFrameSize), 0));
            } else {
                assert_eq!((r, n), (Ok(()), len), "{name} {w}x{h}");
            }
            assert_eq!(scene(0, h, &mut |_| {}), Err(Error::InvalidFrameSize));
        }
    }

    #[test]
    fn benchmark_scenes_fit_every_frame_on_pixel_centres() {
        for (w, h) in [(1, 1), (3, 200), (4, 4), (31, 17), (320, 240), (480, 320), (4096, 4096)] {
            check_benchmarks::<Rgb565, 1>(w, h);
            check_benchmarks::<Rgb888, 4>(w, h);
            check_benchmarks::<Gray8, 8>(w, h);
        }
    }

    #[test]
    fn benchmark_scenes_have_the_promised_shape() {
        let clip = ClipRect::new(0, 0, 320, 240);
        // Covered pixels (with overdraw) and triangles of zero area, per scene.
        let measure = |scene: Scene<Rgb565, 4>| {
            let (mut px, mut empty, mut gouraud) = (0u64, 0, 0);
            scene(320, 240, &mut |p| {
                if let Primitive::Triangle(t) = p {
                    let n: u64 =
                        TriangleSpans::new(t.vertices(), clip, Cull::None).map(|s| s.len as u64).sum();
                    px += n;
                    let v = t.vertices().map(|v| (v.x() as i64, v.y() as i64));
                    empty += usize::from(signed_area2(v) == 0);
                    gouraud += usize::from(matches!(t.shading(), Shading::Gouraud(_)));
                }
            })
            .unwrap();
            (px, empty, gouraud)
        };
        let frame = 320 * 240;
        let (px, _, g) = measure(scatter);
        assert!(px > 2 * frame && px < 6 * frame && g == 0, "scatter covers {px}");
        assert_eq!(measure(scatter_gouraud), (px, measure(scatter).1, SCATTER_LEN));
        let (px, empty, _) = measure(large);
        assert!(px > 3 * frame && px < 5 * frame && empty == 0, "large covers {px}");
        let (px, empty, _) = measure(tiny);
        assert!(px < 4 * TINY_LEN as u64 && empty == 0, "tiny covers {px}, {empty} empty");
        // scatter is scatter_fine moved to pixel centres.
        let mut fine = heapless::Vec::<FineTriangle, SCATTER_LEN>::new();
        scatter_fine(320, 240, &mut |t| fine.push(t).unwrap()).unwrap();
        let mut i = 0;
        scatter::<Rgb888, 8>(320, 240, &mut |p| {
            let Primitive::Triangle(t) = p else { panic!("a line in scatter") };
            let want =
                fine[i].v.map(|(x, y)| SubPoint::pixel_center((x >> 16) as i32, (y >> 16) as i32).unwrap());
            assert_eq!((t.vertices(), t.shading()), (want, Shading::Flat(rgb(fine[i].rgb[0]))));
            i += 1;
        })
        .unwrap();
        // Frozen: benchmarks and firmware depend on these scenes.
        let mut hash = 0xcbf2_9ce4_8422_2325u64;
        let mut eat = |v: i32| hash = (hash ^ v as u32 as u64).wrapping_mul(0x100_0000_01b3);
        for (_, scene, _) in benchmarks::<Rgb565, 4>() {
            scene(320, 240, &mut |p| {
                let v = match p {
                    Primitive::Triangle(t) => t.vertices(),
                    Primitive::Line(l) => [l.start(), l.end(), l.end()],
                };
                for q in v {
                    eat(q.x());
                    eat(q.y());
                }
            })
            .unwrap();
        }
        assert_eq!(hash, 0xa00d_3b63_e662_32a5, "the benchmark scenes changed: {hash:#018x}");
    }
}
