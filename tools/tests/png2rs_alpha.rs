//! `png2rs`'s formats with alpha (`rgb565a8`, `argb4444`, `a8`) against
//! channels rounded in f64 from the documented rules, and the formats
//! without alpha refusing translucent pixels unless told to drop them.

mod common;

use microraster::texture::{A8, Argb4444, Rgb565A8, Sampler, Texture};
use microraster_tools::png::convert::{Alpha, Format, Texels, convert};
use microraster_tools::png::decode::decode;
use microraster_tools::png::emit;
use png::{BitDepth, ColorType};

use common::{Rng, encode, ref_rgb565};

#[test]
fn translucent_pixels_are_rejected_unless_ignored() {
    let data = [10, 20, 30, 255, 40, 50, 60, 0, 70, 80, 90, 254];
    let image = decode(&encode(3, 1, ColorType::Rgba, BitDepth::Eight, &data, None, None)).unwrap();
    assert_eq!(
        convert(&image, Format::Gray8, Alpha::Reject).unwrap_err(),
        "2 pixels are not fully opaque (the first at x 1, y 0); gray8 textures have no alpha: to keep it \
         use --format rgb565a8, argb4444 or a8; to drop it pass --ignore-alpha"
    );
    // Every format without alpha says the same; the alpha formats convert.
    assert!(
        convert(&image, Format::Rgb565, Alpha::Reject).unwrap_err().contains("rgb565 textures have no alpha")
    );
    for f in Format::ALL.into_iter().filter(|f| f.has_alpha()) {
        assert_eq!(convert(&image, f, Alpha::Reject).unwrap().1, 2, "{f:?}");
    }
    let (t, n) = convert(&image, Format::Rgb565, Alpha::Ignore).unwrap();
    assert_eq!(n, 2);
    let want: Vec<u16> =
        data.chunks(4).map(|c| ref_rgb565([0, 1, 2].map(|k| f64::from(c[k])), 255.0)).collect();
    assert_eq!(t, Texels::Rgb565(want));
}

/// The alpha formats against channels and alpha rounded in f64: Argb4444
/// `round(v·15/max)` per nibble, A8 `round(a·255/max)`, Rgb565A8 the
/// reference Rgb565 bits big-endian and the A8 alpha.
fn check_alpha(png: &[u8], rgba: &[[f64; 4]], max: f64) {
    let image = decode(png).unwrap();
    let (Texels::Argb4444(t4), n) = convert(&image, Format::Argb4444, Alpha::Reject).unwrap() else {
        panic!()
    };
    let (Texels::A8(t8), _) = convert(&image, Format::A8, Alpha::Reject).unwrap() else { panic!() };
    let (Texels::Rgb565A8(t24), _) = convert(&image, Format::Rgb565A8, Alpha::Reject).unwrap() else {
        panic!()
    };
    assert_eq!(n, rgba.iter().filter(|c| c[3] != max).count(), "pixels not opaque");
    let q = |v: f64, m: f64| (v * m / max).round() as u16;
    for (i, c) in rgba.iter().enumerate() {
        let want = (q(c[3], 15.0) << 12) | (q(c[0], 15.0) << 8) | (q(c[1], 15.0) << 4) | q(c[2], 15.0);
        assert_eq!(t4[i], want, "texel {i} of {c:?}/{max}");
        assert_eq!(u16::from(t8[i]), q(c[3], 255.0), "alpha {i}");
        let colour = ref_rgb565([c[0], c[1], c[2]], max);
        assert_eq!(
            t24[i],
            [(colour >> 8) as u8, colour as u8, q(c[3], 255.0) as u8],
            "texel {i} of {c:?}/{max}"
        );
    }
    let t24tex = Texture::<Rgb565A8>::new(&t24, image.width, image.height).unwrap();
    let colour = ref_rgb565([rgba[0][0], rgba[0][1], rgba[0][2]], max);
    let [r, g, b, a] = t24tex.texel_rgba(0, 0).unwrap();
    assert_eq!(
        (u16::from(r) >> 3, u16::from(g) >> 2, u16::from(b) >> 3),
        (colour >> 11, (colour >> 5) & 63, colour & 31)
    );
    assert_eq!(u16::from(a), q(rgba[0][3], 255.0));
    // Through a texture: the texel's alpha is the PNG's, at 4 or 8 bits.
    let tex = Texture::<Argb4444>::new(&t4, image.width, image.height).unwrap();
    let mask = Texture::<A8>::new(&t8, image.width, image.height).unwrap();
    let [_, _, _, a] = tex.sample_rgba(Sampler::NEAREST_CLAMP, [0, 0]);
    assert_eq!(f64::from(a), (rgba[0][3] * 15.0 / max).round() * 17.0);
    assert_eq!(mask.texel_rgba(0, 0), Some([255, 255, 255, q(rgba[0][3], 255.0) as u8]));
}

