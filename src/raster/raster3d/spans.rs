//! The plane path of [`draw_triangle`](super::draw_triangle) once a
//! triangle's first spans are known: plane set-up, the depth test of a
//! one-span triangle, and the fragment loops per depth state and shading.

use super::depth_span::{DepthRule, DepthSpan, LessWrite};
use super::precision::Tier;
use super::shade::{Gouraud, ShadeSpan, Shader, channels_in_range};
use super::{Affine, Interpolation, ScreenTriangle};
use crate::Interpolate;
use crate::attr::{Plane, PlaneSetup};
use crate::band::BandView;
use crate::depth::{DepthFormat, DepthState};
use crate::edge::{Span, SpanRest};
use crate::math::divisor::ARMV6M;

/// The rest of [`draw_triangle`](super::draw_triangle) once the first span is known: plane set-up
/// and the fragment loop.
#[inline(always)]
pub(super) fn shade_spans<C, F, M, P, const S: u32, const W: usize, R>(
    tri: &ScreenTriangle<S>,
    spans: (Span, Option<Span>, &R),
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    P: Tier,
    R: SpanRest,
{
    let (first, second, _) = spans;
    // Zero area (on the same snapped coordinates as coverage): no spans either.
    let Some(mut setup) = tri.plane_setup() else { return };
    if second.is_none() {
        setup.sampled_only_on(first.x, first.y, first.len);
    }
    let mut zplane = Plane::default();
    if F::ENABLED {
        setup.plane_into(tri.depth_values::<F>(), &mut zplane);
    }
    // A one-span Gouraud triangle hidden at each of its pixels (a knot's
    // strand behind another) needs no colour planes: its depth is tested
    // first. Exact: where the test fails nothing is written.
    if F::ENABLED
        && !tri.flat
        && second.is_none()
        && !span_passes::<F, W>(first, color.y0(), depth, state, &zplane)
    {
        return;
    }
    let fast = if P::FAST { fast_shade::<C, M, S>(tri) } else { FastShade::Planes(M::PERSPECTIVE) };
    if let FastShade::Const(c) = fast {
        draw_with_test::<C, F, _, _, W>(spans, color, depth, state, &zplane, &c);
    } else if tri.flat {
        draw_with_test::<C, F, _, _, W>(
            spans,
            color,
            depth,
            state,
            &zplane,
            &C::from_channels(tri.v[0].color),
        );
    } else if !M::PERSPECTIVE && channels_in_range::<C, S>(tri) {
        // No per-pixel clamp (`channel_in_range`).
        gouraud_spans::<C, F, M, false, S, W, _>(tri, &setup, spans, color, depth, state, &zplane);
    } else if P::FAST && M::PERSPECTIVE && matches!(fast, FastShade::Planes(false)) {
        // Near enough to screen-linear (`fast_shade`).
        if channels_in_range::<C, S>(tri) {
            gouraud_spans::<C, F, Affine, false, S, W, _>(tri, &setup, spans, color, depth, state, &zplane);
        } else {
            gouraud_spans::<C, F, Affine, true, S, W, _>(tri, &setup, spans, color, depth, state, &zplane);
        }
    } else {
        gouraud_spans::<C, F, M, true, S, W, _>(tri, &setup, spans, color, depth, state, &zplane);
    }
}

/// The fast tier's colour of a triangle on the plane path.
#[derive(Clone, Copy, PartialEq)]
enum FastShade<C> {
    /// Every pixel this colour: each channel's vertex values lie within 2
    /// of each other, and this is the middle of their range (the exact
    /// tier's channel, a rounding of a value inside that range, is within
    /// one of it).
    Const(C),
    /// Gouraud planes, perspective-correct (`true`) or screen-linear.
    Planes(bool),
}

/// [`FastShade`] of a Gouraud or flat triangle (flat: planes, which the
/// caller draws flat). Perspective-correct colour takes screen-linear
/// planes where the vertices' `1/w` are so close that the two differ by
/// `Δ ≤ 1/4` (`tiny::perspective`'s bound): with the affine planes' own
/// error (`2^-7`) and the perspective-correct planes', below one step, so
/// each channel is within one of the exact tier's.
#[inline(always)]
fn fast_shade<C: Interpolate, M: Interpolation, const S: u32>(tri: &ScreenTriangle<S>) -> FastShade<C> {
    if tri.flat {
        return FastShade::Planes(M::PERSPECTIVE);
    }
    let max = C::CHANNEL_MAX;
    let (mut lo, mut spread) = ([0u8; 3], 0u8);
    for k in 0..3 {
        let c = tri.v.map(|v| v.color[k]);
        lo[k] = c[0].min(c[1]).min(c[2]);
        let hi = c[0].max(c[1]).max(c[2]);
        lo[k] += (hi - lo[k]) / 2;
        if max[k] > 0 {
            spread = spread.max(hi - c[0].min(c[1]).min(c[2]));
        }
    }
    if spread <= 2 {
        return FastShade::Const(C::from_channels(lo));
    }
    if M::PERSPECTIVE {
        let a = tri.v.map(|v| u64::from(v.inv_w));
        let (a_min, a_max) = (a[0].min(a[1]).min(a[2]), a[0].max(a[1]).max(a[2]));
        return FastShade::Planes(2 * u64::from(spread) * (a_max - a_min) > a_min);
    }
    FastShade::Planes(false)
}

/// [`shade_spans`]' Gouraud fragment loop, its pixels clamped or not
/// ([`Gouraud`]).
#[inline(always)]
fn gouraud_spans<C, F, M, const CLAMP: bool, const S: u32, const W: usize, R>(
    tri: &ScreenTriangle<S>,
    setup: &PlaneSetup,
    spans: (Span, Option<Span>, &R),
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
    zplane: &Plane,
) where
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
    R: SpanRest,
{
    // Made in place: built and returned, its planes were copied twice.
    let mut shade = Gouraud::<C, M, CLAMP> { planes: [Plane::default(); 4], _m: core::marker::PhantomData };
    shade.set_up(tri, setup);
    draw_with_test::<C, F, _, _, W>(spans, color, depth, state, zplane, &shade);
}

/// Whether the depth test passes at some pixel of `span` (without writing);
/// false where the band has no depth row for it (nothing is drawn there).
#[inline(always)]
fn span_passes<F: DepthFormat, const W: usize>(
    span: Span,
    y0: i32,
    depth: &[[F::Storage; W]],
    state: DepthState,
    zplane: &Plane,
) -> bool {
    let (x0, len) = (span.x as usize, span.len as usize);
    let Some(dspan) = depth.get((span.y - y0) as usize).and_then(|r| r.get(x0..x0 + len)) else {
        return false;
    };
    let mut z = DepthSpan::<F>::new(zplane, span.x, span.y);
    for slot in dspan {
        if state.test.passes(z.value(), F::to_u32(*slot)) {
            return true;
        }
        z.step();
    }
    false
}

/// [`draw_spans`] with the depth state as a type: ordinary opaque drawing
/// ([`DepthState::LESS_WRITE`]) gets a loop without the per-pixel dispatch.
#[inline(always)]
fn draw_with_test<C, F, Sh, R, const W: usize>(
    spans: (Span, Option<Span>, &R),
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: DepthState,
    zplane: &Plane,
    shade: &Sh,
) where
    C: Interpolate,
    F: DepthFormat,
    Sh: Shader<C>,
    R: SpanRest,
{
    if F::ENABLED && state == DepthState::LESS_WRITE {
        draw_spans::<C, F, _, _, _, W>(spans, color, depth, LessWrite, zplane, shade);
    } else {
        draw_spans::<C, F, _, _, _, W>(spans, color, depth, state, zplane, shade);
    }
}

/// The fragment loop of [`draw_triangle`](super::draw_triangle), for one way of shading.
#[inline(always)]
fn draw_spans<C, F, Sh, D, Rest, const W: usize>(
    spans: (Span, Option<Span>, &Rest),
    color: &mut BandView<'_, C, W>,
    depth: &mut [[F::Storage; W]],
    state: D,
    zplane: &Plane,
    shade: &Sh,
) where
    C: Interpolate,
    F: DepthFormat,
    Sh: Shader<C>,
    D: DepthRule,
    Rest: SpanRest,
{
    let y0 = color.y0();
    // Internal iteration: one loop per coverage path (`for_each_ref`), each
    // with the fragment loop inlined, instead of a dispatch per span; the
    // first two spans (found before the set-up) on their own.
    let mut each = |span: Span| {
        let (x0, len) = (span.x as usize, span.len as usize);
        let Some(cspan) = color.row_mut(span.y).and_then(|r| r.get_mut(x0..x0 + len)) else { return };
        let mut sh = shade.start(span.x, span.y);
        if !F::ENABLED {
            for p in cspan.iter_mut() {
                *p = sh.color();
                sh.step();
            }
            return;
        }
        let drow = depth.get_mut((span.y - y0) as usize).and_then(|r| r.get_mut(x0..x0 + len));
        let Some(dspan) = drow else { return };
        let mut z = DepthSpan::<F>::new(zplane, span.x, span.y);
        if !Sh::PERSPECTIVE && !ARMV6M {
            depth_then_colour(cspan, dspan, state, &mut z, &sh);
            return;
        }
        for (p, slot) in cspan.iter_mut().zip(dspan.iter_mut()) {
            let zq = z.value();
            if state.test().passes(zq, F::to_u32(*slot)) {
                if state.write() {
                    *slot = F::from_u32(zq);
                }
                *p = sh.color();
            }
            z.step();
            sh.step();
        }
    };
    let (first, second, rest) = spans;
    each(first);
    if let Some(second) = second {
        each(second);
        rest.for_each_ref(each);
    }
}

/// The affine fragment loop of one span: depth first, 32 pixels at a time,
/// into a mask of the pixels that pass, then the colour of those alone,
/// each from its index ([`ShadeSpan::color_at`]); the same pixels as
/// stepping both together. Stepped together, the depth's and the colour's
/// accumulators and steps did not fit the Cortex-M4's registers, and LLVM's
/// four-times unrolling of small loops for M-class cores gave each span
/// four sets of them to set up (about 110 instructions a span; the standard
/// scene's spans are about 4 pixels long). The perspective-correct loop
/// keeps the stepping: its colour at an index takes four 64-bit products,
/// which cost more than they saved; so does the Cortex-M0 (ARMv6-M), which
/// has no instruction to find the mask's next bit (`docs/setup_cost.md`,
/// thirteenth pass).
#[inline(always)]
fn depth_then_colour<C, F: DepthFormat, D: DepthRule>(
    cspan: &mut [C],
    dspan: &mut [F::Storage],
    state: D,
    z: &mut DepthSpan<F>,
    sh: &impl ShadeSpan<C>,
) {
    for (k, (cs, ds)) in cspan.chunks_mut(32).zip(dspan.chunks_mut(32)).enumerate() {
        let mut pass = 0u32;
        for (i, slot) in ds.iter_mut().enumerate() {
            let zq = z.value();
            if state.test().passes(zq, F::to_u32(*slot)) {
                if state.write() {
                    *slot = F::from_u32(zq);
                }
                pass |= 1 << i;
            }
            z.step();
        }
        let base = 32 * k as u32;
        while pass != 0 {
            let i = pass.trailing_zeros();
            pass &= pass - 1;
            if let Some(p) = cs.get_mut(i as usize) {
                *p = sh.color_at(base + i);
            }
        }
    }
}
