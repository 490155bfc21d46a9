//! Each shape against embedded-graphics' and tiny-skia's same shape, in one run:
//!
//! ```text
//! cargo bench --bench shapes              # about a minute of measuring
//! cargo bench --bench shapes -- circle    # one shape (criterion filter)
//! ```
//!
//! Every benchmark draws the same 24 instances of one shape (sizes 8 to 120
//! px, spread over the frame) at 320 × 240: microraster straight into a
//! slice framebuffer through `Drawable` (`mr_direct`), through 16-row bands
//! (`mr_band16`), through the same bands with each shape's edges built once
//! a frame (`mr_band16_prepared`: `Styled::prepare`, then `Prepared::set`
//! every frame) and anti-aliased in bands (`mr_aa_band16`); e-g's styled
//! primitive into the same framebuffer (`eg`); tiny-skia aliased and
//! anti-aliased into its RGBA pixmap (`skia`, `skia_aa`). e-g has no polygon
//! (its `Triangle` only, benchmarked as `triangle`) and no anti-aliasing. After criterion's output a
//! table of ratios from this run's medians is printed (> 1: microraster is
//! faster), with the verdict computed from it. The `dashboard` group times
//! the dashboard frame (`examples/common/dashboard.rs`) against its plain
//! e-g version.

use criterion::{BenchmarkGroup, Criterion, measurement::WallTime};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{self as eg, PrimitiveStyle};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Band;
use microraster::Renderer;
use microraster::render::from_fn;
use microraster::shape::{self as sh, Shape, ShapeStyle};
use std::hint::black_box;
use std::time::Duration;

#[path = "common/mod.rs"]
pub mod common;
use common::shape_set::{bounds, place};
use common::{BG, Frame, H, SliceFb, W};
#[path = "common/criterion_median.rs"]
mod criterion_median;
use criterion_median::median;
#[allow(dead_code)] // each user takes what it needs
#[path = "../examples/common/dashboard.rs"]
mod dashboard;

const FG: Rgb565 = Rgb565::new(31, 40, 8);
const STROKE: f32 = 5.0;
const SHAPES: [&str; 10] =
    ["rect", "rounded", "circle", "ellipse", "arc", "sector", "polygon", "polyline", "triangle", "line"];

fn star(c: (f32, f32), s: f32) -> [(f32, f32); 10] {
    core::array::from_fn(|i| {
        let a = i as f32 * std::f32::consts::TAU / 10.0;
        let r = if i % 2 == 0 { s / 2.0 } else { s / 5.0 };
        (c.0 + r * a.cos(), c.1 + r * a.sin())
    })
}

fn triangle(c: (f32, f32), s: f32) -> [(f32, f32); 3] {
    [(c.0 - s / 2.0, c.1 + s / 3.0), (c.0 + s / 2.0, c.1 + s / 4.0), (c.0 - s / 6.0, c.1 - s / 2.0)]
}

fn segment(c: (f32, f32), s: f32) -> [(f32, f32); 2] {
    [(c.0 - s / 2.0, c.1 - s / 3.0), (c.0 + s / 2.0, c.1 + s / 3.0)]
}

fn zigzag(c: (f32, f32), s: f32) -> [(f32, f32); 5] {
    core::array::from_fn(|i| {
        (c.0 - s / 2.0 + s * i as f32 / 4.0, c.1 + if i % 2 == 0 { -s / 4.0 } else { s / 4.0 })
    })
}

