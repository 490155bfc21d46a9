//! The meshlet builder's working state: the vertex → triangle adjacency
//! with live counts, the open cluster's local indices and the emitted flags,
//! all in one caller-provided `u32` scratch buffer.

use super::Mesh;
use crate::error::Error;

/// Length of the `u32` scratch buffer [`build_meshlets`](super::build_meshlets) needs for a mesh of
/// `vertices` positions and `triangles` triangles (saturating):
/// `3 · vertices + 1 + 3 · triangles + ⌈triangles / 32⌉`.
///
/// ```
/// use microraster::mesh::meshlet_scratch_len;
/// assert_eq!(meshlet_scratch_len(4, 4), 13 + 12 + 1);
/// ```
pub const fn meshlet_scratch_len(vertices: usize, triangles: usize) -> usize {
    vertices
        .saturating_mul(3)
        .saturating_add(1)
        .saturating_add(triangles.saturating_mul(3))
        .saturating_add(triangles.div_ceil(32))
}

/// The builder's working state, all in the caller's scratch buffer.
pub(super) struct State<'s> {
    /// Start of each vertex's triangle list in `adj` (`nv + 1` entries).
    pub start: &'s mut [u32],
    /// Triangles of each vertex not yet in a cluster: the first `live[v]`
    /// entries of its list (emitted ones are swapped out).
    pub live: &'s mut [u32],
    /// Local index + 1 of each vertex in the open cluster, 0 if not in it.
    pub local: &'s mut [u32],
    pub adj: &'s mut [u32],
    /// One bit per triangle: already in a cluster.
    pub done: &'s mut [u32],
}

impl State<'_> {
    pub fn live_tris(&self, v: usize) -> &[u32] {
        let s = self.start[v] as usize;
        &self.adj[s..s + self.live[v] as usize]
    }

    pub fn is_done(&self, t: usize) -> bool {
        self.done[t / 32] & (1 << (t % 32)) != 0
    }

    /// Marks `t` emitted and removes it from its vertices' live lists.
    pub fn emit(&mut self, t: usize, tri: [u16; 3]) {
        self.done[t / 32] |= 1 << (t % 32);
        for v in tri.map(usize::from) {
            let s = self.start[v] as usize;
            let mut k = 0;
            // A triangle with a repeated corner is listed twice: remove all.
            while k < self.live[v] as usize {
                if self.adj[s + k] as usize == t {
                    self.live[v] -= 1;
                    self.adj[s + k] = self.adj[s + self.live[v] as usize];
                } else {
                    k += 1;
                }
            }
        }
    }
}

/// Splits `scratch` into the [`State`] arrays and fills the adjacency.
pub(super) fn split_scratch(scratch: &mut [u32], nv: usize, nt: usize) -> Result<State<'_>, Error> {
    let (needed, capacity) = (meshlet_scratch_len(nv, nt), scratch.len());
    let scratch = scratch.get_mut(..needed).ok_or(Error::CapacityExceeded { needed, capacity })?;
    let (start, rest) = scratch.split_at_mut(nv + 1);
    let (live, rest) = rest.split_at_mut(nv);
    let (local, rest) = rest.split_at_mut(nv);
    let (adj, done) = rest.split_at_mut(3 * nt);
    Ok(State { start, live, local, adj, done })
}

/// The mesh's adjacency (vertex → triangles) in `st`, everything live.
pub(super) fn fill_adjacency<P>(st: &mut State<'_>, mesh: &Mesh<'_, P>) {
    st.live.fill(0);
    st.local.fill(0);
    st.done.fill(0);
    for tri in mesh.indices {
        for v in tri {
            st.live[usize::from(*v)] += 1;
        }
    }
    let mut sum = 0;
    for v in 0..st.live.len() {
        st.start[v] = sum;
        sum += st.live[v];
        st.live[v] = 0;
    }
    st.start[st.live.len()] = sum;
    for (t, tri) in mesh.indices.iter().enumerate() {
        for v in tri.map(usize::from) {
            st.adj[(st.start[v] + st.live[v]) as usize] = t as u32;
            st.live[v] += 1;
        }
    }
}
