//! The host peer timing runs (2D scenes, the 3D scene) and where the band renderer's time goes.

use super::Peer;
use crate::common::*;
use crate::timing::median_ns;
use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use microraster::depth::{Depth16, DepthBand};
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::Fx;
use microraster::raster3d::{Affine, PerspectiveCorrect};
use microraster::{Band, ClipRect, Primitive, Renderer};
use microraster_scenes::scenes;

/// The slice pass of `Renderer::render` (the primitives whose rows meet the
/// band, each drawn with the renderer's cull) into a blitter that counts the
/// pixels instead of writing them: the frame's set-up and coverage alone.
struct Coverage<'a, const S: u32>(&'a [Primitive<Rgb565, S>]);

impl<const S: u32, const BW: usize, const BH: usize> microraster::render::Pass<Rgb565, BW, BH>
    for Coverage<'_, S>
{
    // Nothing is written, so nothing needs clearing.
    const CLEARS: bool = false;

    fn draw(
        &mut self,
        band: &mut microraster::band::BandView<'_, Rgb565, BW>,
        renderer: &Renderer<Rgb565>,
    ) -> Result<(), microraster::Error> {
        use microraster::blit::Blitter;
        struct Count(ClipRect, u64);
        impl Blitter<Rgb565> for Count {
            fn clip(&self) -> ClipRect {
                self.0
            }
            fn set_pixel(&mut self, _: i32, _: i32, _: Rgb565) {
                self.1 += 1;
            }
            fn fill_span(&mut self, span: microraster::edge::Span, _: Rgb565) {
                self.1 += span.len as u64;
            }
        }
        let (y0, y1) = (band.y0(), band.y1());
        let mut count = Count(band.clip(), 0);
        for prim in self.0 {
            let (lo, hi) = prim.rows();
            if lo < y1 && hi >= y0 {
                prim.draw(&mut count, renderer.cull());
            }
        }
        std::hint::black_box(count.1);
        Ok(())
    }
}

/// Where the band renderer's time goes on one scene.
pub(crate) struct Breakdown {
    pub(crate) scene: &'static str,
    pub(crate) full: f64,
    pub(crate) empty: f64,
    pub(crate) spans: f64,
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn peers2d(
    peers: &mut Vec<Peer>,
    breakdown: &mut Vec<Breakdown>,
    scene: &'static str,
    f4: scenes::Scene<Rgb565, 4>,
    f8: scenes::Scene<Rgb565, 8>,
    gouraud: Option<scenes::Scene<Rgb565, 4>>,
) {
    let s4 = Scene2d::<4>::new(f4);
    let s8 = Scene2d::<8>::new(f8);
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG));
    let mut slice = SliceFb::default();
    let mut egfb = Box::new(EgFb::new());
    let mut pixmap = tiny_skia::Pixmap::new(W as u32, H as u32).unwrap();
    let mut out = vec![BG; W * H];
    let covered = s4.covered;
    let mut add = |renderer, target, key: String, ns, differs| {
        peers.push(Peer { scene, renderer, target, key, ns, differs, covered });
    };
    let k = |rest: &str| format!("{scene}/{rest}");
    add(
        "microraster, 16-row bands",
        "slice",
        k("band16/S4/flat"),
        median_ns(|| mr_band(&s4, &mut band, &mut slice)),
        Some(0),
    );
    let mine = slice.px.clone();
    let diff = |px: &[Rgb565]| Some(px.iter().zip(&mine).filter(|(a, b)| a != b).count());
    let mut index = Vec::new();
    let t = median_ns(|| mr_binned(&s4, &mut band, &mut index, &mut slice));
    add(
        "microraster, 16-row bands, binned (Binned2d)",
        "slice",
        k("band16/S4/flat/binned"),
        t,
        diff(&slice.px),
    );
    let t = median_ns(|| mr_band(&s8, &mut band, &mut slice));
    add("microraster, 16-row bands, S = 8", "slice", k("band16/S8/flat"), t, diff(&slice.px));
    let t = median_ns(|| mr_direct(&s4, &mut slice));
    add("microraster, direct (TargetBlitter)", "slice", k("direct/S4/flat"), t, diff(&slice.px));
    if let Some(g) = gouraud {
        let sg = Scene2d::<4>::new(g);
        let t = median_ns(|| mr_band(&sg, &mut band, &mut slice));
        add("microraster, 16-row bands, Gouraud", "slice", k("band16/S4/gouraud"), t, None);
        let t = median_ns(|| mr_direct(&sg, &mut slice));
        add("microraster, direct, Gouraud", "slice", k("direct/S4/gouraud"), t, None);
    }
    let t = median_ns(|| mr_band(&s4, &mut band, &mut *egfb));
    add("microraster, 16-row bands", "e-g Framebuffer", k("band16/S4/flat/egfb"), t, None);
    let t = median_ns(|| mr_direct(&s4, &mut *egfb));
    add("microraster, direct (TargetBlitter)", "e-g Framebuffer", k("direct/S4/flat/egfb"), t, None);
    let t = median_ns(|| eg(&s4, &mut slice));
    add("embedded-graphics 0.8", "slice", k("eg/slice"), t, diff(&slice.px));
    let t = median_ns(|| eg(&s4, &mut *egfb));
    add("embedded-graphics 0.8", "e-g Framebuffer", k("eg/egfb"), t, None);
    let t = median_ns(|| skia(&s4, &mut pixmap));
    let sk: Vec<[u8; 3]> = pixmap.pixels().iter().map(|p| [p.red(), p.green(), p.blue()]).collect();
    let d = sk.iter().zip(&mine).filter(|(a, b)| **a != rgb8(**b)).count();
    add("tiny-skia 0.12 (no AA)", "Pixmap RGBA8", k("skia"), t, Some(d));
    let t = median_ns(|| reference(&s4, &mut out));
    add("f64 reference", "slice", k("reference"), t, diff(&out));

    // Where the band renderer's time goes: the empty frame (clear + send),
    // and the same band loop with the frame's coverage but nothing written
    // (`Coverage`: each primitive drawn as the frame draws it, into a
    // blitter that only counts pixels), less the empty frame.
    let empty: [Primitive<Rgb565, 4>; 0] = [];
    let e = median_ns(|| Renderer::new(H as u32, BG).render(&empty, &mut band, &mut slice).unwrap());
    let covering =
        median_ns(|| Renderer::new(H as u32, BG).render(Coverage(&s4.prims), &mut band, &mut slice).unwrap());
    let spans = (covering - e).max(0.0);
    let full = peers.iter().find(|p| p.scene == scene).map_or(0.0, |p| p.ns);
    breakdown.push(Breakdown { scene, full, empty: e, spans });
}

