//! The 320 × 240 car dashboard of issue 14, twice: [`dashboard`] with
//! microraster's shape kit (gradients, anti-aliasing, a translucent panel,
//! an alpha sprite) drawn into each band, and [`dashboard_eg`], the same
//! screen in plain `embedded-graphics` (solid, aliased, opaque) into any
//! `DrawTarget`. Shared word for word (`#[path]`) by the demo
//! (`dashboard.png`), the tests, the criterion bench and the Cortex-M4F
//! firmware bench: `no_std`, no allocation.
//!
//! The code between each `dashboard:*:begin` / `end` marker pair is what the
//! README shows and what `cargo run --example readme_2d` counts; what
//! lies outside (colours, the icon, the gauge's geometry) both use.

use core::f32::consts::PI;
use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10, ascii::FONT_10X20};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{self as eg, PrimitiveStyle, PrimitiveStyleBuilder};
use embedded_graphics::text::{Alignment, Text};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Error;
use microraster::band::BandView;
use microraster::math::Scalar;
use microraster::shape::{Arc, Circle, LinearGradient, Polygon, Polyline, RadialGradient, Rect};
use microraster::shape::{RoundedRect, Shape, ShapeStyle};
use microraster::texture::{A8, Bilinear, Sprite, Texture};

/// Frame width.
pub const W: usize = 320;
/// Frame height.
pub const H: u32 = 240;
/// The speed the needle shows (km/h).
pub const SPEED: f32 = 88.0;
/// Background (top of microraster's gradient; e-g's solid fill).
pub const NIGHT: Rgb565 = Rgb565::new(3, 8, 11);
/// Bottom of the background gradient.
pub const DEEP: Rgb565 = Rgb565::new(0, 1, 2);
/// Low end of the gauge ring.
pub const GREEN: Rgb565 = Rgb565::new(4, 52, 10);
/// High end of the gauge ring.
pub const RED: Rgb565 = Rgb565::new(31, 10, 4);
/// Ticks and the needle hub.
pub const WHITE: Rgb565 = Rgb565::new(31, 63, 31);
/// Text: a colour nothing else in either screen has, so tests can find
/// the glyph pixels.
pub const TEXT: Rgb565 = Rgb565::new(26, 58, 31);
/// The needle.
pub const NEEDLE: Rgb565 = Rgb565::new(31, 20, 0);
/// The side panel and its outline.
pub const PANEL: Rgb565 = Rgb565::new(2, 14, 16);
/// The panel's outline.
pub const CYAN: Rgb565 = Rgb565::new(6, 50, 28);
/// The fuel icon's tint.
pub const AMBER: [u8; 3] = [255, 176, 0];
/// The gauge's centre (px).
pub const C: (f32, f32) = (124.0, 124.0);
/// Gauge labels, every 40 km/h from 0 to 240.
pub const LABELS: [&str; 7] = ["0", "40", "80", "120", "160", "200", "240"];

/// The angle of `kmh` on the gauge: 0 at the lower left, 240 at the lower
/// right, 270° clockwise (radians, 0 along +x, clockwise on screen).
pub fn angle(kmh: f32) -> f32 {
    0.75 * PI + 1.5 * PI * kmh / 240.0
}

/// The point `r` px from the centre at `angle` radians.
pub fn polar(r: f32, angle: f32) -> (f32, f32) {
    // The library's sine (not std's): the same bits on the host and on Cortex-M.
    let (s, c) = Scalar::sin_cos(angle);
    (C.0 + r * c, C.1 + r * s)
}

/// [`polar`] rounded to a pixel, for e-g and for text.
pub fn pixel(r: f32, angle: f32) -> Point {
    let (x, y) = polar(r, angle);
    Point::new((x + 0.5) as i32, (y + 0.5) as i32)
}

