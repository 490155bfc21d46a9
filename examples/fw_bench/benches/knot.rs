//! The 20k-triangle knot through the meshlet stage: whole frames, taller
//! bands, and the frame stopped after one stage (Cortex-M4F only).

use core::hint::black_box;

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand};
use microraster::edge::Cull;
use microraster::light::Viewer::{self, Local};
use microraster::math::Scalar;
use microraster::pipeline::ClusterCache;
use microraster::raster3d::{Affine, Interpolation};
use microraster::render::{Direct3d, from_fn};
use microraster::{Band, Error, Renderer};
use microraster_scenes::scenes3d::Scene3d;

use super::frame::{Tall, input};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::knot_mesh;
use super::{Sink, Stage, TALL_20, TALL_48, TALL_240};
use crate::workload::{ANGLE, DEPTH_STATE, S};

/// [`Work::KnotTall`](super::Work::KnotTall). Not inlined: its frames' locals would enlarge
/// [`frame`](super::frame())'s stack frame, and so every row's stack figure.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[inline(never)]
pub(super) fn knot_tall<const W: usize>(
    r: Renderer<Rgb565>,
    rows: u16,
    t: &mut Tall<'_, W>,
    cache: &mut ClusterCache<f32, S>,
    sink: &mut Sink,
) -> Result<(), Error> {
    match rows as usize {
        TALL_20 => meshlets::<f32, _, W, TALL_20>(r, t.band20, t.depth20, cache, Affine, Local, sink),
        TALL_48 => meshlets::<f32, _, W, TALL_48>(r, t.band48, t.depth48, cache, Affine, Local, sink),
        TALL_240 => meshlets::<f32, _, W, TALL_240>(r, t.band240, t.depth240, cache, Affine, Local, sink),
        _ => Err(Error::InvalidParameter(microraster::Param::User)),
    }
}

/// [`Work::KnotVertexRows`](super::Work::KnotVertexRows): the knot's `f32` vertex stage for bands of
/// `rows` rows, each band's triangles only counted (not inlined, as
/// [`knot_tall`]).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[inline(never)]
pub(super) fn knot_vertex_rows<const W: usize>(
    height: u32,
    rows: u16,
    cache: &mut ClusterCache<f32, S>,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, height)?;
    let model = knot_model::<f32>();
    let (mut y0, height) = (0, height as i32);
    while y0 < height {
        let y1 = (y0 + i32::from(rows.max(1))).min(height);
        let mut n = 0u32;
        pipeline.meshlet_triangles(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, (y0, y1 - 1), |t| {
            n += black_box(t).v[0].depth >> 16
        })?;
        black_box(n);
        y0 = y1;
    }
    Ok(())
}

/// [`Work::KnotStage`](super::Work::KnotStage): the knot's frame up to `stage`.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
pub(super) fn knot_stage<T: Scalar, const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    cache: &mut ClusterCache<T, S>,
    stage: Stage,
    sink: &mut Sink,
) -> Result<(), Error> {
    use microraster::depth::{DepthState, DepthTest};
    use microraster::{ClipRect, edge::TriangleSpans};
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, r.height())?;
    let model = knot_model::<T>();
    let never = DepthState::new(DepthTest::Never, false);
    let coverage = matches!(stage, Stage::Coverage);
    let mut result = Ok(());
    match stage {
        Stage::Vertex | Stage::Coverage => r.render(
            from_fn(|view| {
                let (y0, y1) = (view.y0(), view.y1());
                let clip = ClipRect::new(0, y0, W as i32, y1);
                let mut n = 0u32;
                let s = pipeline.meshlet_triangles(
                    &knot_mesh::VALID_KNOT,
                    &model,
                    KNOT_COLOR,
                    cache,
                    (y0, y1 - 1),
                    |t| {
                        n += if coverage {
                            TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None)
                                .map(|s| s.len)
                                .sum::<u32>()
                        } else {
                            black_box(t).v[0].depth >> 16
                        };
                    },
                );
                black_box(n);
                if result.is_ok() {
                    result = s.map(|_| ());
                };
                Ok(())
            }),
            band,
            sink,
        ),
        Stage::NoWrites => r.render(
            Direct3d::new(depth, never, Affine, |band| {
                pipeline.draw_meshlets(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, band).map(|_| ())
            }),
            band,
            sink,
        ),
    }
    .map_err(input)?;
    result
}

/// The knot through the meshlet stage, drawn straight into each band, with
/// the specular term's viewer at `viewer`.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[allow(clippy::too_many_arguments)]
pub(super) fn meshlets<T: Scalar, M: Interpolation, const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    depth: &mut DepthBand<Depth16, W, H>,
    cache: &mut ClusterCache<T, S>,
    interp: M,
    viewer: Viewer,
    sink: &mut Sink,
) -> Result<(), Error> {
    let mut pipeline = Scene3d::pipeline::<T, S>(W as u32, r.height())?;
    pipeline.lighting = pipeline.lighting.map(|l| l.with_viewer(viewer));
    let model = knot_model::<T>();
    r.render(
        Direct3d::new(depth, DEPTH_STATE, interp, |band| {
            pipeline.draw_meshlets(&knot_mesh::VALID_KNOT, &model, KNOT_COLOR, cache, band).map(|_| ())
        }),
        band,
        sink,
    )
    .map_err(input)
}

/// The knot's colour and placement in the standard scene's camera.
pub const KNOT_COLOR: Rgb565 = Rgb565::new(27, 46, 12);

/// The knot's model matrix: turned by the scene's angle about y.
pub fn knot_model<T: Scalar>() -> microraster::math::Mat4<T> {
    microraster::math::transform::rotation_y(T::from_f32(ANGLE))
}
