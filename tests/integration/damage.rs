//! Damage regions (`render::Damage`, `Renderer::render_damaged`): inside the
//! damage the display shows the full frame's pixels, outside it keeps what it
//! had, no pixel is sent twice; a full frame followed by damaged frames (the
//! damage from the moved shapes' and texts' bounds) leaves the display as
//! full frames do, for random scenes, band heights and damage lists; bad
//! input. The random shapes and styles here serve `damage_bounds` too.

use crate::props::runner;
use core::convert::Infallible;
use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::text::Text;
use microraster::band::BandView;
use microraster::render::{Binned2d, Blocking, Damage, DirtyBands, from_fn};
use microraster::shape::{Arc, Cap, Circle, Coverage, Ellipse, Join, LinearGradient, Polygon, Polyline};
use microraster::shape::{Rect, RoundedRect, Shape, ShapeStyle, Styled};
use microraster::{Band, Error, Interpolate, Primitive, RenderError, Renderer, SubPoint, Triangle};
use proptest::prelude::*;

/// A random shape and style.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// 0 rectangle, 1 rounded rectangle, 2 circle, 3 ellipse, 4 polygon,
    /// 5 polyline, 6 arc.
    pub kind: u8,
    /// Four points (positions).
    pub p: [f32; 8],
    /// Sizes and radii.
    pub size: [f32; 3],
    pub fill: bool,
    pub stroke: bool,
    pub width: f32,
    pub join: Join,
    pub cap: Cap,
    pub miter: f32,
    pub aa: bool,
    pub gradient: bool,
    pub opacity: u8,
}

impl Spec {
    /// The geometry's box `(x0, y0, x1, y1)` widened by how far the stroke
    /// can reach: half the width times the miter limit (miter joins) or
    /// √2 (square caps; round and bevel reach less).
    pub fn reach(&self) -> (f32, f32, f32, f32) {
        let [x, y, ..] = self.p;
        let [a, b, _] = self.size;
        let (x0, y0, x1, y1) = match self.kind {
            0 | 1 => (x, y, x + a, y + b),
            2 | 6 => (x - a, y - a, x + a, y + a),
            3 => (x - a, y - b, x + a, y + b),
            _ => {
                let xs = [self.p[0], self.p[2], self.p[4], self.p[6]];
                let ys = [self.p[1], self.p[3], self.p[5], self.p[7]];
                let f = |v: [f32; 4], m: fn(f32, f32) -> f32| v.into_iter().reduce(m).unwrap();
                (f(xs, f32::min), f(ys, f32::min), f(xs, f32::max), f(ys, f32::max))
            }
        };
        let k = if self.join == Join::Miter { self.miter.max(1.5) } else { 1.5 };
        let h = if self.stroke { 0.5 * self.width * k } else { 0.0 };
        (x0 - h, y0 - h, x1 + h, y1 + h)
    }
}

/// Random shapes and styles with positions in `lo..hi`.
pub fn spec(lo: f32, hi: f32) -> impl Strategy<Value = Spec> {
    let joins = prop_oneof![Just(Join::Miter), Just(Join::Round), Just(Join::Bevel)];
    let caps = prop_oneof![Just(Cap::Butt), Just(Cap::Round), Just(Cap::Square)];
    (
        (0u8..7, prop::array::uniform8(lo..hi), prop::array::uniform3(0.3f32..40.0)),
        (0u8..3, prop_oneof![0.3f32..2.0, 2.0f32..12.0], joins, caps, 1.0f32..12.0),
        (any::<bool>(), any::<bool>(), prop_oneof![3 => Just(255u8), 1 => 1u8..255]),
    )
        .prop_map(|((kind, p, size), (paint, width, join, cap, miter), (aa, gradient, opacity))| Spec {
            kind,
            p,
            size,
            // Arcs have no interior: always stroked.
            fill: paint != 1 && kind != 6,
            stroke: paint != 0 || kind == 6,
            width,
            join,
            cap,
            miter,
            aa,
            gradient,
            opacity,
        })
}

/// What is done with a styled shape built from a [`Spec`].
pub trait Visit<C> {
    fn visit<S: Shape, A: Coverage>(&mut self, s: Styled<S, C, A>, aa: bool);
}

