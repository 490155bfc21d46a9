//! Tests of [`super`]: the stack cache against the per-corner path.

use super::*;
use crate::geometry::pipeline::PerVertex;
use crate::light::Lighting;
use crate::math::{Fx, transform};
use crate::mesh::{icosphere, torus};
use embedded_graphics_core::pixelcolor::Rgb565;

type Bins = heapless::Vec<ScreenTriangle<4>, 1200>;

/// [`Pipeline::draw_valid_mesh`] (its vertices through an 8-entry cache
/// on the stack, chunk by chunk) and the empty cache
/// (`VertexCache<T, S, 0>`) give the per-corner path's triangles,
/// in order, and its counts, and so does [`Pipeline::mesh_into`] with
/// a colour per vertex: over a sphere and a torus turned through
/// the view, some through the near plane (clipped), both shadings,
/// whole frames and bands, `f32` and `Fx`.
fn stack_cache_is_per_corner<T: Scalar>() {
    let (mut sp, mut sn, mut si) = ([[0.0; 3]; 162], [[0.0; 3]; 162], [[0; 3]; 320]);
    let (mut tp, mut tn, mut ti) = ([[0.0; 3]; 96], [[0.0; 3]; 96], [[0; 3]; 192]);
    let meshes = [
        icosphere(2, &mut sp, &mut sn, &mut si).unwrap(),
        torus(12, 8, 1.0, 0.35, &mut tp, &mut tn, &mut ti).unwrap(),
    ];
    let f = T::from_f32;
    let view = transform::look_at(
        Vec3::new(f(0.0), f(0.8), f(3.2)),
        Vec3::new(f(0.0), f(0.0), f(0.0)),
        Vec3::new(f(0.0), f(1.0), f(0.0)),
    )
    .unwrap();
    let light = Lighting::new(f(0.2), Vec3::new(f(-0.4), f(0.7), f(0.6)), f(0.8)).with_specular(f(0.5), 16);
    let base = Pipeline::<T, 4>::perspective(view, f(0.9), f(1.0), f(20.0), 160, 120).unwrap();
    let base = base.with_lighting(light);
    let (mut a, mut b) = (Bins::new(), Bins::new());
    let vertex_colors: [Rgb565; 162] =
        core::array::from_fn(|k| Rgb565::new((k * 5 % 32) as u8, (k * 7 % 64) as u8, (k * 3 % 32) as u8));
    let (mut emitted, mut clipped) = (0, 0);
    for mesh in &meshes {
        let mesh = ValidMesh::new(*mesh).unwrap();
        for i in 0..16 {
            let t = i as f32 * 0.4;
            // From well inside the view to across the near plane.
            let model = transform::translation(Vec3::new(f(0.3 * t.sin()), f(0.0), f(0.16 * i as f32)))
                * transform::rotation_y(f(t))
                * transform::rotation_x(f(0.7 * t));
            for shade in [Shade::Gouraud, Shade::Flat] {
                for rows in [None, Some((0, 15)), Some((40, 47)), Some((-20, 3))] {
                    let mut p = base;
                    (p.shade, p.rows) = (shade, rows);
                    a.clear();
                    b.clear();
                    let color = Rgb565::new(25, 40, 10);
                    let sa = p.valid_mesh_into::<super::super::tier::ExactTier, _, _>(
                        &mesh,
                        &model,
                        color,
                        &Uniform,
                        |tri| a.push(tri).map_err(|_| Error::CapacityExceeded { needed: 0, capacity: 0 }),
                    );
                    let sb = p.draw_valid_mesh(&mesh, &model, color, &mut b);
                    assert_eq!(sa, sb, "{i} {shade:?} {rows:?}");
                    assert!(a == b, "{i} {shade:?} {rows:?}: {} vs {} triangles", a.len(), b.len());
                    // The empty cache: the per-corner path itself.
                    b.clear();
                    let empty = &mut VertexCache::<T, 4, 0>::new();
                    let sc = p.draw_valid_mesh_cached(&mesh, &model, color, empty, &mut b);
                    assert!(sa == sc && a == b, "{i} {shade:?} {rows:?}: empty cache");
                    // A colour per vertex, through the stack cache (the
                    // `view3d` front's path) and per corner.
                    a.clear();
                    b.clear();
                    let pv = PerVertex(&vertex_colors);
                    let sa = p.valid_mesh_into::<super::super::tier::ExactTier, _, _>(
                        &mesh,
                        &model,
                        color,
                        &pv,
                        |tri| a.push(tri).map_err(|_| Error::CapacityExceeded { needed: 0, capacity: 0 }),
                    );
                    let sb = p.mesh_into(&mesh, &model, color, &pv, &mut NoMemo, |tri| {
                        b.push(tri).map_err(|_| Error::CapacityExceeded { needed: 0, capacity: 0 })
                    });
                    assert!(sa == sb && a == b, "{i} {shade:?} {rows:?}: per-vertex colours");
                    let s = sa.unwrap();
                    (emitted, clipped) = (emitted + s.emitted, clipped + s.clipped);
                }
            }
        }
    }
    assert!(emitted > 5_000 && clipped > 1_000, "{emitted} emitted, {clipped} clipped");
}

