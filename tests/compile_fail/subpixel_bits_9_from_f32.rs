// error: subpixel bits must be 0..=8
use microraster::SubPoint;

fn main() {
    let _ = SubPoint::<12>::from_f32(1.5, 2.5);
}