/// Builds the shape of `s` in colour `color` and hands it to `v`; shapes
/// the library refuses (degenerate sizes) are skipped.
pub fn visit<C: Interpolate + RgbLike, V: Visit<C>>(s: &Spec, color: C, v: &mut V) {
    let mut style = ShapeStyle::<C>::new();
    if s.fill {
        style = match LinearGradient::new((s.p[0], s.p[1]), (s.p[2], s.p[3]), [color, C::other()]) {
            Ok(g) if s.gradient => style.with_fill(g),
            _ => style.with_fill(color),
        };
    }
    if s.stroke {
        style = style.with_stroke(C::other(), s.width);
    }
    style = style.with_join(s.join).with_cap(s.cap).with_opacity(s.opacity);
    style.miter_limit = s.miter;
    let [x, y, ..] = s.p;
    let [a, b, r] = s.size;
    let pts = [(s.p[0], s.p[1]), (s.p[2], s.p[3]), (s.p[4], s.p[5]), (s.p[6], s.p[7])];
    fn go<S: Shape, C: Interpolate, V: Visit<C>>(
        shape: Result<S, Error>,
        style: ShapeStyle<C>,
        aa: bool,
        v: &mut V,
    ) {
        let Ok(shape) = shape else { return };
        if aa {
            if let Ok(st) = Styled::new(shape, style.antialiased()) {
                v.visit(st, true);
            }
        } else if let Ok(st) = Styled::new(shape, style) {
            v.visit(st, false);
        }
    }
    match s.kind {
        0 => go(Rect::new(x, y, a, b), style, s.aa, v),
        1 => {
            go(Rect::new(x, y, a, b).and_then(|q| RoundedRect::new(q, r.min(a).min(b) * 0.5)), style, s.aa, v)
        }
        2 => go(Circle::new((x, y), a), style, s.aa, v),
        3 => go(Ellipse::new((x, y), a, b), style, s.aa, v),
        4 => go(Polygon::new(&pts), style, s.aa, v),
        5 => go(Polyline::new(&pts), style, s.aa, v),
        // Sweeps within ±6 rad: beyond a turn the outline overlaps itself.
        _ => go(Arc::new((x, y), a, s.p[2] * 0.05, (s.p[3] * 0.05).clamp(-6.0, 6.0)), style, s.aa, v),
    }
}

/// A second colour for strokes and gradients.
pub trait RgbLike: Copy {
    fn other() -> Self;
}
impl RgbLike for Rgb565 {
    fn other() -> Self {
        Rgb565::new(31, 40, 3)
    }
}
impl RgbLike for embedded_graphics::pixelcolor::Gray8 {
    fn other() -> Self {
        embedded_graphics::pixelcolor::Gray8::new(200)
    }
}

/// Draws each visited shape into a band.
struct Draw<'v, 'a, const W: usize>(&'v mut BandView<'a, Rgb565, W>);
impl<const W: usize> Visit<Rgb565> for Draw<'_, '_, W> {
    fn visit<S: Shape, A: Coverage>(&mut self, s: Styled<S, Rgb565, A>, _: bool) {
        s.draw_on(self.0);
    }
}

/// Collects the visited shape's bounds.
struct Bounds(Option<Rectangle>);
impl Visit<Rgb565> for Bounds {
    fn visit<S: Shape, A: Coverage>(&mut self, s: Styled<S, Rgb565, A>, _: bool) {
        self.0 = Some(s.bounds());
    }
}

const W: usize = 96;
const HT: u32 = 72;
const BG: Rgb565 = Rgb565::new(2, 4, 6);
const SENTINEL: Rgb565 = Rgb565::new(31, 0, 31);

/// A scene: shapes, in order, then texts.
#[derive(Debug, Clone)]
struct Scene {
    shapes: Vec<(Spec, u8)>,
    texts: Vec<(String, Point)>,
}

fn palette(i: u8) -> Rgb565 {
    [Rgb565::WHITE, Rgb565::RED, Rgb565::new(3, 50, 20), Rgb565::new(20, 10, 28)][i as usize % 4]
}

