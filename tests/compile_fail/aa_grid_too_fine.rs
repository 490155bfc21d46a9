// error: anti-aliasing needs a supported N and a sample band of W·COLS × H·N
use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::aa::Antialiased;
use microraster::aa::Msaa;
use microraster::{Band, Primitive, Renderer};

fn main() {
    // N = 9 is beyond MAX_GRID, even with matching bands.
    let mut samples = Band::<Gray8, 36, 18>::new(Gray8::new(0));
    let mut out = Band::<Gray8, 4, 2>::new(Gray8::new(0));
    let mut display = MockDisplay::<Gray8>::new();
    let scene: [Primitive<Gray8, 4>; 0] = [];
    let _ = Renderer::new(4, Gray8::new(0)).render(Antialiased::new(Msaa::<9>, &scene, &mut samples), &mut out, &mut display);
}
