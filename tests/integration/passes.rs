//! The one render entry point's contract for every pass and every band loop
//! (`render`, `render_linked`, `render_threads`): a pass's `check` error
//! leaves the display untouched; a draw error stops the drawing, the
//! remaining bands go out as background, and the frame returns that error;
//! the same pass gives the same pixels through every loop.

use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Primitive as _;
use microraster::band::BandView;
use microraster::blit::Blitter;
use microraster::render::{Blocking, Pass, from_fn};
use microraster::{Band, Error, Primitive, RenderError, Renderer, SubPoint, Triangle};

const ON: BinaryColor = BinaryColor::On;
const OFF: BinaryColor = BinaryColor::Off;

/// Lights the first `cols` columns of each band it draws; fails with
/// `error` in the band holding frame row `fail_at` (after lighting it);
/// refuses the frame in `check` if `refuse`.
struct Fill {
    cols: i32,
    fail_at: i32,
    error: Error,
    refuse: bool,
}

impl Fill {
    /// Every column, failing at row `fail_at` with `BufferTooSmall`.
    fn failing_at(fail_at: i32) -> Self {
        Fill { cols: i32::MAX, fail_at, error: Error::BufferTooSmall, refuse: false }
    }

    fn refused() -> Self {
        Fill { refuse: true, ..Fill::failing_at(-1) }
    }
}

impl<const W: usize, const H: usize> Pass<BinaryColor, W, H> for Fill {
    fn check(&mut self, _: &Renderer<BinaryColor>) -> Result<(), Error> {
        if self.refuse { Err(Error::InvalidParameter(microraster::Param::User)) } else { Ok(()) }
    }

    fn draw(
        &mut self,
        band: &mut BandView<'_, BinaryColor, W>,
        _: &Renderer<BinaryColor>,
    ) -> Result<(), Error> {
        let rows = band.y0()..band.y1();
        for y in rows.clone() {
            for x in 0..self.cols.min(W as i32) {
                band.set_pixel(x, y, ON);
            }
        }
        if rows.contains(&self.fail_at) { Err(self.error) } else { Ok(()) }
    }
}

/// `rows` lit rows, then dark ones, in a frame 4 wide and 8 tall.
fn lit_rows(rows: usize) -> Vec<&'static str> {
    (0..8).map(|y| if y < rows { "####" } else { "...." }).collect()
}

#[test]
fn a_refused_pass_sends_nothing_on_every_loop() {
    let r = Renderer::new(8, OFF);
    let mut band = Band::<BinaryColor, 4, 2>::new(OFF);
    let mut d = MockDisplay::new();
    let refused = Err(RenderError::Input(Error::InvalidParameter(microraster::Param::User)));
    assert_eq!(r.render(Fill::refused(), &mut band, &mut d), refused);
    let mut bands = [const { Band::<BinaryColor, 4, 2>::new(OFF) }; 2];
    assert_eq!(r.render_linked(Fill::refused(), &mut bands, &mut Blocking(&mut d)), refused);
    let fills = [(); 2].map(|()| Fill::refused());
    assert_eq!(r.render_threads(fills, &mut bands, &mut d), refused);
    assert_eq!(d, MockDisplay::new(), "nothing sent");
}

#[test]
fn a_draw_error_stops_drawing_and_the_rest_of_the_frame_is_background() {
    let r = Renderer::new(8, OFF);
    // 2-row bands; the pass fails in the band of row 3 (rows 2–3), which it
    // had drawn: rows 0–3 lit, 4–7 background.
    let want = lit_rows(4);
    let mut band = Band::<BinaryColor, 4, 2>::new(ON);
    let mut d = MockDisplay::new();
    let failed = Err(RenderError::Input(Error::BufferTooSmall));
    assert_eq!(r.render(Fill::failing_at(3), &mut band, &mut d), failed);
    d.assert_pattern(&want);
    let mut bands = [const { Band::<BinaryColor, 4, 2>::new(ON) }; 3];
    let mut d = MockDisplay::new();
    assert_eq!(r.render_linked(Fill::failing_at(3), &mut bands, &mut Blocking(&mut d)), failed);
    d.assert_pattern(&want);
}

