//! The tiny path as it was before its runs were stepped: each covered
//! centre's weights, depth sum and channel sums multiplied out afresh (the
//! definition of its pixels). The test draws random tiny triangles both
//! ways, in both tiers, affine and perspective-correct, with and without
//! depth and under several depth states, and wants the same band and depth
//! rows: stepping changes no pixel.

use super::super::precision::{ExactTier, FastTier, Tier};
use super::super::{
    DEPTH_FRAC, DepthRule, Interpolation, ScreenTriangle, ScreenVertex, depth_steps, depth_steps_approx,
};
use super::fast::FastShade;
use super::perspective::{PerspFactors, shade_perspective};
use super::{FRAC, channel_quotient, depth_code, eligible};
use crate::band::{Band, BandView};
use crate::depth::{Depth16, DepthFormat, DepthState, DepthTest, NoDepth};
use crate::edge::Cull;
use crate::edge::small::{Small, setup_state};
use crate::math::divisor::mul_u16_u32;
use crate::raster3d::{Affine, PerspectiveCorrect};
use crate::{Interpolate, SubPoint};
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};

/// The per-centre loop (the former `draw_with`).
fn draw_per_centre<C, F, M, P, D, const S: u32, const W: usize>(
    tri: &ScreenTriangle<S>,
    small: &Small,
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: D,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    P: Tier,
    D: DepthRule,
{
    let det = small.det() as u32;
    let bias = small.biases().map(|b| b as u32);
    let dv = tri.v.map(|v| match (F::ENABLED, P::FAST) {
        (false, _) => 0,
        (true, false) => (depth_steps(v.depth, F::MAX) >> (DEPTH_FRAC - FRAC)) as u32,
        (true, true) => depth_steps_approx(v.depth, F::BITS) >> (DEPTH_FRAC - FRAC),
    });
    let y0 = color.y0();
    let mut persp = None;
    let mut fast = None;
    small.for_each_centre(|x, y, e| {
        let w = [0, 1, 2].map(|i| e[i] as u32 + bias[i]);
        let Some(p) = color.row_mut(y).and_then(|r| r.get_mut(x as usize)) else { return };
        if F::ENABLED {
            let Some(slot) = depth.get_mut((y - y0) as usize).and_then(|r| r.get_mut(x as usize)) else {
                return;
            };
            let n = mul_u16_u32(w[0], dv[0]) + mul_u16_u32(w[1], dv[1]) + mul_u16_u32(w[2], dv[2]);
            let code = depth_code(n, det);
            if !state.test().passes(code, F::to_u32(*slot)) {
                return;
            }
            if state.write() {
                *slot = F::from_u32(code);
            }
        }
        let how = if P::FAST {
            *fast.get_or_insert_with(|| FastShade::new::<M, S>(tri))
        } else if M::PERSPECTIVE && !tri.flat {
            FastShade::Perspective
        } else {
            FastShade::Affine
        };
        *p = match how {
            FastShade::Const(c) => c,
            FastShade::Perspective => shade_perspective::<C, S>(
                tri,
                persp.get_or_insert_with(|| PerspFactors::new::<C, S>(tri, det)),
                w,
                det,
            ),
            FastShade::Affine if tri.flat => C::from_channels(tri.v[0].color),
            FastShade::Affine => {
                let max = C::CHANNEL_MAX;
                let ch = |k: usize| -> u8 {
                    if max[k] == 0 {
                        return 0;
                    }
                    let c = [0, 1, 2].map(|i| tri.v[i].color[k] as u32);
                    let n = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
                    channel_quotient(2 * n + det, 2 * det, max[k]) as u8
                };
                C::from_channels([ch(0), ch(1), ch(2)])
            }
        };
    });
}

const W: usize = 24;
const H: usize = 12;

/// Random tiny triangles drawn into one band both ways, in order (so the
/// depth tests see each other's writes); the number drawn plus the band's
/// pixels they lit.
fn check<C, F, M, P>(rng: &mut crate::test_rng::Rng, state: DepthState, color: impl Fn(u64) -> C) -> usize
where
    C: Interpolate + PartialEq + core::fmt::Debug,
    F: DepthFormat,
    M: Interpolation,
    P: Tier,
{
    let bg = color(0);
    let (mut a, mut b) = (Band::<C, W, H>::new(bg), Band::<C, W, H>::new(bg));
    let far = [[F::FAR; W]; H];
    let (mut da, mut db) = (far, far);
    let mut lit = 0;
    for i in 0..400 {
        let (cx, cy) = (rng.in_range(14) as i32 + 12, rng.in_range(8) as i32 + 6);
        let reach = [4, 16, 40, 70][i % 4];
        let base_w = (rng.next() >> 34) as u32 | 1;
        let mut v = || ScreenVertex::<4> {
            pos: SubPoint::new(cx * 16 + rng.in_range(reach) as i32, cy * 16 + rng.in_range(reach) as i32)
                .unwrap(),
            depth: rng.next() as u32,
            inv_w: base_w.saturating_add((rng.next() >> 40) as u32),
            color: color(rng.next()).to_channels(),
        };
        let tri = ScreenTriangle { v: [v(), v(), v()], flat: rng.next().is_multiple_of(5) };
        let Some(Some(small)) =
            setup_state(tri.v.map(|v| v.pos), crate::ClipRect::new(0, 2, W as i32, 11), Cull::None)
        else {
            continue;
        };
        if !eligible::<F>(&small) {
            continue;
        }
        let rows = if F::ENABLED { 2..11 } else { 0..0 };
        let (ra, rb) = (&mut da[rows.clone()], &mut db[rows]);
        super::draw::<C, F, M, P, 4, W>(&tri, &small, &mut a.view_uncleared(2, 9), ra, state);
        draw_per_centre::<C, F, M, P, _, 4, W>(&tri, &small, &mut b.view_uncleared(2, 9), rb, state);
        assert_eq!(a.rows(), b.rows(), "{tri:?}");
        assert_eq!(da, db, "{tri:?}");
        lit += 1;
    }
    lit + a.rows().iter().flatten().filter(|&&c| c != bg).count()
}

#[test]
fn stepped_runs_are_the_per_centre_pixels() {
    let mut rng = crate::test_rng::Rng(0x7E9_5FA1);
    let rgb565 = |r: u64| Rgb565::new(r as u8 & 31, (r >> 8) as u8 & 63, (r >> 16) as u8 & 31);
    let rgb888 = |r: u64| Rgb888::new(r as u8, (r >> 8) as u8, (r >> 16) as u8);
    let states = [
        DepthState::LESS_WRITE,
        DepthState::LESS_EQUAL_WRITE,
        DepthState::READ_ONLY,
        DepthState::new(DepthTest::Greater, true),
        DepthState::ALWAYS_WRITE,
    ];
    let mut drawn = 0;
    for state in states {
        drawn += check::<_, Depth16, Affine, ExactTier>(&mut rng, state, rgb565);
        drawn += check::<_, Depth16, PerspectiveCorrect, ExactTier>(&mut rng, state, rgb565);
        drawn += check::<_, Depth16, Affine, FastTier>(&mut rng, state, rgb565);
        drawn += check::<_, Depth16, PerspectiveCorrect, FastTier>(&mut rng, state, rgb888);
        drawn += check::<_, Depth16, Affine, ExactTier>(&mut rng, state, rgb888);
    }
    drawn += check::<_, NoDepth, Affine, ExactTier>(&mut rng, DepthState::LESS_WRITE, rgb565);
    drawn += check::<_, NoDepth, PerspectiveCorrect, FastTier>(&mut rng, DepthState::LESS_WRITE, rgb888);
    assert!(drawn > 5_000, "{drawn} tiny triangles and pixels drawn");
}
