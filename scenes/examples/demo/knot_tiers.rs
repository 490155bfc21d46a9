//! The knot in both accuracy tiers (issue 61): `knot_fast.png`, drawn with
//! `Pipeline::with_precision(Precision::Fast)`, and `knot_diff.png`, where
//! it differs from the exact tier's `knot.png`, amplified to be seen.
//!
//! The difference image: black where the tiers agree; where both cover a
//! pixel, grey of [`GAIN`] levels per 8-bit step of the largest channel
//! difference (one step: dark grey, 16 or more: white); magenta where only
//! one tier covers the pixel (its own snapped vertices move an edge).

use super::knot::meshlet_frame;
use super::scene3d::{BACKGROUND, HEIGHT, S, W};
use super::{Canvas, Result, save};
use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
use microraster::raster3d::Precision;
use microraster_scenes::scenes3d::Scene3d;
use std::path::Path;

/// Grey levels per 8-bit step of channel difference in `knot_diff.png`.
pub const GAIN: u8 = 16;
/// Pixels covered by one tier only.
const EDGE: Rgb888 = Rgb888::new(255, 0, 255);

/// What the difference image shows, counted.
#[derive(Default)]
struct Diff {
    same: usize,
    colour: usize,
    max_step: u8,
    edge: usize,
}

fn difference(exact: &Canvas, fast: &Canvas) -> (Canvas, Diff) {
    let mut img = Canvas::new(W as u32, HEIGHT);
    let mut d = Diff::default();
    for ((o, a), b) in img.px.iter_mut().zip(&exact.px).zip(&fast.px) {
        *o = match (*a != BACKGROUND, *b != BACKGROUND) {
            (true, true) | (false, false) => {
                let step = [a.r().abs_diff(b.r()), a.g().abs_diff(b.g()), a.b().abs_diff(b.b())]
                    .into_iter()
                    .max()
                    .unwrap_or(0);
                d.max_step = d.max_step.max(step);
                if step == 0 {
                    d.same += 1;
                } else {
                    d.colour += 1;
                }
                let g = step.saturating_mul(GAIN);
                Rgb888::new(g, g, g)
            }
            _ => {
                d.edge += 1;
                EDGE
            }
        };
    }
    (img, d)
}

/// Writes knot_fast.png and knot_diff.png to `out`.
pub fn run(out: &Path) -> Result<()> {
    let exact = Scene3d::pipeline::<f32, S>(W as u32, HEIGHT)?;
    let fast = exact.with_precision(Precision::Fast);
    let (a, _) = meshlet_frame(&exact)?;
    let (b, _) = meshlet_frame(&fast)?;
    save(&b, &out.join("knot_fast.png"))?;
    let (img, d) = difference(&a, &b);
    save(&img, &out.join("knot_diff.png"))?;
    println!(
        "knot_fast.png: the fast tier; knot_diff.png: {} pixels equal to the exact tier's, {} differ in colour \
         (at most {} steps of 8 bits, shown ×{GAIN}), {} covered by one tier only (magenta)",
        d.same, d.colour, d.max_step, d.edge
    );
    Ok(())
}
