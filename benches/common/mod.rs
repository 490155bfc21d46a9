//! The renderers under comparison, shared word for word by the criterion
//! benchmarks (`benches/peers.rs`) and the report
//! (`cargo run --release --example report`, which includes this file with
//! `#[path]`). Each one draws a whole `W × H` frame, background included, of
//! the same scene from `microraster_scenes::scenes` / `microraster_scenes::scenes3d`:
//!
//! * microraster: the band renderer ([`mr_band`]) and direct drawing through
//!   `TargetBlitter` ([`mr_direct`]); the 3D scene through the vertex stage and
//!   `Triangles3d` ([`mr3d`]);
//! * embedded-graphics 0.8: `Triangle` / `Line` styled primitives ([`eg`]);
//! * tiny-skia 0.12: `fill_path` without anti-aliasing, hairline
//!   `stroke_path` for lines ([`skia`]);
//! * an f64 reference rasterizer ([`reference`], copied from
//!   `tests/integration/reference.rs`: point-in-triangle on the pixel centres,
//!   boundary excluded; lines by the f64 midpoint rule of
//!   `tests/integration/lines.rs`) and an f64 reference 3D pipeline
//!   ([`Ref3d`]: f64 transform, lighting, depth test and perspective-correct
//!   colour);
//! * the physical ceiling: a slice fill of the whole framebuffer ([`memset`]).
//!
//! Targets: [`SliceFb`], a plain `Vec<Rgb565>` whose `fill_solid` and
//! `fill_contiguous` are slice operations (what a DMA-fed display or a plain
//! framebuffer offers), and [`EgFb`], embedded-graphics' own `Framebuffer`,
//! whose `DrawTarget` implementation only has a per-pixel `draw_iter` (every
//! `fill_solid` and `fill_contiguous` goes through it pixel by pixel).
#![allow(dead_code)]

use core::convert::Infallible;
use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{
    Line as EgLine, Primitive as _, PrimitiveStyle, Styled, Triangle as EgTriangle,
};
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::primitives::Rectangle;
use microraster::blit::TargetBlitter;
use microraster::depth::{DepthBand, DepthFormat, DepthState};
use microraster::edge::Cull;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::Mesh;
use microraster::pipeline::Pipeline;
use microraster::raster3d::{Interpolation, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Interpolate, Primitive, Renderer, SubPoint};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{BINS, Scene3d};

/// Frame width.
pub const W: usize = 320;
/// Frame height.
pub const H: usize = 240;
/// Background of every frame (all-zero bits, so byte buffers clear with 0).
pub const BG: Rgb565 = Rgb565::BLACK;
/// Animation angle of the 3D scene: the firmware's (`examples/firmware/workload.rs`).
pub const ANGLE: f32 = 0.6;

/// embedded-graphics' framebuffer of the same colour type.
pub type EgFb = Framebuffer<Rgb565, RawU16, LittleEndian, W, H, { buffer_size::<Rgb565>(W, H) }>;

/// A target that can be reset to the background by its fastest means.
pub trait Frame: DrawTarget<Color = Rgb565, Error = Infallible> {
    /// Sets every pixel to [`BG`].
    fn wipe(&mut self);
}

impl Frame for EgFb {
    fn wipe(&mut self) {
        self.data_mut().fill(0);
    }
}

/// A plain framebuffer with slice-speed `fill_solid` and `fill_contiguous`.
pub struct SliceFb {
    /// Pixels, row by row.
    pub px: Vec<Rgb565>,
}

impl Default for SliceFb {
    fn default() -> Self {
        SliceFb { px: vec![BG; W * H] }
    }
}

impl Frame for SliceFb {
    fn wipe(&mut self) {
        self.px.fill(BG);
    }
}

impl OriginDimensions for SliceFb {
    fn size(&self) -> Size {
        Size::new(W as u32, H as u32)
    }
}

fn inside(area: &Rectangle) -> bool {
    let b = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    area.intersection(&b) == *area && !area.is_zero_sized()
}

