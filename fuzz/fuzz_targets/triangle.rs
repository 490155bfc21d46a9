//! Triangle coverage against the exact `i128` reference, inside the target.
//!
//! For a subpixel setting `S ∈ 0..=8`, three vertices (biased towards the
//! ±2^28 limit, pixel centres and corners, the fast-path extent) and a clip
//! rectangle of up to 96 × 96 pixels:
//! * `SubPoint::new` fails exactly when a coordinate is beyond ±2^28;
//! * `TriangleSpans` equals the exact top-left-rule coverage pixel for pixel,
//!   rows strictly increasing, every pixel inside the clip, none twice, each
//!   cull mode dropping exactly its winding, the fast path taken as documented;
//! * a Gouraud triangle drawn through a `Blitter` covers the same pixels, each
//!   channel within 0.5 + 2^-7 of the exact barycentric value;
//! * `SubPoint::from_f32` / `from_fixed` round exactly as documented.
#![no_main]

use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
use fixed::types::I16F16;
use libfuzzer_sys::fuzz_target;
use microraster::blit::Blitter;
use microraster::edge::{Cull, TriangleSpans, fast_path_extent_px};
use microraster::{ClipRect, Error, SubPoint, Triangle};
use microraster_fuzz::{ExactTriangle, Input, snap_reference};

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

const LIM: i64 = 1 << 28;

fn run<const S: u32>(inp: &mut Input) {
    snapping::<S>(inp);
    let c: [i64; 6] = core::array::from_fn(|_| inp.coord(S));
    let mut v = [SubPoint::<S>::default(); 3];
    for i in 0..3 {
        let (x, y) = (c[2 * i], c[2 * i + 1]);
        let (xi, yi) = (
            x.clamp(i32::MIN as i64, i32::MAX as i64) as i32,
            y.clamp(i32::MIN as i64, i32::MAX as i64) as i32,
        );
        let r = SubPoint::<S>::new(xi, yi);
        let ok = (xi as i64).abs() <= LIM && (yi as i64).abs() <= LIM;
        assert_eq!(r.is_ok(), ok, "SubPoint::<{S}>::new({xi}, {yi}) = {r:?}");
        match r {
            Ok(p) => v[i] = p,
            Err(e) => {
                assert_eq!(e, Error::CoordinateOutOfRange);
                return;
            }
        }
    }
    // The clip near a vertex or the centroid (so the triangle is usually
    // visible), or anywhere.
    let k = inp.u8() % 4;
    let (px, py) = if k < 3 {
        (i64::from(v[k as usize].x()) >> S, i64::from(v[k as usize].y()) >> S)
    } else {
        let sx: i64 = v.iter().map(|p| i64::from(p.x())).sum::<i64>() / 3;
        let sy: i64 = v.iter().map(|p| i64::from(p.y())).sum::<i64>() / 3;
        (sx >> S, sy >> S)
    };
    let clip = inp.clip(px, py, 96);
    let pts = v.map(|p| (p.x(), p.y()));
    let exact = ExactTriangle::new(pts, S);

    let mut counts = [0usize; 3];
    for (ci, cull) in [Cull::None, Cull::Clockwise, Cull::CounterClockwise].into_iter().enumerate() {
        let spans = TriangleSpans::new(v, clip, cull);
        let fast = spans.is_fast_path();
        let mut got = vec![false; area(clip)];
        let mut prev = i32::MIN;
        for s in spans {
            assert!(s.len >= 1 && s.y > prev, "S={S} {pts:?} {clip:?}: bad span order {s:?}");
            prev = s.y;
            for x in s.x..s.x + s.len as i32 {
                assert!(clip.contains(x, s.y), "S={S} {pts:?}: span {s:?} outside {clip:?}");
                let i = index(clip, x, s.y);
                assert!(!got[i], "S={S} {pts:?}: pixel ({x}, {}) twice", s.y);
                got[i] = true;
            }
        }
        let drop = match (cull, &exact) {
            (_, None) => true,
            (Cull::None, _) => false,
            (Cull::Clockwise, Some(t)) => t.clockwise,
            (Cull::CounterClockwise, Some(t)) => !t.clockwise,
        };
        for y in clip.y0()..clip.y1() {
            for x in clip.x0()..clip.x1() {
                let want = !drop && exact.as_ref().is_some_and(|t| t.covers(x, y));
                let g = got[index(clip, x, y)];
                assert_eq!(g, want, "S={S} SubPoint::new {pts:?} {clip:?} {cull:?}: pixel ({x}, {y})");
                counts[ci] += usize::from(g);
            }
        }
        // Fast-path documentation: a bounding box of at most
        // fast_path_extent_px(S) px takes it when anything is drawn; more
        // than one pixel beyond never does.
        let side = |f: fn(&(i32, i32)) -> i32| {
            let c = pts.iter().map(|p| i64::from(f(p)));
            c.clone().max().unwrap() - c.min().unwrap()
        };
        let side = side(|p| p.0).max(side(|p| p.1));
        let one = 1i64 << S;
        if counts[ci] > 0 && side <= fast_path_extent_px(S) * one {
            assert!(fast, "S={S} {pts:?}: bbox fits the fast path but took the wide one");
        }
        if side > (fast_path_extent_px(S) + 1) * one {
            assert!(!fast, "S={S} {pts:?}: bbox too big for i32 but took the fast path");
        }
    }
    assert_eq!(counts[0], counts[1] + counts[2], "S={S} {pts:?}: the cull modes split the coverage");

    // Gouraud through a Blitter: same pixels, channels within 0.5 + 2^-7.
    let cols = [0, 1, 2].map(|_| Rgb888::new(inp.u8(), inp.u8(), inp.u8()));
    let mut rec = Recorder { clip, px: vec![None; area(clip)] };
    Triangle::gouraud(v, cols).draw(&mut rec, Cull::None);
    for y in clip.y0()..clip.y1() {
        for x in clip.x0()..clip.x1() {
            let got = rec.px[index(clip, x, y)];
            let want = exact.as_ref().is_some_and(|t| t.covers(x, y));
            assert_eq!(got.is_some(), want, "S={S} Gouraud {pts:?} {clip:?}: pixel ({x}, {y})");
            if let Some(c) = got {
                let l = ExactTriangle::bary(pts, S, x, y);
                let ch = |c: Rgb888| [c.r(), c.g(), c.b()];
                let (got, vc) = (ch(c), cols.map(ch));
                for k in 0..3 {
                    let exact: f64 = (0..3).map(|i| l[i] * f64::from(vc[i][k])).sum();
                    let err = (f64::from(got[k]) - exact).abs();
                    assert!(
                        err <= 0.5 + 1.0 / 128.0 + 1e-9,
                        "S={S} Gouraud {pts:?} {cols:?}: pixel ({x}, {y}) channel {k} = {} vs exact {exact}",
                        got[k]
                    );
                }
            }
        }
    }
}

