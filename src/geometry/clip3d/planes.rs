//! The planes of [`clip3d`](super): [`ClipPlanes`] and the guard-band formulas.

use crate::clip::MAX_FRAME_DIM;
use crate::edge::fast_path_extent_px;
use crate::math::Scalar;
use crate::subpixel::MAX_SUBPIXEL_BITS;

/// Which planes to clip against (see [`clip3d`](super)); `Copy` settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClipPlanes {
    guard: f32,
    far: bool,
    w_min: f32,
}

impl ClipPlanes {
    /// Default guard-band factor, 256: safe for the range of every viewport
    /// up to [`MAX_FRAME_DIM`] at every subpixel precision
    /// (`guard_band_for_range(4096, 4096, 8) ≈ 510`). An Fx viewport transform
    /// needs a smaller one: [`guard_band_for_limit`]`(w, h, 32767)`.
    pub const DEFAULT_GUARD_BAND: f32 = 256.0;
    /// Largest guard-band factor, 2^30.
    pub const MAX_GUARD_BAND: f32 = 1073741824.0;
    /// Default lower bound on `w`, 2^-16 (see [`clip3d`](super)).
    pub const W_MIN: f32 = 1.0 / 65536.0;
    /// Near, far, `w ≥ W_MIN` and the guard band [`Self::DEFAULT_GUARD_BAND`].
    pub const DEFAULT: Self = ClipPlanes { guard: Self::DEFAULT_GUARD_BAND, far: true, w_min: Self::W_MIN };
    /// [`Self::DEFAULT`] without the far plane.
    pub const NO_FAR: Self = Self::DEFAULT.with_far(false);

    /// Clips at `z ≤ w` too if `far`.
    pub const fn with_far(self, far: bool) -> Self {
        ClipPlanes { far, ..self }
    }

    /// Guard band `|x|, |y| ≤ g·w`; `g` is clamped to `1..=MAX_GUARD_BAND`
    /// (NaN gives 1).
    pub const fn with_guard_band(self, g: f32) -> Self {
        ClipPlanes { guard: clamp(g, 1.0, Self::MAX_GUARD_BAND), ..self }
    }

    /// Lower bound on `w`, clamped to `2^-32..=1` (NaN gives [`Self::W_MIN`]).
    /// In [`Fx`](crate::math::Fx) values below 2^-16 act as 2^-16.
    pub const fn with_w_min(self, w: f32) -> Self {
        let w_min = if w.is_nan() { Self::W_MIN } else { clamp(w, 1.0 / 4294967296.0, 1.0) };
        ClipPlanes { w_min, ..self }
    }

    /// [`Self::DEFAULT`] with the guard band of [`guard_band_for_range`].
    pub const fn for_viewport(width: u32, height: u32, s: u32) -> Self {
        Self::DEFAULT.with_guard_band(guard_band_for_range(width, height, s))
    }

    /// [`Self::DEFAULT`] with the guard band of [`guard_band_for_fast_path`].
    pub const fn for_viewport_fast_path(width: u32, height: u32, s: u32) -> Self {
        Self::DEFAULT.with_guard_band(guard_band_for_fast_path(width, height, s))
    }

    /// The guard-band factor `g`.
    pub const fn guard_band(self) -> f32 {
        self.guard
    }
    /// Whether the far plane is clipped.
    pub const fn far(self) -> bool {
        self.far
    }
    /// The lower bound on `w`.
    pub const fn w_min(self) -> f32 {
        self.w_min
    }
}

