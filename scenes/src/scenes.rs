//! The standard demo scenes, shared by examples, tests, benchmarks and firmware.
//!
//! A scene is a function that emits its [`Primitive`]s for a `width × height`
//! frame into a caller-supplied sink closure, so it needs no allocation: the
//! caller collects into a [`heapless::Vec`] (see [`collect`]), counts, or draws
//! directly. Each scene emits a fixed number of primitives whatever the frame
//! size, given by its `*_LEN` constant; all vertices lie inside the frame.
//!
//! Scenes are deterministic (integer geometry, a fixed-seed xorshift), so the
//! rendered frame is bit-identical on every platform and can be checked by CRC.
//! Colours are given as 8-bit RGB and scaled to each type's channel depth;
//! single-channel types (grey, [`BinaryColor`](embedded_graphics_core::pixelcolor::BinaryColor))
//! get the luma, so on a black background the light colours stay visible.
//!
//! Scenes need at least one subpixel bit (`S >= 1`, a compile error otherwise):
//! they place vertices exactly on pixel centres.
//!
//! ```
//! use embedded_graphics_core::pixelcolor::Rgb565;
//! use microraster::{Primitive, heapless};
//! use microraster_scenes::scenes;
//! let mut scene = heapless::Vec::<Primitive<Rgb565, 4>, { scenes::MIXED_LEN }>::new();
//! let dropped = scenes::collect(scenes::mixed, 320, 240, &mut scene)?;
//! assert_eq!((dropped, scene.len()), (0, scenes::MIXED_LEN));
//! # Ok::<(), microraster::Error>(())
//! ```

use microraster::heapless;
use microraster::{Error, Interpolate, Line, MAX_FRAME_DIM, Primitive, SubPoint, Triangle};

/// Where a scene puts its primitives.
pub type Sink<'a, C, const S: u32> = &'a mut dyn FnMut(Primitive<C, S>);

