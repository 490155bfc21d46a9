//! The fragment-stage options of the report (textures, per-pixel lighting,
//! blending, anti-aliasing, anti-aliased lines), each as one configuration
//! under its report key: the standard 3D scene (`mesh3d`) with every mesh
//! drawn through the option, or scene 5 (`lines`) with anti-aliased lines.
//! Shared by the Cortex-M counts and the host report (`examples/report`).

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::aa::Antialiased3d;
use microraster::aa::{Msaa, MsaaSparse, Ssaa};
use microraster::blend::Mix;
use microraster::depth::{Depth16, DepthBand, DepthFormat, DepthState};
use microraster::fragment::{
    FragTriangle, Fragment, FragmentShader, Output, Phong, Textured, draw_fragment_band, phong_varyings,
    textured_varyings,
};
use microraster::line_aa::LineAa;
use microraster::math::{Mat4, Vec3, transform};
use microraster::pipeline::VertexInput;
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle};
use microraster::render::from_fn;
use microraster::texture::{Filter, Sampler, Texture, from_rgb8};
use microraster::{Band, Error, Primitive, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{BINS, Scene3d};

use crate::configs::{ANGLE, BG, Config, H, Meter, W, input};
use crate::frame::FrameBuffer;

#[allow(dead_code)]
#[path = "../demo/texture_data.rs"]
mod texture_data;
pub use texture_data::BRICKS;

type P = PerspectiveCorrect;
/// The models and material colours of the standard scene (as `Scene3d::draw`).
fn models() -> [(Mat4<f32>, Rgb565); 3] {
    let s = |v: f32| transform::scaling(Vec3::new(v, v, v));
    let c = |r: f32, g: f32, b: f32| {
        Rgb565::new((r * 31.0 + 0.5) as u8, (g * 63.0 + 0.5) as u8, (b * 31.0 + 0.5) as u8)
    };
    [
        (transform::rotation_y(ANGLE) * s(1.45), c(0.9, 0.35, 0.2)),
        (transform::rotation_y(ANGLE * 0.5) * transform::rotation_x(0.45), c(0.25, 0.6, 0.95)),
        (
            transform::translation(Vec3::new(1.05, -0.5, 1.25)) * transform::rotation_y(-ANGLE) * s(0.55),
            c(0.95, 0.85, 0.3),
        ),
    ]
}

/// Every configuration of this module.
pub const LIST: &[Config] = &[
    Config {
        key: "mesh3d/frag/colour",
        run: |m, fb| frag3d::<3, P, _>(m, fb, lit_varyings, &colour, Output::OPAQUE),
    },
    Config {
        key: "mesh3d/frag/texture-nearest-affine",
        run: |m, fb| textured::<Affine, microraster::texture::Nearest>(m, fb, Sampler::NEAREST_WRAP),
    },
    Config {
        key: "mesh3d/frag/texture-nearest-persp",
        run: |m, fb| textured::<P, microraster::texture::Nearest>(m, fb, Sampler::NEAREST_WRAP),
    },
    Config {
        key: "mesh3d/frag/texture-bilinear-persp",
        run: |m, fb| textured::<P, microraster::texture::Bilinear>(m, fb, Sampler::BILINEAR_WRAP),
    },
    Config { key: "mesh3d/frag/phong", run: phong },
    Config {
        key: "mesh3d/frag/translucent",
        run: |m, fb| frag3d::<3, P, _>(m, fb, lit_varyings, &colour, TRANSLUCENT),
    },
    Config { key: "mesh3d/aa/ssaa2", run: |m, fb| aa3d::<_, { 2 * W }, 32>(m, fb, Ssaa::<2>) },
    Config { key: "mesh3d/aa/msaa2", run: |m, fb| aa3d::<_, { 2 * W }, 32>(m, fb, Msaa::<2>) },
    Config { key: "mesh3d/aa/sparse4", run: |m, fb| aa3d::<_, W, 64>(m, fb, MsaaSparse::<4>) },
    Config { key: "lines/aa/band16/S4", run: lines_aa },
];

const TRANSLUCENT: Output<Mix> = Output { depth: DepthState::READ_ONLY, blend: Mix, alpha: 128 };

fn lit_varyings(_: usize, v: &VertexInput<f32>) -> [i32; 3] {
    v.color.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as i32)
}

fn colour(f: &Fragment<3>) -> Rgb565 {
    from_rgb8(f.varyings.map(|c| c.clamp(0, 255) as u8))
}

/// The standard scene's meshes through the fragment stage with `shader`,
/// varyings from `vary(mesh, vertex)`; the vertex stage and the 16-row bands
/// are timed. Lit as the standard scene unless `lighting` is off (Phong).
fn frag3d<const A: usize, M: Interpolation, Sh: FragmentShader<Rgb565, A>>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
    vary: impl Fn(usize, &VertexInput<f32>) -> [i32; A],
    shader: &Sh,
    out: Output<impl microraster::blend::Blend>,
) -> Result<(), Error> {
    frag3d_with::<A, M, Sh>(m, fb, vary, shader, out, true)
}