fn text_at(t: &(String, Point)) -> Text<'_, MonoTextStyle<'static, Rgb565>> {
    Text::new(&t.0, t.1, MonoTextStyle::new(&FONT_6X10, Rgb565::YELLOW))
}

fn draw_scene<const N: usize>(view: &mut BandView<'_, Rgb565, N>, scene: &Scene) -> Result<(), Error> {
    for (s, c) in &scene.shapes {
        visit(s, palette(*c), &mut Draw(view));
    }
    for t in &scene.texts {
        text_at(t).draw(view)?;
    }
    Ok(())
}

fn scene_strategy() -> impl Strategy<Value = Scene> {
    let text = ("[0-9A-Z ]{1,5}", -8i32..100, -4i32..80).prop_map(|(s, x, y)| (s, Point::new(x, y)));
    (prop::collection::vec((spec(-12.0, 108.0), 0u8..4), 0..7), prop::collection::vec(text, 0..3))
        .prop_map(|(shapes, texts)| Scene { shapes, texts })
}

fn rect_strategy() -> impl Strategy<Value = Rectangle> {
    (-30i32..110, -30i32..90, 0u32..60, 0u32..50)
        .prop_map(|(x, y, w, h)| Rectangle::new(Point::new(x, y), Size::new(w, h)))
}

/// A display of `W × HT` pixels that counts writes per pixel.
#[derive(Clone)]
struct Screen {
    px: Vec<Rgb565>,
    writes: Vec<u32>,
}

impl Screen {
    fn new(fill: Rgb565) -> Self {
        Screen { px: vec![fill; W * HT as usize], writes: vec![0; W * HT as usize] }
    }
    fn get(&self, x: i32, y: i32) -> Rgb565 {
        self.px[y as usize * W + x as usize]
    }
}

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        Size::new(W as u32, HT)
    }
}

impl DrawTarget for Screen {
    type Color = Rgb565;
    type Error = Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), Infallible> {
        panic!("the renderer sends rectangles")
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        a: &Rectangle,
        c: I,
    ) -> Result<(), Infallible> {
        assert!(a.size.width > 0 && a.size.height > 0, "empty part sent: {a:?}");
        let mut it = c.into_iter();
        for p in a.points() {
            assert!(p.x >= 0 && p.y >= 0 && (p.x as usize) < W && (p.y as u32) < HT, "{a:?} outside");
            let i = p.y as usize * W + p.x as usize;
            self.px[i] = it.next().expect("one colour per pixel");
            self.writes[i] += 1;
        }
        assert!(it.next().is_none(), "more colours than pixels");
        Ok(())
    }
}

fn full<const H: usize>(scene: &Scene, screen: &mut Screen) {
    let mut band = Band::<Rgb565, W, H>::new(BG);
    Renderer::new(HT, BG).render(from_fn(|v| draw_scene(v, scene)), &mut band, screen).unwrap();
}

fn damaged<const H: usize, const N: usize>(scene: &Scene, damage: &Damage<N>, screen: &mut Screen) {
    let mut band = Band::<Rgb565, W, H>::new(SENTINEL); // stale contents must not show
    Renderer::new(HT, BG)
        .render_damaged(from_fn(|v| draw_scene(v, scene)), damage, &mut band, screen)
        .unwrap();
}

/// Whether `(x, y)` is in any of `rects`.
fn inside(rects: &[Rectangle], x: i32, y: i32) -> bool {
    rects.iter().any(|r| r.contains(Point::new(x, y)))
}

/// One damaged frame against a full one: the damage shows the full frame,
/// the rest keeps the sentinel, each damaged pixel is sent once.
fn check_direct<const H: usize>(scene: &Scene, rects: &[Rectangle]) -> Result<(), TestCaseError> {
    let mut damage = Damage::<8>::new();
    for r in rects {
        damage.add(*r).unwrap();
    }
    let mut reference = Screen::new(SENTINEL);
    full::<H>(scene, &mut reference);
    let mut screen = Screen::new(SENTINEL);
    damaged::<H, 8>(scene, &damage, &mut screen);
    let mut area = 0u64;
    for y in 0..HT as i32 {
        for x in 0..W as i32 {
            let i = y as usize * W + x as usize;
            if inside(rects, x, y) {
                area += 1;
                prop_assert_eq!(screen.writes[i], 1, "({}, {}) sent {} times", x, y, screen.writes[i]);
                prop_assert_eq!(screen.get(x, y), reference.get(x, y), "({}, {}) damaged", x, y);
            } else {
                prop_assert_eq!(screen.writes[i], 0, "({}, {}) outside the damage was sent", x, y);
            }
        }
    }
    prop_assert_eq!(damage.area(W as u32, HT), area);
    Ok(())
}

