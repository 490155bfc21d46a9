//! The `dashboard-drive` row: the dashboard's 60-frame drive of
//! `examples/link.rs` (needle 64 → 88 → 68 km/h and its readout,
//! `examples/common/dashboard_live.rs`) with damage regions. The first,
//! full frame is the `dashboard` row's kind of frame and is not timed here;
//! the timed work is the other [`DRIVE_FRAMES`] frames, each damaged by the
//! needle's old and new bounds and the readout's
//! ([`live::damage`], built inside the timed frame),
//! rendered and sent with `Renderer::render_damaged`. The table divides the
//! count by [`DRIVE_FRAMES`]
//! ([`Work::frames`](super::Work::frames)): instructions per frame, to set
//! against the `dashboard` row's full frame (issue 62: at most 25 % of it).
//! The host checks the frames' CRC (of every damaged part sent, in order)
//! against the target's like any row's, and
//! `tests/integration/damage_drive.rs` that each damaged frame leaves the
//! display equal to a full frame.

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::render::{Damage, from_fn};
use microraster::{Band, Error, Renderer};

use super::frame::input;
use super::live;
use super::{Sink, Work};

/// Frames timed by the row: the drive but its first, full frame.
pub const DRIVE_FRAMES: usize = live::FRAMES - 1;

/// Damage rectangles a frame of the drive needs: the needle's two boxes
/// and the readout's two.
const RECTS: usize = 4;

impl Work {
    /// Frames one run of the work renders: [`DRIVE_FRAMES`] for the drive,
    /// else 1. The table reports instructions per frame.
    pub fn frames(&self) -> u64 {
        match self {
            Work::DashboardDrive => DRIVE_FRAMES as u64,
            _ => 1,
        }
    }
}

/// Pixels one run of the drive sends: the damaged area of each frame
/// (what the host checks the frames' pixel count against).
pub fn drive_pixels(width: u32, height: u32) -> Result<u64, Error> {
    let mut n = 0;
    for f in 1..live::FRAMES {
        let mut damage = Damage::<RECTS>::new();
        live::damage(live::speed(f - 1), live::speed(f), &mut damage)?;
        n += damage.area(width, height);
    }
    Ok(n)
}

/// Frames 1 to 59 of the drive, each with its damage, into `sink`.
pub fn drive<const W: usize, const H: usize>(
    r: Renderer<Rgb565>,
    band: &mut Band<Rgb565, W, H>,
    sink: &mut Sink,
) -> Result<(), Error> {
    for f in 1..live::FRAMES {
        let (from, to) = (live::speed(f - 1), live::speed(f));
        let mut damage = Damage::<RECTS>::new();
        live::damage(from, to, &mut damage)?;
        r.render_damaged(from_fn(|view| live::dashboard_at(view, to)), &damage, band, sink).map_err(input)?;
    }
    Ok(())
}
