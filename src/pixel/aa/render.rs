//! The anti-aliased passes: [`Antialiased`] (2D), [`Antialiased3d`] (3D)
//! and [`Supersampled`] (any pass at sample resolution), each drawn into a
//! sample band and resolved into the band the renderer sends.

use core::marker::PhantomData;

use super::msaa::{self, PixelShader};
use super::resolve::resolve;
use super::{Antialias, Grid, check_height, scale_triangle, scale_vertices};
use crate::band::{Band, BandView};
use crate::blit::Blitter;
use crate::depth::{DepthBand, DepthFormat, DepthState, NoDepth};
use crate::edge::{Cull, Span};
use crate::raster3d::{Affine, Interpolation, ScreenTriangle, ScreenVertex, draw_triangle};
use crate::render::Pass;
use crate::{ClipRect, Error, Interpolate, Primitive, Renderer, Shading, Triangle};

/// A 2D scene anti-aliased as `mode` says ([`Ssaa`](super::Ssaa) or
/// [`Msaa`](super::Msaa), with `N × N` samples per pixel, or
/// [`MsaaSparse`](super::MsaaSparse) with `N`): a [`Pass`] whose bands are
/// drawn into `samples` (`SW = W·COLS` by `SH = H·N` for `W × H` bands,
/// [`Antialias::COLS`] being `N` or 1 for sparse patterns; checked at
/// compile time), box-filtered into the band and sent. Triangles are
/// anti-aliased; lines stay aliased (each lit pixel fills its whole block).
/// The image does not depend on `H`. See [`crate::aa`] for the accuracy and
/// memory figures.
///
/// Errors (from [`Pass::check`], before anything is sent):
/// [`Error::InvalidFrameSize`] if the height times `N` exceeds
/// [`MAX_FRAME_DIM`]; [`Error::CoordinateOutOfRange`] if a vertex times `N`
/// leaves the [`SubPoint`](crate::SubPoint) range.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::prelude::*;
/// use microraster::aa::{Antialiased, Ssaa};
/// use microraster::{Band, Primitive, Renderer, SubPoint, Triangle};
/// let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
/// // The diagonal of a 2 × 2 square: pixels it crosses are half covered.
/// let scene = [Primitive::from(Triangle::flat([p(0, 0), p(2, 0), p(0, 2)], Gray8::WHITE))];
/// let mut samples = Band::<Gray8, 8, 4>::new(Gray8::BLACK); // 4 × 4 samples a pixel
/// let mut out = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
/// let mut display = MockDisplay::new();
/// let frame = Antialiased::new(Ssaa::<4>, &scene, &mut samples);
/// Renderer::new(2, Gray8::BLACK).render(frame, &mut out, &mut display)?;
/// // 6 of 16 samples of the crossed pixels: round(255·6/16) = 96.
/// assert_eq!(display.get_pixel(Point::new(0, 0)), Some(Gray8::WHITE));
/// assert_eq!(display.get_pixel(Point::new(1, 0)), Some(Gray8::new(96)));
/// assert_eq!(display.get_pixel(Point::new(0, 1)), Some(Gray8::new(96)));
/// assert_eq!(display.get_pixel(Point::new(1, 1)), Some(Gray8::BLACK));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
///
/// [`Error::InvalidFrameSize`]: crate::Error::InvalidFrameSize
/// [`Error::CoordinateOutOfRange`]: crate::Error::CoordinateOutOfRange
/// [`MAX_FRAME_DIM`]: crate::MAX_FRAME_DIM
pub struct Antialiased<'a, A, C, const S: u32, const SW: usize, const SH: usize> {
    scene: &'a [Primitive<C, S>],
    samples: &'a mut Band<C, SW, SH>,
    _a: PhantomData<A>,
}

impl<'a, A: Antialias, C: Interpolate, const S: u32, const SW: usize, const SH: usize>
    Antialiased<'a, A, C, S, SW, SH>
{
    /// `scene` anti-aliased as `mode` says, through the sample band `samples`.
    pub fn new(mode: A, scene: &'a [Primitive<C, S>], samples: &'a mut Band<C, SW, SH>) -> Self {
        let _ = mode; // a value, so the call needs no turbofish
        Antialiased { scene, samples, _a: PhantomData }
    }
}

impl<A, C, const S: u32, const W: usize, const H: usize, const SW: usize, const SH: usize> Pass<C, W, H>
    for Antialiased<'_, A, C, S, SW, SH>
