//! Closed meshes through the 3D pipeline have no cracks: a tetrahedron, a
//! deformed cube or a box, either with its faces cut into up to 10 × 10
//! quads (any points, consistently wound faces: a closed surface, folded,
//! flat or degenerate as the points make it; `closed/surface.rs`) under a
//! fuzzed camera, lens, model matrix, frame size, band height and clipping, on the `f32`
//! and `Fx` paths at `S ∈ {0, 4, 8}`, drawn band by band into bins with
//! culling off. Check: every pixel centre of the frame is covered by as
//! many front faces as back faces (`tests/bench_mesh/closed.rs` says why:
//! the top-left rule samples each centre as if moved by an infinitesimal,
//! and a closed surface's image covers any point as often each way). Then
//! the same mesh as clusters (one, or several for a cut cube) through the
//! meshlet stage band by band, whole and cluster by cluster, with culling
//! off and on (`closed/meshlets.rs`).
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
//!
//! The cuts and the box come from the last bytes read: inputs written
//! before they were added mostly end earlier, read 0 there and replay the
//! plain cube.
#![no_main]

use libfuzzer_sys::fuzz_target;
use microraster::ClipRect;
use microraster::clip3d::ClipPlanes;
use microraster::edge::Cull;
use microraster::math::{Mat4, Scalar, Vec3, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::Pipeline;
use microraster_fuzz::{Input, clip_matrix_f64, is_f32};

#[path = "closed/meshlets.rs"]
mod meshlets;
#[path = "closed/surface.rs"]
mod surface;

use meshlets::{draw_mesh, meshlets_agree};
use surface::{CUBE, MAX_CUTS, TETRAHEDRON, subdivided_cube};

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
    let mut positions: Vec<[f32; 3]> =
        (0..if cube { 8 } else { 4 }).map(|_| [(); 3].map(|()| coord(inp))).collect();
    let indices: &[[u16; 3]] = if cube { &CUBE } else { &TETRAHEDRON };
    let model = if inp.bool() {
        Mat4::IDENTITY
    } else {
        Mat4::from_f32(core::array::from_fn(|_| [(); 4].map(|()| coord(inp))))
    };
    let Some(Setup { mut p, proj, frame, viewport }) =
        setup(inp, p, proj, (w, h), (view, near, far, confined))
    else {
        return;
    };
    p.cull = Cull::None;
    let recorded = inp.bool();
    // The cube's faces cut into n × n quads (several clusters); or the
    // cube a box, the one spanned by its first and last corners (flat
    // faces: clusters with narrow normal cones).
    let cuts = 1 + usize::from(inp.u8()) % MAX_CUTS;
    if cube && inp.bool() {
        let (lo, hi) = (positions[0], positions[7]);
        for (c, q) in positions.iter_mut().enumerate() {
            *q = core::array::from_fn(|a| if c >> a & 1 == 1 { hi[a] } else { lo[a] });
        }
    }
    let (positions, indices) =
        if cube && cuts > 1 { subdivided_cube(&positions, cuts) } else { (positions, indices.to_vec()) };
    let mesh = Mesh::new(&positions, &[], &indices, bounding_sphere(&positions));

    // The premise, in f64, with each coordinate's magnitude bound for the
    // rounding margin.
    let (mvp, size) = clip_matrix_f64(proj, p.view(), model);
    let fx = !is_f32::<T>();
    let w_min = f64::from(p.clip.w_min());
    let homogeneous = |q: &[f32; 3]| [f(t(q[0])), f(t(q[1])), f(t(q[2])), 1.0];
    let row = |m: &[[f64; 4]; 4], r: usize, hq: [f64; 4], a: fn(f64) -> f64| {
        (0..4).map(|k| m[k][r] * a(hq[k])).sum::<f64>()
    };
    // Each vertex's clip position and each clip coordinate's magnitude
    // bound, and from that how far the path's rounding can move the
    // coordinate: the premise's and the cone check's.
    let (clip, magnitude): (Vec<[f64; 4]>, Vec<[f64; 4]>) = positions
        .iter()
        .map(|q| {
            let hq = homogeneous(q);
            (
                core::array::from_fn(|r| row(&mvp, r, hq, |x| x)),
                core::array::from_fn(|r| row(&size, r, hq, f64::abs)),
            )
        })
        .unzip();
    let slack = |s: f64| if fx { 0.05 + 2e-3 * s } else { 1e-4 * s };
    let margin: Vec<[f64; 4]> = magnitude.iter().map(|m| m.map(slack)).collect();
    let clear = clip.iter().zip(&magnitude).all(|(c, m)| {
        let (z, wc) = (c[2], c[3]);
        let s = m[2] + m[3];
        let tol = slack(s);
        // The clipper discards a triangle with a coordinate beyond ±2^64
        // (documented): the mesh would open there.
        let in_range = m.iter().all(|&v| v < 2f64.powi(63));
        let inside_far = !p.clip.far() || wc - z > tol;
        s.is_finite() && in_range && (!fx || s < 4000.0) && z > tol && inside_far && wc > w_min + tol
    });
    if !clear {
        return;
    }

    let (fw, fh) = (frame.0 as usize, frame.1 as usize);
    let Some(drawn) = draw_mesh(&p, &mesh, &model, (fw, fh, rows)) else {
        return; // a documented rejection (Fx range): nothing to check
    };
    for (i, (f, b)) in drawn.front.iter().zip(&drawn.back).enumerate() {
        let (x, y) = ((i % fw) as i32, (i / fw) as i32);
        if viewport.contains(x, y) {
            assert_eq!(f, b, "pixel ({x}, {y}): {f} front, {b} back faces");
        } else {
            // Only a confined viewport smaller than the frame leaves any.
            assert_eq!((f, b), (&0, &0), "pixel ({x}, {y}) outside the viewport {viewport:?} covered");
        }
    }
    meshlets_agree(p, mesh, &model, (rows, recorded), (&clip, &margin), &drawn);
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