/// A scene function: `(width, height, sink)`.
///
/// Errors: [`Error::InvalidFrameSize`] if a side is 0, above
/// [`MAX_FRAME_DIM`], or smaller than the scene needs.
pub type Scene<C, const S: u32> = fn(u32, u32, Sink<'_, C, S>) -> Result<(), Error>;

/// Every scene with its name and primitive count, in a fixed order.
pub fn all<C: Interpolate, const S: u32>() -> [(&'static str, Scene<C, S>, usize); 4] {
    [
        ("fill_rule", fill_rule, FILL_RULE_LEN),
        ("gouraud", gouraud, GOURAUD_LEN),
        ("line_fan", line_fan, LINE_FAN_LEN),
        ("mixed", mixed, MIXED_LEN),
    ]
}

/// Runs `scene` and pushes its primitives into `out`, returning how many did
/// not fit (0 when `out` had room for all of them).
pub fn collect<C: Interpolate, const S: u32, const N: usize>(
    scene: Scene<C, S>,
    width: u32,
    height: u32,
    out: &mut heapless::Vec<Primitive<C, S>, N>,
) -> Result<usize, Error> {
    let mut dropped = 0;
    scene(width, height, &mut |p| dropped += usize::from(out.push(p).is_err()))?;
    Ok(dropped)
}

/// Number of primitives [`fill_rule`] emits.
pub const FILL_RULE_LEN: usize = FAN_RING.len() + 2 + 2 * (STRIP_COLS - 1);
/// Smallest frame `(width, height)` [`fill_rule`] accepts.
pub const FILL_RULE_SIZE: (u32, u32) = (28, 14);

/// A fill-rule close-up, 28 × 14 pixels, centred in the frame at a whole-pixel
/// offset (so exact ties stay exact). Three meshes whose triangles share
/// edges exactly, each triangle its own colour (alternately light and dark):
///
/// * a fan of 16 triangles around a vertex exactly on a pixel centre, whose
///   spokes (horizontal, vertical, slopes 1 and ½ and 2) and outer square all
///   run exactly through pixel centres: every one of those ties must go to
///   exactly one triangle;
/// * a convex quad with arbitrary subpixel vertices, split along a diagonal;
/// * a strip of 4 triangles between two rows of pixel-centre vertices, with
///   slope-2 edges through pixel centres.
///
/// Under the top-left rule each mesh covers every pixel of its outline once.
pub fn fill_rule<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    check_frame(width, height, FILL_RULE_SIZE)?;
    let (ox, oy) = ((width - FILL_RULE_SIZE.0) / 2, (height - FILL_RULE_SIZE.1) / 2);
    let mut k = 0;
    for_fill_rule_mesh::<S>(ox as i64 * 16, oy as i64 * 16, &mut |v| {
        // Alternate light and dark so neighbours differ, also in 1-bit colour.
        let [r, g, b] = hue(k * 1536 / FILL_RULE_LEN as u32 + (k % 2) * 768);
        let c = if k % 2 == 0 { pastel([r, g, b]) } else { shade([r, g, b], 110) };
        k += 1;
        sink(Triangle::flat(v, rgb(c)).into());
    })
}

// Fill-rule geometry, in 1/16 px. Pixel centres are `16·n + 8`.
const FAN_CENTER: (i64, i64) = (7 * 16 + 8, 7 * 16 + 8);
/// The fan's rim, clockwise on screen, in whole pixels from its centre.
#[rustfmt::skip]
const FAN_RING: [(i64, i64); 16] = [
    (6, 0), (6, 3), (6, 6), (3, 6), (0, 6), (-3, 6), (-6, 6), (-6, 3),
    (-6, 0), (-6, -3), (-6, -6), (-3, -6), (0, -6), (3, -6), (6, -6), (6, -3),
];
const QUAD: [(i64, i64); 4] = [(245, 14), (438, 37), (394, 122), (259, 98)];
const STRIP_COLS: usize = 3;
const STRIP_TOP: (i64, i64) = (16 * 16 + 8, 8 * 16 + 8);
const STRIP_BOTTOM: (i64, i64) = (18 * 16 + 8, 12 * 16 + 8);
const STRIP_STEP: i64 = 4 * 16;

/// Emits the fill-rule mesh's triangles offset by `(ox, oy)` (1/16 px).
fn for_fill_rule_mesh<const S: u32>(
    ox: i64,
    oy: i64,
    emit: &mut dyn FnMut([SubPoint<S>; 3]),
) -> Result<(), Error> {
    let p = |(x, y): (i64, i64)| at16::<S>(ox + x, oy + y);
    let c = p(FAN_CENTER)?;
    let ring = |i: usize| {
        let (dx, dy) = FAN_RING[i % FAN_RING.len()];
        p((FAN_CENTER.0 + 16 * dx, FAN_CENTER.1 + 16 * dy))
    };
    for i in 0..FAN_RING.len() {
        emit([c, ring(i)?, ring(i + 1)?]);
    }
    let q = [p(QUAD[0])?, p(QUAD[1])?, p(QUAD[2])?, p(QUAD[3])?];
    emit([q[0], q[1], q[2]]);
    emit([q[0], q[2], q[3]]);
    let strip = |(x, y): (i64, i64), k: usize| p((x + k as i64 * STRIP_STEP, y));
    for k in 0..STRIP_COLS - 1 {
        let (t0, t1) = (strip(STRIP_TOP, k)?, strip(STRIP_TOP, k + 1)?);
        let (b0, b1) = (strip(STRIP_BOTTOM, k)?, strip(STRIP_BOTTOM, k + 1)?);
        emit([t0, b0, t1]);
        emit([t1, b0, b1]);
    }
    Ok(())
}

/// Number of primitives [`gouraud`] emits.
pub const GOURAUD_LEN: usize = WHEEL_SEGMENTS + 3;
const WHEEL_SEGMENTS: usize = 16;

/// Gouraud shading: a colour wheel (a fan of 16 triangles, white at the
/// centre, hues on the rim) on the left, and three large overlapping
/// triangles with strongly different vertex colours on the right.
pub fn gouraud<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    let f = Frame::new(width, height)?;
    let (cx, cy) = (f.w * 30 / 100, f.h / 2);
    let r = (f.w * 27 / 100).min(f.h * 45 / 100);
    let rim = |k: usize| f.point::<S>(cx + r * cos64(k * 4) / Q14, cy + r * sin64(k * 4) / Q14);
    let white = rgb::<C>([255, 255, 255]);
    for k in 0..WHEEL_SEGMENTS {
        let (h0, h1) = (hue((k * 96) as u32), hue(((k + 1) % WHEEL_SEGMENTS * 96) as u32));
        let v = [f.point(cx, cy)?, rim(k)?, rim(k + 1)?];
        sink(Triangle::gouraud(v, [white, rgb(h0), rgb(h1)]).into());
    }
    // Per-mille positions of the overlapping triangles' vertices, and their colours.
    const POS: [[(i64, i64); 3]; 3] = [
        [(580, 60), (980, 200), (640, 900)],
        [(700, 950), (620, 300), (990, 760)],
        [(760, 420), (960, 40), (900, 980)],
    ];
    const RGB: [[[u8; 3]; 3]; 3] = [
        [[255, 0, 0], [0, 255, 0], [0, 0, 255]],
        [[0, 255, 255], [255, 0, 255], [255, 255, 0]],
        [[20, 20, 20], [255, 255, 255], [128, 64, 0]],
    ];
    for (pos, cols) in POS.into_iter().zip(RGB) {
        let p = |i: usize| f.point::<S>(f.w * pos[i].0 / 1000, f.h * pos[i].1 / 1000);
        sink(Triangle::gouraud([p(0)?, p(1)?, p(2)?], cols.map(rgb)).into());
    }
    Ok(())
}

