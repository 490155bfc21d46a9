//! Tests of `png2rs` (PNG → Rust source for a static `Texture`): PNGs of
//! every colour type are encoded here with the `png` crate, converted with
//! `microraster_tools::png`, and the texels compared with an independent
//! conversion written from the documented rules (the formats with alpha:
//! `png2rs_alpha.rs`; the committed demo texture: `png2rs_demo.rs`).

mod common;

use microraster_tools::png::convert::{Alpha, Format, Texels, convert};
use microraster_tools::png::decode::decode;
use microraster_tools::png::emit;
use png::{BitDepth, ColorType};

use common::{Rng, encode, ref_rgb565};

/// Rec. 601 luma at 8 bits, exact (f64 of exact integer ratios).
fn ref_luma(rgb: [f64; 3], max: f64) -> f64 {
    (0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]) * 255.0 / max
}

/// Decodes and converts to both formats; checks every texel against the
/// reference computed from `rgb` (per pixel channels in `0..=max`, grey
/// sources with `r = g = b` and `gray` set).
fn check(png: &[u8], w: u32, h: u32, rgb: &[[f64; 3]], max: f64, gray: bool) {
    let image = decode(png).unwrap();
    assert_eq!((image.width, image.height, image.gray), (w, h, gray));
    let (Texels::Rgb565(t565), 0) = convert(&image, Format::Rgb565, Alpha::Reject).unwrap() else { panic!() };
    let (Texels::Gray8(t8), 0) = convert(&image, Format::Gray8, Alpha::Reject).unwrap() else { panic!() };
    assert_eq!((t565.len(), t8.len()), (rgb.len(), rgb.len()));
    for (i, c) in rgb.iter().enumerate() {
        assert_eq!(t565[i], ref_rgb565(*c, max), "texel {i} of {c:?}/{max}");
        if gray {
            assert_eq!(f64::from(t8[i]), (c[0] * 255.0 / max).round(), "grey texel {i}");
        } else {
            // Within ½ of exact Rec. 601 (either way on an exact tie).
            let e = (f64::from(t8[i]) - ref_luma(*c, max)).abs();
            assert!(e <= 0.5 + 1e-9, "luma texel {i} of {c:?}: {} vs {}", t8[i], ref_luma(*c, max));
        }
    }
}

#[test]
fn rgb_and_rgba_8_and_16_bit() {
    let mut rng = Rng(1);
    let (w, h) = (7, 5);
    // 8-bit RGB.
    let data = rng.bytes(w * h * 3);
    let rgb: Vec<[f64; 3]> = data.chunks(3).map(|c| [0, 1, 2].map(|k| f64::from(c[k]))).collect();
    check(&encode(7, 5, ColorType::Rgb, BitDepth::Eight, &data, None, None), 7, 5, &rgb, 255.0, false);
    // 8-bit RGBA, all opaque: alpha accepted and dropped.
    let rgba: Vec<u8> = data.chunks(3).flat_map(|c| [c[0], c[1], c[2], 255]).collect();
    check(&encode(7, 5, ColorType::Rgba, BitDepth::Eight, &rgba, None, None), 7, 5, &rgb, 255.0, false);
    // 16-bit RGB: rounded once from 16 bits (not truncated to 8 first).
    let data = rng.bytes(w * h * 6);
    let rgb16: Vec<[f64; 3]> = data
        .chunks(6)
        .map(|c| [0, 1, 2].map(|k| f64::from(u16::from_be_bytes([c[2 * k], c[2 * k + 1]]))))
        .collect();
    check(&encode(7, 5, ColorType::Rgb, BitDepth::Sixteen, &data, None, None), 7, 5, &rgb16, 65535.0, false);
    // 16-bit RGBA, opaque.
    let rgba: Vec<u8> = data.chunks(6).flat_map(|c| [c[0], c[1], c[2], c[3], c[4], c[5], 255, 255]).collect();
    check(&encode(7, 5, ColorType::Rgba, BitDepth::Sixteen, &rgba, None, None), 7, 5, &rgb16, 65535.0, false);
    // A 16-bit value whose top byte alone would round differently:
    // 0x0440/65535·31 = 0.5148… → 1; truncated to 0x04/255·31 = 0.486 → 0.
    let png = encode(1, 1, ColorType::Rgb, BitDepth::Sixteen, &[0x04, 0x40, 0, 0, 0, 0], None, None);
    let (t, _) = convert(&decode(&png).unwrap(), Format::Rgb565, Alpha::Reject).unwrap();
    assert_eq!(t, Texels::Rgb565(vec![1 << 11]));
}

