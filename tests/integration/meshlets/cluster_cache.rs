//! The frame's cluster record (`ClusterCache`) changes no pixel.

use super::{BG, Clustered, H, W, binned, covered, direct, model, pipeline, torus, torus_of};
use crate::framebuffer::Framebuffer;
use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::{Depth16, DepthBand, DepthState};
use microraster::edge::Cull;
use microraster::math::{Mat4, Vec3, transform};
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::Affine;
use microraster::render::Direct3d;
use microraster::{Band, Renderer};

/// One frame of `c` through `cache` (16-row bands, f32, affine), each band
/// drawing the mesh once per model of `models`, model `k` with cache
/// `k mod cache.len()` (whose record holds `N` clusters).
fn frame_with<const N: usize, const K: usize>(
    c: &Clustered,
    p: &Pipeline<f32, 4>,
    models: &[Mat4<f32>],
    cache: &mut [ClusterCache<f32, 4, N, K>],
) -> Vec<Rgb565> {
    let mut fb = Framebuffer::new(W as u32, H, BG);
    let (mut band, mut depth) = (Band::<Rgb565, W, 16>::new(BG), DepthBand::<Depth16, W, 16>::new());
    let mesh = c.meshlets();
    let n = cache.len();
    Renderer::new(H, BG)
        .render(
            Direct3d::new(&mut depth, DepthState::LESS_WRITE, Affine, |band| {
                for (k, model) in models.iter().enumerate() {
                    p.draw_meshlets(&mesh, model, Rgb565::new(28, 44, 12), &mut cache[k % n], band)?;
                }
                Ok(())
            }),
            &mut band,
            &mut fb,
        )
        .unwrap();
    fb.pixels
}

/// The frame's cluster record (`ClusterCache`) never changes a frame: one
/// cache kept through frames of other matrices, shared by two (each with a
/// record) or five (more than it keeps records of) placements of a mesh
/// drawn in turn in every band, and kept while the mesh itself is
/// moved in place (same buffers, same matrix: only the new frame tells),
/// draws what fresh caches draw.
#[test]
fn a_kept_cluster_cache_draws_what_fresh_caches_draw() {
    let mut c = torus();
    let mut kept = [ClusterCache::new(), ClusterCache::new()];
    let fresh = || [ClusterCache::new(), ClusterCache::new()];
    for i in 0..6 {
        let (angle, eye) = (i as f32 * 0.71, [0.5 * i as f32 - 1.2, 1.0, 3.4]);
        let p = pipeline::<f32>(Cull::Clockwise, eye);
        let one = [model::<f32>(angle)];
        let want = frame_with(&c, &p, &one, &mut fresh());
        assert!(covered(&want) > 1000);
        assert_eq!(frame_with(&c, &p, &one, &mut kept), want, "frame {i}");
        let two =
            [model::<f32>(angle), transform::translation(Vec3::new(0.9, -0.4, -1.0)) * model::<f32>(angle)];
        let want = frame_with(&c, &p, &two, &mut fresh());
        assert_eq!(frame_with(&c, &p, &two, &mut kept[..1]), want, "frame {i}, one cache for two");
        assert_eq!(frame_with(&c, &p, &two, &mut kept), want, "frame {i}, a cache each");
        // More placements than one cache keeps records of (four): they
        // take each other's places in turn.
        let five = [0.0, 0.5, 1.0, 1.5, 2.0].map(|dx| {
            transform::translation(Vec3::new(dx - 1.0, 0.3 * dx - 0.3, -2.0 - dx)) * model::<f32>(angle)
        });
        let want = frame_with(&c, &p, &five, &mut [0; 5].map(|_| ClusterCache::new()));
        assert_eq!(frame_with(&c, &p, &five, &mut kept[..1]), want, "frame {i}, one cache for five");
    }
    // The mesh moved in place between two frames of the same matrix.
    let p = pipeline::<f32>(Cull::Clockwise, [0.3, 1.0, 3.4]);
    let one = [model::<f32>(0.4)];
    let before = frame_with(&c, &p, &one, &mut kept);
    let shift = [0.0, 0.7, 0.0];
    for v in c.positions.iter_mut() {
        (0..3).for_each(|k| v[k] += shift[k]);
    }
    for m in c.meshlets.iter_mut() {
        (0..3).for_each(|k| m.sphere.0[k] += shift[k]);
    }
    (0..3).for_each(|k| c.sphere.0[k] += shift[k]);
    let want = frame_with(&c, &p, &one, &mut fresh());
    assert_ne!(want, before, "the move shows");
    assert_eq!(frame_with(&c, &p, &one, &mut kept), want, "after the move");
}

/// A mesh of more clusters than the frame record keeps: those beyond it are
/// tested per band, and the image is still the binned path's.
#[test]
fn clusters_beyond_the_frame_record_are_drawn() {
    let c = torus_of(128, 24);
    assert!(c.meshlets.len() > microraster::pipeline::FRAME_CLUSTERS + 100, "{}", c.meshlets.len());
    for (i, cull) in [Cull::Clockwise, Cull::None].into_iter().enumerate() {
        let p = pipeline::<f32>(cull, [0.4 * i as f32 - 0.8, 1.1, 3.3]);
        let angle = 0.5 + i as f32;
        let reference = binned::<f32, Affine, 16>(&c, &p, angle);
        assert!(covered(&reference) > 1000);
        assert_eq!(direct::<f32, Affine, 16>(&c, &p, angle, Affine), reference, "{cull:?}");
    }
}

/// The record's capacity changes no pixel: none (every cluster tested per
/// band), part of the mesh's clusters, all of them; for one mesh, or for
/// two placements drawn in turn with records for none, one or both.
#[test]
fn the_record_capacity_changes_no_pixel() {
    let c = torus();
    assert!(c.meshlets.len() > 64, "{}", c.meshlets.len());
    for i in 0..4 {
        let p = pipeline::<f32>(Cull::Clockwise, [0.5 * i as f32 - 1.0, 1.2, 3.3]);
        let angle = 0.9 * i as f32;
        let reference = binned::<f32, Affine, 16>(&c, &p, angle);
        let one = [model::<f32>(angle)];
        let none = frame_with(&c, &p, &one, &mut [ClusterCache::<f32, 4, 0, 0>::sized()]);
        assert_eq!(none, reference, "none {i}");
        let part = frame_with(&c, &p, &one, &mut [ClusterCache::<f32, 4, 64>::sized()]);
        assert_eq!(part, reference, "64 {i}");
        assert_eq!(frame_with(&c, &p, &one, &mut [ClusterCache::new()]), reference, "256 {i}");
        let two =
            [model::<f32>(angle), transform::translation(Vec3::new(0.8, 0.2, -1.5)) * model::<f32>(angle)];
        let want = frame_with(&c, &p, &two, &mut [ClusterCache::new(), ClusterCache::new()]);
        for (k, got) in [
            frame_with(&c, &p, &two, &mut [ClusterCache::<f32, 4, 256, 0>::sized()]),
            frame_with(&c, &p, &two, &mut [ClusterCache::<f32, 4, 256, 1>::sized()]),
            frame_with(&c, &p, &two, &mut [ClusterCache::<f32, 4, 100, 2>::sized()]),
        ]
        .into_iter()
        .enumerate()
        {
            assert_eq!(got, want, "two placements, {k} records, {i}");
        }
    }
}
