//! Sprites: a texture drawn at a position, scaled and rotated, filtered and
//! blended, in one call.
//!
//! # Geometry
//! Unrotated, the sprite is the box of `width·scale × height·scale` pixels
//! whose top-left corner is [`Sprite::at`]; [`Sprite::rotate`] turns it about
//! the box's centre, clockwise on screen (y down) for a positive angle. A
//! pixel belongs to the sprite when its centre maps inside the half-open
//! texture `[0, 1)²`; it samples the texture there with edges clamped. At
//! scale 1 and angle 0 this is texel `(i, j)` at pixel `at + (i, j)`.
//!
//! # Accuracy
//! The pixel-to-texture map is set up in `f64` from the `f32` inputs (the
//! angle's sine and cosine from [`Scalar::sin_cos`](crate::math::Scalar),
//! within 2·10^-7) and stepped per pixel in 2^-32 of the texture; the
//! sample point handed to [`Texture::sample_rgba`] is that truncated to its
//! 2^-16 resolution. Against the `f64` map of the same inputs: with
//! [`Nearest`] every pixel whose exact sample point is farther than
//! `size·2^-16 + 10^-5` texels from a texel border samples the same texel
//! (no tolerance at all for power-of-two sizes at angle 0: the borders are
//! on the grid), and [`Bilinear`](super::Bilinear) is within the filter's
//! bound plus the weight error of that shift
//! (`tests/integration/sprite.rs`).

use super::{Filter, Nearest, Sampler, TexelFormat, Texture, from_rgb8, modulate, shade::div255_round};
use crate::blend::{BlendTarget, Mix};
use crate::math::Scalar;
use crate::{Error, Interpolate, MAX_FRAME_DIM, Param};
use core::marker::PhantomData;
use embedded_graphics_core::prelude::{DrawTarget, Drawable, Pixel, Point};

/// The smallest and largest [`Sprite::scale`] (both allowed); a scale
/// outside is [`Error::InvalidParameter`] when drawn.
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use microraster::texture::{A8, SPRITE_SCALE_RANGE, Sprite, Texture};
/// use microraster::{Band, Error};
/// static DOT: Texture<'static, A8> = Texture::from_rows(&[[255]]);
/// let mut band = Band::<Gray8, 4, 1>::new(Gray8::BLACK);
/// let (lo, hi) = SPRITE_SCALE_RANGE;
/// for scale in [lo, 1.0, hi] {
///     assert_eq!(Sprite::new(&DOT).scale(scale).blend_into(&mut band.view(0, 1, Gray8::BLACK)), Ok(()));
/// }
/// for scale in [lo / 2.0, hi * 2.0, 0.0, -1.0] {
///     let drawn = Sprite::new(&DOT).scale(scale).blend_into(&mut band.view(0, 1, Gray8::BLACK));
///     assert_eq!(drawn, Err(Error::InvalidParameter(microraster::Param::SpriteScale)), "{scale}");
/// }
/// ```
pub const SPRITE_SCALE_RANGE: (f32, f32) = (1.0 / 256.0, 256.0);