#[test]
fn grey_at_every_depth_and_with_alpha() {
    let mut rng = Rng(2);
    for (depth, bits) in [(BitDepth::One, 1), (BitDepth::Two, 2), (BitDepth::Four, 4), (BitDepth::Eight, 8)] {
        let (w, h) = (13u32, 3u32); // rows not a whole number of bytes below 8 bits
        let levels: Vec<u32> = (0..w * h).map(|_| (rng.next() % (1 << bits)) as u32).collect();
        let mut data = Vec::new();
        for row in levels.chunks(w as usize) {
            let mut acc = 0u32;
            let mut n = 0;
            for &l in row {
                acc = (acc << bits) | l;
                n += bits;
                if n == 8 {
                    data.push(acc as u8);
                    (acc, n) = (0, 0);
                }
            }
            if n > 0 {
                data.push((acc << (8 - n)) as u8);
            }
        }
        // The png crate widens low-bit grey by scaling to 8 bits; a texel is
        // exact either way: level·255/(2^bits − 1).
        let max = f64::from((1u32 << bits) - 1);
        let rgb: Vec<[f64; 3]> = levels.iter().map(|&l| [f64::from(l) * 255.0 / max; 3]).collect();
        check(&encode(w, h, ColorType::Grayscale, depth, &data, None, None), w, h, &rgb, 255.0, true);
    }
    // 16-bit grey.
    let data = rng.bytes(6 * 4 * 2);
    let rgb: Vec<[f64; 3]> =
        data.chunks(2).map(|c| [f64::from(u16::from_be_bytes([c[0], c[1]])); 3]).collect();
    check(
        &encode(6, 4, ColorType::Grayscale, BitDepth::Sixteen, &data, None, None),
        6,
        4,
        &rgb,
        65535.0,
        true,
    );
    // Grey + alpha, opaque.
    let data: Vec<u8> = (0..24u8).flat_map(|g| [g * 10, 255]).collect();
    let rgb: Vec<[f64; 3]> = (0..24u8).map(|g| [f64::from(g) * 10.0; 3]).collect();
    check(
        &encode(6, 4, ColorType::GrayscaleAlpha, BitDepth::Eight, &data, None, None),
        6,
        4,
        &rgb,
        255.0,
        true,
    );
}

#[test]
fn palette_images_expand_to_their_colours() {
    let mut rng = Rng(3);
    for (depth, bits) in
        [(BitDepth::One, 1u32), (BitDepth::Two, 2), (BitDepth::Four, 4), (BitDepth::Eight, 8)]
    {
        let entries = 1usize << bits;
        let plte = rng.bytes(entries * 3);
        let (w, h) = (9u32, 4u32);
        let idx: Vec<usize> = (0..w * h).map(|_| (rng.next() % entries as u64) as usize).collect();
        let mut data = Vec::new();
        for row in idx.chunks(w as usize) {
            let (mut acc, mut n) = (0u32, 0);
            for &i in row {
                acc = (acc << bits) | i as u32;
                n += bits;
                if n == 8 {
                    data.push(acc as u8);
                    (acc, n) = (0, 0);
                }
            }
            if n > 0 {
                data.push((acc << (8 - n)) as u8);
            }
        }
        let rgb: Vec<[f64; 3]> = idx.iter().map(|&i| [0, 1, 2].map(|k| f64::from(plte[3 * i + k]))).collect();
        let png = encode(w, h, ColorType::Indexed, depth, &data, Some(&plte), None);
        check(&png, w, h, &rgb, 255.0, false);
        // A tRNS chunk marking every entry opaque changes nothing; one
        // translucent entry in use is rejected.
        let opaque = vec![255u8; entries];
        check(
            &encode(w, h, ColorType::Indexed, depth, &data, Some(&plte), Some(&opaque)),
            w,
            h,
            &rgb,
            255.0,
            false,
        );
        let mut trns = opaque.clone();
        trns[idx[5]] = 128;
        let png = encode(w, h, ColorType::Indexed, depth, &data, Some(&plte), Some(&trns));
        let image = decode(&png).unwrap();
        let e = convert(&image, Format::Rgb565, Alpha::Reject).unwrap_err();
        assert!(e.contains("not fully opaque") && e.contains("--ignore-alpha"), "{e}");
        let translucent = idx.iter().filter(|&&i| i == idx[5]).count();
        let (t, n) = convert(&image, Format::Rgb565, Alpha::Ignore).unwrap();
        assert_eq!(n, translucent);
        // Alpha dropped: the palette colours.
        let want: Vec<u16> = rgb.iter().map(|c| ref_rgb565(*c, 255.0)).collect();
        assert_eq!(t, Texels::Rgb565(want));
    }
}

