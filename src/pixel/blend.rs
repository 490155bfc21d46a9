//! Alpha blending into the band buffer: replace, mix (source-over), multiply,
//! additive, colour add and colour subtract.
//!
//! # Equations
//!
//! Blending works per channel in the colour's native depth
//! ([`Interpolate::to_channels`], maximum `m = CHANNEL_MAX[k]`: 31 or 63 for
//! `Rgb565`, 255 for `Rgb888`, 1 for `BinaryColor`), with an 8-bit alpha
//! `α ∈ 0..=255` (255 = opaque). For source channel `s` and destination
//! channel `d` (both in `0..=m`), each mode computes exactly:
//!
//! | mode | result | alpha |
//! |---|---|---|
//! | [`Replace`] | `s` | ignored |
//! | [`Mix`] (source-over) | `round((d·(255 − α) + s·α) / 255)` = `d + round((s − d)·α/255)` | weights `s` against `d` |
//! | [`Multiply`] | `round(d·(255·m − α·(m − s)) / (255·m))` | fades from `d` (α = 0) to `round(s·d/m)` (α = 255) |
//! | [`Additive`] | `min(m, d + round(s·α/255))` | weights `s` |
//! | [`ColorAdd`] | `min(m, d + s)` | ignored |
//! | [`ColorSubtract`] | `max(0, d − s)` | ignored |
//!
//! `round` is round-to-nearest with ties rounded up. Ties cannot occur when
//! the denominator is odd, which covers every denominator above for the
//! `embedded-graphics` colour types (255 and every `m = 2^b − 1` are odd);
//! the rule only matters for a user [`Interpolate`] type with an even maximum
//! in [`Multiply`]. Consequences: [`Mix`] with α = 255 is `s` and with α = 0
//! is `d`, and its result always lies between `s` and `d` (no saturation is
//! needed); [`Multiply`] with α = 255 is exactly `round(s·d/m)`, so white is
//! its identity and black gives black.
//!
//! **Additive vs colour add.** [`Additive`] is the alpha-weighted "glow"
//! blend, `d + s·α` (saturating); [`ColorAdd`] adds the raw channels and
//! ignores alpha, like [`ColorSubtract`]. Channels a colour type lacks
//! (maximum 0) stay 0.
//!
//! All arithmetic is `u32` integer arithmetic on `u8` inputs: nothing can
//! overflow, and no input (not even channel values above the maximum from a
//! faulty [`Interpolate`] implementation) panics. The division by 255 is a
//! multiply-shift, checked against exact rational arithmetic over its whole
//! domain by the tests; the other divisions are by constants of the colour
//! type, which the compiler turns into multiplications.
//!
//! # Static and runtime choice
//!
//! Each mode is a zero-sized type implementing [`Blend`], so a span loop
//! monomorphizes per mode and a program pays only for the modes it uses.
//! [`BlendMode`] chooses at run time; its span methods dispatch once per span
//! to the same per-mode loops.
//!
//! # Drawing translucent primitives
//!
//! [`BlendBlitter`] is a [`Blitter`](crate::blit::Blitter) that blends into
//! a [`BlendTarget`] (a [`BandView`](crate::band::BandView), or your own
//! readable framebuffer), so every 2D primitive can be drawn translucent.
//! Draw the opaque geometry first, then the translucent geometry through the
//! blitter:
//!
//! ```
//! use embedded_graphics::pixelcolor::Gray8;
//! use microraster::blend::{BlendBlitter, Mix};
//! use microraster::{edge::Cull, Band, SubPoint, Triangle};
//! let p = |x, y| SubPoint::<4>::from_pixels(x, y).unwrap();
//! let mut band = Band::<Gray8, 4, 4>::new(Gray8::new(0));
//! let mut view = band.view(0, 4, Gray8::new(100));
//! let tri = Triangle::flat([p(0, 0), p(4, 0), p(0, 4)], Gray8::new(200));
//! tri.draw(&mut BlendBlitter::new(&mut view, Mix, 64), Cull::None);
//! // 100 + round((200 − 100)·64/255) = 100 + round(25.098) = 125
//! assert_eq!(band.rows()[0], [Gray8::new(125), Gray8::new(125), Gray8::new(125), Gray8::new(100)]);
//! ```
//!
//! # Transparent 3D geometry
//!
//! Draw transparent meshes after all opaque ones, with the depth test on and
//! depth writes off ([`DepthState::READ_ONLY`](crate::depth::DepthState::READ_ONLY)),
//! so they are hidden by opaque surfaces in front of them but do not hide
//! each other. Blending is order-dependent ([`Mix`] is not commutative), so
//! sort the transparent meshes farthest first with [`back_to_front`]. That
//! orders whole meshes only: where transparent surfaces overlap — two meshes
//! that interpenetrate, or a mesh seen through itself — the result still
//! depends on drawing order, and no per-mesh sort can fix that.

