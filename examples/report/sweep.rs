//! The trade sweep: each knob varied alone from the baseline (S = 4, 16-bit
//! depth, 16-row bands, perspective-correct colour, f32 vertex math), cost
//! (host time, median of repeated runs) against error (against f64
//! references).

use crate::common::*;
use crate::timing::median_ns;
use embedded_graphics_core::pixelcolor::{Rgb565, Rgb888};
use fixed::types::I16F16;
use microraster::depth::{DepthBand, DepthFormat, DepthRows, DepthState};
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::Scalar;
use microraster::raster3d::{Affine, Interpolation, ScreenTriangle, draw_triangle};
use microraster::{Band, ClipRect, Interpolate, Primitive, SubPoint, Triangle};
use microraster_scenes::scenes::{self, FineTriangle};
use microraster_scenes::scenes3d::{BINS, Scene3d};

/// One setting of the 3D scene.
#[derive(Clone, Debug, Default)]
pub struct Row3d {
    /// Knob name.
    pub knob: &'static str,
    /// The setting, as shown.
    pub setting: String,
    /// Configuration key (also for the Cortex-M counts).
    pub key: String,
    /// Host time of a whole frame: vertex stage and rasterization, ns.
    pub frame_ns: f64,
    /// Host time of the vertex stage alone, ns.
    pub vertex_ns: f64,
    /// Screen triangles.
    pub tris: usize,
    /// Fragments rasterized (pixels of every triangle, before the depth test).
    pub fragments: u64,
    /// Colour band + depth band bytes.
    pub band_bytes: usize,
    /// Pixels whose visible source triangle differs from the f64 pipeline's.
    pub vis_tri: usize,
    /// Pixels whose visible object (or background) differs from the f64 pipeline's.
    pub vis_obj: usize,
    /// Depth error against the f64 pipeline, in LSB of the format, where both
    /// show the same triangle: max and mean.
    pub depth_max: f64,
    /// See `depth_max`.
    pub depth_mean: f64,
    /// Mean depth error against the f64 pipeline in units of 2^-16 of the
    /// depth range (comparable across formats).
    pub depth_mean_range: f64,
    /// Depth error of the rasterizer alone: stored code against the exact
    /// plane through the same screen triangle's vertex depths, LSB: max, mean.
    pub raster_depth_max: f64,
    /// See `raster_depth_max`.
    pub raster_depth_mean: f64,
    /// Colour error (8-bit channel steps) against the exact perspective-correct
    /// value on the same screen triangle: max and mean.
    pub color_max: f64,
    /// See `color_max`.
    pub color_mean: f64,
    /// Pixels of the `Rgb565` frame that differ from the baseline's.
    pub differs_from_baseline: usize,
    /// The `Rgb565` frame, row-major.
    pub frame: Vec<Rgb565>,
}

/// The f64 reference frame of the 3D scene, computed once.
pub struct Ref3dFrame {
    /// Per pixel: nearest triangle, depth, colour.
    pub px: Vec<RefPixel>,
}

impl Ref3dFrame {
    pub fn new() -> Self {
        let mut px = vec![RefPixel { id: 0, depth: 0.0, color: [0.0; 3] }; W * H];
        Ref3d::new::<Rgb888>(ANGLE).raster(&mut px);
        Ref3dFrame { px }
    }
}

/// Exact barycentrics of the centre of pixel `(x, y)` on `t`'s snapped vertices.
fn bary<const S: u32>(t: &ScreenTriangle<S>, x: i32, y: i32) -> [f64; 3] {
    let p = t.v.map(|v| (2.0 * v.pos.x() as f64, 2.0 * v.pos.y() as f64));
    let half = (1u64 << S) as f64;
    let c = ((2 * x + 1) as f64 * half, (2 * y + 1) as f64 * half);
    let cross =
        |a: (f64, f64), b: (f64, f64), q: (f64, f64)| (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0);
    let det = cross(p[0], p[1], p[2]);
    [cross(p[1], p[2], c) / det, cross(p[2], p[0], c) / det, cross(p[0], p[1], c) / det]
}

/// Exact perspective-correct colour of `t` at the centre of pixel `(x, y)`
/// (`tests/integration/perspective.rs`'s reference): barycentrics of the
/// snapped vertices, `c = Σ λ c q / Σ λ q`.
fn exact_color<const S: u32>(t: &ScreenTriangle<S>, x: i32, y: i32) -> [f64; 3] {
    let l = bary(t, x, y);
    let q = t.v.map(|v| v.inv_w as f64);
    let den: f64 = (0..3).map(|i| l[i] * q[i]).sum();
    [0, 1, 2].map(|k| (0..3).map(|i| l[i] * q[i] * t.v[i].color[k] as f64).sum::<f64>() / den)
}

