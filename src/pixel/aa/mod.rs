//! Anti-aliasing inside the band model: supersampling ([`Ssaa`]) and
//! multisample coverage ([`Msaa`]), both on an ordered `N × N` grid of samples
//! per pixel, and sparse multisampling ([`MsaaSparse`]) on `N` of those
//! samples, without allocation.
//!
//! # Method
//! The samples of pixel `(x, y)` sit at `((i + ½)/N, (j + ½)/N)` inside it,
//! `i, j = 0..N`: exactly the pixel centres of the frame scaled by `N`. So a
//! band is first rendered into a *sample band*, a [`Band<C, SW, SH>`](Band)
//! with `SW = W·N` and `SH = H·N` (checked at compile time), by the ordinary
//! exact rasterizer ([`TriangleSpans`](crate::edge::TriangleSpans)) on
//! vertices multiplied by `N` — an exact integer operation on the snapped
//! coordinates. Watertightness and the top-left rule carry over to samples:
//! each sample on an edge shared by two triangles belongs to exactly one of
//! them, so shared edges sum to full coverage, with no seams and no dark
//! cracks. Then each `N × N` block is box-filtered into one pixel of the
//! output [`Band<C, W, H>`](Band) ([`mod@resolve`]) and the band goes out with
//! one `fill_contiguous`, as usual.
//!
//! * [`Ssaa`] shades every sample: Gouraud and 3D colour are evaluated at
//!   each sample position.
//! * [`Msaa`] evaluates colour once per pixel, at the pixel centre (also when
//!   the centre itself is outside the triangle: the plane is extrapolated, as
//!   GPUs do without centroid sampling), and writes it to the covered
//!   samples; depth is still tested per sample ([`mod@msaa`]). Flat fills,
//!   and so 2D flat triangles, are identical in both modes.
//! * [`MsaaSparse`] is [`Msaa`] keeping only `N` of the `N²` grid samples,
//!   one in each grid row and column (the D3D standard 2-, 4- and 8-sample
//!   patterns are such subsets). Coverage is the same exact, watertight
//!   sample test, the sample band is `W × H·N` (`COLS = 1` sample a pixel
//!   per sample row), and memory and depth work fall by `N`.
//!
//! Lines stay aliased: each pixel the midpoint algorithm lights fills its
//! whole `N × N` block, so a line's pixels and colour are those of
//! [`Renderer::render`](crate::Renderer::render).
//!
//! # Accuracy
//! Coverage of a pixel is `k/N²`, `k` the covered samples; the resolved
//! channel is `round(Σ samples / N²)` (ties up) in the colour's native depth,
//! so a white-on-black pixel is `round(k/N² · max)`. Against the exact area
//! `a` of the snapped triangle inside the pixel:
//!
//! * pixels inside or outside the triangle (not meeting an edge): exact;
//! * pixels crossed by one edge only: `|k/N² − a| ≤ 1/(2N) + 1/(4N²)`. Cut
//!   the pixel into `N` strips along the axis the edge is steeper against
//!   (`|dx/dy| ≤ 1` for rows). In a strip the samples lie on its mid-line,
//!   where the covered part is an interval `L` anchored at one end, and the
//!   `N` points `(i + ½)/N` count it to within `½` of `N·L`: at most `1/(2N)`
//!   of the pixel over all strips. The strip's area equals `L` times its
//!   height unless the edge leaves the pixel through a side within the strip
//!   (a kink in the cross-section), which moves the midpoint rule by at most
//!   `1/(8N)` of the strip; an edge has at most two such kinks: `1/(4N²)`;
//! * other pixels (a vertex inside, or several edges):
//!   `|k/N² − a| ≤ min(1, 4/N)`, from the same strips (rows): counting both
//!   ends of each row's interval errs by less than `1/N` in all; where the
//!   convex cross-section is positive across a whole strip it is concave, so
//!   the midpoint overestimates the strip's mean by at most half the
//!   variation inside the strip (Hermite–Hadamard), at most `1/N` in all as
//!   the cross-section varies by at most 2; the (at most two) strips where it
//!   starts or ends add at most `1/N` each. This is loose: the measured
//!   maximum is below `1/N` (slivers thinner than the sample spacing, which
//!   miss every sample, approach it), and the tests also hold that.
//!
//! For [`MsaaSparse`] (`N` samples, one per grid row and column) a pixel
//! crossed by one horizontal or vertical edge is within `1/(2N)`, as on the
//! whole grid: along the edge's normal the `N` samples sit at the `N` grid
//! positions. Other directions have no bound better than the trivial one
//! proven here; measured over the same triangles, one-edge pixels reach
//! 0.30 (mean 0.067) at `N = 4` (the 2 × 2 grid, same memory: 0.25, mean
//! 0.066) and 0.21 (mean 0.043) at `N = 8`.
//!
//! `tests/integration/antialias.rs` checks these bounds over thousands of
//! random triangles and prints the measured maxima and means; at `N = 2, 4`
//! one-edge pixels reach 0.25 and 0.125 (mean 0.066, 0.023), the others
//! 0.49 and 0.24 (mean 0.056, 0.022).
//!
//! # Memory
//! Bytes per band, 320 px wide, 16-row bands, `Rgb565` colour and `Depth16`
//! (`Band::BYTES`, `DepthBand::BYTES`; asserted below). The output band is
//! needed in every mode; the depth band is at sample resolution for both
//! [`Ssaa`] and [`Msaa`] and absent for 2D scenes. Memory grows as `N²`; the band
//! height is the lever: `N = 4` with 4-row bands costs what `N = 2` with
//! 16-row bands costs (1280 × 16 = 640 × 32 samples).
//!
//! | mode | samples | output band | depth | total |
//! |---|---|---|---|---|
//! | aliased | — | 10,240 | 10,240 | 20,480 |
//! | `N = 2` | 40,960 | 10,240 | 40,960 | 92,160 |
//! | `N = 4` | 163,840 | 10,240 | 163,840 | 337,920 |
//!
//! | [`MsaaSparse`] `N = 4` | 40,960 | 10,240 | 40,960 | 92,160 |
//! | [`MsaaSparse`] `N = 8` | 81,920 | 10,240 | 81,920 | 174,080 |
//!
//! Without depth (2D scenes): 51,200 bytes at `N = 2` (and sparse 4),
//! 174,080 at `N = 4`.
//!
//! ```
//! use embedded_graphics::pixelcolor::Rgb565;
//! use microraster::Band;
//! use microraster::depth::{Depth16, DepthBand};
//! type Px = Band<Rgb565, 320, 16>;
//! assert_eq!((Px::BYTES, DepthBand::<Depth16, 320, 16>::BYTES), (10_240, 10_240));
//! let n2 = Band::<Rgb565, 640, 32>::BYTES + Px::BYTES + DepthBand::<Depth16, 640, 32>::BYTES;
//! let n4 = Band::<Rgb565, 1280, 64>::BYTES + Px::BYTES + DepthBand::<Depth16, 1280, 64>::BYTES;
//! assert_eq!((Band::<Rgb565, 640, 32>::BYTES, n2), (40_960, 92_160));
//! assert_eq!((Band::<Rgb565, 1280, 64>::BYTES, n4), (163_840, 337_920));
//! // Sparse patterns keep one sample a pixel per sample row.
//! let s4 = Band::<Rgb565, 320, 64>::BYTES + Px::BYTES + DepthBand::<Depth16, 320, 64>::BYTES;
//! let s8 = Band::<Rgb565, 320, 128>::BYTES + Px::BYTES + DepthBand::<Depth16, 320, 128>::BYTES;
//! assert_eq!((Band::<Rgb565, 320, 64>::BYTES, s4, s8), (40_960, 92_160, 174_080));
//! // 2D scenes need no depth band.
//! assert_eq!(Band::<Rgb565, 640, 32>::BYTES + Px::BYTES, 51_200);
//! assert_eq!(Band::<Rgb565, 1280, 64>::BYTES + Px::BYTES, 174_080);
//! ```
//!
//! # Ranges
//! Vertices are multiplied by `N`, so the coordinate range of
//! [`SubPoint`] shrinks by `N` (a scene beyond it is
//! [`Error::CoordinateOutOfRange`], before anything is drawn), and the frame
//! height times `N` must not exceed [`MAX_FRAME_DIM`] (else
//! [`Error::InvalidFrameSize`]); `W·N` is bounded the same way by the sample
//! band's own compile-time check. A triangle takes the `i32` fast path when
//! its extent is within [`fast_path_extent_px`](crate::edge::fast_path_extent_px)` / N`.
//!
//! # Cost
//! `cargo run --release --example antialias` times the standard 2D and 3D
//! scenes (320 × 240, `Rgb565`, 16-row bands) in each mode and writes the
//! frames. Per sample, [`Ssaa`] costs what aliased rendering costs per pixel,
//! plus the resolve; [`Msaa`] replaces per-sample colour by one evaluation per
//! touched pixel and some bookkeeping per pixel, which pays where colour is
//! dear (perspective-correct 3D: over 2× faster than [`Ssaa`] at `N = 4` on
//! the host) and not for 2D Gouraud, whose colour steps cheaply along a span
//! (there [`Ssaa`] is about 2× faster at `N = 2`). [`MsaaSparse`] with 4
//! samples costs about what the 2 × 2 grid costs, in memory and 3D time.
//!
//! # Cost when unused
//! Everything here is generic and reached only through
//! [`Antialiased`] and
//! [`Antialiased3d`]:
//! a program that does not call them compiles none of it.