#[test]
fn bad_input_is_an_error() {
    assert!(decode(b"").unwrap_err().starts_with("not a readable PNG"));
    assert!(decode(b"GIF89a....").unwrap_err().starts_with("not a readable PNG"));
    let png = encode(8, 8, ColorType::Rgb, BitDepth::Eight, &[7; 8 * 8 * 3], None, None);
    // Cut inside the image data: the header reads, the pixels do not.
    let cut = &png[..png.len() - 20];
    assert!(decode(cut).is_err());
    // Larger than a texture can be.
    let wide = encode(4097, 1, ColorType::Grayscale, BitDepth::One, &[0; 513], None, None);
    assert_eq!(decode(&wide).unwrap_err(), "4097×1 pixels: width and height must be 1 to 4096");
    let tall = encode(1, 4097, ColorType::Grayscale, BitDepth::One, &[0; 4097], None, None);
    assert!(decode(&tall).is_err());
    // The largest sizes are fine.
    let ok = encode(4096, 1, ColorType::Grayscale, BitDepth::One, &[0xAA; 512], None, None);
    assert_eq!(decode(&ok).unwrap().pixels.len(), 4096);
    // Emitter checks.
    let t = Texels::Gray8(vec![0; 6]);
    let src =
        |name: &str, w, h, k: &str| emit::rust_source(&t, w, h, name, "x.png", k, emit::DEFAULT_PIXELCOLOR);
    for bad in ["", "_", "2x", "a-b", "a b", "é"] {
        assert!(src(bad, 3, 2, "microraster").is_err(), "{bad:?}");
    }
    assert!(src("t", 4, 2, "microraster").unwrap_err().contains("do not make 4×2"));
    assert!(src("t", 3, 2, "micro raster").is_err());
    assert!(src("t", 3, 2, "crate").is_ok());
    assert_eq!(Format::parse("rgb888"), None);
}

/// The PNG specification makes a palette index past the palette's last
/// entry an error; the `png` crate's expansion turns it into black.
#[test]
fn a_palette_index_past_the_palette_is_an_error() {
    use microraster_tools::png::{Options, convert_bytes};
    // (depth, entries, packed rows of 4 × 2 indices with one out of range)
    let cases: [(BitDepth, usize, Vec<u8>); 4] = [
        (BitDepth::Eight, 2, vec![0, 1, 5, 0, 1, 0, 0, 1]),
        (BitDepth::Four, 3, vec![0x01, 0x20, 0x12, 0x03]),
        (BitDepth::Two, 3, vec![0b0001_1000, 0b0011_0010]),
        (BitDepth::One, 1, vec![0b0000_0000, 0b0100_0000]),
    ];
    for (depth, entries, data) in cases {
        let plte: Vec<u8> = (0..entries * 3).map(|i| 40 + i as u8).collect();
        let png = encode(4, 2, ColorType::Indexed, depth, &data, Some(&plte), None);
        let e = decode(&png).unwrap_err();
        assert!(e.contains("palette index") && e.contains(&format!("{entries} entries")), "{depth:?}: {e}");
        let opts = Options::new(Format::Rgb565);
        assert!(convert_bytes(&png, "p", "p.png", &opts).is_err(), "{depth:?}");
        // The same pixels with every index in range convert.
        let mut full = plte.clone();
        full.resize(3 << (depth as u8), 9);
        let ok = encode(4, 2, ColorType::Indexed, depth, &data, Some(&full), None);
        assert!(convert_bytes(&ok, "p", "p.png", &opts).is_ok(), "{depth:?}");
    }
    // Padding bits past the last pixel of a row are not indices.
    let padded = encode(4, 2, ColorType::Indexed, BitDepth::One, &[0x0F, 0x0F], Some(&[1, 2, 3]), None);
    assert_eq!(decode(&padded).unwrap().pixels, vec![[1, 2, 3, 255]; 8]);
    // The command line: an error message and exit status 1, no output.
    let dir = std::env::temp_dir().join(format!("png2rs-index-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.png");
    let plte = [0u8, 0, 0, 255, 255, 255];
    std::fs::write(
        &path,
        encode(4, 2, ColorType::Indexed, BitDepth::Eight, &[0, 1, 5, 0, 1, 0, 0, 1], Some(&plte), None),
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_png2rs"))
        .arg(&path)
        .args(["--name", "bad", "--format", "rgb565"])
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("palette index 5"), "{out:?}");
}

#[test]
fn emitted_source_layout() {
    let t = Texels::Gray8((0..30).map(|i| i * 8).collect());
    let s =
        emit::rust_source(&t, 15, 2, "ramp", "we\"ird\nname.png", "crate", emit::DEFAULT_PIXELCOLOR).unwrap();
    assert!(s.starts_with(
        "// Generated by png2rs from \"we\\\"ird\\nname.png\"; do not edit. 15×2 texels, Gray8.\n"
    ));
    assert!(s.contains("pub static RAMP_TEXELS: [[u8; 15]; 2] = [\n    [\n          0,   8,  16,"));
    assert!(s.contains("15 × 2 texels, Gray8, 30 bytes of flash."));
    assert!(s.ends_with(
        "pub static RAMP: crate::texture::Texture<'static, embedded_graphics::pixelcolor::Gray8> =\n    \
         crate::texture::Texture::from_rows(&RAMP_TEXELS);\n"
    ));
    // The numbers in the array are the texels, in order.
    let numbers: Vec<u32> = s
        .lines()
        .filter(|l| l.starts_with("        "))
        .flat_map(|l| l.split(',').filter_map(|n| n.trim().parse().ok()).collect::<Vec<_>>())
        .collect();
    assert_eq!(numbers, (0..30).map(|i| i * 8).collect::<Vec<u32>>());
}
