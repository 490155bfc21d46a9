//! 2D shapes (`microraster::shape`): every kind (rect, rounded rect, circle,
//! ellipse, arc, sector, polygon, polyline) from `f32` coordinates biased
//! to the frame but also NaN, ±inf and huge; fill and/or stroke with solid,
//! linear or radial paint; any width, join, cap, miter limit and fill rule,
//! aliased or anti-aliased. Checks:
//!
//! * constructors and `Styled::new` fail only with their documented errors;
//! * on a recording canvas with a clip anywhere: every span non-empty,
//!   inside the clip and inside `Styled::rows`, alpha > 0, a gradient gives
//!   a colour per pixel, and no pixel is written more than once by the fill
//!   and once by the stroke;
//! * through the band renderer (64 × 1..48 frame): every frame pixel sent
//!   once, and bands of 1 and 16 rows give the same image;
//! * `Drawable` into a plain `DrawTarget`: no pixel outside it, and
//!   (aliased) the same image as the band renderer;
//! * large and wrapped angles ([`wrapped_angles`], on every input): see there.
#![no_main]

use embedded_graphics_core::Drawable;
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use embedded_graphics_core::prelude::*;
use libfuzzer_sys::fuzz_target;
use microraster::edge::Span;
use microraster::render::from_fn;
use microraster::shape::{
    Arc, Canvas, Cap, Circle, Coverage, Ellipse, FillRule, Join, LinearGradient, Paint, Polygon, Polyline,
    RadialGradient, Rect, RoundedRect, Sector, Shape, ShapeStyle, Styled,
};
use microraster::{Band, ClipRect, Error, Renderer};
use microraster_fuzz::{Input, OnceFrame};

const W: i32 = 64;
const BG: Gray8 = Gray8::new(7);

fuzz_target!(|data: &[u8]| {
    wrapped_angles(data);
    let mut inp = Input::new(data);
    let h = 1 + i32::from(inp.u8() % 48);
    let kind = inp.u8() % 8;
    let aa = inp.bool();
    let Some(style) = style(&mut inp) else { return };
    // Points for polygons and polylines: 0..=11, sometimes up to 60.
    let n = match inp.u8() % 8 {
        0 => usize::from(inp.u8() % 61),
        k => usize::from(k) + usize::from(inp.u8() % 6) - 1,
    };
    let pts: Vec<(f32, f32)> = (0..n).map(|_| (coord(&mut inp), coord(&mut inp))).collect();
    let shape = match kind {
        0 => Rect::new(coord(&mut inp), coord(&mut inp), size(&mut inp), size(&mut inp)).map(S::Rect),
        1 => Rect::new(coord(&mut inp), coord(&mut inp), size(&mut inp), size(&mut inp))
            .and_then(|r| RoundedRect::new(r, size(&mut inp)))
            .map(S::Rounded),
        2 => Circle::new((coord(&mut inp), coord(&mut inp)), size(&mut inp)).map(S::Circle),
        3 => Ellipse::new((coord(&mut inp), coord(&mut inp)), size(&mut inp), size(&mut inp)).map(S::Ellipse),
        4 => Arc::new((coord(&mut inp), coord(&mut inp)), size(&mut inp), angle(&mut inp), angle(&mut inp))
            .map(S::Arc),
        5 => {
            Sector::new((coord(&mut inp), coord(&mut inp)), size(&mut inp), angle(&mut inp), angle(&mut inp))
                .map(S::Sector)
        }
        6 => Polygon::new(&pts).map(S::Polygon),
        _ => Polyline::new(&pts).map(S::Polyline),
    };
    let shape = match shape {
        Ok(s) => s,
        Err(e) => {
            assert!(matches!(e, Error::NonFiniteCoordinate | Error::InvalidParameter(_)), "constructor: {e:?}");
            return;
        }
    };
    match shape {
        S::Rect(s) => run(s, style, aa, h),
        S::Rounded(s) => run(s, style, aa, h),
        S::Circle(s) => run(s, style, aa, h),
        S::Ellipse(s) => run(s, style, aa, h),
        S::Arc(s) => run(s, style, aa, h),
        S::Sector(s) => run(s, style, aa, h),
        S::Polygon(s) => run(s, style, aa, h),
        S::Polyline(s) => run(s, style, aa, h),
    }
});

