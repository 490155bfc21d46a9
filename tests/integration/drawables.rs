//! embedded-graphics drawables drawn into bands (`BandView` and `Band3d` as
//! `DrawTarget`s; `render::from_fn`, `Pass::then`) give
//! the pixels e-g gives drawing the same drawables into a framebuffer of the
//! frame's size, for band heights 1, 3, 16 and the full frame.
//!
//! Reference: [`Clipped`], a plain array framebuffer that implements only
//! `draw_iter` (e-g's default `fill_contiguous`/`fill_solid` turn into
//! pixels), so it shares no clipping code with the band's target.

use crate::framebuffer::Framebuffer;
use embedded_graphics::image::{Image, ImageRaw, ImageRawBE};
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle, MonoTextStyleBuilder, ascii, iso_8859_1};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{
    Arc, Circle, Ellipse, Line, PrimitiveStyle, PrimitiveStyleBuilder, Rectangle, RoundedRectangle,
    StrokeAlignment, Triangle as EgTriangle,
};
use embedded_graphics::text::{Alignment, Baseline, Text, TextStyleBuilder};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::raster3d::PerspectiveCorrect;
use microraster::render::{Direct3d, Pass, Triangles3d, from_fn};
use microraster::{Band, Error, Renderer, SubPoint, Triangle};
use microraster_scenes::scenes3d::{BINS, Scene3d};

const W: usize = 96;
const FH: u32 = 64;
const BG: Rgb565 = Rgb565::new(2, 4, 8);

/// A frame-sized framebuffer that drops pixels outside it, pixel by pixel.
struct Clipped {
    pixels: Vec<Rgb565>,
}

impl Clipped {
    fn new() -> Self {
        Clipped { pixels: vec![BG; W * FH as usize] }
    }
}

impl OriginDimensions for Clipped {
    fn size(&self) -> Size {
        Size::new(W as u32, FH)
    }
}

impl DrawTarget for Clipped {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if (0..W as i32).contains(&p.x) && (0..FH as i32).contains(&p.y) {
                self.pixels[p.y as usize * W + p.x as usize] = c;
            }
        }
        Ok(())
    }
}

