//! Strokes as contours: each side of the path offset by half the width,
//! with joins on the outer side of every turn and caps at open ends.
//!
//! On the inner side of a turn the offset lines are joined through the
//! vertex itself (the "pivot"), which makes small loops that the nonzero
//! rule unites with the rest — one fill, each pixel once. The second side is
//! traversed forwards and its edges are reversed ([`EdgeList::edge`]'s
//! `flip`), which is the same set of edges as walking it backwards, so only
//! a forward, cloneable iterator of points is needed (no allocation).
//!
//! Zero-length segments are skipped. A path whose points all coincide (a
//! zero-length thick line) draws, as SVG does, a disc of the stroke width
//! with [`Cap::Round`], an axis-aligned square with [`Cap::Square`], and
//! nothing with [`Cap::Butt`].

use super::angle::Angle;
use super::edges::EdgeList;
use super::flatten::arc_points;
use super::style::{Cap, Join};
use crate::Error;
use crate::math::Scalar;
use core::f32::consts::PI;

type P = (f32, f32);

/// Half width, join, cap and miter limit of a stroke.
#[derive(Debug, Clone, Copy, PartialEq)]
#[doc(hidden)]
pub struct StrokeParams {
    pub(crate) half: f32,
    pub(crate) join: Join,
    pub(crate) cap: Cap,
    pub(crate) miter_limit: f32,
}

/// Draws connected edges from a current point.
struct Pen<'e, const N: usize> {
    e: &'e mut EdgeList<N>,
    at: P,
    flip: bool,
}

impl<const N: usize> Pen<'_, N> {
    fn line_to(&mut self, p: P) -> Result<(), Error> {
        self.e.edge(self.at, p, self.flip)?;
        self.at = p;
        Ok(())
    }

    /// Round arc around `c` from the current point to `to`, turning by `sweep`.
    fn arc_to(&mut self, c: P, r: f32, sweep: f32, to: P) -> Result<(), Error> {
        let start = micromath::F32Ext::atan2(self.at.1 - c.1, self.at.0 - c.0);
        let (mut i, n) = (0u32, super::flatten::segments(r, sweep));
        arc_points(c, (r, r), start, sweep, |x, y| {
            i += 1;
            // Skip the first point (the pen) and replace the last by the exact end.
            if i > 1 && i <= n { self.line_to((x, y)) } else { Ok(()) }
        })?;
        self.line_to(to)
    }
}

fn sub(a: P, b: P) -> P {
    (a.0 - b.0, a.1 - b.1)
}
fn at(p: P, d: P, k: f32) -> P {
    (p.0 + d.0 * k, p.1 + d.1 * k)
}
/// The unit direction from `a` to `b`, `None` if they (nearly) coincide.
fn unit(a: P, b: P) -> Option<P> {
    let d = sub(b, a);
    let l2 = d.0 * d.0 + d.1 * d.1;
    (l2 > 1e-8).then(|| {
        let l = Scalar::sqrt(l2);
        (d.0 / l, d.1 / l)
    })
}
/// `d` turned a quarter clockwise on screen.
fn normal(d: P) -> P {
    (-d.1, d.0)
}

/// Points with consecutive (near-)duplicates removed.
fn distinct<I: Iterator<Item = P> + Clone>(mut it: I) -> impl Iterator<Item = P> + Clone {
    let mut last: Option<P> = None;
    core::iter::from_fn(move || {
        for p in it.by_ref() {
            if last.is_none_or(|l| unit(l, p).is_some()) {
                last = Some(p);
                return Some(p);
            }
        }
        None
    })
}

/// The join at `q` on side `s` (±1) from direction `d0` to `d1`, from the
/// pen at `q + s·n0·half` to `q + s·n1·half`.
fn join<const N: usize>(
    pen: &mut Pen<'_, N>,
    q: P,
    d0: P,
    d1: P,
    s: f32,
    p: &StrokeParams,
) -> Result<(), Error> {
    let (n0, n1) = (normal(d0), normal(d1));
    let to = at(q, n1, s * p.half);
    let cross = d0.0 * d1.1 - d0.1 * d1.0;
    let dot = d0.0 * d1.0 + d0.1 * d1.1;
    let outer = s * cross < 0.0 || (cross == 0.0 && dot < 0.0);
    if !outer {
        pen.line_to(q)?;
        return pen.line_to(to);
    }
    match p.join {
        Join::Round => {
            let sweep = if cross == 0.0 { -s * PI } else { micromath::F32Ext::atan2(cross, dot) };
            pen.arc_to(q, p.half, sweep, to)
        }
        Join::Miter if 1.0 + dot > 1e-6 && 2.0 / (1.0 + dot) <= p.miter_limit * p.miter_limit => {
            pen.line_to(at(q, (n0.0 + n1.0, n0.1 + n1.1), s * p.half / (1.0 + dot)))?;
            pen.line_to(to)
        }
        _ => pen.line_to(to),
    }
}

/// The cap at end `q` (outward direction `d`), from `q + n·half` to `q − n·half`.
fn cap_path<const N: usize>(pen: &mut Pen<'_, N>, q: P, d: P, p: &StrokeParams) -> Result<(), Error> {
    let n = normal(d);
    let to = at(q, n, -p.half);
    match p.cap {
        Cap::Butt => pen.line_to(to),
        Cap::Square => {
            pen.line_to(at(at(q, n, p.half), d, p.half))?;
            pen.line_to(at(to, d, p.half))?;
            pen.line_to(to)
        }
        Cap::Round => pen.arc_to(q, p.half, -PI, to),
    }
}

