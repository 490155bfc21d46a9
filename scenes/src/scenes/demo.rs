//! The demo scenes that [`all`] lists: the fill-rule close-up, the Gouraud
//! wheel, the line fan and the standard `mixed` scene, placed at subpixel
//! positions (unlike the pixel-centre benchmark scenes), with their tests.

use microraster::{Error, Interpolate, Line, SubPoint, Triangle};

use super::helpers::{Frame, Q14, XorShift, at16, check_frame, cos64, hue, pastel, rgb, shade, sin64};
use super::{Scene, Sink};

/// Every scene with its name and primitive count, in a fixed order.
pub fn all<C: Interpolate, const S: u32>() -> [(&'static str, Scene<C, S>, usize); 4] {
    [
        ("fill_rule", fill_rule, FILL_RULE_LEN),
        ("gouraud", gouraud, GOURAUD_LEN),
        ("line_fan", line_fan, LINE_FAN_LEN),
        ("mixed", mixed, MIXED_LEN),
    ]
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenes::collect;
    use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888, RgbColor};
    use microraster::edge::{Cull, TriangleSpans};
    use microraster::{ClipRect, MAX_FRAME_DIM, Primitive, Shading, heapless};

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
}
