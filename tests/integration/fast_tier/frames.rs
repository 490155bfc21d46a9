//! Whole frames of the two accuracy tiers compared pixel by pixel (shared
//! with `tests/bench_mesh.rs`, which draws the knot): each frame is drawn
//! in one band the height of the frame, so its depth buffer is the whole
//! frame's afterwards.
//!
//! A pixel covered in both frames by the same surface (depth codes within
//! one) must have each RGB565 channel within one of the exact tier's on at
//! least 99.9 % of such pixels and within two on all of them. Elsewhere the
//! fast tier's snapped vertices moved an edge across the pixel centre: a
//! pixel covered in one frame only, or by another surface (an occluding
//! edge moved); those must stay rare (at most 1 % of the covered pixels).

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::depth::{Depth16, DepthBand};

/// A frame's colours and 16-bit depth codes, row by row.
pub(crate) struct Frame {
    pub(crate) colors: Vec<Rgb565>,
    pub(crate) depth: Vec<u32>,
}

impl Frame {
    /// The frame of `colors` and the whole-frame `depth` band.
    pub(crate) fn new<const W: usize, const H: usize>(
        colors: Vec<Rgb565>,
        depth: &DepthBand<Depth16, W, H>,
    ) -> Self {
        let depth =
            (0..H).flat_map(|y| (0..W).map(move |x| (y, x))).map(|(y, x)| depth.get(y, x).unwrap()).collect();
        Frame { colors, depth }
    }
}

/// What [`compare`] found.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Diff {
    /// Pixels covered (depth written) in either frame.
    pub(crate) covered: usize,
    /// Covered in both by the same surface.
    pub(crate) same: usize,
    /// Of those, with every channel within one.
    pub(crate) within_one: usize,
    /// The largest channel difference on the same surface.
    pub(crate) worst: i32,
    /// Covered in one frame only, or by another surface.
    pub(crate) moved: usize,
    /// Same-surface pixels whose colour differs at all.
    pub(crate) differ: usize,
}

impl core::ops::AddAssign for Diff {
    fn add_assign(&mut self, o: Diff) {
        self.covered += o.covered;
        self.same += o.same;
        self.within_one += o.within_one;
        self.worst = self.worst.max(o.worst);
        self.moved += o.moved;
        self.differ += o.differ;
    }
}

/// `exact` and `fast` pixel by pixel; `clear` is the depth of an empty
/// pixel.
pub(crate) fn compare(exact: &Frame, fast: &Frame, clear: u32) -> Diff {
    let mut d = Diff::default();
    for i in 0..exact.colors.len() {
        let (ze, zf) = (exact.depth[i], fast.depth[i]);
        if ze == clear && zf == clear {
            continue;
        }
        d.covered += 1;
        if ze == clear || zf == clear || (i64::from(ze) - i64::from(zf)).abs() > 1 {
            d.moved += 1;
            continue;
        }
        d.same += 1;
        let (a, b) = (exact.colors[i], fast.colors[i]);
        let diff = [(a.r(), b.r()), (a.g(), b.g()), (a.b(), b.b())]
            .map(|(p, q)| (i32::from(p) - i32::from(q)).abs())
            .into_iter()
            .max()
            .unwrap_or(0);
        d.worst = d.worst.max(diff);
        d.within_one += usize::from(diff <= 1);
        d.differ += usize::from(diff > 0);
    }
    d
}

/// The bounds of the module docs, with `what` in the message.
pub(crate) fn check(d: &Diff, what: &str) {
    assert!(d.worst <= 2, "{what}: a channel {} away on the same surface ({d:?})", d.worst);
    assert!(d.within_one * 1000 >= d.same * 999, "{what}: under 99.9 % within one ({d:?})");
    assert!(d.moved * 100 <= d.covered, "{what}: {} of {} px moved ({d:?})", d.moved, d.covered);
}