/// Number of primitives [`line_fan`] emits.
pub const LINE_FAN_LEN: usize = 64;

/// 64 lines radiating from just off the frame centre, 8 per octant (the
/// first of each exactly on the octant boundary: 0°, 45°, 90°, …), with
/// subpixel start and end points. Each octant has its own colour.
pub fn line_fan<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    let f = Frame::new(width, height)?;
    // Off the pixel grid at (w/2 + 5/16, h/2 + 11/16): in 1/16 px, so that for
    // S >= 4 the octant boundaries (equal |dx| and |dy|) stay exact.
    let (cx, cy) = (f.w / 2 + 80, f.h / 2 + 176);
    let r = (f.w.min(f.h) / 2 - 256).max(0);
    for i in 0..LINE_FAN_LEN {
        let (dx, dy) = (cos64(i), sin64(i));
        let a = f.line_point::<S>(cx + r * dx / (5 * Q14), cy + r * dy / (5 * Q14))?;
        let b = f.line_point::<S>(cx + r * dx / Q14, cy + r * dy / Q14)?;
        sink(Line::new(a, b, rgb(pastel(hue((i / 8) as u32 * 192)))).into());
    }
    Ok(())
}

/// Number of primitives [`mixed`] emits.
pub const MIXED_LEN: usize = 2 + MIXED_TRIANGLES + MIXED_LINES;
const MIXED_TRIANGLES: usize = 60;
const MIXED_LINES: usize = 40;

