//! The configurations of the speed/accuracy report (`docs/tradeoffs.md`)
//! that the Cortex-M targets count, each under the key the report prints
//! (its "key" column): the five benchmark scenes at 320 × 240 (`scatter`,
//! `large`, `tiny`, `lines`, `mesh3d`) and every setting of the trade sweep
//! (subpixel bits, depth bits, band height, interpolation, vertex math).
//!
//! Each configuration does what the report times on the host
//! (`examples/report`, `benches/common`), into a framebuffer of the frame's
//! size: a 2D scene is collected into RAM first (untimed), then rendered in
//! bands into the framebuffer or drawn straight into it (`direct`,
//! [`TargetBlitter`]); the 3D scene runs its vertex stage into bins, then
//! `Triangles3d` (both timed), or the vertex stage alone
//! (`mesh3d/vertex/*`); the 20k-triangle knot (`knot20k/*`,
//! `examples/common/knot_mesh.rs`) goes through the meshlet stage per band
//! (`Direct3d` with [`Pipeline::draw_meshlets`], no
//! bins), as `examples/fw_bench` times it. Adding a configuration is one line
//! in [`LIST`].

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use fixed::types::I16F16;
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthBand, DepthFormat, DepthState};
use microraster::edge::Cull;
use microraster::math::{Fx, Scalar, transform};
use microraster::mesh::{MAX_MESHLET_VERTICES, ValidMeshletMesh};
use microraster::pipeline::{ClusterCache, MeshStats, Pipeline, VertexCache};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle};
use microraster::render::{Direct3d, Triangles3d};
use microraster::{Band, Error, Primitive, RenderError, Renderer, SubPoint, Triangle, blit::TargetBlitter};
use microraster_scenes::scenes::{self, FineTriangle, Scene};
use microraster_scenes::scenes3d::{BINS, Scene3d};

use crate::frame::FrameBuffer;

/// Frame width.
pub const W: usize = 320;
/// Frame height.
pub const H: usize = 240;
/// Background of every frame (the report's).
pub const BG: Rgb565 = Rgb565::BLACK;
/// Animation angle of the 3D scene (the report's and the firmware's).
pub const ANGLE: f32 = 0.6;
/// Most primitives of any 2D scene ([`scenes::TINY_LEN`]).
const PRIMS: usize = scenes::TINY_LEN;

/// Brackets the timed part of a configuration.
pub trait Meter {
    /// The timed part begins.
    fn start(&mut self);
    /// The timed part ends.
    fn stop(&mut self);
}

/// What one configuration does: prepares, calls [`Meter::start`], renders
/// one frame into the framebuffer, calls [`Meter::stop`].
pub type Run = fn(&mut dyn Meter, &mut FrameBuffer) -> Result<(), Error>;

/// One configuration under its report key.
pub struct Config {
    /// The report's key.
    pub key: &'static str,
    /// What runs.
    pub run: Run,
}

macro_rules! config {
    ($key:literal, $run:expr) => {
        Config { key: $key, run: |m, fb| $run(m, fb) }
    };
    ($key:literal, $run:expr, $scene:expr) => {
        Config { key: $key, run: |m, fb| $run($scene, m, fb) }
    };
}

type P = PerspectiveCorrect;

