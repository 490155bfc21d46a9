//! One 2D scene prepared for every renderer ([`Scene2d`]) and the renderers
//! of it: microraster (band, binned, direct), embedded-graphics, tiny-skia and
//! the f64 reference rasterizer.

use super::{BG, Frame, H, W};
use core::convert::Infallible;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{
    Line as EgLine, Primitive as _, PrimitiveStyle, Styled, Triangle as EgTriangle,
};
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::primitives::Rectangle;
use microraster::blit::TargetBlitter;
use microraster::edge::Cull;
use microraster::{Band, Primitive, Renderer, SubPoint};
use microraster_scenes::scenes;

enum EgPrim {
    Tri(Styled<EgTriangle, PrimitiveStyle<Rgb565>>),
    Line(Styled<EgLine, PrimitiveStyle<Rgb565>>),
}

struct SkiaPrim {
    path: tiny_skia::Path,
    paint: tiny_skia::Paint<'static>,
    stroke: bool,
}

enum RefPrim {
    Tri([(f64, f64); 3], Rgb565),
    Line((f64, f64), (f64, f64), Rgb565),
}

/// One 2D scene, prepared for every renderer from the same primitives
/// (conversion outside the timed code, as a program would hold its scene).
pub struct Scene2d<const S: u32> {
    /// The microraster primitives.
    pub prims: Vec<Primitive<Rgb565, S>>,
    eg: Vec<EgPrim>,
    skia: Vec<SkiaPrim>,
    refs: Vec<RefPrim>,
    /// Pixels microraster writes for the primitives (overdraw counted), the
    /// frame's fill work.
    pub covered: u64,
}

/// 8-bit RGB of an `Rgb565` (each channel scaled and rounded).
pub fn rgb8(c: Rgb565) -> [u8; 3] {
    let s = |v: u8, max: u32| ((v as u32 * 255 + max / 2) / max) as u8;
    [s(c.r(), 31), s(c.g(), 63), s(c.b(), 31)]
}

impl<const S: u32> Scene2d<S> {
    /// Runs `scene` for the `W × H` frame and prepares every renderer's input.
    /// Gouraud triangles are flat (their first colour) for the peers.
    pub fn new(scene: scenes::Scene<Rgb565, S>) -> Self {
        let mut prims = Vec::new();
        scene(W as u32, H as u32, &mut |p| prims.push(p)).expect("scene");
        Self::from_prims(prims)
    }

    /// The same from a list of primitives (vertices off pixel centres go to
    /// embedded-graphics as the pixel holding them).
    pub fn from_prims(prims: Vec<Primitive<Rgb565, S>>) -> Self {
        let pt = |p: SubPoint<S>| {
            let (x, y) = scenes::center_pixel(p);
            Point::new(x, y)
        };
        let (mut eg, mut skia, mut refs) = (Vec::new(), Vec::new(), Vec::new());
        let mut covered = 0;
        let mut count = Counter(0);
        for p in &prims {
            p.draw(&mut TargetBlitter::new(&mut count), Cull::None);
            let (v, color, line) = match *p {
                Primitive::Triangle(t) => {
                    let c = match t.shading() {
                        microraster::Shading::Flat(c) => c,
                        microraster::Shading::Gouraud(c) => c[0],
                    };
                    (t.vertices().to_vec(), c, false)
                }
                Primitive::Line(l) => (vec![l.start(), l.end()], l.color(), true),
            };
            let f = |q: SubPoint<S>| {
                let (x, y) = q.to_f64();
                (x, y)
            };
            let mut paint = tiny_skia::Paint::default();
            let [r, g, b] = rgb8(color);
            paint.set_color_rgba8(r, g, b, 255);
            paint.anti_alias = false;
            let mut pb = tiny_skia::PathBuilder::new();
            pb.move_to(f(v[0]).0 as f32, f(v[0]).1 as f32);
            for &q in &v[1..] {
                pb.line_to(f(q).0 as f32, f(q).1 as f32);
            }
            if line {
                eg.push(EgPrim::Line(
                    EgLine::new(pt(v[0]), pt(v[1])).into_styled(PrimitiveStyle::with_stroke(color, 1)),
                ));
                refs.push(RefPrim::Line(f(v[0]), f(v[1]), color));
            } else {
                pb.close();
                eg.push(EgPrim::Tri(
                    EgTriangle::new(pt(v[0]), pt(v[1]), pt(v[2]))
                        .into_styled(PrimitiveStyle::with_fill(color)),
                ));
                refs.push(RefPrim::Tri([f(v[0]), f(v[1]), f(v[2])], color));
            }
            if let Some(path) = pb.finish() {
                skia.push(SkiaPrim { path, paint, stroke: line });
            }
        }
        covered += count.0;
        Scene2d { prims, eg, skia, refs, covered }
    }
}

