//! The vertex path's projection error against f64 inside the documented `Fx`
//! envelope.

use embedded_graphics_core::pixelcolor::Gray8;
use microraster::Error;
use microraster::edge::Cull;
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::Pipeline;
use microraster::raster3d::ScreenTriangle;

// ------------------------------------------------------------ vertex stage

/// Screen positions through the pipeline against an f64 projection of the
/// same `f32` points, inside the documented `Fx` envelope (model coordinates
/// within ±4, eye within ±256, target within ±64, fov 20°..120°, near ≥
/// 1/16, far ≤ 4096), bucketed by clip `w` as in the table of
/// `src/geometry/math/transform.rs`: the error must stay below the documented bound
/// plus half a subpixel of snapping (`S = 8`). Beyond the envelope `Fx`
/// constructors report saturation as a typed error.
#[test]
fn limit_vertex_path_error() {
    use microraster::math::{Fx, Scalar};
    /// Worst error per `w` bucket (`< 1`, `1..4`, `≥ 4`) and point counts.
    fn worst<T: Scalar>(
        eye: [f32; 3],
        target: [f32; 3],
        fov: f32,
        near: f32,
        far: f32,
    ) -> ([f64; 3], [usize; 3]) {
        let (w, h) = (320u32, 240u32);
        let f = |v: [f32; 3]| Vec3::<T>::from_f32(v);
        let view = transform::look_at(f(eye), f(target), f([0.0, 1.0, 0.0])).unwrap();
        let mut p =
            Pipeline::<T, 8>::perspective(view, T::from_f32(fov), T::from_f32(near), T::from_f32(far), w, h)
                .unwrap();
        p.cull = Cull::None;
        // Reference: f64 look_at and perspective from the same f32 inputs.
        let e = eye.map(f64::from);
        let d: Vec<f64> = (0..3).map(|i| f64::from(target[i]) - e[i]).collect();
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let fw = [d[0] / len, d[1] / len, d[2] / len];
        let sl = fw[0].hypot(fw[2]);
        let side = [-fw[2] / sl, 0.0, fw[0] / sl]; // fw × (0, 1, 0), normalised
        let up = [
            side[1] * fw[2] - side[2] * fw[1],
            side[2] * fw[0] - side[0] * fw[2],
            side[0] * fw[1] - side[1] * fw[0],
        ];
        let ty = (f64::from(fov) / 2.0).tan();
        let aspect = f64::from(w) / f64::from(h);
        let (mut worst, mut n) = ([0.0f64; 3], [0usize; 3]);
        let grid = [-4.0f32, -2.9, -1.7, -0.6, 0.0, 0.45, 1.3, 2.6, 3.5, 4.0];
        let mut points = Vec::new();
        for x in grid {
            for y in grid {
                points.extend(grid.map(|z| [x, y, z]));
            }
        }
        // And points close to the eye (w < 1), where the error is largest.
        for dist in [0.07f64, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9] {
            for u in [-0.9, -0.5, 0.0, 0.4, 0.85] {
                for v in [-0.85, -0.3, 0.2, 0.9] {
                    let q: [f64; 3] = core::array::from_fn(|i| {
                        e[i] + dist * (fw[i] + u * ty * aspect * side[i] + v * ty * up[i])
                    });
                    if q.iter().all(|c| c.abs() <= 4.0) {
                        points.push(q.map(|c| c as f32));
                    }
                }
            }
        }
        for q in points {
            {
                {
                    let [x, y, z] = q;
                    let rel: Vec<f64> = (0..3).map(|i| f64::from(q[i]) - e[i]).collect();
                    let dot = |a: [f64; 3]| rel.iter().zip(a).map(|(r, b)| r * b).sum::<f64>();
                    let (xs, ys, dist) = (dot(side), dot(up), dot(fw));
                    let (u, v) = (xs / (dist * ty * aspect), ys / (dist * ty));
                    if dist < f64::from(near) * 1.01
                        || dist > f64::from(far) * 0.99
                        || u.abs() > 0.95
                        || v.abs() > 0.95
                    {
                        continue;
                    }
                    let (sx, sy) = (f64::from(w) / 2.0 * (1.0 + u), f64::from(h) / 2.0 * (1.0 - v));
                    // A tiny triangle whose first vertex is the point.
                    let k = 0.002 * dist as f32;
                    let tri = [q, [x + k, y, z], [x, y + k, z]];
                    let mesh = Mesh::new(&tri, &[], &crate::ref3d::ONE_TRIANGLE, bounding_sphere(&tri));
                    let mut bins = heapless::Vec::<ScreenTriangle<8>, 8>::new();
                    p.draw_mesh(&mesh, &Mat4::IDENTITY, Gray8::new(1), &mut bins).unwrap();
                    let Some(t) = bins.first() else { continue };
                    let got = (f64::from(t.v[0].pos.x()) / 256.0, f64::from(t.v[0].pos.y()) / 256.0);
                    let b = if dist < 1.0 {
                        0
                    } else if dist < 4.0 {
                        1
                    } else {
                        2
                    };
                    worst[b] = worst[b].max((got.0 - sx).abs().max((got.1 - sy).abs()));
                    n[b] += 1;
                }
            }
        }
        (worst, n)
    }
    let snap = 1.0 / 512.0;
    let (fx_bound, f32_bound) = ([0.48, 0.10, 0.15], [0.036, 0.018, 0.0045]);
    /// Eye, target, fov, near, far.
    type Camera = ([f32; 3], [f32; 3], f32, f32, f32);
    let cases: [Camera; 7] = [
        ([0.3, -0.2, 4.3], [0.0, 0.0, 0.0], 2.094, 1.0 / 16.0, 4096.0),
        ([-4.5, 0.2, 0.1], [0.0, 0.0, 0.0], 1.5, 1.0 / 16.0, 100.0),
        ([0.0, 1.0, 5.0], [0.0, 0.0, 0.0], 1.0, 1.0 / 16.0, 100.0),
        ([256.0, 200.0, -256.0], [64.0, -64.0, 64.0], 0.349, 1.0 / 16.0, 4096.0), // 20°
        ([-256.0, -256.0, 256.0], [-64.0, 64.0, -64.0], 2.094, 1.0 / 16.0, 4096.0), // 120°
        ([3.0, 2.0, 4.5], [0.0, 0.0, 0.0], 2.094, 1.0 / 16.0, 4096.0),
        ([-2.0, 0.5, 4.2], [1.0, 0.0, -1.0], 0.349, 1.0 / 16.0, 50.0),
    ];
    let mut total = [0usize; 3];
    for (eye, target, fov, near, far) in cases {
        let (ef, nf) = worst::<f32>(eye, target, fov, near, far);
        let (ex, nx) = worst::<Fx>(eye, target, fov, near, far);
        println!(
            "vertex error eye {eye:?} fov {fov}: w<1, 1..4, ≥4: f32 {ef:.4?} px {nf:?}, Fx {ex:.4?} px {nx:?}"
        );
        for b in 0..3 {
            assert!(
                ef[b] <= f32_bound[b] + snap,
                "f32 error {} px beyond {} + snapping",
                ef[b],
                f32_bound[b]
            );
            assert!(ex[b] <= fx_bound[b] + snap, "Fx error {} px beyond {} + snapping", ex[b], fx_bound[b]);
            total[b] += nf[b].min(nx[b]);
        }
    }
    println!("vertex error: points per w bucket {total:?}");
    assert!(total.iter().all(|&n| n >= 50), "points per w bucket: {total:?}");
    // Beyond the Fx envelope: saturation is reported, not hidden.
    let f = |v: [f32; 3]| Vec3::<Fx>::from_f32(v);
    assert_eq!(
        transform::look_at(f([30000.0, 0.0, 0.0]), f([-30000.0, 0.0, 0.0]), f([0.0, 1.0, 0.0])).err(),
        Some(Error::CoordinateOutOfRange)
    );
    assert_eq!(
        transform::perspective(Fx::ONE, Fx::from_bits(1), Fx::ONE, Fx::from_f32(10.0)).err(),
        Some(Error::CoordinateOutOfRange)
    );
    // f32 far beyond: inputs up to f32::MAX/16 never give NaN or inf.
    let g = |v: [f32; 3]| Vec3::<f32>::from_f32(v);
    let big = f32::MAX / 16.0;
    let results = [
        transform::look_at(g([big, 0.0, 0.0]), g([-big, 1.0, 0.0]), g([0.0, 1.0, 0.0])),
        transform::look_at(g([big, big, big]), g([0.0, 0.0, 0.0]), g([0.0, 1.0, 0.0])),
        transform::perspective(1.0, 1.0, 1.0e-30, big),
        transform::orthographic(-big, big, -big, big, -big, big),
    ];
    for m in results.into_iter().flatten() {
        assert!(m.to_f32().iter().flatten().all(|v| v.is_finite()), "{m:?}");
    }
}