/// Every configuration, in the report's order.
pub const LIST: &[Config] = &[
    // The benchmark scenes (peers table).
    config!("scatter/band16/S4/flat", band2d::<4, 16>, scenes::scatter),
    config!("scatter/band16/S8/flat", band2d::<8, 16>, scenes::scatter),
    config!("scatter/direct/S4/flat", direct2d::<4>, scenes::scatter),
    config!("scatter/band16/S4/gouraud", band2d::<4, 16>, scenes::scatter_gouraud),
    config!("scatter/direct/S4/gouraud", direct2d::<4>, scenes::scatter_gouraud),
    config!("large/band16/S4/flat", band2d::<4, 16>, scenes::large),
    config!("large/band16/S8/flat", band2d::<8, 16>, scenes::large),
    config!("large/direct/S4/flat", direct2d::<4>, scenes::large),
    config!("tiny/band16/S4/flat", band2d::<4, 16>, scenes::tiny),
    config!("tiny/band16/S8/flat", band2d::<8, 16>, scenes::tiny),
    config!("tiny/direct/S4/flat", direct2d::<4>, scenes::tiny),
    config!("lines/band16/S4/flat", band2d::<4, 16>, scenes::lines),
    config!("lines/band16/S8/flat", band2d::<8, 16>, scenes::lines),
    config!("lines/direct/S4/flat", direct2d::<4>, scenes::lines),
    // The 2D sweep: scene 1 from unsnapped vertices.
    config!("scatter-fine/band16/S0/flat", fine2d::<0, 16>),
    config!("scatter-fine/band16/S2/flat", fine2d::<2, 16>),
    config!("scatter-fine/band16/S4/flat", fine2d::<4, 16>),
    config!("scatter-fine/band16/S6/flat", fine2d::<6, 16>),
    config!("scatter-fine/band16/S8/flat", fine2d::<8, 16>),
    config!("scatter-fine/band1/S4/flat", fine2d::<4, 1>),
    config!("scatter-fine/band8/S4/flat", fine2d::<4, 8>),
    config!("scatter-fine/band32/S4/flat", fine2d::<4, 32>),
    config!("scatter-fine/band240/S4/flat", fine2d::<4, H>),
    // The 3D sweep (scene 4 is `mesh3d/f32/D16/persp/band16/S4`).
    config!("mesh3d/f32/D16/persp/band16/S4", mesh3d::<f32, Depth16, P, 4, 16>),
    config!("mesh3d/f32/D16/persp/band16/S0", mesh3d::<f32, Depth16, P, 0, 16>),
    config!("mesh3d/f32/D16/persp/band16/S2", mesh3d::<f32, Depth16, P, 2, 16>),
    config!("mesh3d/f32/D16/persp/band16/S6", mesh3d::<f32, Depth16, P, 6, 16>),
    config!("mesh3d/f32/D16/persp/band16/S8", mesh3d::<f32, Depth16, P, 8, 16>),
    config!("mesh3d/f32/D8/persp/band16/S4", mesh3d::<f32, Depth8, P, 4, 16>),
    config!("mesh3d/f32/D24/persp/band16/S4", mesh3d::<f32, Depth24, P, 4, 16>),
    config!("mesh3d/f32/D32/persp/band16/S4", mesh3d::<f32, Depth32, P, 4, 16>),
    config!("mesh3d/f32/D16/persp/band1/S4", mesh3d::<f32, Depth16, P, 4, 1>),
    config!("mesh3d/f32/D16/persp/band8/S4", mesh3d::<f32, Depth16, P, 4, 8>),
    config!("mesh3d/f32/D16/persp/band32/S4", mesh3d::<f32, Depth16, P, 4, 32>),
    config!("mesh3d/f32/D16/persp/band240/S4", mesh3d::<f32, Depth16, P, 4, H>),
    config!("mesh3d/f32/D16/affine/band16/S4", mesh3d::<f32, Depth16, Affine, 4, 16>),
    config!("mesh3d/f32/D16/persp/band16/S4/cache64", mesh3d_cache64::<f32, Depth16, P, 4, 16>),
    config!("mesh3d/Fx/D16/persp/band16/S4", mesh3d::<Fx, Depth16, P, 4, 16>),
    config!("mesh3d/Fx/D16/affine/band16/S4", mesh3d::<Fx, Depth16, Affine, 4, 16>),
    config!("mesh3d/vertex/f32", vertex3d::<f32>),
    config!("mesh3d/vertex/Fx", vertex3d::<Fx>),
    // The 20k-triangle knot (issue 12): both numeric paths, both interpolations.
    config!("knot20k/f32/D16/affine/band16/S4", knot::<f32, Affine>),
    config!("knot20k/f32/D16/persp/band16/S4", knot::<f32, P>),
    config!("knot20k/Fx/D16/affine/band16/S4", knot::<Fx, Affine>),
    config!("knot20k/Fx/D16/persp/band16/S4", knot::<Fx, P>),
    // The same, the mesh stored in 16.16 (`KNOT_FX`): no conversion per vertex.
    config!("knot20k/Fx/D16/affine/band16/S4/fx-mesh", knot_fx_mesh::<Affine>),
    config!("knot20k/Fx/D16/persp/band16/S4/fx-mesh", knot_fx_mesh::<P>),
];

