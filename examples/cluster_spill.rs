//! What drawing each knot cluster once per frame would need: a study for
//! `docs/setup_cost.md` (nineteenth pass), not a renderer.
//!
//! ```text
//! cargo run --release --example cluster_spill          # 16-row bands
//! cargo run --release --example cluster_spill -- 24    # another band height
//! ```
//!
//! The meshlet stage visits a cluster in every band its rows reach and
//! repeats its vertex work there. Drawn whole in the first band that holds
//! one of its triangles, a cluster's covered pixels in the rows below that
//! band would have to wait, in a store, for their band (depth test and
//! write there, in cluster order). For the knot's frame (`benches/common`'s
//! camera and light, the `fw_bench` frame) this prints, per band, the
//! pixels such a store holds once the band is done, and for a store of a
//! given capacity, how many repeated cluster visits it would remove (a
//! cluster is drawn whole only if all its later pixels fit what is free at
//! that moment; otherwise it is visited per band, as now). Pixels are
//! counted before the depth test, as the store would hold them.

#[path = "../benches/common/mod.rs"]
mod common;
#[path = "../benches/common/knot.rs"]
mod knot;
#[path = "common/knot_mesh.rs"]
mod knot_mesh;

use common::{H, W, pipeline3d};
use knot::{KNOT_COLOR, knot_model};
use knot_mesh::{KNOT, KNOT_MESHLETS};
use microraster::ClipRect;
use microraster::edge::{Cull, TriangleSpans};
use microraster::mesh::{MeshletMesh, ValidMeshletMesh};
use microraster::pipeline::ClusterCache;

/// One cluster's covered pixels per frame row and drawn triangles per band.
struct Cluster {
    pixels_per_row: Vec<u32>,
    triangles_per_band: Vec<u32>,
}

impl Cluster {
    /// The first band holding one of its triangles (`None`: none drawn).
    fn first_band(&self) -> Option<usize> {
        self.triangles_per_band.iter().position(|&n| n > 0)
    }

    /// Bands holding one of its triangles: its visits that draw something.
    fn bands(&self) -> usize {
        self.triangles_per_band.iter().filter(|&&n| n > 0).count()
    }

    /// Its pixels per band of `bh` rows.
    fn pixels_per_band(&self, bh: usize) -> Vec<u32> {
        let mut out = vec![0; H.div_ceil(bh)];
        for (row, &n) in self.pixels_per_row.iter().enumerate() {
            out[row / bh] += n;
        }
        out
    }
}

fn main() {
    let bh: usize = std::env::args().nth(1).map_or(16, |s| s.parse().expect("a band height"));
    assert!((1..=H).contains(&bh), "band height 1 to {H}");
    let bands = H.div_ceil(bh);
    let pipeline = pipeline3d::<f32, 4>();
    let model = knot_model::<f32>();
    let clip = ClipRect::new(0, 0, W as i32, H as i32);
    let mut cache = Box::new(ClusterCache::<f32, 4, 0, 0>::sized());
    // Each cluster alone, all rows at once: the triangles the meshlet stage
    // draws for it, in order.
    let clusters: Vec<Cluster> = (0..KNOT_MESHLETS.len())
        .map(|i| {
            let one = MeshletMesh { meshlets: &KNOT_MESHLETS[i..i + 1], ..KNOT };
            let one = ValidMeshletMesh::new(one).expect("a knot cluster");
            let mut c = Cluster { pixels_per_row: vec![0; H], triangles_per_band: vec![0; bands] };
            pipeline
                .meshlet_triangles(&one, &model, KNOT_COLOR, &mut cache, (0, H as i32 - 1), |t| {
                    let (r0, r1) = t.rows();
                    for b in (r0.max(0) as usize / bh)..=(r1.min(H as i32 - 1).max(0) as usize / bh) {
                        c.triangles_per_band[b] += u32::from(r0 <= r1);
                    }
                    for s in TriangleSpans::new(t.v.map(|v| v.pos), clip, Cull::None) {
                        c.pixels_per_row[s.y as usize] += s.len;
                    }
                })
                .expect("the knot's frame");
            c
        })
        .collect();
    let pixels: u32 = clusters.iter().map(|c| c.pixels_per_row.iter().sum::<u32>()).sum();
    let drawn = clusters.iter().filter(|c| c.first_band().is_some()).count();
    let visits: usize = clusters.iter().map(Cluster::bands).sum();
    println!(
        "{bh}-row bands: {pixels} covered pixels; {drawn} clusters draw a triangle, in {visits} cluster-band \
         visits ({} repeated)",
        visits - drawn
    );
    // Unlimited store: what it holds after each band.
    let held: Vec<u32> = (0..bands)
        .map(|k| {
            let below = (k + 1) * bh;
            clusters
                .iter()
                .filter(|c| c.first_band().is_some_and(|f| f <= k))
                .map(|c| c.pixels_per_row[below.min(H)..].iter().sum::<u32>())
                .sum()
        })
        .collect();
    println!("pixels held after each band (no limit): {held:?}, most {}", held.iter().max().unwrap_or(&0));
    // A store of `cap` pixels, clusters drawn whole in order while they fit.
    println!("| store (pixels) | repeated visits removed |");
    println!("|--:|--:|");
    for cap in [256u32, 512, 640, 768, 1024, 1536, 2048] {
        let mut pending = vec![0u32; bands];
        let mut removed = 0;
        for k in 0..bands {
            for c in clusters.iter().filter(|c| c.first_band() == Some(k) && c.bands() > 1) {
                let per_band = c.pixels_per_band(bh);
                let later: u32 = per_band[k + 1..].iter().sum();
                if pending[k + 1..].iter().sum::<u32>() + later <= cap {
                    for (p, n) in pending[k + 1..].iter_mut().zip(&per_band[k + 1..]) {
                        *p += n;
                    }
                    removed += c.bands() - 1;
                }
            }
        }
        println!("| {cap} | {removed} of {} |", visits - drawn);
    }
}
