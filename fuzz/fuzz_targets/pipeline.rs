//! The 3D pipeline end to end: matrices, vertices and settings from the
//! fuzzer (NaN, ±inf, ±f32::MAX, subnormals, huge and tiny values among
//! them) → `Pipeline` → bins → `Triangles3d`, on the `f32` and `Fx`
//! paths, `S ∈ {0, 4, 8}`, every depth format, both interpolations and band
//! heights 1 and 64. Checks:
//! * no panic and no arithmetic overflow (overflow checks are on);
//! * constructors fail with the documented typed errors (invalid viewport
//!   size, non-finite camera parameters), and successful ones give finite
//!   matrices; `draw_mesh` fails only as documented (f32
//!   `CoordinateOutOfRange` only for a clip coordinate near or beyond
//!   ±2^64, by an f64 computation);
//! * every binned triangle has non-zero snapped area, the winding its cull
//!   mode keeps, and touches the requested rows;
//! * nothing from behind the eye: a mesh whose every vertex has clip
//!   `w < 0` (by an f64 computation, with a margin) draws nothing;
//! * every frame pixel is sent exactly once, the image is the same for band
//!   heights 1 and 64, and no pixel is drawn outside the viewport widened by
//!   the guard band (see `STRICT_VIEWPORT`).
#![no_main]

#[path = "pipeline/checks.rs"]
mod checks;
#[path = "pipeline/frame.rs"]
mod frame;
#[path = "pipeline/inputs.rs"]
mod inputs;

use checks::{all_behind_eye, check_ctor, clip_beyond_range};
use embedded_graphics_core::pixelcolor::Rgb565;
use frame::render_any;
use inputs::{matrix, small, vec3};
use libfuzzer_sys::fuzz_target;
use microraster::Error;
use microraster::clip3d::ClipPlanes;
use microraster::depth::{DepthState, DepthTest};
use microraster::edge::Cull;
use microraster::light::{Lighting, Viewer};
use microraster::math::{Mat4, Scalar, Vec3, transform};
use microraster::mesh::{Mesh, bounding_sphere};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::ScreenTriangle;
use microraster_fuzz::{Input, is_f32, signed_area2};

/// Whether drawn pixels must lie inside the viewport itself. A pipeline
/// that is not `confined` (or given an origin) clips x/y at the guard band
/// and the renderer scissors to the frame, so a viewport smaller than the
/// frame is drawn up to the guard band by design (docs/limits.md). The
/// target checks the guard-band bound, which holds for every pipeline.
const STRICT_VIEWPORT: bool = false;

const FW: usize = 64;
const BINS: usize = 24;

fuzz_target!(|data: &[u8]| {
    microraster_fuzz::each_path!(&mut Input::new(data), run);
});

