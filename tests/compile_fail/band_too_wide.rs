// error: band width and height must be 1..=MAX_FRAME_DIM
// MAX_FRAME_DIM is 4096: a 4097-pixel band is rejected.
use embedded_graphics_core::pixelcolor::BinaryColor;
use microraster::Band;

static BAND: Band<BinaryColor, 4097, 1> = Band::new(BinaryColor::Off);

fn main() {
    let _ = BAND.rows();
}