pub mod msaa;
mod render;
pub use render::{Antialiased, Antialiased3d, Supersampled};
pub mod resolve;

use crate::raster3d::ScreenTriangle;
use crate::{Error, MAX_FRAME_DIM, SubPoint};
use core::marker::PhantomData;

#[cfg(doc)]
use crate::Band;

/// The largest grid: up to 8 × 8 = 64 samples per pixel.
pub const MAX_GRID: usize = 8;

mod sealed {
    pub trait Sealed {}
    impl<const N: usize> Sealed for super::Ssaa<N> {}
    impl<const N: usize> Sealed for super::Msaa<N> {}
    impl<const N: usize> Sealed for super::MsaaSparse<N> {}
}

/// An anti-aliasing mode: [`Ssaa`], [`Msaa`] or [`MsaaSparse`], with the grid
/// size `N` (1 to [`MAX_GRID`]; 2, 4 or 8 for [`MsaaSparse`]; anything else
/// is a compile error where it is used).
pub trait Antialias: sealed::Sealed + Copy + Default {
    /// Samples per pixel along each axis of the grid.
    const N: usize;
    /// Samples kept per pixel in each sample row: `N` (the whole grid) or 1
    /// (a sparse pattern). A pixel has `N · COLS` samples.
    const COLS: usize;
    /// True when colour is evaluated once per pixel.
    const SHADE_PER_PIXEL: bool;
    /// For sparse patterns, the grid column of the sample in each grid row
    /// (the first `N` entries).
    const PATTERN: [u8; MAX_GRID];
}

