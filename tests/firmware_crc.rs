//! Host side of the firmware check (`scripts/firmware.sh check`).
//!
//! The firmware (`examples/firmware/`) prints one CRC record per band; the
//! script runs it under QEMU for Cortex-M4F and Cortex-M0 and diffs the output
//! with the same example run on the host (`cargo run --example firmware`).
//! These tests run the firmware's own workload source on the host and make
//! sure that what is compared means something:
//!
//! * the CRC is CRC-32 and the records tile each frame;
//! * the band CRCs are those of the same rows of a frame rendered with another
//!   band height into a framebuffer;
//! * the Cortex-M0's streamed rendering (2D scene generated again per band,
//!   vertex stage run per band) gives exactly the pixels of the per-frame
//!   path ([`Renderer::render`]; [`Scene3d::draw`] + `Triangles3d`).

#[allow(dead_code)]
#[path = "../examples/firmware/workload.rs"]
mod workload;

use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::prelude::*;
use microraster::depth::{Depth16, DepthBand};
use microraster::math::Fx;
use microraster::raster3d::Precision::{Exact, Fast};
use microraster::raster3d::{Affine, PerspectiveCorrect, Precision, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Primitive, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{BINS, Scene3d};
use workload::{Crc32, Record, S};

fn records(run: impl FnOnce(workload::Out<'_>) -> Result<(), microraster::Error>) -> Vec<Record> {
    let mut v = Vec::new();
    run(&mut |r: &Record| v.push(*r)).expect("the workload renders");
    v
}

fn m4f() -> Vec<Record> {
    records(workload::m4f_host)
}

fn m0() -> Vec<Record> {
    records(workload::m0_host)
}

#[test]
fn crc32_is_the_standard_crc() {
    let mut c = Crc32::new();
    c.update(b"123456789");
    assert_eq!(c.value(), 0xCBF4_3926);
    assert_eq!(Crc32::new().value(), 0);
}

/// Every configuration's records: bands in order, tiling the frame with full
/// rows, then a frame record covering all of them.
#[test]
fn records_tile_the_frame() {
    // The 2D scene and the 3D frames of each tier.
    let (n4, n0) = (1 + 2 * workload::M4F_3D.len(), 1 + workload::M0_3D.len());
    let configs = [
        (m4f(), workload::M4F_SIZE, workload::M4F_BAND, n4),
        (m0(), workload::M0_SIZE, workload::M0_BAND, n0),
    ];
    for (recs, (w, h), band, scenes) in configs {
        let frames: Vec<_> = recs.iter().filter(|r| r.band.is_none()).collect();
        assert_eq!(frames.len(), scenes);
        for f in frames {
            let bands: Vec<_> = recs.iter().filter(|r| r.scene == f.scene && r.band.is_some()).collect();
            assert_eq!(bands.len(), (h as usize).div_ceil(band), "{}", f.scene);
            let mut y = 0;
            for (i, b) in bands.iter().enumerate() {
                assert_eq!((b.band, b.y0), (Some(i as u32), y), "{}", f.scene);
                assert_eq!(b.rows as usize, band.min(h as usize - y as usize));
                assert_eq!(b.count as usize, w * b.rows as usize);
                y += b.rows as i32;
            }
            assert_eq!((f.y0, f.rows, f.count as usize), (0, h, w * h as usize), "{}", f.scene);
        }
        // Frames are not blank: most bands differ (the exact tier's frames
        // together, as before the fast tier; each fast frame on its own, as
        // it may equal the exact one where no pixel moved).
        let fast = fast_frames();
        let exact: Vec<_> = recs.iter().filter(|r| !fast.contains(&r.scene)).collect();
        let crcs: std::collections::BTreeSet<_> = exact.iter().map(|r| r.crc).collect();
        assert!(crcs.len() > exact.len() * 3 / 4, "{} distinct CRCs in {} records", crcs.len(), exact.len());
        // (The other configuration's names have no records here.)
        for name in fast.into_iter().filter(|n| recs.iter().any(|r| r.scene == *n)) {
            let own: Vec<_> = recs.iter().filter(|r| r.scene == name).collect();
            let crcs: std::collections::BTreeSet<_> = own.iter().map(|r| r.crc).collect();
            // (A frame alone repeats its blank bands' CRC: half, not ¾.)
            assert!(crcs.len() > own.len() / 2, "{name}: {} distinct CRCs in {}", crcs.len(), own.len());
        }
    }
}

/// The names of the fast tier's frames, both configurations.
fn fast_frames() -> Vec<&'static str> {
    let m4f = workload::M4F_3D.iter().filter(|(p, _)| *p == Fast).flat_map(|(_, n)| *n);
    let m0 = workload::M0_3D.iter().filter(|(p, ..)| *p == Fast).map(|(_, _, n)| *n);
    m4f.chain(m0).collect()
}

/// A framebuffer display.
struct Frame {
    w: usize,
    px: Vec<Rgb565>,
}

impl Frame {
    fn new(w: usize, h: u32) -> Self {
        Frame { w, px: vec![Rgb565::RED; w * h as usize] }
    }

    /// Checks `scene`'s records against the rows of this frame.
    fn check(&self, recs: &[Record], scene: &str) {
        let bands: Vec<_> = recs.iter().filter(|r| r.scene == scene && r.band.is_some()).collect();
        assert!(!bands.is_empty(), "no records for {scene}");
        let mut whole = Crc32::new();
        for b in &bands {
            let mut crc = Crc32::new();
            for c in &self.px[b.y0 as usize * self.w..(b.y0 as usize + b.rows as usize) * self.w] {
                crc.update(&c.into_storage().to_le_bytes());
                whole.update(&c.into_storage().to_le_bytes());
            }
            assert_eq!(crc.value(), b.crc, "{scene} band {:?}", b.band);
        }
        let frame = recs.iter().find(|r| r.scene == scene && r.band.is_none()).expect("a frame record");
        assert_eq!(whole.value(), frame.crc, "{scene} frame");
    }
}

impl OriginDimensions for Frame {
    fn size(&self) -> Size {
        Size::new(self.w as u32, (self.px.len() / self.w) as u32)
    }
}

impl DrawTarget for Frame {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            self.px[p.y as usize * self.w + p.x as usize] = c;
        }
        Ok(())
    }
}

