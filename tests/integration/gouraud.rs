//! Gouraud colour against an f64 barycentric reference on the same snapped
//! vertices. `attr.rs` derives the bound: every channel is within
//! 0.5 + 2^13·2^-20 = 0.5 + 2^-7 of the exact value at the pixel centre.

use crate::framebuffer::Framebuffer;
use crate::reference::Rng;
use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888};
use microraster::blit::TargetBlitter;
use microraster::edge::Cull;
use microraster::{Interpolate, SubPoint, Triangle};

const BOUND: f64 = 0.5 + 1.0 / 128.0;

fn check<C: Interpolate + Default, const S: u32>(rng: &mut Rng, triangles: usize) -> (usize, f64) {
    let (w, h) = (200u32, 150u32);
    let one = f64::from(1u32 << S);
    let (mut pixels, mut worst) = (0usize, 0f64);
    for _ in 0..triangles {
        // Mixed sizes: slivers to larger than the frame, vertices far outside too.
        let scale = [4i64, 40, 400, 4000][rng.below(4) as usize];
        let mut pt = || {
            let cx = rng.range(-50, w as i64 + 50);
            let cy = rng.range(-50, h as i64 + 50);
            let x = (cx << S) + rng.range(-scale << S, scale << S);
            let y = (cy << S) + rng.range(-scale << S, scale << S);
            SubPoint::<S>::new(x as i32, y as i32).unwrap()
        };
        let v = [pt(), pt(), pt()];
        let max = C::CHANNEL_MAX;
        let ch: [[u8; 3]; 3] = [0, 1, 2].map(|_| [0, 1, 2].map(|k| rng.below(max[k] as u64 + 1) as u8));
        let tri = Triangle::gouraud(v, ch.map(C::from_channels));
        let mut fb = Framebuffer::new(w, h, C::default());
        tri.draw(&mut TargetBlitter::new(&mut fb), Cull::None);

        let p: Vec<(f64, f64)> = v.iter().map(|q| (f64::from(q.x()) / one, f64::from(q.y()) / one)).collect();
        let det = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
        for y in 0..h {
            for x in 0..w {
                let i = (y * w + x) as usize;
                if fb.writes[i] == 0 {
                    continue;
                }
                assert_eq!(fb.writes[i], 1);
                let (px, py) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
                let l1 = ((px - p[0].0) * (p[2].1 - p[0].1) - (py - p[0].1) * (p[2].0 - p[0].0)) / det;
                let l2 = ((p[1].0 - p[0].0) * (py - p[0].1) - (p[1].1 - p[0].1) * (px - p[0].0)) / det;
                let got = fb.pixels[i].to_channels();
                for k in 0..3 {
                    let c = |j: usize| f64::from(ch[j][k]);
                    let exact = c(0) + l1 * (c(1) - c(0)) + l2 * (c(2) - c(0));
                    let err = (f64::from(got[k]) - exact).abs();
                    worst = worst.max(err);
                    assert!(
                        err <= BOUND + 1e-9,
                        "channel {k} at ({x},{y}): got {} exact {exact} for {v:?} {ch:?}",
                        got[k]
                    );
                }
                pixels += 1;
            }
        }
    }
    (pixels, worst)
}

#[test]
fn gouraud_matches_f64_barycentric_reference() {
    let mut rng = Rng::new(0x6a09e667);
    let n = 1500;
    let runs = [
        ("Rgb888 S=8", check::<Rgb888, 8>(&mut rng, n)),
        ("Rgb565 S=4", check::<Rgb565, 4>(&mut rng, n)),
        ("Gray8  S=0", check::<Gray8, 0>(&mut rng, n)),
        ("Gray8  S=6", check::<Gray8, 6>(&mut rng, n)),
    ];
    for (name, (pixels, worst)) in runs {
        println!("gouraud {name}: {n} triangles, {pixels} pixels, worst error {worst:.4} (bound {BOUND:.4})");
        assert!(pixels > 100_000, "{name}: too few pixels checked ({pixels})");
    }
}
