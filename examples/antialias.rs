//! Anti-aliasing (`microraster::aa`) on the standard scenes at 320×240,
//! `Rgb565`, 16-row output bands: aliased, SSAA and MSAA at 2×2 and 4×4
//! samples per pixel, and sparse MSAA with 4 and 8. Prints the time per
//! frame and the band memory of each mode, and writes the frames (and 4×
//! close-ups) as PNGs.
//!
//! ```text
//! cargo run --release --example antialias [-- <out_dir>]     # default out/
//! ```

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};
use microraster::aa::{Antialias, Msaa, MsaaSparse, Ssaa};
use microraster::aa::{Antialiased, Antialiased3d};
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::raster3d::{PerspectiveCorrect, ScreenTriangle};
use microraster::render::Triangles3d;
use microraster::{Band, Primitive, Renderer};
use microraster_scenes::scenes;
use microraster_scenes::scenes3d::{BINS, Scene3d};
use std::convert::Infallible;
use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;

const W: usize = 320;
const HEIGHT: u32 = 240;
const H: usize = 16;
const S: u32 = 4;
const BG: Rgb565 = Rgb565::new(2, 5, 4);
type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// A full frame in memory.
struct Frame(Vec<Rgb565>);

impl OriginDimensions for Frame {
    fn size(&self) -> Size {
        Size::new(W as u32, HEIGHT)
    }
}

impl DrawTarget for Frame {
    type Color = Rgb565;
    type Error = Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> std::result::Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            if let Some(px) = self.0.get_mut(p.y as usize * W + p.x as usize) {
                *px = c;
            }
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> std::result::Result<(), Infallible> {
        let start = area.top_left.y as usize * W + area.top_left.x as usize;
        for (px, c) in self.0[start..].iter_mut().zip(colors) {
            *px = c; // bands are full width: the rectangle is one run
        }
        Ok(())
    }
}

/// Runs `draw` a few times; returns the last frame and the fastest time (ms).
fn timed(mut draw: impl FnMut(&mut Frame) -> Result<()>) -> Result<(Frame, f64)> {
    let mut best = f64::INFINITY;
    let mut frame = Frame(vec![BG; W * HEIGHT as usize]);
    for _ in 0..7 {
        let t = Instant::now();
        draw(&mut frame)?;
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
    }
    Ok((frame, best))
}

fn scene_2d() -> Result<heapless::Vec<Primitive<Rgb565, S>, 128>> {
    let mut prims = heapless::Vec::new();
    match scenes::collect(scenes::mixed, W as u32, HEIGHT, &mut prims)? {
        0 => Ok(prims),
        n => Err(format!("{n} primitives did not fit").into()),
    }
}

fn scene_3d() -> Result<heapless::Vec<ScreenTriangle<S>, BINS>> {
    let pipeline = Scene3d::pipeline::<f32, S>(W as u32, HEIGHT)?;
    let mut bins = heapless::Vec::new();
    Scene3d::new().draw::<f32, Rgb565, S, BINS>(&pipeline, 3.0, &mut bins)?;
    Ok(bins)
}

/// One mode on both scenes: (2D frame, ms), (3D frame, ms), 2D and 3D band bytes.
type Outcome = ((Frame, f64), (Frame, f64), usize, usize);

/// One anti-aliased mode on both scenes.
fn run<A: Antialias, const SW: usize, const SH: usize>(
    mode: A,
    prims: &[Primitive<Rgb565, S>],
    tris: &[ScreenTriangle<S>],
) -> Result<Outcome> {
    let r = Renderer::new(HEIGHT, BG);
    let mut samples = Band::<Rgb565, SW, SH>::new(BG);
    let mut depth = DepthBand::<Depth16, SW, SH>::new();
    let mut out = Band::<Rgb565, W, H>::new(BG);
    let f2 = timed(|f| {
        Ok(r.render(Antialiased::new(mode, prims, &mut samples), &mut out, f).map_err(|e| e.to_string())?)
    })?;
    let f3 = timed(|f| {
        let state = DepthState::LESS_WRITE;
        r.render(
            Antialiased3d::new(mode, tris, &mut samples, &mut depth, state, PerspectiveCorrect),
            &mut out,
            f,
        )
        .map_err(|e| e.to_string())?;
        Ok(())
    })?;
    let bytes_2d = Band::<Rgb565, SW, SH>::BYTES + Band::<Rgb565, W, H>::BYTES;
    Ok((f2, f3, bytes_2d, bytes_2d + DepthBand::<Depth16, SW, SH>::BYTES))
}

