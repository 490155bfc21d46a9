// error: mismatched types
// The colour band and the depth band must have the same W and H.
use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::render::Triangles3d;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::{Band, Renderer};

fn main() {
    let mut band = Band::<Gray8, 32, 16>::new(Gray8::new(0));
    let mut depth = DepthBand::<Depth16, 32, 8>::new();
    let mut display = MockDisplay::<Gray8>::new();
    let tris: [ScreenTriangle<4>; 0] = [];
    let _ = Renderer::new(32, Gray8::new(0)).render(Triangles3d::new(&tris, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut display);
}
