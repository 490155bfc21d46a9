//! Band invariance: the image must not depend on the band height, and every
//! band must go out as exactly one `fill_contiguous` over its rectangle.

use crate::framebuffer::Framebuffer;
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8, Rgb565};
use embedded_graphics_core::prelude::*;
use microraster::blit::TargetBlitter;
use microraster::edge::Cull;
use microraster::{Band, Interpolate, Line, Primitive, Renderer, SubPoint, Triangle};

const W: usize = 96;
const HEIGHT: u32 = 61; // not a multiple of 7 or 16: the last band is short

fn random_scene<C: Interpolate>(rng: &mut Rng, n: usize) -> Vec<Primitive<C, 4>> {
    let color = |rng: &mut Rng| {
        let m = C::CHANNEL_MAX;
        C::from_channels([0, 1, 2].map(|k| (rng.below(m[k] as u64 + 1)) as u8))
    };
    let point = |rng: &mut Rng| {
        // Up to 50% beyond the frame on each side, 1/16 px resolution.
        let x = rng.range(-(W as i64) * 8, (W as i64) * 24) as i32;
        let y = rng.range(-(HEIGHT as i64) * 8, (HEIGHT as i64) * 24) as i32;
        SubPoint::<4>::new(x, y).unwrap()
    };
    (0..n)
        .map(|i| match i % 3 {
            0 => Triangle::flat([point(rng), point(rng), point(rng)], color(rng)).into(),
            1 => {
                Triangle::gouraud([point(rng), point(rng), point(rng)], [color(rng), color(rng), color(rng)])
                    .into()
            }
            _ => Line::new(point(rng), point(rng), color(rng)).into(),
        })
        .collect()
}

fn render_banded<C: Interpolate, const H: usize>(
    scene: &[Primitive<C, 4>],
    bg: C,
    cull: Cull,
) -> Framebuffer<C> {
    let mut fb = Framebuffer::new(W as u32, HEIGHT, bg);
    let mut band = Band::<C, W, H>::new(bg);
    Renderer::new(HEIGHT, bg).with_cull(cull).render(scene, &mut band, &mut fb).unwrap();
    // One fill_contiguous per band, full width, consecutive rows, last one short.
    let expected_bands = HEIGHT.div_ceil(H as u32) as usize;
    assert_eq!(fb.contiguous.len(), expected_bands, "band count for H = {H}");
    for (i, r) in fb.contiguous.iter().enumerate() {
        assert_eq!(r.top_left, Point::new(0, (i * H) as i32));
        assert_eq!(r.size.width, W as u32);
        assert_eq!(r.size.height, (HEIGHT - (i * H) as u32).min(H as u32));
    }
    assert!(fb.writes.iter().all(|&w| w == 1), "each frame pixel sent exactly once");
    fb
}

fn render_direct<C: Interpolate>(scene: &[Primitive<C, 4>], bg: C, cull: Cull) -> Vec<C> {
    let mut fb = Framebuffer::new(W as u32, HEIGHT, bg);
    let mut blitter = TargetBlitter::new(&mut fb);
    for p in scene {
        p.draw(&mut blitter, cull);
    }
    fb.pixels
}

fn check_invariance<C: Interpolate + core::fmt::Debug>(seed: u64, bg: C) -> usize {
    let mut rng = Rng::new(seed);
    let mut scenes = 0;
    for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
        for n in [1, 5, 40] {
            let scene = random_scene::<C>(&mut rng, n);
            let full = render_banded::<C, { HEIGHT as usize }>(&scene, bg, cull).pixels;
            assert_eq!(render_banded::<C, 1>(&scene, bg, cull).pixels, full, "band height 1");
            assert_eq!(render_banded::<C, 7>(&scene, bg, cull).pixels, full, "band height 7");
            assert_eq!(render_banded::<C, 16>(&scene, bg, cull).pixels, full, "band height 16");
            assert_eq!(render_direct(&scene, bg, cull), full, "direct rendering without bands");
            scenes += 1;
        }
    }
    scenes
}

