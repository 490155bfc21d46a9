//! Study: band visits of the knot's clusters built from positions with y
//! scaled by K (flatter clusters in model y).
#[path = "common/knot_mesh.rs"]
mod knot_mesh;
use knot_mesh::*;
use microraster::math::{Vec3, transform};
use microraster::mesh::*;

fn main() {
    let (w, h) = (320f32, 240f32);
    let eye = Vec3::new(0.0f32, 1.9, 5.6);
    let view = transform::look_at(eye, Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
    let mvp =
        transform::perspective(0.9f32, w / h, 1.0, 20.0).unwrap() * view * transform::rotation_y(0.6f32);
    let row_of = |p: [f32; 3]| {
        let c = mvp.transform_point(Vec3::new(p[0], p[1], p[2]));
        (1.0 - c.y / c.w) * 0.5 * h
    };
    let mut indices = Vec::new();
    for m in KNOT_MESHLETS.iter() {
        for t in &KNOT_MESHLET_TRIANGLES[m.triangle_offset as usize..][..m.triangle_count as usize] {
            indices.push(t.map(|l| KNOT_MESHLET_VERTICES[m.vertex_offset as usize + l as usize]));
        }
    }
    let rows: Vec<f32> = KNOT_POSITIONS.iter().map(|&p| row_of(p)).collect();
    for k in [1.0f32, 1.5, 2.0, 3.0, 4.0] {
        let pos: Vec<[f32; 3]> = KNOT_POSITIONS.iter().map(|p| [p[0], p[1] * k, p[2]]).collect();
        let sphere = bounding_sphere(&pos);
        let mesh = Mesh::new(&pos, &[], &indices, sphere);
        let nt = indices.len();
        let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
        let mut verts = vec![0u16; meshlet_vertex_bound(nt)];
        let mut tris = vec![[0u8; 3]; nt];
        let mut scratch = vec![0u32; meshlet_scratch_len(pos.len(), nt)];
        let m = build_meshlets(mesh, &mut meshlets, &mut verts, &mut tris, &mut scratch).unwrap();
        let (mut visits, mut vv, mut span) = (0u32, 0u32, 0f32);
        for c in m.meshlets {
            let vs = &m.vertices[c.vertex_offset as usize..][..c.vertex_count as usize];
            let (lo, hi) = vs
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), &i| (a.min(rows[i as usize]), b.max(rows[i as usize])));
            span += hi - lo;
            let mut b0 = 0.0;
            while b0 < h {
                if hi >= b0 - 1.0 && lo <= b0 + 18.0 {
                    visits += 1;
                    vv += vs.len() as u32;
                }
                b0 += 16.0;
            }
        }
        println!(
            "k {k}: {} clusters, mean rows spanned {:.1}, visits {visits}, vertex visits {vv}",
            m.meshlets.len(),
            span / m.meshlets.len() as f32
        );
    }
}