/// The standard 2D scene, used for benchmarks and firmware CRC checks: a
/// full-frame dark gradient (two Gouraud triangles), then 60 triangles from
/// large to tiny (every third Gouraud, the rest flat), then 40 light lines.
/// Positions come from a fixed-seed xorshift, so the scene never changes.
pub fn mixed<C: Interpolate, const S: u32>(
    width: u32,
    height: u32,
    sink: Sink<'_, C, S>,
) -> Result<(), Error> {
    let f = Frame::new(width, height)?;
    let corners = [f.point::<S>(0, 0)?, f.point(f.w, 0)?, f.point(f.w, f.h)?, f.point(0, f.h)?];
    let dark = [[10, 20, 60], [50, 10, 60], [10, 50, 40], [40, 40, 10]].map(rgb::<C>);
    sink(Triangle::gouraud([corners[0], corners[1], corners[2]], [dark[0], dark[1], dark[2]]).into());
    sink(Triangle::gouraud([corners[0], corners[2], corners[3]], [dark[0], dark[2], dark[3]]).into());
    let mut rng = XorShift(0x9E37_79B9);
    for i in 0..MIXED_TRIANGLES {
        // Size classes (diameter in px) from large to tiny: 64..200, 16..64, 4..16, 1..4.
        let (lo, hi) = [(64, 200), (16, 64), (4, 16), (1, 4)][i * 4 / MIXED_TRIANGLES];
        let size = (lo + rng.below(hi - lo)) * 256;
        // Vertices roughly a third of a turn apart, so most triangles are not slivers.
        let (cx, cy, turn) = (rng.below(f.w), rng.below(f.h), rng.below(64) as usize);
        let mut vertex = |k: usize| {
            let (a, r) = (turn + k * 21 + rng.below(9) as usize, size / 4 + rng.below(size / 4 + 1));
            f.point::<S>(cx + r * cos64(a) / Q14, cy + r * sin64(a) / Q14)
        };
        let v = [vertex(0)?, vertex(1)?, vertex(2)?];
        let mut color = || rgb::<C>(shade(hue(rng.below(1536) as u32), 90 + rng.below(166) as u32));
        let t = if i % 3 == 0 {
            Triangle::gouraud(v, [color(), color(), color()])
        } else {
            Triangle::flat(v, color())
        };
        sink(t.into());
    }
    for i in 0..MIXED_LINES {
        // Alternate long lines across the frame with short ones (up to 32 px).
        let a = (rng.below(f.w), rng.below(f.h));
        let b = if i % 2 == 0 {
            (rng.below(f.w), rng.below(f.h))
        } else {
            (a.0 + rng.below(64 * 256) - 32 * 256, a.1 + rng.below(64 * 256) - 32 * 256)
        };
        let c = rgb(pastel(hue(rng.below(1536) as u32)));
        sink(Line::new(f.line_point(a.0, a.1)?, f.line_point(b.0, b.1)?, c).into());
    }
    Ok(())
}

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

/// Frame size in 1/256 px, for placing points with subpixel precision.
#[derive(Clone, Copy)]
struct Frame {
    w: i64,
    h: i64,
}

impl Frame {
    fn new(width: u32, height: u32) -> Result<Self, Error> {
        check_frame(width, height, (1, 1))?;
        Ok(Frame { w: width as i64 * 256, h: height as i64 * 256 })
    }

    /// A point in 1/256 px, clamped into the frame and snapped to `S` bits.
    fn point<const S: u32>(self, x: i64, y: i64) -> Result<SubPoint<S>, Error> {
        at256(x.clamp(0, self.w), y.clamp(0, self.h))
    }

    /// As [`Frame::point`], but strictly inside: a line along `y = h` would
    /// light row `h`, outside the frame.
    fn line_point<const S: u32>(self, x: i64, y: i64) -> Result<SubPoint<S>, Error> {
        let p = self.point::<S>(x, y)?;
        let max = |v: i64| (v >> (8 - S)) as i32 - 1;
        SubPoint::new(p.x().min(max(self.w)), p.y().min(max(self.h)))
    }
}

fn check_frame(width: u32, height: u32, min: (u32, u32)) -> Result<(), Error> {
    let ok = |v: u32, m: u32| v >= m.max(1) && v <= MAX_FRAME_DIM;
    if ok(width, min.0) && ok(height, min.1) { Ok(()) } else { Err(Error::InvalidFrameSize) }
}

/// A point given in 1/16 px, snapped to `S` bits (exact for `S >= 4`; pixel
/// centres stay exact for every `S >= 1`).
fn at16<const S: u32>(x: i64, y: i64) -> Result<SubPoint<S>, Error> {
    at256(x * 16, y * 16)
}

/// A point given in 1/256 px, snapped to `S` bits, rounding halves up.
fn at256<const S: u32>(x: i64, y: i64) -> Result<SubPoint<S>, Error> {
    const { assert!(S >= 1, "the scenes need at least one subpixel bit") };
    let snap = |v: i64| {
        let k = 8 - S.min(8);
        let r = if k == 0 { v } else { (v + (1 << (k - 1))) >> k };
        i32::try_from(r).map_err(|_| Error::CoordinateOutOfRange)
    };
    SubPoint::new(snap(x)?, snap(y)?)
}

