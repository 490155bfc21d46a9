//! Blending: every mode × every colour format against an independent `f64`
//! evaluation of the documented equation (exhaustive for channels of up to
//! 6 bits and for `Gray8`, dense for the 8-bit RGB formats), translucent
//! primitives in a banded render, and the back-to-front sort.

use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics_core::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, Rgb555, Rgb565, Rgb666, Rgb888,
};
use microraster::blend::{
    Additive, Blend, BlendBlitter, BlendMode, ColorAdd, ColorSubtract, Mix, Multiply, Replace, back_to_front,
    back_to_front_by, blend_span, view_depth,
};
use microraster::edge::Cull;
use microraster::math::transform::{look_at, translation};
use microraster::math::{Fx, Mat4, Vec3};
use microraster::mesh::Mesh;
use microraster::render::from_fn;
use microraster::{Band, Interpolate, Line, Renderer, SubPoint, Triangle};

/// Rounds `x` to nearest, asserting it is not (numerically) a tie: the
/// documented equations have odd denominators for these formats, so the
/// exact value is at least 1/(2·255·255) away from any half-integer.
fn round_no_tie(x: f64) -> u8 {
    let frac = x - x.floor();
    assert!((frac - 0.5).abs() > 1e-9, "tie at {x}");
    assert!((-1e-9..=255.0 + 1e-9).contains(&x), "out of range {x}");
    (x + 0.5).floor() as u8
}

/// The documented equation of `mode`, in `f64` (independent of the library's
/// integer arithmetic).
fn reference(mode: BlendMode, s: u8, d: u8, m: u8, a: u8) -> u8 {
    let (sf, df, mf, af) = (f64::from(s), f64::from(d), f64::from(m), f64::from(a));
    match mode {
        BlendMode::Replace => s,
        BlendMode::Mix => round_no_tie(df + (sf - df) * af / 255.0),
        BlendMode::Multiply => round_no_tie(df * (1.0 - af / 255.0 * (1.0 - sf / mf))),
        BlendMode::Additive => (d as u32 + round_no_tie(sf * af / 255.0) as u32).min(m as u32) as u8,
        BlendMode::ColorAdd => (d as u32 + s as u32).min(m as u32) as u8,
        BlendMode::ColorSubtract => (i32::from(d) - i32::from(s)).max(0) as u8,
    }
}

/// Blends `src` over `dst` with the zero-sized type of `mode`.
fn by_type<C: Interpolate>(mode: BlendMode, src: C, dst: C, a: u8) -> C {
    match mode {
        BlendMode::Replace => Replace.blend(src, dst, a),
        BlendMode::Mix => Mix.blend(src, dst, a),
        BlendMode::Multiply => Multiply.blend(src, dst, a),
        BlendMode::Additive => Additive.blend(src, dst, a),
        BlendMode::ColorAdd => ColorAdd.blend(src, dst, a),
        BlendMode::ColorSubtract => ColorSubtract.blend(src, dst, a),
    }
}

/// Counts of one format's check: [cases, saturated adds, clamped subtracts].
fn check_format<C: Interpolate + core::fmt::Debug>(values: &[u8]) -> [u64; 3] {
    let m = C::CHANNEL_MAX;
    let mut n = [0u64; 3];
    // Channel k sees the values shifted by a different offset, so channels
    // are not all tested with the same pair at once.
    let chan = |v: u8, k: usize, off: u32| -> u8 {
        if m[k] == 0 { 0 } else { ((u32::from(v) + off * k as u32) % (u32::from(m[k]) + 1)) as u8 }
    };
    let mut row_dst = Vec::with_capacity(256);
    let mut row_src = Vec::with_capacity(256);
    for &s in values {
        for &d in values {
            let sc = [0, 1, 2].map(|k| chan(s, k, 7));
            let dc = [0, 1, 2].map(|k| chan(d, k, 13));
            let (src, dst) = (C::from_channels(sc), C::from_channels(dc));
            assert_eq!((src.to_channels(), dst.to_channels()), (sc, dc));
            for mode in BlendMode::ALL {
                row_dst.clear();
                row_src.clear();
                for a in 0..=255u8 {
                    let want =
                        [0, 1, 2].map(|k| if m[k] == 0 { 0 } else { reference(mode, sc[k], dc[k], m[k], a) });
                    let got = by_type(mode, src, dst, a);
                    assert_eq!(got.to_channels(), want, "{mode:?} s={sc:?} d={dc:?} a={a} max={m:?}");
                    assert_eq!(mode.blend(src, dst, a), got, "runtime {mode:?}");
                    n[0] += 1;
                    for k in 0..3 {
                        if m[k] > 0 {
                            n[1] += u64::from(
                                mode == BlendMode::ColorAdd
                                    && u16::from(sc[k]) + u16::from(dc[k]) > u16::from(m[k]),
                            );
                            n[2] += u64::from(mode == BlendMode::ColorSubtract && sc[k] > dc[k]);
                        }
                    }
                    row_dst.push(dst);
                    row_src.push(src);
                }
                // The span path, one alpha per call, must agree with the pixel path.
                for a in [0u8, 1, 128, 254, 255] {
                    let mut row = row_dst.clone();
                    blend_span(mode, &mut row, row_src.iter().copied(), a);
                    assert!(row.iter().all(|&c| c == mode.blend(src, dst, a)), "{mode:?} span a={a}");
                }
            }
        }
    }
    n
}