/// A styled shape of any type, drawable on a band view or a `DrawTarget`,
/// and prepared once a frame (`shape::Prepared`) for the bands.
trait MrDraw {
    fn band(&self, v: &mut microraster::band::BandView<'_, Rgb565, W>);
    fn direct(&self, t: &mut SliceFb);
    /// Builds the frame's edges once (`Styled::prepare`).
    fn prepare(&mut self);
    /// Draws from the edges `prepare` built (or as `band` if they did not fit).
    fn band_prepared(&mut self, v: &mut microraster::band::BandView<'_, Rgb565, W>);
}

/// A styled shape and its prepared edges of this frame.
struct Mr<S, A> {
    styled: sh::Styled<S, Rgb565, A>,
    prepared: Option<sh::Prepared<S, Rgb565, A>>,
}

impl<S: Shape + Clone, A: sh::Coverage + Clone> MrDraw for Mr<S, A> {
    fn band(&self, v: &mut microraster::band::BandView<'_, Rgb565, W>) {
        self.styled.draw_on(v);
    }
    fn direct(&self, t: &mut SliceFb) {
        self.styled.draw(t).unwrap();
    }
    fn prepare(&mut self) {
        // In place after the first frame: a shape rebuilt every frame, in
        // the lists it keeps.
        match &mut self.prepared {
            Some(p) => {
                if p.set(self.styled.clone()).is_err() {
                    self.prepared = None;
                }
            }
            None => self.prepared = self.styled.prepare().ok(),
        }
    }
    fn band_prepared(&mut self, v: &mut microraster::band::BandView<'_, Rgb565, W>) {
        match &mut self.prepared {
            Some(p) => p.draw_on(v),
            None => self.styled.draw_on(v),
        }
    }
}

fn boxed<S: Shape + Clone + 'static>(s: S, style: ShapeStyle<Rgb565>, aa: bool) -> Box<dyn MrDraw> {
    if aa {
        Box::new(Mr { styled: s.styled(style.antialiased()).unwrap(), prepared: None })
    } else {
        Box::new(Mr { styled: s.styled(style).unwrap(), prepared: None })
    }
}

/// The 24 instances of shape `name` for microraster.
fn mr_shapes(name: &str, aa: bool) -> Vec<Box<dyn MrDraw>> {
    let (fill, stroke) = (ShapeStyle::fill(FG), ShapeStyle::stroke(FG, STROKE));
    (0..24)
        .map(|k| {
            let (c, s) = place(k);
            let (x, y, w, h) = bounds(k);
            let rect = sh::Rect::new(x, y, w, h).unwrap();
            match name {
                "rect" => boxed(rect, fill, aa),
                "rounded" => boxed(sh::RoundedRect::new(rect, s / 8.0).unwrap(), fill, aa),
                "circle" => boxed(sh::Circle::new(c, s / 2.0).unwrap(), fill, aa),
                "ellipse" => boxed(sh::Ellipse::new(c, s / 2.0, s / 3.0).unwrap(), fill, aa),
                "arc" => boxed(sh::Arc::new(c, s / 2.0, 0.5, 4.0).unwrap(), stroke, aa),
                "sector" => boxed(sh::Sector::new(c, s / 2.0, 0.5, 4.0).unwrap(), fill, aa),
                "polygon" => boxed(sh::Polygon::new(Box::leak(Box::new(star(c, s)))).unwrap(), fill, aa),
                "triangle" => boxed(sh::Polygon::new(Box::leak(Box::new(triangle(c, s)))).unwrap(), fill, aa),
                "line" => boxed(sh::Polyline::new(Box::leak(Box::new(segment(c, s)))).unwrap(), stroke, aa),
                _ => boxed(sh::Polyline::new(Box::leak(Box::new(zigzag(c, s)))).unwrap(), stroke, aa),
            }
        })
        .collect()
}

type EgDraw = Box<dyn Fn(&mut SliceFb)>;

/// The same instances as e-g styled primitives (integer geometry), if e-g has the shape.
fn eg_shapes(name: &str) -> Option<Vec<EgDraw>> {
    let (fill, stroke) = (PrimitiveStyle::with_fill(FG), PrimitiveStyle::with_stroke(FG, STROKE as u32));
    let p = |x: f32, y: f32| Point::new(x.round() as i32, y.round() as i32);
    let deg = |r: f32| Angle::from_degrees(r.to_degrees());
    if name == "polygon" {
        return None;
    }
    Some(
        (0..24)
            .map(|k| -> EgDraw {
                let (c, s) = place(k);
                let (x, y, w, h) = bounds(k);
                let rect = eg::Rectangle::new(p(x, y), Size::new(w as u32, h as u32));
                let d = s as u32;
                match name {
                    "rect" => Box::new(move |t| rect.into_styled(fill).draw(t).unwrap()),
                    "rounded" => Box::new(move |t| {
                        let r = eg::RoundedRectangle::with_equal_corners(rect, Size::new(d / 8, d / 8));
                        r.into_styled(fill).draw(t).unwrap()
                    }),
                    "circle" => Box::new(move |t| {
                        eg::Circle::with_center(p(c.0, c.1), d).into_styled(fill).draw(t).unwrap()
                    }),
                    "ellipse" => Box::new(move |t| {
                        eg::Ellipse::with_center(p(c.0, c.1), Size::new(d, d * 2 / 3))
                            .into_styled(fill)
                            .draw(t)
                            .unwrap()
                    }),
                    "arc" => Box::new(move |t| {
                        eg::Arc::with_center(p(c.0, c.1), d, deg(0.5), deg(4.0))
                            .into_styled(stroke)
                            .draw(t)
                            .unwrap()
                    }),
                    "sector" => Box::new(move |t| {
                        eg::Sector::with_center(p(c.0, c.1), d, deg(0.5), deg(4.0))
                            .into_styled(fill)
                            .draw(t)
                            .unwrap()
                    }),
                    "triangle" => {
                        let [a, b, q] = triangle(c, s).map(|(x, y)| p(x, y));
                        Box::new(move |t| eg::Triangle::new(a, b, q).into_styled(fill).draw(t).unwrap())
                    }
                    "line" => {
                        let [a, b] = segment(c, s).map(|(x, y)| p(x, y));
                        Box::new(move |t| eg::Line::new(a, b).into_styled(stroke).draw(t).unwrap())
                    }
                    _ => {
                        let pts = zigzag(c, s).map(|(x, y)| p(x, y));
                        Box::new(move |t| eg::Polyline::new(&pts).into_styled(stroke).draw(t).unwrap())
                    }
                }
            })
            .collect(),
    )
}

/// The same instances as tiny-skia paths (and the stroke, for stroked shapes).
fn skia_shapes(name: &str) -> Vec<(tiny_skia::Path, Option<tiny_skia::Stroke>)> {
    use tiny_skia::{PathBuilder, Stroke};
    let stroke = Stroke { width: STROKE, ..Stroke::default() };
    (0..24)
        .filter_map(|k| {
            let (c, s) = place(k);
            let (x, y, w, h) = bounds(k);
            let rect = tiny_skia::Rect::from_xywh(x, y, w, h)?;
            let arc = |pb: &mut PathBuilder, close_at_centre: bool| {
                let n = 64;
                if close_at_centre {
                    pb.move_to(c.0, c.1);
                }
                for i in 0..=n {
                    let a = 0.5 + 4.0 * i as f32 / n as f32;
                    let q = (c.0 + s / 2.0 * a.cos(), c.1 + s / 2.0 * a.sin());
                    if i == 0 && !close_at_centre { pb.move_to(q.0, q.1) } else { pb.line_to(q.0, q.1) }
                }
            };
            let mut pb = PathBuilder::new();
            let mut stroked = false;
            match name {
                "rect" => pb.push_rect(rect),
                "rounded" => {
                    // tiny-skia 0.12 has no rounded-rect builder: four quarter circles by cubics.
                    let (r, k) = (s / 8.0, 0.552_284_8 * s / 8.0);
                    let (l, t, rr, b) = (rect.left(), rect.top(), rect.right(), rect.bottom());
                    pb.move_to(l + r, t);
                    pb.line_to(rr - r, t);
                    pb.cubic_to(rr - r + k, t, rr, t + r - k, rr, t + r);
                    pb.line_to(rr, b - r);
                    pb.cubic_to(rr, b - r + k, rr - r + k, b, rr - r, b);
                    pb.line_to(l + r, b);
                    pb.cubic_to(l + r - k, b, l, b - r + k, l, b - r);
                    pb.line_to(l, t + r);
                    pb.cubic_to(l, t + r - k, l + r - k, t, l + r, t);
                    pb.close();
                }
                "circle" => pb.push_circle(c.0, c.1, s / 2.0),
                "ellipse" => pb.push_oval(rect),
                "arc" => {
                    arc(&mut pb, false);
                    stroked = true;
                }
                "sector" => {
                    arc(&mut pb, true);
                    pb.close();
                }
                "polygon" | "triangle" => {
                    let st = if name == "polygon" { star(c, s).to_vec() } else { triangle(c, s).to_vec() };
                    pb.move_to(st[0].0, st[0].1);
                    st[1..].iter().for_each(|q| pb.line_to(q.0, q.1));
                    pb.close();
                }
                "line" => {
                    let [a, b] = segment(c, s);
                    pb.move_to(a.0, a.1);
                    pb.line_to(b.0, b.1);
                    stroked = true;
                }
                _ => {
                    let z = zigzag(c, s);
                    pb.move_to(z[0].0, z[0].1);
                    z[1..].iter().for_each(|q| pb.line_to(q.0, q.1));
                    stroked = true;
                }
            }
            Some((pb.finish()?, stroked.then(|| stroke.clone())))
        })
        .collect()
}

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(15)
        .without_plots()
        .configure_from_args()
}

