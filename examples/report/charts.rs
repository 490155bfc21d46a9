//! PNG charts with plotters' bitmap backend.
//!
//! Fonts: plotters draws text through a font library (`ttf`: font-kit, which
//! needs fontconfig and FreeType on the system; `ab_glyph`: a font file the
//! program must bundle). Neither is needed here: [`MonoText`] wraps the
//! bitmap backend and draws every label with embedded-graphics' built-in
//! bitmap fonts (`mono_font::iso_8859_1`, so µ and × show), which this crate already depends on.
//! plotters keeps only its font-free layout estimate, which [`MonoText`]
//! replaces with the exact size of the bitmap text.

use embedded_graphics::Drawable;
use embedded_graphics::Pixel;
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle, iso_8859_1 as latin1};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Point, Size};
use embedded_graphics::text::{Baseline, Text};
use plotters::prelude::*;
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind};
use std::error::Error;
use std::path::Path;

type Res<T> = Result<T, Box<dyn Error>>;

/// A drawing backend that draws text with embedded-graphics' mono fonts.
pub struct MonoText<B>(pub B);

fn font_for(size: f64) -> &'static MonoFont<'static> {
    if size < 15.0 {
        &latin1::FONT_6X10
    } else if size < 19.0 {
        &latin1::FONT_7X13
    } else {
        &latin1::FONT_9X15
    }
}

/// The lit pixels of `text` in `font`, top-left at the origin.
struct Collect(Vec<(i32, i32)>);

impl OriginDimensions for Collect {
    fn size(&self) -> Size {
        Size::new(4096, 64)
    }
}

impl DrawTarget for Collect {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, px: I) -> Result<(), Self::Error> {
        self.0.extend(px.into_iter().filter(|p| p.1.is_on()).map(|Pixel(p, _)| (p.x, p.y)));
        Ok(())
    }
}

impl<B: DrawingBackend> DrawingBackend for MonoText<B> {
    type ErrorType = B::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }
    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.ensure_prepared()
    }
    fn present(&mut self) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.present()
    }
    fn draw_pixel(&mut self, p: BackendCoord, c: BackendColor) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.draw_pixel(p, c)
    }
    fn draw_line<S: BackendStyle>(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        s: &S,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.draw_line(a, b, s)
    }
    fn draw_rect<S: BackendStyle>(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        s: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.draw_rect(a, b, s, fill)
    }
    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        s: &S,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.draw_path(path, s)
    }
    fn draw_circle<S: BackendStyle>(
        &mut self,
        c: BackendCoord,
        r: u32,
        s: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.draw_circle(c, r, s, fill)
    }
    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        s: &S,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.fill_polygon(vert, s)
    }
    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.0.blit_bitmap(pos, size, src)
    }

    fn estimate_text_size<T: BackendTextStyle>(
        &self,
        text: &str,
        style: &T,
    ) -> Result<(u32, u32), DrawingErrorKind<B::ErrorType>> {
        let f = font_for(style.size());
        Ok((text.chars().count() as u32 * f.character_size.width, f.character_size.height))
    }

    fn draw_text<T: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &T,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let f = font_for(style.size());
        let mut lit = Collect(Vec::new());
        let _ =
            Text::with_baseline(text, Point::zero(), MonoTextStyle::new(f, BinaryColor::On), Baseline::Top)
                .draw(&mut lit);
        let (w, h) =
            (text.chars().count() as i32 * f.character_size.width as i32, f.character_size.height as i32);
        let dx = match style.anchor().h_pos {
            HPos::Left => 0,
            HPos::Right => -w,
            HPos::Center => -w / 2,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0,
            VPos::Center => -h / 2,
            VPos::Bottom => -h,
        };
        let trans = style.transform();
        let color = style.color();
        let (sw, sh) = self.get_size();
        for (x, y) in lit.0 {
            let (x, y) = trans.transform(x + dx, y + dy);
            let (x, y) = (pos.0 + x, pos.1 + y);
            if x >= 0 && y >= 0 && x < sw as i32 && y < sh as i32 {
                self.0.draw_pixel((x, y), color)?;
            }
        }
        Ok(())
    }
}

/// Draws with `draw` into a `w × h` RGB canvas and writes it as a PNG.
fn save(path: &Path, (w, h): (u32, u32), draw: impl FnOnce(&mut [u8]) -> Res<()>) -> Res<()> {
    let mut buf = vec![255u8; (w * h * 3) as usize];
    draw(&mut buf)?;
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.write_header()?.write_image_data(&buf)?;
    Ok(())
}

/// One point of a speed/error chart.
#[derive(Clone, Debug)]
pub struct Point2 {
    /// Label drawn next to the point.
    pub label: String,
    /// Cost (x).
    pub x: f64,
    /// Error (y).
    pub y: f64,
}

/// Indices of the points no other point beats in both cost and error (ties
/// kept), sorted by cost.
pub fn pareto(points: &[Point2]) -> Vec<usize> {
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| {
            !points
                .iter()
                .any(|q| q.x <= points[i].x && q.y <= points[i].y && (q.x < points[i].x || q.y < points[i].y))
        })
        .collect();
    front.sort_by(|&a, &b| points[a].x.total_cmp(&points[b].x));
    front
}