impl DrawTarget for SliceFb {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if (0..W as i32).contains(&p.x) && (0..H as i32).contains(&p.y) {
                self.px[p.y as usize * W + p.x as usize] = c;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        if !inside(area) {
            return self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)));
        }
        let (x0, w) = (area.top_left.x as usize, area.size.width as usize);
        if w == W || area.size.height == 1 {
            // Whole rows (or a single row): one contiguous run of the buffer,
            // copied in one pass.
            let start = area.top_left.y as usize * W + x0;
            let run = &mut self.px[start..][..w * area.size.height as usize];
            for (d, c) in run.iter_mut().zip(colors) {
                *d = c;
            }
            return Ok(());
        }
        let mut it = colors.into_iter();
        for y in area.rows() {
            let row = &mut self.px[y as usize * W + x0..][..w];
            for (d, c) in row.iter_mut().zip(&mut it) {
                *d = c;
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Infallible> {
        let area = area.intersection(&Rectangle::new(Point::zero(), Size::new(W as u32, H as u32)));
        let (x0, w) = (area.top_left.x as usize, area.size.width as usize);
        for y in area.rows() {
            self.px[y as usize * W + x0..][..w].fill(color);
        }
        Ok(())
    }
}

/// The physical ceiling: every pixel of the frame written by a slice fill.
pub fn memset(fb: &mut SliceFb, color: Rgb565) {
    fb.px.fill(color);
}

// ---------------------------------------------------------------------------
// 2D scenes
// ---------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------
// The 3D scene (benchmark scene 4)
// ---------------------------------------------------------------------------

/// The frame's bins.
pub type Bins<const S: u32> = heapless::Vec<ScreenTriangle<S>, BINS>;

/// Background of the 3D frames.
pub const BG3: Rgb565 = Rgb565::BLACK;

/// The standard 3D scene at [`ANGLE`]: the vertex stage on path `T` into
/// `bins`, then `Triangles3d` with `BH`-row bands, depth format `F` and colour
/// interpolation `M` into `target`. Returns the number of screen triangles.
pub fn mr3d<T: Scalar, F: DepthFormat, M: Interpolation, const S: u32, const BH: usize>(
    pipeline: &Pipeline<T, S>,
    bins: &mut Bins<S>,
    band: &mut Band<Rgb565, W, BH>,
    depth: &mut DepthBand<F, W, BH>,
    target: &mut impl Frame,
) -> usize {
    bins.clear();
    Scene3d.draw::<T, Rgb565, S, BINS>(pipeline, ANGLE, bins).unwrap();
    Renderer::new(H as u32, BG3)
        .render(Triangles3d::new(bins, depth, DepthState::LESS_WRITE, M::default()), band, target)
        .unwrap();
    bins.len()
}

/// The standard scene's pipeline for the `W × H` frame.
pub fn pipeline3d<T: Scalar, const S: u32>() -> Pipeline<T, S> {
    Scene3d::pipeline::<T, S>(W as u32, H as u32).unwrap()
}

/// The model matrix and material colour of mesh `k` (sphere, torus, cube) at
/// `angle`, as `Scene3d::draw` builds them (`scenes/src/scenes3d.rs`; the report
/// checks that drawing with these reproduces `Scene3d::draw`'s bins).
pub fn model<T: Scalar>(k: usize, angle: f32) -> (Mat4<T>, [f32; 3]) {
    let f = T::from_f32;
    let s = |v: f32| transform::scaling(Vec3::new(f(v), f(v), f(v)));
    match k {
        0 => (transform::rotation_y(f(angle)) * s(1.45), [0.9, 0.35, 0.2]),
        1 => (transform::rotation_y(f(angle * 0.5)) * transform::rotation_x(f(0.45)), [0.25, 0.6, 0.95]),
        _ => (
            transform::translation(Vec3::new(f(1.05), f(-0.5), f(1.25)))
                * transform::rotation_y(f(-angle))
                * s(0.55),
            [0.95, 0.85, 0.3],
        ),
    }
}

/// The material colour as `Scene3d::draw` quantizes it for `C`.
pub fn material<C: Interpolate>(rgb: [f32; 3]) -> C {
    let m = C::CHANNEL_MAX;
    C::from_channels([0, 1, 2].map(|k| (rgb[k] * m[k] as f32 + 0.5) as u8))
}

/// Marker so the f32 and Fx paths can be named in tables.
pub fn path_name<T: Scalar>() -> &'static str {
    if core::any::type_name::<T>() == core::any::type_name::<Fx>() { "Fx" } else { "f32" }
}