#[test]
fn alpha_formats_keep_the_alpha_channel() {
    let mut rng = Rng(7);
    let (w, h) = (9, 4);
    // 8-bit RGBA.
    let data = rng.bytes(w * h * 4);
    let rgba: Vec<[f64; 4]> = data.chunks(4).map(|c| [0, 1, 2, 3].map(|k| f64::from(c[k]))).collect();
    check_alpha(&encode(9, 4, ColorType::Rgba, BitDepth::Eight, &data, None, None), &rgba, 255.0);
    // 16-bit RGBA: rounded once from 16 bits.
    let data = rng.bytes(w * h * 8);
    let rgba16: Vec<[f64; 4]> = data
        .chunks(8)
        .map(|c| [0, 1, 2, 3].map(|k| f64::from(u16::from_be_bytes([c[2 * k], c[2 * k + 1]]))))
        .collect();
    check_alpha(&encode(9, 4, ColorType::Rgba, BitDepth::Sixteen, &data, None, None), &rgba16, 65535.0);
    // Grey + alpha.
    let data = rng.bytes(w * h * 2);
    let ga: Vec<[f64; 4]> = data.chunks(2).map(|c| [c[0], c[0], c[0], c[1]].map(f64::from)).collect();
    check_alpha(&encode(9, 4, ColorType::GrayscaleAlpha, BitDepth::Eight, &data, None, None), &ga, 255.0);
    // No alpha channel: opaque.
    let data = rng.bytes(w * h * 3);
    let rgb: Vec<[f64; 4]> = data.chunks(3).map(|c| [c[0], c[1], c[2], 255].map(f64::from)).collect();
    check_alpha(&encode(9, 4, ColorType::Rgb, BitDepth::Eight, &data, None, None), &rgb, 255.0);
    // The emitted source names microraster's formats.
    let t = Texels::Argb4444(vec![0xF00F, 0x0FF0]);
    let src =
        emit::rust_source(&t, 2, 1, "icon", "icon.png", "microraster", emit::DEFAULT_PIXELCOLOR).unwrap();
    assert!(src.contains("pub static ICON_TEXELS: [[u16; 2]; 1] = [\n    [\n        0xF00F, 0x0FF0,"));
    assert!(src.contains(
        "pub static ICON: microraster::texture::Texture<'static, microraster::texture::Argb4444> ="
    ));
    let t = Texels::A8(vec![0, 128, 255]);
    let src = emit::rust_source(&t, 3, 1, "m", "m.png", "crate", emit::DEFAULT_PIXELCOLOR).unwrap();
    assert!(src.contains("Texture<'static, crate::texture::A8>"), "{src}");
    assert_eq!((Format::parse("argb4444"), Format::parse("a8")), (Some(Format::Argb4444), Some(Format::A8)));
    let t = Texels::Rgb565A8(vec![[0xF8, 0x00, 255], [0x07, 0xE0, 7], [0, 0x1F, 128]]);
    let src =
        emit::rust_source(&t, 3, 1, "dots", "dots.png", "microraster", emit::DEFAULT_PIXELCOLOR).unwrap();
    assert!(src.contains("pub static DOTS_TEXELS: [[[u8; 3]; 3]; 1] = [\n    [\n        [0xF8, 0x00, 255], [0x07, 0xE0,   7], [0x00, 0x1F, 128],\n"), "{src}");
    assert!(src.contains("3 × 1 texels, Rgb565A8, 9 bytes of flash."), "{src}");
    assert!(src.contains("Texture<'static, microraster::texture::Rgb565A8>"), "{src}");
    assert_eq!(Format::parse("rgb565a8"), Some(Format::Rgb565A8));
    for f in Format::ALL {
        assert_eq!(Format::parse(f.name()), Some(f));
    }
}

/// A smooth alpha gradient keeps its 256 levels in `rgb565a8` (each texel's
/// alpha is the PNG's), where `argb4444` has 16 (the banding the format is
/// for); 16-bit alpha rounds once to 8 bits.
#[test]
fn rgb565a8_keeps_a_smooth_alpha_gradient() {
    // 8-bit RGBA, 256 × 2: alpha rising by one a pixel, a colour ramp too.
    let data: Vec<u8> = (0..2 * 256u32).flat_map(|i| [(i % 256) as u8, 90, 200, (i % 256) as u8]).collect();
    let image = decode(&encode(256, 2, ColorType::Rgba, BitDepth::Eight, &data, None, None)).unwrap();
    let (Texels::Rgb565A8(t), n) = convert(&image, Format::Rgb565A8, Alpha::Reject).unwrap() else {
        panic!()
    };
    assert_eq!(n, 2 * 255, "every pixel but the opaque ones is translucent");
    let alphas: Vec<u8> = t.iter().map(|texel| texel[2]).collect();
    assert_eq!(alphas[..256], (0..=255).collect::<Vec<u8>>()[..], "every level, in order");
    let tex = Texture::<Rgb565A8>::new(&t, 256, 2).unwrap();
    let sampled: std::collections::BTreeSet<u8> =
        (0..256).map(|x| tex.texel_rgba(x, 1).unwrap()[3]).collect();
    assert_eq!(sampled.len(), 256, "256 distinct alphas through the texture");
    // The same image at 4 bits: 16 levels.
    let (Texels::Argb4444(t4), _) = convert(&image, Format::Argb4444, Alpha::Reject).unwrap() else {
        panic!()
    };
    let levels: std::collections::BTreeSet<u16> = t4.iter().map(|t| t >> 12).collect();
    assert_eq!(levels.len(), 16);
    // 16-bit alpha: round(a·255/65535), once.
    let a16: Vec<u16> = (0..64u32).map(|i| (i * 1040 + 7) as u16).collect();
    let data: Vec<u8> =
        a16.iter().flat_map(|a| [0, 0, 0, 0, 0, 0].into_iter().chain(a.to_be_bytes())).collect();
    let image = decode(&encode(64, 1, ColorType::Rgba, BitDepth::Sixteen, &data, None, None)).unwrap();
    let (Texels::Rgb565A8(t), _) = convert(&image, Format::Rgb565A8, Alpha::Reject).unwrap() else {
        panic!()
    };
    for (texel, a) in t.iter().zip(&a16) {
        assert_eq!(f64::from(texel[2]), (f64::from(*a) * 255.0 / 65535.0).round(), "alpha {a}");
    }
}