use crate::color::Interpolate;

mod sort;
mod target;
pub use sort::{back_to_front, back_to_front_by, view_depth};
pub use target::{BlendBlitter, BlendTarget};

/// Fully opaque alpha.
pub const OPAQUE: u8 = 255;

/// `round(x / 255)` for `x ≤ 65_025` (= 255²), exact: no ties exist because 255
/// is odd, and the tests check every `x` in the domain against `(2x + 255) /
/// 510`.
#[inline]
pub(crate) const fn div255_round(x: u32) -> u32 {
    let y = x + 128;
    (y + (y >> 8)) >> 8
}

/// `round(num / den)` with ties up, for `den > 0`.
#[inline]
const fn div_round(num: u32, den: u32) -> u32 {
    (2 * num + den) / (2 * den)
}

/// A blend equation. Implemented by the zero-sized mode types ([`Mix`],
/// [`Multiply`], …) and by the runtime [`BlendMode`]; see the
/// [module docs](self) for the exact equations.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::blend::{Blend, ColorAdd, Mix};
/// let (s, d) = (Rgb565::new(31, 0, 10), Rgb565::new(0, 63, 30));
/// assert_eq!(Mix.blend(s, d, 255), s);
/// assert_eq!(Mix.blend(s, d, 0), d);
/// assert_eq!(ColorAdd.blend(s, d, 0), Rgb565::new(31, 63, 31)); // saturates
/// ```
pub trait Blend: Copy {
    /// One channel: source `s`, destination `d`, channel maximum `max`
    /// (`s` and `d` are normally in `0..=max`), alpha `alpha`.
    fn channel(self, s: u8, d: u8, max: u8, alpha: u8) -> u8;

    /// `src` blended over `dst` with `alpha`, channel by channel.
    #[inline]
    fn blend<C: Interpolate>(self, src: C, dst: C, alpha: u8) -> C {
        let (s, d, m) = (src.to_channels(), dst.to_channels(), C::CHANNEL_MAX);
        let mut out = [0u8; 3];
        for k in 0..3 {
            if m[k] > 0 {
                out[k] = self.channel(s[k], d[k], m[k], alpha);
            }
        }
        C::from_channels(out)
    }

    /// Blends `src` (one colour per pixel) over `dst`, pixel by pixel, until
    /// either runs out.
    #[inline]
    fn blend_span<C: Interpolate, I: IntoIterator<Item = C>>(self, dst: &mut [C], src: I, alpha: u8) {
        for (d, s) in dst.iter_mut().zip(src) {
            *d = self.blend(s, *d, alpha);
        }
    }

    /// Blends one colour over every pixel of `dst`.
    ///
    /// A run of one destination colour (a flat or vertically graded
    /// background under a translucent panel) is blended once: the last
    /// destination and its result are kept, so the same pixel costs a
    /// comparison. The result is the same, as blending reads the colour's
    /// channels only (colours equal by `==` have equal channels).
    #[inline]
    fn blend_fill<C: Interpolate>(self, dst: &mut [C], src: C, alpha: u8) {
        let Some(first) = dst.first().copied() else { return };
        let mut last = (first, self.blend(src, first, alpha));
        for d in dst.iter_mut() {
            if *d != last.0 {
                last = (*d, self.blend(src, *d, alpha));
            }
            *d = last.1;
        }
    }
}