/// Counts pixels written (a `DrawTarget` that stores nothing).
struct Counter(u64);

impl OriginDimensions for Counter {
    fn size(&self) -> Size {
        Size::new(W as u32, H as u32)
    }
}

impl DrawTarget for Counter {
    type Color = Rgb565;
    type Error = Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        self.0 += pixels.into_iter().count() as u64;
        Ok(())
    }
    fn fill_solid(&mut self, area: &Rectangle, _: Rgb565) -> Result<(), Infallible> {
        self.0 += area.size.width as u64 * area.size.height as u64;
        Ok(())
    }
}

/// microraster's band renderer with `BH`-row bands into `target`.
pub fn mr_band<const S: u32, const BH: usize>(
    scene: &Scene2d<S>,
    band: &mut Band<Rgb565, W, BH>,
    target: &mut impl Frame,
) {
    Renderer::new(H as u32, BG).render(&scene.prims[..], band, target).unwrap();
}

/// [`mr_band`] through a [`Binned2d`](microraster::render::Binned2d) index
/// (`index` resized to what the scene needs on its first use): each band
/// reads only the primitives that touch it.
pub fn mr_binned<const S: u32, const BH: usize>(
    scene: &Scene2d<S>,
    band: &mut Band<Rgb565, W, BH>,
    index: &mut Vec<u16>,
    target: &mut impl Frame,
) {
    use microraster::render::Binned2d;
    let renderer = Renderer::new(H as u32, BG);
    match renderer.render(Binned2d::new(&scene.prims, index), band, target) {
        Err(microraster::RenderError::Input(microraster::Error::CapacityExceeded { needed, .. })) => {
            index.resize(needed, 0);
            renderer.render(Binned2d::new(&scene.prims, index), band, target).unwrap();
        }
        other => other.unwrap(),
    }
}

/// microraster drawing straight into `target` (no band): the target is
/// wiped, then every primitive goes through `TargetBlitter` (spans become
/// `fill_solid`, Gouraud spans `fill_contiguous`).
pub fn mr_direct<const S: u32>(scene: &Scene2d<S>, target: &mut impl Frame) {
    target.wipe();
    let mut blitter = TargetBlitter::new(target);
    for p in &scene.prims {
        p.draw(&mut blitter, Cull::None);
    }
}

/// embedded-graphics 0.8: the target is wiped, then every styled primitive drawn.
pub fn eg<const S: u32>(scene: &Scene2d<S>, target: &mut impl Frame) {
    target.wipe();
    for p in &scene.eg {
        match p {
            EgPrim::Tri(t) => t.draw(target).unwrap(),
            EgPrim::Line(l) => l.draw(target).unwrap(),
        }
    }
}

