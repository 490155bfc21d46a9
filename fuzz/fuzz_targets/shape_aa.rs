//! Anti-aliased shape coverage with far vertices (issue #60, items 6 and 7):
//! polygons of 3–6 vertices, each near a 24 × 16 frame on the 1/16 px grid
//! or far from it (anywhere in the ±2^28-subpixel range, its corners and
//! edges included), filled anti-aliased with the nonzero or even-odd rule,
//! on a clip at the origin or moved right and down by up to 32 px. Checks:
//!
//! * every span inside the clip, alpha > 0, no pixel written twice;
//! * no alpha on a pixel outside the polygon's bounding box;
//! * triangles: every pixel's alpha within `½ + 1/256` levels of 255 × its
//!   exact area (`f64` clipping of the snapped vertices, translated to the
//!   pixel first: exact to about 2^-28 px²), the bound `area.rs` states;
//! * quadrilaterals whose diagonal `p0 p2` splits them into two triangles
//!   (`p1`, `p3` strictly on either side, exact integer test): the two
//!   halves as one `Group`, however each is wound, give exactly the pixels
//!   of the whole quadrilateral.
#![no_main]

use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use libfuzzer_sys::fuzz_target;
use microraster::edge::Span;
use microraster::shape::{Canvas, FillRule, Group, Polygon, Shape, ShapeStyle};
use microraster::{ClipRect, Error};
use microraster_fuzz::{Input, snap_reference};

const W: i32 = 24;
const H: i32 = 16;
const LIMIT: i64 = 1 << 28;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let n = 3 + usize::from(inp.u8() % 4);
    let rule = if inp.u8() % 4 == 0 { FillRule::EvenOdd } else { FillRule::NonZero };
    let (ox, oy) = match inp.u8() % 4 {
        // A clip cannot start left of or above the frame (`ClipRect::new` clamps).
        0 => (i32::from(inp.u8() % 33), i32::from(inp.u8() % 33)),
        _ => (0, 0),
    };
    let clip = ClipRect::new(ox, oy, ox + W, oy + H);
    let pts: Vec<(f32, f32)> = (0..n).map(|_| (coord(&mut inp, W), coord(&mut inp, H))).collect();
    // The snapped vertices (subpixels), as the library snaps them.
    let mut sub = Vec::with_capacity(n);
    for &(x, y) in &pts {
        match (snap_reference(x, 4), snap_reference(y, 4)) {
            (Some(Ok(x)), Some(Ok(y))) => sub.push((x, y)),
            _ => return, // out of range: `bad_input` tests and the `shape` target cover it
        }
    }
    let style = ShapeStyle::fill(Gray8::WHITE).with_fill_rule(rule).antialiased();
    let whole = match Polygon::new(&pts).and_then(|p| p.styled(style)) {
        Ok(s) => draw(clip, |c| s.draw_on(c)),
        Err(e) => {
            assert!(matches!(e, Error::CoordinateOutOfRange), "{e:?}");
            return;
        }
    };
    // Bounding box (pixels, exact in f64).
    let px: Vec<(f64, f64)> = sub.iter().map(|&(x, y)| (x as f64 / 16.0, y as f64 / 16.0)).collect();
    let lo = px.iter().fold((f64::MAX, f64::MAX), |a, p| (a.0.min(p.0), a.1.min(p.1)));
    let hi = px.iter().fold((f64::MIN, f64::MIN), |a, p| (a.0.max(p.0), a.1.max(p.1)));
    for (i, &a) in whole.iter().enumerate() {
        let (x, y) = (f64::from(ox + i as i32 % W), f64::from(oy + i as i32 / W));
        let outside = x + 1.0 <= lo.0 || x >= hi.0 || y + 1.0 <= lo.1 || y >= hi.1;
        assert!(!outside || a == 0, "{px:?}: ({x}, {y}) outside the bounding box has alpha {a}");
        if n == 3 {
            let area = pixel_area(&px, x, y);
            let err = (f64::from(a) - 255.0 * area).abs();
            assert!(err <= 0.5 + 1.0 / 256.0, "{px:?}: ({x}, {y}) alpha {a}, exact area {area}");
        }
    }
    if n == 4 && splits(&sub) {
        let flip = inp.u8();
        let half = |i: usize, tri: [usize; 3]| {
            let t = if flip >> i & 1 == 1 { [tri[0], tri[2], tri[1]] } else { tri };
            t.map(|k| pts[k])
        };
        let halves = [half(0, [0, 1, 2]), half(1, [0, 2, 3])];
        let members = [Polygon::new(&halves[0]).unwrap(), Polygon::new(&halves[1]).unwrap()];
        let group = Group::new(&members).styled(style).expect("the halves fit as the whole does");
        assert!(draw(clip, |c| group.draw_on(c)) == whole, "{px:?}: the group differs from the whole");
    }
});

