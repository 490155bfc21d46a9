//! Bins and vertex caches too small: the error says how many entries the
//! call needed, and the bins keep exactly what they held before the call.

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::Error;
use microraster::fragment::FragTriangle;
use microraster::math::{Fx, Mat4, Scalar, Vec3, transform};
use microraster::mesh::{ValidMesh, icosphere};
use microraster::pipeline::{Pipeline, VertexCache};
use microraster::raster3d::ScreenTriangle;

/// Bins of every test: the sphere's front half (about 40 triangles) fits.
const CAP: usize = 64;
const RED: Rgb565 = Rgb565::new(31, 0, 0);

/// A pipeline looking at a unit icosphere of 42 vertices (its arrays leaked:
/// a few hundred bytes per test run).
fn setup<T: Scalar>() -> (Pipeline<T, 4>, ValidMesh<'static>) {
    let p = Box::leak(Box::new([[0.0; 3]; 42]));
    let n = Box::leak(Box::new([[0.0; 3]; 42]));
    let i = Box::leak(Box::new([[0; 3]; 80]));
    let mesh = icosphere(1, p, n, i).unwrap();
    let c = |v: [f32; 3]| Vec3::new(T::from_f32(v[0]), T::from_f32(v[1]), T::from_f32(v[2]));
    let eye = transform::look_at(c([0.0, 0.0, 4.0]), c([0.0; 3]), c([0.0, 1.0, 0.0])).unwrap();
    let f = T::from_f32;
    let pipeline = Pipeline::<T, 4>::perspective(eye, f(0.8), f(1.0), f(10.0), 64, 64).unwrap();
    (pipeline, ValidMesh::new(mesh).unwrap())
}

/// Runs `draw` on bins pre-filled with `pre` copies of `filler`, for every
/// `pre` around the point where the mesh's `emitted` triangles stop fitting.
fn check_bins<X: Copy + PartialEq + core::fmt::Debug>(
    what: &str,
    emitted: usize,
    filler: X,
    mut draw: impl FnMut(&mut heapless::Vec<X, CAP>) -> Result<u32, Error>,
) {
    assert!(emitted > 10 && emitted < CAP, "{what}: {emitted} triangles");
    for pre in [0, CAP - emitted - 1, CAP - emitted, CAP - emitted + 1, CAP - 3, CAP] {
        let mut bins = heapless::Vec::<X, CAP>::new();
        for _ in 0..pre {
            bins.push(filler).unwrap();
        }
        let r = draw(&mut bins);
        if pre + emitted <= CAP {
            assert_eq!(r, Ok(emitted as u32), "{what}: {pre} pre-filled");
            assert_eq!(bins.len(), pre + emitted);
        } else {
            assert_eq!(
                r,
                Err(Error::CapacityExceeded { needed: pre + emitted, capacity: CAP }),
                "{what}: {pre}"
            );
            // No partial mesh: exactly the entries held before the call.
            assert_eq!(bins.len(), pre, "{what}: {pre} pre-filled");
            assert!(bins.iter().all(|&x| x == filler));
        }
    }
}

fn every_path<T: Scalar>() {
    let (pipeline, mesh) = setup::<T>();
    let model = Mat4::<T>::IDENTITY;
    // The reference count: the mesh into bins with room for everything.
    let mut all = heapless::Vec::<ScreenTriangle<4>, 128>::new();
    let emitted = pipeline.draw_valid_mesh(&mesh, &model, RED, &mut all).unwrap().emitted as usize;
    assert_eq!(all.len(), emitted);
    let filler = all[0];

    check_bins("draw_mesh", emitted, filler, |b| {
        pipeline.draw_mesh(mesh.mesh(), &model, RED, b).map(|s| s.emitted)
    });
    check_bins("draw_valid_mesh", emitted, filler, |b| {
        pipeline.draw_valid_mesh(&mesh, &model, RED, b).map(|s| s.emitted)
    });
    let mut cache = Box::new(VertexCache::<T, 4, 42>::new());
    check_bins("draw_valid_mesh_cached", emitted, filler, |b| {
        pipeline.draw_valid_mesh_cached(&mesh, &model, RED, &mut cache, b).map(|s| s.emitted)
    });
    let frag = FragTriangle { tri: filler, varyings: [[7]; 3] };
    check_bins("draw_mesh_varying", emitted, frag, |b| {
        pipeline.draw_mesh_varying(&mesh, &model, RED, |v| [i32::from(v.index)], b).map(|s| s.emitted)
    });

    // A vertex cache one short: chunks, the same bins as every path.
    let mut small = Box::new(VertexCache::<T, 4, 41>::new());
    check_bins("draw_valid_mesh_cached in chunks", emitted, filler, |b| {
        pipeline.draw_valid_mesh_cached(&mesh, &model, RED, &mut small, b).map(|s| s.emitted)
    });
    // A cache below one triangle: needs 3, bins untouched.
    let mut two = Box::new(VertexCache::<T, 4, 2>::new());
    let mut bins = heapless::Vec::<ScreenTriangle<4>, CAP>::new();
    bins.push(filler).unwrap();
    let r = pipeline.draw_valid_mesh_cached(&mesh, &model, RED, &mut two, &mut bins);
    assert_eq!(r, Err(Error::CapacityExceeded { needed: 3, capacity: 2 }));
    assert_eq!(bins.as_slice(), &[filler]);
}

#[test]
fn full_bins_say_how_many_were_needed_and_keep_what_they_held() {
    every_path::<f32>();
    every_path::<Fx>();
}

#[test]
fn capacity_error_text_names_both_counts() {
    let e = Error::CapacityExceeded { needed: 1200, capacity: 1024 };
    assert_eq!(e.to_string(), "buffer holds 1024 entries, 1200 needed");
}
