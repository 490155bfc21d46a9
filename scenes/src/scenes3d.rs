//! The standard 3D scene, shared by the demo, the tests, the benchmarks and
//! the firmware: an icosphere, a torus threaded through it and a cube cutting
//! into the torus (interpenetrating, so painter's-algorithm ordering would
//! fail), in perspective, lit by one directional light.
//!
//! The meshes are `static` data generated ahead of time from the procedural
//! generators ([`generate`]), so they cost flash, not RAM. [`Scene3d::draw`]
//! runs the vertex stage for a given frame size and animation angle into the
//! caller's bins.

use microraster::heapless;
use microraster::light::Lighting;
use microraster::math::{Mat4, Scalar, Vec3, transform};
use microraster::mesh::{
    Mesh, ValidMesh, cube, cube_triangle_count, cube_vertex_count, icosphere, icosphere_triangle_count,
    icosphere_vertex_count, torus, torus_triangle_count, torus_vertex_count,
};
use microraster::pipeline::{MeshStats, Pipeline, Shade, VertexCache};
use microraster::raster3d::ScreenTriangle;
use microraster::view3d::{Camera, Object};
use microraster::{Error, Interpolate};

mod meshes;

const SPHERE_SUBDIV: u32 = 2;
const TORUS_SEGMENTS: (usize, usize) = (28, 14);
const SV: usize = icosphere_vertex_count(SPHERE_SUBDIV);
const ST: usize = icosphere_triangle_count(SPHERE_SUBDIV);
const TV: usize = torus_vertex_count(TORUS_SEGMENTS.0, TORUS_SEGMENTS.1);
const TT: usize = torus_triangle_count(TORUS_SEGMENTS.0, TORUS_SEGMENTS.1);
const CV: usize = cube_vertex_count();
const CT: usize = cube_triangle_count();

/// Triangles in the standard scene's meshes (before culling).
pub const TRIANGLES: usize = ST + TT + CT;

/// Bins large enough for every triangle the standard scene can emit at any
/// angle (front faces plus clipped fans stay well below this; tested).
pub const BINS: usize = 576;

/// Caller-owned storage for generating the standard scene's meshes at run
/// time (about 20 KB); only [`generate`] needs it. [`Scene3d`] itself draws the
/// same meshes from flash (`meshes.rs`, written by
/// `cargo run -p microraster-scenes --example gen_scene_meshes` and checked against [`generate`]).
pub struct MeshBuffers {
    sphere: Buffers<SV, ST>,
    torus: Buffers<TV, TT>,
    cube: Buffers<CV, CT>,
}

struct Buffers<const V: usize, const T: usize> {
    positions: [[f32; 3]; V],
    normals: [[f32; 3]; V],
    indices: [[u16; 3]; T],
}

impl<const V: usize, const T: usize> Buffers<V, T> {
    const fn new() -> Self {
        Buffers { positions: [[0.0; 3]; V], normals: [[0.0; 3]; V], indices: [[0; 3]; T] }
    }
}

impl Default for MeshBuffers {
    fn default() -> Self {
        Self::new()
    }
}

impl MeshBuffers {
    /// Zeroed storage.
    pub const fn new() -> Self {
        MeshBuffers { sphere: Buffers::new(), torus: Buffers::new(), cube: Buffers::new() }
    }
}

/// Generates the standard scene's sphere, torus and cube into `bufs`.
pub fn generate(bufs: &mut MeshBuffers) -> Result<[Mesh<'_>; 3], Error> {
    let s = &mut bufs.sphere;
    let sphere = icosphere(SPHERE_SUBDIV, &mut s.positions, &mut s.normals, &mut s.indices)?;
    let t = &mut bufs.torus;
    let (m, n) = TORUS_SEGMENTS;
    let torus = torus(m, n, 1.6, 0.45, &mut t.positions, &mut t.normals, &mut t.indices)?;
    let c = &mut bufs.cube;
    let cube = cube(&mut c.positions, &mut c.normals, &mut c.indices)?;
    Ok([sphere, torus, cube])
}