// --- the f64 reference pipeline ---------------------------------------------

/// A 4 × 4 matrix, rows.
pub type M4 = [[f64; 4]; 4];

/// `a · b`.
pub fn mul(a: &M4, b: &M4) -> M4 {
    let mut m = [[0.0; 4]; 4];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}

fn apply(m: &M4, p: [f64; 4]) -> [f64; 4] {
    [0, 1, 2, 3].map(|i| (0..4).map(|k| m[i][k] * p[k]).sum())
}

fn ident() -> M4 {
    let mut m = [[0.0; 4]; 4];
    (0..4).for_each(|i| m[i][i] = 1.0);
    m
}

fn rot_x(a: f64) -> M4 {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, 0.0], [0.0, 0.0, 0.0, 1.0]]
}

/// Rotation by `a` radians about y.
pub fn rot_y(a: f64) -> M4 {
    let (s, c) = a.sin_cos();
    [[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]]
}

fn scale(v: f64) -> M4 {
    let mut m = ident();
    (0..3).for_each(|i| m[i][i] = v);
    m
}

fn translate(t: [f64; 3]) -> M4 {
    let mut m = ident();
    (0..3).for_each(|i| m[i][3] = t[i]);
    m
}

/// `v` scaled to unit length.
pub fn norm(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / l)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The standard scene's light (`Scene3d::pipeline`): direction in eye
/// space (not normalised), ambient, diffuse and specular weights, exponent.
pub const LIGHT: [f64; 3] = [-0.4, 0.7, 0.6];
/// Ambient weight of the standard scene's light.
pub const AMBIENT: f64 = 0.25;
/// Diffuse (Lambert) weight.
pub const DIFFUSE: f64 = 0.75;
/// Specular (Blinn–Phong) weight.
pub const SPECULAR: f64 = 0.4;
/// Specular exponent.
pub const SHININESS: i32 = 24;
/// The near plane's distance.
const NEAR: f64 = 1.0;

/// The standard scene's view and projection matrices (`Scene3d::pipeline`:
/// `look_at` from (0, 1.9, 5.6) to the origin, 0.9 rad vertical field of
/// view, near 1, far 20, `W × H`), in f64, rows.
pub fn camera() -> (M4, M4) {
    let eye = [0.0, 1.9, 5.6];
    let f = norm([-eye[0], -eye[1], -eye[2]]);
    let s = norm(cross(f, [0.0, 1.0, 0.0]));
    let u = cross(s, f);
    let view: M4 = [
        [s[0], s[1], s[2], -dot(s, eye)],
        [u[0], u[1], u[2], -dot(u, eye)],
        [-f[0], -f[1], -f[2], dot(f, eye)],
        [0.0, 0.0, 0.0, 1.0],
    ];
    let (near, far, fov) = (NEAR, 20.0, 0.9f64);
    let fy = 1.0 / (fov / 2.0).tan();
    let a = far / (near - far);
    let proj: M4 = [
        [fy / (W as f64 / H as f64), 0.0, 0.0, 0.0],
        [0.0, fy, 0.0, 0.0],
        [0.0, 0.0, a, near * a],
        [0.0, 0.0, -1.0, 0.0],
    ];
    (view, proj)
}

/// One front-facing triangle of the f64 pipeline, in screen space (unsnapped).
#[derive(Clone, Copy, Debug)]
pub struct RefTri {
    /// Pixel coordinates.
    pub xy: [(f64, f64); 3],
    /// Depth `z/w`.
    pub d: [f64; 3],
    /// `1/w`.
    pub q: [f64; 3],
    /// Lit vertex colour in `[0, 1]` per channel.
    pub c: [[f64; 3]; 3],
    /// Source triangle: `mesh · 65536 + index`.
    pub id: u32,
}

