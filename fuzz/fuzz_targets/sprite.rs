//! Sprites (`microraster::texture::Sprite`): a texture of any format
//! (`Gray8`, `Rgb565`, `A8`, `Argb4444`), size (1..16 texels, 4096 wide or
//! tall, and invalid 0 / 4097 / wrong data length) and texels, at any
//! position (up to `i32::MIN`/`MAX`), any `f32` scale and angle (NaN, ±inf,
//! out of range, huge), nearest or bilinear, tinted, any opacity. Checks:
//!
//! * `Texture::new` errors exactly as documented (`InvalidParameter` for a
//!   bad size or too much data, `BufferTooSmall` for too little);
//! * the sprite errors exactly as documented (`NonFiniteCoordinate` for a
//!   non-finite scale or angle, else `InvalidParameter` for a scale outside
//!   `SPRITE_SCALE_RANGE`), from `blend_into` and from `Drawable`, and
//!   draws nothing then;
//! * `blend_into` a recording target: every pixel inside its clip, at most
//!   once, alpha > 0;
//! * through the band renderer (64 × 1..48 frame): every frame pixel sent
//!   once, bands of 1 and 16 rows give the same image;
//! * `Drawable` into a plain `DrawTarget`: no pixel outside it, and exactly
//!   the cut-out of what `blend_into` blends (alpha ≥ 128, its colour).
#![no_main]

use embedded_graphics_core::Drawable;
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888, RgbColor};
use embedded_graphics_core::prelude::*;
use libfuzzer_sys::fuzz_target;
use microraster::blend::{Blend, BlendTarget};
use microraster::render::from_fn;
use microraster::texture::{
    A8, Argb4444, Bilinear, Filter, Nearest, SPRITE_SCALE_RANGE, Sprite, TexelFormat, Texture,
};
use microraster::{Band, ClipRect, Error, Renderer};
use microraster_fuzz::{Input, OnceFrame};
use std::collections::HashMap;

const W: i32 = 64;
const BG: Rgb888 = Rgb888::new(3, 50, 200);

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    match inp.u8() % 4 {
        0 => texture::<A8>(&mut inp),
        1 => texture::<Argb4444>(&mut inp),
        2 => texture::<Gray8>(&mut inp),
        _ => texture::<Rgb565>(&mut inp),
    }
});

/// Storage from fuzzed bits.
trait Store: Copy {
    fn from_bits(v: u16) -> Self;
}
impl Store for u8 {
    fn from_bits(v: u16) -> Self {
        v as u8
    }
}
impl Store for u16 {
    fn from_bits(v: u16) -> Self {
        v
    }
}

fn dim(inp: &mut Input) -> u32 {
    match inp.u8() % 16 {
        0 => inp.pick(&[0, 4096, 4097, u32::MAX]),
        1 => 1 << (inp.u8() % 7),
        _ => 1 + u32::from(inp.u8() % 16),
    }
}

fn texture<F: TexelFormat>(inp: &mut Input)
where
    F::Storage: Store,
{
    let (mut w, mut h) = (dim(inp), dim(inp));
    if u64::from(w) * u64::from(h) > 1 << 13 {
        // Keep the texel buffer small: 4096 × 4096 would cost 32 MB a run.
        if w > 16 { h = h.min(2) } else { w = w.min(2) }
    }
    let n = u64::from(w) * u64::from(h);
    let len = match inp.u8() % 16 {
        0 => n.saturating_sub(1 + u64::from(inp.u8() % 2)),
        1 => n + 1,
        _ => n,
    }
    .min(1 << 14) as usize;
    // Texels: a fuzzed palette of four values, repeated.
    let pal = [inp.u16(), inp.u16(), inp.u16(), inp.u16()].map(F::Storage::from_bits);
    let texels: Vec<F::Storage> = (0..len).map(|i| pal[(i * 7 + i / 5) % 4]).collect();
    let expect = if !(1..=4096).contains(&w) || !(1..=4096).contains(&h) {
        Err(Error::InvalidParameter(microraster::Param::TextureSize))
    } else if (len as u64) < n {
        Err(Error::BufferTooSmall)
    } else if len as u64 > n {
        Err(Error::InvalidParameter(microraster::Param::TextureSize))
    } else {
        Ok(())
    };
    let tex = Texture::<F>::new(&texels, w, h);
    assert_eq!(tex.as_ref().map(|_| ()).map_err(|e| *e), expect, "Texture::new {w}×{h}, {len} texels");
    let Ok(tex) = tex else { return };

    let at = match inp.u8() % 8 {
        0 => Point::new(inp.i32(), inp.i32()),
        1 => Point::new(
            inp.pick(&[i32::MIN, i32::MAX, -4096, 4096]),
            inp.pick(&[i32::MIN, i32::MAX, -4096, 4096]),
        ),
        _ => Point::new(i32::from(inp.u8() as i8) / 2, i32::from(inp.u8() as i8) / 2),
    };
    let scale = match inp.u8() % 8 {
        0 => inp.f32(),
        1 => inp.pick(&[SPRITE_SCALE_RANGE.0, SPRITE_SCALE_RANGE.1, 256.0001, 0.0039, 1.0]),
        2 => f32::from(inp.u8()) / 256.0 + 1.0 / 256.0,
        _ => f32::from(inp.u8() % 64 + 1) / 8.0,
    };
    let angle = match inp.u8() % 4 {
        0 => inp.f32(),
        1 => f32::from(inp.u8() % 8) * core::f32::consts::FRAC_PI_4,
        _ => f32::from(inp.u16() as i16) / 4096.0,
    };
    let tint = [inp.u8(), inp.u8(), inp.u8()];
    let opacity = inp.u8();
    let h = 1 + i32::from(inp.u8() % 48);
    let s = Sprite::<F, Rgb888>::new(&tex).at(at).scale(scale).rotate(angle).tint(tint).opacity(opacity);
    let want = if !scale.is_finite() || !angle.is_finite() {
        Err(Error::NonFiniteCoordinate)
    } else if !(SPRITE_SCALE_RANGE.0..=SPRITE_SCALE_RANGE.1).contains(&scale) {
        Err(Error::InvalidParameter(microraster::Param::SpriteScale))
    } else {
        Ok(())
    };
    if inp.bool() { check(&s.filter(Bilinear), h, want) } else { check(&s.filter(Nearest), h, want) }
}