enum S<'a> {
    Rect(Rect),
    Rounded(RoundedRect),
    Circle(Circle),
    Ellipse(Ellipse),
    Arc(Arc),
    Sector(Sector),
    Polygon(Polygon<'a>),
    Polyline(Polyline<'a>),
}

/// A coordinate: mostly in and around the 64 × 48 frame on the 1/16 px grid
/// (ties on whole and half pixels included), sometimes an extreme `f32`.
fn coord(inp: &mut Input) -> f32 {
    match inp.u8() % 8 {
        0 => inp.f32(),
        1 => f32::from(inp.u8() as i8) / 2.0 + 32.0,
        2 => f32::from(inp.u16() as i16) / 16.0,
        _ => f32::from(inp.u16() % 1600) / 16.0 - 15.0,
    }
}

/// A size or radius: mostly 0..40 px, sometimes negative or extreme.
fn size(inp: &mut Input) -> f32 {
    match inp.u8() % 8 {
        0 => inp.f32(),
        1 => f32::from(inp.u8() % 8) / 8.0,
        _ => f32::from(inp.u16() % 640) / 16.0,
    }
}

fn angle(inp: &mut Input) -> f32 {
    match inp.u8() % 4 {
        0 => inp.f32(),
        _ => f32::from(inp.u16() as i16) / 2048.0,
    }
}

fn paint(inp: &mut Input) -> Option<Paint<Gray8>> {
    let colors = [Gray8::new(inp.u8()), Gray8::new(inp.u8())];
    let made = match inp.u8() % 4 {
        0 | 1 => Ok(Paint::Solid(colors[0])),
        2 => LinearGradient::new((coord(inp), coord(inp)), (coord(inp), coord(inp)), colors).map(Paint::from),
        _ => RadialGradient::new((coord(inp), coord(inp)), size(inp), colors).map(Paint::from),
    };
    match made {
        Ok(p) => Some(p),
        Err(e) => {
            assert!(matches!(e, Error::NonFiniteCoordinate | Error::InvalidParameter(_)), "gradient: {e:?}");
            None
        }
    }
}

fn style(inp: &mut Input) -> Option<ShapeStyle<Gray8>> {
    let mut s = ShapeStyle::new();
    let what = inp.u8() % 3; // fill, stroke, both
    if what != 1 {
        s = s.with_fill(paint(inp)?);
    }
    if what != 0 {
        let w = match inp.u8() % 8 {
            0 => inp.f32(),
            1 => f32::from(inp.u8() % 16) / 16.0,
            _ => f32::from(inp.u8()) / 16.0,
        };
        s = s.with_stroke(paint(inp)?, w);
    }
    s = s.with_join(inp.pick(&[Join::Miter, Join::Round, Join::Bevel]));
    s = s.with_cap(inp.pick(&[Cap::Butt, Cap::Round, Cap::Square]));
    s = s.with_fill_rule(inp.pick(&[FillRule::NonZero, FillRule::EvenOdd]));
    s.miter_limit = match inp.u8() % 8 {
        0 => inp.f32(),
        1 => 1.0 + f32::from(inp.u8()) / 16.0,
        _ => 4.0,
    };
    Some(s)
}

fn run<Sh: Shape>(shape: Sh, style: ShapeStyle<Gray8>, aa: bool, h: i32) {
    if aa { check(shape, style.antialiased(), h, false) } else { check(shape, style, h, true) }
}

fn check<Sh: Shape, A: Coverage>(shape: Sh, style: ShapeStyle<Gray8, A>, h: i32, aliased: bool) {
    let layers = u32::from(style.fill.is_some()) + u32::from(style.stroke.is_some());
    let styled = match Styled::new(shape, style) {
        Ok(s) => s,
        Err(e) => {
            assert!(
                matches!(
                    e,
                    Error::NonFiniteCoordinate
                        | Error::InvalidParameter(_)
                        | Error::CoordinateOutOfRange
                        | Error::BufferTooSmall
                ),
                "Styled::new: {e:?}"
            );
            return;
        }
    };
    let rows = styled.rows();
    assert!(rows.0 <= rows.1, "rows {rows:?}");

    // A recording canvas with a clip around the frame (negative origin too).
    for clip in [ClipRect::new(0, 0, W, h), ClipRect::new(-37, -21, 27, h - 3)] {
        let mut g =
            Grid { clip, hits: vec![0; ((clip.x1() - clip.x0()) * (clip.y1() - clip.y0())) as usize], rows };
        styled.draw_on(&mut g);
        assert!(g.hits.iter().all(|&n| n <= layers), "a pixel written more than once per layer");
    }

    // Through the band renderer at two band heights.
    let one = banded::<Sh, A, 1>(&styled, h);
    let sixteen = banded::<Sh, A, 16>(&styled, h);
    assert!(one == sixteen, "bands of 1 and 16 rows differ");

    // Drawable into a plain framebuffer.
    let mut fb = Plain { h, px: vec![BG; (W * h) as usize] };
    styled.draw(&mut fb).unwrap();
    assert!(!aliased || fb.px == one, "Drawable differs from the band renderer (aliased)");
}

fn banded<Sh: Shape, A: Coverage, const BH: usize>(styled: &Styled<Sh, Gray8, A>, h: i32) -> Vec<Gray8> {
    let mut band = Band::<Gray8, 64, BH>::new(Gray8::BLACK);
    let mut fb = OnceFrame::new(W, h);
    Renderer::new(h as u32, BG)
        .render(
            from_fn(|v| {
                styled.draw_on(v);
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.px.into_iter().map(|p| p.expect("a frame pixel was never sent")).collect()
}

/// Records every span: inside the clip and the shape's rows, per-pixel hits.
struct Grid {
    clip: ClipRect,
    hits: Vec<u32>,
    rows: (i32, i32),
}

impl Grid {
    fn put(&mut self, span: Span, alpha: u8) {
        let c = self.clip;
        assert!(alpha > 0 && span.len > 0, "{span:?} alpha {alpha}");
        assert!(span.y >= c.y0() && span.y < c.y1(), "{span:?} outside {c:?}");
        assert!(
            span.x >= c.x0() && i64::from(span.x) + i64::from(span.len) <= i64::from(c.x1()),
            "{span:?} outside {c:?}"
        );
        assert!(span.y >= self.rows.0 && span.y < self.rows.1, "{span:?} outside rows {:?}", self.rows);
        for x in span.x..span.x + span.len as i32 {
            self.hits[((span.y - c.y0()) * (c.x1() - c.x0()) + x - c.x0()) as usize] += 1;
        }
    }
}

impl Canvas<Gray8> for Grid {
    fn clip(&self) -> ClipRect {
        self.clip
    }
    fn fill(&mut self, span: Span, _: Gray8, alpha: u8) {
        self.put(span, alpha);
    }
    fn shade<I: Iterator<Item = Gray8>>(&mut self, span: Span, colors: I, alpha: u8) {
        assert_eq!(colors.take(span.len as usize).count(), span.len as usize, "too few colours");
        self.put(span, alpha);
    }
}

/// A plain 64-wide framebuffer (overwrites allowed; nothing outside it).
struct Plain {
    h: i32,
    px: Vec<Gray8>,
}

impl OriginDimensions for Plain {
    fn size(&self) -> Size {
        Size::new(W as u32, self.h as u32)
    }
}

impl DrawTarget for Plain {
    type Color = Gray8;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            assert!(p.x >= 0 && p.y >= 0 && p.x < W && p.y < self.h, "pixel {p:?} outside the frame");
            self.px[(p.y * W + p.x) as usize] = c;
        }
        Ok(())
    }
}

/// Sectors' angles, aliased fills wholly inside a 96 × 96 canvas, centre
/// on the 1/32 px grid (ties included), radius 1..31 px:
///
/// * a start and sweep of whole degrees (±180°) give the same pixels as the
///   start plus or minus a turn (`f32` arithmetic, within the angle grid's
///   rounding: `src/pixel/shape/angle.rs`);
/// * `n` slices from `a0 + k·TAU/n` (a0 whole degrees within ±90°, n
///   dividing 360·4096, up to 12) cover each pixel at most once and each
///   centre 0.2 px inside the disc exactly once (they close at the wrap);
/// * any finite start, huge ones included, keeps the sweep: the pixel count
///   is within 1.25 × the outline's length (+ 4) of the area `r²·sweep/2`.
fn wrapped_angles(data: &[u8]) {
    use core::f32::consts::TAU;
    let mut inp = Input::new(data);
    let c = (48.0 + f32::from(inp.u8() as i8) / 32.0, 48.0 + f32::from(inp.u8() as i8) / 32.0);
    let r = 1.0 + f32::from(inp.u16() % 480) / 16.0;
    let sector = |start: f32, sweep: f32| {
        let mut g = Hits(vec![0; SIDE * SIDE]);
        Sector::new(c, r, start, sweep)
            .unwrap()
            .styled(ShapeStyle::fill(Gray8::WHITE))
            .unwrap()
            .draw_on(&mut g);
        g.0
    };
    let degrees =
        |inp: &mut Input, max: u16| (f32::from(inp.u16() % (2 * max + 1)) - f32::from(max)).to_radians();

    let (a0, sweep) = (degrees(&mut inp, 180), degrees(&mut inp, 180));
    let k = if inp.bool() { TAU } else { -TAU };
    assert!(
        sector(a0, sweep) == sector(a0 + k, sweep),
        "start {a0} and {a0} + {k}, sweep {sweep}, {c:?} r {r}"
    );

    let n = inp.pick(&[2u8, 3, 4, 5, 6, 8, 9, 10, 12]);
    let (a0, step) = (degrees(&mut inp, 90), TAU / f32::from(n));
    let mut hits = vec![0u8; SIDE * SIDE];
    for k in 0..n {
        for (h, s) in hits.iter_mut().zip(sector(a0 + f32::from(k) * step, step)) {
            *h += s;
        }
    }
    for (i, &h) in hits.iter().enumerate() {
        let (x, y) = ((i % SIDE) as f32 + 0.5 - c.0, (i / SIDE) as f32 + 0.5 - c.1);
        let inside = x * x + y * y < (r - 0.2) * (r - 0.2);
        assert!(h <= 1 && (h == 1 || !inside), "{n} slices from {a0}, {c:?} r {r}: pixel {i} hit {h}");
    }

    let start = match inp.u8() % 4 {
        0 => inp.f32(),
        1 => f32::from(inp.u16()) * 10f32.powi(i32::from(inp.u8() % 39)),
        _ => -(f32::from(inp.u16()) * 10f32.powi(i32::from(inp.u8() % 39))),
    };
    let sweep = f32::from(inp.u16() as i16) / 4096.0;
    if !start.is_finite() {
        return;
    }
    let count: f32 = sector(start, sweep).iter().map(|&h| f32::from(h)).sum();
    let turn = sweep.abs().min(TAU);
    let (area, outline) = (r * r * turn / 2.0, if turn == TAU { TAU * r } else { 2.0 * r + r * turn });
    assert!(
        (count - area).abs() <= 1.25 * outline + 4.0,
        "start {start} sweep {sweep} r {r}: {count} px, area {area}"
    );
}

/// The side of [`Hits`]' canvas.
const SIDE: usize = 96;

/// Per-pixel write counts of a `SIDE × SIDE` canvas.
struct Hits(Vec<u8>);

impl Canvas<Gray8> for Hits {
    fn clip(&self) -> ClipRect {
        ClipRect::new(0, 0, SIDE as i32, SIDE as i32)
    }
    fn fill(&mut self, span: Span, _: Gray8, _: u8) {
        for x in span.x..span.x + span.len as i32 {
            self.0[span.y as usize * SIDE + x as usize] += 1;
        }
    }
    fn shade<I: Iterator<Item = Gray8>>(&mut self, span: Span, _: I, alpha: u8) {
        self.fill(span, Gray8::BLACK, alpha);
    }
}