where
    A: Antialias,
    C: Interpolate,
{
    fn check(&mut self, renderer: &Renderer<C>) -> Result<(), Error> {
        let () = Grid::<A, W, H, SW, SH>::CHECK;
        check_height(renderer.height(), A::N)?;
        for prim in self.scene {
            if let Primitive::Triangle(t) = prim {
                scale_vertices(t.vertices(), A::N)?;
            }
        }
        Ok(())
    }

    fn draw(&mut self, view: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        let (y0, y1) = (view.y0(), view.y1());
        let mut sv = sample_view::<A, C, SW, SH>(self.samples, renderer.background(), y0, y1);
        let (sy0, sy1) = (sv.y0(), sv.y1());
        for prim in self.scene {
            match prim {
                Primitive::Triangle(t) => draw_2d::<A, C, S, SW>(t, renderer.cull(), &mut sv, sy0, sy1),
                Primitive::Line(l) => {
                    let (lo, hi) = l.rows();
                    if lo < y1 && hi >= y0 {
                        l.draw(&mut Blocks::<A, C, SW> { view: &mut sv, _a: Default::default() });
                    }
                }
            }
        }
        resolve::<A, C, W, SW>(&mut sv, view);
        Ok(())
    }
}

/// Supersampling of any custom pass ([`Ssaa<N>`](super::Ssaa)): `draw`
/// draws each band's sample rows (frame rows × `N`, the view's
/// [`y0`](BandView::y0) and [`height`](BandView::height)) into a sample band
/// cleared to the background, which is then box-filtered into the band and
/// sent. The pass draws geometry scaled by `N` ([`ScreenTriangle::scaled`],
/// [`FragTriangle::scaled`](crate::fragment::FragTriangle::scaled)), with a
/// depth band at sample resolution if it tests depth: the fragment stage
/// ([`crate::fragment`]) anti-aliased.
///
/// Errors: [`Error::InvalidFrameSize`] if
/// `height · N` exceeds [`MAX_FRAME_DIM`](crate::MAX_FRAME_DIM) (before
/// anything is sent); the first error `draw` returns.
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::prelude::*;
/// use microraster::aa::{Ssaa, Supersampled};
/// use microraster::blit::Blitter;
/// use microraster::{Band, Renderer};
/// let mut samples = Band::<Gray8, 4, 2>::new(Gray8::BLACK); // 2 × 2 samples a pixel
/// let mut out = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
/// let mut display = MockDisplay::new();
/// // One white sample in the top-left of pixel (0, 0): a quarter grey.
/// let frame = Supersampled::new(Ssaa::<2>, &mut samples, |sv| Ok(sv.set_pixel(0, 0, Gray8::WHITE)));
/// Renderer::new(2, Gray8::BLACK).render(frame, &mut out, &mut display)?;
/// assert_eq!(display.get_pixel(Point::new(0, 0)), Some(Gray8::new(64)));
/// assert_eq!(display.get_pixel(Point::new(1, 1)), Some(Gray8::BLACK));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub struct Supersampled<'a, C, G, const N: usize, const SW: usize, const SH: usize> {
    samples: &'a mut Band<C, SW, SH>,
    draw: G,
}

