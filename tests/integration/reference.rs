//! Independent reference rasterizers, coverage bitmaps, a PRNG and generators.
//!
//! Written from the specification (pixel `(X, Y)` sampled at `(X+0.5, Y+0.5)`,
//! top-left rule of D3D11.3 §3.4.2.1), not from `src/raster/edge.rs`, so agreement
//! between the two means something. Everything here is brute force: one
//! exact `i128` evaluation of each edge function per pixel centre.

mod generators;
mod triangle;

pub use generators::{random_clip, random_triangle};
pub use triangle::{
    ExactTriangle, TieRule, coverage_and_ties, coverage_with, culled, dist_to_edges, dist_to_segment,
    exact_coverage, float_inside,
};

use microraster::ClipRect;
use microraster::edge::Span;

/// SplitMix64: tiny, deterministic, good enough for test-case generation.
#[derive(Clone)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `0..n`, `n > 0`.
    pub fn below(&mut self, n: u64) -> u64 {
        ((self.next_u64() as u128 * n as u128) >> 64) as u64
    }
    /// Uniform in `lo..=hi`.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }
    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + self.unit() * (hi - lo)
    }
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    /// Log-uniform in `[lo, hi)`.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

/// A set of pixels of one clip rectangle, as a row-major bitmap.
#[derive(Clone, PartialEq, Eq)]
pub struct Coverage {
    pub clip: ClipRect,
    w: usize,
    bits: Vec<bool>,
}

impl Coverage {
    pub fn new(clip: ClipRect) -> Self {
        let w = (clip.x1() - clip.x0()).max(0) as usize;
        let h = (clip.y1() - clip.y0()).max(0) as usize;
        Coverage { clip, w, bits: vec![false; w * h] }
    }
    fn index(&self, x: i32, y: i32) -> usize {
        assert!(self.clip.contains(x, y), "pixel ({x}, {y}) outside {:?}", self.clip);
        (y - self.clip.y0()) as usize * self.w + (x - self.clip.x0()) as usize
    }
    pub fn get(&self, x: i32, y: i32) -> bool {
        self.bits[self.index(x, y)]
    }
    /// Marks a pixel; returns whether it was already marked.
    pub fn set(&mut self, x: i32, y: i32) -> bool {
        let i = self.index(x, y);
        std::mem::replace(&mut self.bits[i], true)
    }
    pub fn count(&self) -> usize {
        self.bits.iter().filter(|&&b| b).count()
    }
    pub fn is_empty(&self) -> bool {
        !self.bits.contains(&true)
    }
    /// Covered pixels, row by row.
    pub fn pixels(&self) -> impl Iterator<Item = (i32, i32)> + '_ {
        let (x0, y0, w) = (self.clip.x0(), self.clip.y0(), self.w.max(1));
        let f = move |(i, _): (usize, &bool)| (x0 + (i % w) as i32, y0 + (i / w) as i32);
        self.bits.iter().enumerate().filter(|(_, b)| **b).map(f)
    }
    /// First pixel `(x, y, self, other)` where the two differ.
    pub fn first_difference(&self, other: &Coverage) -> Option<(i32, i32, bool, bool)> {
        assert_eq!(self.clip, other.clip);
        let i = self.bits.iter().zip(&other.bits).position(|(a, b)| a != b)?;
        let (x, y) = (self.clip.x0() + (i % self.w) as i32, self.clip.y0() + (i / self.w) as i32);
        Some((x, y, self.bits[i], other.bits[i]))
    }
}

/// Collects spans into a [`Coverage`], checking the iterator contract: rows
/// strictly top to bottom (a triangle meets a row in one interval), `len ≥ 1`,
/// every pixel inside `clip`, no pixel twice.
pub fn spans_coverage(spans: impl IntoIterator<Item = Span>, clip: ClipRect) -> Coverage {
    let mut cov = Coverage::new(clip);
    let mut prev_y = i32::MIN;
    for s in spans {
        assert!(s.len >= 1, "empty span {s:?}");
        assert!(s.y > prev_y, "span {s:?} not below the previous row {prev_y}");
        prev_y = s.y;
        for x in s.x..s.x + s.len as i32 {
            assert!(clip.contains(x, s.y), "span {s:?} leaves clip {clip:?}");
            assert!(!cov.set(x, s.y), "span {s:?} overlaps an earlier span");
        }
    }
    cov
}