impl Default for ClipPlanes {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// `v` clamped to `lo..=hi`; NaN gives `lo`.
const fn clamp(v: f32, lo: f32, hi: f32) -> f32 {
    if v.is_nan() || v < lo {
        lo
    } else if v > hi {
        hi
    } else {
        v
    }
}

/// `max(width, height)` clamped to `1..=MAX_FRAME_DIM`.
const fn side(width: u32, height: u32) -> u32 {
    let m = if width > height { width } else { height };
    if m == 0 {
        1
    } else if m > MAX_FRAME_DIM {
        MAX_FRAME_DIM
    } else {
        m
    }
}

const SAFETY: f32 = 1.0 - 1.0 / 1024.0; // covers every rounding of divide, viewport and snap

/// Largest guard band `g` for which every pixel coordinate stays within
/// `±limit_px` after the divide and the viewport transform
/// `px = x0 + (1 + x/w)·width/2`, `py = y0 + (1 − y/w)·height/2`, for any
/// viewport of that size inside the frame (`0 ≤ x0`, `x0 + width ≤
/// MAX_FRAME_DIM`): then `|px| ≤ MAX_FRAME_DIM + (g − 1)·max(width, height)/2`,
/// so `g = 1 + 2·(limit_px·(1 − 2^-10) − 1 − MAX_FRAME_DIM)/max(width, height)`,
/// at least 1. With `limit_px = 32767` this also keeps an
/// [`Fx`](crate::math::Fx) viewport transform from saturating.
pub const fn guard_band_for_limit(width: u32, height: u32, limit_px: u32) -> f32 {
    let m = side(width, height);
    let room = limit_px as f32 * SAFETY - 1.0 - MAX_FRAME_DIM as f32;
    clamp(1.0 + 2.0 * room / m as f32, 1.0, ClipPlanes::MAX_GUARD_BAND)
}

/// The widest guard band whose output the rasterizer accepts at `s` subpixel
/// bits: [`guard_band_for_limit`] with `limit = 2^(28−s)` px, the
/// [`SubPoint`](crate::SubPoint) range (`s` is clamped to
/// [`MAX_SUBPIXEL_BITS`]). 320×240: `g ≈ 104730` at `s = 4`, `≈ 6522` at
/// `s = 8`. Hardly any triangle is clipped in x/y, but one larger than the
/// [`fast_path_extent_px`] in pixels runs on the rasterizer's `i64` path.
pub const fn guard_band_for_range(width: u32, height: u32, s: u32) -> f32 {
    let s = if s > MAX_SUBPIXEL_BITS { MAX_SUBPIXEL_BITS } else { s };
    guard_band_for_limit(width, height, 1 << (28 - s))
}

/// The guard band that keeps every clipped triangle on the rasterizer's
/// `i32` fast path at `s` subpixel bits: its bounding box is at most
/// `g·max(width, height)` px, so `g = (E − 1)·(1 − 2^-10)/max(width, height)`
/// with `E = fast_path_extent_px(s)`, at least 1 (a viewport wider than `E`
/// cannot be guaranteed the fast path). 320×240: `E = 5791`, `g ≈ 18.08` at
/// `s = 4`; `E = 1447`, `g ≈ 4.51` at `s = 8`. The trade against
/// [`guard_band_for_range`]: big triangles are cut into fans of up to 8
/// (more setups, more vertices), but every row runs in `i32`.
pub const fn guard_band_for_fast_path(width: u32, height: u32, s: u32) -> f32 {
    let s = if s > MAX_SUBPIXEL_BITS { MAX_SUBPIXEL_BITS } else { s };
    let m = side(width, height);
    let e = fast_path_extent_px(s) as f32;
    clamp((e - 1.0) * SAFETY / m as f32, 1.0, ClipPlanes::MAX_GUARD_BAND)
}

/// Signed distance of `v` to the plane `p`, `≥ 0` inside.
pub(super) fn plane_dist<U: Scalar>(g: U, w_min: U, v: [U; 4], p: Plane) -> U {
    let [x, y, z, w] = v;
    match p {
        Plane::W => w - w_min,
        Plane::Near => z,
        Plane::Far => w - z,
        Plane::XNeg => g * w + x,
        Plane::XPos => g * w - x,
        Plane::YNeg => g * w + y,
        Plane::YPos => g * w - y,
    }
}

/// The planes, in clipping order (bit `i` of an outcode is `PLANES[i]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Plane {
    W,
    Near,
    Far,
    XNeg,
    XPos,
    YNeg,
    YPos,
}
pub(super) const PLANES: [Plane; 7] =
    [Plane::W, Plane::Near, Plane::Far, Plane::XNeg, Plane::XPos, Plane::YNeg, Plane::YPos];