/// `from_f32` and `from_fixed` against exact rounding.
fn snapping<const S: u32>(inp: &mut Input) {
    let (x, y) = (inp.f32(), inp.f32());
    let got = SubPoint::<S>::from_f32(x, y);
    // x is checked before y.
    let want = match (snap_reference(x, S), snap_reference(y, S)) {
        (None, _) => Err(Error::NonFiniteCoordinate),
        (Some(Err(())), _) => Err(Error::CoordinateOutOfRange),
        (_, None) => Err(Error::NonFiniteCoordinate),
        (_, Some(Err(()))) => Err(Error::CoordinateOutOfRange),
        (Some(Ok(a)), Some(Ok(b))) => Ok((a as i32, b as i32)),
    };
    assert_eq!(got.map(|p| (p.x(), p.y())), want, "SubPoint::<{S}>::from_f32({x:e}, {y:e})");

    let b = inp.i32();
    let got = SubPoint::<S>::from_fixed(I16F16::from_bits(b), I16F16::ZERO).map(|p| p.x());
    // b / 2^16 px = b · 2^(S−16) subpixels, rounded half to even (exact in f64).
    let want = (f64::from(b) * 2f64.powi(S as i32 - 16)).round_ties_even() as i32; // |b·2^-8| < 2^28 always
    assert_eq!(got, Ok(want), "SubPoint::<{S}>::from_fixed(bits {b})");
}

fn area(c: ClipRect) -> usize {
    ((c.x1() - c.x0()).max(0) * (c.y1() - c.y0()).max(0)) as usize
}

fn index(c: ClipRect, x: i32, y: i32) -> usize {
    ((y - c.y0()) * (c.x1() - c.x0()) + (x - c.x0())) as usize
}

struct Recorder {
    clip: ClipRect,
    px: Vec<Option<Rgb888>>,
}

impl Blitter<Rgb888> for Recorder {
    fn clip(&self) -> ClipRect {
        self.clip
    }
    fn set_pixel(&mut self, x: i32, y: i32, color: Rgb888) {
        assert!(self.clip.contains(x, y), "pixel ({x}, {y}) outside {:?}", self.clip);
        let i = index(self.clip, x, y);
        assert!(self.px[i].is_none(), "pixel ({x}, {y}) drawn twice");
        self.px[i] = Some(color);
    }
}
