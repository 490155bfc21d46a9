// error: subpixel bits must be 0..=8
// Nine fractional bits would break the overflow proofs (±2^28 range).
use microraster::SubPoint;

fn main() {
    let _ = SubPoint::<9>::new(0, 0);
}
