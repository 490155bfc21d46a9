// error: depth band width and height must be 1..=MAX_FRAME_DIM
use microraster::depth::{Depth16, DepthBand};

fn main() {
    let _z = DepthBand::<Depth16, 320, 0>::new();
}