#[test]
fn damaged_pixels_are_the_full_frames_and_nothing_else_is_sent() {
    let strategy = (scene_strategy(), prop::collection::vec(rect_strategy(), 0..8), 0u8..3);
    let cases = core::cell::RefCell::new([0usize; 3]);
    runner(160)
        .run(&strategy, |(scene, rects, h)| {
            cases.borrow_mut()[h as usize] += 1;
            match h {
                0 => check_direct::<1>(&scene, &rects),
                1 => check_direct::<7>(&scene, &rects),
                _ => check_direct::<16>(&scene, &rects),
            }
        })
        .unwrap();
    let cases = cases.into_inner();
    assert!(cases.iter().all(|&c| c > 20), "{cases:?}");
}

/// The bounds of shape `i` of `scene`, empty if it draws nothing.
fn shape_bounds(scene: &Scene, i: usize) -> Rectangle {
    let mut b = Bounds(None);
    visit(&scene.shapes[i].0, palette(scene.shapes[i].1), &mut b);
    b.0.unwrap_or(Rectangle::zero())
}

/// One damaged frame's changes: shapes replaced, texts moved, extra rectangles.
type Move = (Vec<(usize, Spec)>, Vec<(usize, Point)>, Vec<Rectangle>);

/// A full frame, then damaged frames where some shapes and texts move
/// (damage: their old and new bounds through `add_moved`, plus random
/// rectangles): after every frame the display equals a full render.
fn check_drive<const H: usize>(first: &Scene, moves: &[Move]) -> Result<(), TestCaseError> {
    let mut screen = Screen::new(SENTINEL);
    full::<H>(first, &mut screen);
    let mut scene = first.clone();
    for (shapes, texts, extra) in moves {
        let mut next = scene.clone();
        let mut damage = Damage::<32>::new();
        for (i, s) in shapes.iter().filter(|(i, _)| *i < scene.shapes.len()) {
            next.shapes[*i].0 = s.clone();
            damage.add_moved(&shape_bounds(&scene, *i), &shape_bounds(&next, *i)).unwrap();
        }
        for (i, p) in texts.iter().filter(|(i, _)| *i < scene.texts.len()) {
            next.texts[*i].1 = *p;
            damage.add_moved(&text_at(&scene.texts[*i]), &text_at(&next.texts[*i])).unwrap();
        }
        for r in extra {
            damage.add(*r).unwrap();
        }
        damaged::<H, 32>(&next, &damage, &mut screen);
        let mut reference = Screen::new(SENTINEL);
        full::<H>(&next, &mut reference);
        prop_assert!(screen.px == reference.px, "the display differs from a full frame");
        scene = next;
    }
    Ok(())
}

#[test]
fn full_then_damaged_frames_equal_full_frames() {
    let moved = (0usize..7, spec(-12.0, 108.0));
    let text = (0usize..3, (-8i32..100, -4i32..80).prop_map(|(x, y)| Point::new(x, y)));
    let frame = (
        prop::collection::vec(moved, 0..3),
        prop::collection::vec(text, 0..2),
        prop::collection::vec(rect_strategy(), 0..3),
    );
    let strategy = (scene_strategy(), prop::collection::vec(frame, 1..4), any::<bool>());
    runner(120)
        .run(&strategy, |(scene, moves, tall)| {
            if tall { check_drive::<16>(&scene, &moves) } else { check_drive::<5>(&scene, &moves) }
        })
        .unwrap();
}

