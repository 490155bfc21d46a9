//! The fragment stage at 320×240 (`fragment.png`): a brick-textured floor and
//! cube (bilinear, perspective-correct, modulated by Gouraud light), the same
//! sphere lit per vertex (left) and per pixel (right: Phong, the highlight
//! Gouraud loses between vertices), and a translucent torus drawn last with
//! depth writes off — rendered in 16-row bands, supersampled 2 × 2
//! (`fragment.png`) and aliased (`fragment_aliased.png`).

use super::texture_data::BRICKS;
use super::{Canvas, Result, save, with_caption};
use embedded_graphics_core::pixelcolor::Rgb888;
use microraster::aa::Ssaa;
use microraster::blend::back_to_front;
use microraster::depth::{Depth16, DepthBand, DepthFormat};
use microraster::fragment::{
    FragTriangle, Fragment, Output, Phong, Textured, draw_fragment_band, phong_varyings, textured_varyings,
};
use microraster::light::Lighting;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{
    Mesh, ValidMesh, cube, cube_triangle_count, cube_vertex_count, icosphere, icosphere_triangle_count,
    icosphere_vertex_count, torus, torus_triangle_count, torus_vertex_count,
};
use microraster::pipeline::{Pipeline, VertexInput};
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle, draw_triangle};
use microraster::texture::Sampler;
use microraster::{Band, Renderer};
use std::path::Path;

const W: usize = 320;
const H: u32 = 240;
const S: u32 = super::S;
const BAND_ROWS: usize = 16;
const BACKGROUND: Rgb888 = Rgb888::new(18, 22, 34);
type Z = Depth16;
type P = PerspectiveCorrect;

/// The floor: a square at y = −1, normals up, four texture repeats.
static FLOOR_POS: [[f32; 3]; 4] =
    [[-4.0, -1.0, -4.0], [-4.0, -1.0, 4.0], [4.0, -1.0, 4.0], [4.0, -1.0, -4.0]];
static FLOOR_N: [[f32; 3]; 4] = [[0.0, 1.0, 0.0]; 4];
static FLOOR_IDX: [[u16; 3]; 2] = [[0, 1, 2], [0, 2, 3]];
static FLOOR_UV: [[f32; 2]; 4] = [[0.0, 0.0], [0.0, 4.0], [4.0, 4.0], [4.0, 0.0]];

fn light() -> Lighting<f32> {
    Lighting::new(0.22, Vec3::new(-0.4, 0.7, 0.6), 0.75).with_specular(0.55, 32)
}

/// Everything the frame draws, binned once.
struct Bins {
    gouraud: Vec<ScreenTriangle<S>>,
    phong: Vec<FragTriangle<S, 6>>,
    textured: Vec<FragTriangle<S, 5>>,
    glass: Vec<FragTriangle<S, 3>>,
}

