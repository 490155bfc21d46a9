//! What the `view3d` front learns about a plain mesh's chunks
//! ([`super::chunked`]) in the first band that walks them, so the bands
//! below skip a chunk that misses them without building it again.
//!
//! The front runs the vertex stage once per band. A plain mesh is taken in
//! chunks of at most 8 vertices; the chunks depend on the index order alone,
//! so they are the same in every band. Building one (its slot table) and
//! finding its vertices' clip `y` and `w` cost about as much as the rest of
//! the frame's vertex work, and most chunks miss most bands. The record
//! keeps, per chunk, its triangle count and the range of its vertices'
//! `y / w` (normalised device `y`); a band whose clip-space bounds
//! ([`Band`]) lie wholly below or above that range skips the chunk by its
//! count.
//!
//! # Same pixels
//! A chunk is skipped only if every vertex has `w ≥ w_min` and
//! `fl(y / w)` lies above the band's `above` bound (or every one below
//! `below`): the bounds are a pixel above and two below the band, and
//! `fl(y / w)` is within `2^-24·|y/w|` of `y / w`, at most `2^-22` where it
//! is compared with a bound (`|bound| ≤ 4`), far inside the margin that
//! [`Band::side`] keeps for the same decision. The chunk's triangles lie in
//! the convex hull of its vertices, so none has a pixel in the band, and
//! the band's image is the one it would be without the record (tested
//! against the binned path, which keeps no record). A vertex with `w`
//! below `w_min` or a `y / w` that is NaN makes its chunk never skipped.
//!
//! # Lifetime
//! One record per [`View3d::draw`](crate::view3d::View3d::draw) call,
//! cleared at its start: the same objects, matrices and pipeline in every
//! band but for the rows. Each object (up to [`FRAME_OBJECTS`]) owns a run
//! of entries, recorded in the first band that walks its chunks; chunks
//! beyond the capacity ([`FRAME_CHUNKS`] in all) are built in every band,
//! as without a record.

use super::Band;
use super::cache::Cached;

/// Chunks a frame's record holds, over all objects (12 bytes each).
pub(crate) const FRAME_CHUNKS: usize = 256;
/// Objects of a frame with a run in the record (the rest have none).
pub(crate) const FRAME_OBJECTS: usize = 8;

/// What [`Pipeline::draw_chunked`](super::Pipeline) asks of a record, chunk
/// by chunk in the mesh's order.
pub(crate) trait ChunkMemo<T> {
    /// The next chunk's triangle count if it is recorded and misses `band`
    /// (then it is skipped, not built).
    fn skip(&mut self, band: &Band<T>) -> Option<usize>;
    /// The next chunk was built and drawn: `triangles` of them, its
    /// vertices' clip `y` and `w` in `slots`.
    fn drawn<const S: u32>(&mut self, triangles: usize, slots: &[Cached<T, S>], band: &Band<T>);
}

/// No record (the binned path): every chunk is built.
pub(crate) struct NoMemo;

impl<T> ChunkMemo<T> for NoMemo {
    #[inline(always)]
    fn skip(&mut self, _: &Band<T>) -> Option<usize> {
        None
    }
    #[inline(always)]
    fn drawn<const S: u32>(&mut self, _: usize, _: &[Cached<T, S>], _: &Band<T>) {}
}

/// One chunk: its triangles and the range of its vertices' `y / w`
/// (NaN: never skipped).
#[derive(Clone, Copy)]
struct ChunkRows {
    triangles: u16,
    lo: f32,
    hi: f32,
}

/// An object's run of entries.
#[derive(Clone, Copy, Default)]
struct Run {
    start: u16,
    len: u16,
    /// Whether `start` is set (the object has been walked once).
    open: bool,
}

/// A frame's record (module docs), owned by the front.
pub(crate) struct FrameChunks {
    entries: [ChunkRows; FRAME_CHUNKS],
    used: usize,
    runs: [Run; FRAME_OBJECTS],
}

impl FrameChunks {
    pub(crate) const fn new() -> Self {
        let empty = ChunkRows { triangles: 0, lo: f32::NAN, hi: f32::NAN };
        FrameChunks {
            entries: [empty; FRAME_CHUNKS],
            used: 0,
            runs: [Run { start: 0, len: 0, open: false }; FRAME_OBJECTS],
        }
    }

    /// Forgets the last frame.
    pub(crate) fn clear(&mut self) {
        self.used = 0;
        self.runs = [Run::default(); FRAME_OBJECTS];
    }

    /// Object `i`'s run, for one walk of its chunks (`None` beyond
    /// [`FRAME_OBJECTS`]).
    pub(crate) fn object(&mut self, i: usize) -> Option<ObjectChunks<'_>> {
        let run = self.runs.get_mut(i)?;
        Some(ObjectChunks { entries: &mut self.entries, used: &mut self.used, run, next: 0 })
    }
}

/// One walk of an object's chunks through the record.
pub(crate) struct ObjectChunks<'a> {
    entries: &'a mut [ChunkRows; FRAME_CHUNKS],
    used: &'a mut usize,
    run: &'a mut Run,
    /// The chunk the walk is at.
    next: usize,
}

