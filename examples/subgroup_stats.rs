//! Study for `docs/setup_cost.md` (twenty-sixth pass), not a renderer: how
//! many of the knot's per-visit vertex `y`/`w` evaluations a cluster split
//! into slabs with their own bounding spheres could skip.
//!
//! ```text
//! cargo run --release --example subgroup_stats -- ANGLE SLAB_VERTICES   # e.g. 0.6 16
//! ```
//!
//! Each cluster's vertices are sorted along the axis of its largest extent
//! and cut into slabs of `SLAB_VERTICES`. A cluster visits a 16-row band
//! when its vertices' rows, with the band test's margin (a row above, two
//! below), meet the band (no normal-cone test: an approximation of the
//! stage's visits). A slab is skipped when its sphere (centre, radius
//! projected at the centre's depth) lies beyond that margin: "sphere";
//! "exact" counts slabs whose vertices all lie beyond it, the bound no
//! slab test can pass.

#[path = "common/knot_mesh.rs"]
mod knot_mesh;
use knot_mesh::{KNOT_MESHLET_VERTICES, KNOT_MESHLETS, KNOT_POSITIONS};
use microraster::math::{Vec3, transform};

fn main() {
    let arg = |i: usize, d: f32| std::env::args().nth(i).map_or(d, |a| a.parse().expect("a number"));
    let (angle, slab) = (arg(1, 0.6), arg(2, 16.0) as usize);
    let (w, h, band) = (320f32, 240f32, 16f32);
    let eye = Vec3::new(0.0f32, 1.9, 5.6);
    let view = transform::look_at(eye, Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
    let mvp = transform::perspective(0.9f32, w / h, 1.0, 20.0).unwrap() * view * transform::rotation_y(angle);
    let focal = 1.0 / 0.45f32.tan();
    let row_of = |p: [f32; 3]| {
        let c = mvp.transform_point(Vec3::new(p[0], p[1], p[2]));
        ((1.0 - c.y / c.w) * 0.5 * h, c.w)
    };
    let (mut visits, mut vertex_visits, mut exact, mut sphere) = (0u64, 0u64, 0u64, 0u64);
    for m in KNOT_MESHLETS.iter() {
        let at = |i: usize| KNOT_POSITIONS[KNOT_MESHLET_VERTICES[m.vertex_offset as usize + i] as usize];
        let pts: Vec<[f32; 3]> = (0..m.vertex_count as usize).map(at).collect();
        let rows: Vec<f32> = pts.iter().map(|&p| row_of(p).0).collect();
        let (lo, hi) = rows.iter().fold((f32::MAX, f32::MIN), |(a, b), &r| (a.min(r), b.max(r)));
        let extent = |k: usize| {
            let v = pts.iter().map(|p| p[k]);
            v.clone().fold(f32::MIN, f32::max) - v.fold(f32::MAX, f32::min)
        };
        let k = (0..3).max_by(|&a, &b| extent(a).total_cmp(&extent(b))).unwrap();
        let mut order: Vec<usize> = (0..pts.len()).collect();
        order.sort_by(|&a, &b| pts[a][k].total_cmp(&pts[b][k]));
        let slabs: Vec<&[usize]> = order.chunks(slab).collect();
        // Each slab's sphere as a centre row and a radius in rows.
        let spheres: Vec<(f32, f32)> = slabs
            .iter()
            .map(|g| {
                let n = g.len() as f32;
                let c = [0, 1, 2].map(|k| g.iter().map(|&i| pts[i][k]).sum::<f32>() / n);
                let dist = |i: usize| (0..3).map(|k| (pts[i][k] - c[k]).powi(2)).sum::<f32>().sqrt();
                let r = g.iter().map(|&i| dist(i)).fold(0.0, f32::max);
                let (row, cw) = row_of(c);
                (row, r * focal * 0.5 * h / (cw - r).max(0.1))
            })
            .collect();
        let mut b0 = 0.0;
        while b0 < h {
            let (y0, y1) = (b0 - 1.0, b0 + band + 2.0);
            if hi >= y0 && lo <= y1 {
                visits += 1;
                vertex_visits += pts.len() as u64;
                for (g, &(row, r)) in slabs.iter().zip(&spheres) {
                    if g.iter().all(|&i| rows[i] < y0) || g.iter().all(|&i| rows[i] > y1) {
                        exact += g.len() as u64;
                    }
                    if row + r < y0 || row - r > y1 {
                        sphere += g.len() as u64;
                    }
                }
            }
            b0 += band;
        }
    }
    let pc = |n: u64| 100.0 * n as f64 / vertex_visits as f64;
    println!(
        "slabs of {slab}: {visits} cluster visits, {vertex_visits} vertex visits; skipped by the slab spheres \
         {sphere} ({:.1} %), by the vertices themselves {exact} ({:.1} %)",
        pc(sphere),
        pc(exact)
    );
}
