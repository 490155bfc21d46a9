//! Midpoint lines against the documented rule, evaluated exactly in `i128`
//! inside the target: for `S ∈ 0..=8`, end points anywhere in (and beyond)
//! the ±2^28 range and a clip rectangle of up to 300 × 300 pixels anywhere
//! in the frame, `line_pixels` must equal the reference pixel for pixel and
//! in order, report its exact length, stay inside the clip, and
//! `line_rows` must contain every drawn row (and be exact for lines inside
//! the largest frame). A `Line` drawn through the band renderer must light
//! the same pixels.
#![no_main]

use embedded_graphics_core::pixelcolor::BinaryColor;
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;
use libfuzzer_sys::fuzz_target;
use microraster::line::{line_pixels, line_rows};
use microraster::{Band, ClipRect, Line, Primitive, Renderer, SubPoint};
use microraster_fuzz::{Input, line_reference};

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    match inp.u8() % 9 {
        0 => run::<0>(&mut inp),
        1 => run::<1>(&mut inp),
        2 => run::<2>(&mut inp),
        3 => run::<3>(&mut inp),
        4 => run::<4>(&mut inp),
        5 => run::<5>(&mut inp),
        6 => run::<6>(&mut inp),
        7 => run::<7>(&mut inp),
        _ => run::<8>(&mut inp),
    }
});

fn run<const S: u32>(inp: &mut Input) {
    let lim = 1i64 << 28;
    let c: [i64; 4] = core::array::from_fn(|_| inp.coord(S).clamp(-lim, lim));
    let a = SubPoint::<S>::new(c[0] as i32, c[1] as i32).unwrap();
    // The end point: independent, or a short / axis-aligned / diagonal step.
    let b = match inp.u8() % 4 {
        0 => SubPoint::<S>::new(c[2] as i32, c[3] as i32).unwrap(),
        k => {
            let d = i64::from(inp.u16() as i16);
            let (dx, dy) = match k {
                1 => (d, 0),
                2 => (d, d * i64::from(inp.u8() as i8) / 64),
                _ => (d, -d),
            };
            let (dx, dy) = if inp.bool() { (dy, dx) } else { (dx, dy) };
            SubPoint::<S>::new((c[0] + dx).clamp(-lim, lim) as i32, (c[1] + dy).clamp(-lim, lim) as i32)
                .unwrap()
        }
    };
    let (pa, pb) = ((a.x(), a.y()), (b.x(), b.y()));
    let mid =
        ((i64::from(pa.0) + i64::from(pb.0)) >> (S + 1), (i64::from(pa.1) + i64::from(pb.1)) >> (S + 1));
    let k = inp.u8() % 3;
    let near =
        [(i64::from(pa.0) >> S, i64::from(pa.1) >> S), (i64::from(pb.0) >> S, i64::from(pb.1) >> S), mid];
    let clip = inp.clip(near[k as usize].0, near[k as usize].1, 300);

    let got: Vec<(i32, i32)> = line_pixels(a, b, clip).collect();
    let want = line_reference(pa, pb, S, clip);
    assert_eq!(got, want, "S={S} a={pa:?} b={pb:?} {clip:?}");
    assert_eq!(line_pixels(a, b, clip).len(), got.len());
    assert!(got.iter().all(|&(x, y)| clip.contains(x, y)));
    let rows = line_rows(a, b);
    for &(_, y) in &got {
        let (r0, r1) = rows.expect("pixels drawn but line_rows is None");
        assert!(r0 <= y && y <= r1, "S={S} a={pa:?} b={pb:?}: row {y} outside {rows:?}");
    }
    let frame = 0..(4096i64 << S);
    if [pa.0, pa.1, pb.0, pb.1].iter().all(|v| frame.contains(&i64::from(*v))) {
        let all = line_reference(pa, pb, S, ClipRect::new(0, 0, 4096, 4096));
        let exact = all.iter().map(|p| p.1).min().zip(all.iter().map(|p| p.1).max());
        assert_eq!(rows, exact, "S={S} a={pa:?} b={pb:?}: line_rows not exact");
    }

    // Through the band renderer (frame 64 × 40 at the clip's origin is not
    // needed: the frame is fixed at (0, 0), the line is wherever it is).
    let frame_h = 1 + u32::from(inp.u8() % 40);
    let scene = [Primitive::from(Line::new(a, b, BinaryColor::On))];
    let mut band = Band::<BinaryColor, 64, 7>::new(BinaryColor::Off);
    let mut fb = Frame { h: frame_h, on: vec![0u8; 64 * frame_h as usize] };
    Renderer::new(frame_h, BinaryColor::Off).render(&scene, &mut band, &mut fb).unwrap();
    let frame_clip = ClipRect::new(0, 0, 64, frame_h as i32);
    let want = line_reference(pa, pb, S, frame_clip);
    let mut lit: Vec<(i32, i32)> =
        (0..fb.on.len()).filter(|&i| fb.on[i] == 2).map(|i| ((i % 64) as i32, (i / 64) as i32)).collect();
    let mut want_sorted = want.clone();
    want_sorted.sort_by_key(|&(x, y)| (y, x));
    lit.sort_by_key(|&(x, y)| (y, x));
    assert_eq!(lit, want_sorted, "S={S} a={pa:?} b={pb:?}: band renderer");
    assert!(fb.on.iter().all(|&w| w >= 1), "a frame pixel was never sent");
}

/// A 64-wide frame recording each pixel: 0 unsent, 1 off, 2 on; sending a
/// pixel twice or outside the frame fails.
struct Frame {
    h: u32,
    on: Vec<u8>,
}

impl OriginDimensions for Frame {
    fn size(&self) -> Size {
        Size::new(64, self.h)
    }
}

impl DrawTarget for Frame {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            assert!(
                p.x >= 0 && p.y >= 0 && p.x < 64 && (p.y as u32) < self.h,
                "pixel {p:?} outside the frame"
            );
            let i = (p.y * 64 + p.x) as usize;
            assert_eq!(self.on[i], 0, "pixel {p:?} sent twice");
            self.on[i] = if c.is_on() { 2 } else { 1 };
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = BinaryColor>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)))
    }
}
