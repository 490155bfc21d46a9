// error: band width and height must be 1..=MAX_FRAME_DIM
// A band of zero rows is rejected when the band is built.
use embedded_graphics_core::pixelcolor::BinaryColor;
use microraster::Band;

fn main() {
    let band = Band::<BinaryColor, 16, 0>::new(BinaryColor::Off);
    let _ = band.rows();
}
