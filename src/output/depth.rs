//! Integer depth (z) buffers, one per band, with the bit depth as a type parameter.
//!
//! A [`DepthBand<F, W, H>`] holds `H` rows of `W` depth values in the format
//! `F`: [`NoDepth`] (no storage, every test passes), [`Depth8`], [`Depth16`],
//! [`Depth24`] or [`Depth32`]. Like the colour [`Band`](crate::Band) it is
//! owned by the user, built by a `const fn`, and its size is checked at
//! compile time. Memory per 320-wide, 16-row band ([`DepthBand::BYTES`],
//! asserted by a unit test against `W · H · size_of::<Storage>()`):
//!
//! | format      | storage | bits | bytes per 320 × 16 band |
//! |-------------|---------|------|-------------------------|
//! | [`NoDepth`] | `()`    | 0    | 0                       |
//! | [`Depth8`]  | `u8`    | 8    | 5,120                   |
//! | [`Depth16`] | `u16`   | 16   | 10,240                  |
//! | [`Depth24`] | `u32`   | 24   | 20,480                  |
//! | [`Depth32`] | `u32`   | 32   | 20,480                  |
//!
//! [`Depth24`] is kept unpacked in a `u32` (one aligned word per access), so
//! it costs as much memory as [`Depth32`]; it exists to reproduce the values
//! of 24-bit GPU depth buffers.
//!
//! # What is stored: screen-space `z/w`
//! A depth value is `d = z_clip / w_clip ∈ [0, 1]` (0 at the near plane, 1 at
//! the far plane, the D3D/Vulkan convention), quantized to `b` bits as
//! `round(d · (2^b − 1))`. For a perspective projection with near and far
//! distances `n < f` and eye distance `z`, `d = f/(f − n) · (1 − n/z)`.
//!
//! `d` is an affine function of `1/w`, and `1/w` is affine in screen `x, y`
//! over a triangle, so `d` is *exactly linear in screen space*: it is
//! interpolated by the same integer plane arithmetic as the edge functions
//! and Gouraud colour, with no per-pixel division.
//!
//! The price is that precision is concentrated near the near plane. One code
//! step `Δ = 1/(2^b − 1)` in `d` spans an eye-space distance of
//! `Δz ≈ z² · Δ · (f − n)/(f · n) ≈ z² · Δ / n` (for `f ≫ n`), and half of
//! all codes lie between `n` and `2fn/(f + n) ≈ 2n`. With `n = 0.1`,
//! `f = 100` and [`Depth16`], `Δz` is about 0.00015 at `z = 1`, 0.015 at
//! `z = 10` and 1.5 at `z = 100`; [`Depth24`] divides these by 256, and
//! [`Depth8`] multiplies them by 257. Moving the near plane out is the most
//! effective fix: `Δz` scales with `1/n`.
//!
//! Alternatives we did not choose: storing `w` (a "W-buffer") gives uniform
//! eye-space precision, but `w` is not linear in screen space, so every pixel
//! would need a division (or a perspective-correct interpolator) and the
//! result would not be exact; storing `1/w` is screen-linear but, once scaled
//! to the integer range, is just an affine remap of `z/w` without the
//! near/far normalisation. `z/w` interpolates exactly and matches the depth
//! values D3D and Vulkan produce. Reversed depth (near = 1) only helps
//! floating-point buffers; with integers it has the same precision, and can
//! be had with [`DepthTest::Greater`] and [`DepthBand::clear_to`]`(rows, 0)`.
//!
//! # Quantization guarantee
//! With `MAX = 2^b − 1` ([`DepthFormat::MAX`]):
//!
//! * [`quantize_unit`] maps `u = d · 2^32` (`0..=2^32`, larger values clamp to
//!   `2^32`) to `round(u · MAX / 2^32)`;
//! * [`quantize_f32`] maps an `f32` `d` to `round(d · MAX)`, clamping `d` to
//!   `[0, 1]` (negative values and `-0.0` give 0, values above 1 give `MAX`);
//!   NaN and infinities are [`Error::NonFiniteCoordinate`](crate::Error::NonFiniteCoordinate).
//!
//! Both are computed exactly in `u64` integer arithmetic (no floating-point
//! operation at all, so soft-float targets pay nothing) and round ties up:
//! the result is the correctly rounded value for every input, hence
//! monotonic non-decreasing, with 0 → 0 and 1 → `MAX` exactly.
//!
//! ```
//! use microraster::depth::{quantize_f32, quantize_unit, Depth16, Depth8, DepthBand, DepthState};
//! assert_eq!(quantize_f32::<Depth8>(0.5), Ok(128)); // 127.5 rounds up
//! assert_eq!(quantize_unit::<Depth16>(1 << 32), 0xFFFF);
//! let mut z = DepthBand::<Depth16, 320, 16>::new(); // every value is FAR = 0xFFFF
//! let near = u32::from(quantize_f32::<Depth16>(0.25)?);
//! assert!(z.test_and_set(3, 10, near, DepthState::LESS_WRITE));
//! assert!(!z.test_and_set(3, 10, near + 1, DepthState::LESS_WRITE)); // farther: hidden
//! assert_eq!(z.get(3, 10), Some(near));
//! # Ok::<(), microraster::Error>(())
//! ```