/// tiny-skia 0.12 into an RGBA8888 `Pixmap` (its only format), anti-aliasing
/// off; triangles with `fill_path` (winding), lines as hairlines.
pub fn skia<const S: u32>(scene: &Scene2d<S>, pixmap: &mut tiny_skia::Pixmap) {
    pixmap.fill(tiny_skia::Color::BLACK);
    let id = tiny_skia::Transform::identity();
    let hairline = tiny_skia::Stroke { width: 0.0, ..Default::default() };
    for p in &scene.skia {
        if p.stroke {
            pixmap.stroke_path(&p.path, &p.paint, &hairline, id, None);
        } else {
            pixmap.fill_path(&p.path, &p.paint, tiny_skia::FillRule::Winding, id, None);
        }
    }
}

/// Point-in-triangle on `f64` vertices, either winding, boundary excluded
/// (`tests/integration/reference.rs`).
#[inline]
pub fn float_inside(v: [(f64, f64); 3], px: f64, py: f64) -> bool {
    let e = |a: (f64, f64), b: (f64, f64)| (b.0 - a.0) * (py - a.1) - (b.1 - a.1) * (px - a.0);
    let (e0, e1, e2) = (e(v[0], v[1]), e(v[1], v[2]), e(v[2], v[0]));
    (e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0)
}

/// Calls `hit(x, y)` for every pixel of the frame whose centre `float_inside`
/// puts inside `v` (brute force over the bounding box).
#[inline]
pub fn float_triangle(v: [(f64, f64); 3], mut hit: impl FnMut(usize, usize)) {
    let lo = |i: usize| v.iter().map(|p| if i == 0 { p.0 } else { p.1 }).fold(f64::INFINITY, f64::min);
    let hi = |i: usize| v.iter().map(|p| if i == 0 { p.0 } else { p.1 }).fold(f64::NEG_INFINITY, f64::max);
    let (x0, x1) = ((lo(0) - 0.5).floor().max(0.0) as usize, ((hi(0) - 0.5).ceil() as i64).min(W as i64 - 1));
    let (y0, y1) = ((lo(1) - 0.5).floor().max(0.0) as usize, ((hi(1) - 0.5).ceil() as i64).min(H as i64 - 1));
    for y in y0..=y1.max(-1) as usize {
        for x in x0..=x1.max(-1) as usize {
            if float_inside(v, x as f64 + 0.5, y as f64 + 0.5) {
                hit(x, y);
            }
        }
    }
}

/// The f64 midpoint rule of `tests/integration/lines.rs`: one pixel per
/// major-axis centre in `[a, b)`, the minor index the floor of the exact line
/// there.
pub fn float_line(a: (f64, f64), b: (f64, f64), mut hit: impl FnMut(usize, usize)) {
    let x_major = (b.0 - a.0).abs() >= (b.1 - a.1).abs();
    let (ua, va, ub, vb) = if x_major { (a.0, a.1, b.0, b.1) } else { (a.1, a.0, b.1, b.0) };
    if ua == ub {
        return;
    }
    let (lo, hi) = if ub > ua { (ua, ub) } else { (ub, ua) };
    let mut m = (lo - 0.5).floor() as i64;
    while (m as f64) + 0.5 < hi + 1.0 {
        let c = m as f64 + 0.5;
        let in_segment = if ub > ua { ua <= c && c < ub } else { ub < c && c <= ua };
        if in_segment {
            let minor = (va + (vb - va) * (c - ua) / (ub - ua)).floor() as i64;
            let (x, y) = if x_major { (m, minor) } else { (minor, m) };
            if (0..W as i64).contains(&x) && (0..H as i64).contains(&y) {
                hit(x as usize, y as usize);
            }
        }
        m += 1;
    }
}

/// The f64 reference rasterizer into a plain pixel buffer.
pub fn reference<const S: u32>(scene: &Scene2d<S>, out: &mut [Rgb565]) {
    out.fill(BG);
    for p in &scene.refs {
        match *p {
            RefPrim::Tri(v, c) => float_triangle(v, |x, y| out[y * W + x] = c),
            RefPrim::Line(a, b, c) => float_line(a, b, |x, y| out[y * W + x] = c),
        }
    }
}
