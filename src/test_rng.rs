//! xorshift64 for the unit tests: deterministic cases without a dependency.

/// The generator; its state is the seed (non-zero).
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    /// The next state.
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// Uniform-ish in `-r..=r`.
    pub(crate) fn in_range(&mut self, r: i64) -> i64 {
        (self.next() % (2 * r as u64 + 1)) as i64 - r
    }

    /// In `0..scale`, from the state's top 24 bits.
    pub(crate) fn unit(&mut self, scale: f32) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32 * scale
    }
}