/// Fixed-point one for the sine table.
const Q14: i64 = 1 << 14;
/// `sin(k·π/32)·2^14` for `k = 0..=16`: a quarter wave in 16 steps.
const SIN_Q14: [i64; 17] = [
    0, 1606, 3196, 4756, 6270, 7723, 9102, 10394, 11585, 12665, 13623, 14449, 15137, 15679, 16069, 16305,
    16384,
];

/// `sin(i·2π/64)` in Q14 for any `i`.
fn sin64(i: usize) -> i64 {
    let i = i % 64;
    match i / 16 {
        0 => SIN_Q14[i],
        1 => SIN_Q14[32 - i],
        2 => -SIN_Q14[i - 32],
        _ => -SIN_Q14[64 - i],
    }
}

/// `cos(i·2π/64)` in Q14.
fn cos64(i: usize) -> i64 {
    sin64(i + 16)
}

/// Fully saturated hue; `t` in `0..1536` goes once round the wheel from red.
fn hue(t: u32) -> [u8; 3] {
    let t = t % 1536;
    let (sector, f) = (t / 256, (t % 256) as u8);
    match sector {
        0 => [255, f, 0],
        1 => [255 - f, 255, 0],
        2 => [0, 255, f],
        3 => [0, 255 - f, 255],
        4 => [f, 0, 255],
        _ => [255, 0, 255 - f],
    }
}

/// Half-way to white: luma at least 142, so "on" even in 1-bit colour.
fn pastel(c: [u8; 3]) -> [u8; 3] {
    c.map(|v| ((v as u32 + 255) / 2) as u8)
}

/// `c` scaled by `level / 255`.
fn shade(c: [u8; 3], level: u32) -> [u8; 3] {
    c.map(|v| (v as u32 * level.min(255) / 255) as u8)
}

/// An 8-bit RGB colour in `C`'s channel depth; single-channel types get the luma.
fn rgb<C: Interpolate>(c: [u8; 3]) -> C {
    let m = C::CHANNEL_MAX;
    let scale = |v: u32, max: u8| ((v * max as u32 + 127) / 255) as u8;
    if m[1] == 0 && m[2] == 0 {
        let luma = (77 * c[0] as u32 + 150 * c[1] as u32 + 29 * c[2] as u32 + 128) >> 8;
        C::from_channels([scale(luma, m[0]), 0, 0])
    } else {
        C::from_channels([scale(c[0] as u32, m[0]), scale(c[1] as u32, m[1]), scale(c[2] as u32, m[2])])
    }
}

/// Marsaglia's xorshift32: tiny and deterministic.
struct XorShift(u32);