fn check<F: TexelFormat, Fi: Filter>(s: &Sprite<'_, F, Rgb888, Fi>, h: i32, want: Result<(), Error>) {
    // A recording target: the frame, and a clip reaching far outside it.
    let mut frame = Recorder { clip: ClipRect::new(0, 0, W, h), seen: HashMap::new() };
    assert_eq!(s.blend_into(&mut frame), want, "blend_into");
    let mut wide = Recorder { clip: ClipRect::new(-300, -70, 90, 33), seen: HashMap::new() };
    assert_eq!(s.blend_into(&mut wide), want, "blend_into (wide clip)");
    if want.is_err() {
        assert!(frame.seen.is_empty() && wide.seen.is_empty(), "drawn despite an error");
    }
    // The two clips agree where they overlap.
    for (&(x, y), v) in &frame.seen {
        if y < 33 && x < 90 {
            assert_eq!(wide.seen.get(&(x, y)), Some(v), "({x}, {y}) depends on the clip");
        }
    }

    // Band renderer, bands of 1 and 16 rows.
    let one = banded::<F, Fi, 1>(s, h, want);
    let sixteen = banded::<F, Fi, 16>(s, h, want);
    assert!(one == sixteen, "bands of 1 and 16 rows differ");

    // Drawable: the cut-out of what blend_into blends.
    let mut fb = OnceFrame::new(W, h);
    assert_eq!(s.draw(&mut fb).unwrap(), want, "Drawable");
    for y in 0..h {
        for x in 0..W {
            let cut = frame.seen.get(&(x, y)).filter(|v| v[3] >= 128).map(|v| Rgb888::new(v[0], v[1], v[2]));
            assert_eq!(fb.px[(y * W + x) as usize], cut, "Drawable at ({x}, {y})");
        }
    }
}

fn banded<F: TexelFormat, Fi: Filter, const BH: usize>(
    s: &Sprite<'_, F, Rgb888, Fi>,
    h: i32,
    want: Result<(), Error>,
) -> Vec<Rgb888> {
    let mut band = Band::<Rgb888, 64, BH>::new(Rgb888::BLACK);
    let mut fb = OnceFrame::new(W, h);
    Renderer::new(h as u32, BG)
        .render(
            from_fn(|v| {
                assert_eq!(s.blend_into(v), want, "blend_into a band");
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.px.into_iter().map(|p| p.expect("a frame pixel was never sent")).collect()
}

/// Records what a sprite blends: colour and alpha per pixel, each once.
struct Recorder {
    clip: ClipRect,
    seen: HashMap<(i32, i32), [u8; 4]>,
}

impl BlendTarget<Rgb888> for Recorder {
    fn clip(&self) -> ClipRect {
        self.clip
    }
    fn blend_pixel<B: Blend>(&mut self, _: B, x: i32, y: i32, c: Rgb888, a: u8) {
        assert!(self.clip.contains(x, y), "({x}, {y}) outside {:?}", self.clip);
        assert!(a > 0, "({x}, {y}) blended with alpha 0");
        assert!(self.seen.insert((x, y), [c.r(), c.g(), c.b(), a]).is_none(), "({x}, {y}) blended twice");
    }
}