/// A cap as its own closed contour, oriented like a body whose outline runs
/// from `q − n·half` to `q + n·half` at that end when `flip` is set.
pub(crate) fn cap<const N: usize>(
    e: &mut EdgeList<N>,
    q: P,
    d: P,
    flip: bool,
    p: &StrokeParams,
) -> Result<(), Error> {
    let start = at(q, normal(d), p.half);
    let mut pen = Pen { e, at: start, flip };
    cap_path(&mut pen, q, d, p)?;
    pen.line_to(start)
}

/// One side (`s = ±1`) of an open path, pen at its first offset point.
fn open_side<const N: usize, I>(
    pen: &mut Pen<'_, N>,
    mut pts: I,
    s: f32,
    p: &StrokeParams,
) -> Result<(), Error>
where
    I: Iterator<Item = P>,
{
    let (Some(q), Some(mut next)) = (pts.next(), pts.next()) else { return Ok(()) };
    let mut d = unit(q, next).unwrap_or((1.0, 0.0));
    for r in pts {
        let d1 = unit(next, r).unwrap_or(d);
        pen.line_to(at(next, normal(d), s * p.half))?;
        join(pen, next, d, d1, s, p)?;
        (next, d) = (r, d1);
    }
    pen.line_to(at(next, normal(d), s * p.half))
}

/// The stroke of the path through `pts`, closed back to its start if `closed`.
pub(crate) fn path<const N: usize, I>(
    e: &mut EdgeList<N>,
    pts: I,
    closed: bool,
    p: &StrokeParams,
) -> Result<(), Error>
where
    I: Iterator<Item = P> + Clone,
{
    let pts = distinct(pts);
    let mut it = pts.clone();
    let Some(first) = it.next() else { return Ok(()) };
    let Some(second) = it.next() else { return dot(e, first, p) };
    // The last point distinct from the first (closed paths).
    let last = pts.clone().filter(|&q| unit(q, first).is_some()).last().unwrap_or(second);
    let (last_d, first_d) =
        (unit(last, first).unwrap_or((1.0, 0.0)), unit(first, second).unwrap_or((1.0, 0.0)));
    if closed {
        for (s, flip) in [(1.0, false), (-1.0, true)] {
            let start = at(first, normal(last_d), s * p.half);
            let mut pen = Pen { e: &mut *e, at: start, flip };
            join(&mut pen, first, last_d, first_d, s, p)?;
            let tail = pts.clone().skip(1).filter(|&q| unit(q, first).is_some());
            open_side(&mut pen, core::iter::once(first).chain(tail).chain(core::iter::once(first)), s, p)?;
            pen.line_to(start)?;
        }
        return Ok(());
    }
    let (end, end_d) = end_of(pts.clone(), first_d);
    let start = at(first, normal(first_d), p.half);
    let mut pen = Pen { e: &mut *e, at: start, flip: false };
    open_side(&mut pen, pts.clone(), 1.0, p)?;
    cap_path(&mut pen, end, end_d, p)?;
    let mut back = Pen { e: &mut *e, at: at(first, normal(first_d), -p.half), flip: true };
    open_side(&mut back, pts, -1.0, p)?;
    let b0 = at(first, normal(first_d), -p.half);
    let mut pen = Pen { e, at: b0, flip: false };
    cap_path(&mut pen, first, (-first_d.0, -first_d.1), p)
}

/// The last point and the direction of the last segment.
fn end_of<I: Iterator<Item = P>>(pts: I, first_d: P) -> (P, P) {
    let (mut prev, mut d) = (None::<P>, first_d);
    for q in pts {
        if let Some(a) = prev {
            d = unit(a, q).unwrap_or(d);
        }
        prev = Some(q);
    }
    (prev.unwrap_or((0.0, 0.0)), d)
}

/// A zero-length thick line at `q`.
fn dot<const N: usize>(e: &mut EdgeList<N>, q: P, p: &StrokeParams) -> Result<(), Error> {
    match p.cap {
        Cap::Butt => Ok(()),
        Cap::Square => {
            let h = p.half;
            e.polygon(&[(q.0 - h, q.1 - h), (q.0 + h, q.1 - h), (q.0 + h, q.1 + h), (q.0 - h, q.1 + h)])
        }
        Cap::Round => {
            e.close()?;
            arc_points(q, (p.half, p.half), 0.0, 2.0 * PI, |x, y| e.line_to(x, y))?;
            e.close()
        }
    }
}

/// Slice front-end.
pub(crate) fn polyline<const N: usize>(
    e: &mut EdgeList<N>,
    pts: &[P],
    closed: bool,
    p: &StrokeParams,
) -> Result<(), Error> {
    path(e, pts.iter().copied(), closed, p)
}

/// The outline of a sector (centre, then the arc) as a closed stroked path:
/// `start` as reduced by [`near`](super::angle::near), the end directions given (those
/// of the fill).
pub(crate) fn sector<const N: usize>(
    e: &mut EdgeList<N>,
    c: P,
    r: f32,
    (start, sweep): (f32, f32),
    (from, to): (Angle, Angle),
    p: &StrokeParams,
) -> Result<(), Error> {
    let n = super::flatten::segments(r, sweep);
    let arc = (0..=n).map(move |i| {
        let a = match i {
            0 => from,
            i if i == n => to,
            i => Angle::from_radians(start + sweep * (i as f32 / n as f32)),
        };
        let (s, co) = a.sin_cos();
        (c.0 + r * co, c.1 + r * s)
    });
    path(e, core::iter::once(c).chain(arc), true, p)
}