use crate::MAX_FRAME_DIM;

mod format;
pub use format::{
    Depth8, Depth16, Depth24, Depth32, DepthFormat, NoDepth, UNIT_ONE, quantize_f32, quantize_unit,
};
mod rows;
pub use rows::DepthRows;

/// A depth comparison: does a new fragment at depth `new` pass against the
/// `stored` value? (Default: [`Less`](DepthTest::Less).)
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub enum DepthTest {
    /// `new < stored`: nearer wins (with depth 0 at the near plane).
    #[default]
    Less,
    /// `new <= stored`.
    LessEqual,
    /// `new > stored` (for reversed depth).
    Greater,
    /// `new >= stored`.
    GreaterEqual,
    /// `new == stored`.
    Equal,
    /// `new != stored`.
    NotEqual,
    /// Always passes.
    Always,
    /// Never passes.
    Never,
}

impl DepthTest {
    /// Whether `new` passes against `stored`.
    ///
    /// ```
    /// use microraster::depth::DepthTest;
    /// const P: bool = DepthTest::LessEqual.passes(7, 7);
    /// assert!(P && !DepthTest::Less.passes(7, 7));
    /// ```
    #[inline]
    pub const fn passes(self, new: u32, stored: u32) -> bool {
        match self {
            DepthTest::Less => new < stored,
            DepthTest::LessEqual => new <= stored,
            DepthTest::Greater => new > stored,
            DepthTest::GreaterEqual => new >= stored,
            DepthTest::Equal => new == stored,
            DepthTest::NotEqual => new != stored,
            DepthTest::Always => true,
            DepthTest::Never => false,
        }
    }
}

/// How a primitive uses the depth buffer: the test, and whether passing
/// fragments write their depth. (Default: [`DepthState::LESS_WRITE`].)
///
/// ```
/// use microraster::depth::{DepthState, DepthTest};
/// // Opaque geometry: nearer wins and is remembered.
/// assert_eq!(DepthState::default(), DepthState::LESS_WRITE);
/// // Translucent geometry: tested against the opaque, never written.
/// let glass = DepthState::new(DepthTest::Less, false);
/// assert!(!glass.write);
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct DepthState {
    /// The comparison a fragment must pass to be drawn.
    pub test: DepthTest,
    /// Whether a passing fragment stores its depth.
    pub write: bool,
}

impl DepthState {
    /// Nearer fragments win and record their depth: ordinary opaque geometry.
    pub const LESS_WRITE: Self = Self::new(DepthTest::Less, true);
    /// Like [`LESS_WRITE`](Self::LESS_WRITE), but equal depth also passes
    /// (multi-pass drawing of the same geometry).
    pub const LESS_EQUAL_WRITE: Self = Self::new(DepthTest::LessEqual, true);
    /// Tested like [`LESS_WRITE`](Self::LESS_WRITE) but never written:
    /// transparent geometry drawn after the opaque scene.
    pub const READ_ONLY: Self = Self::new(DepthTest::Less, false);
    /// Always drawn, depth recorded (e.g. a background that resets depth).
    pub const ALWAYS_WRITE: Self = Self::new(DepthTest::Always, true);
    /// Always drawn, depth untouched: the depth buffer is ignored.
    pub const DISABLED: Self = Self::new(DepthTest::Always, false);

    /// A state with this test and write flag.
    pub const fn new(test: DepthTest, write: bool) -> Self {
        DepthState { test, write }
    }
}

impl Default for DepthState {
    fn default() -> Self {
        Self::LESS_WRITE
    }
}