fn save(frame: &Frame, path: &Path, crop: Option<(usize, usize, usize, usize, usize)>) -> Result<()> {
    let (x0, y0, w, h, zoom) = crop.unwrap_or((0, 0, W, HEIGHT as usize, 1));
    let mut data = Vec::with_capacity(w * h * zoom * zoom * 3);
    for y in 0..h * zoom {
        for x in 0..w * zoom {
            let c = Rgb888::from(frame.0[(y0 + y / zoom) * W + x0 + x / zoom]);
            data.extend([c.r(), c.g(), c.b()]);
        }
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, (w * zoom) as u32, (h * zoom) as u32);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header()?;
    writer.write_image_data(&data)?;
    writer.finish()?;
    Ok(())
}

fn main() -> Result<()> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "out".into()));
    std::fs::create_dir_all(&out)?;
    let (prims, tris) = (scene_2d()?, scene_3d()?);

    let r = Renderer::new(HEIGHT, BG);
    let mut band = Band::<Rgb565, W, H>::new(BG);
    let mut depth = DepthBand::<Depth16, W, H>::new();
    let a2 = timed(|f| Ok(r.render(&prims, &mut band, f).map_err(|e| e.to_string())?))?;
    let a3 = timed(|f| {
        r.render(
            Triangles3d::new(&tris, &mut depth, DepthState::LESS_WRITE, PerspectiveCorrect),
            &mut band,
            f,
        )
        .map_err(|e| e.to_string())?;
        Ok(())
    })?;
    let aliased = (
        a2,
        a3,
        Band::<Rgb565, W, H>::BYTES,
        Band::<Rgb565, W, H>::BYTES + DepthBand::<Depth16, W, H>::BYTES,
    );
    let modes = [
        ("aliased", aliased),
        ("ssaa2", run::<Ssaa<2>, { W * 2 }, { H * 2 }>(Ssaa, &prims, &tris)?),
        ("msaa2", run::<Msaa<2>, { W * 2 }, { H * 2 }>(Msaa, &prims, &tris)?),
        ("ssaa4", run::<Ssaa<4>, { W * 4 }, { H * 4 }>(Ssaa, &prims, &tris)?),
        ("msaa4", run::<Msaa<4>, { W * 4 }, { H * 4 }>(Msaa, &prims, &tris)?),
        ("sparse4", run::<MsaaSparse<4>, W, { H * 4 }>(MsaaSparse, &prims, &tris)?),
        ("sparse8", run::<MsaaSparse<8>, W, { H * 8 }>(MsaaSparse, &prims, &tris)?),
    ];
    println!(
        "320×240 Rgb565, {H}-row bands ({} 2D primitives, {} 3D triangles), host, best of 7:",
        prims.len(),
        tris.len()
    );
    println!("| mode | 2D ms/frame | 3D ms/frame | 2D band bytes | 3D band bytes (Depth16) |");
    println!("|---|---|---|---|---|");
    for (name, ((f2, t2), (f3, t3), b2, b3)) in &modes {
        println!("| {name} | {t2:.2} | {t3:.2} | {b2} | {b3} |");
        save(f2, &out.join(format!("aa_2d_{name}.png")), None)?;
        save(f3, &out.join(format!("aa_3d_{name}.png")), None)?;
        save(f2, &out.join(format!("aa_2d_{name}_zoom.png")), Some((100, 60, 80, 60, 4)))?;
        save(f3, &out.join(format!("aa_3d_{name}_zoom.png")), Some((110, 70, 80, 60, 4)))?;
    }
    println!("wrote {}/aa_{{2d,3d}}_<mode>[_zoom].png", out.display());
    Ok(())
}
