//! The standard 3D scene (`microraster_scenes::scenes3d`) at 320×240: the colour
//! frame, its depth buffer, the fixed-point vertex path and affine colour
//! interpolation for comparison, a band-height invariance check and the
//! memory the frame needs.

use super::{BLACK, Canvas, Result, save, with_caption};
use embedded_graphics::prelude::*;
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};
use microraster::depth::{Depth16, DepthBand, DepthFormat, DepthState};
use microraster::math::{Fx, Scalar};
use microraster::raster3d::{Affine, Interpolation, PerspectiveCorrect, ScreenTriangle, draw_triangle};
use microraster::render::{Triangles3d, from_fn};
use microraster::{Band, Renderer};
use microraster_scenes::scenes3d::{BINS, Scene3d, Stats, TRIANGLES};
use std::path::Path;

pub const W: usize = 320;
pub const HEIGHT: u32 = 240;
/// Subpixel bits, as in the 2D scenes: 1/16 px.
pub const S: u32 = super::S;
/// Band rows of the main frame.
pub const BAND_ROWS: usize = 16;
/// Animation angle (radians) of the frame shown.
pub const ANGLE: f32 = 3.0;
/// Frame background: a dark slate, so that unlit sides stand out from it.
pub const BACKGROUND: Rgb888 = Rgb888::new(18, 22, 34);

type Z = Depth16;
type Bins = heapless::Vec<ScreenTriangle<S>, BINS>;

/// Writes scene3d.png, depth3d.png, scene3d_fx.png and scene3d_affine.png to
/// `out` and prints the statistics.
pub fn run(out: &Path) -> Result<()> {
    let (bins, stats) = vertex_stage::<f32>()?;
    let (bins_fx, stats_fx) = vertex_stage::<Fx>()?;

    // The frame, drawn with our own depth rows so the depth buffer can be kept.
    let (frame, depth) = render_keeping_depth::<PerspectiveCorrect, BAND_ROWS>(&bins)?;
    // The same frame through the library's Triangles3d must be identical ...
    if render_3d::<PerspectiveCorrect, BAND_ROWS>(&bins)?.px != frame.px {
        return Err("Triangles3d and from_fn + draw_triangle drew different frames".into());
    }
    // ... and so must every band height, colour and depth alike.
    check_bands::<1>(&bins, &frame, &depth)?;
    check_bands::<7>(&bins, &frame, &depth)?;
    check_bands::<240>(&bins, &frame, &depth)?;

    save(&frame, &out.join("scene3d.png"))?;
    print_stats("f32", &stats);
    println!("  identical for bands of 1, 7, 16 and 240 rows (colour and depth), and via Triangles3d");

    let (grey, lo, hi) = depth_image(&depth)?;
    let grey = with_caption(
        &grey,
        &[
            &format!("Depth16 z/w, used codes {lo}..{hi} stretched:"),
            "nearest white, farthest dark grey, empty black",
        ],
    )?;
    save(&grey, &out.join("depth3d.png"))?;
    println!(
        "  depth: codes {lo}..{hi} of 0..{} used; grey = 32 + 223·({hi} − d)/({hi} − {lo}), background (d = {}) black",
        Z::MAX,
        Z::MAX
    );

    let fx = render_3d::<PerspectiveCorrect, BAND_ROWS>(&bins_fx)?;
    save(&fx, &out.join("scene3d_fx.png"))?;
    print_stats("Fx 16.16", &stats_fx);
    print_diff("Fx vertex path", &diff(&frame, &fx));

    let affine = render_3d::<Affine, BAND_ROWS>(&bins)?;
    save(&affine, &out.join("scene3d_affine.png"))?;
    print_diff("affine colour", &diff(&frame, &affine));

    print_memory();
    Ok(())
}

/// The vertex stage of the standard scene on the numeric path `T`.
fn vertex_stage<T: Scalar>() -> Result<(Bins, Stats)> {
    let pipeline = Scene3d::pipeline::<T, S>(W as u32, HEIGHT)?;
    let mut bins = Bins::new();
    let stats = Scene3d::new().draw::<T, Rgb888, S, BINS>(&pipeline, ANGLE, &mut bins)?;
    Ok((bins, stats))
}

/// The frame through `Triangles3d` with `H`-row bands.
fn render_3d<M: Interpolation, const H: usize>(tris: &[ScreenTriangle<S>]) -> Result<Canvas> {
    let mut canvas = Canvas::new(W as u32, HEIGHT);
    let mut band = Band::<Rgb888, W, H>::new(BACKGROUND);
    let mut depth = DepthBand::<Z, W, H>::new();
    Renderer::new(HEIGHT, BACKGROUND)
        .render(
            Triangles3d::new(tris, &mut depth, DepthState::LESS_WRITE, M::default()),
            &mut band,
            &mut canvas,
        )
        .map_err(|e| e.to_string())?;
    Ok(canvas)
}