impl XorShift {
    /// A value in `0..n` (`n > 0`); the modulo bias does not matter here.
    fn below(&mut self, n: i64) -> i64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x as i64 % n.max(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use microraster::edge::{Cull, TriangleSpans};
    use microraster::{ClipRect, Shading};

    /// Twice the signed area of a triangle (zero: degenerate).
    fn signed_area2(p: [(i64, i64); 3]) -> i64 {
        (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
    }
    use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888, RgbColor};

    /// Checks counts, vertices inside the frame and row ranges inside the frame.
    fn check_fits<C: Interpolate + core::fmt::Debug, const S: u32>(w: u32, h: u32) {
        let one = SubPoint::<S>::ONE;
        let (wx, hy) = (w as i32 * one, h as i32 * one);
        let inside = |p: SubPoint<S>, slack: i32| {
            (0..=wx - slack).contains(&p.x()) && (0..=hy - slack).contains(&p.y())
        };
        for (name, scene, len) in all::<C, S>() {
            let mut n = 0;
            let r = scene(w, h, &mut |p: Primitive<C, S>| {
                n += 1;
                let ok = match p {
                    Primitive::Triangle(t) => t.vertices().iter().all(|&v| inside(v, 0)),
                    Primitive::Line(l) => inside(l.start(), 1) && inside(l.end(), 1),
                };
                let (lo, hi) = p.rows();
                assert!(ok && (lo > hi || (lo >= 0 && hi < h as i32)), "{name} {w}x{h}: {p:?}");
            });
            if name == "fill_rule" && (w < FILL_RULE_SIZE.0 || h < FILL_RULE_SIZE.1) {
                assert_eq!((r, n), (Err(Error::InvalidFrameSize), 0));
            } else {
                assert_eq!((r, n), (Ok(()), len), "{name} {w}x{h}");
            }
            assert_eq!(scene(0, h, &mut |_| {}), Err(Error::InvalidFrameSize));
            assert_eq!(scene(w, MAX_FRAME_DIM + 1, &mut |_| {}), Err(Error::InvalidFrameSize));
        }
    }

    #[test]
    fn every_scene_fits_every_frame() {
        for (w, h) in [(1, 1), (3, 200), (28, 14), (31, 17), (320, 240), (480, 320), (4096, 4096)] {
            check_fits::<Rgb565, 1>(w, h);
            check_fits::<Rgb888, 4>(w, h);
            check_fits::<Gray8, 8>(w, h);
            check_fits::<BinaryColor, 3>(w, h);
        }
    }

    const W: usize = 30;
    const H: usize = 16;

    /// Adds the pixels each triangle covers in a `W × H` frame to `hits`.
    fn hit<const S: u32>(hits: &mut [[u8; W]; H], tris: &[[SubPoint<S>; 3]]) {
        for &v in tris {
            for s in TriangleSpans::new(v, ClipRect::new(0, 0, W as i32, H as i32), Cull::None) {
                for x in s.x..s.x + s.len as i32 {
                    hits[s.y as usize][x as usize] += 1;
                }
            }
        }
    }

    fn fill_rule_tiles<const S: u32>() {
        let mut mesh = heapless::Vec::<[SubPoint<S>; 3], FILL_RULE_LEN>::new();
        for_fill_rule_mesh::<S>(16, 16, &mut |v| mesh.push(v).unwrap()).unwrap();
        let p = |x: i64, y: i64| at16::<S>(16 + x, 16 + y).unwrap();
        // Each part's outline, triangulated differently from the mesh.
        let (c, r) = (FAN_CENTER, 6 * 16);
        let sq = [p(c.0 - r, c.1 - r), p(c.0 + r, c.1 - r), p(c.0 + r, c.1 + r), p(c.0 - r, c.1 + r)];
        let q = QUAD.map(|(x, y)| p(x, y));
        let last = (STRIP_COLS - 1) as i64 * STRIP_STEP;
        let (t0, t1) = (p(STRIP_TOP.0, STRIP_TOP.1), p(STRIP_TOP.0 + last, STRIP_TOP.1));
        let (b0, b1) = (p(STRIP_BOTTOM.0, STRIP_BOTTOM.1), p(STRIP_BOTTOM.0 + last, STRIP_BOTTOM.1));
        let parts = [
            (&mesh[..16], [[sq[0], sq[1], sq[2]], [sq[0], sq[2], sq[3]]], 12 * 12),
            (&mesh[16..18], [[q[0], q[1], q[3]], [q[1], q[2], q[3]]], 0),
            (&mesh[18..], [[t0, t1, b1], [t0, b1, b0]], 4 * 8),
        ];
        let mut all = [[0u8; W]; H];
        for (tris, outline, area) in parts {
            let (mut got, mut want) = ([[0u8; W]; H], [[0u8; W]; H]);
            hit(&mut got, tris);
            hit(&mut want, &outline);
            hit(&mut all, tris);
            assert!(want.iter().flatten().all(|&n| n <= 1));
            assert_eq!(got, want, "S = {S}: the mesh must cover its outline exactly once");
            let n = got.iter().flatten().filter(|&&n| n > 0).count();
            assert!(n > 0 && (area == 0 || n == area), "S = {S}: {n} pixels, want {area}");
        }
        assert!(all.iter().flatten().all(|&n| n <= 1), "S = {S}: parts overlap");
    }

    #[test]
    fn fill_rule_meshes_tile_their_outlines_exactly_once() {
        fill_rule_tiles::<1>();
        fill_rule_tiles::<4>();
        fill_rule_tiles::<8>();
        // Neighbours alternate light and dark, so ownership shows even in 1-bit colour.
        let mut k = 0;
        fill_rule::<BinaryColor, 4>(28, 14, &mut |p| {
            assert!(matches!(p, Primitive::Triangle(t) if t.shading() == Shading::Flat(BinaryColor::from(k % 2 == 0))));
            k += 1;
        })
        .unwrap();
    }

    #[test]
    fn gouraud_wheel_is_white_in_the_middle_and_hued_at_the_rim() {
        let mut k = 0;
        gouraud::<Rgb888, 4>(320, 240, &mut |p| {
            let Primitive::Triangle(t) = p else { panic!("a line in gouraud") };
            let Shading::Gouraud(c) = t.shading() else { panic!("a flat triangle in gouraud") };
            let wheel = c[0] == Rgb888::WHITE
                && c[1] != c[2]
                && c[1..].iter().all(|c| c.to_channels().contains(&255));
            assert_eq!(wheel, k < WHEEL_SEGMENTS, "triangle {k}");
            k += 1;
        })
        .unwrap();
    }

    #[test]
    fn line_fan_has_eight_lines_per_octant() {
        let mut i = 0;
        line_fan::<Rgb565, 4>(128, 96, &mut |p| {
            let Primitive::Line(l) = p else { panic!("a triangle in line_fan") };
            let (mut dx, mut dy) = (l.end().x() - l.start().x(), l.end().y() - l.start().y());
            // Rotate by -90° into [0°, 90°), then split at 45° (the boundary goes up).
            let mut octant = 0;
            while !(dx > 0 && dy >= 0) {
                (dx, dy) = (dy, -dx);
                octant += 2;
            }
            assert_eq!(octant + usize::from(dy >= dx), i / 8, "line {i}: {l:?}");
            i += 1;
        })
        .unwrap();
    }

    #[test]
    fn mixed_is_frozen_and_varied() {
        let mut a = heapless::Vec::<Primitive<Rgb565, 4>, MIXED_LEN>::new();
        assert_eq!(collect(mixed, 320, 240, &mut a), Ok(0));
        let mut short = heapless::Vec::<Primitive<Rgb565, 4>, 10>::new();
        assert_eq!(collect(mixed, 320, 240, &mut short), Ok(MIXED_LEN - 10));
        // A hash of every coordinate and colour: firmware CRCs depend on this scene.
        let mut hash = 0xcbf2_9ce4_8422_2325u64;
        let mut eat = |v: i32| hash = (hash ^ v as u32 as u64).wrapping_mul(0x100_0000_01b3);
        let (mut lines, mut gouraud) = (0, 0);
        for p in &a {
            let (v, c) = match *p {
                Primitive::Line(l) => {
                    lines += 1;
                    ([l.start(), l.end(), l.end()], [l.color(); 3])
                }
                Primitive::Triangle(t) => match t.shading() {
                    Shading::Flat(c) => (t.vertices(), [c; 3]),
                    Shading::Gouraud(c) => {
                        gouraud += 1;
                        (t.vertices(), c)
                    }
                },
            };
            v.iter().flat_map(|v| [v.x(), v.y()]).for_each(&mut eat);
            c.iter().flat_map(|c| c.to_channels()).for_each(|ch| eat(ch.into()));
        }
        assert_eq!((lines, gouraud), (MIXED_LINES, 2 + MIXED_TRIANGLES / 3));
        assert_eq!(hash, 0xc403_0545_d823_c0fb, "the mixed scene changed");
        // Lines are light: on, even in 1-bit colour.
        let on = |p| !matches!(p, Primitive::Line(l) if l.color() == BinaryColor::Off);
        mixed::<BinaryColor, 4>(320, 240, &mut |p| assert!(on(p))).unwrap();
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
