//! Multisampling: coverage and depth per sample, colour once per pixel.
//!
//! A triangle's coverage is the exact sample-grid coverage of its vertices
//! scaled by `N` (see [`crate::aa`]). Its spans arrive one sample row at a
//! time; the `N` sample rows of one pixel row are gathered, and every pixel
//! they touch is visited once: its covered samples are depth-tested one by
//! one (depth plane evaluated at each sample position, the depth band at
//! sample resolution), and if any passes, the colour is evaluated once at
//! the pixel centre and written to the samples that passed. With a sparse
//! pattern ([`MsaaSparse`](super::MsaaSparse)) each grid row of a pixel has
//! one sample, at the pattern's column, stored at the pixel's column.
//!
//! Colour at the pixel centre: flat triangles use vertex 0's colour; the
//! others interpolate their vertex colours with [`Varyings`], affine or
//! perspective-correct as the `interp` argument says, so the colour is
//! within that module's stated bound of the exact value (½ + 2^-7 of a
//! channel step for affine), and for 2D Gouraud triangles it equals, pixel for
//! pixel, what the aliased renderer draws where the centre is covered.
//!
//! # Why no per-pixel depth
//! A depth buffer at pixel resolution (test the pixel centre, then write the
//! covered samples) would save memory, but two triangles meeting at a crease
//! both extrapolate their planes to the centres of the pixels along the
//! crease; the nearer value wins the whole pixel and the other triangle's
//! samples there are lost: a crack of background along every silhouette-free
//! edge. Depth is therefore per sample; [`NoDepth`](crate::depth::NoDepth)
//! drops it entirely (zero bytes, zero work).

use super::{Antialias, MAX_GRID, mode_ok, scale_triangle};
use crate::band::BandView;
use crate::blit::Blitter;
use crate::depth::{DepthFormat, DepthRows, DepthState};
use crate::edge::{Cull, Span, TriangleSpans};
use crate::raster3d::{Interpolation, ScreenTriangle, depth_value};
use crate::varyings::Varyings;
use crate::{ClipRect, Error, Interpolate};

/// Rasterizes `tri` (positions in pixels) into a sample-resolution colour
/// view and its depth rows (`depth` holds the view's rows, first to last;
/// without depth pass [`DepthRows::none`]), multisampled on the `N × N` grid
/// of `mode`, the colour interpolated as `interp` says. Every parameter is
/// inferred from the arguments.
///
/// Errors with [`Error::CoordinateOutOfRange`] if the positions times `N`
/// leave the [`SubPoint`](crate::SubPoint) range; nothing is drawn then.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::prelude::*;
/// use microraster::aa::{Msaa, msaa};
/// use microraster::depth::{DepthRows, DepthState};
/// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
/// use microraster::{Band, SubPoint};
/// let v = |x, y| ScreenVertex {
///     pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
///     color: [255, 0, 0],
///     ..Default::default()
/// };
/// // The lower-left half of a 2 × 1 px rectangle, on a 2 × 2 grid.
/// let tri = ScreenTriangle { v: [v(0, 0), v(2, 1), v(0, 1)], flat: true };
/// let mut samples = Band::<Gray8, 4, 2>::new(Gray8::BLACK);
/// let mut view = samples.view(0, 2, Gray8::BLACK);
/// msaa::draw_triangle(Msaa::<2>, &tri, &mut view, &mut DepthRows::none(), DepthState::DISABLED, Affine)?;
/// let lit = view.pixels().filter(|c| *c == Gray8::WHITE).count();
/// assert_eq!(lit, 4); // half of the 8 samples
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn draw_triangle<A, C, F, M, const S: u32, const SW: usize>(
    mode: A,
    tri: &ScreenTriangle<S>,
    samples: &mut BandView<'_, C, SW>,
    depth: &mut DepthRows<'_, F, SW>,
    state: DepthState,
    interp: M,
) -> Result<(), Error>
where
    A: Antialias,
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    let _ = (mode, interp); // values, so the call needs no turbofish
    const { assert!(mode_ok::<A>(), "anti-aliasing needs a supported N") };
    let scaled = scale_triangle(tri, A::N)?;
    if let Some(shader) = PixelShader::<C>::new::<M, S>(tri) {
        draw_scaled::<A, C, F, S, SW>(&scaled, Cull::None, samples, &mut *depth, state, |x, y| {
            shader.at(x, y)
        });
    }
    Ok(())
}

/// The fragment hook of multisampling: like [`draw_triangle`], but the colour
/// of pixel `(x, y)` (frame pixels, not samples) is `shade(x, y)`, called at
/// most once per pixel and only if one of its covered samples passes the
/// depth test. For custom shading (textures, lighting) at one evaluation per
/// pixel.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::prelude::*;
/// use microraster::aa::{Msaa, msaa};
/// use microraster::depth::{DepthRows, DepthState};
/// use microraster::raster3d::{ScreenTriangle, ScreenVertex};
/// use microraster::{Band, SubPoint};
/// let v = |x, y| ScreenVertex { pos: SubPoint::<4>::from_pixels(x, y).unwrap(), ..Default::default() };
/// let tri = ScreenTriangle { v: [v(0, 0), v(4, 0), v(0, 2)], flat: true };
/// let mut samples = Band::<Gray8, 16, 8>::new(Gray8::BLACK); // 4 × 2 px, 4 × 4 samples each
/// let mut view = samples.view(0, 8, Gray8::BLACK);
/// let mut calls = 0;
/// msaa::draw_fragments(Msaa::<4>, &tri, &mut view, &mut DepthRows::none(), DepthState::DISABLED, |x, y| {
///     calls += 1;
///     Gray8::new(10 * x as u8 + y as u8)
/// })?;
/// assert_eq!(calls, 6); // pixels touched: 4 in row 0, 2 in row 1
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn draw_fragments<A, C, F, const S: u32, const SW: usize>(
    mode: A,
    tri: &ScreenTriangle<S>,
    samples: &mut BandView<'_, C, SW>,
    depth: &mut DepthRows<'_, F, SW>,
    state: DepthState,
    shade: impl FnMut(i32, i32) -> C,
) -> Result<(), Error>
where
    A: Antialias,
    C: Interpolate,
    F: DepthFormat,
{
    let _ = mode; // a value, so the call needs no turbofish
    const { assert!(mode_ok::<A>(), "anti-aliasing needs a supported N") };
    let scaled = scale_triangle(tri, A::N)?;
    draw_scaled::<A, C, F, S, SW>(&scaled, Cull::None, samples, &mut *depth, state, shade);
    Ok(())
}