/// Per pixel of the f64 reference frame: the nearest triangle's id
/// (`u32::MAX` for background), its depth and its perspective-correct colour.
#[derive(Clone, Copy, Debug)]
pub struct RefPixel {
    /// Source triangle id, `u32::MAX` if none.
    pub id: u32,
    /// Depth `z/w` in `[0, 1]`.
    pub depth: f64,
    /// Colour channels in `[0, 1]`.
    pub color: [f64; 3],
}

/// The standard 3D scene through an f64 pipeline: f64 model, view and
/// projection (same camera, lights and materials as `scenes3d`), f64 lighting
/// (ambient + Lambert + Blinn–Phong per vertex), back faces culled by the
/// unsnapped screen area, then per pixel centre an f64 point-in-triangle test,
/// the depth `z/w` interpolated exactly and `LESS` (the nearest wins), and
/// perspective-correct colour. No snapping, no quantization.
pub struct Ref3d {
    /// Front-facing triangles.
    pub tris: Vec<RefTri>,
}

impl Ref3d {
    /// The vertex stage at `angle`, with materials quantized for `C` as the
    /// library does.
    pub fn new<C: Interpolate>(angle: f32) -> Self {
        let (view, proj) = camera();
        let near = NEAR;
        let light = norm(LIGHT);
        let (ambient, diffuse, spec, exp) = (AMBIENT, DIFFUSE, SPECULAR, SHININESS);
        let ang = angle as f64;
        let models = [
            mul(&rot_y(ang), &scale(1.45)),
            mul(&rot_y(ang * 0.5), &rot_x(0.45)),
            mul(&mul(&translate([1.05, -0.5, 1.25]), &rot_y(-ang)), &scale(0.55)),
        ];
        let mut tris = Vec::new();
        for (k, mesh) in Scene3d.meshes().iter().enumerate() {
            let mv = mul(&view, &models[k]);
            let mvp = mul(&proj, &mv);
            let base = material::<C>(model::<f32>(k, angle).1).to_channels();
            let max = C::CHANNEL_MAX;
            let base = [0, 1, 2].map(|i| if max[i] == 0 { 0.0 } else { base[i] as f64 / max[i] as f64 });
            // Rotation and uniform scale: the normal matrix is the rotation part, normalised.
            let nm = |n: [f32; 3]| {
                let v = apply(&mv, [n[0] as f64, n[1] as f64, n[2] as f64, 0.0]);
                norm([v[0], v[1], v[2]])
            };
            for (i, idx) in mesh.indices.iter().enumerate() {
                let vert = |j: usize| {
                    let p = mesh.positions[idx[j] as usize].map(|c| c as f64);
                    let clip = apply(&mvp, [p[0], p[1], p[2], 1.0]);
                    let eye_p = apply(&mv, [p[0], p[1], p[2], 1.0]);
                    let n = nm(mesh.normals[idx[j] as usize]);
                    let lambert = dot(n, light).max(0.0);
                    let sp = if lambert > 0.0 {
                        let h = norm([
                            light[0] - norm([eye_p[0], eye_p[1], eye_p[2]])[0],
                            light[1] - norm([eye_p[0], eye_p[1], eye_p[2]])[1],
                            light[2] - norm([eye_p[0], eye_p[1], eye_p[2]])[2],
                        ]);
                        spec * dot(n, h).max(0.0).powi(exp)
                    } else {
                        0.0
                    };
                    let c = base.map(|b| (b * (ambient + diffuse * lambert) + sp).clamp(0.0, 1.0));
                    assert!(clip[3] > near * 0.999, "the f64 reference does not clip");
                    let w = clip[3];
                    let xy = (W as f64 / 2.0 * (1.0 + clip[0] / w), H as f64 / 2.0 * (1.0 - clip[1] / w));
                    (xy, clip[2] / w, 1.0 / w, c)
                };
                let v = [vert(0), vert(1), vert(2)];
                let xy = v.map(|v| v.0);
                let area =
                    (xy[1].0 - xy[0].0) * (xy[2].1 - xy[0].1) - (xy[2].0 - xy[0].0) * (xy[1].1 - xy[0].1);
                if area >= 0.0 {
                    continue; // clockwise on screen (y down): a back face, or zero area
                }
                tris.push(RefTri {
                    xy,
                    d: v.map(|v| v.1),
                    q: v.map(|v| v.2),
                    c: v.map(|v| v.3),
                    id: (k as u32) << 16 | i as u32,
                });
            }
        }
        Ref3d { tris }
    }

