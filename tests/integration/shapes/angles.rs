//! Arc and sector angles: a large start keeps its sweep, and angles that
//! differ by whole turns (as `f32` arithmetic computes them) give the same
//! pixels, so pie slices built as `a0 + k·TAU/n` close at the wrap.

use super::{CURVE_MARGIN, Grid, H, W, draw, fill};
use crate::reference::Rng;
use core::f32::consts::TAU;
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::shape::{Arc, Sector, ShapeStyle};

fn count(g: &Grid) -> u32 {
    g.hits.iter().sum()
}

/// `a` reduced to `[0, 2π)` in f64, then rounded to f32.
fn reduced(a: f32) -> f32 {
    f64::from(a).rem_euclid(std::f64::consts::TAU) as f32
}

/// The sector (radius 12, sweep 2 rad) covered 142 px for a start up
/// to 10^5 rad, 140 at 10^6 and 51 from 10^7 on: the start was not reduced
/// before the sweep was added to it.
#[test]
fn a_large_start_keeps_the_sweep() {
    let c = (32.0, 24.0);
    let ring = ShapeStyle::stroke(Gray8::WHITE, 3.0);
    for start in [1e5f32, 1e6, 1e7, 1e8, 1e10, -1e7, 3.0e9, 1e20, f32::MAX, -f32::MAX] {
        let sector = count(&draw(Sector::new(c, 12.0, start, 2.0).unwrap(), fill()));
        assert!((140..=145).contains(&sector), "sector from {start}: {sector} px");
        // Where f64 knows the direction (to |start|·2^-52 rad): the same pixels.
        if start.abs() <= 1e10 {
            let near = count(&draw(Sector::new(c, 12.0, reduced(start), 2.0).unwrap(), fill()));
            assert_eq!(sector, near, "sector from {start}");
            let arc = draw(Arc::new(c, 12.0, start, -2.0).unwrap(), ring);
            let arc_near = draw(Arc::new(c, 12.0, reduced(start), -2.0).unwrap(), ring);
            assert_eq!(count(&arc), count(&arc_near), "arc from {start}");
        }
    }
}

/// The centre on an odd multiple of 1/32 px: a corner straight above or
/// beside it snaps up or down on the sign of a sine or cosine near 0.
const TIES: [(f32, f32); 3] = [(32.03125, 24.03125), (31.96875, 23.5), (32.5, 24.09375)];

#[test]
fn whole_turns_draw_the_same_slice() {
    // Whole turns are not representable: `a0 + k·TAU` is off by the f32
    // rounding, which the angle grid absorbs for angles on it (whole
    // degrees, k·TAU/n for n dividing 360·4096).
    let mut angles: Vec<f32> = (-12..=12).map(|k| k as f32 * TAU / 24.0).collect();
    angles.extend((-360..360).step_by(5).map(|d| (d as f32).to_radians()));
    for c in TIES {
        for &a0 in &angles {
            let one = draw(Sector::new(c, 12.0, a0, 1.0).unwrap(), fill());
            for k in [-2.0f32, -1.0, 1.0, 2.0] {
                let other = draw(Sector::new(c, 12.0, a0 + k * TAU, 1.0).unwrap(), fill());
                assert!(one.hits == other.hits, "centre {c:?}, start {a0} and {a0} + {k}·TAU");
            }
        }
    }
}

/// `n` slices from `a0 + k·TAU/n`, the last ending at `a0 + TAU` (as f32
/// computes it): every pixel at most once, every centre clearly inside the
/// disc exactly once.
fn assert_pie(c: (f32, f32), r: f32, a0: f32, n: usize) {
    let step = TAU / n as f32;
    let slices: Vec<Grid> =
        (0..n).map(|k| draw(Sector::new(c, r, a0 + k as f32 * step, step).unwrap(), fill())).collect();
    for (x, y) in (0..H).flat_map(|y| (0..W).map(move |x| (x, y))) {
        let hits: u32 = slices.iter().map(|g| g.at(x, y)).sum();
        let (dx, dy) = (f64::from(x) + 0.5 - f64::from(c.0), f64::from(y) + 0.5 - f64::from(c.1));
        let inside = (dx * dx + dy * dy).sqrt() < f64::from(r) - CURVE_MARGIN;
        assert!(hits <= 1 && (hits == 1 || !inside), "{n} slices from {a0} at {c:?}: ({x}, {y}) hit {hits}");
    }
}

#[test]
fn pies_close_at_the_wrap() {
    let mut rng = Rng::new(0x9e1);
    for c in TIES.into_iter().chain([(32.0, 24.0), (31.5, 24.5)]) {
        for n in [2usize, 3, 4, 5, 6, 8, 12] {
            for a0 in [0.0, -core::f32::consts::FRAC_PI_2, core::f32::consts::PI, 30f32.to_radians()] {
                assert_pie(c, 12.0, a0, n);
            }
            let a0 = (rng.range(-720, 720) as f32).to_radians();
            assert_pie(c, rng.uniform(3.0, 20.0) as f32, a0, n);
        }
    }
}
