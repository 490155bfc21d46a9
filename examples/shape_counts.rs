//! Frames of `cargo bench --bench shapes`' filled shapes for an instruction
//! counter: the host's times move with its load (a shapes bench run has read
//! one row 0.41 and the next 0.83), its instruction counts do not.
//! `bash scripts/shape-counts.sh` runs this under Valgrind's callgrind and
//! prints instructions per frame (the difference of two frame counts, so
//! start-up cancels out):
//!
//! ```text
//! cargo run --release --example shape_counts -- circle prepared 30
//! ```
//!
//! Shapes: `rect`, `rounded`, `circle`, `ellipse` (the bench's 24 instances,
//! filled, 320 × 240 `Rgb565`). Ways: `eg` (embedded-graphics' shape into the
//! slice framebuffer, after its wipe), `direct` (microraster through
//! `Drawable` into the same, after its wipe), `bands` (16-row bands, each
//! shape built in every band it meets), `prepared` (16-row bands, each
//! shape's edges built once a frame: `Prepared::set`), `empty` (16-row bands,
//! nothing drawn).

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{self as eg, PrimitiveStyle};
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::render::from_fn;
use microraster::shape::{self as sh, Shape, ShapeStyle};
use microraster::{Band, Renderer};
use std::hint::black_box;

#[allow(unused_imports)] // each user takes what it needs (the module allows dead code)
#[path = "../benches/common/mod.rs"]
mod common;
use common::shape_set::{bounds, place};
use common::{BG, Frame, H, SliceFb, W};

const FG: Rgb565 = Rgb565::new(31, 40, 8);

/// `frames` frames of `shape` drawn the `way` way.
fn run<S: Shape + Clone>(
    make: impl Fn(usize) -> S,
    eg: impl Fn(usize, &mut SliceFb),
    way: &str,
    frames: usize,
) {
    let set: Vec<_> = (0..24).map(|k| make(k).styled(ShapeStyle::fill(FG)).unwrap()).collect();
    let mut prepared: Vec<_> = set.iter().map(|s| s.prepare().unwrap()).collect();
    let mut fb = SliceFb::default();
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let renderer = Renderer::new(H as u32, BG);
    for _ in 0..frames {
        match way {
            "eg" => {
                fb.wipe();
                (0..24).for_each(|k| eg(k, &mut fb));
            }
            "direct" => {
                fb.wipe();
                set.iter().for_each(|s| s.draw(&mut fb).unwrap());
            }
            "bands" => {
                let frame = from_fn(|v| {
                    set.iter().for_each(|s| s.draw_on(v));
                    Ok(())
                });
                renderer.render(frame, &mut band, &mut fb).unwrap();
            }
            "prepared" => {
                prepared.iter_mut().zip(&set).for_each(|(p, s)| p.set(s.clone()).unwrap());
                let frame = from_fn(|v| {
                    prepared.iter_mut().for_each(|p| p.draw_on(v));
                    Ok(())
                });
                renderer.render(frame, &mut band, &mut fb).unwrap();
            }
            "empty" => renderer.render((), &mut band, &mut fb).unwrap(),
            _ => panic!("way: eg, direct, bands, prepared or empty"),
        }
        black_box(&fb.px);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [shape, way, frames] = &args[..] else {
        panic!("usage: shape_counts <rect|rounded|circle|ellipse> <eg|direct|bands|prepared|empty> <frames>")
    };
    let frames: usize = frames.parse().expect("frames: a count");
    let fill = PrimitiveStyle::with_fill(FG);
    let p = |x: f32, y: f32| Point::new(x.round() as i32, y.round() as i32);
    let eg_rect = |k: usize| {
        let (x, y, w, h) = bounds(k);
        eg::Rectangle::new(p(x, y), Size::new(w as u32, h as u32))
    };
    let rect = |k: usize| {
        let (x, y, w, h) = bounds(k);
        sh::Rect::new(x, y, w, h).unwrap()
    };
    let size = |k: usize| place(k).1;
    match shape.as_str() {
        "rect" => run(rect, |k, t| eg_rect(k).into_styled(fill).draw(t).unwrap(), way, frames),
        "rounded" => run(
            |k| sh::RoundedRect::new(rect(k), size(k) / 8.0).unwrap(),
            |k, t| {
                let d = size(k) as u32;
                let r = eg::RoundedRectangle::with_equal_corners(eg_rect(k), Size::new(d / 8, d / 8));
                r.into_styled(fill).draw(t).unwrap()
            },
            way,
            frames,
        ),
        "circle" => run(
            |k| sh::Circle::new(place(k).0, size(k) / 2.0).unwrap(),
            |k, t| {
                let (c, s) = place(k);
                eg::Circle::with_center(p(c.0, c.1), s as u32).into_styled(fill).draw(t).unwrap()
            },
            way,
            frames,
        ),
        "ellipse" => run(
            |k| sh::Ellipse::new(place(k).0, size(k) / 2.0, size(k) / 3.0).unwrap(),
            |k, t| {
                let (c, s) = place(k);
                let d = s as u32;
                let e = eg::Ellipse::with_center(p(c.0, c.1), Size::new(d, d * 2 / 3));
                e.into_styled(fill).draw(t).unwrap()
            },
            way,
            frames,
        ),
        _ => panic!("shape: rect, rounded, circle or ellipse"),
    }
}