/// A texture drawn at a position, scaled, rotated, filtered ([`Nearest`] or
/// [`Bilinear`](super::Bilinear)), tinted and blended, for colour type `C`.
///
/// Two ways to draw it:
/// * [`Sprite::blend_into`] any [`BlendTarget`] (a band's
///   [`BandView`](crate::band::BandView), your framebuffer): source-over with
///   the texel's alpha times [`Sprite::opacity`];
/// * e-g's [`Drawable`] into any `DrawTarget`, which cannot be read back: a
///   cut-out, drawing opaque the pixels whose alpha (times opacity) is at
///   least 128 and nothing elsewhere. Its output is the sprite's own
///   `Result`, so a bad scale or angle is a typed error there too.
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use microraster::blend::{Blend, Mix};
/// use microraster::texture::{Argb4444, Bilinear, Sprite, Texture};
/// use microraster::{Band, Renderer};
/// use microraster::render::from_fn;
/// static ICON: [[u16; 2]; 2] = [[0xFF00, 0x0000], [0x80F0, 0xF00F]]; // red, clear, ½ green, blue
/// static TEX: Texture<'static, Argb4444> = Texture::from_rows(&ICON);
/// let mut band = Band::<Rgb565, 16, 4>::new(Rgb565::BLACK);
/// # let mut display = embedded_graphics::mock_display::MockDisplay::new();
/// Renderer::new(16, Rgb565::WHITE).render(from_fn(|view| {
///     Sprite::new(&TEX).at(Point::new(2, 2)).scale(4.0).blend_into(view)?; // 8×8 px
///     Sprite::new(&TEX).at(Point::new(8, 8)).scale(3.0).rotate(0.5).filter(Bilinear).blend_into(view)
/// }), &mut band, &mut display)?;
/// assert_eq!(display.get_pixel(Point::new(3, 3)), Some(Rgb565::RED));
/// assert_eq!(display.get_pixel(Point::new(7, 3)), Some(Rgb565::WHITE)); // clear texel
/// let half_green = Mix.blend(Rgb565::GREEN, Rgb565::WHITE, 136); // alpha 8/15
/// assert_eq!(display.get_pixel(Point::new(3, 7)), Some(half_green));
/// # Ok::<(), microraster::RenderError<core::convert::Infallible>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Sprite<'t, F: TexelFormat, C, Fi: Filter = Nearest> {
    texture: &'t Texture<'t, F>,
    at: Point,
    scale: f32,
    angle: f32,
    filter: Fi,
    tint: [u8; 3],
    opacity: u8,
    _c: PhantomData<C>,
}

impl<'t, F: TexelFormat, C> Sprite<'t, F, C, Nearest> {
    /// The texture at the origin, scale 1, unrotated, nearest texel, untinted
    /// (white), opaque.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, texture::{A8, Sprite, Texture}};
    /// static TEX: Texture<'static, A8> = Texture::from_rows(&[[255, 255]]);
    /// let mut band = Band::<Gray8, 3, 1>::new(Gray8::BLACK);
    /// Sprite::new(&TEX).blend_into(&mut band.view(0, 1, Gray8::BLACK))?;
    /// assert_eq!(band.rows()[0], [Gray8::WHITE, Gray8::WHITE, Gray8::BLACK]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn new(texture: &'t Texture<'t, F>) -> Self {
        Sprite {
            texture,
            at: Point::zero(),
            scale: 1.0,
            angle: 0.0,
            filter: Nearest,
            tint: [255; 3],
            opacity: 255,
            _c: PhantomData,
        }
    }
}