/// Draws `tris` into one full-frame `Rgb888` band with depth format `F`
/// and interpolation `M`; returns colours and stored depth codes.
fn full_frame<F: DepthFormat, M: Interpolation, const S: u32>(
    tris: &[ScreenTriangle<S>],
) -> (Vec<Rgb888>, Vec<u32>) {
    let mut band = Box::new(Band::<Rgb888, W, H>::new(Rgb888::new(0, 0, 0)));
    let mut depth = vec![[F::FAR; W]; H];
    {
        let mut view = band.view(0, H, Rgb888::new(0, 0, 0));
        let mut rows = DepthRows::<F, W>::new(&mut depth);
        for t in tris {
            draw_triangle(t, &mut view, &mut rows, DepthState::LESS_WRITE, M::default());
        }
    }
    let color = band.rows().iter().flatten().copied().collect();
    (color, depth.iter().flatten().map(|&s| F::to_u32(s)).collect())
}

/// Times and measures one configuration of the 3D scene.
pub fn run3d<T: Scalar, F: DepthFormat, M: Interpolation, const S: u32, const BH: usize>(
    reference: &Ref3dFrame,
    knob: &'static str,
    setting: &str,
) -> Row3d {
    let p = pipeline3d::<T, S>();
    let mut bins = Box::new(Bins::<S>::new());
    let mut band = Box::new(Band::<Rgb565, W, BH>::new(BG3));
    let mut depth = Box::new(DepthBand::<F, W, BH>::new());
    let mut fb = SliceFb::default();
    let frame_ns = median_ns(|| {
        mr3d::<T, F, M, S, BH>(&p, &mut bins, &mut band, &mut depth, &mut fb);
    });
    let vertex_ns = median_ns(|| {
        bins.clear();
        Scene3d.draw::<T, Rgb565, S, BINS>(&p, ANGLE, &mut bins).unwrap();
    });
    let tris = bins.len();
    let frame = fb.px.clone();

    // Errors: the same screen triangles with Rgb888 colours, and their sources.
    let (bins8, ids) = bins_with_ids::<T, Rgb888, S>(&p, ANGLE);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let fragments = bins8
        .iter()
        .map(|t| TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None).map(|s| s.len as u64).sum::<u64>())
        .sum();
    // Which bin is visible where: bin index + 1 as a flat colour.
    let idbins: Vec<ScreenTriangle<S>> = bins8
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let mut t = *t;
            let n = (i + 1) as u32;
            t.v[0].color = [(n >> 16) as u8, (n >> 8) as u8, n as u8];
            t.flat = true;
            t
        })
        .collect();
    let (idc, codes) = full_frame::<F, Affine, S>(&idbins);
    let (colors, _) = full_frame::<F, M, S>(&bins8);
    let mut row = Row3d {
        knob,
        setting: setting.to_string(),
        frame_ns,
        vertex_ns,
        tris,
        fragments,
        band_bytes: Band::<Rgb565, W, BH>::BYTES + DepthBand::<F, W, BH>::BYTES,
        frame,
        ..Row3d::default()
    };
    let (mut dsum, mut dn, mut csum, mut cn, mut rsum, mut rn) = (0.0, 0usize, 0.0, 0usize, 0.0, 0usize);
    for i in 0..W * H {
        let [a, b, c] = idc[i].to_channels();
        let bin = ((a as usize) << 16 | (b as usize) << 8 | c as usize).checked_sub(1);
        let src = bin.map_or(u32::MAX, |b| ids[b]);
        let r = &reference.px[i];
        row.vis_tri += usize::from(src != r.id);
        row.vis_obj += usize::from(src >> 16 != r.id >> 16);
        if let Some(b) = bin {
            let (x, y) = ((i % W) as i32, (i / W) as i32);
            let want = exact_color(&bins8[b], x, y);
            let got = colors[i].to_channels();
            for k in 0..3 {
                let e = (got[k] as f64 - want[k]).abs();
                row.color_max = row.color_max.max(e);
                csum += e;
                cn += 1;
            }
            // Vertex depths are `z/w · (2^32 − 1)` (`ScreenVertex::depth`).
            let l = bary(&bins8[b], x, y);
            let plane = (0..3).map(|k| l[k] * bins8[b].v[k].depth as f64).sum::<f64>() / 4294967295.0;
            let e = (codes[i] as f64 - plane * F::MAX as f64).abs();
            row.raster_depth_max = row.raster_depth_max.max(e);
            rsum += e;
            rn += 1;
            if src == r.id {
                let e = (codes[i] as f64 - r.depth * F::MAX as f64).abs();
                row.depth_max = row.depth_max.max(e);
                dsum += e;
                dn += 1;
            }
        }
    }
    row.depth_mean = dsum / dn.max(1) as f64;
    row.depth_mean_range = row.depth_mean / F::MAX as f64 * 65536.0;
    row.raster_depth_mean = rsum / rn.max(1) as f64;
    row.color_mean = csum / cn.max(1) as f64;
    row
}