fn run<T: Scalar, const S: u32>(inp: &mut Input) {
    let dims = [0u32, 1, 2, 3, 7, 16, 40, 63, 64, 65, 100, 4095, 4096, 4097, u32::MAX];
    let pick_dim =
        |inp: &mut Input| if inp.u8().is_multiple_of(4) { inp.u32() % 5000 } else { inp.pick(&dims) };
    let (width, height) = (pick_dim(inp), pick_dim(inp));
    let size_ok = (1..=4096).contains(&width) && (1..=4096).contains(&height);

    let view = match inp.u8() % 4 {
        0 => Mat4::IDENTITY,
        1 | 2 => {
            let ((e, eye), (t, target), (u, up)) = (vec3::<T>(inp), vec3::<T>(inp), vec3::<T>(inp));
            let r = transform::look_at(eye, target, up);
            let all: Vec<f32> = [e, t, u].concat();
            check_ctor("look_at", &all, &r);
            match r {
                Ok(m) => m,
                Err(_) => return,
            }
        }
        _ => matrix(inp),
    };
    let ratios = [1.0f32, 1.0001, 2.0, 100.0, 1.0e4, 1.0e7, 0.5, -1.0];
    let (p, proj) = match inp.u8() % 3 {
        0 => {
            let (fov, near) = (inp.f32(), inp.f32());
            let fov = if inp.bool() { fov } else { 0.5 + f32::from(inp.u8()) / 100.0 };
            let near =
                if inp.bool() { near } else { inp.pick(&[0.1f32, 1.0, 1.0e-3, 1.0 / 65536.0, 0.0, -1.0]) };
            let far = if inp.bool() { inp.f32() } else { near * inp.pick(&ratios) };
            let inputs = [fov, near, far];
            let r = transform::perspective(
                T::from_f32(fov),
                T::from_f32(1.0),
                T::from_f32(near),
                T::from_f32(far),
            );
            check_ctor("perspective", &inputs, &r);
            let r = Pipeline::<T, S>::perspective(
                view,
                T::from_f32(fov),
                T::from_f32(near),
                T::from_f32(far),
                width,
                height,
            );
            // The same projection the pipeline builds (aspect = width / height).
            let aspect = T::from_f32(width as f32 / height.max(1) as f32);
            let proj =
                transform::perspective(T::from_f32(fov), aspect, T::from_f32(near), T::from_f32(far)).ok();
            if is_f32::<T>() && inputs.iter().any(|v| !v.is_finite()) {
                assert!(r.is_err(), "perspective{inputs:?} accepted");
            }
            if is_f32::<T>() && inputs.iter().all(|v| v.is_finite()) && !(near > 0.0 && far > near) {
                assert!(r.is_err(), "perspective{inputs:?}: near ≤ 0 or far ≤ near accepted");
            }
            // A bad viewport with finite camera input: InvalidFrameSize, as
            // `Pipeline::new` (issue 13).
            if inputs.iter().all(|v| v.is_finite()) && !size_ok {
                assert_eq!(r.as_ref().err(), Some(&Error::InvalidFrameSize), "perspective {width}×{height}");
            }
            (r, proj)
        }
        1 => {
            let v: [f32; 6] = core::array::from_fn(|_| small(inp));
            let r = transform::orthographic(
                T::from_f32(v[0]),
                T::from_f32(v[1]),
                T::from_f32(v[2]),
                T::from_f32(v[3]),
                T::from_f32(v[4]),
                T::from_f32(v[5]),
            );
            check_ctor("orthographic", &v, &r);
            match r {
                Ok(m) => (Pipeline::<T, S>::new(view, m, T::ONE, width, height), Some(m)),
                Err(_) => return,
            }
        }
        _ => {
            let w_ref = inp.f32();
            let m = matrix(inp);
            let r = Pipeline::<T, S>::new(view, m, T::from_f32(w_ref), width, height);
            if r.is_ok() {
                assert!(
                    T::from_f32(w_ref) > T::ZERO && (w_ref.is_finite() || !is_f32::<T>()),
                    "w_ref {w_ref} accepted"
                );
            }
            (r, Some(m))
        }
    };
    let mut p = match p {
        Ok(p) => {
            assert!(size_ok, "viewport {width}×{height} accepted");
            p
        }
        Err(e) => {
            assert!(
                matches!(
                    e,
                    Error::InvalidFrameSize
                        | Error::InvalidParameter(_)
                        | Error::NonFiniteCoordinate
                        | Error::CoordinateOutOfRange
                ),
                "{e:?}"
            );
            if !size_ok {
                assert!(matches!(
                    e,
                    Error::InvalidFrameSize
                        | Error::NonFiniteCoordinate
                        | Error::InvalidParameter(_)
                        | Error::CoordinateOutOfRange
                ));
            }
            return;
        }
    };

    // Settings.
    let origin = match inp.u8() % 4 {
        0 | 1 => (0, 0),
        2 => (i32::from(inp.u8() as i8), i32::from(inp.u8() as i8)),
        _ => (inp.i32(), inp.i32()),
    };
    p = p.with_origin(origin.0, origin.1);
    // `with_origin` clamps the origin to ±MAX_FRAME_DIM (documented).
    let lim = microraster::MAX_FRAME_DIM as i32;
    let origin = (origin.0.clamp(-lim, lim), origin.1.clamp(-lim, lim));
    match inp.u8() % 6 {
        0 => p.clip = p.clip.with_guard_band(inp.f32()),
        1 => p.clip = p.clip.with_w_min(inp.f32()),
        2 => p.clip = p.clip.with_far(false),
        3 => p.clip = ClipPlanes::for_viewport(width, height, S),
        _ => {}
    }
    p.cull = inp.pick(&[Cull::None, Cull::Clockwise, Cull::CounterClockwise]);
    p.shade = if inp.bool() { Shade::Flat } else { Shade::Gouraud };
    let mut light_error = None;
    if inp.bool() {
        let (_, dir) = vec3::<T>(inp);
        let l = Lighting::new(T::from_f32(small(inp)), dir, T::from_f32(small(inp)));
        let l = if inp.bool() { l.with_specular(T::from_f32(small(inp)), u32::from(inp.u8())) } else { l };
        let l = l.with_viewer(inp.pick(&[Viewer::Local, Viewer::Infinite]));
        // The vertex stage reports exactly `validate`'s error (issue 13).
        light_error = l.validate().err();
        assert!(
            matches!(light_error, None | Some(Error::NonFiniteCoordinate | Error::InvalidParameter(_))),
            "Lighting::validate: undocumented error {light_error:?}"
        );
        p = p.with_lighting(l);
    }
    if inp.u8().is_multiple_of(4) {
        let a = i32::from(inp.u8()) - 20;
        p.rows = Some((a, a + i32::from(inp.u8() as i8)));
    }

    // The mesh: 3–6 positions, 1–4 triangles, maybe normals, a sphere that
    // is exact, loose or wrong.
    let n = 3 + usize::from(inp.u8() % 4);
    let positions: Vec<[f32; 3]> = (0..n).map(|_| [small(inp), small(inp), small(inp)]).collect();
    let normals: Vec<[f32; 3]> =
        if inp.bool() { (0..n).map(|_| [small(inp), small(inp), small(inp)]).collect() } else { vec![] };
    let tris = 1 + usize::from(inp.u8() % 4);
    let indices: Vec<[u16; 3]> = (0..tris)
        .map(|_| {
            let idx =
                |inp: &mut Input| u16::from(inp.u8()) % (n as u16 + u16::from(inp.u8().is_multiple_of(16)));
            [idx(inp), idx(inp), idx(inp)]
        })
        .collect();
    let sphere = match inp.u8() % 4 {
        0 => ([inp.f32(), inp.f32(), inp.f32()], inp.f32()),
        1 => ([0.0; 3], 1.0e6),
        _ => bounding_sphere(&positions),
    };
    let mesh = Mesh::new(&positions, &normals, &indices, sphere);
    let model = match inp.u8() % 5 {
        0 | 1 => Mat4::IDENTITY,
        2 => transform::rotation_y(T::from_f32(inp.f32())),
        3 => transform::scaling(Vec3::from_f32([small(inp), small(inp), small(inp)])),
        _ => matrix(inp),
    };
    let color = Rgb565::new(inp.u8(), inp.u8(), inp.u8());
    let mut bins = heapless::Vec::<ScreenTriangle<S>, BINS>::new();
    let bad_index = indices.iter().flatten().any(|&i| usize::from(i) >= n);
    let valid = mesh.validate();
    assert!(!bad_index || matches!(valid, Err(Error::InvalidMesh(_))), "bad index passed validate");
    match p.draw_mesh(&mesh, &model, color, &mut bins) {
        Ok(st) => {
            assert_eq!(valid, Ok(()), "draw_mesh accepted a mesh validate rejects");
            assert_eq!(light_error, None, "draw_mesh accepted lighting validate rejects");
            assert_eq!(st.emitted as usize, bins.len())
        }
        // draw_mesh validates the mesh first: exactly validate's error.
        Err(e) if valid.is_err() => assert_eq!(valid, Err(e), "draw_mesh error {e:?}, validate's {valid:?}"),
        // Then the lighting: exactly its `validate` error.
        Err(e) if light_error.is_some() => {
            assert_eq!(light_error, Some(e), "draw_mesh error {e:?} with bad lighting")
        }
        // Fx: a coordinate 16.16 cannot hold (issue 13); f32: a clip
        // coordinate beyond the clipper's ±2^64 (issue 60).
        Err(Error::CoordinateOutOfRange) => assert!(
            !is_f32::<T>()
                || proj.is_some_and(|proj| clip_beyond_range(&p, proj, &model, &positions, &indices)),
            "f32 draw_mesh: CoordinateOutOfRange within the clipper's range"
        ),
        // A model with a NaN or infinite entry (a NaN angle, an overflowing
        // matrix) is NonFiniteCoordinate, not a singular model (issue 63).
        Err(Error::NonFiniteCoordinate) if !model.cols.iter().flatten().all(|v| v.is_finite()) => {}
        Err(e @ (Error::InvalidMesh(_) | Error::NonFiniteCoordinate)) => {
            panic!("draw_mesh error {e:?} without validate's")
        }
        // Full bins: the count needed, and no partial mesh left.
        Err(Error::CapacityExceeded { needed, capacity }) => {
            assert!(capacity == BINS && needed > BINS, "needed {needed} of {capacity}");
            assert!(bins.is_empty(), "{} triangles left after CapacityExceeded", bins.len());
        }
        Err(Error::InvalidParameter(_)) => {}
        Err(e) => panic!("draw_mesh: undocumented error {e:?}"),
    }

    for t in &bins {
        let det = signed_area2(t);
        assert_ne!(det, 0, "zero-area triangle binned");
        match p.cull {
            Cull::Clockwise => assert!(det < 0, "clockwise triangle binned with Cull::Clockwise"),
            Cull::CounterClockwise => assert!(det > 0, "counter-clockwise triangle binned"),
            Cull::None => {}
        }
        if let Some((y0, y1)) = p.rows {
            let (lo, hi) = t.rows();
            assert!(lo <= y1 && hi >= y0, "triangle rows {lo}..={hi} miss the requested {y0}..={y1}");
        }
        assert!(t.v.iter().all(|v| v.inv_w >= 1));
    }

    // Nothing from behind the eye.
    if !bad_index && proj.is_some_and(|proj| all_behind_eye(&p, proj, &model, &positions, &indices)) {
        assert!(bins.is_empty(), "a mesh entirely behind the eye produced {} triangles", bins.len());
    }

    // Render: three frames (two backgrounds, two band heights).
    let fh = 1 + usize::from(inp.u8() % 64);
    let (fmt, interp) = (inp.u8() % 5, inp.bool());
    let state = inp.pick(&[
        DepthState::LESS_WRITE,
        DepthState::LESS_EQUAL_WRITE,
        DepthState::READ_ONLY,
        DepthState::ALWAYS_WRITE,
        DepthState::new(DepthTest::Greater, true),
        DepthState::new(DepthTest::NotEqual, true),
    ]);
    let (bg1, bg2) = (Rgb565::new(1, 2, 3), Rgb565::new(30, 60, 29));
    let a = render_any::<S, 1>(&bins, fh, bg1, state, fmt, interp);
    // FUZZ_STATS=1 prints how much each input draws (to check the seeds).
    static STATS: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    if *STATS.get_or_init(|| std::env::var_os("FUZZ_STATS").is_some()) {
        let b = render_any::<S, 1>(&bins, fh, bg2, state, fmt, interp);
        let drawn = a.iter().zip(&b).filter(|(x, y)| x == y).count();
        eprintln!("STATS bins={} drawn={drawn}", bins.len());
    }
    let b = render_any::<S, 1>(&bins, fh, bg2, state, fmt, interp);
    let c = render_any::<S, 64>(&bins, fh, bg1, state, fmt, interp);
    assert!(a == c, "the image depends on the band height");
    let g = f64::from(p.clip.guard_band());
    let (w, h) = (f64::from(width), f64::from(height));
    let (ox, oy) = (f64::from(origin.0), f64::from(origin.1));
    let (gx, gy) =
        if STRICT_VIEWPORT { (0.0, 0.0) } else { ((g - 1.0) * w / 2.0 + 1.0, (g - 1.0) * h / 2.0 + 1.0) };
    for y in 0..fh {
        for x in 0..FW {
            let i = y * FW + x;
            if a[i] == b[i] {
                // Drawn: the centre must be inside the (widened) viewport.
                let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                assert!(
                    cx > ox - gx && cx < ox + w + gx && cy > oy - gy && cy < oy + h + gy,
                    "pixel ({x}, {y}) drawn outside viewport {origin:?} {width}×{height} (guard band {g})"
                );
            }
        }
    }
}