fn run(g: &mut BenchmarkGroup<'_, WallTime>, id: &str, mut f: impl FnMut()) {
    g.bench_function(id, |b| b.iter(&mut f));
}

fn bench_shape(c: &mut Criterion, name: &str) {
    let (mut aliased, aa) = (mr_shapes(name, false), mr_shapes(name, true));
    let mut fb = SliceFb::default();
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let renderer = Renderer::new(H as u32, BG);
    let mut pixmap = tiny_skia::Pixmap::new(W as u32, H as u32).unwrap();
    let mut g = c.benchmark_group(format!("shape_{name}"));
    run(&mut g, "mr_direct", || {
        fb.wipe();
        aliased.iter().for_each(|s| s.direct(&mut fb));
        black_box(&fb.px);
    });
    let mut banded = |set: &[Box<dyn MrDraw>], fb: &mut SliceFb| {
        renderer
            .render(
                from_fn(|v| {
                    set.iter().for_each(|s| s.band(v));
                    Ok(())
                }),
                &mut band,
                fb,
            )
            .unwrap();
        black_box(&fb.px);
    };
    run(&mut g, "mr_band16", || banded(&aliased, &mut fb));
    run(&mut g, "mr_aa_band16", || banded(&aa, &mut fb));
    // The same frame with each shape's edges built once per frame (in the
    // timed loop), then walked band by band: the same pixels.
    run(&mut g, "mr_band16_prepared", || {
        aliased.iter_mut().for_each(|s| s.prepare());
        renderer
            .render(
                from_fn(|v| {
                    aliased.iter_mut().for_each(|s| s.band_prepared(v));
                    Ok(())
                }),
                &mut band,
                &mut fb,
            )
            .unwrap();
        black_box(&fb.px);
    });
    if let Some(e) = eg_shapes(name) {
        run(&mut g, "eg", || {
            fb.wipe();
            e.iter().for_each(|d| d(&mut fb));
            black_box(&fb.px);
        });
    }
    let paths = skia_shapes(name);
    for (id, aa) in [("skia", false), ("skia_aa", true)] {
        let mut paint = tiny_skia::Paint::default();
        paint.set_color_rgba8(255, 160, 64, 255);
        paint.anti_alias = aa;
        run(&mut g, id, || {
            pixmap.fill(tiny_skia::Color::BLACK);
            for (p, st) in &paths {
                match st {
                    Some(st) => pixmap.stroke_path(p, &paint, st, tiny_skia::Transform::identity(), None),
                    None => pixmap.fill_path(
                        p,
                        &paint,
                        tiny_skia::FillRule::Winding,
                        tiny_skia::Transform::identity(),
                        None,
                    ),
                }
            }
            black_box(pixmap.data());
        });
    }
    g.finish();
}

