//! Anti-aliased coverage of polygons with far vertices (issue #60, item 7):
//! triangles crossing a 128 × 128 frame with one or two vertices D px away,
//! D = 10^2 … 10^7 and ±(2^24 − 1) px (the edge of the ±2^28-subpixel
//! range), against the exact area of each pixel in `f64`.
//!
//! The reference translates the (1/16 px, hence exact in `f64`) vertices to
//! the pixel before clipping, so its error is about 2^-28 px², far below
//! the bound checked: `|alpha − 255 · area| ≤ ½ + 1/256` (`area.rs`), and
//! no alpha outside the triangle's bounding box.

use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::ClipRect;
use microraster::edge::Span;
use microraster::shape::{Canvas, Polygon, Shape, ShapeStyle};

const F: i32 = 128;
/// The documented bound beyond 8-bit rounding, in levels.
const SLACK: f64 = 1.0 / 256.0;
const FAR: f64 = 16_777_215.0; // 2^24 − 1 px = 2^28 − 16 subpixels

/// Alpha per pixel of a 128 × 128 frame; a pixel written twice fails.
struct Frame {
    alpha: Vec<u8>,
}

impl Frame {
    fn put(&mut self, s: Span, a: u8) {
        assert!((0..F).contains(&s.y) && s.x >= 0 && s.x + s.len as i32 <= F, "{s:?} outside the clip");
        for x in s.x..s.x + s.len as i32 {
            let p = &mut self.alpha[(s.y * F + x) as usize];
            assert_eq!(*p, 0, "({x}, {}) written twice", s.y);
            *p = a;
        }
    }
}

impl Canvas<Gray8> for Frame {
    fn clip(&self) -> ClipRect {
        ClipRect::new(0, 0, F, F)
    }
    fn fill(&mut self, s: Span, _: Gray8, a: u8) {
        self.put(s, a)
    }
    fn shade<I: Iterator<Item = Gray8>>(&mut self, s: Span, _: I, a: u8) {
        self.put(s, a)
    }
}

/// Area of the triangle `t` inside the unit pixel at `(x, y)`: the
/// vertices moved to the pixel first (exact on the 1/16 px grid, so far
/// vertices lose nothing), then the shared clip-and-shoelace reference.
fn pixel_area(t: &[(f64, f64); 3], x: f64, y: f64) -> f64 {
    super::antialiased::pixel_area(&t.map(|p| (p.0 - x, p.1 - y)), 0.0, 0.0)
}

/// `v` on the 1/16 px grid and exactly an `f32` (every `f32` of magnitude
/// ≥ 2^19 already is a multiple of 1/16).
fn on_grid(v: f64) -> f64 {
    let g = f64::from(((v * 16.0).round() / 16.0) as f32);
    assert_eq!(g * 16.0, (g * 16.0).round());
    g
}

/// Worst `|alpha − 255 · area|` over the frame, after checking the bound
/// and the bounding box; also how many pixels were partial.
fn check(t: [(f64, f64); 3]) -> (f64, usize) {
    let pts = t.map(|p| (p.0 as f32, p.1 as f32));
    let mut frame = Frame { alpha: vec![0; (F * F) as usize] };
    Polygon::new(&pts)
        .unwrap()
        .styled(ShapeStyle::fill(Gray8::WHITE).antialiased())
        .unwrap()
        .draw_on(&mut frame);
    let (x_lo, x_hi) =
        (t.iter().map(|p| p.0).fold(f64::MAX, f64::min), t.iter().map(|p| p.0).fold(f64::MIN, f64::max));
    let (y_lo, y_hi) =
        (t.iter().map(|p| p.1).fold(f64::MAX, f64::min), t.iter().map(|p| p.1).fold(f64::MIN, f64::max));
    let (mut worst, mut partial) = (0.0f64, 0);
    for y in 0..F {
        for x in 0..F {
            let a = f64::from(frame.alpha[(y * F + x) as usize]);
            let (fx, fy) = (f64::from(x), f64::from(y));
            if fx + 1.0 <= x_lo || fx >= x_hi || fy + 1.0 <= y_lo || fy >= y_hi {
                assert_eq!(a, 0.0, "{t:?}: ({x}, {y}) outside the bounding box has alpha {a}");
                continue;
            }
            let area = pixel_area(&t, fx, fy);
            let err = (a - 255.0 * area).abs();
            assert!(
                err <= 0.5 + SLACK,
                "{t:?}: ({x}, {y}) alpha {a}, exact area {area} (255·area {})",
                255.0 * area
            );
            worst = worst.max(err);
            partial += (area > 0.0 && area < 1.0) as usize;
        }
    }
    (worst, partial)
}

#[test]
fn antialiased_area_is_exact_with_far_vertices() {
    let mut rng = Rng::new(0xfa7);
    let mut partial = 0;
    for d in [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, FAR] {
        for k in 0..6 {
            let near = |rng: &mut Rng| (on_grid(rng.uniform(-8.0, 136.0)), on_grid(rng.uniform(-8.0, 136.0)));
            let a = rng.uniform(0.0, std::f64::consts::TAU);
            // Far enough to stay on a grid point at distance d, clamped to the range.
            let far = |a: f64| {
                let c = |v: f64| on_grid(v.clamp(-FAR, FAR));
                (c(64.0 + d * a.cos()), c(64.0 + d * a.sin()))
            };
            let t = if k % 2 == 0 {
                [near(&mut rng), near(&mut rng), far(a)]
            } else {
                // Two far vertices either side of the frame's direction.
                let spread = rng.uniform(0.05, 1.0);
                [near(&mut rng), far(a), far(a + spread)]
            };
            partial += check(t).1;
        }
    }
    // The range's corners and edges exactly.
    for (p, q) in [((FAR, FAR), (-FAR, 100.0)), ((-FAR, -FAR), (FAR, 3.0)), ((FAR, 0.5), (FAR, 127.5))] {
        partial += check([(10.0625, 20.5), p, q]).1;
        partial += check([(120.9375, 64.25), q, p]).1;
    }
    assert!(partial > 2000, "{partial} partial pixels");
}
