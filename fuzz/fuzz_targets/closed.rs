//! Closed meshes through the 3D pipeline have no cracks: a tetrahedron or a
//! deformed cube (any points, consistently wound faces: a closed surface,
//! folded, flat or degenerate as the points make it) under a fuzzed camera,
//! lens, model matrix, frame size, band height and clipping, on the `f32`
//! and `Fx` paths at `S ∈ {0, 4, 8}`, drawn band by band into bins with
//! culling off. Check: every pixel centre of the frame is covered by as
//! many front faces as back faces (`tests/bench_mesh/closed.rs` says why:
//! the top-left rule samples each centre as if moved by an infinitesimal,
//! and a closed surface's image covers any point as often each way). Then
//! the same mesh as a cluster through the meshlet stage band by band, with
//! culling off and on (`meshlets_agree`).
//!
//! The lens is the usual perspective one, or (from bytes read after the
//! mesh, so inputs written before they were added replay unchanged) a
//! perturbed perspective, an orthographic or a raw projection matrix
//! through `Pipeline::new`; the viewport is the whole frame, or one placed
//! by `Pipeline::with_origin` in a frame of its own size, hanging off it
//! or inside it; the far plane on or off, `w_min` the default or fuzzed,
//! the guard band the fast path's, a small one or `ClipPlanes::for_viewport`'s.
//!
//! Premise, checked in `f64` from the pipeline's own matrices with a margin
//! for the path's rounding: every vertex lies strictly inside the near and
//! (when clipped) far planes and above `w_min`, with clip coordinates
//! within ±2^63 (a cut there, or the clipper's discarding of a triangle
//! with a coordinate beyond ±2^64, opens the mesh). Cuts at the guard band
//! lie outside the viewport, or within a subpixel of its edge
//! (`Pipeline::confined`), which no centre sees: the check holds at every
//! centre of the viewport, and a confined viewport inside a larger frame
//! must leave every centre outside it uncovered. Inputs the pipeline
//! rejects with a documented error (`Fx` beyond 16.16) are skipped.
#![no_main]

use embedded_graphics_core::pixelcolor::Rgb565;
use libfuzzer_sys::fuzz_target;
use microraster::ClipRect;
use microraster::clip3d::ClipPlanes;
use microraster::edge::{Cull, TriangleSpans};
use microraster::math::{Mat4, Scalar, Vec3, transform};
use microraster::mesh::{
    Mesh, Meshlet, ValidMeshletMesh, bounding_sphere, build_meshlets, meshlet_bound, meshlet_scratch_len,
    meshlet_vertex_bound,
};
use microraster::pipeline::{ClusterCache, Pipeline};
use microraster::raster3d::ScreenTriangle;
use microraster_fuzz::{Input, clip_matrix_f64, is_f32, signed_area2};

