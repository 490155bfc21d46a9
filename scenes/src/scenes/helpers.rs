//! What the demo and benchmark scenes are built from: frame-size checks and
//! subpixel points, the integer sine table, 8-bit colours and the xorshift.

use microraster::{Error, Interpolate, MAX_FRAME_DIM, SubPoint};

/// Frame size in 1/256 px, for placing points with subpixel precision.
#[derive(Clone, Copy)]
pub(super) struct Frame {
    pub(super) w: i64,
    pub(super) h: i64,
}

impl Frame {
    pub(super) fn new(width: u32, height: u32) -> Result<Self, Error> {
        check_frame(width, height, (1, 1))?;
        Ok(Frame { w: width as i64 * 256, h: height as i64 * 256 })
    }

    /// A point in 1/256 px, clamped into the frame and snapped to `S` bits.
    pub(super) fn point<const S: u32>(self, x: i64, y: i64) -> Result<SubPoint<S>, Error> {
        at256(x.clamp(0, self.w), y.clamp(0, self.h))
    }

    /// As [`Frame::point`], but strictly inside: a line along `y = h` would
    /// light row `h`, outside the frame.
    pub(super) fn line_point<const S: u32>(self, x: i64, y: i64) -> Result<SubPoint<S>, Error> {
        let p = self.point::<S>(x, y)?;
        let max = |v: i64| (v >> (8 - S)) as i32 - 1;
        SubPoint::new(p.x().min(max(self.w)), p.y().min(max(self.h)))
    }
}

pub(super) fn check_frame(width: u32, height: u32, min: (u32, u32)) -> Result<(), Error> {
    let ok = |v: u32, m: u32| v >= m.max(1) && v <= MAX_FRAME_DIM;
    if ok(width, min.0) && ok(height, min.1) { Ok(()) } else { Err(Error::InvalidFrameSize) }
}

/// A point given in 1/16 px, snapped to `S` bits (exact for `S >= 4`; pixel
/// centres stay exact for every `S >= 1`).
pub(super) fn at16<const S: u32>(x: i64, y: i64) -> Result<SubPoint<S>, Error> {
    at256(x * 16, y * 16)
}

/// A point given in 1/256 px, snapped to `S` bits, rounding halves up.
fn at256<const S: u32>(x: i64, y: i64) -> Result<SubPoint<S>, Error> {
    const { assert!(S >= 1, "the scenes need at least one subpixel bit") };
    let snap = |v: i64| {
        let k = 8 - S.min(8);
        let r = if k == 0 { v } else { (v + (1 << (k - 1))) >> k };
        i32::try_from(r).map_err(|_| Error::CoordinateOutOfRange)
    };
    SubPoint::new(snap(x)?, snap(y)?)
}

/// Fixed-point one for the sine table.
pub(super) const Q14: i64 = 1 << 14;
/// `sin(k·π/32)·2^14` for `k = 0..=16`: a quarter wave in 16 steps.
const SIN_Q14: [i64; 17] = [
    0, 1606, 3196, 4756, 6270, 7723, 9102, 10394, 11585, 12665, 13623, 14449, 15137, 15679, 16069, 16305,
    16384,
];

/// `sin(i·2π/64)` in Q14 for any `i`.
pub(super) fn sin64(i: usize) -> i64 {
    let i = i % 64;
    match i / 16 {
        0 => SIN_Q14[i],
        1 => SIN_Q14[32 - i],
        2 => -SIN_Q14[i - 32],
        _ => -SIN_Q14[64 - i],
    }
}

/// `cos(i·2π/64)` in Q14.
pub(super) fn cos64(i: usize) -> i64 {
    sin64(i + 16)
}

/// Fully saturated hue; `t` in `0..1536` goes once round the wheel from red.
pub(super) fn hue(t: u32) -> [u8; 3] {
    let t = t % 1536;
    let (sector, f) = (t / 256, (t % 256) as u8);
    match sector {
        0 => [255, f, 0],
        1 => [255 - f, 255, 0],
        2 => [0, 255, f],
        3 => [0, 255 - f, 255],
        4 => [f, 0, 255],
        _ => [255, 0, 255 - f],
    }
}

/// Half-way to white: luma at least 142, so "on" even in 1-bit colour.
pub(super) fn pastel(c: [u8; 3]) -> [u8; 3] {
    c.map(|v| ((v as u32 + 255) / 2) as u8)
}

/// `c` scaled by `level / 255`.
pub(super) fn shade(c: [u8; 3], level: u32) -> [u8; 3] {
    c.map(|v| (v as u32 * level.min(255) / 255) as u8)
}

/// An 8-bit RGB colour in `C`'s channel depth; single-channel types get the luma.
pub(super) fn rgb<C: Interpolate>(c: [u8; 3]) -> C {
    let m = C::CHANNEL_MAX;
    let scale = |v: u32, max: u8| ((v * max as u32 + 127) / 255) as u8;
    if m[1] == 0 && m[2] == 0 {
        let luma = (77 * c[0] as u32 + 150 * c[1] as u32 + 29 * c[2] as u32 + 128) >> 8;
        C::from_channels([scale(luma, m[0]), 0, 0])
    } else {
        C::from_channels([scale(c[0] as u32, m[0]), scale(c[1] as u32, m[1]), scale(c[2] as u32, m[2])])
    }
}

/// Marsaglia's xorshift32: tiny and deterministic.
pub(super) struct XorShift(pub(super) u32);

impl XorShift {
    /// A value in `0..n` (`n > 0`); the modulo bias does not matter here.
    pub(super) fn below(&mut self, n: i64) -> i64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x as i64 % n.max(1)
    }
}
