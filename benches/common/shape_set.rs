//! Where the shapes bench (`benches/shapes.rs`) and its instruction counts
//! (`examples/shape_counts.rs`) place their 24 instances of each shape.

use super::{H, W};

/// Instance `k`: centre, size (8 to 120 px), spread over the frame.
pub fn place(k: usize) -> ((f32, f32), f32) {
    let size = 8.0 + (k * 37 % 113) as f32;
    let (x, y) = ((k * 53 % W) as f32, (k * 29 % H) as f32);
    ((x, y), size)
}

/// The box of instance `k` (rectangles, rounded rectangles, ellipses):
/// left, top, width, height.
pub fn bounds(k: usize) -> (f32, f32, f32, f32) {
    let (c, s) = place(k);
    (c.0 - s / 2.0, c.1 - s / 3.0, s, s / 1.5)
}