#[test]
fn threads_return_the_topmost_error_and_blank_each_threads_later_bands() {
    // One band of 2 rows per thread turn: thread 0 draws rows 0–1 and 4–5,
    // thread 1 rows 2–3 and 6–7. Thread 1 fails at row 2, thread 0 at row 4:
    // the frame's error is row 2's, and each thread's later bands are dark.
    let r = Renderer::new(8, OFF);
    let mut bands = [const { Band::<BinaryColor, 4, 2>::new(ON) }; 2];
    let mut d = MockDisplay::new();
    let column = |fail_at, error| Fill { cols: 1, fail_at, error, refuse: false };
    let passes =
        [column(4, Error::BufferTooSmall), column(2, Error::InvalidParameter(microraster::Param::User))];
    assert_eq!(
        r.render_threads(passes, &mut bands, &mut d),
        Err(RenderError::Input(Error::InvalidParameter(microraster::Param::User)))
    );
    d.assert_pattern(&["#...", "#...", "#...", "#...", "#...", "#...", "....", "...."]);
}

#[test]
fn an_overlay_error_stops_later_overlays_and_keeps_the_frame_below() {
    let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
    let scene = [Primitive::from(Triangle::flat([p(0, 0), p(4, 0), p(0, 8)], ON))];
    let r = Renderer::new(8, OFF);
    let mut band = Band::<BinaryColor, 4, 4>::new(OFF);
    // Without the overlay: the triangle.
    let mut plain = MockDisplay::new();
    r.render(&scene, &mut band, &mut plain).unwrap();
    // The overlay lights the last column, and fails in its first band: the
    // first band has the triangle and the column, the second the background
    // (drawing stopped), not the triangle alone.
    let mut d = MockDisplay::new();
    let mut calls = 0;
    // A slice's type does not fix the band height: name it (a 3D pass's does).
    let frame = Pass::<BinaryColor, 4, 4>::then(&scene, |view| {
        calls += 1;
        embedded_graphics::primitives::Line::new(Point::new(3, view.y0()), Point::new(3, view.y0() + 3))
            .into_styled(embedded_graphics::primitives::PrimitiveStyle::with_stroke(ON, 1))
            .draw(view)?;
        Err(Error::InvalidParameter(microraster::Param::User))
    });
    assert_eq!(
        r.render(frame, &mut band, &mut d),
        Err(RenderError::Input(Error::InvalidParameter(microraster::Param::User)))
    );
    assert_eq!(calls, 1);
    for y in 0..8 {
        for x in 0..4 {
            let pt = Point::new(x, y);
            let want = if y < 4 && x == 3 {
                Some(ON)
            } else if y < 4 {
                plain.get_pixel(pt)
            } else {
                Some(OFF)
            };
            assert_eq!(d.get_pixel(pt), want, "({x}, {y})");
        }
    }
}

#[test]
fn the_same_pass_draws_the_same_pixels_through_every_loop() {
    let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
    let scene = [
        Primitive::from(Triangle::flat([p(0, 0), p(7, 1), p(2, 9)], ON)),
        Primitive::from(microraster::Line::new(p(0, 9), p(7, 0), ON)),
    ];
    let r = Renderer::new(10, OFF);
    let mut want = MockDisplay::new();
    r.render(&scene, &mut Band::<BinaryColor, 8, 10>::new(OFF), &mut want).unwrap();
    let mut one = MockDisplay::new();
    r.render(&scene[..], &mut Band::<BinaryColor, 8, 3>::new(ON), &mut one).unwrap();
    let mut linked = MockDisplay::new();
    let mut bands = [const { Band::<BinaryColor, 8, 3>::new(ON) }; 2];
    r.render_linked(&scene, &mut bands, &mut Blocking(&mut linked)).unwrap();
    let mut threads = MockDisplay::new();
    r.render_threads([&scene; 2], &mut bands, &mut threads).unwrap();
    // A closure pass drawing the same primitives through `Blitter`.
    let mut closure = MockDisplay::new();
    let frame = from_fn(|view| {
        for prim in &scene {
            match prim {
                Primitive::Triangle(t) => t.draw(view, microraster::Cull::None),
                Primitive::Line(l) => l.draw(view),
            }
        }
        Ok(())
    });
    r.render(frame, &mut Band::<BinaryColor, 8, 4>::new(ON), &mut closure).unwrap();
    for (name, d) in
        [("3-row bands", &one), ("linked", &linked), ("threads", &threads), ("from_fn", &closure)]
    {
        assert_eq!(d, &want, "{name}");
    }
}
