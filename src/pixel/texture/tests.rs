//! Unit tests of the colour arithmetic against f64 (exhaustive where the
//! input space allows) and of the constructors. Sampling is tested against an
//! f64 reference in `tests/integration/texture.rs`.

use super::shade::{channel_to_8bit, div255_round};
use super::*;
use crate::Interpolate;
use embedded_graphics_core::pixelcolor::{
    Bgr565, BinaryColor, Gray2, Gray4, Gray8, Rgb555, Rgb565, Rgb666, Rgb888,
};

/// Round half up in f64, for the references.
fn round(x: f64) -> f64 {
    (x + 0.5).floor()
}

#[test]
fn div255_is_exact_rounding_over_its_range() {
    for x in 0..=255 * 255u32 {
        assert_eq!(f64::from(div255_round(x)), round(f64::from(x) / 255.0), "{x}");
    }
}

#[test]
fn modulate_is_exact_for_every_pair() {
    for t in 0..=255u8 {
        for c in 0..=255u8 {
            let want = round(f64::from(t) * f64::from(c) / 255.0) as u8;
            assert_eq!(modulate([t, c, t], [c, t, 255]), [want, want, t]);
        }
    }
    assert_eq!(modulate([7, 8, 9], [0; 3]), [0; 3]);
}

#[test]
fn native_to_8bit_is_exact_for_every_maximum() {
    for max in 0..=255u8 {
        for c in 0..=255u8 {
            let want = if max == 0 { 0.0 } else { round(f64::from(c.min(max)) * 255.0 / f64::from(max)) };
            assert_eq!(f64::from(channel_to_8bit(c, max)), want, "c {c} max {max}");
        }
    }
    assert_eq!(to_rgb8::<Rgb565>([31, 63, 31]), [255; 3]);
    assert_eq!(to_rgb8::<Rgb666>([1, 2, 3]), [4, 8, 12]);
    assert_eq!(to_rgb8::<Bgr565>([0, 40, 99]), [0, 162, 255]); // 40·255/63 = 161.9; 99 → max
    assert_eq!(to_rgb8::<Gray2>([2, 9, 9]), [170; 3]);
    assert_eq!(to_rgb8::<BinaryColor>([1, 0, 0]), [255; 3]);
    assert_eq!(to_rgb8::<Rgb888>([1, 2, 3]), [1, 2, 3]);
}

#[test]
fn luma_within_bound_on_every_input() {
    let mut worst = 0f64;
    for rgb in 0..1u32 << 24 {
        let [r, g, b] = [rgb >> 16, (rgb >> 8) & 255, rgb & 255].map(|c| c as u8);
        let exact = 0.299 * f64::from(r) + 0.587 * f64::from(g) + 0.114 * f64::from(b);
        let e = (f64::from(luma([r, g, b])) - exact).abs();
        worst = worst.max(e);
    }
    assert!(worst <= 0.5 + 0.003, "luma error {worst}");
    for l in 0..=255u8 {
        assert_eq!(luma([l; 3]), l);
    }
}

fn check_from_rgb8<C: Interpolate + core::fmt::Debug>() {
    let m = C::CHANNEL_MAX;
    let grey = m[1] == 0;
    for v in 0..=255u8 {
        let rgb = [v, 255 - v, v / 3];
        let got = from_rgb8::<C>(rgb).to_channels();
        if grey {
            // Through the luma: double rounding, bound from the docs.
            let exact = (0.299 * f64::from(rgb[0]) + 0.587 * f64::from(rgb[1]) + 0.114 * f64::from(rgb[2]))
                * f64::from(m[0])
                / 255.0;
            let bound = 0.5 + (0.5 + 0.003) * f64::from(m[0]) / 255.0;
            assert!((f64::from(got[0]) - exact).abs() <= bound, "{rgb:?} → {got:?}");
            // A grey input is exactly that grey, rounded once.
            assert_eq!(
                f64::from(from_rgb8::<C>([v; 3]).to_channels()[0]),
                round(f64::from(v) * f64::from(m[0]) / 255.0)
            );
        } else {
            for k in 0..3 {
                assert_eq!(f64::from(got[k]), round(f64::from(rgb[k]) * f64::from(m[k]) / 255.0), "{rgb:?}");
            }
        }
    }
}

#[test]
fn from_rgb8_rounds_to_nearest() {
    check_from_rgb8::<Rgb565>();
    check_from_rgb8::<Rgb555>();
    check_from_rgb8::<Rgb666>();
    check_from_rgb8::<Rgb888>();
    check_from_rgb8::<Bgr565>();
    check_from_rgb8::<Gray8>();
    check_from_rgb8::<Gray4>();
    check_from_rgb8::<Gray2>();
    check_from_rgb8::<BinaryColor>();
    // 8 → native → 8 is the identity on the native levels.
    for c in 0..=63u8 {
        let n = [c / 2, c, 31 - c / 2];
        assert_eq!(from_rgb8::<Rgb565>(to_rgb8::<Rgb565>(n)).to_channels(), n);
    }
}

