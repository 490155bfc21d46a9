// error: pixel centres need at least one subpixel bit
use microraster::SubPoint;

fn main() {
    let _ = SubPoint::<0>::pixel_center(3, 4);
}