fn bins() -> Result<Bins> {
    let view =
        transform::look_at(Vec3::new(0.0, 1.6, 6.2), Vec3::new(0.0, -0.1, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
    let unlit = Pipeline::<f32, S>::perspective(view, 0.8, 1.0, 30.0, W as u32, H)?;
    let lit = unlit.with_lighting(light());
    let (mut sp, mut sn, mut si) = (
        vec![[0.0; 3]; icosphere_vertex_count(2)],
        vec![[0.0; 3]; icosphere_vertex_count(2)],
        vec![[0u16; 3]; icosphere_triangle_count(2)],
    );
    let sphere = ValidMesh::new(icosphere(2, &mut sp, &mut sn, &mut si)?)?;
    let (mut cp, mut cn, mut ci) = ([[0.0; 3]; 24], [[0.0; 3]; 24], [[0u16; 3]; 12]);
    const { assert!(cube_vertex_count() == 24 && cube_triangle_count() == 12) };
    let cube_mesh = cube(&mut cp, &mut cn, &mut ci)?;
    let cube_v = ValidMesh::new(cube_mesh)?;
    let (tv, tt) = (torus_vertex_count(32, 12), torus_triangle_count(32, 12));
    let (mut tp, mut tn, mut ti) = (vec![[0.0; 3]; tv], vec![[0.0; 3]; tv], vec![[0u16; 3]; tt]);
    let torus_mesh = ValidMesh::new(torus(32, 12, 0.75, 0.22, &mut tp, &mut tn, &mut ti)?)?;
    let floor = ValidMesh::new(Mesh::new(&FLOOR_POS, &FLOOR_N, &FLOOR_IDX, ([0.0, -1.0, 0.0], 5.66)))?;

    let place = |x: f32, y: f32, z: f32, s: f32| -> Mat4<f32> {
        transform::translation(Vec3::new(x, y, z)) * transform::scaling(Vec3::new(s, s, s))
    };
    let material = Rgb888::new(200, 90, 60);
    let mut g = heapless::Vec::<ScreenTriangle<S>, 1024>::new();
    lit.draw_valid_mesh(&sphere, &place(-1.45, 0.15, -0.6, 0.95), material, &mut g)?;
    let mut ph = heapless::Vec::<FragTriangle<S, 6>, 1024>::new();
    unlit.draw_mesh_varying(&sphere, &place(1.45, 0.15, -0.6, 0.95), material, phong_varyings, &mut ph)?;

    let mut tx = heapless::Vec::<FragTriangle<S, 5>, 64>::new();
    let white = Rgb888::new(255, 255, 255);
    let floor_uv = |v: &VertexInput<f32>| textured_varyings(FLOOR_UV[v.index as usize], v);
    lit.draw_mesh_varying(&floor, &Mat4::IDENTITY, white, floor_uv, &mut tx)?;
    // The cube's faces: texture coordinates from the two object axes across
    // each face (its normal picks them).
    let (cpos, cnrm) = (cube_mesh.positions, cube_mesh.normals);
    let cube_uv = |v: &VertexInput<f32>| {
        let (p, n) = (cpos[v.index as usize], cnrm[v.index as usize]);
        let uv = if n[0] != 0.0 {
            [p[2], p[1]]
        } else if n[1] != 0.0 {
            [p[0], p[2]]
        } else {
            [p[0], p[1]]
        };
        textured_varyings(uv.map(|c| c + 0.5), v)
    };
    let cube_model = transform::translation(Vec3::new(0.0, -0.55, 1.3))
        * transform::rotation_y(0.6)
        * transform::scaling(Vec3::new(0.9, 0.9, 0.9));
    lit.draw_mesh_varying(&cube_v, &cube_model, white, cube_uv, &mut tx)?;

    // Translucent meshes: drawn after the opaque ones, farthest first.
    let mut glass_meshes = [
        (
            transform::translation(Vec3::new(-1.7, -0.3, 1.9)) * transform::rotation_x(1.2),
            Rgb888::new(80, 200, 255),
        ),
        (
            transform::translation(Vec3::new(1.8, -0.35, 1.7)) * transform::rotation_x(0.9),
            Rgb888::new(255, 230, 90),
        ),
    ];
    back_to_front(&mut glass_meshes, |(m, _)| microraster::blend::view_depth(&view, m, torus_mesh.mesh()));
    let mut gl = heapless::Vec::<FragTriangle<S, 3>, 1024>::new();
    let color_varyings = |v: &VertexInput<f32>| v.color.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as i32);
    for (m, c) in &glass_meshes {
        lit.draw_mesh_varying(&torus_mesh, m, *c, color_varyings, &mut gl)?;
    }
    Ok(Bins { gouraud: g.to_vec(), phong: ph.to_vec(), textured: tx.to_vec(), glass: gl.to_vec() })
}

/// Draws every pass of one band (rows `y0..y1` of `view`).
fn draw_passes<F: DepthFormat, const BW: usize, const BH: usize>(
    b: &Bins,
    view: &mut microraster::band::BandView<'_, Rgb888, BW>,
    depth: &mut DepthBand<F, BW, BH>,
    y0: i32,
    y1: i32,
) -> std::result::Result<(), microraster::Error> {
    let rows = depth.rows_mut((y1 - y0) as usize);
    for r in rows.iter_mut() {
        r.fill(F::FAR);
    }
    for t in &b.gouraud {
        let (lo, hi) = t.rows();
        if lo < y1 && hi >= y0 {
            draw_triangle::<_, F, P, S, BW>(t, view, rows, Output::OPAQUE.depth);
        }
    }
    let phong = Phong { lighting: light() };
    draw_fragment_band::<_, F, P, _, _, S, BW, 6>(&b.phong, view, rows, &phong, Output::OPAQUE)?;
    let bricks = Textured { texture: &BRICKS, sampler: Sampler::BILINEAR_WRAP };
    draw_fragment_band::<_, F, P, _, _, S, BW, 5>(&b.textured, view, rows, &bricks, Output::OPAQUE)?;
    let glass = |f: &Fragment<3>| {
        let c = f.varyings.map(|c| c.clamp(0, 255) as u8);
        Rgb888::new(c[0], c[1], c[2])
    };
    draw_fragment_band::<_, F, P, _, _, S, BW, 3>(&b.glass, view, rows, &glass, Output::translucent(140))
}

/// The frame in `BAND_ROWS`-row bands.
fn render(b: &Bins) -> Result<Canvas> {
    let mut canvas = Canvas::new(W as u32, H);
    let mut band = Box::new(Band::<Rgb888, W, BAND_ROWS>::new(BACKGROUND));
    let mut depth = Box::new(DepthBand::<Z, W, BAND_ROWS>::new());
    let mut result = Ok(());
    Renderer::new(H, BACKGROUND)
        .render_with(&mut band, &mut canvas, |view, y0, y1| {
            if result.is_ok() {
                result = draw_passes(b, view, &mut depth, y0, y1);
            }
        })
        .map_err(|e| format!("{e:?}"))?;
    result?;
    Ok(canvas)
}

/// The same bins on the sample grid of `n × n` supersampling.
fn scaled(b: &Bins, n: usize) -> Result<Bins> {
    Ok(Bins {
        gouraud: b.gouraud.iter().map(|t| t.scaled(n)).collect::<std::result::Result<_, _>>()?,
        phong: b.phong.iter().map(|t| t.scaled(n)).collect::<std::result::Result<_, _>>()?,
        textured: b.textured.iter().map(|t| t.scaled(n)).collect::<std::result::Result<_, _>>()?,
        glass: b.glass.iter().map(|t| t.scaled(n)).collect::<std::result::Result<_, _>>()?,
    })
}

/// The frame supersampled 2 × 2 (`Ssaa<2>`): the same passes on a 640-wide
/// sample band of 32 rows with its own depth band, box-filtered per band.
fn render_ssaa2(b: &Bins) -> Result<Canvas> {
    let b2 = scaled(b, 2)?;
    let mut canvas = Canvas::new(W as u32, H);
    let mut samples = Box::new(Band::<Rgb888, { 2 * W }, { 2 * BAND_ROWS }>::new(BACKGROUND));
    let mut depth = Box::new(DepthBand::<Z, { 2 * W }, { 2 * BAND_ROWS }>::new());
    let mut out = Box::new(Band::<Rgb888, W, BAND_ROWS>::new(BACKGROUND));
    let mut result = Ok(());
    Renderer::new(H, BACKGROUND)
        .render_supersampled_with(Ssaa::<2>, &mut samples, &mut out, &mut canvas, |view, sy0, sy1| {
            if result.is_ok() {
                result = draw_passes(&b2, view, &mut depth, sy0, sy1);
            }
        })
        .map_err(|e| format!("{e:?}"))?;
    result?;
    Ok(canvas)
}

/// Writes fragment.png (supersampled 2 × 2) and fragment_aliased.png to `out`.
pub fn run(out: &Path) -> Result<()> {
    let b = bins()?;
    save(&render(&b)?, &out.join("fragment_aliased.png"))?;
    let frame = render_ssaa2(&b)?;
    let frame = with_caption(
        &frame,
        &[
            "Bricks: bilinear, perspective-correct texture.",
            "Spheres: Gouraud (left), per-pixel Phong (right).",
            "Tori: translucent (alpha 140), no depth writes.",
            "Supersampled 2x2 in 16-row bands.",
        ],
    )?;
    save(&frame, &out.join("fragment.png"))?;
    println!(
        "fragment.png: {} Gouraud, {} Phong, {} textured, {} translucent triangles; 16-row bands",
        b.gouraud.len(),
        b.phong.len(),
        b.textured.len(),
        b.glass.len()
    );
    Ok(())
}