fn all(max: u8) -> Vec<u8> {
    (0..=max).collect()
}

/// Every value with step 3, plus the corners and their neighbours.
fn dense() -> Vec<u8> {
    let mut v: Vec<u8> = (0..=255).step_by(3).collect();
    v.extend([1, 2, 127, 128, 253, 254, 255]);
    v.sort();
    v.dedup();
    v
}

#[test]
fn every_mode_and_format_matches_the_reference_small_channels() {
    let mut total = [0u64; 3];
    let mut add = |n: [u64; 3]| (0..3).for_each(|i| total[i] += n[i]);
    add(check_format::<BinaryColor>(&all(1)));
    add(check_format::<Gray2>(&all(3)));
    add(check_format::<Gray4>(&all(15)));
    add(check_format::<Rgb555>(&all(31)));
    add(check_format::<Bgr555>(&all(31)));
    add(check_format::<Rgb565>(&all(63)));
    add(check_format::<Bgr565>(&all(63)));
    add(check_format::<Rgb666>(&all(63)));
    add(check_format::<Bgr666>(&all(63)));
    println!(
        "≤ 6-bit formats: {} blends exhaustively checked, {} saturated adds, {} subtracts at 0",
        total[0], total[1], total[2]
    );
    assert!(total[1] > 100_000 && total[2] > 100_000, "saturation corners not exercised");
}

#[test]
fn every_mode_and_format_matches_the_reference_8_bit() {
    let g = check_format::<Gray8>(&all(255));
    assert_eq!(g[0], 256 * 256 * 256 * 6, "Gray8 exhaustive");
    let r = check_format::<Rgb888>(&dense());
    let b = check_format::<Bgr888>(&dense());
    println!("8-bit: Gray8 {} (exhaustive), Rgb888 {}, Bgr888 {} blends checked", g[0], r[0], b[0]);
    assert!(g[1] > 0 && g[2] > 0 && r[1] > 0 && b[2] > 0);
}

#[test]
fn faulty_channels_above_the_maximum_do_not_panic() {
    // A user colour type could report channels above CHANNEL_MAX; the channel
    // functions take any u8 without overflow.
    for mode in BlendMode::ALL {
        for (s, d, m) in [(255, 255, 1), (200, 3, 3), (3, 200, 3), (255, 0, 31), (0, 255, 63)] {
            for a in [0, 1, 128, 255] {
                let _ = mode.channel(s, d, m, a);
            }
        }
    }
}

/// A translucent triangle over an opaque one, rendered in 3-row bands.
#[test]
fn translucent_triangle_over_opaque_in_bands() {
    let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
    // Opaque: centres with x + y ≤ 4 (the hypotenuse is a right edge).
    let opaque = Triangle::flat([p(0, 0), p(6, 0), p(0, 6)], Gray4::new(12));
    // Translucent: x − y ≥ 2 (the hypotenuse is a left edge, ties included), x ≤ 7.
    let glass = Triangle::flat([p(2, 0), p(8, 0), p(8, 6)], Gray4::new(15));
    let mut band = Band::<Gray4, 8, 3>::new(Gray4::new(0));
    let mut display = MockDisplay::<Gray4>::new();
    Renderer::new(7, Gray4::new(0))
        .render(
            from_fn(|view| {
                opaque.draw(view, Cull::None);
                glass.draw(&mut BlendBlitter::new(view, Mix, 128), Cull::None);
                Ok(())
            }),
            &mut band,
            &mut display,
        )
        .unwrap();
    // Over 0: round(15·128/255) = round(7.53) = 8.
    // Over 12: round((12·127 + 15·128)/255) = round(13.51) = 14 = E.
    display.assert_pattern(&[
        "CCEEE888", //
        "CCCE8888", "CCC08888", "CC000888", "C0000088", "00000008", "00000000",
    ]);
}