/// The slice-of-primitives pass (rows cleared as written, `CLEARS = false`;
/// damaged rows packed) and `Binned2d` (bands at multiples of `H`) through
/// damage: the damage shows the full frame, nothing else is sent.
#[test]
fn primitive_slices_through_damage() {
    let tri = (prop::array::uniform6(-200i32..1700), 0u8..4);
    let strategy = (prop::collection::vec(tri, 0..8), prop::collection::vec(rect_strategy(), 0..6));
    runner(150)
        .run(&strategy, |(tris, rects)| {
            let p = |x: i32, y: i32| SubPoint::<4>::new(x, y).unwrap();
            let prims: Vec<Primitive<Rgb565, 4>> = tris
                .iter()
                .map(|(v, c)| {
                    Triangle::flat([p(v[0], v[1]), p(v[2], v[3]), p(v[4], v[5])], palette(*c)).into()
                })
                .collect();
            let mut damage = Damage::<8>::new();
            rects.iter().for_each(|r| damage.add(*r).unwrap());
            let r = Renderer::new(HT, BG);
            let mut band = Band::<Rgb565, W, 8>::new(BG);
            let (mut reference, mut screen) = (Screen::new(SENTINEL), Screen::new(SENTINEL));
            r.render(&prims[..], &mut band, &mut reference).unwrap();
            let mut band = Band::<Rgb565, W, 8>::new(SENTINEL);
            r.render_damaged(&prims[..], &damage, &mut band, &mut screen).unwrap();
            // Binned2d: per-band lists, so its bands stay at multiples of H.
            let mut binned = Screen::new(SENTINEL);
            let mut index = [0u16; HT as usize / 8 * 9]; // every primitive in every band
            r.render_damaged(Binned2d::new(&prims, &mut index), &damage, &mut band, &mut binned).unwrap();
            for (i, (a, b)) in screen.px.iter().zip(&reference.px).enumerate() {
                let (x, y) = ((i % W) as i32, (i / W) as i32);
                let want = if inside(&rects, x, y) { *b } else { SENTINEL };
                prop_assert_eq!(*a, want, "({}, {})", x, y);
                prop_assert_eq!(binned.px[i], want, "({}, {}) binned", x, y);
                prop_assert!(screen.writes[i] <= 1 && binned.writes[i] <= 1);
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn bad_damage_input() {
    let r = Renderer::new(HT, BG);
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let scene = Scene { shapes: vec![], texts: vec![("88".into(), Point::new(10, 20))] };
    // An empty list: nothing sent, Ok.
    let mut screen = Screen::new(SENTINEL);
    assert_eq!(
        r.render_damaged(from_fn(|v| draw_scene(v, &scene)), &Damage::<4>::new(), &mut band, &mut screen),
        Ok(())
    );
    assert!(screen.writes.iter().all(|&w| w == 0));
    // Rectangles wholly outside the frame: nothing sent; partly: clipped.
    let rect = |x, y, w, h| Rectangle::new(Point::new(x, y), Size::new(w, h));
    let mut damage = Damage::<4>::new();
    damage.add(rect(W as i32, 0, 50, 50)).unwrap();
    damage.add(rect(0, HT as i32 + 3, 50, 50)).unwrap();
    damage.add(rect(i32::MAX - 2, i32::MIN, u32::MAX, u32::MAX)).unwrap();
    r.render_damaged(from_fn(|v| draw_scene(v, &scene)), &damage, &mut band, &mut screen).unwrap();
    assert!(screen.writes.iter().all(|&w| w == 0));
    assert_eq!(damage.area(W as u32, HT), 0);
    let mut damage = Damage::<4>::new();
    damage.add(rect(-10, HT as i32 - 4, 20, 100)).unwrap();
    r.render_damaged(from_fn(|v| draw_scene(v, &scene)), &damage, &mut band, &mut screen).unwrap();
    assert_eq!(screen.writes.iter().sum::<u32>(), 10 * 4);
    // The whole plane: the whole frame, once.
    let mut all = Screen::new(SENTINEL);
    let mut damage = Damage::<1>::new();
    damage.add(rect(i32::MIN, i32::MIN, u32::MAX, u32::MAX)).unwrap();
    damage.add(rect(-1, -1, 3, 3)).unwrap(); // inside: no slot needed
    r.render_damaged(from_fn(|v| draw_scene(v, &scene)), &damage, &mut band, &mut all).unwrap();
    let mut reference = Screen::new(SENTINEL);
    full::<16>(&scene, &mut reference);
    assert!(all.writes.iter().all(|&w| w == 1) && all.px == reference.px);
    // Too many rectangles: a typed error when added, the list unchanged.
    let mut damage = Damage::<2>::new();
    damage.add(rect(0, 0, 4, 4)).unwrap();
    damage.add(rect(10, 0, 4, 4)).unwrap();
    let before = damage.clone();
    assert_eq!(damage.add(rect(20, 0, 4, 4)), Err(Error::CapacityExceeded { needed: 3, capacity: 2 }));
    assert_eq!(
        damage.add_moved(&rect(0, 10, 4, 4), &rect(40, 10, 4, 4)),
        Err(Error::CapacityExceeded { needed: 3, capacity: 2 })
    );
    assert_eq!(damage, before);
    // One that holds both stored ones takes their place.
    damage.add(rect(0, 0, 20, 8)).unwrap();
    assert_eq!(damage.rects().collect::<Vec<_>>(), [rect(0, 0, 20, 8)]);
    // The frame is checked before anything is sent.
    let mut small = Screen::new(SENTINEL);
    let tall = Renderer::new(HT + 1, BG).render_damaged(
        from_fn(|v| draw_scene(v, &scene)),
        &damage,
        &mut band,
        &mut small,
    );
    let (frame, target) =
        (microraster::Region::new(0, 0, W as u32, HT + 1), microraster::Region::new(0, 0, W as u32, HT));
    assert_eq!(tall, Err(RenderError::Input(Error::FrameOutsideTarget { frame, target })));
    assert!(small.writes.iter().all(|&w| w == 0));
    // A pass error: the damaged parts still go out (background after the
    // error), the error is returned.
    let mut failing = Screen::new(SENTINEL);
    let mut damage = Damage::<2>::new();
    damage.add(rect(0, 0, 8, 40)).unwrap();
    let out = r.render_damaged(
        from_fn(|_| Err(Error::InvalidParameter(microraster::Param::User))),
        &damage,
        &mut band,
        &mut failing,
    );
    assert_eq!(out, Err(RenderError::Input(Error::InvalidParameter(microraster::Param::User))));
    assert_eq!(failing.writes.iter().sum::<u32>(), 8 * 40);
    assert!((0..40).all(|y| failing.get(3, y) == BG));
}

/// Damaged frames between full frames through `DirtyBands`: after
/// `force_full_frame` the dirty-band sink sends what changed since the
/// damaged frames too, and the display equals a full render throughout.
#[test]
fn damage_combines_with_dirty_bands() {
    let at = |x: i32| Scene { shapes: vec![], texts: vec![("42".into(), Point::new(x, 30))] };
    let r = Renderer::new(HT, BG);
    let mut bands = [const { Band::<Rgb565, W, 16>::new(BG) }; 2];
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let mut screen = Screen::new(SENTINEL);
    let mut sink = DirtyBands::<_, 8>::new(Blocking(&mut screen));
    r.render_linked(from_fn(|v| draw_scene(v, &at(10))), &mut bands, &mut sink).unwrap();
    // Damaged: the text moves to 40 and back to 10 (the display shows 10).
    for (from, to) in [(10, 40), (40, 10), (10, 40)] {
        let mut damage = Damage::<4>::new();
        damage.add_moved(&text_at(&at(from).texts[0]), &text_at(&at(to).texts[0])).unwrap();
        r.render_damaged(from_fn(|v| draw_scene(v, &at(to))), &damage, &mut band, &mut *sink.inner().0)
            .unwrap();
    }
    // Back to a full frame at 10 through the dirty-band sink: its records
    // say the display shows 10, so it must be told otherwise.
    sink.force_full_frame();
    r.render_linked(from_fn(|v| draw_scene(v, &at(10))), &mut bands, &mut sink).unwrap();
    let mut reference = Screen::new(SENTINEL);
    full::<16>(&at(10), &mut reference);
    assert!(sink.inner().0.px == reference.px);
}