/// The dashboard frame (`examples/common/dashboard.rs`): microraster in
/// 16-row bands against the plain e-g version into the same framebuffer.
fn bench_dashboard(c: &mut Criterion) {
    let mut fb = SliceFb::default();
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(dashboard::NIGHT));
    let renderer = Renderer::new(H as u32, dashboard::NIGHT);
    let mut g = c.benchmark_group("dashboard");
    run(&mut g, "mr_band16", || {
        renderer.render(from_fn(dashboard::dashboard), &mut band, &mut fb).unwrap();
        black_box(&fb.px);
    });
    run(&mut g, "eg", || {
        dashboard::dashboard_eg(&mut fb).unwrap();
        black_box(&fb.px);
    });
    g.finish();
}

/// What every 16-row frame pays before any shape: the empty frame (each
/// band cleared and sent), against e-g's wipe of the framebuffer.
fn bench_floor(c: &mut Criterion) {
    let mut fb = SliceFb::default();
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let renderer = Renderer::new(H as u32, BG);
    let mut g = c.benchmark_group("floor");
    run(&mut g, "mr_band16", || {
        renderer.render((), &mut band, &mut fb).unwrap();
        black_box(&fb.px);
    });
    run(&mut g, "eg", || {
        fb.wipe();
        black_box(&fb.px);
    });
    g.finish();
}

