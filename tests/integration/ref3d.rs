//! Shared f64 references for the 3D suites: exact barycentrics on snapped
//! vertices, a full-frame drawing helper with depth read-back, and one-triangle
//! meshes. Written from the documented conventions (pixel centres at +0.5,
//! depth `z/w` as `depth / 2^32`, D3D/Vulkan clip volume), not from `src/`.

use microraster::band::Band;
use microraster::depth::{DepthFormat, DepthRows, DepthState};
use microraster::raster3d::{Interpolation, ScreenTriangle, draw_triangle};
use microraster::{Interpolate, SubPoint};

/// Exact barycentric numerators of the centre of pixel `(x, y)` for the
/// snapped triangle `v`, and their common denominator (twice the signed area,
/// internal units `2^-(S+1)` px): `λ_i = num[i] / det`. `None` for zero area.
pub fn bary<const S: u32>(v: [SubPoint<S>; 3], x: i32, y: i32) -> Option<([i128; 3], i128)> {
    let p = v.map(|q| (2 * q.x() as i128, 2 * q.y() as i128));
    let c = ((2 * x as i128 + 1) << S, (2 * y as i128 + 1) << S);
    let cross = |a: (i128, i128), b: (i128, i128), q: (i128, i128)| {
        (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0)
    };
    let det = cross(p[0], p[1], p[2]);
    if det == 0 {
        return None;
    }
    // λ0 is the sub-area opposite vertex 0, and so on; the three sum to det.
    Some(([cross(p[1], p[2], c), cross(p[2], p[0], c), cross(p[0], p[1], c)], det))
}

/// Whether the snapped triangle `v` is tiny as the `raster3d` docs define
/// it (twice its area below 2^16 internal units of `2^-(S+1)` px): drawn
/// with per-pixel barycentric sums instead of planes.
pub fn is_tiny<const S: u32>(v: [SubPoint<S>; 3]) -> bool {
    bary(v, 0, 0).is_some_and(|(_, det)| det.abs() < 1 << 16)
}

/// `Σ λ_i · val_i` at the centre of pixel `(x, y)`, with the sum of products
/// formed exactly in `i128` (no cancellation), then one division in f64.
/// `val` must stay below 2^64 in magnitude.
pub fn plane_at<const S: u32>(v: [SubPoint<S>; 3], val: [i128; 3], x: i32, y: i32) -> Option<f64> {
    let (num, det) = bary(v, x, y)?;
    let s: i128 = (0..3).map(|i| num[i] * val[i]).sum();
    Some(s as f64 / det as f64)
}

/// Exact depth code at the centre of pixel `(x, y)`: the plane through the
/// vertices' `depth / (2^32 − 1)` times `2^b − 1`.
pub fn depth_code<F: DepthFormat, const S: u32>(t: &ScreenTriangle<S>, x: i32, y: i32) -> Option<f64> {
    let d = plane_at(t.v.map(|v| v.pos), t.v.map(|v| v.depth as i128), x, y)?;
    Some(d / 4294967295.0 * F::MAX as f64)
}

/// Draws `tris` in order with [`draw_triangle`] into one full-frame band of
/// `W × H` pixels (background `bg`, depth cleared to far) and returns the
/// colours and stored depth codes, row-major.
pub fn draw_frame<C, F, M, const S: u32, const W: usize, const H: usize>(
    tris: &[ScreenTriangle<S>],
    bg: C,
    state: DepthState,
) -> (Vec<C>, Vec<u32>)
where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    let mut band = Box::new(Band::<C, W, H>::new(bg));
    let mut depth = vec![[F::FAR; W]; H];
    {
        let mut view = band.view(0, H, bg);
        let mut rows = DepthRows::<F, W>::new(&mut depth);
        for t in tris {
            draw_triangle(t, &mut view, &mut rows, state, M::default());
        }
    }
    let color = band.rows().iter().flatten().copied().collect();
    let depth = depth.iter().flatten().map(|&s| F::to_u32(s)).collect();
    (color, depth)
}

/// Indices of a single triangle.
pub const ONE_TRIANGLE: [[u16; 3]; 1] = [[0, 1, 2]];
/// Indices of a quad `0 1 2 3` split along `0–2`.
pub const QUAD: [[u16; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

/// A bounding sphere about the origin containing every position with a wide
/// margin: valid, but so loose that the pipeline's sphere test never rejects
/// the mesh (it contains the eye), leaving all the work to the clipper.
pub fn loose_sphere(p: &[[f32; 3]]) -> ([f32; 3], f32) {
    let r = p.iter().map(|q| (q[0] as f64).hypot(q[1] as f64).hypot(q[2] as f64)).fold(1.0, f64::max);
    ([0.0; 3], (2.0 * r) as f32)
}