fn frag3d_with<const A: usize, M: Interpolation, Sh: FragmentShader<Rgb565, A>>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
    vary: impl Fn(usize, &VertexInput<f32>) -> [i32; A],
    shader: &Sh,
    out: Output<impl microraster::blend::Blend>,
    lighting: bool,
) -> Result<(), Error> {
    let mut p = Scene3d::pipeline::<f32, 4>(W as u32, H as u32)?;
    if !lighting {
        p.lighting = None;
    }
    let mut bins = heapless::Vec::<FragTriangle<4, A>, BINS>::new();
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let mut depth = DepthBand::<Depth16, W, 16>::zeroed();
    m.start();
    let mut result = Ok(());
    for (k, (mesh, (model, c))) in Scene3d.valid_meshes().iter().zip(models()).enumerate() {
        if result.is_ok() {
            result = p.draw_mesh_varying(mesh, &model, c, |v| vary(k, v), &mut bins).map(|_| ());
        }
    }
    let r = result.and_then(|()| {
        let mut inner = Ok(());
        Renderer::new(H as u32, BG)
            .render(
                from_fn(|view| {
                    let (y0, y1) = (view.y0(), view.y1());
                    let mut rows = depth.rows_mut((y1 - y0) as usize);
                    for r in rows.iter_mut() {
                        r.fill(Depth16::FAR);
                    }
                    if inner.is_ok() {
                        inner = draw_fragment_band(&bins, view, &mut rows, shader, out, M::default());
                    };
                    Ok(())
                }),
                &mut band,
                fb,
            )
            .map_err(input)?;
        inner
    });
    m.stop();
    r
}

/// Per-pixel lighting with the standard scene's light (vertex stage unlit).
fn phong(m: &mut dyn Meter, fb: &mut FrameBuffer) -> Result<(), Error> {
    let lighting = Scene3d::pipeline::<f32, 4>(W as u32, H as u32)?
        .lighting
        .ok_or(Error::InvalidParameter(microraster::Param::User))?;
    frag3d_with::<6, P, _>(m, fb, |_, v| phong_varyings(v), &Phong { lighting }, Output::OPAQUE, false)
}

/// Texture coordinates of a standard-scene vertex: a planar map of its object
/// position (`x + z`, `y`), so every mesh is covered by several repeats.
fn textured<M: Interpolation, Fi: Filter>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
    sampler: Sampler<Fi>,
) -> Result<(), Error> {
    let [sphere, torus, cube] = Scene3d.valid_meshes();
    let pos = [sphere.mesh().positions, torus.mesh().positions, cube.mesh().positions];
    let tex: &Texture<'static, Rgb565> = &BRICKS;
    let shader = Textured { texture: tex, sampler };
    let uv = move |k: usize, v: &VertexInput<f32>| {
        let p = pos[k].get(v.index as usize).copied().unwrap_or([0.0; 3]);
        textured_varyings([p[0] + p[2], p[1]], v)
    };
    frag3d::<5, M, _>(m, fb, uv, &shader, Output::OPAQUE)
}

/// The standard scene's bins drawn anti-aliased (`mode`), 16-row output bands.
fn aa3d<A: microraster::aa::Antialias, const SW: usize, const SH: usize>(
    m: &mut dyn Meter,
    fb: &mut FrameBuffer,
    mode: A,
) -> Result<(), Error> {
    let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, H as u32)?;
    let mut bins = heapless::Vec::<ScreenTriangle<4>, BINS>::new();
    let mut samples = Band::<Rgb565, SW, SH>::new(BG);
    let mut depth = DepthBand::<Depth16, SW, SH>::zeroed();
    let mut out = Band::<Rgb565, W, 16>::new(BG);
    m.start();
    let r = Scene3d.draw::<f32, Rgb565, 4, BINS>(&pipeline, ANGLE, &mut bins).and_then(|_| {
        Renderer::new(H as u32, BG)
            .render(
                Antialiased3d::new(
                    mode,
                    &bins,
                    &mut samples,
                    &mut depth,
                    DepthState::LESS_WRITE,
                    P::default(),
                ),
                &mut out,
                fb,
            )
            .map_err(input)
    });
    m.stop();
    r
}

/// Scene 5 with anti-aliased lines (Wu, mixed over the band), 16-row bands.
fn lines_aa(m: &mut dyn Meter, fb: &mut FrameBuffer) -> Result<(), Error> {
    let mut prims = heapless::Vec::<Primitive<Rgb565, 4>, { scenes::LINES_LEN }>::new();
    if scenes::collect(scenes::lines::<Rgb565, 4>, W as u32, H as u32, &mut prims)? != 0 {
        return Err(Error::BufferTooSmall);
    }
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    m.start();
    let r = Renderer::new(H as u32, BG)
        .render(
            from_fn(|view| {
                let (y0, y1) = (view.y0(), view.y1());
                for p in &prims {
                    if let Primitive::Line(l) = p {
                        let (lo, hi) = l.rows();
                        if lo < y1 && hi >= y0 {
                            LineAa::new(l.start(), l.end(), l.color()).draw(view);
                        }
                    }
                }
                Ok(())
            }),
            &mut band,
            fb,
        )
        .map_err(input);
    m.stop();
    r
}
