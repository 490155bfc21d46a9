//! The standard 3D scene, shared by the demo, the tests, the benchmarks and
//! the firmware: an icosphere, a torus threaded through it and a cube cutting
//! into the torus (interpenetrating, so painter's-algorithm ordering would
//! fail), in perspective, lit by one directional light.
//!
//! The meshes are generated into a caller-owned [`Scene3d`] (no allocation;
//! [`Scene3d::new`] is `const`, so it can be a `static`), then
//! [`Scene3d::draw`] runs the vertex stage for a given frame size and animation
//! angle into the caller's bins.

use crate::light::Lighting;
use crate::math::{Mat4, Scalar, Vec3, transform};
use crate::mesh::{
    Mesh, cube, cube_triangle_count, cube_vertex_count, icosphere, icosphere_triangle_count,
    icosphere_vertex_count, torus, torus_triangle_count, torus_vertex_count,
};
use crate::pipeline::{MeshStats, Pipeline, Shade};
use crate::raster3d::ScreenTriangle;
use crate::{Error, Interpolate};

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
pub const BINS: usize = 1024;

struct Buffers<const V: usize, const T: usize> {
    positions: [[f32; 3]; V],
    normals: [[f32; 3]; V],
    indices: [[u16; 3]; T],
}

impl<const V: usize, const T: usize> Buffers<V, T> {
    const fn new() -> Self {
        Buffers { positions: [[0.0; 3]; V], normals: [[0.0; 3]; V], indices: [[0; 3]; T] }
    }

    fn mesh(&self, sphere: ([f32; 3], f32)) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.normals, &self.indices, sphere)
    }
}

/// Mesh storage for the standard scene (about 27 KB).
pub struct Scene3d {
    sphere: Buffers<SV, ST>,
    torus: Buffers<TV, TT>,
    cube: Buffers<CV, CT>,
    spheres: Option<[([f32; 3], f32); 3]>,
}

/// Statistics of one [`Scene3d::draw`] call, summed over the meshes.
pub type Stats = MeshStats;

impl Default for Scene3d {
    fn default() -> Self {
        Self::new()
    }
}

impl Scene3d {
    /// Empty storage; the meshes are generated on the first [`Scene3d::draw`].
    pub const fn new() -> Self {
        Scene3d { sphere: Buffers::new(), torus: Buffers::new(), cube: Buffers::new(), spheres: None }
    }

    /// The three meshes, generated on first use (once; later frames reuse them).
    pub fn meshes(&mut self) -> Result<[Mesh<'_>; 3], Error> {
        let spheres = match self.spheres {
            Some(b) => b,
            None => {
                let s = &mut self.sphere;
                let a = icosphere(SPHERE_SUBDIV, &mut s.positions, &mut s.normals, &mut s.indices)?;
                let t = &mut self.torus;
                let (m, n) = TORUS_SEGMENTS;
                let b = torus(m, n, 1.6, 0.45, &mut t.positions, &mut t.normals, &mut t.indices)?;
                let c = &mut self.cube;
                let c = cube(&mut c.positions, &mut c.normals, &mut c.indices)?;
                let b = [a.bounding_sphere, b.bounding_sphere, c.bounding_sphere];
                self.spheres = Some(b);
                b
            }
        };
        Ok([self.sphere.mesh(spheres[0]), self.torus.mesh(spheres[1]), self.cube.mesh(spheres[2])])
    }

    /// The camera and lighting of the standard scene for a `width × height`
    /// frame, with `S` subpixel bits.
    pub fn pipeline<T: Scalar, const S: u32>(width: u32, height: u32) -> Result<Pipeline<T, S>, Error> {
        let f = T::from_f32;
        let view = transform::look_at(
            Vec3::new(f(0.0), f(2.2), f(6.5)),
            Vec3::new(f(0.0), f(0.0), f(0.0)),
            Vec3::new(f(0.0), f(1.0), f(0.0)),
        )?;
        let light =
            Lighting::new(f(0.25), Vec3::new(f(-0.4), f(0.7), f(0.6)), f(0.75)).with_specular(f(0.4), 24);
        let mut p = Pipeline::perspective(view, f(0.9), f(1.0), f(20.0), width, height)?.with_lighting(light);
        p.shade = Shade::Gouraud;
        Ok(p)
    }

    /// Runs the vertex stage of the standard scene at animation angle
    /// `angle` (radians) into `bins`, with colours of type `C`.
    pub fn draw<T: Scalar, C: Interpolate, const S: u32, const N: usize>(
        &mut self,
        pipeline: &Pipeline<T, S>,
        angle: f32,
        bins: &mut heapless::Vec<ScreenTriangle<S>, N>,
    ) -> Result<Stats, Error> {
        let f = T::from_f32;
        let color = |rgb: [f32; 3]| {
            let m = C::CHANNEL_MAX;
            C::from_channels([0, 1, 2].map(|k| (rgb[k] * m[k] as f32 + 0.5) as u8))
        };
        let models: [(Mat4<T>, C); 3] = [
            (
                transform::rotation_y(f(angle)) * transform::scaling(Vec3::new(f(1.25), f(1.25), f(1.25))),
                color([0.9, 0.35, 0.2]),
            ),
            (transform::rotation_y(f(angle * 0.5)) * transform::rotation_x(f(0.9)), color([0.25, 0.6, 0.95])),
            (
                transform::translation(Vec3::new(f(1.6), f(-0.2), f(0.4)))
                    * transform::rotation_y(f(-angle))
                    * transform::scaling(Vec3::new(f(0.6), f(0.6), f(0.6))),
                color([0.95, 0.85, 0.3]),
            ),
        ];
        let meshes = self.meshes()?;
        let mut total = Stats::default();
        for (mesh, (model, c)) in meshes.iter().zip(models) {
            let s = pipeline.draw_mesh(mesh, &model, c, bins)?;
            total.clipped += s.clipped;
            total.back_faces += s.back_faces;
            total.degenerate += s.degenerate;
            total.emitted += s.emitted;
        }
        Ok(total)
    }
}
