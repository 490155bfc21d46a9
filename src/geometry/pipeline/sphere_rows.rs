//! The frame rows a cluster's bounding sphere can reach, for the frame
//! record ([`super::frame_clusters`]).
//!
//! Over a sphere of centre `c` and radius `r` (widened by the validation's
//! tolerance, as [`InsideView`](super::inside::InsideView)), clip `y` and `w` lie within `y_c ± r·|Y|`
//! and `w_c ± r·|W|` (`Y`, `W`: the rows' `xyz`, Cauchy–Schwarz). Where
//! `w_c − r·|W|` is positive, `y/w` lies between the extreme ratios of
//! those intervals; each is widened by `2^-10` of its magnitude plus
//! `2^-10` (the `f32` rounding of the dot products and quotients is below
//! `2^-20` relative), and the frame rows of those NDC bounds
//! (`oy + (1 − y)·h/2`, as `Pipeline::band_bounds`) by two rows more, for
//! snapping and the top-left rule. A sphere reaching `w ≤ 0`, or values
//! that are not finite, gives no rows: the cluster is tested per band.

use crate::math::Vec4;
use crate::math::scalar::{ceil_i32, floor_i32};
use crate::mesh::SPHERE_TOLERANCE;

/// The frame rows of spheres (module docs) for one matrix and viewport.
pub(super) struct SphereRows {
    y: Vec4<f32>,
    w: Vec4<f32>,
    /// `|Y|` and `|W|` of the rows' `xyz`.
    y_len: f32,
    w_len: f32,
    half_h: f32,
    oy: f32,
}

impl SphereRows {
    pub(super) fn new(rows: [Vec4<f32>; 4], height: u32, oy: i64) -> Self {
        let (y, w) = (rows[1], rows[3]);
        let half_h = height as f32 * 0.5;
        SphereRows { y, w, y_len: y.xyz().length(), w_len: w.xyz().length(), half_h, oy: oy as f32 }
    }

    /// The first and last frame rows the sphere can reach, or `None`.
    pub(super) fn rows(&self, (c, r): ([f32; 3], f32)) -> Option<(i16, i16)> {
        let r = r * (1.0 + 2.0 * SPHERE_TOLERANCE);
        let centre = Vec4::new(c[0], c[1], c[2], 1.0);
        let (yc, wc) = (self.y.dot(centre), self.w.dot(centre));
        let (ry, rw) = (r * self.y_len, r * self.w_len);
        let (w_lo, w_hi) = (wc - rw, wc + rw);
        if !(w_lo > 0.0 && w_hi.is_finite()) {
            return None;
        }
        let (y_lo, y_hi) = (yc - ry, yc + ry);
        let lo = y_lo / if y_lo >= 0.0 { w_hi } else { w_lo };
        let hi = y_hi / if y_hi >= 0.0 { w_lo } else { w_hi };
        let widen = |v: f32| v.abs() * (1.0 / 1024.0) + 1.0 / 1024.0;
        let (lo, hi) = (lo - widen(lo), hi + widen(hi));
        // NDC y runs up, rows down: the top row from the highest y.
        let row = |k: f32| self.oy + (1.0 - k) * self.half_h;
        let (top, bottom) = (row(hi) - 2.0, row(lo) + 2.0);
        if !(top.is_finite() && bottom.is_finite()) {
            return None;
        }
        // Saturated to `i16` (a cast would wrap): rows beyond it stay beyond
        // every band, which lies within 0..4096 (`MAX_FRAME_DIM`).
        let to_i16 = |v: i32| v.clamp(i16::MIN.into(), i16::MAX.into()) as i16;
        Some((to_i16(floor_i32(top)), to_i16(ceil_i32(bottom))))
    }
}

#[cfg(test)]
mod tests {
    use super::super::inside::tests::{eye_at_z5, rng};
    use super::*;
    use crate::math::{Mat4, Vec3, transform};

