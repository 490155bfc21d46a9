//! The `closed` target's meshlet check: the mesh built into clusters and
//! drawn through `Pipeline::meshlet_triangles` band by band must cover what
//! `draw_mesh` covers, cluster by cluster.

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::ClipRect;
use microraster::clip3d::MAX_POLYGON_VERTICES;
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::{Mat4, Scalar};
use microraster::mesh::{
    Mesh, Meshlet, MeshletMesh, ValidMeshletMesh, build_meshlets, meshlet_bound, meshlet_scratch_len,
    meshlet_vertex_bound,
};
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::ScreenTriangle;
use microraster_fuzz::signed_area2;

use super::surface::MAX_TRIANGLES;

/// Capacity of one band's bins in [`draw_mesh`]: every triangle of the
/// largest mesh, each clipped into a polygon of at most
/// `MAX_POLYGON_VERTICES` corners (a fan of two fewer triangles), so no
/// input is skipped for want of room.
const BINS: usize = MAX_TRIANGLES * (MAX_POLYGON_VERTICES - 2);

/// A frame's `rows`-row bands, first and last row.
pub fn bands(h: usize, rows: usize) -> impl Iterator<Item = (i32, i32)> {
    (0..h as i32).step_by(rows).map(move |y0| (y0, (y0 + rows as i32).min(h as i32) - 1))
}

/// How many front and back faces cover each pixel centre of a frame.
#[derive(PartialEq, Debug)]
pub struct Coverage {
    pub w: usize,
    pub front: Vec<u16>,
    pub back: Vec<u16>,
}

impl Coverage {
    pub fn new(w: usize, h: usize) -> Self {
        Coverage { w, front: vec![0; w * h], back: vec![0; w * h] }
    }

    fn h(&self) -> usize {
        self.front.len() / self.w
    }

    /// `tri`'s centres in frame rows `y0..=y1`, counted by its winding.
    pub fn add<const S: u32>(&mut self, tri: &ScreenTriangle<S>, y0: i32, y1: i32) {
        let counts = if signed_area2(tri) > 0 { &mut self.back } else { &mut self.front };
        let clip = ClipRect::new(0, y0, self.w as i32, y1 + 1);
        for s in TriangleSpans::new(tri.v.map(|v| v.pos), clip, Cull::None) {
            for x in s.x..s.x + s.len as i32 {
                counts[s.y as usize * self.w + x as usize] += 1;
            }
        }
    }

    fn plus(&mut self, other: &Coverage) {
        let sum = |a: &mut [u16], b: &[u16]| a.iter_mut().zip(b).for_each(|(a, b)| *a += b);
        sum(&mut self.front, &other.front);
        sum(&mut self.back, &other.back);
    }

    fn is_empty(&self) -> bool {
        self.front.iter().chain(&self.back).all(|&c| c == 0)
    }
}

/// `mesh` through `p.draw_mesh` band by band (culling as `p` says), or
/// `None` where the pipeline rejects it with a documented error (`Fx`
/// range).
pub fn draw_mesh<T: Scalar, const S: u32>(
    p: &Pipeline<T, S>,
    mesh: &Mesh<'_, f32>,
    model: &Mat4<T>,
    (w, h, rows): (usize, usize, usize),
) -> Option<Coverage> {
    let mut drawn = Coverage::new(w, h);
    let mut bins = Box::new(heapless::Vec::<ScreenTriangle<S>, BINS>::new());
    for (y0, y1) in bands(h, rows) {
        let mut band = *p;
        band.rows = Some((y0, y1));
        bins.clear();
        band.draw_mesh(mesh, model, Rgb565::new(31, 0, 0), &mut bins).ok()?;
        for tri in bins.iter() {
            drawn.add(tri, y0, y1);
        }
    }
    Some(drawn)
}