/// Every configuration: [`LIST`] and the fragment-stage options
/// (`fragment::LIST`).
pub fn all() -> impl Iterator<Item = &'static Config> {
    LIST.iter().chain(crate::fragment::LIST)
}

/// The input error of a render call (the framebuffer itself never fails).
pub fn input<E>(e: RenderError<E>) -> Error {
    match e {
        RenderError::Input(e) => e,
        // The framebuffer never fails.
        RenderError::Target(_) => Error::InvalidParameter(microraster::Param::User),
    }
}

/// A 2D scene collected (untimed), then rendered in `BH`-row bands.
fn band2d<const S: u32, const BH: usize>(
    scene: Scene<Rgb565, S>,
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
) -> Result<(), Error> {
    let mut prims = heapless::Vec::<Primitive<Rgb565, S>, PRIMS>::new();
    if scenes::collect(scene, W as u32, H as u32, &mut prims)? != 0 {
        return Err(Error::BufferTooSmall);
    }
    render2d::<S, BH>(&prims, m, fb)
}

fn render2d<const S: u32, const BH: usize>(
    prims: &[Primitive<Rgb565, S>],
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
) -> Result<(), Error> {
    let mut band = Band::<Rgb565, W, BH>::new(BG);
    m.start();
    let r = Renderer::new(H as u32, BG).render(prims, &mut band, fb).map_err(input);
    m.stop();
    r
}

/// A 2D scene collected (untimed), then drawn straight into the framebuffer
/// (wiped first, as the host's `mr_direct`).
fn direct2d<const S: u32>(
    scene: Scene<Rgb565, S>,
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
) -> Result<(), Error> {
    let mut prims = heapless::Vec::<Primitive<Rgb565, S>, PRIMS>::new();
    if scenes::collect(scene, W as u32, H as u32, &mut prims)? != 0 {
        return Err(Error::BufferTooSmall);
    }
    m.start();
    fb.wipe(BG);
    let mut blitter = TargetBlitter::new(fb);
    for p in &prims {
        p.draw(&mut blitter, Cull::None);
    }
    m.stop();
    Ok(())
}

/// Scene 1's unsnapped vertices snapped to `S` bits (as the report's
/// `sweep::snapped`), then rendered in `BH`-row bands.
fn fine2d<const S: u32, const BH: usize>(m: &mut dyn Meter, fb: &mut FrameBuffer) -> Result<(), Error> {
    let mut prims = heapless::Vec::<Primitive<Rgb565, S>, PRIMS>::new();
    let mut result = Ok(());
    scenes::scatter_fine(W as u32, H as u32, &mut |t: FineTriangle| {
        let snap = |(x, y): (i64, i64)| {
            SubPoint::<S>::from_fixed(I16F16::from_bits(x as i32), I16F16::from_bits(y as i32))
        };
        let [r, g, b] = t.rgb[0];
        let prim = match (snap(t.v[0]), snap(t.v[1]), snap(t.v[2])) {
            (Ok(a), Ok(b2), Ok(c)) => Triangle::flat([a, b2, c], Rgb565::new(r >> 3, g >> 2, b >> 3)).into(),
            (Err(e), ..) | (_, Err(e), _) | (.., Err(e)) => return result = Err(e),
        };
        if prims.push(prim).is_err() {
            result = Err(Error::BufferTooSmall);
        }
    })?;
    result?;
    render2d::<S, BH>(&prims, m, fb)
}

/// The standard 3D scene: vertex stage into bins, then `Triangles3d` with
/// `BH`-row bands, depth format `F` and colour interpolation `M` (both timed).
fn mesh3d<T: Scalar, F: DepthFormat, M: Interpolation, const S: u32, const BH: usize>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
) -> Result<(), Error> {
    mesh3d_with::<T, F, M, S, BH>(m, fb, |p, bins| Scene3d.draw::<T, Rgb565, S, BINS>(p, ANGLE, bins))
}