/// Speed against error for one knob: every setting as a labelled point, the
/// Pareto front joined by a line.
pub fn pareto_chart(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    points: &[Point2],
    log_y: bool,
) -> Res<()> {
    save(path, (760, 480), |buf| {
        let root = MonoText(BitMapBackend::with_buffer(buf, (760, 480))).into_drawing_area();
        root.fill(&WHITE)?;
        let (x0, x1) = bounds(points.iter().map(|p| p.x), false);
        let (y0, y1) = bounds(points.iter().map(|p| p.y), true);
        let front = pareto(points);
        let blue = RGBColor(30, 90, 200);
        let mut b = ChartBuilder::on(&root);
        b.caption(title, ("sans-serif", 20)).margin(16).x_label_area_size(40).y_label_area_size(80);
        macro_rules! draw {
            ($chart:expr) => {{
                let mut chart = $chart;
                chart
                    .configure_mesh()
                    .x_desc(x_label)
                    .y_desc(y_label)
                    .x_label_formatter(&|v| short(*v))
                    .y_label_formatter(&|v| short(*v))
                    .draw()?;
                chart.draw_series(LineSeries::new(
                    front.iter().map(|&i| (points[i].x, points[i].y)),
                    Color::stroke_width(&blue, 2),
                ))?;
                for (i, p) in points.iter().enumerate() {
                    let c = if front.contains(&i) { blue } else { RGBColor(150, 150, 150) };
                    chart.draw_series(std::iter::once(Circle::new((p.x, p.y), 5, c.filled())))?;
                    chart.draw_series(std::iter::once(plotters::element::Text::new(
                        p.label.clone(),
                        (p.x, p.y),
                        ("sans-serif", 12)
                            .into_font()
                            .color(&BLACK)
                            .pos(plotters::style::text_anchor::Pos::new(HPos::Left, VPos::Bottom)),
                    )))?;
                }
            }};
        }
        if log_y {
            let lo = points.iter().map(|p| p.y).filter(|&y| y > 0.0).fold(f64::INFINITY, f64::min);
            draw!(b.build_cartesian_2d(x0..x1, (lo / 2.0..y1 * 2.0).log_scale())?);
        } else {
            draw!(b.build_cartesian_2d(x0..x1, y0..y1)?);
        }
        root.present()?;
        Ok(())
    })
}

/// Horizontal bars, one per `(label, value)`, with the value printed.
pub fn bar_chart(
    path: &Path,
    title: &str,
    x_label: &str,
    bars: &[(String, f64)],
    log: bool,
    mark: Option<f64>,
) -> Res<()> {
    let h = 90 + 22 * bars.len() as u32;
    save(path, (940, h), |buf| {
        let root = MonoText(BitMapBackend::with_buffer(buf, (940, h))).into_drawing_area();
        root.fill(&WHITE)?;
        let max = bars.iter().map(|b| b.1).fold(0.0, f64::max) * 1.25;
        let min = bars.iter().map(|b| b.1).fold(f64::INFINITY, f64::min);
        let n = bars.len() as f64;
        let labels: Vec<String> = bars.iter().map(|b| b.0.clone()).collect();
        let fmt = move |v: &f64| {
            let i = (n - 1.0 - v.round()) as isize;
            if (v - v.round()).abs() < 0.01 && i >= 0 && (i as usize) < labels.len() {
                labels[i as usize].clone()
            } else {
                String::new()
            }
        };
        let mut b = ChartBuilder::on(&root);
        b.caption(title, ("sans-serif", 20)).margin(12).x_label_area_size(36).y_label_area_size(340);
        let blue = RGBColor(30, 90, 200);
        macro_rules! draw {
            ($chart:expr, $x0:expr) => {{
                let mut chart = $chart;
                chart
                    .configure_mesh()
                    .disable_y_mesh()
                    .y_labels(bars.len() * 2 + 1)
                    .y_label_formatter(&fmt)
                    .x_label_formatter(&|v| short(*v))
                    .x_desc(x_label)
                    .draw()?;
                if let Some(m) = mark {
                    let red = RGBColor(200, 30, 30);
                    chart.draw_series(LineSeries::new(
                        [(m, -0.6), (m, n - 0.4)],
                        Color::stroke_width(&red, 2),
                    ))?;
                }
                for (i, (_, v)) in bars.iter().enumerate() {
                    let y = n - 1.0 - i as f64;
                    chart.draw_series(std::iter::once(Rectangle::new(
                        [($x0, y - 0.35), (*v, y + 0.35)],
                        blue.filled(),
                    )))?;
                    chart.draw_series(std::iter::once(plotters::element::Text::new(
                        short(*v),
                        (*v, y),
                        ("sans-serif", 12)
                            .into_font()
                            .color(&BLACK)
                            .pos(plotters::style::text_anchor::Pos::new(HPos::Left, VPos::Center)),
                    )))?;
                }
            }};
        }
        if log {
            let x0 = min / 2.0;
            draw!(b.build_cartesian_2d((x0..max * 2.0).log_scale(), -0.6..n - 0.4)?, x0);
        } else {
            draw!(b.build_cartesian_2d(0.0..max, -0.6..n - 0.4)?, 0.0);
        }
        root.present()?;
        Ok(())
    })
}

fn bounds(v: impl Iterator<Item = f64> + Clone, from_zero: bool) -> (f64, f64) {
    let hi = v.clone().fold(f64::NEG_INFINITY, f64::max);
    let lo = v.fold(f64::INFINITY, f64::min);
    let span = (hi - lo).max(hi.abs() * 0.1).max(1e-9);
    let lo = if from_zero && lo >= 0.0 { 0.0 } else { lo - span * 0.1 };
    (lo, hi + span * 0.25)
}

/// A number in at most 4 significant digits, with k/M suffixes.
pub fn short(v: f64) -> String {
    let a = v.abs();
    if a >= 1e6 {
        format!("{:.3}M", v / 1e6)
    } else if a >= 1e4 {
        format!("{:.1}k", v / 1e3)
    } else if a >= 100.0 {
        format!("{v:.0}")
    } else if a >= 1.0 {
        format!("{v:.2}")
    } else if a == 0.0 {
        "0".into()
    } else if a >= 0.001 {
        format!("{v:.4}")
    } else {
        format!("{v:.1e}")
    }
}