/// A fuel pump, 12 × 12: `#` opaque, `+` half, else clear.
const fn mask(rows: [&[u8; 12]; 12]) -> [[u8; 12]; 12] {
    let mut out = [[0; 12]; 12];
    let mut i = 0;
    while i < 144 {
        out[i / 12][i % 12] = match rows[i / 12][i % 12] {
            b'#' => 255,
            b'+' => 128,
            _ => 0,
        };
        i += 1;
    }
    out
}

/// The icon's alpha.
pub static FUEL_MASK: [[u8; 12]; 12] = mask([
    b" ######+    ",
    b" #    #  #+ ",
    b" #    #   # ",
    b" ######## # ",
    b" ###### # # ",
    b" ###### # # ",
    b" ###### # # ",
    b" ######  +# ",
    b" ######     ",
    b" ######     ",
    b"########    ",
    b"########    ",
]);
/// The icon as an 8-bit alpha texture.
pub static FUEL: Texture<'static, A8> = Texture::from_rows(&FUEL_MASK);

// dashboard:mr:begin
/// The dashboard with microraster's shapes, into one band (any height).
pub fn dashboard_showing<const N: usize>(
    view: &mut BandView<'_, Rgb565, N>,
    kmh: f32,
    readout: &str,
) -> Result<(), Error> {
    let sky = LinearGradient::new((0.0, 0.0), (0.0, 240.0), [NIGHT, DEEP])?;
    Rect::new(0.0, 0.0, 320.0, 240.0)?.styled(ShapeStyle::fill(sky))?.draw_on(view);
    let zones = LinearGradient::new((40.0, 0.0), (210.0, 0.0), [GREEN, RED])?;
    let ring = ShapeStyle::stroke(zones, 10.0).antialiased();
    Arc::new(C, 100.0, angle(0.0), angle(240.0) - angle(0.0))?.styled(ring)?.draw_on(view);
    let text = MonoTextStyle::new(&FONT_6X10, TEXT);
    for k in 0..=24 {
        let (a, major) = (angle(10.0 * k as f32), k % 4 == 0);
        let tick = [polar(if major { 78.0 } else { 84.0 }, a), polar(92.0, a)];
        let pen = ShapeStyle::stroke(WHITE, if major { 3.0 } else { 1.5 }).antialiased();
        Polyline::new(&tick)?.styled(pen)?.draw_on(view);
        if major {
            let at = pixel(64.0, a) + Point::new(0, 4);
            view.draw_visible(&Text::with_alignment(LABELS[k / 4], at, text, Alignment::Center))?;
        }
    }
    let a = angle(kmh);
    let needle = [polar(90.0, a), polar(5.0, a + PI / 2.0), polar(16.0, a + PI), polar(5.0, a - PI / 2.0)];
    Polygon::new(&needle)?.styled(ShapeStyle::fill(NEEDLE).antialiased())?.draw_on(view);
    let hub = RadialGradient::new((C.0 - 3.0, C.1 - 3.0), 12.0, [WHITE, DEEP])?;
    Circle::new(C, 10.0)?.styled(ShapeStyle::fill(hub).antialiased())?.draw_on(view);
    let glass = ShapeStyle::fill(PANEL).with_stroke(CYAN, 1.5).with_opacity(180).antialiased();
    RoundedRect::new(Rect::new(200.0, 40.0, 108.0, 160.0)?, 10.0)?.styled(glass)?.draw_on(view);
    Sprite::new(&FUEL).at(Point::new(216, 58)).scale(2.0).filter(Bilinear).tint(AMBER).blend_into(view)?;
    view.draw_visible(&Text::new("FUEL 62%", Point::new(248, 74), text))?;
    view.draw_visible(&Text::new("ODO 12840", Point::new(216, 110), text))?;
    view.draw_visible(&Text::new("21.5 C", Point::new(216, 130), text))?;
    let big = MonoTextStyle::new(&FONT_10X20, TEXT);
    view.draw_visible(&Text::with_alignment(readout, Point::new(124, 178), big, Alignment::Center))?;
    view.draw_visible(&Text::with_alignment("km/h", Point::new(124, 192), text, Alignment::Center))?;
    Ok(())
}
// dashboard:mr:end

