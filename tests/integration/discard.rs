//! A fragment the shader discards writes neither colour nor depth: geometry
//! behind it, drawn afterwards, still shows through (with a writing depth
//! test, not only with `DepthState::READ_ONLY`).

use crate::fragment::rect;
use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
use microraster::Band;
use microraster::depth::{Depth16, DepthBand};
use microraster::fragment::{FragTriangle, Fragment, FragmentShader, Output, draw_fragment_triangle};
use microraster::raster3d::Affine;

/// Discards the left half of the frame (x < 50), red elsewhere.
struct HalfHole;

impl FragmentShader<Rgb888, 0> for HalfHole {
    fn shade(&self, _: &Fragment<0>) -> Rgb888 {
        Rgb888::RED
    }
    fn shade_or_discard(&self, f: &Fragment<0>) -> Option<(Rgb888, u8)> {
        (f.x >= 50).then_some((Rgb888::RED, 255))
    }
}

fn draw<Sh: FragmentShader<Rgb888, 0>>(
    t: &[FragTriangle<4, 0>],
    shader: &Sh,
    view: &mut microraster::band::BandView<'_, Rgb888, 100>,
    depth: &mut DepthBand<Depth16, 100, 60>,
) {
    for t in t {
        draw_fragment_triangle(t, view, &mut depth.rows_mut(60), shader, Output::OPAQUE, Affine).unwrap();
    }
}

#[test]
fn discarded_fragments_write_no_depth() {
    let mut band = Box::new(Band::<Rgb888, 100, 60>::new(Rgb888::BLACK));
    let mut depth = Box::new(DepthBand::<Depth16, 100, 60>::new());
    let mut view = band.view(0, 60, Rgb888::BLACK);
    let z = |f: f64| (f * u32::MAX as f64) as u32;
    // Near (0.3) across x 0..100, half discarded; then far (0.6) blue over all of it.
    draw(&rect(0, 100, z(0.3), [0, 0, 0]), &HalfHole, &mut view, &mut depth);
    let flat = |f: &Fragment<0>| Rgb888::new(f.color[0], f.color[1], f.color[2]);
    draw(&rect(0, 100, z(0.6), [0, 0, 255]), &flat, &mut view, &mut depth);
    let px = |x: usize| band.rows()[30][x];
    assert_eq!(px(20), Rgb888::BLUE, "behind a discarded fragment: drawn");
    assert_eq!(px(80), Rgb888::RED, "behind a kept fragment: hidden");
}
