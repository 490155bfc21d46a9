//! The dashboard of `dashboard.rs` as it changes while driving: the needle
//! and the speed readout follow a speed, the rest stays. For the display
//! link's bytes-sent numbers (`examples/link.rs`) and the dirty-band test
//! (`tests/integration/dashboard.rs`).
//!
//! [`dashboard_at`] is `dashboard`'s code with the speed a parameter (kept
//! apart so that `dashboard`, which the README shows, counts and benchmarks,
//! stays as it is); the test checks that both draw the same pixels at
//! `SPEED`. The includer names `dashboard.rs`'s module `scene`:
//!
//! ```ignore
//! #[path = "common/dashboard.rs"]
//! mod scene;
//! #[path = "common/dashboard_live.rs"]
//! mod live;
//! ```

use super::scene::{AMBER, C, CYAN, DEEP, FUEL, GREEN, LABELS, NEEDLE, NIGHT, PANEL, RED, TEXT, WHITE};
use super::scene::{angle, pixel, polar};
use core::f32::consts::PI;
use core::fmt::Write;
use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10, ascii::FONT_10X20};
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Alignment, Text};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Error;
use microraster::band::BandView;
use microraster::shape::{Arc, Circle, LinearGradient, Polygon, Polyline, RadialGradient, Rect};
use microraster::shape::{RoundedRect, Shape, ShapeStyle};
use microraster::texture::{Bilinear, Sprite};

/// Frames of the drive.
pub const FRAMES: usize = 60;

/// The speed (km/h) in frame `f` of the drive: accelerating from 64 to 88
/// over frames 0–19 (1.2 km/h a frame), cruising at 88 for frames 20–34
/// (the screen does not change), braking to 68 over frames 35–59.
pub fn speed(f: usize) -> f32 {
    match f {
        0..20 => 64.0 + 1.2 * f as f32,
        20..35 => 88.0,
        _ => 88.0 - 0.8 * (f - 34) as f32,
    }
}

/// The dashboard with the needle at `kmh` and the readout showing it
/// rounded to a whole km/h.
pub fn dashboard_at<const N: usize>(view: &mut BandView<'_, Rgb565, N>, kmh: f32) -> Result<(), Error> {
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
            Text::with_alignment(LABELS[k / 4], at, text, Alignment::Center).draw(view)?;
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
    Text::new("FUEL 62%", Point::new(248, 74), text).draw(view)?;
    Text::new("ODO 12840", Point::new(216, 110), text).draw(view)?;
    Text::new("21.5 C", Point::new(216, 130), text).draw(view)?;
    let big = MonoTextStyle::new(&FONT_10X20, TEXT);
    let mut readout = heapless::String::<8>::new();
    write!(readout, "{}", (kmh + 0.5) as u32).map_err(|_| Error::InvalidParameter)?;
    Text::with_alignment(&readout, Point::new(124, 178), big, Alignment::Center).draw(view)?;
    Text::with_alignment("km/h", Point::new(124, 192), text, Alignment::Center).draw(view)?;
    Ok(())
}
