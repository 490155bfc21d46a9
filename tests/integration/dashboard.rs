//! The dashboard example (`examples/common/dashboard.rs`): the same image
//! for band heights 1, 16 and the full frame; its text pixel for pixel the
//! plain embedded-graphics version's; the panel translucent where e-g's is
//! opaque.

use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::{Band, Renderer};

#[allow(dead_code)] // the constants the demo and benches use
#[path = "../../examples/common/dashboard.rs"]
mod scene;
use scene::{H, NIGHT, TEXT, W};

fn render<const BH: usize>() -> Vec<Rgb565> {
    let mut band = Box::new(Band::<Rgb565, W, BH>::new(NIGHT));
    let mut fb = Framebuffer::new(W as u32, H, Rgb565::new(31, 0, 31));
    Renderer::new(H, NIGHT).render_drawables(&mut band, &mut fb, scene::dashboard).unwrap();
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
