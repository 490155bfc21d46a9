//! The f64 reference 3D pipeline ([`Ref3d`]): f64 matrices, the standard
//! scene's camera and light, transform, lighting and perspective-correct raster.

use super::{BG3, H, W, float_triangle, material, model};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Interpolate;
use microraster_scenes::scenes3d::Scene3d;

/// A 4 × 4 matrix, rows.
pub type M4 = [[f64; 4]; 4];

/// `a · b`.
pub fn mul(a: &M4, b: &M4) -> M4 {
    let mut m = [[0.0; 4]; 4];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}

fn apply(m: &M4, p: [f64; 4]) -> [f64; 4] {
    [0, 1, 2, 3].map(|i| (0..4).map(|k| m[i][k] * p[k]).sum())
}

fn ident() -> M4 {
    let mut m = [[0.0; 4]; 4];
    (0..4).for_each(|i| m[i][i] = 1.0);
    m
}

fn rot_x(a: f64) -> M4 {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, 0.0], [0.0, 0.0, 0.0, 1.0]]
}

/// Rotation by `a` radians about y.
pub fn rot_y(a: f64) -> M4 {
    let (s, c) = a.sin_cos();
    [[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]]
}

fn scale(v: f64) -> M4 {
    let mut m = ident();
    (0..3).for_each(|i| m[i][i] = v);
    m
}

fn translate(t: [f64; 3]) -> M4 {
    let mut m = ident();
    (0..3).for_each(|i| m[i][3] = t[i]);
    m
}

/// `v` scaled to unit length.
pub fn norm(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / l)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The standard scene's light (`Scene3d::pipeline`): direction in eye
/// space (not normalised), ambient, diffuse and specular weights, exponent.
pub const LIGHT: [f64; 3] = [-0.4, 0.7, 0.6];
/// Ambient weight of the standard scene's light.
pub const AMBIENT: f64 = 0.25;
/// Diffuse (Lambert) weight.
pub const DIFFUSE: f64 = 0.75;
/// Specular (Blinn–Phong) weight.
pub const SPECULAR: f64 = 0.4;
/// Specular exponent.
pub const SHININESS: i32 = 24;
/// The near plane's distance.
const NEAR: f64 = 1.0;

/// The standard scene's view and projection matrices (`Scene3d::pipeline`:
/// `look_at` from (0, 1.9, 5.6) to the origin, 0.9 rad vertical field of
/// view, near 1, far 20, `W × H`), in f64, rows.
pub fn camera() -> (M4, M4) {
    let eye = [0.0, 1.9, 5.6];
    let f = norm([-eye[0], -eye[1], -eye[2]]);
    let s = norm(cross(f, [0.0, 1.0, 0.0]));
    let u = cross(s, f);
    let view: M4 = [
        [s[0], s[1], s[2], -dot(s, eye)],
        [u[0], u[1], u[2], -dot(u, eye)],
        [-f[0], -f[1], -f[2], dot(f, eye)],
        [0.0, 0.0, 0.0, 1.0],
    ];
    let (near, far, fov) = (NEAR, 20.0, 0.9f64);
    let fy = 1.0 / (fov / 2.0).tan();
    let a = far / (near - far);
    let proj: M4 = [
        [fy / (W as f64 / H as f64), 0.0, 0.0, 0.0],
        [0.0, fy, 0.0, 0.0],
        [0.0, 0.0, a, near * a],
        [0.0, 0.0, -1.0, 0.0],
    ];
    (view, proj)
}

/// One front-facing triangle of the f64 pipeline, in screen space (unsnapped).
#[derive(Clone, Copy, Debug)]
pub struct RefTri {
    /// Pixel coordinates.
    pub xy: [(f64, f64); 3],
    /// Depth `z/w`.
    pub d: [f64; 3],
    /// `1/w`.
    pub q: [f64; 3],
    /// Lit vertex colour in `[0, 1]` per channel.
    pub c: [[f64; 3]; 3],
    /// Source triangle: `mesh · 65536 + index`.
    pub id: u32,
}

/// Per pixel of the f64 reference frame: the nearest triangle's id
/// (`u32::MAX` for background), its depth and its perspective-correct colour.
#[derive(Clone, Copy, Debug)]
pub struct RefPixel {
    /// Source triangle id, `u32::MAX` if none.
    pub id: u32,
    /// Depth `z/w` in `[0, 1]`.
    pub depth: f64,
    /// Colour channels in `[0, 1]`.
    pub color: [f64; 3],
}

/// The standard 3D scene through an f64 pipeline: f64 model, view and
/// projection (same camera, lights and materials as `scenes3d`), f64 lighting
/// (ambient + Lambert + Blinn–Phong per vertex), back faces culled by the
/// unsnapped screen area, then per pixel centre an f64 point-in-triangle test,
/// the depth `z/w` interpolated exactly and `LESS` (the nearest wins), and
/// perspective-correct colour. No snapping, no quantization.
pub struct Ref3d {
    /// Front-facing triangles.
    pub tris: Vec<RefTri>,
}

