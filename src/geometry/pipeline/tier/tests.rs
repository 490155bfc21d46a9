//! The fast tier's vertex bounds against the exact tier, vertex by vertex:
//! snapped `x`, `y` within one subpixel, the depth's 16-bit code within
//! one, `1/w` within `2^-20` relative; every route that snaps a vertex
//! (eager, cached with the pre-snap quotients, general) gives the same
//! point; the lit colour within `2^-12` of full intensity.

use super::super::Pipeline;
use super::super::model_light::{FAST_SPEC_FLOOR, ModelLight};
use super::super::presnap::{PreSnap, depth_f32};
use super::{ExactTier, FastTier};
use crate::light::{Lighting, Viewer};
use crate::math::vec::tests::Rng;
use crate::math::{Fx, Mat4, Scalar, Vec3, transform};
use crate::raster3d::ScreenVertex;

/// The 16-bit depth code of a `u32` depth (`Depth16`'s top bits).
fn code(d: u32) -> i64 {
    i64::from(d >> 16)
}

/// Fast and exact snaps of `c` agree within the bounds (module docs);
/// returns whether they differ at all, `None` if either fails.
fn compare<T: Scalar, const S: u32>(p: &Pipeline<T, S>, c: [T; 4]) -> Option<bool> {
    let e: ScreenVertex<S> = p.snap_vertex::<ExactTier>(c)?;
    let f = p.snap_vertex::<FastTier>(c).expect("the fast tier snaps what the exact one does");
    let (dx, dy) = (f.pos.x() - e.pos.x(), f.pos.y() - e.pos.y());
    assert!(dx.abs() <= 1 && dy.abs() <= 1, "{c:?}: {e:?} vs {f:?}");
    assert!((code(f.depth) - code(e.depth)).abs() <= 1, "depth {c:?}: {e:?} vs {f:?}");
    let rel = (f64::from(f.inv_w) - f64::from(e.inv_w)).abs() / f64::from(e.inv_w);
    assert!(rel <= 1.0 / 1_048_576.0 || (f.inv_w as i64 - e.inv_w as i64).abs() <= 2, "1/w {c:?}");
    Some(dx != 0 || dy != 0)
}

fn pipeline<T: Scalar>() -> Pipeline<T, 4> {
    Pipeline::perspective(Mat4::IDENTITY, T::from_f32(0.9), T::from_f32(1.0), T::from_f32(20.0), 320, 240)
        .unwrap()
}

/// Random clip positions across the guard band, rounding ties and the
/// guard band's edge, for `f32` and `Fx`.
fn snaps_within_one<T: Scalar>(seed: u64) {
    let p = pipeline::<T>();
    let g = p.clip.guard_band() as f64;
    let mut rng = Rng(seed);
    let (mut n, mut moved) = (0u32, 0u32);
    for i in 0..300_000u32 {
        let w = [rng.range(1.0, 20.0), rng.range(1.0, 1.2), rng.range(15.0, 20.0)][i as usize % 3];
        let span = [1.2, g, 1.0][i as usize % 3];
        let mut x = rng.range(-span, span) * w;
        let y = rng.range(-span, span) * w;
        match i % 4 {
            // A tie: x/w·2560 a half-integer (as exactly as f32 allows).
            1 => x = ((rng.range(-2000.0, 2000.0)).floor() + 0.5) / 2560.0 * w,
            // On the guard band's edge.
            2 => x = if i % 8 == 2 { g as f32 * w } else { -(g as f32) * w },
            _ => {}
        }
        let z = rng.range(0.0, 1.0) * w;
        let c = [x, y, z, w].map(T::from_f32);
        if let Some(m) = compare(&p, c) {
            n += 1;
            moved += u32::from(m);
        }
    }
    // Not vacuous: nearly all snap, and some fast positions do move.
    assert!(n > 290_000 && moved > 0, "{n} snapped, {moved} moved");
}

#[test]
fn fast_snaps_within_one_subpixel_f32() {
    snaps_within_one::<f32>(0xFA57_0F32);
}

#[test]
fn fast_snaps_within_one_subpixel_fx() {
    snaps_within_one::<Fx>(0xFA57_00F1);
}