    /// Every point of a sphere (within its tolerance) in front of the eye
    /// projects at least one row inside the recorded rows, over random
    /// cameras, spheres and viewports; the rows are not vacuous.
    #[test]
    fn sphere_rows_hold_every_point() {
        let mut seed = 0x0B5E_55ED_F00Du64;
        let (mut checked, mut tight) = (0u32, 0u32);
        for _ in 0..400 {
            let dir = Vec3::new(rng(&mut seed), rng(&mut seed), rng(&mut seed) + 2.0);
            let eye = dir * (2.0 + 3.0 * rng(&mut seed).abs());
            let Ok(view) = transform::look_at(eye, Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)) else {
                continue;
            };
            let Ok(proj) = transform::perspective(0.5 + rng(&mut seed).abs(), 1.3, 0.3, 20.0) else {
                continue;
            };
            let mvp: Mat4<f32> = proj * view;
            let rows = super::super::rows_f32(&mvp);
            let (h, oy) = (60 + (rng(&mut seed).abs() * 400.0) as u32, (rng(&mut seed) * 100.0) as i64);
            let reach = SphereRows::new(rows, h, oy);
            for _ in 0..40 {
                let c = [rng(&mut seed) * 3.0, rng(&mut seed) * 3.0, rng(&mut seed) * 3.0];
                let r = rng(&mut seed).abs() * 0.5;
                let Some((top, bottom)) = reach.rows((c, r)) else { continue };
                tight += (i32::from(bottom) - i32::from(top) < h as i32) as u32;
                for i in 0..48 {
                    let d = [rng(&mut seed), rng(&mut seed), rng(&mut seed)];
                    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                    if len == 0.0 {
                        continue;
                    }
                    let s = r * (1.0 + SPHERE_TOLERANCE) / len
                        * if i % 3 == 0 { 1.0 } else { rng(&mut seed).abs() };
                    let p = [0, 1, 2].map(|k| f64::from(c[k] + d[k] * s));
                    let row = |v: Vec4<f32>| {
                        f64::from(v.x) * p[0] + f64::from(v.y) * p[1] + f64::from(v.z) * p[2] + f64::from(v.w)
                    };
                    let (y, w) = (row(rows[1]), row(rows[3]));
                    assert!(w > 0.0, "a sphere with rows reaches w ≤ 0");
                    let screen = oy as f64 + (1.0 - y / w) * f64::from(h) * 0.5;
                    // A triangle there covers rows whose centre it reaches:
                    // within a row of the point.
                    assert!(
                        f64::from(top) <= screen - 1.0 && f64::from(bottom) >= screen + 1.0,
                        "{c:?} {r} {screen}"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 100_000 && tight > 5_000, "{checked} {tight}");
    }

    /// Spheres across or behind the eye, and values that are not finite,
    /// give no rows (tested per band); spheres just in front of the eye
    /// give rows saturated to `i16`.
    #[test]
    fn spheres_at_the_eye_have_no_rows_and_near_it_saturate() {
        let reach = SphereRows::new(super::super::rows_f32(&eye_at_z5()), 240, 0);
        let (top, bottom) = reach.rows(([0.0; 3], 0.5)).expect("in front");
        assert!(top < 120 && bottom > 120 && bottom - top < 80, "{top} {bottom}");
        // Spheres just in front of the eye reach far beyond the frame, past
        // the `i16` range: their rows saturate instead of wrapping.
        let mut huge = 0;
        for k in 1..200 {
            let r = 0.51 - 0.51 * 0.9f32.powi(k);
            if let Some((top, bottom)) = reach.rows(([0.0, 0.0, 4.49], r)) {
                assert!(top <= 120 && bottom >= 120, "{r}: {top} {bottom}");
                huge += (top == i16::MIN || bottom == i16::MAX) as u32;
            }
        }
        assert!(huge > 5, "{huge}");
        assert_eq!(reach.rows(([0.0, 0.0, 5.0], 0.5)), None); // around the eye
        assert_eq!(reach.rows(([0.0, 0.0, 9.0], 0.5)), None); // behind it
        assert_eq!(reach.rows(([f32::NAN, 0.0, 0.0], 0.5)), None);
        assert_eq!(reach.rows(([0.0; 3], f32::INFINITY)), None);
    }
}