/// The scene's meshes, validated at compile time.
static VALID: [ValidMesh<'static>; 3] = [valid(meshes::SPHERE), valid(meshes::TORUS), valid(meshes::CUBE)];

const fn valid(mesh: Mesh<'static>) -> ValidMesh<'static> {
    match ValidMesh::new(mesh) {
        Ok(m) => m,
        Err(_) => panic!("a standard scene mesh is invalid"), // a build error (const evaluation)
    }
}

/// The standard 3D scene. Its meshes are `static` (flash on a
/// microcontroller): the type holds no data.
#[derive(Debug, Clone, Copy, Default)]
pub struct Scene3d;

/// Statistics of one [`Scene3d::draw`] call, summed over the meshes.
pub type Stats = MeshStats;

impl Scene3d {
    /// The scene.
    pub const fn new() -> Self {
        Scene3d
    }

    /// The three meshes (sphere, torus, cube), validated at compile time.
    pub fn valid_meshes(&self) -> &'static [ValidMesh<'static>; 3] {
        &VALID
    }

    /// The three meshes: sphere, torus, cube.
    pub fn meshes(&self) -> [Mesh<'static>; 3] {
        [meshes::SPHERE, meshes::TORUS, meshes::CUBE]
    }

    /// The camera and lighting of the standard scene for a `width × height`
    /// frame, with `S` subpixel bits.
    pub fn pipeline<T: Scalar, const S: u32>(width: u32, height: u32) -> Result<Pipeline<T, S>, Error> {
        let f = T::from_f32;
        let view = transform::look_at(
            Vec3::new(f(0.0), f(1.9), f(5.6)),
            Vec3::new(f(0.0), f(0.0), f(0.0)),
            Vec3::new(f(0.0), f(1.0), f(0.0)),
        )?;
        let mut p = Pipeline::perspective(view, f(0.9), f(1.0), f(20.0), width, height)?
            .with_lighting(Self::lighting());
        p.shade = Shade::Gouraud;
        Ok(p)
    }

    /// The standard scene's light: ambient 0.25, one directional light,
    /// specular 0.4 with exponent 24.
    pub fn lighting<T: Scalar>() -> Lighting<T> {
        let f = T::from_f32;
        Lighting::new(f(0.25), Vec3::new(f(-0.4), f(0.7), f(0.6)), f(0.75)).with_specular(f(0.4), 24)
    }

    /// The standard scene's camera for the one-call front
    /// ([`View3d`](microraster::view3d::View3d)): the eye, target and lens
    /// of [`Scene3d::pipeline`].
    pub const fn camera() -> Camera {
        Camera::look_at([0.0, 1.9, 5.6], [0.0; 3]).perspective(0.9, 1.0, 20.0)
    }

    /// The three meshes as the front's objects at animation angle `angle`:
    /// the models and colours of [`Scene3d::draw`] (each model matrix
    /// applied whole, so the vertices are the same bit for bit).
    pub fn objects<C: Interpolate>(angle: f32) -> [Object<'static, C>; 3] {
        let [a, b, c] = Self::models::<f32, C>(angle);
        let object = |mesh, (model, color): (Mat4<f32>, C)| Object::new(mesh, color).then(model);
        [object(&VALID[0], a), object(&VALID[1], b), object(&VALID[2], c)]
    }

    /// Runs the vertex stage of the standard scene at animation angle
    /// `angle` (radians) into `bins`, with colours of type `C`.
    pub fn draw<T: Scalar, C: Interpolate, const S: u32, const N: usize>(
        &self,
        pipeline: &Pipeline<T, S>,
        angle: f32,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<Stats, Error> {
        let mut total = Stats::default();
        for (mesh, (model, c)) in VALID.iter().zip(Self::models::<T, C>(angle)) {
            let s = pipeline.draw_valid_mesh(mesh, &model, c, bins)?;
            total.clipped += s.clipped;
            total.back_faces += s.back_faces;
            total.degenerate += s.degenerate;
            total.emitted += s.emitted;
        }
        Ok(total)
    }

    /// Model matrices and colours of the three meshes at `angle`. Not
    /// inlined: its matrix temporaries would stay in [`Scene3d::draw`]'s
    /// stack frame during the vertex stage (the Cortex-M0 has 16 KB of RAM).
    #[inline(never)]
    fn models<T: Scalar, C: Interpolate>(angle: f32) -> [(Mat4<T>, C); 3] {
        let f = T::from_f32;
        let color = |rgb: [f32; 3]| {
            let m = C::CHANNEL_MAX;
            C::from_channels([0, 1, 2].map(|k| (rgb[k] * m[k] as f32 + 0.5) as u8))
        };
        let models: [(Mat4<T>, C); 3] = [
            (
                transform::rotation_y(f(angle)) * transform::scaling(Vec3::new(f(1.45), f(1.45), f(1.45))),
                color([0.9, 0.35, 0.2]),
            ),
            (
                transform::rotation_y(f(angle * 0.5)) * transform::rotation_x(f(0.45)),
                color([0.25, 0.6, 0.95]),
            ),
            (
                transform::translation(Vec3::new(f(1.05), f(-0.5), f(1.25)))
                    * transform::rotation_y(f(-angle))
                    * transform::scaling(Vec3::new(f(0.55), f(0.55), f(0.55))),
                color([0.95, 0.85, 0.3]),
            ),
        ];
        models
    }
}

/// Vertices of the standard scene's largest mesh: the capacity of a
/// [`VertexCache`] for [`Scene3d::draw_cached`] (the torus, 392; about
/// 15.7 KB for `f32` and for [`Fx`](microraster::math::Fx)).
pub const CACHE_VERTICES: usize = max3(SV, TV, CV);

const fn max3(a: usize, b: usize, c: usize) -> usize {
    let m = if a > b { a } else { b };
    if m > c { m } else { c }
}

impl Scene3d {
    /// [`Scene3d::draw`] with a vertex cache (each vertex transformed, snapped
    /// and lit once per mesh, or once per chunk of the mesh's triangles
    /// where `V` is below [`CACHE_VERTICES`]:
    /// [`Pipeline::draw_valid_mesh_cached`]); the same triangles. `V` must
    /// be at least 3 (checked at compile time). Not inlined: its 2.3 KB
    /// frame would join its caller's (in `examples/fw_bench`, the frame
    /// every row's stack figure includes).
    #[inline(never)]
    pub fn draw_cached<T: Scalar, C: Interpolate, const S: u32, const V: usize, const N: usize>(
        &self,
        pipeline: &Pipeline<T, S>,
        angle: f32,
        cache: &mut VertexCache<T, S, V>,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<Stats, Error> {
        const { assert!(V >= 3, "the vertex cache must hold a triangle") };
        let mut total = Stats::default();
        for (mesh, (model, c)) in VALID.iter().zip(Self::models::<T, C>(angle)) {
            let s = pipeline.draw_valid_mesh_cached(mesh, &model, c, cache, bins)?;
            total.clipped += s.clipped;
            total.back_faces += s.back_faces;
            total.degenerate += s.degenerate;
            total.emitted += s.emitted;
        }
        Ok(total)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use embedded_graphics_core::pixelcolor::Rgb565;

    #[test]
    fn flash_meshes_equal_the_generators_bit_for_bit() {
        let mut bufs = std::boxed::Box::new(MeshBuffers::new());
        let generated = generate(&mut bufs).unwrap();
        for (g, s) in generated.iter().zip(Scene3d.meshes()) {
            assert_eq!(g.positions, s.positions);
            assert_eq!(g.normals, s.normals);
            assert_eq!(g.indices, s.indices);
            assert_eq!(g.bounding_sphere, s.bounding_sphere);
            s.validate().unwrap();
        }
        assert_eq!(generated.iter().map(|m| m.triangle_count()).sum::<usize>(), TRIANGLES);
        const { assert!(TRIANGLES >= 1000) };
    }

    /// The scene through a cache of `V` vertices (the whole of each mesh,
    /// or chunks of them) equals the scene through `draw_valid_mesh` (chunks
    /// of 8 vertices; `mesh_bins`' tests compare that with a transform per
    /// corner); the triangles and counts compared.
    fn cache_of<T: Scalar, const V: usize>() -> usize {
        let mut cache = std::boxed::Box::new(VertexCache::<T, 4, V>::new());
        let (mut a, mut b) = (heapless::Vec::<_, BINS>::new(), heapless::Vec::<_, BINS>::new());
        let mut n = 0;
        for shade in [Shade::Gouraud, Shade::Flat] {
            for rows in [None, Some((0, 15)), Some((100, 107)), Some((-50, 3)), Some((230, 300))] {
                for i in 0..12 {
                    let angle = i as f32 * 0.55;
                    let mut p = Scene3d::pipeline::<T, 4>(320, 240).unwrap();
                    p.shade = shade;
                    p.rows = rows;
                    a.clear();
                    b.clear();
                    let sa = Scene3d.draw::<T, Rgb565, 4, BINS>(&p, angle, &mut a).unwrap();
                    let sb = Scene3d.draw_cached::<T, Rgb565, 4, V, BINS>(&p, angle, &mut cache, &mut b);
                    assert_eq!(Ok(sa), sb, "{V}: {shade:?} {rows:?} {angle}");
                    assert!(a == b, "{V}: {shade:?} {rows:?} {angle}: {} vs {} triangles", a.len(), b.len());
                    n += a.len();
                }
            }
        }
        n
    }

    fn cached_equals_uncached<T: Scalar>() {
        // The whole mesh, chunks of 64 (a cluster's), of 7, of one triangle.
        for (v, n) in [
            (CACHE_VERTICES, cache_of::<T, CACHE_VERTICES>()),
            (64, cache_of::<T, 64>()),
            (7, cache_of::<T, 7>()),
            (3, cache_of::<T, 3>()),
        ] {
            assert!(n > 10_000, "{v}: {n}");
        }
        let mut cache = std::boxed::Box::new(VertexCache::<T, 4, CACHE_VERTICES>::new());
        let (mut a, mut b) = (heapless::Vec::<_, BINS>::new(), heapless::Vec::<_, BINS>::new());
        // A mesh without normals (face normals, per triangle) and a cache too small.
        let sphere = Scene3d.meshes()[0];
        let bare = ValidMesh::new(Mesh { normals: &[], ..sphere }).unwrap();
        let p = Scene3d::pipeline::<T, 4>(320, 240).unwrap();
        let model = Mat4::IDENTITY;
        a.clear();
        b.clear();
        let sa = p.draw_valid_mesh(&bare, &model, Rgb565::new(31, 20, 5), &mut a).unwrap();
        let sb = p.draw_valid_mesh_cached(&bare, &model, Rgb565::new(31, 20, 5), &mut cache, &mut b).unwrap();
        assert!(sa == sb && a == b, "no normals: {sa:?} vs {sb:?}");
        assert!(sa.emitted > 100);
        // Chunks of a mesh with face normals; a cache below one triangle.
        let mut small = VertexCache::<T, 4, 100>::new();
        b.clear();
        let sc = p.draw_valid_mesh_cached(&bare, &model, Rgb565::new(31, 20, 5), &mut small, &mut b).unwrap();
        assert!(sa == sc && a == b, "no normals, chunks: {sa:?} vs {sc:?}");
        let mut tiny = VertexCache::<T, 4, 2>::new();
        let r = p.draw_valid_mesh_cached(&bare, &model, Rgb565::new(31, 20, 5), &mut tiny, &mut b);
        assert_eq!(r, Err(Error::CapacityExceeded { needed: 3, capacity: 2 }));
    }

    #[test]
    fn vertex_cache_gives_the_same_triangles() {
        cached_equals_uncached::<f32>();
        cached_equals_uncached::<microraster::math::Fx>();
    }

    #[test]
    fn bins_hold_every_angle_for_both_vertex_paths() {
        let p = Scene3d::pipeline::<f32, 4>(320, 240).unwrap();
        let q = Scene3d::pipeline::<microraster::math::Fx, 4>(320, 240).unwrap();
        let mut most = 0;
        for i in 0..96 {
            let angle = i as f32 * core::f32::consts::TAU / 96.0;
            let mut bins = heapless::Vec::<_, BINS>::new();
            most = most.max(Scene3d.draw::<f32, Rgb565, 4, BINS>(&p, angle, &mut bins).unwrap().emitted);
            bins.clear();
            most = most.max(Scene3d.draw::<_, Rgb565, 4, BINS>(&q, angle, &mut bins).unwrap().emitted);
        }
        std::println!("standard scene: at most {most} triangles emitted over 96 angles (bins: {BINS})");
        assert!(most as usize <= BINS && most > 400);
    }
}