macro_rules! mode {
    ($(#[$doc:meta])* $name:ident, |$s:ident, $d:ident, $m:ident, $a:ident| $body:expr) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        pub struct $name;

        impl Blend for $name {
            #[inline]
            fn channel(self, $s: u8, $d: u8, $m: u8, $a: u8) -> u8 {
                let ($s, $d, $m, $a) = (u32::from($s), u32::from($d), u32::from($m), u32::from($a));
                let _ = $a;
                // Every body's result is at most max(s, d, m) ≤ 255.
                ($body) as u8
            }
        }
    };
}

mode!(
    /// `s`: the source replaces the destination; alpha is ignored.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray4;
    /// use microraster::blend::{Blend, Replace};
    /// assert_eq!(Replace.blend(Gray4::new(3), Gray4::new(9), 0), Gray4::new(3));
    /// ```
    Replace,
    |s, d, m, a| {
        let _ = (d, m);
        s
    }
);

mode!(
    /// Source-over: `round((d·(255 − α) + s·α) / 255)`, i.e. `d + round((s −
    /// d)·α/255)`.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::blend::{Blend, Mix};
    /// // (10·155 + 250·100)/255 = 104.1 → 104
    /// assert_eq!(Mix.blend(Gray8::new(250), Gray8::new(10), 100), Gray8::new(104));
    /// ```
    Mix,
    |s, d, m, a| {
        let _ = m;
        div255_round(d * (255 - a) + s * a)
    }
);

mode!(
    /// Multiply, faded by alpha: `round(d·(255·m − α·(m − s)) / (255·m))`;
    /// with α = 255 that is `round(s·d/m)`, with α = 0 it is `d`.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use microraster::blend::{Blend, Multiply};
    /// let d = Rgb565::new(20, 40, 31);
    /// // 20·15/31 = 9.68 → 10, 40·63/63 = 40, 31·0/31 = 0
    /// assert_eq!(Multiply.blend(Rgb565::new(15, 63, 0), d, 255), Rgb565::new(10, 40, 0));
    /// assert_eq!(Multiply.blend(Rgb565::new(15, 63, 0), d, 0), d);
    /// ```
    Multiply,
    |s, d, m, a| {
        let s = s.min(m); // keeps m − s ≥ 0 for a faulty Interpolate implementation
        div_round(d * (255 * m - a * (m - s)), 255 * m)
    }
);

mode!(
    /// Alpha-weighted additive: `min(m, d + round(s·α/255))`.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use microraster::blend::{Additive, Blend};
    /// // 100 + round(200·128/255) = 100 + round(100.39) = 200
    /// assert_eq!(Additive.blend(Gray8::new(200), Gray8::new(100), 128), Gray8::new(200));
    /// assert_eq!(Additive.blend(Gray8::new(200), Gray8::new(100), 255), Gray8::new(255));
    /// ```
    Additive,
    |s, d, m, a| (d + div255_round(s * a)).min(m)
);

mode!(
    /// Saturating colour add: `min(m, d + s)`; alpha is ignored.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray2;
    /// use microraster::blend::{Blend, ColorAdd};
    /// assert_eq!(ColorAdd.blend(Gray2::new(2), Gray2::new(2), 0), Gray2::new(3));
    /// ```
    ColorAdd,
    |s, d, m, a| (d + s).min(m)
);

mode!(
    /// Colour subtract saturating at 0: `max(0, d − s)`; alpha is ignored.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray2;
    /// use microraster::blend::{Blend, ColorSubtract};
    /// assert_eq!(ColorSubtract.blend(Gray2::new(3), Gray2::new(2), 0), Gray2::new(0));
    /// assert_eq!(ColorSubtract.blend(Gray2::new(1), Gray2::new(2), 0), Gray2::new(1));
    /// ```
    ColorSubtract,
    |s, d, m, a| {
        let _ = m;
        d.saturating_sub(s)
    }
);

/// A blend mode chosen at run time. Its [`Blend::blend_span`] and
/// [`Blend::blend_fill`] dispatch once per call to the per-mode loops.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::blend::{Blend, BlendMode, Mix};
/// let (s, d) = (Gray8::new(250), Gray8::new(10));
/// assert_eq!(BlendMode::Mix.blend(s, d, 77), Mix.blend(s, d, 77));
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub enum BlendMode {
    /// [`Replace`].
    Replace,
    /// [`Mix`] (source-over), the default.
    #[default]
    Mix,
    /// [`Multiply`].
    Multiply,
    /// [`Additive`].
    Additive,
    /// [`ColorAdd`].
    ColorAdd,
    /// [`ColorSubtract`].
    ColorSubtract,
}

impl BlendMode {
    /// Every mode, in declaration order.
    pub const ALL: [BlendMode; 6] = [
        BlendMode::Replace,
        BlendMode::Mix,
        BlendMode::Multiply,
        BlendMode::Additive,
        BlendMode::ColorAdd,
        BlendMode::ColorSubtract,
    ];
}

/// Calls `$f` with the zero-sized type of the mode `$mode`.
macro_rules! dispatch {
    ($mode:expr, |$b:ident| $f:expr) => {
        match $mode {
            BlendMode::Replace => {
                let $b = Replace;
                $f
            }
            BlendMode::Mix => {
                let $b = Mix;
                $f
            }
            BlendMode::Multiply => {
                let $b = Multiply;
                $f
            }
            BlendMode::Additive => {
                let $b = Additive;
                $f
            }
            BlendMode::ColorAdd => {
                let $b = ColorAdd;
                $f
            }
            BlendMode::ColorSubtract => {
                let $b = ColorSubtract;
                $f
            }
        }
    };
}

impl Blend for BlendMode {
    #[inline]
    fn channel(self, s: u8, d: u8, max: u8, alpha: u8) -> u8 {
        dispatch!(self, |b| b.channel(s, d, max, alpha))
    }

    #[inline]
    fn blend<C: Interpolate>(self, src: C, dst: C, alpha: u8) -> C {
        dispatch!(self, |b| b.blend(src, dst, alpha))
    }

    fn blend_span<C: Interpolate, I: IntoIterator<Item = C>>(self, dst: &mut [C], src: I, alpha: u8) {
        dispatch!(self, |b| b.blend_span(dst, src, alpha))
    }

    fn blend_fill<C: Interpolate>(self, dst: &mut [C], src: C, alpha: u8) {
        dispatch!(self, |b| b.blend_fill(dst, src, alpha))
    }
}

/// Blends `src` over `dst` pixel by pixel with `mode` and `alpha` (stops when
/// either runs out): the span-level entry point for shading stages.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::blend::{blend_span, Additive};
/// let mut row = [Gray8::new(10), Gray8::new(250)];
/// blend_span(Additive, &mut row, [Gray8::new(20), Gray8::new(20)], 255);
/// assert_eq!(row, [Gray8::new(30), Gray8::new(255)]);
/// ```
#[inline]
pub fn blend_span<B: Blend, C: Interpolate>(
    mode: B,
    dst: &mut [C],
    src: impl IntoIterator<Item = C>,
    alpha: u8,
) {
    mode.blend_span(dst, src, alpha);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `blend_fill` (which blends each run of one destination colour once)
    /// against blending pixel by pixel, for every mode.
    fn fill_is_per_pixel<B: Blend>(mode: B) {
        use embedded_graphics_core::pixelcolor::Rgb565;
        let mut x = 0x2545_f491u32;
        for len in [0usize, 1, 2, 7, 40] {
            for alpha in [0u8, 1, 128, 180, 254, 255] {
                // Runs of repeated colours with changes between them.
                let mut dst = [Rgb565::new(0, 0, 0); 40];
                for (i, d) in dst.iter_mut().enumerate().take(len) {
                    x ^= x << 13;
                    x ^= x >> 17;
                    x ^= x << 5;
                    let v = if i % 3 == 0 { x } else { (i / 5) as u32 };
                    *d = Rgb565::new((v % 32) as u8, ((v >> 5) % 64) as u8, ((v >> 11) % 32) as u8);
                }
                let src = Rgb565::new(6, 50, 28);
                let want: [Rgb565; 40] = core::array::from_fn(|i| mode.blend(src, dst[i], alpha));
                mode.blend_fill(&mut dst[..len], src, alpha);
                assert_eq!(dst[..len], want[..len], "len {len}, alpha {alpha}");
            }
        }
    }

    #[test]
    fn blend_fill_equals_blending_each_pixel() {
        fill_is_per_pixel(Replace);
        fill_is_per_pixel(Mix);
        fill_is_per_pixel(Multiply);
        fill_is_per_pixel(Additive);
        fill_is_per_pixel(ColorAdd);
        fill_is_per_pixel(ColorSubtract);
        fill_is_per_pixel(BlendMode::Mix);
    }

    #[test]
    fn div255_round_is_exact_over_its_domain() {
        for x in 0..=65_025u32 {
            // round(x/255) = floor((2x + 255) / 510); no ties since 255 is odd.
            assert_eq!(div255_round(x), (2 * x + 255) / 510, "x = {x}");
        }
    }
}