impl Ref3d {
    /// The vertex stage at `angle`, with materials quantized for `C` as the
    /// library does.
    pub fn new<C: Interpolate>(angle: f32) -> Self {
        let (view, proj) = camera();
        let near = NEAR;
        let light = norm(LIGHT);
        let (ambient, diffuse, spec, exp) = (AMBIENT, DIFFUSE, SPECULAR, SHININESS);
        let ang = angle as f64;
        let models = [
            mul(&rot_y(ang), &scale(1.45)),
            mul(&rot_y(ang * 0.5), &rot_x(0.45)),
            mul(&mul(&translate([1.05, -0.5, 1.25]), &rot_y(-ang)), &scale(0.55)),
        ];
        let mut tris = Vec::new();
        for (k, mesh) in Scene3d.meshes().iter().enumerate() {
            let mv = mul(&view, &models[k]);
            let mvp = mul(&proj, &mv);
            let base = material::<C>(model::<f32>(k, angle).1).to_channels();
            let max = C::CHANNEL_MAX;
            let base = [0, 1, 2].map(|i| if max[i] == 0 { 0.0 } else { base[i] as f64 / max[i] as f64 });
            // Rotation and uniform scale: the normal matrix is the rotation part, normalised.
            let nm = |n: [f32; 3]| {
                let v = apply(&mv, [n[0] as f64, n[1] as f64, n[2] as f64, 0.0]);
                norm([v[0], v[1], v[2]])
            };
            for (i, idx) in mesh.indices.iter().enumerate() {
                let vert = |j: usize| {
                    let p = mesh.positions[idx[j] as usize].map(|c| c as f64);
                    let clip = apply(&mvp, [p[0], p[1], p[2], 1.0]);
                    let eye_p = apply(&mv, [p[0], p[1], p[2], 1.0]);
                    let n = nm(mesh.normals[idx[j] as usize]);
                    let lambert = dot(n, light).max(0.0);
                    let sp = if lambert > 0.0 {
                        let h = norm([
                            light[0] - norm([eye_p[0], eye_p[1], eye_p[2]])[0],
                            light[1] - norm([eye_p[0], eye_p[1], eye_p[2]])[1],
                            light[2] - norm([eye_p[0], eye_p[1], eye_p[2]])[2],
                        ]);
                        spec * dot(n, h).max(0.0).powi(exp)
                    } else {
                        0.0
                    };
                    let c = base.map(|b| (b * (ambient + diffuse * lambert) + sp).clamp(0.0, 1.0));
                    assert!(clip[3] > near * 0.999, "the f64 reference does not clip");
                    let w = clip[3];
                    let xy = (W as f64 / 2.0 * (1.0 + clip[0] / w), H as f64 / 2.0 * (1.0 - clip[1] / w));
                    (xy, clip[2] / w, 1.0 / w, c)
                };
                let v = [vert(0), vert(1), vert(2)];
                let xy = v.map(|v| v.0);
                let area =
                    (xy[1].0 - xy[0].0) * (xy[2].1 - xy[0].1) - (xy[2].0 - xy[0].0) * (xy[1].1 - xy[0].1);
                if area >= 0.0 {
                    continue; // clockwise on screen (y down): a back face, or zero area
                }
                tris.push(RefTri {
                    xy,
                    d: v.map(|v| v.1),
                    q: v.map(|v| v.2),
                    c: v.map(|v| v.3),
                    id: (k as u32) << 16 | i as u32,
                });
            }
        }
        Ref3d { tris }
    }

    /// Rasterizes every triangle into `out` (`W × H`, row-major).
    pub fn raster(&self, out: &mut [RefPixel]) {
        out.fill(RefPixel { id: u32::MAX, depth: f64::INFINITY, color: [0.0; 3] });
        for t in &self.tris {
            let p = t.xy;
            let det = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
            float_triangle(p, |x, y| {
                let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                let l1 = ((cx - p[0].0) * (p[2].1 - p[0].1) - (cy - p[0].1) * (p[2].0 - p[0].0)) / det;
                let l2 = ((p[1].0 - p[0].0) * (cy - p[0].1) - (p[1].1 - p[0].1) * (cx - p[0].0)) / det;
                let l = [1.0 - l1 - l2, l1, l2];
                let d = (0..3).map(|i| l[i] * t.d[i]).sum::<f64>();
                let px = &mut out[y * W + x];
                if d < px.depth && (0.0..=1.0).contains(&d) {
                    let qs = (0..3).map(|i| l[i] * t.q[i]).sum::<f64>();
                    let color =
                        [0, 1, 2].map(|k| (0..3).map(|i| l[i] * t.q[i] * t.c[i][k]).sum::<f64>() / qs);
                    *px = RefPixel { id: t.id, depth: d, color };
                }
            });
        }
    }

    /// The reference frame as `Rgb565` (for the benchmark: transform,
    /// lighting, rasterization and the colour conversion, timed together).
    pub fn frame(angle: f32, px: &mut [RefPixel], out: &mut [Rgb565]) {
        let r = Ref3d::new::<Rgb565>(angle);
        r.raster(px);
        for (o, p) in out.iter_mut().zip(px.iter()) {
            *o = if p.id == u32::MAX {
                BG3
            } else {
                let c = |v: f64, m: f64| (v * m + 0.5) as u8;
                Rgb565::new(c(p.color[0], 31.0), c(p.color[1], 63.0), c(p.color[2], 31.0))
            };
        }
    }
}