const TETRAHEDRON: [[u16; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
/// The faces of a cube with corners `x + 2y + 4z`, wound one way round.
const CUBE: [[u16; 3]; 12] = [
    [0, 2, 3],
    [0, 3, 1],
    [4, 5, 7],
    [4, 7, 6],
    [0, 1, 5],
    [0, 5, 4],
    [2, 6, 7],
    [2, 7, 3],
    [0, 4, 6],
    [0, 6, 2],
    [1, 3, 7],
    [1, 7, 5],
];

fuzz_target!(|data: &[u8]| {
    microraster_fuzz::each_path!(&mut Input::new(data), run);
});

/// A coordinate: mostly on a coarse grid in ±8, sometimes any `f32`.
fn coord(inp: &mut Input) -> f32 {
    if inp.u8().is_multiple_of(8) { inp.f32() } else { f32::from(inp.u8() as i8) / 16.0 }
}

fn run<T: Scalar, const S: u32>(inp: &mut Input) {
    let (w, h) = (1 + u32::from(inp.u8() % 96), 1 + u32::from(inp.u8() % 96));
    let v = |p: [f32; 3]| Vec3::new(T::from_f32(p[0]), T::from_f32(p[1]), T::from_f32(p[2]));
    let eye = [(); 3].map(|()| coord(inp));
    let target = [(); 3].map(|()| coord(inp));
    let up = if inp.bool() { [0.0, 1.0, 0.0] } else { [(); 3].map(|()| coord(inp)) };
    let Ok(view) = transform::look_at(v(eye), v(target), v(up)) else { return };
    let fov = 0.05 + f32::from(inp.u8()) / 85.0;
    let near = inp.pick(&[1.0e-3f32, 0.1, 1.0]);
    let far = near * inp.pick(&[2.0f32, 100.0, 1.0e4]);
    let (t, f) = (T::from_f32, |x: T| f64::from(x.to_f32()));
    let Ok(p) = Pipeline::<T, S>::perspective(view, t(fov), t(near), t(far), w, h) else { return };
    let Ok(proj) = transform::perspective(t(fov), t(w as f32 / h as f32), t(near), t(far)) else { return };
    let confined = inp.bool();
    let rows = inp.pick(&[1, 3, 16, 64]);

    let cube = inp.bool();
    let positions: Vec<[f32; 3]> =
        (0..if cube { 8 } else { 4 }).map(|_| [(); 3].map(|()| coord(inp))).collect();
    let indices: &[[u16; 3]] = if cube { &CUBE } else { &TETRAHEDRON };
    let model = if inp.bool() {
        Mat4::IDENTITY
    } else {
        Mat4::from_f32(core::array::from_fn(|_| [(); 4].map(|()| coord(inp))))
    };
    let mesh = Mesh::new(&positions, &[], indices, bounding_sphere(&positions));
    let Some(Setup { mut p, proj, frame, viewport }) =
        setup(inp, p, proj, (w, h), (view, near, far, confined))
    else {
        return;
    };
    p.cull = Cull::None;

    // The premise, in f64, with each coordinate's magnitude bound for the
    // rounding margin.
    let (mvp, size) = clip_matrix_f64(proj, p.view(), model);
    let fx = !is_f32::<T>();
    let w_min = f64::from(p.clip.w_min());
    let homogeneous = |q: &[f32; 3]| [f(t(q[0])), f(t(q[1])), f(t(q[2])), 1.0];
    let row = |m: &[[f64; 4]; 4], r: usize, hq: [f64; 4], a: fn(f64) -> f64| {
        (0..4).map(|k| m[k][r] * a(hq[k])).sum::<f64>()
    };
    // Each vertex's clip position: the premise's and the cone check's.
    let clip: Vec<[f64; 4]> =
        positions.iter().map(|q| core::array::from_fn(|r| row(&mvp, r, homogeneous(q), |x| x))).collect();
    let clear = positions.iter().zip(&clip).all(|(q, c)| {
        let hq = homogeneous(q);
        let (z, wc) = (c[2], c[3]);
        let s = row(&size, 2, hq, f64::abs) + row(&size, 3, hq, f64::abs);
        let tol = if fx { 0.05 + 2e-3 * s } else { 1e-4 * s };
        // The clipper discards a triangle with a coordinate beyond ±2^64
        // (documented): the mesh would open there.
        let in_range = (0..4).all(|r| row(&size, r, hq, f64::abs) < 2f64.powi(63));
        let inside_far = !p.clip.far() || wc - z > tol;
        s.is_finite() && in_range && (!fx || s < 4000.0) && z > tol && inside_far && wc > w_min + tol
    });
    if !clear {
        return;
    }

    let (fw, fh) = (frame.0 as usize, frame.1 as usize);
    let mut drawn = Coverage::new(fw, fh);
    for (y0, y1) in bands(fh, rows) {
        let mut band = p;
        band.rows = Some((y0, y1));
        let mut bins = heapless::Vec::<ScreenTriangle<S>, 128>::new();
        if band.draw_mesh(&mesh, &model, Rgb565::new(31, 0, 0), &mut bins).is_err() {
            return; // a documented rejection (Fx range): nothing to check
        }
        for tri in &bins {
            drawn.add(tri, y0, y1);
        }
    }
    for (i, (f, b)) in drawn.front.iter().zip(&drawn.back).enumerate() {
        let (x, y) = ((i % fw) as i32, (i / fw) as i32);
        if viewport.contains(x, y) {
            assert_eq!(f, b, "pixel ({x}, {y}): {f} front, {b} back faces");
        } else {
            // Only a confined viewport smaller than the frame leaves any.
            assert_eq!((f, b), (&0, &0), "pixel ({x}, {y}) outside the viewport {viewport:?} covered");
        }
    }
    meshlets_agree(inp, p, mesh, &model, (rows, &clip), &drawn);
}

/// A frame's `rows`-row bands, first and last row.
fn bands(h: usize, rows: usize) -> impl Iterator<Item = (i32, i32)> {
    (0..h as i32).step_by(rows).map(move |y0| (y0, (y0 + rows as i32).min(h as i32) - 1))
}

/// How many front and back faces cover each pixel centre of a frame.
#[derive(PartialEq, Debug)]
struct Coverage {
    w: usize,
    front: Vec<u16>,
    back: Vec<u16>,
}

impl Coverage {
    fn new(w: usize, h: usize) -> Self {
        Coverage { w, front: vec![0; w * h], back: vec![0; w * h] }
    }

    /// `tri`'s centres in frame rows `y0..=y1`, counted by its winding.
    fn add<const S: u32>(&mut self, tri: &ScreenTriangle<S>, y0: i32, y1: i32) {
        let counts = if signed_area2(tri) > 0 { &mut self.back } else { &mut self.front };
        let clip = ClipRect::new(0, y0, self.w as i32, y1 + 1);
        for s in TriangleSpans::new(tri.v.map(|v| v.pos), clip, Cull::None) {
            for x in s.x..s.x + s.len as i32 {
                counts[s.y as usize * self.w + x as usize] += 1;
            }
        }
    }
}

/// The same mesh built into clusters (one: it has at most 12 triangles)
/// through the meshlet stage band by band (`Pipeline::meshlet_triangles`,
/// with the frame's record of the cluster or without). Culling off, the
/// coverage must be `draw_mesh`'s: the cluster tests against the band's
/// slab and the view volume reject only what has no triangle there. Back
/// faces culled, it must be the front faces' alone; where the normal cone
/// rejected the cluster, none of it, and no triangle may face the eye (in
/// `f64`, with a margin; in exact arithmetic none does, and a front face of
/// `draw_mesh`'s is then a sliver that snapping inverted).
fn meshlets_agree<T: Scalar, const S: u32>(
    inp: &mut Input,
    p: Pipeline<T, S>,
    mesh: Mesh<'_, f32>,
    model: &Mat4<T>,
    (rows, clip): (usize, &[[f64; 4]]),
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
    let Ok(m) = ValidMeshletMesh::new(built) else { return };
    let recorded = inp.bool();
    let h = drawn.front.len() / drawn.w;
    for cull in [Cull::None, Cull::Clockwise] {
        let mut q = p;
        q.cull = cull;
        let (mut record, mut plain) = (ClusterCache::<T, S>::new(), ClusterCache::<T, S, 0, 0>::sized());
        let mut got = Coverage::new(drawn.w, h);
        let mut away = false;
        for (y0, y1) in bands(h, rows) {
            let color = Rgb565::new(31, 0, 0);
            let sink = |tri: &ScreenTriangle<S>| got.add(tri, y0, y1);
            let stats = if recorded {
                q.meshlet_triangles(&m, model, color, &mut record, (y0, y1), sink)
            } else {
                q.meshlet_triangles(&m, model, color, &mut plain, (y0, y1), sink)
            };
            let Ok(stats) = stats else { return }; // a documented rejection, as above
            away |= stats.clusters_back_facing > 0;
        }
        match cull {
            Cull::None => assert_eq!(&got, drawn, "the meshlet stage's coverage differs from draw_mesh's"),
            _ if away => {
                assert!(got.front.iter().chain(&got.back).all(|&c| c == 0), "a rejected cluster drew");
                // Rejected rightly: no triangle faces the eye (in f64, with
                // a margin for the paths' rounding of positions and matrices).
                for t in mesh.indices {
                    let c = t.map(|i| clip[usize::from(i)]);
                    let s = c.map(|c| (c[0] / c[3], -c[1] / c[3]));
                    let (a, b) =
                        ((s[1].0 - s[0].0) * (s[2].1 - s[0].1), (s[2].0 - s[0].0) * (s[1].1 - s[0].1));
                    assert!(a - b >= -1e-4 * (a.abs() + b.abs()), "the cone rejected a front face: {s:?}");
                }
            }
            _ => {
                assert_eq!(got.front, drawn.front, "culled: front faces' coverage differs");
                assert!(got.back.iter().all(|&c| c == 0), "culled: a back face drawn");
            }
        }
    }
}

/// The pipeline and frame [`run`] checks: lens, viewport and clip planes.
struct Setup<T: Scalar, const S: u32> {
    p: Pipeline<T, S>,
    proj: Mat4<T>,
    frame: (u32, u32),
    viewport: ClipRect,
}

/// From the bytes after the mesh (all 0 past the input's end: the
/// perspective pipeline `p` of a `w × h` viewport with projection `proj`, the viewport the whole
/// frame, confined as `confined` says): the lens, the viewport's place and
/// the clip planes. `None` where `Pipeline::new` rejects the lens.
fn setup<T: Scalar, const S: u32>(
    inp: &mut Input,
    mut p: Pipeline<T, S>,
    mut proj: Mat4<T>,
    (w, h): (u32, u32),
    (view, near, far, confined): (Mat4<T>, f32, f32, bool),
) -> Option<Setup<T, S>> {
    let t = T::from_f32;
    let raw = |proj: [[f32; 4]; 4], w_ref: f32| -> Option<(Pipeline<T, S>, Mat4<T>)> {
        let proj = Mat4::from_f32(proj);
        Some((Pipeline::new(view, proj, t(w_ref), w, h).ok()?, proj))
    };
    (p, proj) = match inp.u8() % 4 {
        0 => (p, proj),
        // The perspective lens with entries moved by up to ±2 in 1/64 steps.
        1 => {
            let mut m = proj.to_f32();
            for c in &mut m {
                for e in c.iter_mut() {
                    if inp.bool() {
                        *e += f32::from(inp.u8() as i8) / 64.0;
                    }
                }
            }
            raw(m, near)?
        }
        // Orthographic: a box of half-height r (the frame's aspect) from
        // `near` to `far` in front of the eye, w = 1.
        2 => {
            let r = 0.25 + f32::from(inp.u8()) / 16.0;
            let (sx, sy, d) = (h as f32 / (w as f32 * r), 1.0 / r, far - near);
            raw(
                [
                    [sx, 0.0, 0.0, 0.0],
                    [0.0, sy, 0.0, 0.0],
                    [0.0, 0.0, -1.0 / d, 0.0],
                    [0.0, 0.0, -near / d, 1.0],
                ],
                1.0,
            )?
        }
        _ => raw([(); 4].map(|()| [(); 4].map(|()| coord(inp))), inp.pick(&[near, 1.0]))?,
    };
    let mut frame = (w, h);
    let mut viewport = ClipRect::new(0, 0, w as i32, h as i32);
    if inp.bool() {
        // A frame of its own size; the viewport placed in it, off its
        // edges or inside it, and confined (`with_origin`).
        frame = (1 + u32::from(inp.u8() % 96), 1 + u32::from(inp.u8() % 96));
        let (x, y) = (i32::from(inp.u8() as i8) / 2, i32::from(inp.u8() as i8) / 2);
        p = p.with_origin(x, y);
        viewport = ClipRect::new(x, y, x + w as i32, y + h as i32);
    } else {
        p.clip = match inp.u8() % 4 {
            0 | 1 => p.clip,
            2 => p.clip.with_guard_band(1.0 + f32::from(inp.u8()) / 64.0),
            _ => ClipPlanes::for_viewport(w, h, S),
        };
        if confined {
            p = p.confined();
        }
    }
    if inp.bool() {
        p.clip = p.clip.with_far(false);
    }
    if inp.bool() {
        p.clip = p.clip.with_w_min(inp.pick(&[1.0e-9f32, 1.0e-3, 0.1, 1.0]));
    }
    Some(Setup { p, proj, frame, viewport })
}
