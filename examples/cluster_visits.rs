//! Three studies of the knot's cluster visits for `docs/setup_cost.md`
//! (twenty-sixth and twenty-eighth passes), not a renderer. Both use the `fw_bench` frame's
//! camera and angle, and approximate the stage's visits from the vertices'
//! rows: a cluster visits a 16-row band when its vertices' rows, with the
//! band test's margin (a row above, two below), meet the band (no
//! normal-cone test; 481 visits here against the stage's 486).
//!
//! ```text
//! cargo run --release --example cluster_visits -- slabs 16   # slabs of 16 vertices
//! cargo run --release --example cluster_visits -- flat       # clusters built flatter in y
//! cargo run --release --example cluster_visits -- done       # finished triangles skipped
//! cargo run --release --example cluster_visits -- handed     # what the raster is handed
//! ```
//!
//! * `slabs N`: each cluster's vertices sorted along the axis of its
//!   largest extent and cut into slabs of `N`. A slab is skipped when its
//!   sphere (centre, radius projected at the centre's depth) lies beyond
//!   the band's margin ("sphere"); "exact" counts slabs whose vertices all
//!   lie beyond it, the bound no slab test can pass.
//! * `flat`: the clusters `build_meshlets` makes from the positions with
//!   `y` scaled by `K` (flatter in model `y`, which this camera's rows
//!   mostly follow), their visits counted with the real positions.
//! * `done`: a per-cluster mask of the triangles no later band needs
//!   (back faces once a band has met them, and triangles that end above
//!   the next band): the triangle visits and vertex `y`/`w` computations
//!   a cluster's later visits would keep (only the live triangles and
//!   their vertices).
//! * `handed` (thirty-ninth pass): the triangles the meshlet stage itself
//!   hands to the raster in each 16-row band
//!   (`Pipeline::meshlet_triangles`), their candidate centres (the
//!   bounding box's columns times its rows in the band), the centres they
//!   cover, how many cover none, and how many have no centre row at all.

#[path = "../benches/common/mod.rs"]
mod common;
#[path = "../benches/common/knot.rs"]
mod knot;
#[path = "common/knot_mesh.rs"]
mod knot_mesh;
use knot_mesh::{KNOT_MESHLET_TRIANGLES, KNOT_MESHLET_VERTICES, KNOT_MESHLETS, KNOT_POSITIONS};
use microraster::math::{Mat4, Vec3, transform};
use microraster::mesh::{
    Mesh, Meshlet, bounding_sphere, build_meshlets, meshlet_bound, meshlet_scratch_len, meshlet_vertex_bound,
};

const H: f32 = common::H as f32;
const BAND: f32 = 16.0;

fn main() {
    // The benchmark frame's view and model; its projection as
    // `Scene3d::pipeline` makes it (which keeps the matrix private).
    let view = common::pipeline3d::<f32, 4>().view();
    let projection = transform::perspective(0.9f32, common::W as f32 / H, 1.0, 20.0).unwrap();
    let mvp = projection * view * knot::knot_model::<f32>();
    let mut args = std::env::args().skip(1);
    match args.next().as_deref() {
        Some("flat") => flat(&mvp),
        Some("done") => done(&mvp),
        Some("handed") => handed(),
        _ => slabs(&mvp, args.next().map_or(16, |a| a.parse().expect("a slab size"))),
    }
}

/// The row (from the top, in pixels) and clip `w` of a model position.
fn row_of(mvp: &Mat4<f32>, p: [f32; 3]) -> (f32, f32) {
    let c = mvp.transform_point(Vec3::new(p[0], p[1], p[2]));
    ((1.0 - c.y / c.w) * 0.5 * H, c.w)
}

/// The tops of the bands whose rows, with the band test's margin, meet `lo..=hi`.
fn bands(lo: f32, hi: f32) -> impl Iterator<Item = f32> {
    (0..(H / BAND) as u32).map(|b| b as f32 * BAND).filter(move |&b0| hi >= b0 - 1.0 && lo <= b0 + BAND + 2.0)
}

fn extent(rows: impl Iterator<Item = f32>) -> (f32, f32) {
    rows.fold((f32::MAX, f32::MIN), |(a, b), r| (a.min(r), b.max(r)))
}

