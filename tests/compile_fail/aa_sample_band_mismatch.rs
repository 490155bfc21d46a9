// error: anti-aliasing needs a supported N and a sample band of W·COLS × H·N
use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::aa::Antialiased;
use microraster::aa::Ssaa;
use microraster::{Band, Primitive, Renderer};

fn main() {
    // 4 × 4 samples a pixel need a 64 × 16 sample band, not 32 × 16.
    let mut samples = Band::<Gray8, 32, 16>::new(Gray8::new(0));
    let mut out = Band::<Gray8, 16, 4>::new(Gray8::new(0));
    let mut display = MockDisplay::<Gray8>::new();
    let scene: [Primitive<Gray8, 4>; 0] = [];
    let _ = Renderer::new(16, Gray8::new(0)).render(Antialiased::new(Ssaa::<4>, &scene, &mut samples), &mut out, &mut display);
}
