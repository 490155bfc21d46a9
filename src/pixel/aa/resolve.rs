//! The resolve: each pixel's `K` samples box-filtered into one pixel
//! (`K = N²` on the whole grid, `N` for [`MsaaSparse`](super::MsaaSparse)).
//!
//! Per channel, in the colour's native depth ([`Interpolate::to_channels`]),
//! the pixel is the mean of its `K` samples rounded to nearest, ties up:
//! `⌊(2·Σ + K) / (2·K)⌋`. So a pixel whose samples all hold one colour is
//! that colour exactly (the common case, which skips the arithmetic), and a
//! white-on-black pixel with `k` covered samples is `round(k/K · max)`.

use super::{Antialias, mode_ok};
use crate::Interpolate;
use crate::band::BandView;

/// Resolves the sample rows of `samples` into the rows of `out`: output row
/// `y` comes from sample rows `y·N .. y·N + N`, output column `x` from sample
/// columns `x·COLS .. x·COLS + COLS` ([`Antialias::N`], [`Antialias::COLS`]).
/// Output rows whose samples the view lacks are left as they are.
/// `SW == W·COLS` and a supported `N` are checked at compile time.
///
/// This is the last step of
/// [`Antialiased`](crate::aa::Antialiased); call
/// it yourself inside [`from_fn`](crate::render::from_fn)
/// to mix anti-aliased and custom drawing.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_graphics::prelude::*;
/// use microraster::aa::{Ssaa, resolve::resolve};
/// use microraster::blit::Blitter;
/// use microraster::Band;
/// let mut samples = Band::<Gray8, 4, 2>::new(Gray8::BLACK);
/// let mut out = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
/// let mut sv = samples.view(0, 2, Gray8::BLACK);
/// sv.set_pixel(0, 0, Gray8::WHITE); // 1 of pixel 0's 4 samples
/// sv.set_pixel(2, 0, Gray8::WHITE); // 3 of pixel 1's 4 samples
/// sv.set_pixel(3, 0, Gray8::WHITE);
/// sv.set_pixel(3, 1, Gray8::WHITE);
/// let mut ov = out.view(0, 1, Gray8::BLACK);
/// resolve::<Ssaa<2>, _, 2, 4>(&mut sv, &mut ov);
/// let px: Vec<u8> = ov.pixels().map(|c| c.luma()).collect();
/// assert_eq!(px, [64, 191]); // 255/4 = 63.75 → 64, 765/4 = 191.25 → 191
/// ```
pub fn resolve<A, C, const W: usize, const SW: usize>(
    samples: &mut BandView<'_, C, SW>,
    out: &mut BandView<'_, C, W>,
) where
    A: Antialias,
    C: Interpolate,
{
    const {
        assert!(
            mode_ok::<A>() && SW == W * A::COLS,
            "anti-aliasing needs a supported N and a sample band of W·COLS × H·N"
        )
    };
    let n = A::N;
    let oy0 = out.y0();
    for r in 0..out.height() {
        // Frame rows fit i32 (`MAX_FRAME_DIM`·`MAX_GRID`); a view elsewhere just misses.
        let Some(sy) = (oy0 as i64 + r as i64).checked_mul(n as i64).and_then(|v| i32::try_from(v).ok())
        else {
            continue;
        };
        let last = sy.checked_add(n as i32 - 1);
        if samples.row_mut(sy).is_none() || last.and_then(|l| samples.row_mut(l)).is_none() {
            continue;
        }
        let Some(orow) = out.row_mut(oy0 + r as i32) else { continue };
        for (x, px) in orow.iter_mut().enumerate() {
            *px = resolve_block::<A, C, SW>(samples, sy, x * A::COLS);
        }
    }
}

/// The pixel of the block whose top-left sample is `(sx, sy)`; every row
/// `sy .. sy + N` is in the view (checked by the caller).
#[inline]
fn resolve_block<A: Antialias, C: Interpolate, const SW: usize>(
    samples: &mut BandView<'_, C, SW>,
    sy: i32,
    sx: usize,
) -> C {
    let (n, cols) = (A::N, A::COLS);
    let first = samples.row_mut(sy).and_then(|row| row.get(sx).copied());
    let Some(first) = first else { return C::from_channels([0; 3]) };
    let mut uniform = true;
    for j in 0..n as i32 {
        if let Some(block) = samples.row_mut(sy + j).and_then(|row| row.get(sx..sx + cols)) {
            uniform &= block.iter().all(|&c| c == first);
        }
    }
    if uniform {
        return first;
    }
    let mut sum = [0u32; 3];
    for j in 0..n as i32 {
        if let Some(block) = samples.row_mut(sy + j).and_then(|row| row.get(sx..sx + cols)) {
            for c in block {
                let ch = c.to_channels();
                for k in 0..3 {
                    sum[k] += u32::from(ch[k]); // ≤ 64 · 255
                }
            }
        }
    }
    let n2 = (n * cols) as u32;
    C::from_channels(sum.map(|s| ((2 * s + n2) / (2 * n2)) as u8))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Band;
    use crate::aa::Ssaa;
    use crate::blit::Blitter;
    use embedded_graphics_core::pixelcolor::Rgb565;

    fn check<A: Antialias, const SW: usize, const SH: usize>(seed: u64) {
        let n = A::N;
        let mut state = seed;
        let mut next = |m: u8| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 33) % (m as u64 + 1)) as u8
        };
        let mut samples = Band::<Rgb565, SW, SH>::new(Rgb565::new(0, 0, 0));
        let mut out = Band::<Rgb565, 5, 3>::new(Rgb565::new(0, 0, 0));
        let mut sv = samples.view(3 * n as i32, SH, Rgb565::new(0, 0, 0)); // frame rows 3..6
        let max = Rgb565::CHANNEL_MAX;
        for y in 0..SH as i32 {
            for x in 0..SW as i32 {
                // Half the blocks uniform, the others random per sample.
                let c = if (x / n as i32 + y / n as i32) % 2 == 0 {
                    Rgb565::new(7, 50, 1)
                } else {
                    Rgb565::from_channels([next(max[0]), next(max[1]), next(max[2])])
                };
                sv.set_pixel(x, 3 * n as i32 + y, c);
            }
        }
        let mut ov = out.view(3, 3, Rgb565::new(0, 0, 0));
        resolve::<A, Rgb565, 5, SW>(&mut sv, &mut ov);
        let px: [Rgb565; 15] = core::array::from_fn(|i| ov.pixels().nth(i).unwrap());
        for (i, p) in px.iter().enumerate() {
            let (bx, by) = (i % 5 * n, i / 5 * n);
            let mut sum = [0u32; 3];
            for y in by..by + n {
                for x in bx..bx + n {
                    let c = samples.rows()[y][x].to_channels();
                    (0..3).for_each(|k| sum[k] += c[k] as u32);
                }
            }
            // Round half up of the exact mean, in f64.
            let want = sum.map(|s| (s as f64 / (n * n) as f64 + 0.5).floor() as u8);
            assert_eq!(p.to_channels(), want, "pixel {i}, sums {sum:?}");
        }
    }

    #[test]
    fn resolve_rounds_the_mean_of_each_channel_to_nearest() {
        for seed in 0..20 {
            check::<Ssaa<1>, 5, 3>(seed);
            check::<Ssaa<2>, 10, 6>(seed);
            check::<Ssaa<3>, 15, 9>(seed);
            check::<Ssaa<8>, 40, 24>(seed);
        }
    }
}
