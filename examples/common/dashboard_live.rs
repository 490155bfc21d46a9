//! The dashboard of `dashboard.rs` as it changes while driving: the needle
//! and the speed readout follow a speed, the rest stays. For the display
//! link's bytes-sent numbers (`examples/link.rs`) and the dirty-band test
//! (`tests/integration/dashboard.rs`).
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
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Error;
use microraster::band::BandView;

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
    write!(readout, "{}", (kmh + 0.5) as u32).map_err(|_| Error::InvalidParameter)?;
    super::scene::dashboard_showing(view, kmh, &readout)
}