fn slabs(mvp: &Mat4<f32>, slab: usize) {
    // 1/tan of half the 0.9 rad field of view.
    let focal = 1.0 / 0.45f32.tan();
    let (mut visits, mut vertex_visits, mut exact, mut sphere) = (0u64, 0u64, 0u64, 0u64);
    for m in KNOT_MESHLETS.iter() {
        let at = |i: usize| KNOT_POSITIONS[KNOT_MESHLET_VERTICES[m.vertex_offset as usize + i] as usize];
        let pts: Vec<[f32; 3]> = (0..m.vertex_count as usize).map(at).collect();
        let rows: Vec<f32> = pts.iter().map(|&p| row_of(mvp, p).0).collect();
        let (lo, hi) = extent(rows.iter().copied());
        let axis_extent = |k: usize| {
            let (a, b) = extent(pts.iter().map(|p| p[k]));
            b - a
        };
        let k = (0..3).max_by(|&a, &b| axis_extent(a).total_cmp(&axis_extent(b))).unwrap();
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
                let (row, cw) = row_of(mvp, c);
                (row, r * focal * 0.5 * H / (cw - r).max(0.1))
            })
            .collect();
        for b0 in bands(lo, hi) {
            let (y0, y1) = (b0 - 1.0, b0 + BAND + 2.0);
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
    }
    let pc = |n: u64| 100.0 * n as f64 / vertex_visits as f64;
    println!(
        "slabs of {slab}: {visits} cluster visits, {vertex_visits} vertex visits; skipped by the slab spheres \
         {sphere} ({:.1} %), by the vertices themselves {exact} ({:.1} %)",
        pc(sphere),
        pc(exact)
    );
}

fn flat(mvp: &Mat4<f32>) {
    let mut indices = Vec::new();
    for m in KNOT_MESHLETS.iter() {
        for t in &KNOT_MESHLET_TRIANGLES[m.triangle_offset as usize..][..m.triangle_count as usize] {
            indices.push(t.map(|l| KNOT_MESHLET_VERTICES[m.vertex_offset as usize + l as usize]));
        }
    }
    let rows: Vec<f32> = KNOT_POSITIONS.iter().map(|&p| row_of(mvp, p).0).collect();
    println!("| y scaled by | clusters | mean rows a cluster spans | cluster visits | vertex visits |");
    println!("|--:|--:|--:|--:|--:|");
    for k in [1.0f32, 1.5, 2.0, 3.0, 4.0] {
        let pos: Vec<[f32; 3]> = KNOT_POSITIONS.iter().map(|p| [p[0], p[1] * k, p[2]]).collect();
        let mesh = Mesh::new(&pos, &[], &indices, bounding_sphere(&pos));
        let nt = indices.len();
        let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
        let mut verts = vec![0u16; meshlet_vertex_bound(nt)];
        let mut tris = vec![[0u8; 3]; nt];
        let mut scratch = vec![0u32; meshlet_scratch_len(pos.len(), nt)];
        let m = build_meshlets(mesh, &mut meshlets, &mut verts, &mut tris, &mut scratch)
            .expect("the knot's clusters");
        let (mut visits, mut vertex_visits, mut span) = (0usize, 0usize, 0f32);
        for c in m.meshlets {
            let vs = &m.vertices[c.vertex_offset as usize..][..c.vertex_count as usize];
            let (lo, hi) = extent(vs.iter().map(|&i| rows[usize::from(i)]));
            span += hi - lo;
            let n = bands(lo, hi).count();
            (visits, vertex_visits) = (visits + n, vertex_visits + n * vs.len());
        }
        let n = m.meshlets.len();
        println!("| {k} | {n} | {:.1} | {visits} | {vertex_visits} |", span / n as f32);
    }
}

/// The screen position (pixels) of a model position.
fn screen_of(mvp: &Mat4<f32>, p: [f32; 3]) -> (f32, f32) {
    let c = mvp.transform_point(Vec3::new(p[0], p[1], p[2]));
    ((1.0 + c.x / c.w) * 0.5 * common::W as f32, (1.0 - c.y / c.w) * 0.5 * H)
}