/// Supersampling: `N × N` samples per pixel, each shaded.
///
/// ```
/// use microraster::aa::{Antialias, Ssaa};
/// assert_eq!(<Ssaa<4> as Antialias>::N, 4);
/// assert!(!<Ssaa<4> as Antialias>::SHADE_PER_PIXEL);
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Ssaa<const N: usize>;

/// Multisampling: `N × N` coverage (and depth) samples per pixel, colour
/// evaluated once per pixel at its centre.
///
/// ```
/// use microraster::aa::{Antialias, Msaa};
/// assert!(<Msaa<2> as Antialias>::SHADE_PER_PIXEL);
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Msaa<const N: usize>;

/// Sparse multisampling: `N` samples per pixel, one in each row and column
/// of the `N × N` grid (an "N-rooks" pattern), colour once per pixel. The
/// patterns are the D3D standard ones for 2, 4 and 8 samples (each a subset
/// of the grid's centres), so coverage is as exact and as watertight as on
/// the whole grid, at `1/N` of its memory and depth work. Near-horizontal and
/// near-vertical edges get `N + 1` levels, as on the whole grid; other
/// directions fewer.
///
/// ```
/// use microraster::aa::{Antialias, MsaaSparse};
/// // D3D's 4× pattern: row j of the 4 × 4 grid keeps column PATTERN[j].
/// assert_eq!(<MsaaSparse<4> as Antialias>::PATTERN[..4], [1, 3, 0, 2]);
/// assert_eq!(<MsaaSparse<4> as Antialias>::COLS, 1);
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MsaaSparse<const N: usize>;

impl<const N: usize> Antialias for Ssaa<N> {
    const N: usize = N;
    const COLS: usize = N;
    const SHADE_PER_PIXEL: bool = false;
    const PATTERN: [u8; MAX_GRID] = [0; MAX_GRID];
}

impl<const N: usize> Antialias for Msaa<N> {
    const N: usize = N;
    const COLS: usize = N;
    const SHADE_PER_PIXEL: bool = true;
    const PATTERN: [u8; MAX_GRID] = [0; MAX_GRID];
}

impl<const N: usize> Antialias for MsaaSparse<N> {
    const N: usize = N;
    const COLS: usize = 1;
    const SHADE_PER_PIXEL: bool = true;
    // D3D11 standard sample positions (1/16 px) mapped to grid rows → columns.
    const PATTERN: [u8; MAX_GRID] = match N {
        2 => [0, 1, 0, 0, 0, 0, 0, 0],
        4 => [1, 3, 0, 2, 0, 0, 0, 0],
        8 => [7, 2, 4, 0, 6, 3, 1, 5],
        _ => [0; MAX_GRID],
    };
}