#[test]
fn rgb565_bit_replication_within_documented_bound() {
    let mut worst = 0f64;
    for raw in 0..=u16::MAX {
        let got = Rgb565::expand(raw);
        let c = Rgb565::from(embedded_graphics_core::pixelcolor::raw::RawU16::new(raw));
        let native = c.to_channels();
        for k in 0..3 {
            let exact = f64::from(native[k]) * 255.0 / f64::from(Rgb565::CHANNEL_MAX[k]);
            worst = worst.max((f64::from(got[k]) - exact).abs());
        }
        // The ends are exact.
        if raw == 0 || raw == u16::MAX {
            assert_eq!(got, [u8::from(raw != 0) * 255; 3]);
        }
    }
    assert!(worst <= 0.72 && worst > 0.7, "{worst}");
    assert_eq!(Gray8::expand(3), [3; 3]);
}

#[test]
fn constructor_checks_sizes_and_length() {
    let data = [0u16; 12];
    assert!(Texture::<Rgb565>::new(&data, 4, 3).is_ok());
    assert!(Texture::<Rgb565>::new(&data, 12, 1).is_ok());
    assert_eq!(Texture::<Rgb565>::new(&data, 5, 3).err(), Some(Error::BufferTooSmall));
    assert_eq!(
        Texture::<Rgb565>::new(&data, 3, 3).err(),
        Some(Error::InvalidParameter(crate::Param::TextureSize))
    );
    assert_eq!(
        Texture::<Rgb565>::new(&data, 0, 3).err(),
        Some(Error::InvalidParameter(crate::Param::TextureSize))
    );
    assert_eq!(
        Texture::<Rgb565>::new(&data, 4, 0).err(),
        Some(Error::InvalidParameter(crate::Param::TextureSize))
    );
    assert_eq!(
        Texture::<Rgb565>::new(&[], 4097, 1).err(),
        Some(Error::InvalidParameter(crate::Param::TextureSize))
    );
    assert_eq!(
        Texture::<Rgb565>::new(&[], u32::MAX, u32::MAX).err(),
        Some(Error::InvalidParameter(crate::Param::TextureSize))
    );
    static ROWS: [[u8; 4096]; 1] = [[9; 4096]];
    static WIDE: Texture<'static, Gray8> = Texture::from_rows(&ROWS);
    assert_eq!((WIDE.width(), WIDE.height(), WIDE.data().len()), (4096, 1, 4096));
    let t = Texture::<Gray8>::new(&[1, 2, 3, 4, 5, 6], 3, 2).unwrap();
    assert_eq!(t.texel(2, 1), Some([6; 3]));
    assert_eq!((t.texel(3, 0), t.texel(0, 2)), (None, None));
}

#[test]
fn power_of_two_sizes_are_detected_per_axis() {
    for (n, pow2) in [(1, Some(0)), (2, Some(1)), (3, None), (64, Some(6)), (96, None), (4096, Some(12))] {
        assert_eq!(Axis::new(n).pow2, pow2, "{n}");
    }
}

/// Rgb565A8 against its documented layout, on every colour and alpha: the
/// colour is the big-endian `Rgb565` bits (expanded exactly as a
/// `Texture<Rgb565>` texel), the alpha the third byte unchanged.
#[test]
fn rgb565a8_is_rgb565_colour_and_exact_alpha() {
    for raw in 0..=u16::MAX {
        let a = (raw % 251) as u8 ^ (raw >> 8) as u8; // every alpha, many times over
        let t = Rgb565A8::texel(raw, a);
        assert_eq!(t, [(raw >> 8) as u8, raw as u8, a]);
        assert_eq!(Rgb565A8::expand(t), Rgb565::expand(raw), "{raw:#06x}");
        assert_eq!(Rgb565A8::alpha(t), a);
    }
    for a in 0..=255u8 {
        assert_eq!(Rgb565A8::alpha(Rgb565A8::texel(0x1234, a)), a);
    }
    // Through a texture: texel and texel_rgba agree with expand and alpha.
    let texels = [Rgb565A8::texel(0xF800, 0), Rgb565A8::texel(0x001F, 1), Rgb565A8::texel(0xFFFF, 254)];
    let tex = Texture::<Rgb565A8>::new(&texels, 3, 1).unwrap();
    assert_eq!(tex.texel(0, 0), Some([255, 0, 0]));
    assert_eq!(tex.texel_rgba(1, 0), Some([0, 0, 255, 1]));
    assert_eq!(tex.texel_rgba(2, 0), Some([255, 255, 255, 254]));
    assert_eq!(tex.texel_rgba(3, 0), None);
}
