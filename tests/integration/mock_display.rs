//! embedded-graphics `MockDisplay` pattern tests. `MockDisplay` panics when a
//! pixel is drawn twice, so these double as exactly-once checks through the
//! public `DrawTarget` path.

use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics_core::pixelcolor::BinaryColor;
use microraster::blit::TargetBlitter;
use microraster::edge::Cull;
use microraster::{SubPoint, Triangle};

fn p(x: i32, y: i32) -> SubPoint<4> {
    SubPoint::from_pixels(x, y).unwrap()
}

#[test]
fn quad_split_on_a_diagonal_fills_each_pixel_once() {
    let mut display = MockDisplay::<BinaryColor>::new();
    let mut b = TargetBlitter::new(&mut display);
    // Both triangles share the diagonal whose centres are exact ties.
    Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On).draw(&mut b, Cull::None);
    Triangle::flat([p(4, 0), p(4, 4), p(0, 4)], BinaryColor::Off).draw(&mut b, Cull::None);
    // The diagonal's tie pixels belong to the lower-right triangle: for it the
    // diagonal is a left edge, for the upper-left one a right edge.
    display.assert_pattern(&["###.", "##..", "#...", "...."]);
}

#[test]
fn top_edge_owns_ties_bottom_edge_does_not() {
    let mut display = MockDisplay::<BinaryColor>::new();
    let mut b = TargetBlitter::new(&mut display);
    // A 4 px wide rectangle from y = 0.5 to y = 3.5: both horizontal edges run
    // exactly through pixel centres.
    let q = |x: i32, y: f32| SubPoint::<4>::from_f32(x as f32, y).unwrap();
    let (tl, tr, bl, br) = (q(0, 0.5), q(4, 0.5), q(0, 3.5), q(4, 3.5));
    Triangle::flat([tl, tr, br], BinaryColor::On).draw(&mut b, Cull::None);
    Triangle::flat([tl, br, bl], BinaryColor::On).draw(&mut b, Cull::None);
    // Row 0's centres lie on the top edge (covered), row 3's on the bottom edge (not).
    display.assert_pattern(&["####", "####", "####"]);
}

#[test]
fn culling_drops_one_winding() {
    let cw = [p(0, 0), p(3, 0), p(0, 3)];
    let ccw = [p(0, 0), p(0, 3), p(3, 0)];
    for (cull, drawn_cw, drawn_ccw) in
        [(Cull::None, true, true), (Cull::Clockwise, false, true), (Cull::CounterClockwise, true, false)]
    {
        for (v, expect) in [(cw, drawn_cw), (ccw, drawn_ccw)] {
            let mut display = MockDisplay::<BinaryColor>::new();
            Triangle::flat(v, BinaryColor::On).draw(&mut TargetBlitter::new(&mut display), cull);
            let pattern: &[&str] = if expect { &["##", "# "] } else { &[] };
            display.assert_pattern(pattern);
        }
    }
}