/// True if `A` is a mode microraster supports: `N` in `1..=MAX_GRID` and, for
/// a sparse pattern, one sample in each grid column.
pub(crate) const fn mode_ok<A: Antialias>() -> bool {
    if A::N < 1 || A::N > MAX_GRID {
        return false;
    }
    if A::COLS == A::N {
        return true;
    }
    let mut seen = [false; MAX_GRID];
    let mut j = 0;
    while j < A::N {
        let c = A::PATTERN[j] as usize;
        if A::COLS != 1 || c >= A::N || seen[c] {
            return false;
        }
        seen[c] = true;
        j += 1;
    }
    A::N > 1
}

/// Compile-time agreement of a mode with its pixel and sample bands.
pub(crate) struct Grid<A, const W: usize, const H: usize, const SW: usize, const SH: usize>(PhantomData<A>);

impl<A: Antialias, const W: usize, const H: usize, const SW: usize, const SH: usize> Grid<A, W, H, SW, SH> {
    pub(crate) const CHECK: () = assert!(
        mode_ok::<A>() && SW == W * A::COLS && SH == H * A::N,
        "anti-aliasing needs a supported N and a sample band of W·COLS × H·N"
    );
}

/// Checks a frame of `height` rows at grid `n` against [`MAX_FRAME_DIM`].
pub(crate) fn check_height(height: u32, n: usize) -> Result<(), Error> {
    match height.checked_mul(n as u32) {
        Some(h) if h <= MAX_FRAME_DIM => Ok(()),
        _ => Err(Error::InvalidFrameSize),
    }
}

/// `p · n`: the same point on the sample grid.
pub(crate) fn scale_point<const S: u32>(p: SubPoint<S>, n: usize) -> Result<SubPoint<S>, Error> {
    let n = n as i64; // ≤ MAX_GRID
    let x = i32::try_from(p.x() as i64 * n).map_err(|_| Error::CoordinateOutOfRange)?;
    let y = i32::try_from(p.y() as i64 * n).map_err(|_| Error::CoordinateOutOfRange)?;
    SubPoint::new(x, y)
}

/// The three vertices, each scaled by `n`.
pub(crate) fn scale_vertices<const S: u32>(v: [SubPoint<S>; 3], n: usize) -> Result<[SubPoint<S>; 3], Error> {
    Ok([scale_point(v[0], n)?, scale_point(v[1], n)?, scale_point(v[2], n)?])
}

/// `tri` on the sample grid: positions scaled by `n`, everything else kept.
pub(crate) fn scale_triangle<const S: u32>(
    tri: &ScreenTriangle<S>,
    n: usize,
) -> Result<ScreenTriangle<S>, Error> {
    let pos = scale_vertices(tri.v.map(|v| v.pos), n)?;
    let mut out = *tri;
    for (v, p) in out.v.iter_mut().zip(pos) {
        v.pos = p;
    }
    Ok(out)
}

impl<const S: u32> ScreenTriangle<S> {
    /// The triangle on the sample grid of `n × n` supersampling: positions
    /// scaled by `n`, depth, `1/w` and colour kept.
    ///
    /// Errors: [`Error::CoordinateOutOfRange`] if a scaled coordinate leaves
    /// the [`SubPoint`] range.
    pub fn scaled(&self, n: usize) -> Result<Self, Error> {
        scale_triangle(self, n)
    }
}

impl<const S: u32, const A: usize> crate::fragment::FragTriangle<S, A> {
    /// [`ScreenTriangle::scaled`] with the varyings kept.
    pub fn scaled(&self, n: usize) -> Result<Self, Error> {
        Ok(crate::fragment::FragTriangle { tri: scale_triangle(&self.tri, n)?, varyings: self.varyings })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaling_is_exact_and_range_checked() {
        let p = SubPoint::<4>::new(-37, 1 << 25).unwrap();
        let q = scale_point(p, 8).unwrap();
        assert_eq!((q.x(), q.y()), (-296, 1 << 28));
        assert_eq!(scale_point(p, 9).map(|_| ()), Err(Error::CoordinateOutOfRange));
        let edge = SubPoint::<0>::new(-(1 << 28), 1 << 28).unwrap();
        assert_eq!(scale_point(edge, 2).map(|_| ()), Err(Error::CoordinateOutOfRange));
        assert_eq!(scale_point(edge, 1), Ok(edge));
    }

    #[test]
    fn height_limit_scales_with_the_grid() {
        assert_eq!(check_height(1024, 4), Ok(()));
        assert_eq!(check_height(1025, 4), Err(Error::InvalidFrameSize));
        assert_eq!(check_height(u32::MAX, 8), Err(Error::InvalidFrameSize));
    }
}
