//! `Styled::bounds`: for random shapes and styles (every shape, fill and
//! stroke, every join with random miter limits, every cap, aliased and
//! anti-aliased) no pixel outside the reported bounds is ever written, and
//! the bounds are not loose: within 2 px of the anti-aliased shape's
//! written pixels where nothing thin reaches out (no miter), and within the
//! geometric reach (control points ± half the width times the miter limit,
//! or √2 for square caps) plus 2 px always.
//!
//! The written pixels come from a recording [`Canvas`]: every span the
//! shape emits with a coverage above zero, so a pixel the bound missed is
//! seen even if its colour would round to the background.

use crate::props::runner;
use embedded_graphics::pixelcolor::{Gray8, GrayColor};
use microraster::ClipRect;
use microraster::edge::Span;
use microraster::shape::{Canvas, Coverage, Join, Shape, Styled};

use super::damage::{Spec, Visit, spec, visit};

const SIDE: i32 = 160;

/// Pixels of a `SIDE × SIDE` frame written with coverage above zero.
struct Record {
    hit: Vec<bool>,
}

impl Record {
    fn new() -> Self {
        Record { hit: vec![false; (SIDE * SIDE) as usize] }
    }
    fn mark(&mut self, s: Span, alpha: u8) {
        if alpha == 0 {
            return;
        }
        for x in s.x..s.x + s.len as i32 {
            assert!((0..SIDE).contains(&x) && (0..SIDE).contains(&s.y), "span outside the clip: {s:?}");
            self.hit[(s.y * SIDE + x) as usize] = true;
        }
    }
    /// The box of the written pixels, if any.
    fn lit(&self) -> Option<(i32, i32, i32, i32)> {
        let mut b: Option<(i32, i32, i32, i32)> = None;
        for (i, _) in self.hit.iter().enumerate().filter(|(_, h)| **h) {
            let (x, y) = (i as i32 % SIDE, i as i32 / SIDE);
            b = Some(b.map_or((x, y, x + 1, y + 1), |(a, c, d, e)| {
                (a.min(x), c.min(y), d.max(x + 1), e.max(y + 1))
            }));
        }
        b
    }
}

impl Canvas<Gray8> for Record {
    fn clip(&self) -> ClipRect {
        ClipRect::new(0, 0, SIDE, SIDE)
    }
    fn fill(&mut self, span: Span, _: Gray8, alpha: u8) {
        self.mark(span, alpha);
    }
    fn shade<I: Iterator<Item = Gray8>>(&mut self, span: Span, _: I, alpha: u8) {
        self.mark(span, alpha);
    }
}

/// Draws the shape into a [`Record`] and checks its bounds against it.
struct Check<'a> {
    spec: &'a Spec,
    drawn: usize,
    tight: usize,
}

impl Visit<Gray8> for Check<'_> {
    fn visit<S: Shape, A: Coverage>(&mut self, s: Styled<S, Gray8, A>, aa: bool) {
        let b = s.bounds();
        let mut rec = Record::new();
        s.draw_on(&mut rec);
        let Some(lit) = rec.lit() else { return };
        self.drawn += 1;
        let (bx0, by0) = (b.top_left.x, b.top_left.y);
        let (bx1, by1) = (bx0 + b.size.width as i32, by0 + b.size.height as i32);
        // Conservative: every written pixel inside.
        assert!(
            lit.0 >= bx0 && lit.1 >= by0 && lit.2 <= bx1 && lit.3 <= by1,
            "{:?}: written {lit:?} outside bounds {b:?}",
            self.spec
        );
        // Not loose, against the geometry.
        let g = self.spec.reach();
        assert!(
            bx0 as f32 >= g.0 - 2.0
                && by0 as f32 >= g.1 - 2.0
                && bx1 as f32 <= g.2 + 2.0
                && by1 as f32 <= g.3 + 2.0,
            "{:?}: bounds {b:?} beyond the geometric reach {g:?}",
            self.spec
        );
        // Not loose, against the anti-aliased pixels, where no thin part
        // reaches out (whose coverage rounds to 0): no miter tips, no
        // polygon spikes, opaque.
        let mitered = self.spec.stroke && self.spec.join == Join::Miter;
        let spiky = matches!(self.spec.kind, 4 | 5);
        // Only the canvas's pixels are seen: bounds within it.
        let seen = bx0 >= 0 && by0 >= 0 && bx1 <= SIDE && by1 <= SIDE;
        let thick = !self.spec.stroke || self.spec.width >= 1.0;
        if aa && seen && !mitered && !spiky && self.spec.opacity == 255 && thick {
            self.tight += 1;
            let slack = 2;
            assert!(
                bx0 >= lit.0 - slack && by0 >= lit.1 - slack && bx1 <= lit.2 + slack && by1 <= lit.3 + slack,
                "{:?}: bounds {b:?} loose around the written {lit:?}",
                self.spec
            );
        }
    }
}

#[test]
fn styled_bounds_hold_every_written_pixel() {
    let counts = core::cell::RefCell::new((0usize, 0usize, [0usize; 7]));
    runner(1500)
        .run(&spec(20.0, 140.0), |s| {
            let mut c = Check { spec: &s, drawn: 0, tight: 0 };
            visit(&s, Gray8::WHITE, &mut c);
            let mut n = counts.borrow_mut();
            n.0 += c.drawn;
            n.1 += c.tight;
            n.2[s.kind as usize % 7] += c.drawn;
            Ok(())
        })
        .unwrap();
    let (drawn, tight, kinds) = counts.into_inner();
    println!("bounds: {drawn} shapes drawn, {tight} checked for tightness, per kind {kinds:?}");
    assert!(drawn > 1000 && tight > 100 && kinds.iter().all(|&k| k > 50), "{drawn} {tight} {kinds:?}");
}

/// A miter at a sharp angle reaches far (up to the limit), and the bound
/// follows it; at a limit of 1 the same corner is bevelled and the bound
/// shrinks.
#[test]
fn miter_bounds_follow_the_limit() {
    use microraster::shape::{AntiAliased, Polyline, ShapeStyle};
    let pts = [(20.0, 60.0), (80.0, 64.0), (20.0, 68.0)];
    let line = Polyline::new(&pts).unwrap();
    let pen = |limit| {
        let mut p = ShapeStyle::stroke(Gray8::WHITE, 4.0).with_join(Join::Miter).antialiased();
        p.miter_limit = limit;
        p
    };
    let far = line.styled(pen(40.0)).unwrap();
    let cut = line.styled(pen(1.0)).unwrap();
    let right =
        |s: &Styled<Polyline<'_>, Gray8, AntiAliased>| s.bounds().top_left.x + s.bounds().size.width as i32;
    // The tip of a miter of half-angle atan(4/60): 2 / sin(3.8°) ≈ 30 px past the vertex.
    assert!(right(&far) >= 80 + 25, "{:?}", far.bounds());
    assert!(right(&cut) <= 80 + 3, "{:?}", cut.bounds());
    for s in [far, cut] {
        let mut rec = Record::new();
        s.draw_on(&mut rec);
        let lit = rec.lit().unwrap();
        assert!(lit.2 <= right(&s) && lit.2 >= right(&s) - 3, "{lit:?} {:?}", s.bounds());
    }
}