    /// Rasterizes every triangle into `out` (`W × H`, row-major).
    pub fn raster(&self, out: &mut [RefPixel]) {
        out.fill(RefPixel { id: u32::MAX, depth: f64::INFINITY, color: [0.0; 3] });
        for t in &self.tris {
            let p = t.xy;
            let det = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
            float_triangle(p, |x, y| {
                let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                let l1 = ((cx - p[0].0) * (p[2].1 - p[0].1) - (cy - p[0].1) * (p[2].0 - p[0].0)) / det;
                let l2 = ((p[1].0 - p[0].0) * (cy - p[0].1) - (p[1].1 - p[0].1) * (cx - p[0].0)) / det;
                let l = [1.0 - l1 - l2, l1, l2];
                let d = (0..3).map(|i| l[i] * t.d[i]).sum::<f64>();
                let px = &mut out[y * W + x];
                if d < px.depth && (0.0..=1.0).contains(&d) {
                    let qs = (0..3).map(|i| l[i] * t.q[i]).sum::<f64>();
                    let color =
                        [0, 1, 2].map(|k| (0..3).map(|i| l[i] * t.q[i] * t.c[i][k]).sum::<f64>() / qs);
                    *px = RefPixel { id: t.id, depth: d, color };
                }
            });
        }
    }

    /// The reference frame as `Rgb565` (for the benchmark: transform,
    /// lighting, rasterization and the colour conversion, timed together).
    pub fn frame(angle: f32, px: &mut [RefPixel], out: &mut [Rgb565]) {
        let r = Ref3d::new::<Rgb565>(angle);
        r.raster(px);
        for (o, p) in out.iter_mut().zip(px.iter()) {
            *o = if p.id == u32::MAX {
                BG3
            } else {
                let c = |v: f64, m: f64| (v * m + 0.5) as u8;
                Rgb565::new(c(p.color[0], 31.0), c(p.color[1], 63.0), c(p.color[2], 31.0))
            };
        }
    }
}

/// The standard scene's vertex stage one source triangle at a time, so that
/// every screen triangle knows where it came from: returns the bins (equal to
/// `Scene3d::draw`'s, which is checked) and, per bin, the source id
/// `mesh · 65536 + index`.
pub fn bins_with_ids<T: Scalar, C: Interpolate, const S: u32>(
    pipeline: &Pipeline<T, S>,
    angle: f32,
) -> (Bins<S>, Vec<u32>) {
    let mut bins = Bins::<S>::new();
    let mut ids = Vec::new();
    for (k, mesh) in Scene3d.meshes().iter().enumerate() {
        let (m, rgb) = model::<T>(k, angle);
        for i in 0..mesh.indices.len() {
            let one = Mesh { indices: &mesh.indices[i..i + 1], ..*mesh };
            let before = bins.len();
            pipeline.draw_mesh(&one, &m, material::<C>(rgb), &mut bins).unwrap();
            ids.extend(core::iter::repeat_n((k as u32) << 16 | i as u32, bins.len() - before));
        }
    }
    let mut whole = Bins::<S>::new();
    Scene3d.draw::<T, C, S, BINS>(pipeline, angle, &mut whole).unwrap();
    assert!(whole == bins, "per-triangle vertex stage differs from Scene3d::draw");
    (bins, ids)
}
