//! Property tests (proptest) of the 3D path at its extremes: the clipper's
//! output invariants for any input (NaN, ±inf, huge, `w → 0+`, `w < 0`); the
//! pipeline fed NaN and ±inf in every `f32` input (matrices, vertices,
//! lighting colours, near/far/fov, `w_ref`, viewport sizes); nothing from
//! behind the eye; depth exactly at near and far for far/near from 1.0001 to
//! 10^7; viewports from 1×1 to 4096×4096 drawn exactly, with bands of 1 row
//! and of the full frame.

mod clipper;
mod non_finite;
mod viewports;
mod w_and_depth;

use embedded_graphics_core::pixelcolor::Gray8;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::{Affine, PerspectiveCorrect, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Renderer};
use proptest::prelude::*;

/// An `f32` from the extremes or from a moderate range.
fn wild() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![
        4 => -4.0f32..4.0,
        1 => prop_oneof![Just(f32::NAN), Just(f32::INFINITY), Just(f32::NEG_INFINITY)],
        1 => prop_oneof![Just(0.0f32), Just(-0.0), Just(f32::MIN_POSITIVE), Just(1.0e-30), Just(-1.0e-30)],
        1 => prop_oneof![Just(f32::MAX), Just(f32::MIN), Just(f32::MAX / 16.0), Just(1.8e19), Just(-1.9e19)],
        1 => any::<u32>().prop_map(f32::from_bits),
    ]
}

/// Mostly a moderate value, sometimes an extreme one.
fn rare_wild() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![12 => -4.0f32..4.0, 1 => wild()]
}

/// A clip-space `w`: ordinary, tending to 0 from above, zero, negative.
fn clip_w() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![
        3 => 0.05f32..20.0,
        2 => (-45i32..-1).prop_map(|e| 2f32.powi(e)), // w → 0+
        1 => prop_oneof![Just(0.0f32), Just(-0.0)],
        2 => -20.0f32..-1.0e-6,
        1 => wild(),
    ]
}

const FW: usize = 48;
const FH: usize = 40;

/// Renders `bins` into an `FW × FH` frame with bands of `H` rows; every frame
/// pixel must be sent exactly once.
fn render<const S: u32, const H: usize>(
    bins: &[ScreenTriangle<S>],
    bg: Gray8,
    perspective: bool,
) -> Vec<Gray8> {
    let mut fb = crate::framebuffer::Framebuffer::new(FW as u32, FH as u32, Gray8::new(7));
    let mut band = Box::new(Band::<Gray8, FW, H>::new(bg));
    let mut depth = Box::new(DepthBand::<Depth16, FW, H>::new());
    let r = Renderer::new(FH as u32, bg);
    if perspective {
        r.render(
            Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            &mut fb,
        )
    } else {
        r.render(Triangles3d::new(bins, &mut depth, DepthState::LESS_WRITE, Affine), &mut band, &mut fb)
    }
    .unwrap();
    assert!(fb.writes.iter().all(|&w| w == 1), "a frame pixel sent {:?} times", fb.writes.iter().max());
    fb.pixels
}

/// Drawn pixels: equal under two backgrounds (band height 1 vs full, too).
fn drawn<const S: u32>(bins: &[ScreenTriangle<S>], perspective: bool) -> Vec<bool> {
    let a = render::<S, 1>(bins, Gray8::new(3), perspective);
    let b = render::<S, FH>(bins, Gray8::new(250), perspective);
    let c = render::<S, FH>(bins, Gray8::new(3), perspective);
    assert!(a == c, "the image depends on the band height");
    a.iter().zip(&b).map(|(a, b)| a == b).collect()
}