impl ChunkMemo<f32> for ObjectChunks<'_> {
    #[inline]
    fn skip(&mut self, band: &Band<f32>) -> Option<usize> {
        if self.next >= usize::from(self.run.len) {
            return None;
        }
        let e = self.entries.get(usize::from(self.run.start) + self.next)?;
        let misses = band.above.is_some_and(|a| e.lo > a) || band.below.is_some_and(|b| e.hi < b);
        // A chunk that is drawn instead counts in `drawn`.
        self.next += usize::from(misses);
        misses.then_some(usize::from(e.triangles))
    }

    fn drawn<const S: u32>(&mut self, triangles: usize, slots: &[Cached<f32, S>], band: &Band<f32>) {
        let c = self.next;
        self.next += 1;
        if c < usize::from(self.run.len) {
            return;
        }
        if !self.run.open {
            (self.run.start, self.run.open) = (*self.used as u16, true);
        }
        // Only the run that ends the record grows, one chunk after the other.
        let end = usize::from(self.run.start) + usize::from(self.run.len);
        if end != *self.used || c != usize::from(self.run.len) {
            return;
        }
        let (Some(e), Ok(triangles)) = (self.entries.get_mut(end), u16::try_from(triangles)) else { return };
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        for s in slots {
            let (y, w) = (s.clip[1], s.clip[3]);
            let ndc = y / w;
            if !(w >= band.w_min && w > 0.0) || ndc.is_nan() {
                (lo, hi) = (f32::NAN, f32::NAN);
                break;
            }
            (lo, hi) = (lo.min(ndc), hi.max(ndc));
        }
        *e = ChunkRows { triangles, lo, hi };
        self.run.len += 1;
        *self.used += 1;
    }
}

impl<T, M: ChunkMemo<T>> ChunkMemo<T> for Option<M> {
    #[inline]
    fn skip(&mut self, band: &Band<T>) -> Option<usize> {
        self.as_mut()?.skip(band)
    }
    #[inline]
    fn drawn<const S: u32>(&mut self, triangles: usize, slots: &[Cached<T, S>], band: &Band<T>) {
        if let Some(m) = self {
            m.drawn(triangles, slots, band);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;
    use crate::math::{Vec3, transform};
    use crate::mesh::{ValidMesh, icosphere, torus};
    use crate::pipeline::{Pipeline, Uniform};
    use crate::raster3d::ScreenTriangle;
    use embedded_graphics_core::pixelcolor::Rgb565;

    type Tris = heapless::Vec<ScreenTriangle<4>, 400>;

    fn push(v: &mut Tris, t: ScreenTriangle<4>) -> Result<(), Error> {
        v.push(t).map_err(|_| Error::InvalidMesh(crate::MeshFault::Unchecked))
    }

    /// Counts the chunks the record lets a band skip.
    struct Counting<'a>(ObjectChunks<'a>, &'a mut usize);

    impl ChunkMemo<f32> for Counting<'_> {
        fn skip(&mut self, band: &Band<f32>) -> Option<usize> {
            let n = self.0.skip(band);
            *self.1 += usize::from(n.is_some());
            n
        }
        fn drawn<const S: u32>(&mut self, triangles: usize, slots: &[Cached<f32, S>], band: &Band<f32>) {
            self.0.drawn(triangles, slots, band);
        }
    }

    /// Band by band, top to bottom, two meshes through one frame's record
    /// give the triangles of the walk without a record, in order (some
    /// through the near plane); the record skips most chunks of the later
    /// bands; a record too small for both keeps the first mesh's chunks
    /// and still gives the same triangles.
    #[test]
    fn a_record_skips_chunks_and_keeps_every_triangle() {
        let (mut sp, mut sn, mut si) = ([[0.0; 3]; 162], [[0.0; 3]; 162], [[0; 3]; 320]);
        let (mut tp, mut tn, mut ti) = ([[0.0; 3]; 96], [[0.0; 3]; 96], [[0; 3]; 192]);
        let sphere = ValidMesh::new(icosphere(2, &mut sp, &mut sn, &mut si).unwrap()).unwrap();
        let torus = ValidMesh::new(torus(12, 8, 1.0, 0.35, &mut tp, &mut tn, &mut ti).unwrap()).unwrap();
        let v = |x, y, z| Vec3::new(x, y, z);
        let view = transform::look_at(v(0.0, 0.8, 3.2), v(0.0, 0.0, 0.0), v(0.0, 1.0, 0.0)).unwrap();
        let base = Pipeline::<f32, 4>::perspective(view, 0.9, 1.0, 20.0, 160, 120).unwrap();
        let models = [transform::rotation_y(0.7), transform::translation(v(0.2, -0.3, 2.0))];
        let meshes = [sphere, torus];
        for small in [false, true] {
            let mut record = FrameChunks::new();
            let (mut skipped, mut compared) = (0, 0);
            for y0 in (0..120).step_by(8) {
                let mut p = base;
                p.rows = Some((y0, y0 + 7));
                for (i, (mesh, model)) in meshes.iter().zip(&models).enumerate() {
                    let (mut with, mut without) = (Tris::new(), Tris::new());

                    let color = Rgb565::new(20, 40, 10);
                    // The small record's room ends inside the first mesh's chunks.
                    if small {
                        record.used = record.used.max(FRAME_CHUNKS - 20);
                    }
                    let memo = &mut Counting(record.object(i).unwrap(), &mut skipped);
                    let a = p.mesh_into(mesh, model, color, &Uniform, memo, |t| push(&mut with, t));
                    let b = p.mesh_into(mesh, model, color, &Uniform, &mut NoMemo, |t| push(&mut without, t));
                    assert!(a.is_ok() && b.is_ok() && with == without, "band {y0}, mesh {i}");
                    compared += with.len();
                }
            }
            let recorded = record.used - if small { FRAME_CHUNKS - 20 } else { 0 };
            assert!(compared > 300, "{compared} triangles");
            if small {
                assert!(recorded == 20 && skipped > 0, "{recorded} chunks recorded, {skipped} skipped");
            } else {
                assert!(
                    recorded > 60 && skipped > 5 * recorded,
                    "{recorded} chunks recorded, {skipped} skipped"
                );
            }
        }
    }
}
