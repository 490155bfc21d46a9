//! Back faces rejected before snapping (`f32` only): the orientation of a
//! triangle from the values snapping rounds, with a margin that covers the
//! rounding, so a back face costs neither its vertices' conversion to
//! subpixels nor the exact area test.
//!
//! # Why the margin suffices
//! With `f32`, snapping a coordinate `c` (`x`, or `−y` since y is flipped)
//! of a vertex with clip `w` computes `q = fl(fl(c / w) · a)`, `a` half the
//! viewport in subpixels ([`Scalar::div_scaled_by`](crate::math::Scalar)),
//! then `origin + round_even(q)`. [`PreSnap::quotients`] computes the same `q`, bit
//! for bit. So each snapped coordinate is `B + R` with `B` a per-axis integer
//! and `|R − q| ≤ 1/2`.
//!
//! The exact test ([`super::Pipeline::keep`]) takes the sign of
//! `A = cross(R1 − R0, R2 − R0)` (`B` cancels). With `e1 = q1 − q0`,
//! `e2 = q2 − q0` (exact) and `d1, d2` the rounding of the differences
//! (each component within 1): `A = cross(e1, e2) + cross(e1, d2) +
//! cross(d1, e2) + cross(d1, d2)`, so `|A − cross(e1, e2)| ≤ M =
//! |e1x| + |e1y| + |e2x| + |e2y| + 2`. In `f32` the differences round by a
//! relative `u = 2^-24`, the products and their difference by `u` more: the
//! computed `Â` is within `5u·T`, `T = |e1x·e2y| + |e1y·e2x|`, of
//! `cross(e1, e2)`. The bound is computed as `(M̂ + 2^-20·T̂)·(1 + 2^-10)`,
//! where `2^-20 = 16u` covers `5u` and `T̂ ≥ (1 − 4u)·T`, and the factor
//! covers the relative error (a few `u`) of the computed `M̂`, `T̂` and sum.
//! So `Â > bound` gives `A > 0`, `Â < −bound` gives `A < 0`: the exact test
//! decides the same. With `|q| ≤ 2^22` nothing overflows and, with the
//! offsets within `2^27` ([`PreSnap::new`]), snapping cannot fail for these
//! vertices, so the triangle is counted as a back face exactly as before.

use super::tier::Tier;
use crate::math::Scalar;
use crate::math::divisor::{TWO23, round_even_below_2p23, round_even_f32, round_even_signed_below_2p22};

/// The largest `|q|` [`orientation`] accepts.
const Q_MAX: f32 = 4_194_304.0; // 2^22

/// The largest `|q|` the fast tier rounds from its own quotients
/// (`snap::FAST_SNAP_MAX`); the general path decides beyond it.
const FAST_Q_MAX: f32 = 2_097_152.0; // 2^21

/// The quotients snapping rounds, x then −y (`ax`, `ay` half the viewport
/// in subpixels): the exact tier's `c/w·a`, the fast tier's `c·(1/w)·a`
/// (one `VDIV`, as `FastQuotient` computes it), within that tier's range.
#[inline(always)]
fn tier_quotients<R: Tier>(x: f32, y: f32, w: f32, [ax, ay]: [f32; 2]) -> Option<[f32; 2]> {
    let (q, lim) = if R::FAST {
        let r = 1.0 / w;
        ([x * r * ax, -y * r * ay], FAST_Q_MAX)
    } else {
        ([x / w * ax, -y / w * ay], Q_MAX)
    };
    // False for NaN and infinity too.
    (q[0].abs() <= lim && q[1].abs() <= lim).then_some(q)
}

/// Per mesh: the halves of the viewport that snapping scales by, or `None`
/// when the pre-snap test does not apply (`Fx`, an odd subpixel extent, or
/// an origin so far out that snapping might fail).
#[derive(Clone, Copy)]
pub(super) struct PreSnap {
    half: Option<[f32; 2]>,
    /// `origin·2^S + full/2` per axis: the snapped position is this plus
    /// `round_even(q)`.
    base: [i32; 2],
}