/// `H` rows of `W` depth values in format `F`, matching a colour
/// [`Band<C, W, H>`](crate::Band). `W · H · size_of::<F::Storage>()` bytes
/// ([`DepthBand::BYTES`]): zero for [`NoDepth`].
///
/// `W` and `H` must be 1 to [`MAX_FRAME_DIM`]; anything else is a compile
/// error.
///
/// ```
/// use microraster::depth::{Depth16, DepthBand, NoDepth};
/// static Z: DepthBand<Depth16, 320, 16> = DepthBand::new();
/// assert_eq!(Z.get(15, 319), Some(0xFFFF));
/// assert_eq!(DepthBand::<NoDepth, 320, 16>::BYTES, 0);
/// ```
///
/// ```compile_fail
/// use microraster::depth::{Depth16, DepthBand};
/// let z = DepthBand::<Depth16, 0, 16>::new(); // W = 0 is rejected
/// ```
#[derive(Clone)]
pub struct DepthBand<F: DepthFormat, const W: usize, const H: usize> {
    rows: [[F::Storage; W]; H],
}

impl<F: DepthFormat, const W: usize, const H: usize> DepthBand<F, W, H> {
    const CHECK: () = assert!(
        W >= 1 && H >= 1 && W <= MAX_FRAME_DIM as usize && H <= MAX_FRAME_DIM as usize,
        "depth band width and height must be 1..=MAX_FRAME_DIM"
    );

    /// Bytes of memory the band occupies.
    pub const BYTES: usize = core::mem::size_of::<Self>();

    /// A band with every value [`FAR`](DepthFormat::FAR).
    pub const fn new() -> Self {
        let () = Self::CHECK;
        DepthBand { rows: [[F::FAR; W]; H] }
    }

    /// A band with every value 0. The renderers clear each band to far before
    /// drawing, so this is as good as [`DepthBand::new`] for them, and as a
    /// `static` it goes to `.bss` (zero-initialised RAM) instead of costing
    /// its size in flash as well.
    pub const fn zeroed() -> Self {
        let () = Self::CHECK;
        DepthBand { rows: [[F::ZERO; W]; H] }
    }

    /// The rows of stored depth.
    pub fn rows(&self) -> &[[F::Storage; W]; H] {
        &self.rows
    }

    /// Row `i`, or `None` if `i ≥ H`.
    pub fn row(&self, i: usize) -> Option<&[F::Storage; W]> {
        self.rows.get(i)
    }

    /// Row `i` for writing, or `None` if `i ≥ H`.
    pub fn row_mut(&mut self, i: usize) -> Option<&mut [F::Storage; W]> {
        self.rows.get_mut(i)
    }

    /// The value at row `row`, column `x` (0 for [`NoDepth`]), or `None`
    /// outside the band.
    pub fn get(&self, row: usize, x: usize) -> Option<u32> {
        self.rows.get(row)?.get(x).map(|&s| F::to_u32(s))
    }

    /// Sets the first `rows` rows (at most `H`) to [`FAR`](DepthFormat::FAR).
    #[inline]
    pub fn clear(&mut self, rows: usize) {
        self.fill(rows, F::FAR);
    }

    /// Sets the first `rows` rows (at most `H`) to `z` (clamped to `MAX`);
    /// `clear_to(rows, 0)` prepares reversed depth.
    pub fn clear_to(&mut self, rows: usize, z: u32) {
        self.fill(rows, F::from_u32(z));
    }

    fn fill(&mut self, rows: usize, v: F::Storage) {
        if F::ENABLED {
            crate::band::clear_rows(&mut self.rows[..rows.min(H)], v);
        }
    }

    /// Applies `state` to a fragment at depth `z` (clamped to `MAX`) over
    /// pixel `(x, row)`: returns whether it passes the test, and stores `z`
    /// if it passes and `state.write` is set. Outside the band: `false`.
    ///
    /// For [`NoDepth`] this is the constant `true` (there is no depth test,
    /// whatever `state` and the indices), and compiles to nothing.
    #[inline]
    pub fn test_and_set(&mut self, row: usize, x: usize, z: u32, state: DepthState) -> bool {
        if !F::ENABLED {
            return true;
        }
        let Some(slot) = self.rows.get_mut(row).and_then(|r| r.get_mut(x)) else {
            return false;
        };
        let z = z.min(F::MAX);
        let pass = state.test.passes(z, F::to_u32(*slot));
        if pass && state.write {
            *slot = F::from_u32(z);
        }
        pass
    }
}

impl<F: DepthFormat, const W: usize, const H: usize> Default for DepthBand<F, W, H> {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests;
