// error: the linked band loop needs at least two bands
// Double-banded rendering with a single band: nothing could render while the
// band is on the wire. One band is `Renderer::render`.
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::render::from_fn;
use microraster::{Band, Renderer};

fn main() {
    let mut bands = [Band::<Gray8, 8, 4>::new(Gray8::new(0))];
    let _ = Renderer::new(8, Gray8::new(0)).render_linked((), &mut bands, &mut ());
}
