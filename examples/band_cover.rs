//! How many of the triangles the meshlet stage hands to a band cover none
//! of its pixel centres: a study for `docs/setup_cost.md` (twenty-first
//! pass), not a renderer.
//!
//! ```text
//! cargo run --release --example band_cover          # 16-row bands
//! cargo run --release --example band_cover -- 24    # another band height
//! ```
//!
//! The stage computes each handed triangle's depths and lit colours
//! (`Pipeline::complete`) before the raster finds its coverage. For the
//! knot's frame (`benches/common`'s camera and light, the `fw_bench` frame)
//! this prints, summed over the bands, the triangles handed to the raster,
//! those whose box holds no pixel centre of the band, those that cover no
//! centre, and the distinct vertices (by snapped position, per band) the
//! handed and the covering triangles use: what computing depths and
//! colours only for covering triangles would skip.

#[path = "../benches/common/mod.rs"]
mod common;
#[path = "../benches/common/knot.rs"]
mod knot;
#[path = "common/knot_mesh.rs"]
mod knot_mesh;

use std::collections::HashSet;

use common::{H, W, pipeline3d};
use knot::{KNOT_COLOR, knot_model};
use knot_mesh::KNOT;
use microraster::edge::{Cull, TriangleSpans};
use microraster::mesh::ValidMeshletMesh;
use microraster::pipeline::ClusterCache;
use microraster::{ClipRect, SubPoint};

/// Subpixel bits of the knot's pipeline.
const S: u32 = 4;

/// Whether the box of `v` holds the centre of a pixel in rows `y0..y1`.
fn box_holds_centre(v: [SubPoint<S>; 3], (y0, y1): (i32, i32)) -> bool {
    let (one, half) = (1 << S, 1 << (S - 1));
    let (xs, ys) = (v.map(|p| p.x()), v.map(|p| p.y()));
    let lo = |c: [i32; 3]| (c.iter().min().copied().unwrap_or(0) - half + one - 1) >> S;
    let hi = |c: [i32; 3]| (c.iter().max().copied().unwrap_or(0) - half) >> S;
    lo(xs) <= hi(xs) && lo(ys).max(y0) <= hi(ys).min(y1 - 1)
}

fn main() {
    let bh: usize = std::env::args().nth(1).map_or(16, |s| s.parse().expect("a band height"));
    assert!((1..=H).contains(&bh), "band height 1 to {H}");
    let pipeline = pipeline3d::<f32, S>();
    let model = knot_model::<f32>();
    let mesh = ValidMeshletMesh::new(KNOT).expect("the knot's meshlets");
    let mut cache = Box::new(ClusterCache::new());
    let (mut handed, mut no_centre, mut uncovered, mut pixels) = (0u32, 0u32, 0u32, 0u32);
    let (mut used, mut used_covering) = (0usize, 0usize);
    for y0 in (0..H).step_by(bh) {
        let rows = (y0 as i32, (y0 + bh).min(H) as i32);
        let clip = ClipRect::new(0, rows.0, W as i32, rows.1);
        let (mut all, mut covering) = (HashSet::new(), HashSet::new());
        pipeline
            .meshlet_triangles(&mesh, &model, KNOT_COLOR, &mut cache, (rows.0, rows.1 - 1), |t| {
                let v = t.v.map(|v| v.pos);
                let n: u32 = TriangleSpans::new(v, clip, Cull::None).map(|s| s.len).sum();
                handed += 1;
                pixels += n;
                no_centre += u32::from(!box_holds_centre(v, rows));
                uncovered += u32::from(n == 0);
                for p in v {
                    all.insert((p.x(), p.y()));
                    if n > 0 {
                        covering.insert((p.x(), p.y()));
                    }
                }
            })
            .expect("the knot's frame");
        (used, used_covering) = (used + all.len(), used_covering + covering.len());
    }
    println!(
        "{bh}-row bands: {handed} triangles handed to the raster, {pixels} covered pixels; {uncovered} \
         ({:.1} %) cover no pixel centre of their band, {no_centre} of them with no centre in their box; \
         vertices used per band (distinct snapped positions, summed): {used} by the handed triangles, \
         {used_covering} ({:.1} %) by those that cover a centre",
        100.0 * f64::from(uncovered) / f64::from(handed),
        100.0 * used_covering as f64 / used as f64
    );
}
