//! The dashboard example (`examples/common/dashboard.rs`): the same image
//! for band heights 1, 16 and the full frame; its text pixel for pixel the
//! plain embedded-graphics version's; the panel translucent where e-g's is
//! opaque. The driving dashboard (`examples/common/dashboard_live.rs`):
//! `dashboard` at its speed, and through dirty bands every frame of the drive
//! is the plain band loop's, with fewer bands sent.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::render::from_fn;
use microraster::{Band, Renderer};

#[path = "../../examples/common/dashboard_live.rs"]
pub(crate) mod live; // also damage_drive's
#[allow(dead_code)] // the constants the demo and benches use
#[path = "../../examples/common/dashboard.rs"]
pub(crate) mod scene;
use microraster::render::{Blocking, DirtyBands};
use scene::{H, NIGHT, TEXT, W};

fn render<const BH: usize>() -> Vec<Rgb565> {
    let mut band = Box::new(Band::<Rgb565, W, BH>::new(NIGHT));
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
    Renderer::new(H, NIGHT).render(from_fn(scene::dashboard), &mut band, &mut fb).unwrap();
    assert!(fb.writes.iter().all(|&n| n == 1), "every pixel sent exactly once");
    fb.pixels
}

fn plain() -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
    scene::dashboard_eg(&mut fb).unwrap();
    fb.pixels
}

fn at(img: &[Rgb565], x: usize, y: usize) -> Rgb565 {
    img[y * W + x]
}

#[test]
fn dashboard_is_the_same_for_every_band_height() {
    let full = render::<240>();
    assert_eq!(render::<1>(), full, "1-row bands");
    assert_eq!(render::<16>(), full, "16-row bands");
    let mut colours: Vec<u16> =
        full.iter().map(|c| embedded_graphics_core::prelude::IntoStorage::into_storage(*c)).collect();
    colours.sort_unstable();
    colours.dedup();
    // Gradients and anti-aliased edges: far more colours than the palette.
    println!("dashboard: {} distinct colours", colours.len());
    assert!(colours.len() > 200, "only {} colours", colours.len());
}

#[test]
fn dashboard_text_is_pixel_identical_to_plain_embedded_graphics() {
    let (mr, eg) = (render::<16>(), plain());
    let text = |img: &[Rgb565]| img.iter().map(|&c| c == TEXT).collect::<Vec<_>>();
    let n = text(&eg).iter().filter(|&&t| t).count();
    println!("dashboard: {n} text pixels, identical in both versions");
    assert!(n > 300, "the labels and readouts are drawn ({n} text pixels)");
    assert!(text(&mr) == text(&eg), "text pixels differ");
}

#[test]
fn dashboard_panel_is_translucent_over_the_ring() {
    let (mr, eg) = (render::<16>(), plain());
    // Inside the panel (x 200..308), below its text: over the gauge ring
    // (radius 95..105 around (124, 124) spans x 216..225 on row 150) and
    // over the background.
    let (over_ring, over_sky) = ((220, 150), (290, 150));
    assert_eq!(at(&eg, over_ring.0, over_ring.1), at(&eg, over_sky.0, over_sky.1), "e-g: opaque");
    assert_ne!(
        at(&mr, over_ring.0, over_ring.1),
        at(&mr, over_sky.0, over_sky.1),
        "microraster: the ring shows"
    );
}

#[test]
fn driving_dashboard_at_its_speed_is_the_dashboard() {
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(NIGHT));
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
    Renderer::new(H, NIGHT)
        .render(from_fn(|v| live::dashboard_at(v, scene::SPEED)), &mut band, &mut fb)
        .unwrap();
    assert!(fb.pixels == render::<16>(), "dashboard_at(SPEED) differs from dashboard");
}

/// The drive through `DirtyBands` (double-banded loop, `BH`-row bands): after
/// every frame the display shows the plain band loop's frame; returns the
/// bands sent and the bands of all frames.
fn drive<const BH: usize, const N: usize>() -> (u64, u64) {
    let r = Renderer::new(H, NIGHT);
    let mut band = Box::new(Band::<Rgb565, W, BH>::new(NIGHT));
    let mut bands = Box::new([const { Band::<Rgb565, W, BH>::new(NIGHT) }; 2]);
    let mut display = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
    let mut sink = DirtyBands::<_, N>::new(Blocking(&mut display));
    let mut sent_before = 0;
    for f in 0..live::FRAMES {
        let kmh = live::speed(f);
        let mut plain = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
        r.render(from_fn(|v| live::dashboard_at(v, kmh)), &mut band, &mut plain).unwrap();
        let mut failed = Ok(());
        r.render_linked(
            from_fn(|view| {
                if failed.is_ok() {
                    failed = live::dashboard_at(view, kmh);
                }
                Ok(())
            }),
            &mut bands,
            &mut sink,
        )
        .unwrap();
        failed.unwrap();
        assert!(sink.inner().0.pixels == plain.pixels, "wrong skip: {BH}-row bands, frame {f}");
        let sent = sink.sent_bands() - sent_before;
        sent_before = sink.sent_bands();
        if (21..35).contains(&f) {
            assert_eq!(sent, 0, "frame {f} repeats frame {}: nothing to send", f - 1);
        } else {
            assert!(sent > 0, "frame {f}: the needle moved, some band must go out");
        }
    }
    (sink.sent_bands(), (live::FRAMES * (H as usize).div_ceil(BH)) as u64)
}

#[test]
fn driving_dashboard_through_dirty_bands_is_the_plain_loop_and_sends_less() {
    for (sent, all) in [drive::<16, 15>(), drive::<7, 35>()] {
        assert!(sent * 2 < all, "{sent} of {all} bands sent");
    }
}
