// error: subpixel bits must be 0..=8
// `SubPoint<S>`'s `Default` runs the same compile-time check as every other
// constructor, so an unsupported subpixel count cannot reach the rasterizer.
use microraster::edge::{Cull, TriangleSpans};
use microraster::{ClipRect, SubPoint};

fn main() {
    let p = SubPoint::<9>::default();
    let _ = TriangleSpans::new([p, p, p], ClipRect::new(0, 0, 4, 4), Cull::None).count();
}