impl<'t, F: TexelFormat, C, Fi: Filter> Sprite<'t, F, C, Fi> {
    /// The top-left corner of the unrotated box, in pixels.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::Point};
    /// use microraster::{Band, texture::{A8, Sprite, Texture}};
    /// static DOT: Texture<'static, A8> = Texture::from_rows(&[[255]]);
    /// let mut band = Band::<Gray8, 3, 1>::new(Gray8::BLACK);
    /// Sprite::new(&DOT).at(Point::new(2, 0)).blend_into(&mut band.view(0, 1, Gray8::BLACK))?;
    /// assert_eq!(band.rows()[0], [Gray8::BLACK, Gray8::BLACK, Gray8::WHITE]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn at(self, at: Point) -> Self {
        Sprite { at, ..self }
    }

    /// Pixels per texel, in [`SPRITE_SCALE_RANGE`] (checked when drawn).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, Error, texture::{A8, Sprite, Texture}};
    /// static DOT: Texture<'static, A8> = Texture::from_rows(&[[255]]);
    /// let mut band = Band::<Gray8, 3, 1>::new(Gray8::BLACK);
    /// Sprite::new(&DOT).scale(2.0).blend_into(&mut band.view(0, 1, Gray8::BLACK))?;
    /// assert_eq!(band.rows()[0], [Gray8::WHITE, Gray8::WHITE, Gray8::BLACK]);
    /// let too_big = Sprite::new(&DOT).scale(1000.0).blend_into(&mut band.view(0, 1, Gray8::BLACK));
    /// assert_eq!(too_big, Err(Error::InvalidParameter(microraster::Param::SpriteScale)));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn scale(self, scale: f32) -> Self {
        Sprite { scale, ..self }
    }

    /// The angle in radians, clockwise on screen, about the box's centre
    /// (finite; checked when drawn).
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, texture::{A8, Sprite, Texture}};
    /// static HALF: Texture<'static, A8> = Texture::from_rows(&[[255, 0]]); // opaque, clear
    /// let mut band = Band::<Gray8, 2, 1>::new(Gray8::BLACK);
    /// Sprite::new(&HALF).rotate(PI).blend_into(&mut band.view(0, 1, Gray8::BLACK))?; // half a turn
    /// assert_eq!(band.rows()[0], [Gray8::BLACK, Gray8::WHITE]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn rotate(self, angle: f32) -> Self {
        Sprite { angle, ..self }
    }

    /// The same sprite sampled with `filter` ([`Nearest`] or
    /// [`Bilinear`](super::Bilinear)).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, texture::{A8, Bilinear, Sprite, Texture}};
    /// static RAMP: Texture<'static, A8> = Texture::from_rows(&[[0, 255]]);
    /// let mut band = Band::<Gray8, 4, 1>::new(Gray8::BLACK);
    /// // Pixel 1 is a quarter texel right of texel 0's centre: nearest gives texel 0
    /// // (clear), bilinear a quarter of texel 1.
    /// Sprite::new(&RAMP).scale(2.0).filter(Bilinear).blend_into(&mut band.view(0, 1, Gray8::BLACK))?;
    /// let grey = band.rows()[0][1].luma();
    /// assert!(grey > 0 && grey < 128);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn filter<G: Filter>(self, filter: G) -> Sprite<'t, F, C, G> {
        let Sprite { texture, at, scale, angle, tint, opacity, .. } = self;
        Sprite { texture, at, scale, angle, filter, tint, opacity, _c: PhantomData }
    }

    /// Multiplies the texels' colour by `tint` (8-bit channels; white leaves
    /// them unchanged): the colour of an [`A8`](super::A8) mask.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use microraster::{Band, texture::{A8, Sprite, Texture}};
    /// static DOT: Texture<'static, A8> = Texture::from_rows(&[[255]]);
    /// let mut band = Band::<Rgb565, 1, 1>::new(Rgb565::BLACK);
    /// Sprite::new(&DOT).tint([0, 255, 0]).blend_into(&mut band.view(0, 1, Rgb565::BLACK))?;
    /// assert_eq!(band.rows()[0], [Rgb565::GREEN]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn tint(self, tint: [u8; 3]) -> Self {
        Sprite { tint, ..self }
    }

    /// Multiplies the texels' alpha by `opacity / 255`.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use microraster::{Band, blend::{Blend, Mix}, texture::{A8, Sprite, Texture}};
    /// static DOT: Texture<'static, A8> = Texture::from_rows(&[[255]]);
    /// let mut band = Band::<Gray8, 1, 1>::new(Gray8::BLACK);
    /// Sprite::new(&DOT).opacity(128).blend_into(&mut band.view(0, 1, Gray8::BLACK))?;
    /// assert_eq!(band.rows()[0], [Mix.blend(Gray8::WHITE, Gray8::BLACK, 128)]);
    /// # Ok::<(), microraster::Error>(())
    /// ```
    pub fn opacity(self, opacity: u8) -> Self {
        Sprite { opacity, ..self }
    }

    /// The pixel-to-texture map, checked: `Err` for a scale outside
    /// [`SPRITE_SCALE_RANGE`] ([`Error::InvalidParameter`]) or a NaN or
    /// infinite scale or angle ([`Error::NonFiniteCoordinate`]).
    fn map(&self) -> Result<Map, Error> {
        let (s, a) = (self.scale, self.angle);
        if !s.is_finite() || !a.is_finite() {
            return Err(Error::NonFiniteCoordinate);
        }
        if !(SPRITE_SCALE_RANGE.0..=SPRITE_SCALE_RANGE.1).contains(&s) {
            return Err(Error::InvalidParameter(Param::SpriteScale));
        }
        // The crate's sin/cos (std's inherent one would shadow it in host tests).
        let (sin, cos) = Scalar::sin_cos(a);
        let (sin, cos, s) = (f64::from(sin), f64::from(cos), f64::from(s));
        let (w, h) = (f64::from(self.texture.width()), f64::from(self.texture.height()));
        let (hw, hh) = (w * s / 2.0, h * s / 2.0); // half the box, in pixels
        let (cx, cy) = (f64::from(self.at.x) + hw, f64::from(self.at.y) + hh);
        // The box's corners → its pixel bounding box, clipped to the frame range.
        let (ex, ey) = (hw * cos.abs() + hh * sin.abs(), hw * sin.abs() + hh * cos.abs());
        let clip = |lo: f64, hi: f64| {
            let max = f64::from(MAX_FRAME_DIM);
            // Clamped to 0..=4096 first, so truncation is floor and the casts exact.
            let (lo, hi) = ((lo - 0.5).clamp(0.0, max), (hi + 0.5).clamp(0.0, max));
            (lo as i32, hi as i32 + i32::from(f64::from(hi as i32) < hi))
        };
        let (x0, x1) = clip(cx - ex, cx + ex);
        let (y0, y1) = clip(cy - ey, cy + ey);
        // A box wholly outside the frame range covers nothing; its centre
        // may be ~2^31 px away, beyond what the fixed-point map below holds.
        if x0 >= x1 || y0 >= y1 {
            return Ok(Map { x0, x1: x0, y0, y1: y0, u: [0; 3], v: [0; 3] });
        }
        // Texture coordinate (of 1.0 = the whole texture) of a frame point
        // p: R(−a)(p − c)/(s·size) + ½; in units of 2^-32, at the centre of
        // pixel (x0, y0), and its steps per pixel.
        let one = 4_294_967_296.0; // 2^32
        let (dx, dy) = (f64::from(x0) + 0.5 - cx, f64::from(y0) + 0.5 - cy);
        let u = [(cos * dx + sin * dy) / (s * w) + 0.5, cos / (s * w), sin / (s * w)];
        let v = [(cos * dy - sin * dx) / (s * h) + 0.5, -sin / (s * h), cos / (s * h)];
        // The box meets the frame range, so |u0| ≤ 2^13·256 + 1 and |steps| ≤ 256:
        // all below 2^63 at 2^32.
        let fix = |t: f64| floor_i64(t * one + 0.5);
        Ok(Map { x0, x1, y0, y1, u: u.map(fix), v: v.map(fix) })
    }

    /// Calls `pixel(x, y, rgba)` for each sprite pixel in columns `cx0..cx1`,
    /// rows `cy0..cy1` (clamped to the sprite's box and the frame range).
    fn for_each<P: FnMut(i32, i32, [u8; 4])>(&self, clip: [i32; 4], mut pixel: P) -> Result<(), Error> {
        let m = self.map()?;
        let sampler = Sampler { filter: self.filter, ..Sampler::<Fi>::default() }
            .with_address(super::Address::Clamp, super::Address::Clamp);
        let (xa, xb) = (m.x0.max(clip[0]), m.x1.min(clip[2]));
        let (ya, yb) = (m.y0.max(clip[1]), m.y1.min(clip[3]));
        const ONE: i64 = 1 << 32;
        for y in ya..yb {
            let (i, j) = (i64::from(xa - m.x0), i64::from(y - m.y0));
            let (mut u, mut v) = (m.u[0] + i * m.u[1] + j * m.u[2], m.v[0] + i * m.v[1] + j * m.v[2]);
            for x in xa..xb {
                if (0..ONE).contains(&u) && (0..ONE).contains(&v) {
                    // In [0, 2^32): the 2^-16 coordinate fits i32.
                    let [r, g, b, a] =
                        self.texture.sample_rgba(sampler, [(u >> 16) as i32, (v >> 16) as i32]);
                    let [r, g, b] = modulate([r, g, b], self.tint);
                    pixel(x, y, [r, g, b, div255_round(u32::from(a) * u32::from(self.opacity)) as u8]);
                }
                u += m.u[1];
                v += m.v[1];
            }
        }
        Ok(())
    }

    /// Blends the sprite into `target` (source-over, alpha = texel alpha ×
    /// opacity), clipped to the target.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a scale outside
    /// [`SPRITE_SCALE_RANGE`], [`Error::NonFiniteCoordinate`] for a NaN or
    /// infinite scale or angle; nothing is drawn then.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use microraster::blend::{Blend, Mix};
    /// use microraster::texture::{Sprite, Texture, A8};
    /// use microraster::{Band, Error};
    /// static MASK: Texture<'static, A8> = Texture::from_rows(&[[255, 128]]);
    /// let mut band = Band::<Rgb565, 4, 1>::new(Rgb565::BLACK);
    /// let mut view = band.view(0, 1, Rgb565::BLACK);
    /// Sprite::new(&MASK).at(Point::new(1, 0)).tint([255, 0, 0]).blend_into(&mut view)?;
    /// let half_red = Mix.blend(Rgb565::RED, Rgb565::BLACK, 128);
    /// assert_eq!(band.rows()[0], [Rgb565::BLACK, Rgb565::RED, half_red, Rgb565::BLACK]);
    /// let mut view = band.view(0, 1, Rgb565::BLACK);
    /// assert_eq!(Sprite::new(&MASK).scale(f32::NAN).blend_into(&mut view), Err(Error::NonFiniteCoordinate));
    /// assert_eq!(Sprite::new(&MASK).scale(-1.0).blend_into(&mut view), Err(Error::InvalidParameter(microraster::Param::SpriteScale)));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn blend_into<T: BlendTarget<C>>(&self, target: &mut T) -> Result<(), Error>
    where
        C: Interpolate,
    {
        let c = target.clip();
        self.for_each([c.x0(), c.y0(), c.x1(), c.y1()], |x, y, [r, g, b, a]| {
            if a > 0 {
                target.blend_pixel(Mix, x, y, from_rgb8::<C>([r, g, b]), a);
            }
        })
    }
}

