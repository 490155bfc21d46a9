//! The target's checks outside `run`: constructor results, a binned
//! triangle's signed area, and the f64 test for a mesh wholly behind the eye.

use microraster::Error;
use microraster::math::{Mat4, Scalar};
use microraster::pipeline::Pipeline;
use microraster_fuzz::{clip_matrix_f64, is_f32};

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
                    Error::NonFiniteCoordinate | Error::InvalidParameter(_) | Error::CoordinateOutOfRange
                ),
                "{what}{inputs:?}: {e:?}"
            );
        }
    }
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
    let (mvp, mag) = clip_matrix_f64(proj, p.view(), *model);
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

/// True if a vertex some triangle uses may have an `f32` clip coordinate
/// beyond the clipper's input range, ±2^64 (the vertex stage's
/// `CoordinateOutOfRange`): in f64 from the pipeline's matrices, `|v|` plus
/// the path's rounding (`1e-5` of the sum of magnitudes, as above) reaches
/// 2^64, or a value is not finite.
pub(super) fn clip_beyond_range<T: Scalar, const S: u32>(
    p: &Pipeline<T, S>,
    proj: Mat4<T>,
    model: &Mat4<T>,
    pos: &[[f32; 3]],
    idx: &[[u16; 3]],
) -> bool {
    let (mvp, mag) = clip_matrix_f64(proj, p.view(), *model);
    let limit = 2f64.powi(64);
    idx.iter().flatten().any(|&i| {
        let q = pos[usize::from(i)].map(f64::from);
        let h = [q[0], q[1], q[2], 1.0];
        (0..4).any(|r| {
            let v: f64 = (0..4).map(|k| mvp[k][r] * h[k]).sum();
            let size: f64 = (0..4).map(|k| mag[k][r] * h[k].abs()).sum();
            !(v.abs() + 1e-5 * size < limit)
        })
    })
}