/// One setting of a 2D sweep on scene 1.
#[derive(Clone, Debug, Default)]
pub struct Row2d {
    /// Knob name.
    pub knob: &'static str,
    /// The setting.
    pub setting: String,
    /// Configuration key.
    pub key: String,
    /// Host time of the frame (band renderer into a slice framebuffer), ns.
    pub frame_ns: f64,
    /// Pixels of the frame whose top triangle differs from the f64
    /// rasterizer's on the unsnapped vertices.
    pub mismatches: usize,
    /// Pixels the f64 rasterizer covers (the denominator of the rate).
    pub ref_covered: usize,
    /// Pixels differing from the baseline frame (16-row bands).
    pub differs_from_baseline: usize,
    /// The frame.
    pub frame: Vec<Rgb565>,
}

/// Scene 1 before snapping.
pub fn fine_scene() -> Vec<FineTriangle> {
    let mut v = Vec::new();
    scenes::scatter_fine(W as u32, H as u32, &mut |t| v.push(t)).unwrap();
    v
}

/// Scene 1's unsnapped vertices snapped to `S` bits (round to nearest, ties
/// to even, by the library's fixed-point snapping).
pub fn snapped<const S: u32>(fine: &[FineTriangle]) -> Vec<Primitive<Rgb565, S>> {
    fine.iter()
        .map(|t| {
            let v = t.v.map(|(x, y)| {
                SubPoint::<S>::from_fixed(I16F16::from_bits(x as i32), I16F16::from_bits(y as i32)).unwrap()
            });
            let [r, g, b] = t.rgb[0];
            Triangle::flat(v, Rgb565::new(r >> 3, g >> 2, b >> 3)).into()
        })
        .collect()
}

/// The top triangle (index + 1, 0 for none) at every pixel, f64 reference on
/// the unsnapped vertices.
pub fn reference_ids(fine: &[FineTriangle]) -> Vec<u16> {
    let mut ids = vec![0u16; W * H];
    for (i, t) in fine.iter().enumerate() {
        let v = t.v.map(|(x, y)| (x as f64 / 65536.0, y as f64 / 65536.0));
        float_triangle(v, |x, y| ids[y * W + x] = (i + 1) as u16);
    }
    ids
}

/// Scene 1 at `S` subpixel bits with `BH`-row bands.
pub fn run2d<const S: u32, const BH: usize>(
    fine: &[FineTriangle],
    ref_ids: &[u16],
    knob: &'static str,
    setting: &str,
) -> Row2d {
    let prims = snapped::<S>(fine);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let mut ids = vec![0u16; W * H];
    for (i, p) in prims.iter().enumerate() {
        let Primitive::Triangle(t) = p else { unreachable!() };
        for s in TriangleSpans::new(t.vertices(), clip, Cull::None) {
            let row = s.y as usize * W;
            ids[row + s.x as usize..row + s.x as usize + s.len as usize].fill((i + 1) as u16);
        }
    }
    let mismatches = ids.iter().zip(ref_ids).filter(|(a, b)| a != b).count();
    let ref_covered = ref_ids.iter().filter(|&&v| v != 0).count();
    let scene = Scene2d::<S>::from_prims(prims);
    let mut band = Box::new(Band::<Rgb565, W, BH>::new(BG));
    let mut fb = SliceFb::default();
    let frame_ns = median_ns(|| mr_band(&scene, &mut band, &mut fb));
    Row2d {
        knob,
        setting: setting.to_string(),
        frame_ns,
        mismatches,
        ref_covered,
        frame: fb.px.clone(),
        ..Row2d::default()
    }
}

/// Fragments per band-height for the 3D scene are the same; this gives the
/// number of `(triangle, band)` setups, the work that grows as bands shrink.
pub fn setups_per_frame<const S: u32>(tris: &[ScreenTriangle<S>], bh: usize) -> usize {
    tris.iter()
        .map(|t| {
            let (lo, hi) = t.rows();
            let (lo, hi) = (lo.max(0), hi.min(H as i32 - 1));
            if lo > hi { 0 } else { (hi as usize / bh) - (lo as usize / bh) + 1 }
        })
        .sum()
}