/// A coordinate: near the frame on the 1/16 px grid, or far (a random
/// subpixel in the range, or one of its ends).
fn coord(inp: &mut Input, size: i32) -> f32 {
    let s = match inp.u8() % 8 {
        0 => i64::from(inp.i32()) % (LIMIT + 1),
        1 => inp.pick(&[LIMIT, -LIMIT, LIMIT - 16, -(LIMIT - 16), LIMIT / 3, -LIMIT / 7]),
        2 => i64::from(inp.i32() >> 8),
        _ => i64::from(inp.u16() % (((size as u16) + 16) * 16)) - 128,
    };
    // Exact below 2^24 subpixels; beyond, the nearest f32 (snapping is checked above).
    s as f32 / 16.0
}

/// Alpha per pixel of `clip` after `draw`: spans inside it, alpha > 0, each
/// pixel at most once.
fn draw(clip: ClipRect, draw: impl FnOnce(&mut Grid)) -> Vec<u8> {
    let mut g = Grid { clip, alpha: vec![0; (W * H) as usize] };
    draw(&mut g);
    g.alpha
}

struct Grid {
    clip: ClipRect,
    alpha: Vec<u8>,
}

impl Grid {
    fn put(&mut self, s: Span, a: u8) {
        let c = self.clip;
        assert!(a > 0 && s.len > 0, "{s:?} alpha {a}");
        assert!(
            s.y >= c.y0() && s.y < c.y1() && s.x >= c.x0() && s.x + s.len as i32 <= c.x1(),
            "{s:?} outside {c:?}"
        );
        for x in s.x..s.x + s.len as i32 {
            let p = &mut self.alpha[((s.y - c.y0()) * W + x - c.x0()) as usize];
            assert_eq!(*p, 0, "({x}, {}) written twice", s.y);
            *p = a;
        }
    }
}

impl Canvas<Gray8> for Grid {
    fn clip(&self) -> ClipRect {
        self.clip
    }
    fn fill(&mut self, s: Span, _: Gray8, a: u8) {
        self.put(s, a)
    }
    fn shade<I: Iterator<Item = Gray8>>(&mut self, s: Span, _: I, a: u8) {
        self.put(s, a)
    }
}

/// True if `p1` and `p3` lie strictly on either side of the line `p0 p2`:
/// the triangles `p0 p1 p2` and `p0 p2 p3` then share only that edge, and
/// their union is the (simple) quadrilateral. Exact in `i128`.
fn splits(q: &[(i64, i64)]) -> bool {
    let cross = |o: (i64, i64), a: (i64, i64), b: (i64, i64)| {
        i128::from(a.0 - o.0) * i128::from(b.1 - o.1) - i128::from(a.1 - o.1) * i128::from(b.0 - o.0)
    };
    let (s1, s3) = (cross(q[0], q[2], q[1]), cross(q[0], q[2], q[3]));
    s1 != 0 && s3 != 0 && (s1 > 0) != (s3 > 0)
}

/// Area of the triangle `t` (pixels) inside the unit pixel at `(x, y)`:
/// Sutherland–Hodgman on the stack (a triangle clipped by four sides has at
/// most 7 vertices), then the shoelace formula.
fn pixel_area(t: &[(f64, f64)], x: f64, y: f64) -> f64 {
    let mut poly = [(0.0, 0.0); 8];
    let mut n = t.len();
    for (i, p) in t.iter().enumerate() {
        poly[i] = (p.0 - x, p.1 - y);
    }
    for (axis, v, keep_above) in [(0, 0.0, true), (0, 1.0, false), (1, 0.0, true), (1, 1.0, false)] {
        let inside = |p: (f64, f64)| {
            let c = if axis == 0 { p.0 } else { p.1 };
            if keep_above { c >= v } else { c <= v }
        };
        let (mut out, mut m) = ([(0.0, 0.0); 8], 0);
        for i in 0..n {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            if inside(a) {
                out[m] = a;
                m += 1;
            }
            if inside(a) != inside(b) {
                let (ca, cb) = if axis == 0 { (a.0, b.0) } else { (a.1, b.1) };
                let s = (v - ca) / (cb - ca);
                out[m] = (a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1));
                m += 1;
            }
        }
        (poly, n) = (out, m);
        if n == 0 {
            return 0.0;
        }
    }
    let s: f64 = (0..n).map(|i| poly[i].0 * poly[(i + 1) % n].1 - poly[(i + 1) % n].0 * poly[i].1).sum();
    (s / 2.0).abs()
}
