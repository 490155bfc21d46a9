extern crate std;
use super::*;
use crate::Band;
use crate::shape::{Circle, Polygon, Shape, ShapeStyle, Styled};
use crate::test_rng::Rng;
use embedded_graphics::pixelcolor::{Gray8, GrayColor};
use std::format;
use std::vec::Vec;

/// `shape` drawn into bands of `h` rows of a 64 × 48 frame, assembled.
fn frame<S: Shape, A: crate::shape::Coverage>(shape: &Styled<S, Gray8, A>, h: usize) -> Vec<Gray8> {
    frame_by(h, |v| shape.draw_on(v))
}

/// A 64 × 48 frame in bands of `h` rows (cleared to grey 20), each drawn
/// by `draw`, assembled.
pub(super) fn frame_by(
    h: usize,
    mut draw: impl FnMut(&mut crate::band::BandView<'_, Gray8, 64>),
) -> Vec<Gray8> {
    let mut out = Vec::new();
    let mut band = Band::<Gray8, 64, 48>::new(Gray8::BLACK);
    for y0 in (0..48).step_by(h) {
        let rows = h.min(48 - y0);
        draw(&mut band.view(y0 as i32, rows, Gray8::new(20)));
        out.extend(band.rows()[..rows].iter().flatten());
    }
    out
}

/// The exact rows and per-part edge counts of `s`, from its edges.
fn exact<S: Shape>(s: &Styled<S, Gray8>) -> ((i32, i32), usize, usize) {
    let mut e = EdgeList::measuring();
    s.fill_edges(&mut e).unwrap();
    let nf = e.len();
    s.stroke_edges(&mut e).unwrap();
    (s.extent().unwrap(), nf, e.len())
}

#[test]
fn polyline_and_polygon_reach_holds_their_edges() {
    use crate::shape::{Cap, Join, Polyline};
    let mut rng = Rng(0x853c_49e6_748f_ea9b);
    let mut rnd = |scale: f32| rng.unit(scale);
    for i in 0..400 {
        let n = 1 + (rnd(7.0) as usize);
        let base = if i % 5 == 0 { 9.0e5 } else { 0.0 };
        let pts: Vec<(f32, f32)> =
            (0..n).map(|_| (base + rnd(60.0) - 10.0, base + rnd(60.0) - 10.0)).collect();
        let join = [Join::Miter, Join::Round, Join::Bevel][i % 3];
        let cap = [Cap::Butt, Cap::Square, Cap::Round][(i / 3) % 3];
        let mut style = ShapeStyle::fill(Gray8::WHITE).with_stroke(Gray8::BLACK, rnd(12.0));
        (style.join, style.cap, style.miter_limit) = (join, cap, 1.0 + rnd(6.0));
        let stroke = Some(style.params());
        for closed in [false, true] {
            let (reach, (rows, nf, ns)) = if closed {
                let s = Polygon::new(&pts).unwrap().styled(style).unwrap();
                (s.shape.reach(true, stroke.as_ref()), exact(&s))
            } else {
                let s = Polyline::new(&pts).unwrap().styled(style).unwrap();
                (s.shape.reach(true, stroke.as_ref()), exact(&s))
            };
            let r = reach.expect("near points and few edges: a reach");
            let what = format!("{pts:?} {join:?} {cap:?} closed {closed}");
            assert!(nf <= r.edges && ns <= r.edges, "{what}: {nf}, {ns} edges, bound {}", r.edges);
            if rows.0 < rows.1 {
                assert!(r.rows.0 <= rows.0 && rows.1 <= r.rows.1, "{what}: {rows:?} in {:?}", r.rows);
                // Loose by at most the margin and the longest miter or cap.
                let p = style.params();
                let slack = (p.half * p.miter_limit.max(core::f32::consts::SQRT_2)).ceil() as i32 + 2;
                let loose = (rows.0 - r.rows.0).max(r.rows.1 - rows.1);
                assert!(loose <= slack, "{what}: {rows:?} vs {:?}", r.rows);
            }
        }
    }
}

#[test]
fn arc_and_rounded_rect_reach_holds_their_edges() {
    use crate::shape::{Arc, Cap, Rect, RoundedRect};
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut rnd = |scale: f32| rng.unit(scale);
    for i in 0..300 {
        let cap = [Cap::Butt, Cap::Square, Cap::Round][i % 3];
        let mut style = ShapeStyle::fill(Gray8::WHITE).with_stroke(Gray8::BLACK, rnd(14.0));
        style.cap = cap;
        let base = if i % 4 == 0 { 5.0e5 } else { 0.0 };
        let (c, r) = ((base + rnd(80.0) - 20.0, base + rnd(80.0) - 20.0), rnd(150.0));
        let arc = Arc::new(c, r, rnd(20.0) - 10.0, rnd(16.0) - 8.0).unwrap().styled(style).unwrap();
        let rect = Rect::new(c.0, c.1, rnd(120.0), rnd(120.0)).unwrap();
        let rounded = RoundedRect::new(rect, rnd(40.0)).unwrap().styled(style).unwrap();
        let stroke = Some(style.params());
        for (reach, (rows, nf, ns), tight) in [
            (arc.shape.reach(true, stroke.as_ref()), exact(&arc), false),
            (rounded.shape.reach(true, stroke.as_ref()), exact(&rounded), true),
            (
                rounded.shape.reach(true, None),
                exact(&rounded.shape.styled(ShapeStyle::fill(Gray8::WHITE)).unwrap()),
                true,
            ),
        ] {
            let r = reach.expect("near and few edges: a reach");
            let what = format!("{i}: {c:?} {cap:?}");
            assert!(nf <= r.edges && ns <= r.edges, "{what}: {nf}, {ns} edges, bound {}", r.edges);
            if rows.0 < rows.1 {
                assert!(r.rows.0 <= rows.0 && rows.1 <= r.rows.1, "{what}: {rows:?} in {:?}", r.rows);
                if tight {
                    let loose = (rows.0 - r.rows.0).max(r.rows.1 - rows.1);
                    assert!(loose <= 2, "{what}: {rows:?} vs {:?}", r.rows);
                }
            }
        }
    }
}

#[test]
fn windowed_parts_draw_every_band_height_alike() {
    // 120 slanted edges within 6 rows (so a band holds more than the
    // small list: the fall-back), filled; 30 of them stroked too (over
    // a hundred stroke edges); and a large ring.
    let zig: Vec<(f32, f32)> = (0..120)
        .map(|i| (2.0 + i as f32 * 0.5, 20.0 + (i % 2) as f32 * 6.0 + (i % 5) as f32 * 0.1))
        .collect();
    let style = ShapeStyle::fill(Gray8::WHITE).with_stroke(Gray8::new(90), 1.5).with_opacity(200);
    let fill = ShapeStyle::fill(Gray8::WHITE).with_opacity(200);
    let zig_aa = Polygon::new(&zig).unwrap().styled(fill.antialiased()).unwrap();
    let zig_al = Polygon::new(&zig[..30]).unwrap().styled(style).unwrap();
    let ring = Circle::new((30.0, 25.0), 40.0).unwrap().styled(style.antialiased()).unwrap();
    let whole = (frame(&zig_aa, 48), frame(&zig_al, 48), frame(&ring, 48));
    assert!(whole.0.iter().any(|&c| c != Gray8::new(20)));
    for h in [1, 3, 4, 16, 17] {
        assert!(frame(&zig_aa, h) == whole.0, "anti-aliased zigzag, bands of {h}");
        assert!(frame(&zig_al, h) == whole.1, "aliased zigzag, bands of {h}");
        assert!(frame(&ring, h) == whole.2, "ring, bands of {h}");
    }
}

#[test]
fn aliased_rect_takes_whole_spans_with_the_scans_pixels() {
    // `Rect` fills aliased through `box_fill` (no edges); the same corners
    // as a `Polygon` go through the scan. Random boxes, many on the 1/16 px
    // grid at pixel centres and edges (the rule's ties), empty ones, boxes
    // past every side, both fill rules, translucent ones and a gradient:
    // the same pixels in bands of every height and in narrowed columns.
    use crate::shape::{FillRule, LinearGradient, Rect};
    let mut rng = Rng(0xd1b5_4a32_d192_ed03);
    for i in 0..800 {
        let mut v = |scale: f32, off: f32| {
            let u = rng.unit(scale) - off;
            // Half of them on the grid: k/16 px, often a centre (k ≡ 8).
            if i % 2 == 0 { (u * 2.0).round() / 2.0 + [0.0, 0.0625, 0.5][i % 3] } else { u }
        };
        let (x, y) = (v(90.0, 14.0), v(70.0, 11.0));
        let (w, h) =
            if i % 11 == 0 { (0.0, v(20.0, 0.0).abs()) } else { (v(40.0, 0.0).abs(), v(30.0, 0.0).abs()) };
        let corners = [(x, y), (x + w, y), (x + w, y + h), (x, y + h)];
        let rule = [FillRule::NonZero, FillRule::EvenOdd][i % 2];
        let opacity = [255, 255, 180, 1, 0][i % 5];
        let mut style = ShapeStyle::fill(Gray8::new(200)).with_fill_rule(rule).with_opacity(opacity);
        if i % 7 == 3 {
            style.fill = Some(
                LinearGradient::new((0.0, 0.0), (64.0, 20.0), [Gray8::WHITE, Gray8::new(60)]).unwrap().into(),
            );
        }
        let rect = Rect::new(x, y, w, h).unwrap().styled(style).unwrap();
        let poly = Polygon::new(&corners).unwrap().styled(style).unwrap();
        let what = format!("{i}: {corners:?} {rule:?} {opacity}");
        for bh in [48, 16, 5, 1] {
            assert!(frame(&rect, bh) == frame(&poly, bh), "{what}, bands of {bh}");
        }
        let (c0, c1) = ((i % 23) as i32, 64 - (i % 17) as i32);
        let cols = |s: &dyn Fn(&mut crate::band::BandView<'_, Gray8, 64>)| {
            let mut band = Band::<Gray8, 64, 48>::new(Gray8::BLACK);
            s(&mut band.view(0, 48, Gray8::new(20)).with_columns(c0, c1));
            band.rows().concat()
        };
        assert!(cols(&|v| rect.draw_on(v)) == cols(&|v| poly.draw_on(v)), "{what}, columns {c0}..{c1}");
        // Direct, through `TargetCanvas` (its rectangles joined from the spans).
        let direct = |s: &dyn Fn(&mut Fb)| {
            let mut fb = Fb::new();
            s(&mut fb);
            fb.data().to_vec()
        };
        // Over a background (partial pixels mixed) and without one (skipped
        // below half coverage); the rectangle arrives as one `fill_rect`.
        for over in [true, false] {
            let draw = |d: &mut Fb, s: &dyn Fn(&mut crate::shape::TargetCanvas<'_, Fb>)| {
                let canvas = crate::shape::TargetCanvas::new(d);
                let mut canvas = if over { canvas.over(Gray8::new(7)) } else { canvas };
                s(&mut canvas);
                canvas.finish().unwrap();
            };
            assert!(
                direct(&|d| draw(d, &|c| rect.draw_on(c))) == direct(&|d| draw(d, &|c| poly.draw_on(c))),
                "{what}, direct, over a background: {over}"
            );
        }
    }
}

type Fb = embedded_graphics::framebuffer::Framebuffer<
    Gray8,
    embedded_graphics::pixelcolor::raw::RawU8,
    embedded_graphics::pixelcolor::raw::LittleEndian,
    64,
    48,
    { embedded_graphics::framebuffer::buffer_size::<Gray8>(64, 48) },
>;
