//! Dirty-band skipping: a [`BandSink`] adaptor that remembers a 64-bit
//! signature of each band it sent and does not send a band whose signature
//! is unchanged since the last frame.

use super::link::{BandSink, FrameBands, Lent};
use crate::{Error, Interpolate};

/// Sends a band to the inner sink only if it differs from what that band
/// position showed last frame, judged by a 64-bit signature of its pixels
/// ([`signature`]). `N` signatures (8 bytes each, plus a flag) are stored:
/// at least the frame's number of bands, else the frame is refused with
/// [`Error::BufferTooSmall`].
///
/// Opt-in: wrap a sink in it. [`DirtyBands::force_full_frame`] makes the next
/// frame send every band (after the display was cleared or lost its
/// contents); a frame whose size, offset or band height differs from the last
/// one's is sent in full anyway.
///
/// **Failed transfers.** A band counts as shown only once the inner sink
/// hands it back without an error (from `submit`, or from `reclaim` after
/// its transfer finished). A band whose transfer failed, or was still on
/// the wire when the frame stopped at an error, is sent again by the next
/// frame whatever its pixels; the bands the failed frame did not reach keep
/// their record (the display still shows them). So after an error, drawing
/// the frame again repairs the display, with no other call; if the failure
/// may have disturbed more than the bands it was sending (the display reset
/// or lost power), call [`DirtyBands::force_full_frame`] first.
///
/// **Wrong skips.** A band is skipped wrongly only if its pixels changed but
/// its signature did not. A change of a single pixel always changes the
/// signature (every step of [`signature`] is a bijection of its state; see
/// there). For other changes, if the signature behaved as a random 64-bit
/// function the chance per changed band would be 2⁻⁶⁴ ≈ 5.4 × 10⁻²⁰: 15
/// bands at 60 frames/s, all changing, would go about 6 × 10⁸ years between
/// wrong skips. This is a model, not a bound: the mix is not a cryptographic
/// hash, so a frame built to collide can. The tests compare every skipping
/// frame with a full render and have never seen a wrong skip.
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use microraster::render::DirtyBands;
/// use microraster::{Band, Renderer};
/// let mut bands = [const { Band::<Gray8, 8, 4>::new(Gray8::new(0)) }; 2];
/// let mut sink = DirtyBands::<(), 4>::new(());
/// let r = Renderer::new(16, Gray8::new(0));
/// r.render_linked((), &mut bands, &mut sink).unwrap();
/// assert_eq!(sink.sent_bands(), 4); // first frame: everything
/// r.render_linked((), &mut bands, &mut sink).unwrap();
/// assert_eq!(sink.sent_bands(), 4); // nothing changed: nothing more sent
/// sink.force_full_frame();
/// r.render_linked((), &mut bands, &mut sink).unwrap();
/// assert_eq!(sink.sent_bands(), 8);
/// ```
pub struct DirtyBands<S, const N: usize> {
    inner: S,
    signatures: [Shown; N],
    frame: Option<FrameBands>,
    sent_bands: u64,
    sent_pixels: u64,
}

impl<S, const N: usize> DirtyBands<S, N> {
    const CHECK: () = assert!(N >= 1, "DirtyBands needs room for at least one band signature");

    /// `inner`, with no band sent yet (the first frame is sent in full).
    pub const fn new(inner: S) -> Self {
        let () = Self::CHECK;
        DirtyBands { inner, signatures: [Shown::Unknown; N], frame: None, sent_bands: 0, sent_pixels: 0 }
    }

    /// The next frame sends every band.
    pub fn force_full_frame(&mut self) {
        self.signatures = [Shown::Unknown; N];
    }

    /// Bands passed to the inner sink so far.
    pub fn sent_bands(&self) -> u64 {
        self.sent_bands
    }

    /// Pixels passed to the inner sink so far.
    pub fn sent_pixels(&self) -> u64 {
        self.sent_pixels
    }

    /// The inner sink.
    pub fn inner(&mut self) -> &mut S {
        &mut self.inner
    }

    /// The inner sink, giving up the signatures.
    pub fn into_inner(self) -> S {
        self.inner
    }
}

