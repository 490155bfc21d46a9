//! Host simulator: renders the standard scenes (`microraster_scenes::scenes` and,
//! in [`scene3d`], `microraster_scenes::scenes3d`) with the band renderer into an
//! in-memory display and writes them as PNGs.
//!
//! ```text
//! cargo run --example demo [-- <out_dir>]     # default out/ (this package: scenes/)
//! ```

use embedded_graphics::mono_font::{MonoTextStyleBuilder, ascii::FONT_6X10};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line as EgLine, Primitive as _, PrimitiveStyle, Rectangle};
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};
use microraster::{Band, Primitive, Renderer, SubPoint};
use microraster_scenes::scenes;
use std::convert::Infallible;
use std::error::Error;
use std::path::{Path, PathBuf};

mod dashboard;
mod fragment;
mod knot;
mod knot_tiers;
mod scene3d;

/// Subpixel bits: 1/16 px.
const S: u32 = 4;
type Prim = Primitive<Rgb888, S>;
type Result<T> = std::result::Result<T, Box<dyn Error>>;

const BLACK: Rgb888 = Rgb888::BLACK;
const WHITE: Rgb888 = Rgb888::WHITE;
const GRID: Rgb888 = Rgb888::new(70, 70, 70);

fn main() -> Result<()> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;

    // Fill rule: 30 × 16 px, each pixel a 24 × 24 block.
    let (small, scene) = render::<30, 16>(scenes::fill_rule, 16)?;
    let mut big = magnify(&small, 24, Some(GRID));
    overlay_fill_rule(&mut big, &scene, 24)?;
    let big = with_caption(
        &big,
        &[
            "Each dot is a pixel centre; a pixel takes the colour of the one triangle",
            "covering its centre. Ringed dots lie exactly on an edge (ties): top-left rule.",
        ],
    )?;
    save(&big, &out.join("fill_rule.png"))?;

    let (gouraud, _) = render::<320, 16>(scenes::gouraud, 240)?;
    save(&gouraud, &out.join("gouraud.png"))?;

    let (fan, _) = render::<96, 16>(scenes::line_fan, 96)?;
    save(&magnify(&fan, 5, Some(Rgb888::new(30, 30, 30))), &out.join("line_fan.png"))?;

    let (mixed, _) = render::<320, 60>(scenes::mixed, 240)?;
    save(&mixed, &out.join("mixed.png"))?;

    // Bands: the same scene through a target that records each band's rectangle.
    const BAND_ROWS: usize = 16;
    let scene = collect::<320>(scenes::mixed, 240)?;
    let mut canvas = Canvas::new(320, 240);
    let mut recorder = Recorder { inner: &mut canvas, rects: Vec::new() };
    let mut band = Band::<Rgb888, 320, BAND_ROWS>::new(BLACK);
    Renderer::new(240, BLACK).render(&scene, &mut band, &mut recorder).map_err(|e| e.to_string())?;
    let rects = recorder.rects;
    // The band height must not change the image: compare with mixed.png (60-row bands).
    if canvas.px != mixed.px {
        return Err("16-row bands rendered a different image than 60-row bands".into());
    }
    // Doubled in size so that the labels stay legible.
    let banded = draw_bands(&magnify(&canvas, 2, None), &rects, 2)?;
    save(&banded, &out.join("bands.png"))?;
    let bytes = |px: usize| 320 * px * core::mem::size_of::<Rgb888>();
    println!(
        "  {} bands of up to {BAND_ROWS} rows (same pixels as mixed.png, drawn with 60-row bands)",
        rects.len()
    );
    println!(
        "  one band: {} bytes as Rgb888 ({} as Rgb565); a whole 320×240 Rgb888 frame: {} bytes",
        Band::<Rgb888, 320, BAND_ROWS>::BYTES,
        Band::<Rgb565, 320, BAND_ROWS>::BYTES,
        bytes(240),
    );

    scene3d::run(&out)?;
    knot::run(&out)?;
    knot_tiers::run(&out)?;
    dashboard::run(&out)?;
    fragment::run(&out)
}

/// Runs a scene for a `W × height` frame into a fixed-capacity list.
fn collect<const W: usize>(scene: scenes::Scene<Rgb888, S>, height: u32) -> Result<heapless::Vec<Prim, 128>> {
    let mut prims = heapless::Vec::new();
    match scenes::collect(scene, W as u32, height, &mut prims)? {
        0 => Ok(prims),
        n => Err(format!("{n} primitives did not fit").into()),
    }
}

