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

/// A frame that does not fit in the display is an error before any band is
/// sent, not a silently clipped `Ok`: the display here lets out-of-bounds
/// pixels through (as real drivers clip them), so without the check all
/// four renders would succeed.
#[test]
fn frame_outside_the_display_is_an_error_and_draws_nothing() {
    use embedded_graphics_core::prelude::Point;
    use microraster::{Band, Error, Region, RenderError, Renderer};
    let scene = [microraster::Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], BinaryColor::On))];
    // The frame as given, on MockDisplay's 64 × 64.
    let outside = |x, y, width, height| {
        let frame = Region { x, y, width, height };
        Err(RenderError::Input(Error::FrameOutsideTarget { frame, target: Region::new(0, 0, 64, 64) }))
    };
    let clipping = || {
        let mut d = MockDisplay::<BinaryColor>::new(); // 64 × 64
        d.set_allow_out_of_bounds_drawing(true);
        d
    };
    // A band one pixel wider than the display.
    let mut d = clipping();
    let mut wide = Band::<BinaryColor, 65, 4>::new(BinaryColor::Off);
    assert_eq!(Renderer::new(8, BinaryColor::Off).render(&scene, &mut wide, &mut d), outside(0, 0, 65, 8));
    assert_eq!(d, MockDisplay::new(), "nothing drawn");
    // A frame one row taller than the display.
    let mut band = Band::<BinaryColor, 8, 4>::new(BinaryColor::Off);
    let mut d = clipping();
    assert_eq!(Renderer::new(65, BinaryColor::Off).render(&scene, &mut band, &mut d), outside(0, 0, 8, 65));
    assert_eq!(d, MockDisplay::new(), "nothing drawn");
    // An offset that moves a fitting frame past either edge.
    for offset in [Point::new(57, 0), Point::new(0, -1)] {
        let r = Renderer::new(8, BinaryColor::Off).with_offset(offset);
        let mut d = clipping();
        assert_eq!(r.render(&scene, &mut band, &mut d), outside(offset.x, offset.y, 8, 8), "{offset:?}");
    }
    // Exactly the display's size, and a frame touching its corner, fit.
    let mut full = Band::<BinaryColor, 64, 16>::new(BinaryColor::Off);
    assert_eq!(
        Renderer::new(64, BinaryColor::Off).render(&scene, &mut full, &mut MockDisplay::new()),
        Ok(())
    );
    let r = Renderer::new(8, BinaryColor::Off).with_offset(Point::new(56, 56));
    assert_eq!(r.render(&scene, &mut band, &mut MockDisplay::new()), Ok(()));
}

/// The threaded band loop checks the frame against the display the same way.
#[test]
fn threaded_frame_outside_the_display_is_an_error() {
    use microraster::{Band, Error, Region, RenderError, Renderer};
    let mut bands = [(); 2].map(|()| Band::<BinaryColor, 8, 4>::new(BinaryColor::Off));
    let mut d = MockDisplay::<BinaryColor>::new();
    d.set_allow_out_of_bounds_drawing(true);
    let r = Renderer::new(65, BinaryColor::Off).render_threads([(), ()], &mut bands, &mut d);
    let (frame, target) = (Region::new(0, 0, 8, 65), Region::new(0, 0, 64, 64));
    assert_eq!(r, Err(RenderError::Input(Error::FrameOutsideTarget { frame, target })));
    assert_eq!(d, MockDisplay::new(), "nothing drawn");
}

/// `RenderError` is a `core::error::Error`, so `?` lifts it into a boxed
/// error; its source is the input error.
#[test]
fn render_error_converts_into_a_boxed_std_error() {
    use microraster::{Band, Renderer};
    fn frame() -> Result<(), Box<dyn std::error::Error>> {
        let mut band = Band::<BinaryColor, 65, 4>::new(BinaryColor::Off);
        Renderer::new(4, BinaryColor::Off).render((), &mut band, &mut MockDisplay::new())?;
        Ok(())
    }
    let e = frame().unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid input: frame 65 x 4 at (0, 0) does not fit in the draw target's 64 x 64 at (0, 0)"
    );
    let source = e.source().expect("the input error");
    let (frame, target) = (microraster::Region::new(0, 0, 65, 4), microraster::Region::new(0, 0, 64, 64));
    assert_eq!(source.to_string(), microraster::Error::FrameOutsideTarget { frame, target }.to_string());
}