impl<'a, C, S, const W: usize, const N: usize> BandSink<'a, C, W> for DirtyBands<S, N>
where
    C: Interpolate,
    S: BandSink<'a, C, W>,
{
    type Error = S::Error;

    fn begin(&mut self, frame: &FrameBands) -> Result<(), Error> {
        if frame.bands() > N {
            return Err(Error::BufferTooSmall);
        }
        // Signatures of another frame geometry say nothing about this one.
        if self.frame != Some(*frame) {
            self.force_full_frame();
            self.frame = Some(*frame);
        }
        self.inner.begin(frame)
    }

    fn submit(&mut self, band: Lent<'a, C, W>) -> Result<Option<Lent<'a, C, W>>, S::Error> {
        let sig = signature(band.pixels());
        // `begin` checked the count; an index past it (a renderer bug) sends.
        let Some(slot) = self.signatures.get_mut(band.index()) else {
            return self.inner.submit(band);
        };
        if *slot == Shown::Sent(sig) {
            return Ok(Some(band));
        }
        // Not shown until the inner sink hands the band back without an
        // error: a failed or unfinished transfer leaves it `Sending`, which
        // matches no signature, so the next frame sends it again.
        *slot = Shown::Sending(sig);
        self.sent_bands += 1;
        self.sent_pixels += band.pixels().len() as u64;
        let back = self.inner.submit(band)?;
        Ok(self.delivered(back))
    }

    fn reclaim(&mut self) -> Result<Option<Lent<'a, C, W>>, S::Error> {
        let back = self.inner.reclaim()?;
        Ok(self.delivered(back))
    }
}

impl<S, const N: usize> DirtyBands<S, N> {
    /// The inner sink handed `back` back: its transfer finished, so the
    /// display shows the signature it was sent with.
    fn delivered<'a, C: Copy, const W: usize>(
        &mut self,
        back: Option<Lent<'a, C, W>>,
    ) -> Option<Lent<'a, C, W>> {
        if let Some(slot) = back.as_ref().and_then(|b| self.signatures.get_mut(b.index())) {
            if let Shown::Sending(sig) = *slot {
                *slot = Shown::Sent(sig);
            }
        }
        back
    }
}

/// What a band position of the display shows, as far as [`DirtyBands`]
/// knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Shown {
    /// Unknown: the next band there is sent.
    Unknown,
    /// A band of this signature was handed to the inner sink, which has not
    /// yet handed it back (or failed): the display may show either frame.
    Sending(u64),
    /// A band of this signature was sent and its transfer finished.
    Sent(u64),
}

/// The 64-bit signature of a band's pixels: each pixel's channels packed
/// into a word `p` (one-to-one: the channels determine the colour), then
/// `h ← xorshift32((h ⊕ p) · K)` with odd `K`, then MurmurHash3's 64-bit
/// finaliser. For a fixed pixel each step is a bijection of `h` (xor, times
/// an odd number mod 2⁶⁴, xorshift, are all invertible), and for a fixed `h`
/// two different pixels give two different states; so two bands that differ
/// in one pixel always have different signatures. The pixel count seeds the
/// state (a shorter last band is also told apart by [`DirtyBands`]' frame check).
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microraster::render::signature;
/// let a = [Rgb565::new(1, 2, 3); 64];
/// let mut b = a;
/// b[17] = Rgb565::new(1, 2, 4);
/// assert_ne!(signature(&a), signature(&b));
/// ```
// Out of line: one call a band (thousands of pixels), one copy of the loop
// in the program, and a symbol (`…::render::dirty::signature`) by which
// `scripts/code-size.sh` sees whether a program links the dirty-band code.
#[inline(never)]
pub fn signature<C: Interpolate>(pixels: &[C]) -> u64 {
    const K: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut h = (pixels.len() as u64).wrapping_mul(K);
    for &c in pixels {
        let [r, g, b] = c.to_channels();
        let p = u64::from(r) | u64::from(g) << 8 | u64::from(b) << 16;
        h = (h ^ p).wrapping_mul(K);
        h ^= h >> 32;
    }
    fmix64(h)
}

/// MurmurHash3's finaliser: a bijection that spreads every input bit over
/// the output.
fn fmix64(mut h: u64) -> u64 {
    h ^= h >> 33;
    h = h.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
    h ^= h >> 33;
    h = h.wrapping_mul(0xC4CE_B9FE_1A85_EC53);
    h ^ (h >> 33)
}
