//! Shapes (`microraster::shape`), aliased: the same pixels as the triangle
//! core for triangles, exact partitions where shapes share edges, curves
//! within the stated tolerance of the true curve, band invariance, and
//! typed errors for bad input.

mod angles;
mod bad_input;
mod bands_and_gradients;
mod coverage;

use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::ClipRect;
use microraster::edge::Span;
use microraster::shape::{Canvas, Coverage, Shape, ShapeStyle, Styled, TOLERANCE};

pub const W: i32 = 64;
pub const H: i32 = 48;
/// Chords inside the curve by at most TOLERANCE, vertices snapped by at most
/// √2/32 px, plus f32 slack.
pub const CURVE_MARGIN: f64 = TOLERANCE as f64 + 0.044_2 + 1e-3;

/// Records every write: hit counts and the last alpha per pixel.
pub struct Grid {
    pub clip: ClipRect,
    pub hits: Vec<u32>,
    pub alpha: Vec<u32>,
}

impl Grid {
    pub fn new() -> Self {
        Self::with_clip(ClipRect::new(0, 0, W, H))
    }
    pub fn with_clip(clip: ClipRect) -> Self {
        Grid { clip, hits: vec![0; (W * H) as usize], alpha: vec![0; (W * H) as usize] }
    }
    pub fn at(&self, x: i32, y: i32) -> u32 {
        self.hits[(y * W + x) as usize]
    }
    pub fn alpha_at(&self, x: i32, y: i32) -> u32 {
        self.alpha[(y * W + x) as usize]
    }
    fn put(&mut self, span: Span, alpha: u8) {
        assert!(span.y >= self.clip.y0() && span.y < self.clip.y1(), "row {} outside the clip", span.y);
        assert!(
            span.x >= self.clip.x0() && span.x + span.len as i32 <= self.clip.x1(),
            "{span:?} outside the clip"
        );
        for x in span.x..span.x + span.len as i32 {
            let i = (span.y * W + x) as usize;
            self.hits[i] += 1;
            self.alpha[i] += u32::from(alpha);
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
    fn shade<I: Iterator<Item = Gray8>>(&mut self, span: Span, _: I, alpha: u8) {
        self.put(span, alpha);
    }
}

pub fn draw<S: Shape, A: Coverage>(shape: S, style: ShapeStyle<Gray8, A>) -> Grid {
    let mut g = Grid::new();
    Styled::new(shape, style).unwrap().draw_on(&mut g);
    g
}

pub fn fill() -> ShapeStyle<Gray8> {
    ShapeStyle::fill(Gray8::WHITE)
}

/// A point on the 1/16 px grid, sometimes on whole or half pixels (ties).
pub fn grid_point(rng: &mut Rng, lo: f64, hi: f64, ties: bool) -> (f32, f32) {
    let mut p = (rng.uniform(lo, hi), rng.uniform(lo, hi) * H as f64 / W as f64);
    if ties {
        p = ((p.0 * 2.0).round() / 2.0, (p.1 * 2.0).round() / 2.0);
    }
    (((p.0 * 16.0).round() / 16.0) as f32, ((p.1 * 16.0).round() / 16.0) as f32)
}
