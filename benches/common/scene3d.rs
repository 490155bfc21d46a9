//! The standard 3D scene (benchmark scene 4) through microraster: the vertex
//! stage and `Triangles3d` ([`mr3d`]), its pipeline, models and materials.

use super::{ANGLE, Frame, H, W};
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{DepthBand, DepthFormat, DepthState};
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::Mesh;
use microraster::pipeline::Pipeline;
use microraster::raster3d::{Interpolation, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Interpolate, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d};

/// The frame's bins.
pub type Bins<const S: u32> = heapless::Vec<ScreenTriangle<S>, BINS>;

/// Background of the 3D frames.
pub const BG3: Rgb565 = Rgb565::BLACK;

/// The standard 3D scene at [`ANGLE`]: the vertex stage on path `T` into
/// `bins`, then `Triangles3d` with `BH`-row bands, depth format `F` and colour
/// interpolation `M` into `target`. Returns the number of screen triangles.
pub fn mr3d<T: Scalar, F: DepthFormat, M: Interpolation, const S: u32, const BH: usize>(
    pipeline: &Pipeline<T, S>,
    bins: &mut Bins<S>,
    band: &mut Band<Rgb565, W, BH>,
    depth: &mut DepthBand<F, W, BH>,
    target: &mut impl Frame,
) -> usize {
    bins.clear();
    Scene3d.draw::<T, Rgb565, S, BINS>(pipeline, ANGLE, bins).unwrap();
    Renderer::new(H as u32, BG3)
        .render(Triangles3d::new(bins, depth, DepthState::LESS_WRITE, M::default()), band, target)
        .unwrap();
    bins.len()
}

/// The standard scene's pipeline for the `W × H` frame.
pub fn pipeline3d<T: Scalar, const S: u32>() -> Pipeline<T, S> {
    Scene3d::pipeline::<T, S>(W as u32, H as u32).unwrap()
}

/// The model matrix and material colour of mesh `k` (sphere, torus, cube) at
/// `angle`, as `Scene3d::draw` builds them (`scenes/src/scenes3d.rs`; the report
/// checks that drawing with these reproduces `Scene3d::draw`'s bins).
pub fn model<T: Scalar>(k: usize, angle: f32) -> (Mat4<T>, [f32; 3]) {
    let f = T::from_f32;
    let s = |v: f32| transform::scaling(Vec3::new(f(v), f(v), f(v)));
    match k {
        0 => (transform::rotation_y(f(angle)) * s(1.45), [0.9, 0.35, 0.2]),
        1 => (transform::rotation_y(f(angle * 0.5)) * transform::rotation_x(f(0.45)), [0.25, 0.6, 0.95]),
        _ => (
            transform::translation(Vec3::new(f(1.05), f(-0.5), f(1.25)))
                * transform::rotation_y(f(-angle))
                * s(0.55),
            [0.95, 0.85, 0.3],
        ),
    }
}

/// The material colour as `Scene3d::draw` quantizes it for `C`.
pub fn material<C: Interpolate>(rgb: [f32; 3]) -> C {
    let m = C::CHANNEL_MAX;
    C::from_channels([0, 1, 2].map(|k| (rgb[k] * m[k] as f32 + 0.5) as u8))
}

/// Marker so the f32 and Fx paths can be named in tables.
pub fn path_name<T: Scalar>() -> &'static str {
    if core::any::type_name::<T>() == core::any::type_name::<Fx>() { "Fx" } else { "f32" }
}

/// The standard scene's vertex stage one source triangle at a time, so that
/// every screen triangle knows where it came from: returns the bins (equal to
/// `Scene3d::draw`'s, which is checked) and, per bin, the source id
/// `mesh · 65536 + index`.
pub fn bins_with_ids<T: Scalar, C: Interpolate, const S: u32>(
    pipeline: &Pipeline<T, S>,
    angle: f32,
) -> (Bins<S>, Vec<u32>) {
    let mut bins = Bins::<S>::new();
    let mut ids = Vec::new();
    for (k, mesh) in Scene3d.meshes().iter().enumerate() {
        let (m, rgb) = model::<T>(k, angle);
        for i in 0..mesh.indices.len() {
            let one = Mesh { indices: &mesh.indices[i..i + 1], ..*mesh };
            let before = bins.len();
            pipeline.draw_mesh(&one, &m, material::<C>(rgb), &mut bins).unwrap();
            ids.extend(core::iter::repeat_n((k as u32) << 16 | i as u32, bins.len() - before));
        }
    }
    let mut whole = Bins::<S>::new();
    Scene3d.draw::<T, C, S, BINS>(pipeline, angle, &mut whole).unwrap();
    assert!(whole == bins, "per-triangle vertex stage differs from Scene3d::draw");
    (bins, ids)
}
