//! Writing one mesh's triangles into the caller's bins, all or nothing.
//!
//! When the bins fill up mid-mesh, the rest of the mesh is still run through
//! the vertex stage but only counted, so the error can say how many entries
//! the call needed ([`Error::CapacityExceeded`]); then the bins are cut back
//! to their length at entry. On the success path this costs nothing beyond
//! the check `heapless::Vec::push` makes anyway.

use crate::Error;

/// The caller's bins during one `draw_*` call.
pub(super) struct BinWriter<'a, X, const N: usize> {
    bins: &'a mut heapless::Vec<X, N>,
    /// The bins' length at entry, restored on any error.
    start: usize,
    /// Items that did not fit (counted, not stored).
    overflow: usize,
}

impl<'a, X, const N: usize> BinWriter<'a, X, N> {
    /// Starts a call that appends to `bins`.
    pub(super) fn new(bins: &'a mut heapless::Vec<X, N>) -> Self {
        let start = bins.len();
        BinWriter { bins, start, overflow: 0 }
    }

    /// Appends `item`, or counts it once the bins are full.
    #[inline]
    pub(super) fn push(&mut self, item: X) {
        if self.bins.push(item).is_err() {
            self.overflow += 1;
        }
    }

    /// [`BinWriter::push`] as the sink a vertex stage hands its items to.
    #[inline]
    pub(super) fn sink(&mut self) -> impl FnMut(X) -> Result<(), Error> + '_ {
        move |item| {
            self.push(item);
            Ok(())
        }
    }

    /// Ends the call: `result` if every item fitted and it is `Ok`;
    /// otherwise the bins go back to their length at entry and the error is
    /// `result`'s, or [`Error::CapacityExceeded`] when only the room ran out.
    pub(super) fn finish<R>(self, result: Result<R, Error>) -> Result<R, Error> {
        let needed = self.bins.len() + self.overflow;
        let result = match result {
            Ok(_) if self.overflow > 0 => Err(Error::CapacityExceeded { needed, capacity: N }),
            r => r,
        };
        if result.is_err() {
            self.bins.truncate(self.start);
        }
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overflow_counts_and_restores_the_entry_length() {
        let mut bins = heapless::Vec::<u8, 4>::new();
        bins.push(7).unwrap();
        let mut w = BinWriter::new(&mut bins);
        for i in 0..6 {
            w.push(i);
        }
        assert_eq!(w.finish(Ok(())), Err(Error::CapacityExceeded { needed: 7, capacity: 4 }));
        assert_eq!(bins.as_slice(), &[7]);
    }

    #[test]
    fn other_errors_restore_too_and_success_keeps_everything() {
        let mut bins = heapless::Vec::<u8, 4>::new();
        let mut w = BinWriter::new(&mut bins);
        w.push(1);
        assert_eq!(
            w.finish::<()>(Err(Error::InvalidMesh(crate::MeshFault::Unchecked))),
            Err(Error::InvalidMesh(crate::MeshFault::Unchecked))
        );
        assert!(bins.is_empty());
        let mut w = BinWriter::new(&mut bins);
        (0..4).for_each(|i| w.push(i));
        assert_eq!(w.finish(Ok(5)), Ok(5));
        assert_eq!(bins.as_slice(), &[0, 1, 2, 3]);
    }
}
