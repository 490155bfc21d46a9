// error: band width and height must be 1..=MAX_FRAME_DIM
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Band;

fn main() {
    let _band = Band::<Rgb565, 0, 16>::new(Rgb565::new(0, 0, 0));
}