/// Renders a scene with `H`-row bands; returns the frame and the primitives.
fn render<const W: usize, const H: usize>(
    scene: scenes::Scene<Rgb888, S>,
    height: u32,
) -> Result<(Canvas, heapless::Vec<Prim, 128>)> {
    let prims = collect::<W>(scene, height)?;
    let mut canvas = Canvas::new(W as u32, height);
    let mut band = Band::<Rgb888, W, H>::new(BLACK);
    Renderer::new(height, BLACK).render(&prims, &mut band, &mut canvas).map_err(|e| e.to_string())?;
    Ok((canvas, prims))
}

/// A plain RGB framebuffer: the simulated display.
struct Canvas {
    size: Size,
    px: Vec<Rgb888>,
}

impl Canvas {
    fn new(w: u32, h: u32) -> Self {
        Canvas { size: Size::new(w, h), px: vec![BLACK; (w * h) as usize] }
    }

    fn index(&self, p: Point) -> Option<usize> {
        let (w, h) = (self.size.width as i32, self.size.height as i32);
        ((0..w).contains(&p.x) && (0..h).contains(&p.y)).then(|| (p.y * w + p.x) as usize)
    }

    fn get(&self, p: Point) -> Rgb888 {
        self.index(p).map_or(BLACK, |i| self.px[i])
    }
}

impl OriginDimensions for Canvas {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for Canvas {
    type Color = Rgb888;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
        &mut self,
        pixels: I,
    ) -> std::result::Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if let Some(i) = self.index(p) {
                self.px[i] = c;
            }
        }
        Ok(())
    }
}

/// Forwards to `inner`, remembering the rectangle of every `fill_contiguous`
/// (the renderer sends each band with exactly one).
struct Recorder<'a, D> {
    inner: &'a mut D,
    rects: Vec<Rectangle>,
}

impl<D: Dimensions> Dimensions for Recorder<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.inner.bounding_box()
    }
}

impl<D: DrawTarget> DrawTarget for Recorder<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<D::Color>>>(
        &mut self,
        pixels: I,
    ) -> std::result::Result<(), D::Error> {
        self.inner.draw_iter(pixels)
    }

    fn fill_contiguous<I: IntoIterator<Item = D::Color>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> std::result::Result<(), D::Error> {
        self.rects.push(*area);
        self.inner.fill_contiguous(area, colors)
    }
}

/// Each pixel as an `m × m` block, optionally with a grid line on its top and left.
fn magnify(src: &Canvas, m: u32, grid: Option<Rgb888>) -> Canvas {
    let mut dst = Canvas::new(src.size.width * m, src.size.height * m);
    let m = m as i32;
    for y in 0..dst.size.height as i32 {
        for x in 0..dst.size.width as i32 {
            let c = match grid {
                Some(g) if x % m == 0 || y % m == 0 => g,
                _ => src.get(Point::new(x / m, y / m)),
            };
            let i = (y * dst.size.width as i32 + x) as usize;
            dst.px[i] = c;
        }
    }
    dst
}

/// Draws the triangle edges at their exact snapped positions and a dot on
/// every pixel centre, ringed where the centre lies exactly on an edge.
fn overlay_fill_rule(big: &mut Canvas, scene: &[Prim], m: i32) -> Result<()> {
    let at = |p: SubPoint<S>| Point::new((p.x() * m + 8) >> S, (p.y() * m + 8) >> S);
    let tris: Vec<[SubPoint<S>; 3]> = scene
        .iter()
        .filter_map(|p| if let Primitive::Triangle(t) = p { Some(t.vertices()) } else { None })
        .collect();
    for v in &tris {
        for i in 0..3 {
            EgLine::new(at(v[i]), at(v[(i + 1) % 3]))
                .into_styled(PrimitiveStyle::with_stroke(WHITE, 1))
                .draw(big)?;
        }
    }
    let (w, h) = (big.size.width as i32 / m, big.size.height as i32 / m);
    for y in 0..h {
        for x in 0..w {
            let centre = Point::new(x * m + m / 2, y * m + m / 2);
            let c = big.get(centre + Point::new(2, 2)); // the pixel's own colour, off the edge lines
            let luma = (77 * c.r() as u32 + 150 * c.g() as u32 + 29 * c.b() as u32) >> 8;
            let ink = if luma > 110 { BLACK } else { WHITE };
            let tie = tris
                .iter()
                .any(|v| (0..3).any(|i| on_segment(v[i], v[(i + 1) % 3], (16 * x + 8, 16 * y + 8))));
            if tie {
                Circle::with_center(centre, 13).into_styled(PrimitiveStyle::with_stroke(ink, 2)).draw(big)?;
            }
            Circle::with_center(centre, 5).into_styled(PrimitiveStyle::with_fill(ink)).draw(big)?;
        }
    }
    Ok(())
}

