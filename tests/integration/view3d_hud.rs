//! The front's HUD (`View3d::draw_with`): the frame equals the meshes drawn
//! into a framebuffer with the HUD drawn over them, for every band height;
//! a translucent panel blends over the meshes; `draw` is `draw_with` with
//! an empty HUD; a HUD's error fails the frame.

use crate::framebuffer::Framebuffer;
use embedded_graphics::mono_font::{MonoTextStyle, ascii::FONT_6X10};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics::text::Text;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::band::BandView;
use microraster::shape::{Rect, Shape, ShapeStyle};
use microraster::view3d::{CUBE, Camera, Object, View3d};
use microraster::{Band, Error, Param, RenderError};

const W: usize = 96;
const H: u32 = 72;
const BG: Rgb565 = Rgb565::BLACK;
/// The panel: a colour the lit cube has nowhere, half transparent.
const PANEL: Rgb565 = Rgb565::new(0, 0, 31);
/// The panel's rows and columns.
const PANEL_AT: (f32, f32, f32, f32) = (8.0, 28.0, 80.0, 24.0);

fn camera() -> Camera {
    Camera::look_at([2.0, 2.5, 5.0], [0.0, 0.0, 0.0])
}

fn objects() -> [Object<'static, Rgb565>; 2] {
    [
        Object::new(&CUBE, Rgb565::new(31, 40, 4)).rotate_y(0.4),
        Object::new(&CUBE, Rgb565::new(8, 60, 12)).scale(0.5).translate([1.6, 0.3, -0.5]),
    ]
}

/// Text, an opaque e-g outline and a translucent microraster panel.
fn hud<const N: usize>(view: &mut BandView<'_, Rgb565, N>) -> Result<(), Error> {
    let text = MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE);
    view.draw_visible(&Text::new("FPS 60", Point::new(2, 9), text))?;
    let outline = Rectangle::new(Point::new(0, 0), Size::new(W as u32, H))
        .into_styled(PrimitiveStyle::with_stroke(Rgb565::YELLOW, 1));
    view.draw_visible(&outline)?;
    let (x, y, w, h) = PANEL_AT;
    Rect::new(x, y, w, h)?.styled(ShapeStyle::fill(PANEL).with_opacity(128))?.draw_on(view);
    Ok(())
}

/// The reference: the meshes into a framebuffer (a band as tall as the
/// frame), then the HUD over them.
fn meshes_then_hud(with_hud: bool) -> Vec<Rgb565> {
    let mut full = Box::new(Band::<Rgb565, W, { H as usize }>::new(BG));
    let mut frame = full.view(0, H as usize, BG);
    let mut view = Box::new(View3d::<Rgb565, W, { H as usize }>::new(BG));
    view.draw(&camera(), &objects(), &mut frame).unwrap();
    if with_hud {
        hud(&mut frame).unwrap();
    }
    full.rows().iter().flatten().copied().collect()
}

/// The front with the HUD, in `BH`-row bands.
fn front<const BH: usize>() -> Vec<Rgb565> {
    let mut view = Box::new(View3d::<Rgb565, W, BH>::new(BG));
    let mut fb = Framebuffer::new(W as u32, H, BG);
    view.draw_with(&camera(), &objects(), &mut fb, hud).unwrap();
    fb.pixels
}

#[test]
fn hud_frame_equals_meshes_then_hud_on_a_framebuffer() {
    let want = meshes_then_hud(true);
    assert_ne!(want, meshes_then_hud(false), "the HUD shows");
    for (bh, got) in [(1, front::<1>()), (5, front::<5>()), (16, front::<16>()), (72, front::<72>())] {
        let diff = want.iter().zip(&got).filter(|(a, b)| a != b).count();
        assert_eq!(diff, 0, "{bh}-row bands: {diff} pixels differ");
    }
}

#[test]
fn a_translucent_panel_blends_over_the_meshes() {
    let (meshes, with_hud) = (meshes_then_hud(false), front::<16>());
    let (x0, y0, w, h) = PANEL_AT;
    let mut blended = 0;
    for y in (y0 as usize + 1)..(y0 + h) as usize - 1 {
        for x in (x0 as usize + 1)..(x0 + w) as usize - 1 {
            let (under, over) = (meshes[y * W + x], with_hud[y * W + x]);
            // Half of each: every channel strictly between the two
            // (where they differ by more than rounding), on the mesh and
            // on the background alike.
            for (u, p, o) in [
                (under.r(), PANEL.r(), over.r()),
                (under.g(), PANEL.g(), over.g()),
                (under.b(), PANEL.b(), over.b()),
            ] {
                if u.abs_diff(p) > 2 {
                    assert!(
                        o > u.min(p) && o < u.max(p),
                        "({x}, {y}): {under:?} under {PANEL:?} gave {over:?}"
                    );
                }
            }
            blended += usize::from(under != BG);
        }
    }
    assert!(blended > 100, "the panel covers the meshes: {blended} pixels");
}

#[test]
fn draw_is_draw_with_an_empty_hud() {
    let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
    let (mut a, mut b) = (Framebuffer::new(W as u32, H, BG), Framebuffer::new(W as u32, H, BG));
    view.draw(&camera(), &objects(), &mut a).unwrap();
    view.draw_with(&camera(), &objects(), &mut b, |_| Ok(())).unwrap();
    assert_eq!(a.pixels, b.pixels);
    assert_eq!(a.pixels, meshes_then_hud(false));
    // Each band sent once: the HUD adds no transfer.
    assert_eq!(a.contiguous.len(), b.contiguous.len());
}

#[test]
fn a_hud_error_fails_the_frame() {
    let mut view = Box::new(View3d::<Rgb565, W, 16>::new(BG));
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let mut bands = 0;
    let r = view.draw_with(&camera(), &objects(), &mut fb, |band| {
        bands += 1;
        if band.y0() >= 32 { Err(Error::InvalidParameter(Param::User)) } else { Ok(()) }
    });
    assert_eq!(r, Err(RenderError::Input(Error::InvalidParameter(Param::User))));
    assert_eq!(bands, 3, "no band drawn after the error");
}