/// The same mesh built into clusters, through the meshlet stage band by
/// band (`Pipeline::meshlet_triangles`, with the frame's record of the
/// clusters if `recorded`), whole and one cluster at a time. Each
/// cluster's reference is `draw_mesh` of its own triangles (the mesh's
/// sphere kept, so the same path), and together they must cover what
/// `drawn` covers. Culling off, a cluster must cover its reference: the
/// cluster tests against the band's slab and the view volume reject only
/// what has no triangle there. Back faces culled, its reference's front
/// faces alone; where the normal cone rejected it, nothing, and none of its
/// triangles may face the eye (in `f64`, with a margin; in exact
/// arithmetic none does, and a front face of `draw_mesh`'s is then a sliver
/// that snapping inverted). The whole mesh, each way, covers the sum of
/// its clusters.
pub fn meshlets_agree<T: Scalar, const S: u32>(
    p: Pipeline<T, S>,
    mesh: Mesh<'_, f32>,
    model: &Mat4<T>,
    (rows, recorded): (usize, bool),
    (clip, margin): (&[[f64; 4]], &[[f64; 4]]),
    drawn: &Coverage,
) {
    let (nv, nt) = (mesh.positions.len(), mesh.indices.len());
    let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
    let mut vertices = vec![0; meshlet_vertex_bound(nt)];
    let mut triangles = vec![[0; 3]; nt];
    let mut scratch = vec![0; meshlet_scratch_len(nv, nt)];
    let Ok(built) = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch) else {
        return;
    };
    let (w, h) = (drawn.w, drawn.h());
    // Band by band, as a frame draws: the coverage, and whether the normal
    // cone rejected a cluster.
    let meshlet_draw = |q: &Pipeline<T, S>, m: MeshletMesh<'_, f32>| -> Option<(Coverage, bool)> {
        let m = ValidMeshletMesh::new(m).ok()?;
        let (mut record, mut plain) = (ClusterCache::<T, S>::new(), ClusterCache::<T, S, 0, 0>::sized());
        let mut got = Coverage::new(w, h);
        let mut away = false;
        for (y0, y1) in bands(h, rows) {
            let color = Rgb565::new(31, 0, 0);
            let sink = |tri: &ScreenTriangle<S>| got.add(tri, y0, y1);
            let stats = if recorded {
                q.meshlet_triangles(&m, model, color, &mut record, (y0, y1), sink)
            } else {
                q.meshlet_triangles(&m, model, color, &mut plain, (y0, y1), sink)
            };
            away |= stats.ok()?.clusters_back_facing > 0; // else a documented rejection
        }
        Some((got, away))
    };
    let mut culled = p;
    culled.cull = Cull::Clockwise;
    let (mut all_off, mut all_culled) = (Coverage::new(w, h), Coverage::new(w, h));
    for (c, cluster) in built.meshlets.iter().enumerate() {
        let local =
            &built.triangles[cluster.triangle_offset as usize..][..usize::from(cluster.triangle_count)];
        let slots = &built.vertices[cluster.vertex_offset as usize..];
        let indices: Vec<[u16; 3]> = local.iter().map(|t| t.map(|i| slots[usize::from(i)])).collect();
        let Some(reference) = draw_mesh(&p, &Mesh { indices: &indices, ..mesh }, model, (w, h, rows)) else {
            return;
        };
        let one = MeshletMesh { meshlets: &built.meshlets[c..=c], ..built };
        let Some((off, _)) = meshlet_draw(&p, one) else { return };
        assert_eq!(off, reference, "cluster {c}: the meshlet stage's coverage differs from draw_mesh's");
        let Some((on, away)) = meshlet_draw(&culled, one) else { return };
        if away {
            assert!(on.is_empty(), "cluster {c}: rejected, yet it drew");
            // Rejected rightly: no triangle faces the eye (in f64, with
            // a margin for the paths' rounding of positions and matrices).
            for t in &indices {
                let v = t.map(|i| screen(clip[usize::from(i)], margin[usize::from(i)]));
                let (s, d) = (v.map(|v| v.0), v.map(|v| v.1));
                let (e1, e2) = ((s[1].0 - s[0].0, s[1].1 - s[0].1), (s[2].0 - s[0].0, s[2].1 - s[0].1));
                let (a, b) = (e1.0 * e2.1, e2.0 * e1.1);
                // Each edge vector moves by at most the sum of its ends'
                // margins, the cross product by what that makes of it.
                let (u1, u2) = (d[0] + d[1], d[0] + d[2]);
                let moved = u1 * (e2.0.abs() + e2.1.abs()) + u2 * (e1.0.abs() + e1.1.abs()) + 2.0 * u1 * u2;
                assert!(
                    a - b >= -(moved + 1e-4 * (a.abs() + b.abs())),
                    "cluster {c}: the cone rejected a front face: {s:?}"
                );
            }
        } else {
            assert_eq!(on.front, reference.front, "cluster {c}, culled: front faces' coverage differs");
            assert!(on.back.iter().all(|&c| c == 0), "cluster {c}, culled: a back face drawn");
        }
        all_off.plus(&reference);
        all_culled.plus(&on);
    }
    assert_eq!(&all_off, drawn, "the clusters' draw_mesh coverage differs from the whole mesh's");
    let Some((off, _)) = meshlet_draw(&p, built) else { return };
    assert_eq!(off, all_off, "the whole meshlet mesh's coverage differs from its clusters'");
    let Some((on, _)) = meshlet_draw(&culled, built) else { return };
    assert_eq!(on, all_culled, "culled: the whole meshlet mesh's coverage differs from its clusters'");
}

/// A vertex's screen position `(x/w, −y/w)` from its clip position `c`, and
/// how far it can move when each clip coordinate moves by at most its
/// `margin`: `(m_xy + max(|x|, |y|)/|w|·m_w)/(w − m_w)` (the premise keeps
/// `w − m_w` above `w_min`).
fn screen(c: [f64; 4], margin: [f64; 4]) -> ((f64, f64), f64) {
    let s = (c[0] / c[3], -c[1] / c[3]);
    let d = (margin[0].max(margin[1]) + s.0.abs().max(s.1.abs()) * margin[3]) / (c[3] - margin[3]);
    (s, d)
}