#[test]
fn image_is_identical_for_band_heights_1_7_16_and_full() {
    let mut scenes = 0;
    for seed in 1..=12 {
        scenes += check_invariance(seed, Rgb565::new(0, 0, 0));
        scenes += check_invariance(seed + 100, Gray8::new(17));
        scenes += check_invariance(seed + 200, BinaryColor::Off);
    }
    println!("band invariance: {scenes} scenes × 5 renderings compared");
    assert_eq!(scenes, 12 * 3 * 9);
}

#[test]
fn frame_offset_and_bad_height() {
    let mut rng = Rng::new(7);
    let scene = random_scene::<Rgb565>(&mut rng, 10);
    let bg = Rgb565::new(1, 2, 3);
    let mut band = Band::<Rgb565, W, 8>::new(bg);
    let mut fb = Framebuffer::new(W as u32 + 5, HEIGHT + 9, Rgb565::new(31, 63, 31));
    Renderer::new(HEIGHT, bg).with_offset(Point::new(5, 9)).render(&scene[..], &mut band, &mut fb).unwrap();
    let reference = render_banded::<Rgb565, 8>(&scene, bg, Cull::None).pixels;
    for y in 0..HEIGHT {
        for x in 0..W as u32 {
            let shifted = fb.pixels[((y + 9) * (W as u32 + 5) + x + 5) as usize];
            assert_eq!(shifted, reference[(y * W as u32 + x) as usize]);
        }
    }
    for bad in [0, microraster::MAX_FRAME_DIM + 1] {
        let r = Renderer::new(bad, bg).render(&scene[..], &mut band, &mut fb);
        assert_eq!(r, Err(microraster::RenderError::Input(microraster::Error::InvalidFrameSize)));
    }
}

/// `Binned2d` over `scene` with `H`-row bands and an index of exactly the
/// length it needs (found from the error of an empty one); one entry less
/// is refused before anything is sent.
fn render_binned<C: Interpolate + core::fmt::Debug, const H: usize>(
    scene: &[Primitive<C, 4>],
    bg: C,
    cull: Cull,
) -> Vec<C> {
    use microraster::render::Binned2d;
    use microraster::{Error, RenderError};
    let renderer = Renderer::new(HEIGHT, bg).with_cull(cull);
    let mut band = Band::<C, W, H>::new(bg);
    let mut fb = Framebuffer::new(W as u32, HEIGHT, bg);
    let needed = match renderer.render(Binned2d::new(scene, &mut []), &mut band, &mut fb) {
        Err(RenderError::Input(Error::CapacityExceeded { needed, capacity: 0 })) => needed,
        other => panic!("an empty index: {other:?}"),
    };
    // The bands and, for each primitive, the bands its rows reach in the frame.
    let bands = HEIGHT.div_ceil(H as u32) as usize;
    let reach = |p: &Primitive<C, 4>| {
        let (lo, hi) = p.rows();
        let (lo, hi) = (lo.max(0), hi.min(HEIGHT as i32 - 1));
        if lo > hi { 0 } else { (hi as usize / H) - (lo as usize / H) + 1 }
    };
    assert_eq!(needed, bands + scene.iter().map(reach).sum::<usize>(), "H = {H}");
    let mut index = vec![0u16; needed];
    let short = renderer.render(Binned2d::new(scene, &mut index[..needed - 1]), &mut band, &mut fb);
    assert_eq!(short, Err(RenderError::Input(Error::CapacityExceeded { needed, capacity: needed - 1 })));
    assert!(fb.contiguous.is_empty(), "a refused frame sends nothing");
    renderer.render(Binned2d::new(scene, &mut index), &mut band, &mut fb).unwrap();
    fb.pixels
}