fn main() {
    let mut c = config();
    for name in SHAPES {
        bench_shape(&mut c, name);
    }
    bench_floor(&mut c);
    bench_dashboard(&mut c);
    c.final_summary();
    ratios();
}

/// Peer / microraster ratios (> 1: microraster faster) and the verdicts.
fn ratios() {
    println!("\nRatios from this run (criterion medians; > 1: microraster is faster)");
    println!(
        "{:<9} {:>10} {:>10} {:>10} {:>10} {:>11} {:>9} {:>9}  verdict (e-g: direct and the faster banded way >= 1.0)",
        "shape", "eg/direct", "eg/band16", "eg/prep16", "skia/band", "skia_aa/aa", "band µs", "aa µs"
    );
    let (mut faster, mut total) = (0, 0);
    for name in SHAPES {
        let g = format!("shape_{name}");
        let m = |id: &str| median(&g, id);
        let r = [
            m("eg").zip(m("mr_direct")),
            m("eg").zip(m("mr_band16")),
            m("skia").zip(m("mr_band16")),
            m("skia_aa").zip(m("mr_aa_band16")),
            m("eg").zip(m("mr_band16_prepared")),
        ]
        .map(|v| v.map(|(p, o)| p / o));
        // The prepared column is shown, not counted; the verdict takes the
        // faster banded way.
        let (r, prepared) = ([r[0], r[1], r[2], r[3]], r[4]);
        let banded = r[1].into_iter().chain(prepared).reduce(f64::max);
        for v in r.iter().flatten() {
            total += 1;
            faster += usize::from(*v >= 1.0);
        }
        let cell = |v: Option<f64>| v.map_or("-".into(), |v| format!("{v:.2}"));
        let worst = [r[0], banded].iter().flatten().fold(f64::INFINITY, |a, &b| a.min(b));
        let verdict = if worst == f64::INFINITY {
            "no e-g shape".into()
        } else if worst >= 1.0 {
            "met".into()
        } else {
            format!("missed by {:.2}x", 1.0 / worst)
        };
        let us = |id: &str| m(id).map_or("-".into(), |t| format!("{:.1}", t / 1000.0));
        println!(
            "{:<9} {:>10} {:>10} {:>10} {:>10} {:>11} {:>9} {:>9}  {verdict}",
            name,
            cell(r[0]),
            cell(r[1]),
            cell(prepared),
            cell(r[2]),
            cell(r[3]),
            us("mr_band16"),
            us("mr_aa_band16")
        );
    }
    println!("verdict: microraster at least as fast in {faster} of {total} comparisons");
    if let Some((e, m)) = median("floor", "eg").zip(median("floor", "mr_band16")) {
        println!(
            "empty frame (the floor of every band16 row): e-g's wipe {:.1} µs, 16-row bands {:.1} µs",
            e / 1e3,
            m / 1e3
        );
    }
    if let Some((e, m)) = median("dashboard", "eg").zip(median("dashboard", "mr_band16")) {
        println!(
            "dashboard frame: e-g {:.0} µs, microraster (16-row bands) {:.0} µs, e-g / microraster {:.2}",
            e / 1e3,
            m / 1e3,
            e / m
        );
    }
}