/// True if `p` (1/16 px) lies exactly on the segment `a`–`b`.
fn on_segment(a: SubPoint<S>, b: SubPoint<S>, p: (i32, i32)) -> bool {
    let (ax, ay, bx, by) = (a.x() as i64, a.y() as i64, b.x() as i64, b.y() as i64);
    let (px, py) = (p.0 as i64, p.1 as i64);
    let cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    cross == 0 && px >= ax.min(bx) && px <= ax.max(bx) && py >= ay.min(by) && py <= ay.max(by)
}

/// `img` with lines of text on a strip below it.
fn with_caption(img: &Canvas, lines: &[&str]) -> Result<Canvas> {
    let strip = 12 * lines.len() as u32 + 8;
    let mut out = Canvas::new(img.size.width, img.size.height + strip);
    out.px[..img.px.len()].copy_from_slice(&img.px);
    let style = MonoTextStyleBuilder::new().font(&FONT_6X10).text_color(WHITE).build();
    for (i, line) in lines.iter().enumerate() {
        let y = img.size.height as i32 + 4 + 12 * i as i32;
        Text::with_baseline(line, Point::new(6, y), style, Baseline::Top).draw(&mut out)?;
    }
    Ok(out)
}

/// Tints alternate bands, marks every band's top edge and labels it.
fn draw_bands(img: &Canvas, rects: &[Rectangle], scale: i32) -> Result<Canvas> {
    let mut out = Canvas::new(img.size.width, img.size.height);
    out.px.copy_from_slice(&img.px);
    let tint = Rgb888::new(255, 200, 0);
    let label =
        MonoTextStyleBuilder::new().font(&FONT_6X10).text_color(WHITE).background_color(BLACK).build();
    for (k, r) in rects.iter().enumerate() {
        let (y0, y1) = (r.top_left.y * scale, (r.top_left.y + r.size.height as i32) * scale);
        if k % 2 == 1 {
            for y in y0..y1 {
                for x in 0..out.size.width as i32 {
                    let i = out.index(Point::new(x, y)).ok_or("band outside the image")?;
                    out.px[i] = mix(out.px[i], tint, 70);
                }
            }
        }
        let w = out.size.width as i32;
        EgLine::new(Point::new(0, y0), Point::new(w - 1, y0))
            .into_styled(PrimitiveStyle::with_stroke(tint, 1))
            .draw(&mut out)?;
        let text = format!("band {k}: rows {}..{}", r.top_left.y, r.top_left.y + r.size.height as i32);
        Text::with_baseline(&text, Point::new(w - 6 * text.len() as i32 - 4, y0 + 2), label, Baseline::Top)
            .draw(&mut out)?;
    }
    Ok(out)
}

/// `a` moved `t/255` of the way to `b`.
fn mix(a: Rgb888, b: Rgb888, t: u32) -> Rgb888 {
    let f = |a: u8, b: u8| ((a as u32 * (255 - t) + b as u32 * t) / 255) as u8;
    Rgb888::new(f(a.r(), b.r()), f(a.g(), b.g()), f(a.b(), b.b()))
}

fn save(img: &Canvas, path: &Path) -> Result<()> {
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, img.size.width, img.size.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let data: Vec<u8> = img.px.iter().flat_map(|c| [c.r(), c.g(), c.b()]).collect();
    let mut writer = enc.write_header()?;
    writer.write_image_data(&data)?;
    writer.finish()?;
    let bytes = std::fs::metadata(path)?.len();
    println!("wrote {} ({}×{}, {bytes} bytes)", path.display(), img.size.width, img.size.height);
    Ok(())
}