const FONTS: [&MonoFont<'static>; 4] =
    [&ascii::FONT_4X6, &ascii::FONT_6X10, &ascii::FONT_10X20, &iso_8859_1::FONT_7X13_BOLD];

/// Text in every font, with and without a background, aligned three ways,
/// several lines, partly off every side of the frame.
fn text<D: DrawTarget<Color = Rgb565>>(d: &mut D, k: usize) -> Result<(), D::Error> {
    let font = FONTS[k % FONTS.len()];
    let plain = MonoTextStyle::new(font, Rgb565::WHITE);
    let boxed = MonoTextStyleBuilder::new()
        .font(font)
        .text_color(Rgb565::YELLOW)
        .background_color(Rgb565::new(0, 20, 10))
        .underline()
        .build();
    let right = TextStyleBuilder::new().alignment(Alignment::Right).baseline(Baseline::Middle).build();
    let centre = TextStyleBuilder::new().alignment(Alignment::Center).baseline(Baseline::Bottom).build();
    let s = (k as i32) * 3;
    Text::new("Speed 88 km/h\nfuel ¼ tank", Point::new(-3 + s, 5), plain).draw(d)?;
    Text::new("ÄBC wrap", Point::new(10, -4 + s), boxed).draw(d)?;
    Text::with_text_style("right\nedge", Point::new(W as i32 + 4, 30), boxed, right).draw(d)?;
    Text::with_text_style("bottom", Point::new(48, FH as i32 + 3 - s), plain, centre).draw(d)?;
    Text::new("x", Point::new(-2000, 20), boxed).draw(d)?; // off the frame entirely
    Ok(())
}

/// An image (big-endian Rgb565 bytes), whole and partly off the frame, and a
/// sub-image.
fn images<D: DrawTarget<Color = Rgb565>>(d: &mut D, k: usize) -> Result<(), D::Error> {
    static BYTES: [u8; 2 * 13 * 7] = {
        let mut b = [0u8; 2 * 13 * 7];
        let mut i = 0;
        while i < b.len() {
            b[i] = (i as u8).wrapping_mul(37) ^ 0x5A;
            i += 1;
        }
        b
    };
    let raw: ImageRawBE<Rgb565> = ImageRaw::new(&BYTES, 13);
    let s = k as i32;
    Image::new(&raw, Point::new(3 + s, 4)).draw(d)?;
    Image::new(&raw, Point::new(-5, FH as i32 - 4 + s)).draw(d)?;
    Image::new(&raw, Point::new(W as i32 - 6, -3 - s)).draw(d)?;
    let sub = raw.sub_image(&Rectangle::new(Point::new(2, 1), Size::new(8, 5)));
    Image::new(&sub, Point::new(40, 20 + s)).draw(d)?;
    Ok(())
}

/// Styled primitives: fills, strokes of every alignment, thick lines.
fn shapes<D: DrawTarget<Color = Rgb565>>(d: &mut D, k: usize) -> Result<(), D::Error> {
    let s = k as i32 * 2;
    let align = [StrokeAlignment::Inside, StrokeAlignment::Center, StrokeAlignment::Outside][k % 3];
    let both = PrimitiveStyleBuilder::new()
        .fill_color(Rgb565::RED)
        .stroke_color(Rgb565::GREEN)
        .stroke_width(3)
        .stroke_alignment(align)
        .build();
    let thick = PrimitiveStyle::with_stroke(Rgb565::CYAN, 1 + k as u32);
    Circle::new(Point::new(-6 + s, 10), 23).into_styled(both).draw(d)?;
    Rectangle::new(Point::new(30, -4 + s), Size::new(20, 15)).into_styled(both).draw(d)?;
    RoundedRectangle::with_equal_corners(
        Rectangle::new(Point::new(55, 40 - s), Size::new(45, 30)),
        Size::new(8, 6),
    )
    .into_styled(both)
    .draw(d)?;
    Ellipse::new(Point::new(10, 40), Size::new(30, 17)).into_styled(thick).draw(d)?;
    Arc::new(Point::new(60, 5), 28, 30.0.deg(), 250.0.deg()).into_styled(thick).draw(d)?;
    Line::new(Point::new(-10, 70), Point::new(100, -8 + s)).into_styled(thick).draw(d)?;
    EgTriangle::new(Point::new(70, 10), Point::new(90, 60), Point::new(40, 58 - s))
        .into_styled(PrimitiveStyle::with_fill(Rgb565::MAGENTA))
        .draw(d)?;
    d.fill_solid(&Rectangle::new(Point::new(80, 50), Size::new(40, 40)), Rgb565::BLUE)?;
    Ok(())
}

fn all<D: DrawTarget<Color = Rgb565>>(d: &mut D, k: usize) -> Result<(), D::Error> {
    shapes(d, k)?;
    images(d, k)?;
    text(d, k)
}

/// A scene drawable into any target (a generic `fn` cannot become one
/// function pointer for every band's lifetime).
trait Scene {
    fn draw<D: DrawTarget<Color = Rgb565>>(d: &mut D, k: usize) -> Result<(), D::Error>;
}

macro_rules! scene {
    ($name:ident, $f:ident) => {
        struct $name;
        impl Scene for $name {
            fn draw<D: DrawTarget<Color = Rgb565>>(d: &mut D, k: usize) -> Result<(), D::Error> {
                $f(d, k)
            }
        }
    };
}
scene!(TextScene, text);
scene!(ImageScene, images);
scene!(ShapeScene, shapes);
scene!(AllScene, all);

fn reference<S: Scene>(k: usize) -> Vec<Rgb565> {
    let mut fb = Clipped::new();
    S::draw(&mut fb, k).unwrap();
    fb.pixels
}

/// The frame through bands of `H` rows; also checks the band loop sent every
/// pixel once.
fn banded<S: Scene, const H: usize>(k: usize) -> Vec<Rgb565> {
    let mut band = Band::<Rgb565, W, H>::new(Rgb565::BLACK);
    let mut fb = Framebuffer::new(W as u32, FH, Rgb565::BLACK);
    Renderer::new(FH, BG).render(from_fn(|view| Ok(S::draw(view, k)?)), &mut band, &mut fb).unwrap();
    assert!(fb.writes.iter().all(|&n| n == 1));
    fb.pixels
}

fn check<S: Scene>(name: &str) {
    for k in 0..6 {
        let want = reference::<S>(k);
        // The scene must draw something on the frame for the test to mean anything.
        assert!(want.iter().filter(|&&c| c != BG).count() > 100, "{name} {k}: too little drawn");
        assert_eq!(banded::<S, 1>(k), want, "{name} {k}: 1-row bands");
        assert_eq!(banded::<S, 3>(k), want, "{name} {k}: 3-row bands");
        assert_eq!(banded::<S, 16>(k), want, "{name} {k}: 16-row bands");
        assert_eq!(banded::<S, { FH as usize }>(k), want, "{name} {k}: one band");
    }
}

#[test]
fn text_matches_eg_into_a_framebuffer() {
    check::<TextScene>("text");
}

#[test]
fn images_match_eg_into_a_framebuffer() {
    check::<ImageScene>("images");
}

#[test]
fn styled_primitives_match_eg_into_a_framebuffer() {
    check::<ShapeScene>("shapes");
    check::<AllScene>("all");
}

#[test]
fn triangles_and_text_in_one_pass() {
    // Reference: microraster's scene rendered alone, then e-g's text over it.
    let p = |x, y| SubPoint::<4>::from_f32(x, y).unwrap();
    let tris = [
        Triangle::flat([p(-3.2, 2.5), p(70.1, 9.7), p(20.3, 61.9)], Rgb565::RED),
        Triangle::flat([p(90.0, 0.0), p(95.9, 63.4), p(40.6, 30.2)], Rgb565::GREEN),
    ];
    let scene = tris.map(microraster::Primitive::from);
    for k in 0..4 {
        let mut want = Framebuffer::new(W as u32, FH, Rgb565::BLACK);
        let mut band = Band::<Rgb565, W, 7>::new(BG);
        Renderer::new(FH, BG).render(&scene, &mut band, &mut want).unwrap();
        let mut want = Clipped { pixels: want.pixels };
        text(&mut want, k).unwrap();

        let mut fb = Framebuffer::new(W as u32, FH, Rgb565::BLACK);
        Renderer::new(FH, BG)
            .render(
                from_fn(|view| {
                    for t in &tris {
                        t.draw(view, Cull::None);
                    }
                    Ok(text(view, k)?)
                }),
                &mut band,
                &mut fb,
            )
            .unwrap();
        assert_eq!(fb.pixels, want.pixels, "font {k}");
    }
}

#[test]
fn drawables_follow_the_frame_offset() {
    // The frame at (7, 5) on a larger target: drawables stay in frame coordinates.
    let (ox, oy) = (7usize, 5usize);
    let mut fb = Framebuffer::new(W as u32 + 20, FH + 10, Rgb565::BLACK);
    let mut band = Band::<Rgb565, W, 5>::new(BG);
    Renderer::new(FH, BG)
        .with_offset(Point::new(ox as i32, oy as i32))
        .render(from_fn(|view| Ok(all(view, 1)?)), &mut band, &mut fb)
        .unwrap();
    let want = reference::<AllScene>(1);
    for y in 0..FH as usize {
        let row = &fb.pixels[(y + oy) * (W + 20) + ox..][..W];
        assert_eq!(row, &want[y * W..][..W], "row {y}");
    }
}

#[test]
fn closure_errors_are_returned_and_bands_still_sent() {
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let mut fb = Framebuffer::new(W as u32, FH, Rgb565::BLACK);
    let mut calls = 0;
    let r = Renderer::new(FH, BG).render(
        from_fn(|_| {
            calls += 1;
            Err(Error::InvalidParameter(microraster::Param::User))
        }),
        &mut band,
        &mut fb,
    );
    assert_eq!(r, Err(microraster::RenderError::Input(Error::InvalidParameter(microraster::Param::User))));
    assert_eq!(calls, 1, "no call after the first error");
    assert!(fb.writes.iter().all(|&n| n == 1) && fb.pixels.iter().all(|&c| c == BG));
    // A bad frame height is an error before anything is drawn.
    let r = Renderer::new(0, BG).render(from_fn(|_| Ok(())), &mut band, &mut fb);
    assert_eq!(r, Err(microraster::RenderError::Input(Error::InvalidFrameSize)));
}

#[test]
fn extreme_rectangles_are_clipped_without_overflow() {
    let mut band = Band::<Rgb565, W, 4>::new(BG);
    let mut view = band.view(30, 4, BG);
    let huge = Rectangle::new(Point::new(i32::MIN, i32::MIN), Size::new(u32::MAX, u32::MAX));
    view.fill_solid(&huge, Rgb565::RED).unwrap();
    assert!(band.rows().iter().flatten().all(|&c| c == Rgb565::RED));
    // Far corner beyond i32, a short colour iterator: no panic, rows it reaches drawn.
    let mut view = band.view(30, 4, BG);
    let far = Rectangle::new(Point::new(i32::MAX - 1, i32::MAX - 1), Size::new(u32::MAX, 3));
    view.fill_contiguous(&far, core::iter::repeat_n(Rgb565::RED, 10)).unwrap();
    view.fill_solid(&far, Rgb565::RED).unwrap();
    assert!(band.rows().iter().flatten().all(|&c| c == BG));
    // An area starting left of and above the band, with too few colours for it.
    let mut view = band.view(30, 4, BG);
    let area = Rectangle::new(Point::new(-2, 29), Size::new(5, 3));
    view.fill_contiguous(&area, (0..12u16).map(|i| Rgb565::new(i as u8, 0, 0))).unwrap();
    // Colour i sits at (i % 5 − 2, 29 + i / 5): row 29 is above the band,
    // row 30 gets 7, 8, 9 in columns 0..3, row 31 runs out of colours at x = −1.
    let red = |i: u8| Rgb565::new(i, 0, 0);
    let r = band.rows();
    assert_eq!(r[0][..4], [red(7), red(8), red(9), BG]);
    assert_eq!(r[1][..4], [BG; 4]);
}

/// The standard 3D scene's triangles at `angle`, and its frame through
/// `Triangles3d` alone.
fn scene3d(angle: f32) -> (heapless::Vec<microraster::raster3d::ScreenTriangle<4>, BINS>, Vec<Rgb565>) {
    let pipeline = Scene3d::pipeline::<f32, 4>(W as u32, FH).unwrap();
    let mut bins = heapless::Vec::new();
    Scene3d.draw::<f32, Rgb565, 4, BINS>(&pipeline, angle, &mut bins).unwrap();
    let mut fb = Framebuffer::new(W as u32, FH, Rgb565::BLACK);
    let (mut band, mut depth) = (Band::<Rgb565, W, 8>::new(BG), DepthBand::<Depth16, W, 8>::new());
    Renderer::new(FH, BG)
        .render(
            Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            &mut fb,
        )
        .unwrap();
    (bins, fb.pixels)
}

/// The HUD over the 3D frame (reference) against `Pass::then` and
/// `Direct3d` with the HUD drawn into its `Band3d`, for `H`-row bands.
/// The depth band starts full of garbage: the renderer must clear it.
fn hud_over_3d<const H: usize>(angle: f32, k: usize) {
    let (bins, frame) = scene3d(angle);
    assert!(frame.iter().filter(|&&c| c != BG).count() > 500, "the 3D scene is on screen");
    let mut want = Clipped { pixels: frame };
    all(&mut want, k).unwrap();

    let garbage = || {
        let mut d = DepthBand::<Depth16, W, H>::new();
        d.rows_mut(H).iter_mut().flatten().for_each(|z| *z = 1);
        d
    };
    let mut band = Band::<Rgb565, W, H>::new(Rgb565::BLACK);
    let (mut fb, mut depth) = (Framebuffer::new(W as u32, FH, Rgb565::BLACK), garbage());
    Renderer::new(FH, BG)
        .render(
            Triangles3d::new(&bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect)
                .then(|hud| Ok(all(hud, k)?)),
            &mut band,
            &mut fb,
        )
        .unwrap();
    assert!(fb.writes.iter().all(|&n| n == 1));
    assert_eq!(fb.pixels, want.pixels, "Triangles3d.then(HUD), {H}-row bands, angle {angle}");

    let (mut fb, mut depth) = (Framebuffer::new(W as u32, FH, Rgb565::BLACK), garbage());
    Renderer::new(FH, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |b| {
                b.draw_all(&bins);
                Ok(all(b, k)?)
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    assert_eq!(fb.pixels, want.pixels, "Direct3d + Band3d HUD, {H}-row bands, angle {angle}");
}

#[test]
fn hud_over_3d_matches_hud_drawn_on_the_3d_frame() {
    for (i, k) in [(0, 0), (1, 1), (2, 3)] {
        let angle = i as f32 * 1.3;
        hud_over_3d::<1>(angle, k);
        hud_over_3d::<3>(angle, k);
        hud_over_3d::<16>(angle, k);
        hud_over_3d::<{ FH as usize }>(angle, k);
    }
}

#[test]
fn drawables_under_3d_are_covered_by_it() {
    // A backdrop drawn into the Band3d before the meshes: the meshes cover it
    // wherever they are (the backdrop writes no depth), the rest is backdrop.
    let (bins, frame) = scene3d(0.7);
    let backdrop = Rgb565::new(9, 9, 9);
    let mut band = Band::<Rgb565, W, 16>::new(BG);
    let (mut fb, mut depth) =
        (Framebuffer::new(W as u32, FH, Rgb565::BLACK), DepthBand::<Depth16, W, 16>::new());
    Renderer::new(FH, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, PerspectiveCorrect, |b| {
                b.clear(backdrop)?;
                b.draw_all(&bins);
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    for (got, want) in fb.pixels.iter().zip(&frame) {
        assert_eq!(*got, if *want == BG { backdrop } else { *want });
    }
}
