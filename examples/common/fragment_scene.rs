//! The fragment-stage scene, shared word for word (`#[path]`) by the host
//! demo (`fragment.png`), the Cortex-M4F firmware and the Cortex-M counts: a
//! brick-textured floor and cube (bilinear, perspective-correct, modulated by
//! Gouraud light), the standard scene's sphere lit per vertex (left) and per
//! pixel (right, [`Phong`]), and its torus twice, translucent, drawn last and
//! farthest first with depth writes off. Meshes and texture are in flash.
//! `no_std`: the bins are `heapless` vectors with the given capacities.

use embedded_graphics_core::pixelcolor::Rgb888;
use microraster::blend::{back_to_front, view_depth};
use microraster::depth::{DepthBand, DepthFormat};
use microraster::fragment::{
    FragTriangle, Fragment, Output, Phong, Textured, draw_fragment_band, phong_varyings, textured_varyings,
};
use microraster::light::Lighting;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, ValidMesh};
use microraster::pipeline::{Pipeline, VertexInput};
use microraster::raster3d::{Interpolation, ScreenTriangle, draw_triangle};
use microraster::texture::{Sampler, from_rgb8};
use microraster::{Error, Interpolate, band::BandView};
use microraster_scenes::scenes3d::Scene3d;

#[allow(dead_code)]
#[path = "../demo/texture_data.rs"]
mod texture_data;
pub use texture_data::BRICKS;

/// Frame width and height.
pub const W: usize = 320;
/// Frame height.
pub const H: u32 = 240;
/// Frame background: a dark slate.
pub const BACKGROUND: Rgb888 = Rgb888::new(18, 22, 34);

/// The floor: a square at y = −1, normals up, four texture repeats.
static FLOOR_POS: [[f32; 3]; 4] =
    [[-4.0, -1.0, -4.0], [-4.0, -1.0, 4.0], [4.0, -1.0, 4.0], [4.0, -1.0, -4.0]];
static FLOOR_N: [[f32; 3]; 4] = [[0.0, 1.0, 0.0]; 4];
static FLOOR_IDX: [[u16; 3]; 2] = [[0, 1, 2], [0, 2, 3]];
static FLOOR_UV: [[f32; 2]; 4] = [[0.0, 0.0], [0.0, 4.0], [4.0, 4.0], [4.0, 0.0]];
static FLOOR: ValidMesh<'static> =
    match ValidMesh::new(Mesh::new(&FLOOR_POS, &FLOOR_N, &FLOOR_IDX, ([0.0, -1.0, 0.0], 5.66))) {
        Ok(m) => m,
        Err(_) => panic!("invalid floor"),
    };

/// The light of the scene (eye space).
pub fn light() -> Lighting<f32> {
    Lighting::new(0.22, Vec3::new(-0.4, 0.7, 0.6), 0.75).with_specular(0.55, 32)
}

/// The screen triangles of one frame (or one band), per pass.
#[derive(Clone)]
pub struct FragBins<const S: u32, const G: usize, const P: usize, const X: usize, const L: usize> {
    /// Gouraud-lit sphere (plain 3D triangles).
    pub gouraud: heapless::Vec<ScreenTriangle<S>, G>,
    /// Phong-lit sphere: eye-space normals and positions.
    pub phong: heapless::Vec<FragTriangle<S, 6>, P>,
    /// Floor and cube: texture coordinates and lit colour.
    pub textured: heapless::Vec<FragTriangle<S, 5>, X>,
    /// The translucent tori: lit colour.
    pub glass: heapless::Vec<FragTriangle<S, 3>, L>,
}

impl<const S: u32, const G: usize, const P: usize, const X: usize, const L: usize> FragBins<S, G, P, X, L> {
    /// Empty bins.
    pub const fn new() -> Self {
        FragBins {
            gouraud: heapless::Vec::new(),
            phong: heapless::Vec::new(),
            textured: heapless::Vec::new(),
            glass: heapless::Vec::new(),
        }
    }

    /// Moves every triangle to the sample grid of `n × n` supersampling
    /// (`ScreenTriangle::scaled`).
    pub fn scale(&mut self, n: usize) -> Result<(), Error> {
        for t in self.gouraud.iter_mut() {
            *t = t.scaled(n)?;
        }
        for t in self.phong.iter_mut() {
            *t = t.scaled(n)?;
        }
        for t in self.textured.iter_mut() {
            *t = t.scaled(n)?;
        }
        for t in self.glass.iter_mut() {
            *t = t.scaled(n)?;
        }
        Ok(())
    }

    /// Empties every pass.
    pub fn clear(&mut self) {
        self.gouraud.clear();
        self.phong.clear();
        self.textured.clear();
        self.glass.clear();
    }
}

/// The camera with and without lighting (the Phong pass lights per pixel).
pub struct FragmentScene<const S: u32> {
    /// The pipeline with the scene's light (Gouraud, textured, glass).
    pub lit: Pipeline<f32, S>,
    /// The same camera unlit (the Phong pass gets material colours).
    pub unlit: Pipeline<f32, S>,
    view: Mat4<f32>,
}

