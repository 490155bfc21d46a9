//! The dashboard's 60-frame drive (`examples/common/dashboard_live.rs`)
//! with damage regions, as `fw_bench`'s `dashboard-drive` row and the link
//! example run it: one full frame, then each frame damaged by the needle's
//! old and new bounds and the readout's. After every frame the display is
//! the full frame's; each frame sends each damaged pixel once and no other,
//! and the cruise (speed unchanged) sends nothing.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::render::{Damage, from_fn};
use microraster::{Band, Renderer};

// The dashboard's modules, included once (in the `dashboard` suite).
use crate::dashboard::live;
use crate::dashboard::scene::{H, NIGHT, W};

#[test]
fn the_drive_with_damage_is_the_full_frames() {
    let r = Renderer::new(H, NIGHT);
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(NIGHT));
    let mut shown = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
    r.render(from_fn(|v| live::dashboard_at(v, live::speed(0))), &mut band, &mut shown).unwrap();
    let mut quiet = 0;
    for f in 1..live::FRAMES {
        let (from, to) = (live::speed(f - 1), live::speed(f));
        let mut damage = Damage::<4>::new();
        live::damage(from, to, &mut damage).unwrap();
        shown.writes.iter_mut().for_each(|w| *w = 0);
        r.render_damaged(from_fn(|v| live::dashboard_at(v, to)), &damage, &mut band, &mut shown).unwrap();
        let mut full = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
        r.render(from_fn(|v| live::dashboard_at(v, to)), &mut band, &mut full).unwrap();
        assert!(shown.pixels == full.pixels, "frame {f}: the display is not the full frame");
        let sent: u64 = shown.writes.iter().map(|&w| u64::from(w)).sum();
        assert!(shown.writes.iter().all(|&w| w <= 1), "frame {f}: a pixel sent twice");
        assert_eq!(sent, damage.area(W as u32, H), "frame {f}");
        if from == to {
            quiet += 1;
            assert_eq!(sent, 0, "frame {f}: nothing changed, nothing sent");
        } else {
            // The needle's two boxes at least: well under the frame.
            assert!(sent > 0 && sent < u64::from(W as u32 * H) / 4, "frame {f}: {sent} pixels");
        }
    }
    assert_eq!(quiet, 14, "the cruise: frames 21–34");
}