/// A cluster's revisits with a per-cluster mask of the triangles no later
/// band needs (back faces, and triangles that end above the next band):
/// the triangle visits and the vertex `y`/`w` computations left.
fn done(mvp: &Mat4<f32>) {
    let (mut visits, mut revisits) = (0u64, 0u64);
    let (mut tri_all, mut tri_live, mut vert_all, mut vert_live) = (0u64, 0u64, 0u64, 0u64);
    let (mut tri_re, mut vert_re) = (0u64, 0u64);
    let mut back_total = [0u64; 2];
    for m in KNOT_MESHLETS.iter() {
        let at = |i: usize| KNOT_POSITIONS[KNOT_MESHLET_VERTICES[m.vertex_offset as usize + i] as usize];
        let scr: Vec<(f32, f32)> = (0..m.vertex_count as usize).map(|i| screen_of(mvp, at(i))).collect();
        let tris = &KNOT_MESHLET_TRIANGLES[m.triangle_offset as usize..][..m.triangle_count as usize];
        let area = |t: &[u8; 3]| {
            let [a, b, c] = t.map(|i| scr[i as usize]);
            (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)
        };
        for t in tris {
            back_total[(area(t) > 0.0) as usize] += 1;
        }
        let (lo, hi) = extent(scr.iter().map(|s| s.1));
        let mut live = vec![true; tris.len()];
        for (k, b0) in bands(lo, hi).enumerate() {
            let (y0, y1) = (b0 - 1.0, b0 + BAND + 2.0);
            visits += 1;
            let lt: Vec<usize> = (0..tris.len()).filter(|&i| live[i]).collect();
            let mut need = vec![false; scr.len()];
            for &i in &lt {
                for j in tris[i] {
                    need[j as usize] = true;
                }
            }
            let nv = need.iter().filter(|&&n| n).count() as u64;
            tri_all += tris.len() as u64;
            vert_all += scr.len() as u64;
            tri_live += lt.len() as u64;
            vert_live += nv;
            if k > 0 {
                revisits += 1;
                tri_re += lt.len() as u64;
                vert_re += nv;
            }
            for &i in &lt {
                let rows = tris[i].map(|j| scr[j as usize].1);
                let (tlo, thi) = (rows[0].min(rows[1]).min(rows[2]), rows[0].max(rows[1]).max(rows[2]));
                let reached = thi >= y0 && tlo <= y1;
                // Back faces (this camera's: positive screen area) once seen,
                // and triangles that end above the next band.
                if (reached && area(&tris[i]) > 0.0) || thi < b0 + BAND - 1.0 {
                    live[i] = false;
                }
            }
        }
    }
    println!(
        "{visits} cluster visits ({revisits} revisits); areas by sign {back_total:?}\n\
         triangle visits {tri_all}, live {tri_live} (revisits: {tri_re} of them)\n\
         vertex y/w {vert_all}, needed {vert_live} (revisits: {vert_re} of them)"
    );
}

/// The `handed` study (module docs).
fn handed() {
    use microraster::edge::{Cull, TriangleSpans};
    use microraster::{ClipRect, raster3d::ScreenTriangle};
    let p = common::pipeline3d::<f32, 4>();
    let mut cache = Box::new(microraster::pipeline::ClusterCache::new());
    let model = knot::knot_model::<f32>();
    let (mut handed, mut candidates, mut covered, mut none, mut no_row) = (0u32, 0i64, 0u64, 0u32, 0u32);
    for y0 in (0..common::H as i32).step_by(BAND as usize) {
        let rows = (y0, y0 + BAND as i32 - 1);
        let band = ClipRect::new(0, y0, common::W as i32, rows.1 + 1);
        let mut each = |t: &ScreenTriangle<4>| {
            handed += 1;
            let (lo, hi) = t.rows();
            no_row += (lo > hi) as u32;
            // Columns whose centre x + 0.5 lies between the leftmost and
            // rightmost vertex, as `ScreenTriangle::rows` finds the rows (in
            // internal units of 2^-(S + 1) px, S = 4).
            let (one, half) = (1 << 5, 1 << 4);
            let xs = t.v.map(|v| 2 * v.pos.x());
            let (x_lo, x_hi) = (xs.into_iter().min().unwrap_or(0), xs.into_iter().max().unwrap_or(0));
            let cols = ((x_hi - half) >> 5) - ((x_lo - half + one - 1) >> 5) + 1;
            let rows_in = hi.min(rows.1) - lo.max(rows.0) + 1;
            candidates += i64::from(cols.max(0) * rows_in.max(0));
            let n: u32 = TriangleSpans::new(t.v.map(|v| v.pos), band, Cull::None).map(|s| s.len).sum();
            covered += u64::from(n);
            none += (n == 0) as u32;
        };
        p.meshlet_triangles(&knot_mesh::VALID_KNOT, &model, knot::KNOT_COLOR, &mut cache, rows, &mut each)
            .expect("the knot's frame");
    }
    println!(
        "handed to the raster: {handed} triangle-band pairs, {:.2} candidate centres and {:.2} covered \
         centres each; {none} ({:.1} %) cover no centre of their band, {no_row} have no centre row",
        candidates as f64 / handed as f64,
        covered as f64 / handed as f64,
        100.0 * none as f64 / handed as f64,
    );
}
