//! The target's checks outside `run`: constructor results, a binned
//! triangle's signed area, and the f64 test for a mesh wholly behind the eye.

use super::inputs::is_f32;
use microraster::Error;
use microraster::math::{Mat4, Scalar};
use microraster::pipeline::Pipeline;
use microraster::raster3d::ScreenTriangle;

pub(super) fn check_ctor<T: Scalar>(what: &str, inputs: &[f32], r: &Result<Mat4<T>, Error>) {
    match r {
        Ok(m) => {
            assert!(m.to_f32().iter().flatten().all(|v| v.is_finite()), "{what}{inputs:?}: non-finite matrix")
        }
        Err(e) => {
            if is_f32::<T>() && inputs.iter().any(|v| !v.is_finite()) {
                assert_eq!(*e, Error::NonFiniteCoordinate, "{what}{inputs:?}");
            }
            assert!(
                matches!(
                    e,
                    Error::NonFiniteCoordinate | Error::InvalidParameter | Error::CoordinateOutOfRange
                ),
                "{what}{inputs:?}: {e:?}"
            );
        }
    }
}

pub(super) fn signed_area2<const S: u32>(t: &ScreenTriangle<S>) -> i64 {
    let p = t.v.map(|v| (i64::from(v.pos.x()), i64::from(v.pos.y())));
    (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
}

/// True if every triangle has all three clip-space `w` clearly below 0,
/// computed in f64 from the pipeline's own (converted) matrices and
/// positions, with a margin for the path's rounding. `Fx` only when nothing
/// can saturate.
pub(super) fn all_behind_eye<T: Scalar, const S: u32>(
    p: &Pipeline<T, S>,
    proj: Mat4<T>,
    model: &Mat4<T>,
    pos: &[[f32; 3]],
    idx: &[[u16; 3]],
) -> bool {
    let f64m = |m: Mat4<T>| m.to_f32().map(|c| c.map(f64::from));
    let mul = |a: [[f64; 4]; 4], b: [[f64; 4]; 4]| -> [[f64; 4]; 4] {
        core::array::from_fn(|c| core::array::from_fn(|r| (0..4).map(|k| a[k][r] * b[c][k]).sum()))
    };
    let abs = |a: [[f64; 4]; 4]| a.map(|c| c.map(f64::abs));
    let (v, m) = (f64m(p.view()), f64m(*model));
    let proj = f64m(proj);
    let mvp = mul(proj, mul(v, m));
    let mag = mul(abs(proj), mul(abs(v), abs(m)));
    let fx = !is_f32::<T>();
    if fx && mag.iter().flatten().any(|&e| e > 4000.0) {
        return false;
    }
    idx.iter().all(|t| {
        t.iter().all(|&i| {
            let q = pos[usize::from(i)].map(|c| f64::from(T::from_f32(c).to_f32()));
            let h = [q[0], q[1], q[2], 1.0];
            let w: f64 = (0..4).map(|k| mvp[k][3] * h[k]).sum();
            let size: f64 = (0..4).map(|k| mag[k][3] * h[k].abs()).sum();
            if !w.is_finite() || !size.is_finite() || (fx && size > 4000.0) {
                return false;
            }
            let tol = if fx { 0.01 + 1e-3 * size } else { 1e-5 * size };
            w < -tol
        })
    })
}
