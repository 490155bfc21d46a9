//! The dashboard of `dashboard.rs` as it changes while driving: the needle
//! and the speed readout follow a speed, the rest stays. For the display
//! link's bytes-sent numbers (`examples/link.rs`), the dirty-band test
//! (`tests/integration/dashboard.rs`) and the damage-region drive ([`damage`]:
//! `fw_bench`'s `dashboard-drive` row, `tests/integration/damage_drive.rs`).
//!
//! [`dashboard_at`] formats the readout and draws `dashboard_showing`, the
//! code the README shows; the test checks that at `SPEED` it draws
//! `dashboard`'s pixels. The includer names `dashboard.rs`'s module `scene`:
//!
//! ```ignore
//! #[path = "common/dashboard.rs"]
//! mod scene;
//! #[path = "common/dashboard_live.rs"]
//! mod live;
//! ```

use core::fmt::Write;
use embedded_graphics::prelude::{Dimensions, Point};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Error;
use microraster::band::BandView;
use microraster::render::Damage;

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
    let mut readout = heapless::String::<8>::new();
    write!(readout, "{}", (kmh + 0.5) as u32).map_err(|_| Error::BufferTooSmall)?;
    super::scene::dashboard_showing(view, kmh, &readout)
}

/// The readout's text at `kmh`: a whole km/h.
#[allow(dead_code)] // not every includer drives with damage
fn readout(kmh: f32) -> heapless::String<8> {
    let mut s = heapless::String::<8>::new();
    // Up to 10 digits: fits 8 for any speed of the drive; a longer one is empty.
    let _ = write!(s, "{}", (kmh + 0.5) as u32);
    s
}

/// The pixels the needle at `kmh` can light ([`Styled::bounds`](microraster::shape::Styled::bounds)
/// of the needle `dashboard_showing` draws).
#[allow(dead_code)] // not every includer drives with damage
pub fn needle_bounds(kmh: f32) -> Result<Rectangle, Error> {
    use super::scene::{NEEDLE, angle, polar};
    use core::f32::consts::PI;
    use microraster::shape::{Polygon, Shape, ShapeStyle};
    let a = angle(kmh);
    let needle = [polar(90.0, a), polar(5.0, a + PI / 2.0), polar(16.0, a + PI), polar(5.0, a - PI / 2.0)];
    Ok(Polygon::new(&needle)?.styled(ShapeStyle::fill(NEEDLE).antialiased())?.bounds())
}

/// The box of the readout's text at `kmh` (as `dashboard_showing` places it).
#[allow(dead_code)] // not every includer drives with damage
pub fn readout_bounds(kmh: f32) -> Rectangle {
    use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_10X20};
    use embedded_graphics::text::{Alignment, Text};
    let text = readout(kmh);
    let big = MonoTextStyle::new(&FONT_10X20, super::scene::TEXT);
    Text::with_alignment(&text, Point::new(124, 178), big, Alignment::Center).bounding_box()
}

/// What changes from the dashboard at `from` km/h to `to`: the needle's
/// old and new bounds, and the readout's if its text changed; nothing if
/// the speed did not.
#[allow(dead_code)] // not every includer drives with damage
pub fn damage<const N: usize>(from: f32, to: f32, damage: &mut Damage<N>) -> Result<(), Error> {
    if from != to {
        damage.add_moved(&needle_bounds(from)?, &needle_bounds(to)?)?;
    }
    if readout(from) != readout(to) {
        damage.add_moved(&readout_bounds(from), &readout_bounds(to))?;
    }
    Ok(())
}