/// The firmware's records equal the CRCs of frames rendered with 5-row
/// bands, per frame (primitives collected, all triangles binned), into a
/// framebuffer: for the Cortex-M0 configuration this also shows that its
/// streamed and per-band rendering draws the per-frame pixels.
#[test]
fn band_crcs_match_a_framebuffer() {
    const B: usize = 5;
    fn mixed<const W: usize>(h: u32) -> Frame {
        let mut prims = heapless::Vec::<Primitive<Rgb565, S>, { scenes::MIXED_LEN }>::new();
        assert_eq!(scenes::collect(scenes::mixed, W as u32, h, &mut prims), Ok(0));
        let mut frame = Frame::new(W, h);
        let mut band = Box::new(Band::<Rgb565, W, B>::new(workload::BACKGROUND));
        Renderer::new(h, workload::BACKGROUND).render(&prims, &mut band, &mut frame).unwrap();
        frame
    }
    fn scene3d<T: microraster::math::Scalar, M: microraster::raster3d::Interpolation, const W: usize>(
        h: u32,
        precision: Precision,
    ) -> Frame {
        let pipeline = Scene3d::pipeline::<T, S>(W as u32, h).unwrap().with_precision(precision);
        let mut bins = Box::new(heapless::Vec::<ScreenTriangle<S>, BINS>::new());
        Scene3d.draw::<T, Rgb565, S, BINS>(&pipeline, workload::ANGLE, &mut bins).unwrap();
        let mut frame = Frame::new(W, h);
        let mut band = Box::new(Band::<Rgb565, W, B>::new(workload::BACKGROUND));
        let mut depth = Box::new(DepthBand::<Depth16, W, B>::new());
        Renderer::new(h, workload::BACKGROUND)
            .render(
                Triangles3d::new(&bins, &mut depth, workload::DEPTH_STATE, M::default()),
                &mut band,
                &mut frame,
            )
            .unwrap();
        frame
    }
    const W0: usize = workload::M0_SIZE.0;
    const W4: usize = workload::M4F_SIZE.0;
    let (h0, h4) = (workload::M0_SIZE.1, workload::M4F_SIZE.1);
    let (m0, m4f) = (m0(), m4f());
    mixed::<W0>(h0).check(&m0, "mixed/160x128");
    scene3d::<Fx, Affine, W0>(h0, Exact).check(&m0, "scene3d-fx/160x128");
    mixed::<W4>(h4).check(&m4f, "mixed/320x240");
    scene3d::<f32, PerspectiveCorrect, W4>(h4, Exact).check(&m4f, "scene3d-f32/320x240");
    scene3d::<Fx, PerspectiveCorrect, W4>(h4, Exact).check(&m4f, "scene3d-fx/320x240");
    // The fast tier's own frames, band by band as a framebuffer of them.
    scene3d::<Fx, Affine, W0>(h0, Fast).check(&m0, "scene3d-fx-fast/160x128");
    scene3d::<f32, Affine, W0>(h0, Fast).check(&m0, "scene3d-f32-fast/160x128");
    scene3d::<f32, PerspectiveCorrect, W4>(h4, Fast).check(&m4f, "scene3d-f32-fast/320x240");
    scene3d::<Fx, PerspectiveCorrect, W4>(h4, Fast).check(&m4f, "scene3d-fx-fast/320x240");
}

/// The host's reference lines are the firmware example's: the same records,
/// printed the same way.
#[test]
fn record_lines() {
    let r = Record { scene: "mixed/160x128", band: Some(3), y0: 12, rows: 4, crc: 0x00ab_cdef, count: 640 };
    assert_eq!(r.to_string(), "mixed/160x128 3 12 4 00abcdef 640");
    let f = Record { band: None, y0: 0, rows: 128, count: 20480, ..r };
    assert_eq!(f.to_string(), "mixed/160x128 frame 0 128 00abcdef 20480");
    let n = m0().len();
    assert_eq!(n, (1 + workload::M0_3D.len()) * (128 / workload::M0_BAND + 1));
}