impl PreSnap {
    /// For a viewport `size` at `origin` with `s` subpixel bits.
    pub(super) fn new<T: Scalar>(size: (u32, u32), origin: (i64, i64), s: u32) -> Self {
        let axis = |size: u32, origin: i64| {
            let full = i64::from(size) << s;
            let base = origin.checked_mul(1 << s)?.checked_add(full / 2)?;
            // `full / 2 < 2^24` is exact in f32, as `div_scaled_by` converts it.
            (full % 2 == 0 && base.abs() <= 1 << 27 && full < 1 << 25)
                .then_some(((full / 2) as f32, base as i32))
        };
        match (crate::math::vec::is_float::<T>(), axis(size.0, origin.0), axis(size.1, origin.1)) {
            (true, Some((hx, bx)), Some((hy, by))) => PreSnap { half: Some([hx, hy]), base: [bx, by] },
            _ => PreSnap { half: None, base: [0; 2] },
        }
    }

    /// The snapped position from [`PreSnap::quotients`] `q`: bit for bit
    /// what [`Pipeline::snap_xy`](super::Pipeline) gives (`|q| ≤ 2^22`
    /// and the base within `2^27`: it never fails).
    #[inline]
    pub(super) fn snap<const S: u32>(&self, q: [f32; 2]) -> Option<crate::SubPoint<S>> {
        let r = q.map(|v| round_even_f32(v) as i32);
        crate::SubPoint::new(self.base[0] + r[0], self.base[1] + r[1]).ok()
    }

    /// The snapped position of clip position `c`, bit for bit
    /// [`Pipeline::snap_xy`](super::Pipeline) of it, for a vertex whose
    /// depth is deferrable (`z` finite, `|z| ≤ 128·w`, as
    /// `Pipeline::depth_deferrable`) and whose [`PreSnap::quotients`] are
    /// usable; `None` otherwise (then the caller snaps the general way).
    /// The quotients (`|q| ≤ 2^22`) are rounded by
    /// [`round_even_signed_below_2p22`]: the value of [`round_even_f32`],
    /// without its sign and range branches.
    #[inline]
    pub(super) fn snap_inside<T: Scalar, const S: u32, R: Tier>(
        &self,
        c: [T; 4],
    ) -> Option<crate::SubPoint<S>> {
        let half = self.half?;
        let (x, y, z, w) = (c[0].to_f32(), c[1].to_f32(), c[2].to_f32(), c[3].to_f32());
        // `w > 0` finite; `z` finite (NaN fails the comparison) within 128·w.
        if !(w > 0.0 && w <= f32::MAX && z.abs() <= w * 128.0) {
            return None;
        }
        let q = tier_quotients::<R>(x, y, w, half)?;
        let r = q.map(round_even_signed_below_2p22);
        crate::SubPoint::new(self.base[0] + r[0], self.base[1] + r[1]).ok()
    }

    /// Whether the test applies at all.
    pub(super) fn active(&self) -> bool {
        self.half.is_some()
    }

    /// The values snapping rounds for clip position `c` (x, then −y), or
    /// `None` if the test cannot use this vertex (not `f32`, `w` not a
    /// positive finite divisor, or beyond [`Q_MAX`]).
    #[inline]
    pub(super) fn quotients<T: Scalar, R: Tier>(&self, c: [T; 4]) -> Option<[f32; 2]> {
        let half = self.half?;
        let (x, y, w) = (c[0].to_f32(), c[1].to_f32(), c[3].to_f32());
        if !(w > 0.0 && w <= f32::MAX) {
            return None;
        }
        tier_quotients::<R>(x, y, w, half)
    }
}