#[test]
fn runtime_mode_blitter_and_lines() {
    let p = |x, y| SubPoint::<4>::pixel_center(x, y).unwrap();
    let mut band = Band::<Rgb565, 4, 1>::new(Rgb565::new(0, 0, 0));
    let mut view = band.view(0, 1, Rgb565::new(10, 20, 30));
    // A horizontal midpoint line lights x = 0..3 (end exclusive) through set_pixel.
    let line = Line::new(p(0, 0), p(3, 0), Rgb565::new(25, 50, 5));
    line.draw(&mut BlendBlitter::new(&mut view, BlendMode::ColorAdd, 0));
    line.draw(&mut BlendBlitter::new(&mut view, BlendMode::ColorSubtract, 0));
    // (10 + 25 → 31) − 25 = 6; (20 + 50 → 63) − 50 = 13; (30 + 5 → 31) − 5 = 26.
    let px = Rgb565::new(6, 13, 26);
    assert_eq!(band.rows()[0], [px, px, px, Rgb565::new(10, 20, 30)]);
}

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

#[test]
fn back_to_front_sorts_farthest_first() {
    let mut rng = Rng(0x5eed);
    for len in 0..40usize {
        let mut items: Vec<(usize, f32)> =
            (0..len).map(|i| (i, (rng.next() % 64) as f32 * 0.25 - 4.0)).collect();
        let mut keys: Vec<u32> = items.iter().map(|x| x.1.to_bits()).collect();
        back_to_front(&mut items, |x| x.1);
        for w in items.windows(2) {
            assert!(w[0].1 >= w[1].1, "{w:?}");
        }
        // A permutation: the same depths and every key once.
        let mut after: Vec<u32> = items.iter().map(|x| x.1.to_bits()).collect();
        keys.sort();
        after.sort();
        assert_eq!(keys, after);
        let mut ids: Vec<usize> = items.iter().map(|x| x.0).collect();
        ids.sort();
        assert_eq!(ids, (0..len).collect::<Vec<_>>());

        let mut fx: Vec<Fx> = (0..len).map(|_| Fx::from_bits((rng.next() % 1000) as i32 - 500)).collect();
        back_to_front_by(&mut fx, |v| *v);
        assert!(fx.windows(2).all(|w| w[0] >= w[1]));
    }
    // NaN does not break the sort.
    let mut v = [1.0f32, f32::NAN, 3.0, -2.0];
    back_to_front(&mut v, |x| *x);
    assert!(v[0].is_nan() && v[1..] == [3.0, 1.0, -2.0]);
}

#[test]
fn view_depth_orders_meshes_along_the_view_direction() {
    static POS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    static IDX: [[u16; 3]; 1] = [[0, 1, 2]];
    let mesh = Mesh::new(&POS, &[], &IDX, ([0.25, 0.25, 0.0], 1.0));
    // Camera at x = 10 looking towards −x: depth grows as x decreases.
    let view =
        look_at(Vec3::new(10.0f32, 0.0, 0.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
    let mut meshes: Vec<(&str, Mat4<f32>)> = [("x=2", 2.0), ("x=-3", -3.0), ("x=7", 7.0), ("x=0", 0.0)]
        .map(|(n, x)| (n, translation(Vec3::new(x, 0.0, 0.0))))
        .into();
    let mut keyed: Vec<(&str, f32)> = meshes.iter().map(|(n, m)| (*n, view_depth(&view, m, &mesh))).collect();
    back_to_front(&mut keyed, |k| k.1);
    assert_eq!(keyed.iter().map(|k| k.0).collect::<Vec<_>>(), ["x=-3", "x=0", "x=2", "x=7"]);
    // The centre is at x + 0.25: depth 10 − (x + 0.25).
    assert!((keyed[0].1 - 12.75).abs() < 1e-4 && (keyed[3].1 - 2.75).abs() < 1e-4, "{keyed:?}");
    // The closure form sorts the same way.
    back_to_front(&mut meshes, |(_, m)| view_depth(&view, m, &mesh));
    assert_eq!(meshes.iter().map(|k| k.0).collect::<Vec<_>>(), ["x=-3", "x=0", "x=2", "x=7"]);
}