/// [`draw_fragments`] with the triangle already on the sample grid, and a
/// cull mode.
pub(crate) fn draw_scaled<A, C, F, const S: u32, const SW: usize>(
    scaled: &ScreenTriangle<S>,
    cull: Cull,
    samples: &mut BandView<'_, C, SW>,
    depth: &mut [[F::Storage; SW]],
    state: DepthState,
    mut shade: impl FnMut(i32, i32) -> C,
) where
    A: Antialias,
    C: Interpolate,
    F: DepthFormat,
{
    let n = A::N as i32;
    if !mode_ok::<A>() {
        return;
    }
    let zplane = if F::ENABLED {
        match scaled.plane_setup() {
            Some(setup) => Some(setup.plane(scaled.depth_values::<F>())),
            None => return,
        }
    } else {
        None
    };
    let sy0 = samples.y0();
    // The view's rows, and its columns on the sample grid (`COLS` of `N` kept).
    let c = samples.clip();
    let clip = ClipRect::new(0, c.y0(), (SW / A::COLS * A::N) as i32, c.y1());
    let mut spans = TriangleSpans::new(scaled.v.map(|v| v.pos), clip, cull).peekable();
    while let Some(first) = spans.next() {
        // All sample rows of one pixel row (spans come top to bottom).
        let py = first.y.div_euclid(n);
        let mut group: [Option<Span>; MAX_GRID] = [None; MAX_GRID];
        group[0] = Some(first);
        let mut count = 1;
        while let Some(s) = spans.next_if(|s| s.y.div_euclid(n) == py) {
            if let Some(slot) = group.get_mut(count) {
                *slot = Some(s);
                count += 1;
            }
        }
        let group = &group[..count];
        let (lo, hi) = group.iter().flatten().fold((i32::MAX, i32::MIN), |(lo, hi), s| {
            (lo.min(s.x.div_euclid(n)), hi.max((s.x + s.len as i32 - 1).div_euclid(n)))
        });
        for px in lo..=hi {
            let mut color = None;
            let (bx0, bx1) = (px * n, px * n + n);
            for s in group.iter().flatten() {
                // Stored samples a..b of this pixel in the row; `sx` the grid
                // column of the first.
                let (a, b, sx) = if A::COLS == 1 {
                    let j = (s.y - py * n) as usize % MAX_GRID;
                    let sx = bx0 + A::PATTERN[j] as i32;
                    if sx < s.x || sx >= s.x + s.len as i32 {
                        continue;
                    }
                    (px as usize, px as usize + 1, sx)
                } else {
                    let (a, b) = (s.x.max(bx0), (s.x + s.len as i32).min(bx1));
                    if a >= b {
                        continue;
                    }
                    (a as usize, b as usize, a)
                };
                let Some(crow) = samples.row_mut(s.y).and_then(|r| r.get_mut(a..b)) else { continue };
                let Some(zp) = &zplane else {
                    crow.fill(*color.get_or_insert_with(|| shade(px, py)));
                    continue;
                };
                let drow = usize::try_from(s.y - sy0).ok().and_then(|r| depth.get_mut(r));
                let Some(drow) = drow.and_then(|r| r.get_mut(a..b)) else { continue };
                let (mut z, dz) = (zp.at(sx, s.y), zp.step_x());
                for (p, slot) in crow.iter_mut().zip(drow) {
                    let zq = depth_value::<F>(z);
                    z = z.wrapping_add(dz); // exact modulo 2^64, as in `attr`
                    if state.test.passes(zq, F::to_u32(*slot)) {
                        if state.write {
                            *slot = F::from_u32(zq);
                        }
                        *p = *color.get_or_insert_with(|| shade(px, py));
                    }
                }
            }
        }
    }
}

/// The colour of a triangle at pixel centres.
pub(crate) enum PixelShader<C> {
    Flat(C),
    Planes(Varyings<3>),
}

impl<C: Interpolate> PixelShader<C> {
    /// `None` for a zero-area triangle.
    pub(crate) fn new<M: Interpolation, const S: u32>(tri: &ScreenTriangle<S>) -> Option<Self> {
        if tri.flat {
            return Some(PixelShader::Flat(C::from_channels(tri.v[0].color)));
        }
        // Channels are ≤ 255, far inside the varyings' range: no error path.
        let values = tri.v.map(|v| v.color.map(i32::from));
        Varyings::new(tri, values, M::default()).ok().flatten().map(PixelShader::Planes)
    }

    #[inline]
    pub(crate) fn at(&self, x: i32, y: i32) -> C {
        match self {
            PixelShader::Flat(c) => *c,
            PixelShader::Planes(v) => {
                let c = v.at(x, y);
                let max = C::CHANNEL_MAX;
                C::from_channels([0, 1, 2].map(|k| c[k].clamp(0, i32::from(max[k])) as u8))
            }
        }
    }
}