/// [`mesh3d`] with a vertex cache of 64 entries (a [`VertexCache`] of
/// [`MAX_MESHLET_VERTICES`], 3,072 bytes): each mesh in chunks of its
/// triangles, the same bins.
fn mesh3d_cache64<T: Scalar, F: DepthFormat, M: Interpolation, const S: u32, const BH: usize>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
) -> Result<(), Error> {
    let mut cache = VertexCache::<T, S, MAX_MESHLET_VERTICES>::new();
    mesh3d_with::<T, F, M, S, BH>(m, fb, |p, bins| {
        Scene3d.draw_cached::<T, Rgb565, S, MAX_MESHLET_VERTICES, BINS>(p, ANGLE, &mut cache, bins)
    })
}

/// [`mesh3d`] with the vertex stage `vertex`.
fn mesh3d_with<T: Scalar, F: DepthFormat, M: Interpolation, const S: u32, const BH: usize>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
    mut vertex: impl FnMut(
        &Pipeline<T, S>,
        &mut heapless::Vec<ScreenTriangle<S>, BINS>,
    ) -> Result<MeshStats, Error>,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, H as u32)?;
    let mut bins = heapless::Vec::<ScreenTriangle<S>, BINS>::new();
    let mut band = Band::<Rgb565, W, BH>::new(BG);
    let mut depth = DepthBand::<F, W, BH>::zeroed();
    m.start();
    let r = vertex(&pipeline, &mut bins).and_then(|_| {
        Renderer::new(H as u32, BG)
            .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, M::default()), &mut band, fb)
            .map_err(input)
    });
    m.stop();
    r
}

/// The 3D scene's vertex stage alone (timed); the frame is then rendered
/// (untimed) so that its checksum covers the vertex stage's output.
fn vertex3d<T: Scalar>(m: &mut dyn Meter, fb: &mut FrameBuffer) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<T, 4>(W as u32, H as u32)?;
    let mut bins = heapless::Vec::<ScreenTriangle<4>, BINS>::new();
    m.start();
    let r = Scene3d.draw::<T, Rgb565, 4, BINS>(&pipeline, ANGLE, &mut bins);
    m.stop();
    r?;
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let mut depth = DepthBand::<Depth16, W, 16>::zeroed();
    Renderer::new(H as u32, BG)
        .render(Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, fb)
        .map_err(input)
}

/// The knot's colour (`examples/fw_bench`'s `KNOT_COLOR`).
pub const KNOT_COLOR: Rgb565 = Rgb565::new(27, 46, 12);

/// The 20k-triangle knot in the standard scene's camera and light, turned by
/// [`ANGLE`] about y (as `examples/fw_bench` and the demo draw it): the
/// meshlet stage per 16-row band, straight into the band, 16-bit depth.
fn knot<T: Scalar, M: Interpolation + Default>(m: &mut dyn Meter, fb: &mut FrameBuffer) -> Result<(), Error> {
    knot_of::<T, M, f32>(&crate::knot_mesh::VALID_KNOT, m, fb)
}

/// [`knot`] through the fixed-point stage from the knot's data in 16.16
/// (`KNOT_FX`, the same values as `Fx::from_f32` of the `f32` data, its
/// own clusters).
fn knot_fx_mesh<M: Interpolation + Default>(m: &mut dyn Meter, fb: &mut FrameBuffer) -> Result<(), Error> {
    knot_of::<Fx, M, Fx>(&crate::knot_mesh::VALID_KNOT_FX, m, fb)
}

/// [`knot`] of `mesh` (positions and normals stored as `P`).
fn knot_of<T: Scalar, M: Interpolation + Default, P: Scalar>(
    mesh: &ValidMeshletMesh<'static, P>,
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
) -> Result<(), Error> {
    let pipeline: Pipeline<T, 4> = Scene3d::pipeline::<T, 4>(W as u32, H as u32)?;
    let model = transform::rotation_y(T::from_f32(ANGLE));
    let mut cache = ClusterCache::new();
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let mut depth = DepthBand::<Depth16, W, 16>::zeroed();
    m.start();
    let r = Renderer::new(H as u32, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, M::default(), |band| {
                pipeline.draw_meshlets(mesh, &model, KNOT_COLOR, &mut cache, band).map(|_| ())
            }),
            &mut band,
            fb,
        )
        .map_err(input);
    m.stop();
    r
}