impl<'a, C, G, const N: usize, const SW: usize, const SH: usize> Supersampled<'a, C, G, N, SW, SH>
where
    C: Interpolate,
    G: FnMut(&mut BandView<'_, C, SW>) -> Result<(), Error>,
{
    /// `draw` at `N × N` samples a pixel, through the sample band `samples`.
    pub fn new(mode: super::Ssaa<N>, samples: &'a mut Band<C, SW, SH>, draw: G) -> Self {
        let _ = mode; // a value, so the call needs no turbofish
        Supersampled { samples, draw }
    }
}

impl<C, G, const N: usize, const W: usize, const H: usize, const SW: usize, const SH: usize> Pass<C, W, H>
    for Supersampled<'_, C, G, N, SW, SH>
where
    C: Interpolate,
    G: FnMut(&mut BandView<'_, C, SW>) -> Result<(), Error>,
{
    fn check(&mut self, renderer: &Renderer<C>) -> Result<(), Error> {
        let () = Grid::<super::Ssaa<N>, W, H, SW, SH>::CHECK;
        check_height(renderer.height(), N)
    }

    fn draw(&mut self, view: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        let (y0, y1) = (view.y0(), view.y1());
        let mut sv = sample_view::<super::Ssaa<N>, C, SW, SH>(self.samples, renderer.background(), y0, y1);
        let drawn = (self.draw)(&mut sv);
        resolve::<super::Ssaa<N>, C, W, SW>(&mut sv, view);
        drawn
    }
}

/// Screen triangles from the vertex stage anti-aliased as `mode` says, with
/// colour interpolation `interp` ([`Affine`] or
/// [`PerspectiveCorrect`](crate::raster3d::PerspectiveCorrect)) and the
/// depth buffer `depth` at *sample* resolution (`SW × SH`, cleared to far
/// at each band; [`NoDepth`] for none), tested as `state` says. Depth is
/// tested per sample in every mode; [`Msaa`](super::Msaa) and
/// [`MsaaSparse`](super::MsaaSparse) evaluate colour once per pixel
/// ([`super::msaa`]). The renderer's cull mode does not apply: the vertex
/// stage culls.
///
/// Errors as for [`Antialiased`].
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::prelude::*;
/// use microraster::aa::{Antialiased3d, Msaa};
/// use microraster::depth::{Depth16, DepthBand, DepthState};
/// use microraster::raster3d::{Affine, ScreenTriangle, ScreenVertex};
/// use microraster::{Band, Renderer, SubPoint};
/// let v = |x, y| ScreenVertex {
///     pos: SubPoint::<4>::from_pixels(x, y).unwrap(),
///     color: [255, 0, 0],
///     inv_w: 1 << 30,
///     ..Default::default()
/// };
/// let tris = [ScreenTriangle { v: [v(0, 0), v(2, 0), v(0, 2)], flat: true }];
/// let mut samples = Band::<Gray8, 4, 4>::new(Gray8::BLACK); // 2 × 2 samples a pixel
/// let mut depth = DepthBand::<Depth16, 4, 4>::new();
/// let mut out = Band::<Gray8, 2, 2>::new(Gray8::BLACK);
/// let mut display = MockDisplay::new();
/// let frame = Antialiased3d::new(Msaa::<2>, &tris, &mut samples, &mut depth, DepthState::LESS_WRITE, Affine);
/// Renderer::new(2, Gray8::BLACK).render(frame, &mut out, &mut display)?;
/// // The diagonal pixels have 1 of 4 samples covered: round(255/4) = 64.
/// assert_eq!(display.get_pixel(Point::new(1, 0)), Some(Gray8::new(64)));
/// assert_eq!(display.get_pixel(Point::new(0, 0)), Some(Gray8::WHITE));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
pub struct Antialiased3d<'a, A, C, F: DepthFormat, M, const S: u32, const SW: usize, const SH: usize> {
    triangles: &'a [ScreenTriangle<S>],
    samples: &'a mut Band<C, SW, SH>,
    depth: &'a mut DepthBand<F, SW, SH>,
    state: DepthState,
    _am: PhantomData<(A, M)>,
}

impl<'a, A, C, F, M, const S: u32, const SW: usize, const SH: usize> Antialiased3d<'a, A, C, F, M, S, SW, SH>
where
    A: Antialias,
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    /// `triangles` anti-aliased as `mode` says through `samples`, tested
    /// against `depth` as `state` says, colour interpolated as `interp` says.
    pub fn new(
        mode: A,
        triangles: &'a [ScreenTriangle<S>],
        samples: &'a mut Band<C, SW, SH>,
        depth: &'a mut DepthBand<F, SW, SH>,
        state: DepthState,
        interp: M,
    ) -> Self {
        let _ = (mode, interp); // values, so the call needs no turbofish
        Antialiased3d { triangles, samples, depth, state, _am: PhantomData }
    }
}

impl<A, C, F, M, const S: u32, const W: usize, const H: usize, const SW: usize, const SH: usize> Pass<C, W, H>
    for Antialiased3d<'_, A, C, F, M, S, SW, SH>