impl<const S: u32> FragmentScene<S> {
    /// The scene for a `width × height` viewport.
    pub fn new(width: u32, height: u32) -> Result<Self, Error> {
        let view = transform::look_at(
            Vec3::new(0.0, 1.6, 6.2),
            Vec3::new(0.0, -0.1, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        )?;
        let unlit = Pipeline::<f32, S>::perspective(view, 0.8, 1.0, 30.0, width, height)?;
        Ok(FragmentScene { lit: unlit.with_lighting(light()), unlit, view })
    }

    /// Keeps only triangles touching frame rows `rows` (per-band vertex stage).
    pub fn set_rows(&mut self, rows: Option<(i32, i32)>) {
        self.lit.rows = rows;
        self.unlit.rows = rows;
    }

    /// The vertex stage of every pass into `bins`.
    pub fn draw<const G: usize, const P: usize, const X: usize, const L: usize>(
        &self,
        bins: &mut FragBins<S, G, P, X, L>,
    ) -> Result<(), Error> {
        let [sphere, torus, cube] = Scene3d.valid_meshes();
        let place = |x: f32, y: f32, z: f32, s: f32| -> Mat4<f32> {
            transform::translation(Vec3::new(x, y, z)) * transform::scaling(Vec3::new(s, s, s))
        };
        let material = Rgb888::new(200, 90, 60);
        self.lit.draw_valid_mesh(sphere, &place(-1.45, 0.15, -0.6, 0.95), material, &mut bins.gouraud)?;
        let phong_model = place(1.45, 0.15, -0.6, 0.95);
        self.unlit.draw_mesh_varying(sphere, &phong_model, material, phong_varyings, &mut bins.phong)?;

        let white = Rgb888::new(255, 255, 255);
        let floor_uv = |v: &VertexInput<f32>| textured_varyings(FLOOR_UV[v.index as usize], v);
        self.lit.draw_mesh_varying(&FLOOR, &Mat4::IDENTITY, white, floor_uv, &mut bins.textured)?;
        // Cube faces: texture coordinates from the two object axes across
        // each face (its normal picks them).
        let (cpos, cnrm) = (cube.mesh().positions, cube.mesh().normals);
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
        self.lit.draw_mesh_varying(cube, &cube_model, white, cube_uv, &mut bins.textured)?;

        // Translucent meshes: after the opaque ones, farthest first.
        let tilt = |x: f32, z: f32, a: f32| {
            transform::translation(Vec3::new(x, -0.3, z))
                * transform::rotation_x(a)
                * transform::scaling(Vec3::new(0.5, 0.5, 0.5))
        };
        let mut glass = [
            (tilt(-1.7, 1.9, 1.2), Rgb888::new(80, 200, 255)),
            (tilt(1.8, 1.7, 0.9), Rgb888::new(255, 230, 90)),
        ];
        back_to_front(&mut glass, |(m, _)| view_depth(&self.view, m, torus.mesh()));
        let lit_color = |v: &VertexInput<f32>| v.color.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as i32);
        for (m, c) in &glass {
            self.lit.draw_mesh_varying(torus, m, *c, lit_color, &mut bins.glass)?;
        }
        Ok(())
    }
}

/// Draws every pass of one band (rows `y0..y1` of `view`, which may be a
/// sample band with geometry scaled to it), clearing `depth` first.
#[allow(clippy::too_many_arguments)]
pub fn draw_passes<
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    const S: u32,
    const BW: usize,
    const BH: usize,
    const G: usize,
    const P: usize,
    const X: usize,
    const L: usize,
>(
    bins: &FragBins<S, G, P, X, L>,
    view: &mut BandView<'_, C, BW>,
    depth: &mut DepthBand<F, BW, BH>,
    y0: i32,
    y1: i32,
) -> Result<(), Error> {
    let mut rows = depth.rows_mut((y1 - y0) as usize);
    for r in rows.iter_mut() {
        r.fill(F::FAR);
    }
    for t in &bins.gouraud {
        let (lo, hi) = t.rows();
        if lo < y1 && hi >= y0 {
            draw_triangle(t, view, &mut rows, Output::OPAQUE.depth, M::default());
        }
    }
    let phong = Phong { lighting: light() };
    draw_fragment_band(&bins.phong, view, &mut rows, &phong, Output::OPAQUE, M::default())?;
    let bricks = Textured { texture: &BRICKS, sampler: Sampler::BILINEAR_WRAP };
    draw_fragment_band(&bins.textured, view, &mut rows, &bricks, Output::OPAQUE, M::default())?;
    let glass = |f: &Fragment<3>| from_rgb8::<C>(f.varyings.map(|c| c.clamp(0, 255) as u8));
    draw_fragment_band(&bins.glass, view, &mut rows, &glass, Output::translucent(140), M::default())
}