/// The depth and `1/w` of [`Pipeline::snap_depth`](super::Pipeline) for
/// `f32`, bit for bit, where that depth is deferrable (`w > 0` finite, `|z|
/// ≤ 128·w`, as `Pipeline::depth_deferrable`) and `w_ref/w·2^30` is within
/// `2^40`; `None` otherwise (then the caller takes the general path). The
/// same quotients are rounded as [`round_even_f32`] rounds them (`2^23`
/// added and taken away below `2^23`, an integer above, where `as u32`
/// saturates as the clamp to `u32::MAX` does) and clamped as there, without
/// the 64-bit values.
/// In the fast tier from `1/w` (one `VDIV`), as `FastQuotient` computes
/// them (`Pipeline::snap_depth` in that tier).
#[inline]
pub(super) fn depth_f32<R: Tier>(z: f32, w: f32, w_ref: Option<f32>) -> Option<(u32, u32)> {
    if !(w > 0.0 && w <= f32::MAX && z.abs() <= w * 128.0) {
        return None;
    }
    // `|v| ≤ 2^40`, not NaN: `round_even_f32(v).clamp(lo, u32::MAX)`.
    let round = |v: f32, lo: u32| -> u32 {
        if v >= TWO23 {
            v as u32
        } else if v > 0.0 {
            (round_even_below_2p23(v) as u32).max(lo)
        } else {
            lo
        }
    };
    // |z/w| ≤ 128: the depth quotient is within 2^39.
    let rw = 1.0 / w; // the fast tier's only division (unused in the exact)
    let div = |n: f32| if R::FAST { n * rw } else { n / w };
    let depth = round(div(z) * 4_294_967_296.0, 0);
    // No `1/w` wanted: 1, as `Pipeline::snap_depth` leaves it.
    let Some(w_ref) = w_ref else { return Some((depth, 1)) };
    let r = div(w_ref) * 1_073_741_824.0;
    // NaN too.
    if r.is_nan() || r.abs() > 1_099_511_627_776.0 {
        return None;
    }
    Some((depth, round(r, 1)))
}

