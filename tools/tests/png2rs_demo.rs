//! The committed demo texture (`assets/bricks.png`, `examples/demo/texture_data.rs`)
//! is the procedural one and the converter's current output, so neither can go stale.

/// The demo texture, compiled as part of this test. Regenerate after
/// changing the emitter or the PNG:
/// `cargo run -p microraster-tools --bin png2rs -- assets/bricks.png --name BRICKS --format rgb565 --out examples/demo/texture_data.rs`
mod demo {
    include!("../../examples/demo/texture_data.rs");
}

mod common;

use common::{Rng, encode};
use embedded_graphics::pixelcolor::{Gray8, Rgb565};
use microraster::texture::{Sampler, Texture, UV_ONE};
use microraster_tools::png::convert::{Alpha, Format, Texels, convert};
use microraster_tools::png::decode::decode;
use microraster_tools::png::emit;
use png::{BitDepth, ColorType};

const BRICKS_PNG: &[u8] = include_bytes!("../../assets/bricks.png");
const BRICKS_RS: &str = include_str!("../../examples/demo/texture_data.rs");

/// The demo texture, procedurally: 64 × 64 RGB, bricks 16 × 8 px with a
/// 1 px mortar joint, every other course offset by half a brick, each brick
/// a shade of red-brown with a little deterministic grain.
fn bricks() -> Vec<u8> {
    let mut rng = Rng(0xb51c);
    let shades: Vec<[i32; 3]> = (0..32)
        .map(|_| {
            let d = (rng.next() % 41) as i32 - 20;
            [168 + d, 74 + d / 2 + (rng.next() % 15) as i32, 52 + d / 3]
        })
        .collect();
    let mut out = Vec::with_capacity(64 * 64 * 3);
    for y in 0..64i32 {
        for x in 0..64i32 {
            let course = y / 8;
            let xs = x + if course % 2 == 1 { 8 } else { 0 };
            let mortar = y % 8 == 7 || xs % 16 == 15;
            let grain = (rng.next() % 17) as i32 - 8;
            let c = if mortar {
                [196 + grain / 2, 190 + grain / 2, 178 + grain / 2]
            } else {
                let brick = (course * 4 + (xs / 16) % 4) as usize;
                shades[brick].map(|v| v + grain)
            };
            out.extend(c.map(|v| v.clamp(0, 255) as u8));
        }
    }
    out
}

/// Set `PNG2RS_WRITE_DEMO=1` to (re)write `assets/bricks.png` from
/// [`bricks`]; otherwise the committed PNG must decode to exactly that.
#[test]
fn demo_png_is_the_procedural_bricks() {
    let pixels = bricks();
    if std::env::var_os("PNG2RS_WRITE_DEMO").is_some() {
        let png = encode(64, 64, ColorType::Rgb, BitDepth::Eight, &pixels, None, None);
        std::fs::write(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/bricks.png"), png).unwrap();
        return;
    }
    let image = decode(BRICKS_PNG).unwrap();
    assert_eq!((image.width, image.height, image.gray, image.max), (64, 64, false, 255));
    let decoded: Vec<u8> = image.pixels.iter().flat_map(|p| [p[0], p[1], p[2]].map(|c| c as u8)).collect();
    assert_eq!(decoded, pixels);
}

#[test]
fn demo_texture_source_is_current_and_compiles() {
    let image = decode(BRICKS_PNG).unwrap();
    let (texels, _) = convert(&image, Format::Rgb565, Alpha::Reject).unwrap();
    let src = emit::rust_source(
        &texels,
        64,
        64,
        "bricks",
        "bricks.png",
        emit::DEFAULT_CRATE,
        emit::DEFAULT_PIXELCOLOR,
    )
    .unwrap();
    assert_eq!(src, BRICKS_RS, "examples/demo/texture_data.rs is stale: regenerate it (see `mod demo`)");
    // The compiled static holds exactly those texels, in a usable texture.
    let Texels::Rgb565(t) = texels else { panic!() };
    let tex: &Texture<'static, Rgb565> = &demo::BRICKS;
    assert_eq!((tex.width(), tex.height()), (64, 64));
    assert_eq!(tex.data(), &t[..]);
    assert_eq!(demo::BRICKS_TEXELS.as_flattened(), &t[..]);
    // Texel (0, 7) is mortar: light grey.
    let m = tex.sample(Sampler::NEAREST_CLAMP, [UV_ONE / 128, 15 * UV_ONE / 128]);
    assert!(m.iter().all(|&c| c > 160), "{m:?}");
    // A grey texture of the same PNG builds too.
    let (Texels::Gray8(g), _) = convert(&image, Format::Gray8, Alpha::Reject).unwrap() else { panic!() };
    assert!(Texture::<Gray8>::new(&g, 64, 64).is_ok());
}