where
    A: Antialias,
    C: Interpolate,
    F: DepthFormat,
    M: Interpolation,
{
    fn check(&mut self, renderer: &Renderer<C>) -> Result<(), Error> {
        let () = Grid::<A, W, H, SW, SH>::CHECK;
        check_height(renderer.height(), A::N)?;
        for tri in self.triangles {
            scale_triangle(tri, A::N)?;
        }
        Ok(())
    }

    fn draw(&mut self, view: &mut BandView<'_, C, W>, renderer: &Renderer<C>) -> Result<(), Error> {
        let (y0, y1) = (view.y0(), view.y1());
        let mut sv = sample_view::<A, C, SW, SH>(self.samples, renderer.background(), y0, y1);
        let (sy0, sy1) = (sv.y0(), sv.y1());
        let mut rows = self.depth.rows_mut(sv.height());
        for r in rows.iter_mut() {
            r.fill(F::FAR);
        }
        for tri in self.triangles {
            let Ok(scaled) = scale_triangle(tri, A::N) else { continue };
            let (lo, hi) = scaled.rows();
            if lo < sy1 && hi >= sy0 {
                if A::SHADE_PER_PIXEL {
                    let Some(shader) = PixelShader::<C>::new::<M, S>(tri) else { continue };
                    let shade = |x, y| shader.at(x, y);
                    msaa::draw_scaled::<A, C, F, S, SW>(
                        &scaled,
                        Cull::None,
                        &mut sv,
                        &mut rows,
                        self.state,
                        shade,
                    );
                } else {
                    draw_triangle(&scaled, &mut sv, &mut rows, self.state, M::default());
                }
            }
        }
        resolve::<A, C, W, SW>(&mut sv, view);
        Ok(())
    }
}

/// The sample rows of output rows `y0..y1`, cleared to `background`.
fn sample_view<'a, A: Antialias, C: Interpolate, const SW: usize, const SH: usize>(
    samples: &'a mut Band<C, SW, SH>,
    background: C,
    y0: i32,
    y1: i32,
) -> BandView<'a, C, SW> {
    let n = A::N as i32;
    // Rows are within MAX_FRAME_DIM / N (checked), so the products fit.
    samples.view(y0 * n, ((y1 - y0) * n) as usize, background)
}

/// One 2D triangle on the sample grid, if it touches sample rows `sy0..sy1`.
fn draw_2d<A: Antialias, C: Interpolate, const S: u32, const SW: usize>(
    t: &Triangle<C, S>,
    cull: Cull,
    sv: &mut BandView<'_, C, SW>,
    sy0: i32,
    sy1: i32,
) {
    let Ok(v) = scale_vertices(t.vertices(), A::N) else { return };
    let scaled = Triangle::new(v, t.shading());
    let (lo, hi) = scaled.rows();
    if lo >= sy1 || hi < sy0 {
        return;
    }
    let (cs, flat) = match t.shading() {
        // Flat fills are the same in every full-grid mode: whole sample spans.
        Shading::Flat(_) if A::COLS == A::N => return scaled.draw(sv, cull),
        Shading::Gouraud(_) if !A::SHADE_PER_PIXEL => return scaled.draw(sv, cull),
        Shading::Flat(c) => ([c; 3], true),
        Shading::Gouraud(cs) => (cs, false),
    };
    let vertex =
        |i: usize| ScreenVertex { pos: t.vertices()[i], depth: 0, inv_w: 1, color: cs[i].to_channels() };
    let pixel = ScreenTriangle { v: [vertex(0), vertex(1), vertex(2)], flat };
    let mut on_grid = pixel;
    for (sv, p) in on_grid.v.iter_mut().zip(v) {
        sv.pos = p;
    }
    let Some(shader) = PixelShader::<C>::new::<Affine, S>(&pixel) else { return };
    let shade = |x, y| shader.at(x, y);
    msaa::draw_scaled::<A, C, NoDepth, S, SW>(&on_grid, cull, sv, &mut [], DepthState::DISABLED, shade);
}

/// A pixel-resolution [`Blitter`] over a sample view: each pixel fills all
/// its samples (aliased lines).
struct Blocks<'v, 'a, A, C, const SW: usize> {
    view: &'v mut BandView<'a, C, SW>,
    _a: core::marker::PhantomData<A>,
}

impl<A: Antialias, C: Interpolate, const SW: usize> Blitter<C> for Blocks<'_, '_, A, C, SW> {
    fn clip(&self) -> ClipRect {
        let (n, cols) = (A::N as i32, A::COLS as i32);
        let (y0, rows) = (self.view.y0(), self.view.height() as i32);
        ClipRect::new(0, y0 / n, SW as i32 / cols, (y0 + rows) / n)
    }

    fn set_pixel(&mut self, x: i32, y: i32, color: C) {
        let (n, cols) = (A::N as i32, A::COLS as i32);
        for j in 0..n {
            self.view.fill_span(Span { y: y * n + j, x: x * cols, len: cols as u32 }, color);
        }
    }
}