/// The sign of the snapped signed area (`signed_area2`) of a triangle with
/// [`PreSnap::quotients`] `q`: `1` or `-1` when certain (module docs), `0`
/// when the margin does not decide.
#[inline]
pub(super) fn orientation(q: [[f32; 2]; 3]) -> i8 {
    let (e1x, e1y) = (q[1][0] - q[0][0], q[1][1] - q[0][1]);
    let (e2x, e2y) = (q[2][0] - q[0][0], q[2][1] - q[0][1]);
    let (p, n) = (e1x * e2y, e1y * e2x);
    let area = p - n;
    let m = e1x.abs() + e1y.abs() + e2x.abs() + e2y.abs() + 2.0;
    let bound = (m + (p.abs() + n.abs()) * (1.0 / 1_048_576.0)) * (1.0 + 1.0 / 1024.0);
    if area > bound {
        1
    } else if area < -bound {
        -1
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::super::tier::ExactTier;
    use super::*;

    /// The exact test's area from the rounded quotients.
    fn snapped_area(q: [[f32; 2]; 3]) -> i64 {
        let r = q.map(|v| v.map(round_even_f32));
        (r[1][0] - r[0][0]) * (r[2][1] - r[0][1]) - (r[2][0] - r[0][0]) * (r[1][1] - r[0][1])
    }

    struct Rng(u64);
    impl Rng {
        fn unit(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Random small and large triangles, slivers, near-degenerate and
    /// half-integer (rounding-tie) vertices: whenever the pre-snap test is
    /// certain, the exact test agrees in sign.
    #[test]
    fn never_contradicts_the_snapped_test() {
        let mut rng = Rng(0x5EED_CAFE);
        let (mut decided, mut total) = (0u32, 0u32);
        for i in 0..400_000u32 {
            let scale = [4.0, 32.0, 512.0, 65536.0, 4_000_000.0][i as usize % 5];
            let centre = [rng.unit() - 0.5, rng.unit() - 0.5].map(|c| c * 8.0e6);
            let mut q = [[0.0f32; 2]; 3];
            for v in &mut q {
                *v = [0, 1].map(|k| (centre[k] + (rng.unit() - 0.5) * scale) as f32);
            }
            match i % 4 {
                // A sliver: the third vertex near the line of the first two.
                1 => {
                    let t = rng.unit() as f32;
                    q[2] = [0, 1].map(|k| q[0][k] + (q[1][k] - q[0][k]) * t + (rng.unit() as f32 - 0.5));
                }
                // Ties: half-integer coordinates.
                2 => q = q.map(|v| v.map(|c| (c.floor() + 0.5).clamp(-Q_MAX, Q_MAX))),
                _ => {}
            }
            if q.iter().flatten().any(|c| c.abs() > Q_MAX) {
                continue;
            }
            total += 1;
            let o = orientation(q);
            if o != 0 {
                decided += 1;
                assert_eq!(i64::from(o), snapped_area(q).signum(), "{q:?}");
            }
        }
        // Not vacuous: most random triangles are decided, but not all.
        assert!(decided > total / 2 && decided < total, "{decided} of {total}");
    }

    /// Adversarial: triangles whose snapped area is tiny (±1 or 0 after
    /// rounding, but larger or of the other sign before) are never decided
    /// against the exact sign.
    #[test]
    fn adversarial_rounding_flips() {
        let mut rng = Rng(0xBADC_0FFE);
        let mut flips = 0;
        for _ in 0..200_000 {
            let base = [0, 1].map(|_| ((rng.unit() - 0.5) * 2.0e6).round() as f32);
            let off = |r: &mut Rng| (r.unit() as f32 - 0.5) * 0.999;
            let len = (rng.unit() * 64.0) as f32;
            let mut q = [base, [base[0] + len, base[1]], [base[0] + len / 2.0, base[1] + 1.0]];
            for v in &mut q {
                *v = [v[0] + off(&mut rng), v[1] + off(&mut rng)];
            }
            let exact = snapped_area(q);
            let real = f64::from(q[1][0] - q[0][0]) * f64::from(q[2][1] - q[0][1])
                - f64::from(q[2][0] - q[0][0]) * f64::from(q[1][1] - q[0][1]);
            flips += u32::from(real.signum() as i64 != exact.signum());
            let o = orientation(q);
            assert!(o == 0 || i64::from(o) == exact.signum(), "{q:?}: {o} vs {exact}");
        }
        // The rounding does flip signs here: the margin is what saves the test.
        assert!(flips > 100, "{flips}");
    }

    /// The deferred depth agrees with `div_scaled_by`'s rounding and clamps,
    /// over depths in and beyond the view volume, ties and extreme `w`.
    #[test]
    fn depth_f32_is_snap_depth() {
        let mut rng = Rng(0xDE97_0001);
        let want = |z: f32, w: f32, w_ref: f32| {
            let d = z.div_scaled_by(w, u32::MAX as i64)?.clamp(0, u32::MAX as i64) as u32;
            let r = w_ref.div_scaled_by(w, 1 << 30).unwrap_or(i64::MAX).clamp(1, u32::MAX as i64) as u32;
            Some((d, r))
        };
        let mut n = 0;
        for i in 0..400_000u32 {
            let w = [(rng.unit() * 50.0) as f32, (rng.unit() * 1e-6) as f32, (rng.unit() * 1e30) as f32]
                [i as usize % 3];
            let z = ((rng.unit() - 0.5) * 300.0) as f32 * w;
            // A depth quotient on a tie below 2^23.
            let z = if i % 7 == 0 {
                (((rng.unit() * 8e6) as f32).floor() + 0.5) / 4_294_967_296.0 * w
            } else {
                z
            };
            let w_ref = [1.0f32, 1e-9, 3e9, 0.37][i as usize % 4];
            if let Some(got) = depth_f32::<ExactTier>(z, w, Some(w_ref)) {
                assert_eq!(Some(got), want(z, w, w_ref), "{z} {w} {w_ref}");
                // Without 1/w: the same depth, and 1.
                assert_eq!(depth_f32::<ExactTier>(z, w, None), Some((got.0, 1)));
                n += 1;
            }
        }
        assert!(n > 100_000, "{n}");
        assert_eq!(depth_f32::<ExactTier>(1.0, 1.0, Some(f32::INFINITY)), None);
        assert_eq!(depth_f32::<ExactTier>(129.0, 1.0, Some(1.0)), None);
        assert_eq!(depth_f32::<ExactTier>(129.0, 1.0, None), None);
    }

    /// The inside snap agrees with the quotients' rounding (ties included)
    /// and declines exactly the vertices the general path must take.
    #[test]
    fn snap_inside_is_the_presnap_rounding() {
        let p = PreSnap::new::<f32>((320, 240), (3, -5), 4);
        let mut rng = Rng(0x51A9_0001);
        let (mut ties, mut n) = (0, 0);
        for i in 0..400_000u32 {
            let w = (rng.unit() * 100.0 + 1e-3) as f32;
            let mut c = [0, 1].map(|_| ((rng.unit() - 0.5) * 2.2) as f32 * w);
            if i % 3 == 0 {
                // A quotient on a tie (half-integer) or an integer.
                let q = ((rng.unit() - 0.5) * 5000.0).floor() as f32 + if i % 2 == 0 { 0.5 } else { 0.0 };
                c[0] = q / 2560.0 * w;
            }
            let z = [0.5 * w, -200.0 * w, f32::NAN, 128.0 * w][i as usize % 4];
            let clip = [c[0], c[1], z, w];
            let got = p.snap_inside::<f32, 4, ExactTier>(clip);
            let usable = z.is_finite() && z.abs() <= w * 128.0;
            let want = p.quotients::<_, ExactTier>(clip).filter(|_| usable).and_then(|q| p.snap::<4>(q));
            assert_eq!(got, want, "{clip:?}");
            if let Some(q) = p.quotients::<_, ExactTier>(clip) {
                ties += u32::from(q[0].fract().abs() == 0.5);
            }
            n += u32::from(got.is_some());
        }
        assert!(ties > 1000 && n > 100_000, "{ties} ties, {n} snapped");
        for v in [0.5f32, 1.5, 2.5, -0.5, -1.5, -2.5, 4_194_303.5, -4_194_303.5, 4_194_304.0] {
            assert_eq!(round_even_signed_below_2p22(v) as i64, round_even_f32(v), "{v}");
        }
        assert_eq!(
            PreSnap::new::<crate::math::Fx>((320, 240), (0, 0), 4)
                .snap_inside::<crate::math::Fx, 4, ExactTier>([crate::math::Fx::ZERO; 4]),
            None
        );
    }

    #[test]
    fn quotients_match_snapping() {
        let p = PreSnap::new::<f32>((320, 240), (0, 0), 4);
        let mut rng = Rng(0x0123_4567);
        for _ in 0..100_000 {
            let w = (rng.unit() * 10.0 + 0.01) as f32;
            let c = [(rng.unit() - 0.5) * 4.0, (rng.unit() - 0.5) * 4.0].map(|v| v as f32 * w);
            let q = p.quotients::<_, ExactTier>([c[0], c[1], 0.0, w]).expect("in range");
            assert_eq!(round_even_f32(q[0]), c[0].div_scaled_by(w, 320 * 16 / 2).unwrap());
            assert_eq!(round_even_f32(q[1]), (-c[1]).div_scaled_by(w, 240 * 16 / 2).unwrap());
        }
        // Through the pipeline's own snapping, with an origin.
        let pipe = crate::pipeline::Pipeline::<f32, 4>::perspective(
            crate::math::Mat4::IDENTITY,
            0.8,
            1.0,
            10.0,
            320,
            240,
        )
        .unwrap()
        .with_origin(-37, 1000);
        let p = PreSnap::new::<f32>(pipe.size, pipe.origin, 4);
        for _ in 0..100_000 {
            let w = (rng.unit() * 10.0 + 0.01) as f32;
            let c = [(rng.unit() - 0.5) * 4.0, (rng.unit() - 0.5) * 4.0].map(|v| v as f32 * w);
            let clip = [c[0], c[1], 0.0, w];
            let q = p.quotients::<_, ExactTier>(clip).expect("in range");
            assert_eq!(p.snap::<4>(q), pipe.snap_xy::<ExactTier>(clip, w));
        }
        assert!(!PreSnap::new::<crate::math::Fx>((320, 240), (0, 0), 4).active());
        assert!(!PreSnap::new::<f32>((321, 240), (0, 0), 0).active());
        assert!(!PreSnap::new::<f32>((320, 240), (1 << 26, 0), 4).active());
    }
}