/// The dashboard at [`SPEED`], reading "88" (the README's screen, the
/// benches' and the firmware's frame).
pub fn dashboard<const N: usize>(view: &mut BandView<'_, Rgb565, N>) -> Result<(), Error> {
    dashboard_showing(view, SPEED, "88")
}

// dashboard:eg:begin
/// The same dashboard in plain embedded-graphics, into any `DrawTarget`.
pub fn dashboard_eg_showing<D: DrawTarget<Color = Rgb565>>(
    d: &mut D,
    kmh: f32,
    readout: &str,
) -> Result<(), D::Error> {
    d.clear(NIGHT)?;
    let deg = |a: f32| Angle::from_radians(a);
    let ring = PrimitiveStyle::with_stroke(GREEN, 10);
    let sweep = angle(240.0) - angle(0.0);
    eg::Arc::with_center(pixel(0.0, 0.0), 200, deg(angle(0.0)), deg(sweep)).into_styled(ring).draw(d)?;
    let text = MonoTextStyle::new(&FONT_6X10, TEXT);
    for k in 0..=24 {
        let (a, major) = (angle(10.0 * k as f32), k % 4 == 0);
        let tick = eg::Line::new(pixel(if major { 78.0 } else { 84.0 }, a), pixel(92.0, a));
        tick.into_styled(PrimitiveStyle::with_stroke(WHITE, if major { 3 } else { 1 })).draw(d)?;
        if major {
            let at = pixel(64.0, a) + Point::new(0, 4);
            Text::with_alignment(LABELS[k / 4], at, text, Alignment::Center).draw(d)?;
        }
    }
    let a = angle(kmh);
    let needle = PrimitiveStyle::with_fill(NEEDLE);
    let (tip, back) = (pixel(90.0, a), pixel(16.0, a + PI));
    eg::Triangle::new(tip, pixel(5.0, a + PI / 2.0), back).into_styled(needle).draw(d)?;
    eg::Triangle::new(tip, pixel(5.0, a - PI / 2.0), back).into_styled(needle).draw(d)?;
    eg::Circle::with_center(pixel(0.0, 0.0), 21).into_styled(PrimitiveStyle::with_fill(WHITE)).draw(d)?;
    let glass = PrimitiveStyleBuilder::new().fill_color(PANEL).stroke_color(CYAN).stroke_width(1).build();
    let panel = eg::Rectangle::new(Point::new(200, 40), Size::new(108, 160));
    eg::RoundedRectangle::with_equal_corners(panel, Size::new(10, 10)).into_styled(glass).draw(d)?;
    let amber = Rgb565::new(31, 44, 0);
    for (i, _) in FUEL_MASK.iter().flatten().enumerate().filter(|(_, a)| **a >= 128) {
        let p = Point::new(216 + 2 * (i % 12) as i32, 58 + 2 * (i / 12) as i32);
        eg::Rectangle::new(p, Size::new(2, 2)).into_styled(PrimitiveStyle::with_fill(amber)).draw(d)?;
    }
    Text::new("FUEL 62%", Point::new(248, 74), text).draw(d)?;
    Text::new("ODO 12840", Point::new(216, 110), text).draw(d)?;
    Text::new("21.5 C", Point::new(216, 130), text).draw(d)?;
    let big = MonoTextStyle::new(&FONT_10X20, TEXT);
    Text::with_alignment(readout, Point::new(124, 178), big, Alignment::Center).draw(d)?;
    Text::with_alignment("km/h", Point::new(124, 192), text, Alignment::Center).draw(d)?;
    Ok(())
}
// dashboard:eg:end

/// The plain embedded-graphics dashboard at [`SPEED`], reading "88".
pub fn dashboard_eg<D: DrawTarget<Color = Rgb565>>(d: &mut D) -> Result<(), D::Error> {
    dashboard_eg_showing(d, SPEED, "88")
}
