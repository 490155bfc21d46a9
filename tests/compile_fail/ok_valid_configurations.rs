// pass
// The control case: the valid neighbours of every error above compile.
use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8};
use microraster::aa::Antialiased;
use microraster::render::Triangles3d;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::math::Mat4;
use microraster::mesh::Mesh;
use microraster::pipeline::Pipeline;
use microraster::raster3d::{Affine, ScreenTriangle};
use microraster::{Band, Renderer, SubPoint};

static WIDE: Band<BinaryColor, 4096, 1> = Band::new(BinaryColor::Off);

fn main() {
    let _ = WIDE.rows();
    let _ = Band::<BinaryColor, 1, 1>::new(BinaryColor::Off);
    let _ = DepthBand::<Depth16, 320, 1>::new();
    let _ = SubPoint::<8>::new(0, 0);
    let _ = SubPoint::<0>::from_f32(1.5, 2.5);
    let _ = SubPoint::<1>::pixel_center(3, 4);
    let p = Pipeline::<f32, 8>::new(Mat4::IDENTITY, Mat4::IDENTITY, 1.0, 32, 32).unwrap();
    let mesh = Mesh::new(&[], &[], &[], ([0.0; 3], 0.0));
    let mut bins = heapless::Vec::<ScreenTriangle<8>, 4>::new();
    let _ = p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(1), &mut bins);
    let mut band = Band::<Gray8, 32, 16>::new(Gray8::new(0));
    let mut depth = DepthBand::<Depth16, 32, 16>::new();
    let mut display = MockDisplay::<Gray8>::new();
    let _ = Renderer::new(16, Gray8::new(0)).render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut display);
    // Anti-aliasing: the sample bands of the two aa_* cases, made consistent.
    let scene: [microraster::Primitive<Gray8, 4>; 0] = [];
    let mut samples = Band::<Gray8, 64, 16>::new(Gray8::new(0));
    let mut out = Band::<Gray8, 16, 4>::new(Gray8::new(0));
    let _ = Renderer::new(16, Gray8::new(0)).render(Antialiased::new(microraster::aa::Ssaa::<4>, &scene, &mut samples), &mut out, &mut display);
    let mut samples = Band::<Gray8, 32, 16>::new(Gray8::new(0));
    let mut out = Band::<Gray8, 4, 2>::new(Gray8::new(0));
    let _ = Renderer::new(4, Gray8::new(0)).render(Antialiased::new(microraster::aa::Msaa::<8>, &scene, &mut samples), &mut out, &mut display);
}
