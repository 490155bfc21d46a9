// error: subpixel bits must be 0..=8
// The vertex stage snaps into SubPoint<S>: an unsupported S fails there.
use embedded_graphics_core::pixelcolor::Gray8;
use microraster::math::Mat4;
use microraster::mesh::Mesh;
use microraster::pipeline::Pipeline;
use microraster::raster3d::ScreenTriangle;

fn main() {
    let p = Pipeline::<f32, 9>::new(Mat4::IDENTITY, Mat4::IDENTITY, 1.0, 32, 32).unwrap();
    let mesh = Mesh::new(&[], &[], &[], ([0.0; 3], 0.0));
    let mut bins = heapless::Vec::<ScreenTriangle<9>, 4>::new();
    let _ = p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(1), &mut bins);
}