/// Every route gives the fast tier's one point: the eager `snap_inside`,
/// the cached path's quotients and their rounding, and the general
/// `snap_xy`; the deferred depth equals `snap_depth`.
#[test]
fn fast_routes_snap_alike() {
    let p = pipeline::<f32>().with_origin(3, -7);
    let pre = PreSnap::new::<f32>(p.size, p.origin, 4);
    let mut rng = Rng(0x0000_70E5);
    let mut inside = 0;
    for i in 0..300_000u32 {
        let w = rng.range(0.5, 30.0);
        let span = [1.5, 40.0, 1.0e4][i as usize % 3];
        let c = [rng.range(-span, span) * w, rng.range(-span, span) * w, rng.range(0.0, 1.0) * w, w];
        let general = c[3].divisor().and_then(|d| p.snap_xy::<FastTier>(c, d));
        if let Some(pos) = pre.snap_inside::<f32, 4, FastTier>(c) {
            assert_eq!(Some(pos), general, "{c:?}");
            inside += 1;
        }
        if let Some(q) = pre.quotients::<f32, FastTier>(c) {
            assert_eq!(pre.snap::<4>(q), general, "{c:?}");
        }
        let d = depth_f32::<FastTier>(c[2], c[3], Some(1.0));
        if let (Some(d), Some(w)) = (d, c[3].divisor()) {
            assert_eq!(Some(d), p.snap_depth::<FastTier>(c, w), "{c:?}");
        }
    }
    assert!(inside > 100_000, "{inside}");
}

/// A vertex beyond the fast quotients' range snaps exactly (a guard band
/// as wide as snapping allows).
#[test]
fn beyond_the_fast_range_snaps_exactly() {
    let mut p = pipeline::<f32>();
    p.clip = p.clip.with_guard_band(crate::clip3d::guard_band_for_range(320, 240, 4));
    let w = 1.0f32;
    for x in [900.0f32, -1500.0, 3.0e3, 1.0e4] {
        let c = [x, 0.25, 0.5, w];
        let (e, f) = (p.snap_vertex::<ExactTier>(c), p.snap_vertex::<FastTier>(c));
        assert_eq!(e.map(|v| v.pos), f.map(|v| v.pos), "{x}");
    }
}

/// The lit colour of the fast tier within `2^-12` of the exact tier's
/// (a fifth of a 6-bit channel's step) over random similarities,
/// normals, positions, lights, strengths, exponents (odd and even) and
/// both viewers; the specular floor is what it says.
#[test]
fn fast_lighting_within_bound() {
    let mut rng = Rng(0x00C0_10A5);
    let (mut worst, mut worst_fx, mut spec) = (0.0f32, 0.0f32, 0);
    for i in 0..3_000u32 {
        let exp = [1, 2, 5, 8, 16, 24, 33, 64, 128][i as usize % 9];
        let viewer = if i % 4 == 3 { Viewer::Infinite } else { Viewer::Local };
        let d = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(0.1, 1.0));
        let strength = rng.range(0.05, 1.0);
        let light = Lighting::<f32>::new(rng.range(0.0, 0.3), d, rng.range(0.3, 0.8))
            .with_specular(strength, exp)
            .with_viewer(viewer);
        let light_fx = Lighting::<Fx>::new(
            Fx::from_f32(light.ambient),
            Vec3::from_f32([light.direction.x, light.direction.y, light.direction.z]),
            Fx::from_f32(light.diffuse),
        )
        .with_specular(Fx::from_f32(strength), exp)
        .with_viewer(viewer);
        let s = rng.range(0.5, 2.0);
        let m = transform::translation(Vec3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-8.0, -3.0),
        )) * transform::rotation_y(rng.range(0.0, 6.3))
            * transform::rotation_x(rng.range(0.0, 6.3))
            * transform::scaling(Vec3::new(s, s, s));
        let m_fx = Mat4 { cols: m.cols.map(|c| c.map(Fx::from_f32)) };
        let (e, f) =
            (ModelLight::new(&light, &m, false).unwrap(), ModelLight::new(&light, &m, true).unwrap());
        let (ex, fx) = (
            ModelLight::new(&light_fx, &m_fx, false).unwrap(),
            ModelLight::new(&light_fx, &m_fx, true).unwrap(),
        );
        for _ in 0..40 {
            let n = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let n = n.map(|v| v / len);
            let p = Vec3::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
            let base = [1.0, 0.6, 0.2];
            let (a, b) = (e.shade::<ExactTier>(n, p, base), f.shade::<FastTier>(n, p, base));
            // Blue's base is 0.2: above 0.25 the highlight adds at least 0.03.
            spec += usize::from(a[2] > 0.25);
            for k in 0..3 {
                worst = worst.max((a[k] - b[k]).abs());
            }
            let pf = Vec3::from_f32([p.x, p.y, p.z]);
            let bf = base.map(Fx::from_f32);
            let (a, b) = (ex.shade::<ExactTier>(n, pf, bf), fx.shade::<FastTier>(n, pf, bf));
            for k in 0..3 {
                worst_fx = worst_fx.max((a[k].to_f32() - b[k].to_f32()).abs());
            }
        }
    }
    assert!(worst <= 1.0 / 4096.0 && worst_fx <= 1.0 / 4096.0, "f32 {worst:e}, Fx {worst_fx:e}");
    // Not vacuous: the tiers differ, and highlights were lit.
    assert!(worst > 0.0 && worst_fx > 0.0 && spec > 1000, "{worst:e} {worst_fx:e} {spec}");
    const { assert!(FAST_SPEC_FLOOR <= 1.0 / 4096.0) };
}