/// The checked map: the pixel box `x0..x1 × y0..y1` and the texture
/// coordinates `[at (x0, y0), per column, per row]` in 2^-32.
struct Map {
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
    u: [i64; 3],
    v: [i64; 3],
}

impl<F: TexelFormat, C: Interpolate, Fi: Filter> Drawable for Sprite<'_, F, C, Fi> {
    type Color = C;
    type Output = Result<(), Error>;

    /// Draws the sprite as a cut-out (alpha × opacity ≥ 128 opaque, the
    /// rest not at all) into any `DrawTarget`; the sprite's own errors are
    /// the output, the target's the outer error.
    fn draw<D: DrawTarget<Color = C>>(&self, target: &mut D) -> Result<Result<(), Error>, D::Error> {
        let b = target.bounding_box();
        let end = |o: i32, n: u32| i64::from(o).saturating_add(i64::from(n)).min(i64::from(i32::MAX)) as i32;
        let clip =
            [b.top_left.x, b.top_left.y, end(b.top_left.x, b.size.width), end(b.top_left.y, b.size.height)];
        // Pixels go out a row at a time: one `draw_iter` per row.
        let mut row = heapless::Vec::<Pixel<C>, 64>::new();
        let mut failed = Ok(());
        let mut flush = |row: &mut heapless::Vec<Pixel<C>, 64>, target: &mut D| {
            if failed.is_ok() {
                failed = target.draw_iter(row.iter().copied());
            }
            row.clear();
        };
        let out = self.for_each(clip, |x, y, [r, g, b, a]| {
            if a >= 128 {
                if row.is_full() {
                    flush(&mut row, target);
                }
                let _ = row.push(Pixel(Point::new(x, y), from_rgb8::<C>([r, g, b])));
            }
        });
        flush(&mut row, target);
        failed.map(|()| out)
    }
}

/// `⌊t⌋` for `|t| < 2^62` (core has no `f64::floor` without `std`).
fn floor_i64(t: f64) -> i64 {
    let i = t as i64;
    i - i64::from((i as f64) > t)
}