#[test]
fn stack_cache_is_per_corner_f32() {
    stack_cache_is_per_corner::<f32>();
}

#[test]
fn stack_cache_is_per_corner_fx() {
    stack_cache_is_per_corner::<Fx>();
}

/// The stack cache of [`Pipeline::draw_valid_mesh`] is as small as its
/// docs say (about 480 bytes with its slot table).
#[test]
fn stack_cache_size() {
    let size = |c: usize, t: usize| c * SMALL_SLOTS + t;
    let table = core::mem::size_of::<SmallTable>();
    let f = size(core::mem::size_of::<Cached<f32, 4>>(), table);
    let x = size(core::mem::size_of::<Cached<Fx, 4>>(), table);
    assert!((440..=520).contains(&f) && (440..=520).contains(&x), "{f} {x}");
}

/// A chunk ends when its triangle list is full (`2·C` triangles for `C`
/// slots), not only when its slots are: a tetrahedron whose faces each
/// repeat 140 times (560 triangles over 4 vertices) gives the per-corner
/// path's triangles and counts through the stack cache (8 slots, chunks of
/// 16 triangles) and through a caller's cache of 3 (a chunk per run of one
/// face, 128 triangles at most).
#[test]
fn chunks_end_when_their_triangle_list_is_full() {
    let s = 1.0 / 3.0f32.sqrt();
    let positions = [[s, s, s], [s, -s, -s], [-s, s, -s], [-s, -s, s]];
    let faces = [[0u16, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
    let indices: [[u16; 3]; 560] = core::array::from_fn(|t| faces[t / 140]);
    let mesh = ValidMesh::new(Mesh::new(&positions, &positions, &indices, ([0.0; 3], 1.0))).unwrap();
    let view =
        transform::look_at(Vec3::new(0.4, 0.9, 3.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    let p = Pipeline::<f32, 4>::perspective(view.unwrap(), 0.9, 1.0, 20.0, 160, 120).unwrap();
    let model = transform::rotation_y(0.5);
    let color = Rgb565::new(25, 40, 10);
    let (mut a, mut b) = (Bins::new(), Bins::new());
    let sa =
        p.valid_mesh_into::<super::super::tier::ExactTier, _, _>(&mesh, &model, color, &Uniform, |tri| {
            a.push(tri).map_err(|_| Error::CapacityExceeded { needed: 0, capacity: 0 })
        });
    assert!(a.len() >= 280, "{} triangles", a.len());
    let sb = p.draw_valid_mesh(&mesh, &model, color, &mut b);
    assert!(sa == sb && a == b, "stack cache: {} vs {} triangles", a.len(), b.len());
    b.clear();
    let sc = p.draw_valid_mesh_cached(&mesh, &model, color, &mut VertexCache::<f32, 4, 3>::new(), &mut b);
    assert!(sa == sc && a == b, "cache of 3: {} vs {} triangles", a.len(), b.len());
}