pub(crate) fn peers3d(peers: &mut Vec<Peer>) {
    let (p32, pfx) = (pipeline3d::<f32, 4>(), pipeline3d::<Fx, 4>());
    let mut bins = Box::new(Bins::<4>::new());
    let mut band = Box::new(Band::<Rgb565, W, 16>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut slice = SliceFb::default();
    let mut egfb = Box::new(EgFb::new());
    mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let covered = bins
        .iter()
        .map(|t| TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None).map(|s| s.len as u64).sum::<u64>())
        .sum();
    let mine = slice.px.clone();
    // 3D frames differ by colour rounding: count pixels more than one step off.
    let far = |a: Rgb565, b: Rgb565| {
        let d = |x: u8, y: u8| x.abs_diff(y) > 1;
        d(a.r(), b.r()) || d(a.g(), b.g()) || d(a.b(), b.b())
    };
    let diff = |px: &[Rgb565]| Some(px.iter().zip(&mine).filter(|(a, b)| far(**a, **b)).count());
    let mut add = |renderer, target, key: &str, ns, differs| {
        peers.push(Peer {
            scene: "mesh3d",
            renderer,
            target,
            key: format!("mesh3d/{key}"),
            ns,
            differs,
            covered,
        });
    };
    let t = median_ns(|| {
        mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    });
    add("microraster, f32, perspective-correct", "slice", "f32/D16/persp/band16/S4", t, Some(0));
    let t = median_ns(|| {
        mr3d::<Fx, Depth16, PerspectiveCorrect, 4, 16>(&pfx, &mut bins, &mut band, &mut depth, &mut slice);
    });
    add("microraster, Fx, perspective-correct", "slice", "Fx/D16/persp/band16/S4", t, diff(&slice.px));
    let t = median_ns(|| {
        mr3d::<f32, Depth16, Affine, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut slice);
    });
    add("microraster, f32, affine", "slice", "f32/D16/affine/band16/S4", t, diff(&slice.px));
    let t = median_ns(|| {
        mr3d::<f32, Depth16, PerspectiveCorrect, 4, 16>(&p32, &mut bins, &mut band, &mut depth, &mut *egfb);
    });
    add("microraster, f32, perspective-correct", "e-g Framebuffer", "f32/D16/persp/band16/S4/egfb", t, None);
    let mut px = vec![RefPixel { id: 0, depth: 0.0, color: [0.0; 3] }; W * H];
    let mut out = vec![BG3; W * H];
    let t = median_ns(|| Ref3d::frame(ANGLE, &mut px, &mut out));
    add("f64 reference pipeline", "slice", "reference", t, diff(&out));
}