/// The binned pass draws exactly what the slice pass draws, for every band
/// height, colour type and culling, with primitives beyond the frame.
#[test]
fn binned_primitives_draw_what_the_slice_draws() {
    let mut scenes = 0;
    for seed in 1..=6 {
        let mut rng = Rng::new(seed + 300);
        for cull in [Cull::None, Cull::Clockwise] {
            for n in [1, 5, 40, 300] {
                let scene = random_scene::<Rgb565>(&mut rng, n);
                let bg = Rgb565::new(3, 5, 7);
                let full = render_banded::<Rgb565, { HEIGHT as usize }>(&scene, bg, cull).pixels;
                assert_eq!(render_binned::<Rgb565, 1>(&scene, bg, cull), full, "band height 1");
                assert_eq!(render_binned::<Rgb565, 7>(&scene, bg, cull), full, "band height 7");
                assert_eq!(render_binned::<Rgb565, 16>(&scene, bg, cull), full, "band height 16");
                let gray = random_scene::<Gray8>(&mut rng, n);
                let full = render_banded::<Gray8, 16>(&gray, Gray8::new(9), cull).pixels;
                assert_eq!(render_binned::<Gray8, 16>(&gray, Gray8::new(9), cull), full, "Gray8");
                scenes += 1;
            }
        }
    }
    assert_eq!(scenes, 6 * 2 * 4);
}

/// Issue 60, finding 9: 40,000 primitives that each touch both bands of a
/// 4-row frame need 80,002 index entries, more than a `u16` counts. Any
/// index at least that long draws them as the slice does; one entry less is
/// refused with the index's own length as the capacity.
#[test]
fn binned_index_past_65535_entries() {
    use microraster::render::Binned2d;
    use microraster::{Error, RenderError};
    let bg = Gray8::new(0);
    let p = |x: i32, y: i32| SubPoint::<4>::new(x, y).unwrap();
    // Rows 0..4 each, of varied widths and colours: the order shows.
    let scene: Vec<Primitive<Gray8, 4>> = (0..40_000)
        .map(|i| {
            let w = 16 * (2 + i % 7);
            Triangle::flat([p(0, 0), p(w, 0), p(0, 64)], Gray8::new((i % 251) as u8)).into()
        })
        .collect();
    let renderer = Renderer::new(4, bg);
    let mut band = Band::<Gray8, 8, 2>::new(bg);
    let mut fb = Framebuffer::new(8, 4, bg);
    renderer.render(&scene[..], &mut band, &mut fb).unwrap();
    let full = fb.pixels;
    for len in [80_002, 160_004] {
        let mut index = vec![0u16; len];
        let mut fb = Framebuffer::new(8, 4, bg);
        renderer.render(Binned2d::new(&scene, &mut index), &mut band, &mut fb).unwrap();
        assert!(fb.pixels == full, "index of {len}");
    }
    let mut index = vec![0u16; 80_001];
    let mut fb = Framebuffer::new(8, 4, bg);
    let short = renderer.render(Binned2d::new(&scene, &mut index), &mut band, &mut fb);
    assert_eq!(short, Err(RenderError::Input(Error::CapacityExceeded { needed: 80_002, capacity: 80_001 })));
    assert!(fb.contiguous.is_empty(), "a refused frame sends nothing");
}

/// A primitive's number is a `u16` entry: 65,535 primitives are drawn,
/// 65,536 are refused (whatever the index's length) before anything is sent.
#[test]
fn binned_primitive_count_limit() {
    use microraster::render::Binned2d;
    use microraster::{Error, RenderError};
    let bg = Gray8::new(0);
    let p = |x: i32, y: i32| SubPoint::<4>::new(x, y).unwrap();
    let tri = |i: usize| Triangle::flat([p(0, 0), p(128, 0), p(0, 64)], Gray8::new((i % 251) as u8)).into();
    let scene: Vec<Primitive<Gray8, 4>> = (0..65_536).map(tri).collect();
    let renderer = Renderer::new(4, bg);
    let mut band = Band::<Gray8, 8, 4>::new(bg);
    let mut index = vec![0u16; 70_000];
    let mut fb = Framebuffer::new(8, 4, bg);
    renderer.render(Binned2d::new(&scene[..65_535], &mut index), &mut band, &mut fb).unwrap();
    let mut slice = Framebuffer::new(8, 4, bg);
    renderer.render(&scene[..65_535], &mut band, &mut slice).unwrap();
    assert!(fb.pixels == slice.pixels);
    let mut fb = Framebuffer::new(8, 4, bg);
    let all = renderer.render(Binned2d::new(&scene, &mut index), &mut band, &mut fb);
    assert_eq!(all, Err(RenderError::Input(Error::CapacityExceeded { needed: 65_536, capacity: 65_535 })));
    assert!(fb.contiguous.is_empty(), "a refused frame sends nothing");
}