/// The frame through the public band loop, `render::from_fn`, with
/// one [`draw_triangle`] call per triangle that touches the band; each band's
/// depth rows are copied out before the next band reuses them. Returns the
/// frame and its depth buffer, row by row.
fn render_keeping_depth<M: Interpolation, const H: usize>(
    tris: &[ScreenTriangle<S>],
) -> Result<(Canvas, Vec<u16>)> {
    let mut canvas = Canvas::new(W as u32, HEIGHT);
    let mut band = Band::<Rgb888, W, H>::new(BACKGROUND);
    let mut zband = DepthBand::<Z, W, H>::new();
    let mut depth = vec![Z::FAR; W * HEIGHT as usize];
    Renderer::new(HEIGHT, BACKGROUND)
        .render(
            from_fn(|view| {
                let (y0, y1) = (view.y0(), view.y1());
                zband.clear(H);
                let mut rows = zband.rows_mut((y1 - y0) as usize);
                for tri in tris {
                    let (lo, hi) = tri.rows();
                    if lo < y1 && hi >= y0 {
                        draw_triangle(tri, view, &mut rows, DepthState::LESS_WRITE, M::default());
                    }
                }
                for (dst, src) in depth.chunks_exact_mut(W).skip(y0 as usize).zip(rows.iter()) {
                    dst.copy_from_slice(src);
                }
                Ok(())
            }),
            &mut band,
            &mut canvas,
        )
        .map_err(|e| e.to_string())?;
    Ok((canvas, depth))
}

/// Errors unless `H`-row bands give the same colour and depth as `frame`,
/// `depth`, both through `from_fn` and through `Triangles3d`.
fn check_bands<const H: usize>(tris: &[ScreenTriangle<S>], frame: &Canvas, depth: &[u16]) -> Result<()> {
    let (c, d) = render_keeping_depth::<PerspectiveCorrect, H>(tris)?;
    let lib = render_3d::<PerspectiveCorrect, H>(tris)?;
    if c.px != frame.px || lib.px != frame.px {
        return Err(format!("{H}-row bands drew a different 3D frame than {BAND_ROWS}-row bands").into());
    }
    if d != depth {
        return Err(format!("{H}-row bands left a different depth buffer than {BAND_ROWS}-row bands").into());
    }
    Ok(())
}

/// Grey levels from the depth codes, contrast stretched over the codes in
/// use: the nearest white (255), the farthest 32, background (far) black.
/// Returns the image and the range of codes used.
fn depth_image(depth: &[u16]) -> Result<(Canvas, u16, u16)> {
    let used = || depth.iter().copied().filter(|&d| d != Z::FAR);
    let (lo, hi) = (used().min().ok_or("empty depth buffer")?, used().max().ok_or("empty depth buffer")?);
    let span = u32::from(hi - lo).max(1);
    let mut img = Canvas::new(W as u32, HEIGHT);
    for (p, &d) in img.px.iter_mut().zip(depth) {
        *p = if d == Z::FAR {
            BLACK
        } else {
            let g = (32 + 223 * u32::from(hi - d) / span).min(255) as u8;
            Rgb888::new(g, g, g)
        };
    }
    Ok((img, lo, hi))
}

/// How two frames differ.
struct Diff {
    /// Pixels that differ at all.
    pixels: usize,
    /// Of those, pixels where some channel differs by more than 2 (a different
    /// surface or background, not shading rounding).
    large: usize,
    /// Largest channel difference.
    max: u8,
}

fn diff(a: &Canvas, b: &Canvas) -> Diff {
    let mut d = Diff { pixels: 0, large: 0, max: 0 };
    for (p, q) in a.px.iter().zip(&b.px) {
        let m = [p.r().abs_diff(q.r()), p.g().abs_diff(q.g()), p.b().abs_diff(q.b())]
            .into_iter()
            .max()
            .unwrap_or(0);
        if m > 0 {
            d.pixels += 1;
            d.large += usize::from(m > 2);
            d.max = d.max.max(m);
        }
    }
    d
}

fn print_diff(what: &str, d: &Diff) {
    println!(
        "  {what}: {} of {} pixels differ from scene3d.png ({} by more than 2 levels in a channel, at most {})",
        d.pixels,
        W * HEIGHT as usize,
        d.large,
        d.max
    );
}

fn print_stats(path: &str, s: &Stats) {
    println!(
        "  vertex stage ({path}, angle {ANGLE} rad): {TRIANGLES} triangles in; {} emitted, {} back faces, \
         {} clipped, {} degenerate",
        s.emitted, s.back_faces, s.clipped, s.degenerate
    );
}

fn print_memory() {
    let band = Band::<Rgb565, W, BAND_ROWS>::BYTES;
    let depth = DepthBand::<Z, W, BAND_ROWS>::BYTES;
    let tri = core::mem::size_of::<ScreenTriangle<S>>();
    let bins = tri * BINS;
    let meshes = core::mem::size_of::<Scene3d>();
    let flash: usize = Scene3d::new()
        .meshes()
        .iter()
        .map(|m| size_of_val(m.positions) + size_of_val(m.normals) + size_of_val(m.indices))
        .sum();
    let frame = W * HEIGHT as usize * core::mem::size_of::<Rgb565>();
    println!(
        "  RAM: Rgb565 band {band} + Depth16 band {depth} + bins {bins} ({BINS} × {tri}) \
         + Scene3d {meshes} = {} bytes (mesh data: {flash} bytes of static data, flash on a microcontroller)",
        band + depth + bins + meshes
    );
    println!(
        "  versus a full 320×240 Rgb565 framebuffer: {frame} bytes ({} with a full Depth16 buffer too)",
        frame + W * HEIGHT as usize * core::mem::size_of::<u16>()
    );
}
