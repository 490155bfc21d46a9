//! Band-height invariance of shape images, and gradients against an f64 ramp.

use super::{H, W, grid_point};
use crate::framebuffer::Framebuffer;
use crate::reference::Rng;
use embedded_graphics_core::Drawable;
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::render::from_fn;
use microraster::shape::{Cap, Circle, Polyline, Rect, RoundedRect, Shape, ShapeStyle};
use microraster::{Band, Renderer};

fn render_banded<const BH: usize>(
    scene: &dyn Fn(&mut microraster::band::BandView<'_, Gray8, 64>),
) -> Vec<Gray8> {
    let mut fb = Framebuffer::new(W as u32, H as u32, Gray8::BLACK);
    let mut band = Band::<Gray8, 64, BH>::new(Gray8::BLACK);
    Renderer::new(H as u32, Gray8::new(7))
        .render(
            from_fn(|view| {
                scene(view);
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.pixels
}

#[test]
fn every_band_height_draws_the_same_image() {
    use microraster::shape::{LinearGradient, RadialGradient};
    let pts = [(3.0, 40.0), (20.0, 6.5), (33.3, 30.0), (60.0, 2.0)];
    let ramp = LinearGradient::new((0.0, 0.0), (64.0, 48.0), [Gray8::new(20), Gray8::new(240)]).unwrap();
    let glow = RadialGradient::new((40.0, 24.0), 20.0, [Gray8::WHITE, Gray8::new(60)]).unwrap();
    let a = Circle::new((40.0, 24.0), 19.3)
        .unwrap()
        .styled(ShapeStyle::fill(glow).with_stroke(Gray8::new(90), 2.5))
        .unwrap();
    let b = Polyline::new(&pts)
        .unwrap()
        .styled(ShapeStyle::stroke(ramp, 4.0).with_cap(Cap::Round).antialiased())
        .unwrap();
    let c = RoundedRect::new(Rect::new(5.5, 5.5, 20.0, 12.0).unwrap(), 4.0).unwrap();
    let c = c.styled(ShapeStyle::fill(Gray8::new(150)).antialiased()).unwrap();
    let scene = |v: &mut microraster::band::BandView<'_, Gray8, 64>| {
        a.draw_on(v);
        b.draw_on(v);
        c.draw_on(v);
    };
    let whole = render_banded::<48>(&scene);
    assert!(whole.iter().filter(|p| p.luma() > 7).count() > 800);
    assert_eq!(render_banded::<1>(&scene), whole);
    assert_eq!(render_banded::<7>(&scene), whole);
    assert_eq!(render_banded::<16>(&scene), whole);
    // Drawable straight into a DrawTarget: the aliased circle is the same.
    let mut fb = Framebuffer::new(W as u32, H as u32, Gray8::new(7));
    let mut band = Band::<Gray8, 64, 16>::new(Gray8::BLACK);
    a.draw(&mut fb).unwrap();
    let mut banded = Framebuffer::new(W as u32, H as u32, Gray8::BLACK);
    Renderer::new(H as u32, Gray8::new(7))
        .render(
            from_fn(|v| {
                a.draw_on(v);
                Ok(())
            }),
            &mut band,
            &mut banded,
        )
        .unwrap();
    assert_eq!(fb.pixels, banded.pixels);
}

/// Gradients against `c0 + t·(c1 − c0)` in `f64`, `t` clamped: within ½ of
/// a channel step plus the 8-bit `t` (½/255 of the range, and f32 slack).
#[test]
fn gradients_match_the_f64_ramp() {
    use microraster::shape::{LinearGradient, RadialGradient};
    let mut rng = Rng::new(0x96ad);
    let mut checked = 0;
    for i in 0..300 {
        let (c0, c1) = (rng.range(0, 255) as u8, rng.range(0, 255) as u8);
        let (a, b) = (grid_point(&mut rng, -10.0, 74.0, false), grid_point(&mut rng, -10.0, 74.0, false));
        let radial = i % 2 == 1;
        let r = rng.uniform(1.0, 60.0) as f32;
        let paint: microraster::shape::Paint<Gray8> = if radial {
            RadialGradient::new(a, r, [Gray8::new(c0), Gray8::new(c1)]).unwrap().into()
        } else {
            match LinearGradient::new(a, b, [Gray8::new(c0), Gray8::new(c1)]) {
                Ok(g) => g.into(),
                Err(_) => continue,
            }
        };
        let full = Rect::new(0.0, 0.0, W as f32, H as f32).unwrap().styled(ShapeStyle::fill(paint)).unwrap();
        let mut fb = Framebuffer::new(W as u32, H as u32, Gray8::BLACK);
        let mut band = Band::<Gray8, 64, 16>::new(Gray8::BLACK);
        Renderer::new(H as u32, Gray8::BLACK)
            .render(
                from_fn(|v| {
                    full.draw_on(v);
                    Ok(())
                }),
                &mut band,
                &mut fb,
            )
            .unwrap();
        let (ax, ay, bx, by) = (f64::from(a.0), f64::from(a.1), f64::from(b.0), f64::from(b.1));
        for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let t = if radial {
                ((px - ax).powi(2) + (py - ay).powi(2)).sqrt() / f64::from(r)
            } else {
                ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / ((bx - ax).powi(2) + (by - ay).powi(2))
            }
            .clamp(0.0, 1.0);
            let exact = f64::from(c0) + t * (f64::from(c1) - f64::from(c0));
            let range = (f64::from(c1) - f64::from(c0)).abs();
            let got = f64::from(fb.pixels[(y * W + x) as usize].luma());
            assert!((got - exact).abs() <= 0.5 + range * 0.51 / 255.0, "{i}: ({x}, {y}) {got} vs {exact}");
            checked += 1;
        }
    }
    assert!(checked > 800_000, "{checked}");
}
