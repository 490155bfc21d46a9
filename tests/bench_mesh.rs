//! The meshlet benchmark mesh (`examples/common/knot_mesh.rs`): the
//! committed file is the generator's output (`examples/gen_bench_mesh.rs`),
//! and the mesh is what the benchmarks need — valid, closed, consistently
//! wound, about 10,000 vertices and 20,000 triangles, full compact clusters,
//! 1–2 pixels per triangle with the standard camera. `closed` and `placed`
//! check that its image (and the standard scene's) has no cracks: every
//! pixel centre covered as often by front as by back faces, in both accuracy
//! tiers; `fast_frames` compares the knot's fast frames with the exact ones.

#[path = "bench_mesh/closed.rs"]
mod closed;
#[path = "bench_mesh/fast_frames.rs"]
mod fast_frames;
#[path = "integration/framebuffer.rs"]
#[allow(dead_code)]
mod framebuffer;
#[path = "integration/fast_tier/frames.rs"]
mod frames;
#[path = "../examples/gen_bench_mesh.rs"]
#[allow(dead_code)]
mod gen_bench_mesh;
#[path = "../examples/common/knot_mesh.rs"]
mod knot_mesh;
#[path = "bench_mesh/placed.rs"]
mod placed;

use std::collections::HashSet;

use gen_bench_mesh::{ALONG, KNOT_R, SCALE, TUBE};
use knot_mesh::{KNOT, KNOT_FX, KNOT_INDICES, KNOT_MESH, VALID_KNOT, VALID_KNOT_FX};
use microraster::math::{Fx, Scalar};
use microraster::mesh::ValidMeshletMesh;

#[test]
fn committed_file_equals_the_generator_output() {
    let src = gen_bench_mesh::rust_source(&gen_bench_mesh::knot().unwrap());
    // No diff of 1 MB on failure: just how to fix it.
    assert!(
        src == include_str!("../examples/common/knot_mesh.rs"),
        "stale: cargo run --example gen_bench_mesh > examples/common/knot_mesh.rs"
    );
}

#[test]
fn knot_is_valid_closed_and_wound_counter_clockwise_from_outside() {
    assert_eq!(ValidMeshletMesh::new(KNOT), Ok(VALID_KNOT));
    assert_eq!(KNOT_MESH.check_winding(), Ok(()));
    let (nv, nt) = (KNOT_MESH.vertex_count(), KNOT_MESH.triangle_count());
    assert!(nt >= 20_000 && (9_000..=11_000).contains(&nv), "{nv} {nt}");
    // Closed 2-manifold, consistently oriented: every directed edge once,
    // and its reverse too.
    let mut edges = HashSet::new();
    for &[a, b, c] in KNOT_INDICES.iter() {
        for e in [(a, b), (b, c), (c, a)] {
            assert!(edges.insert(e), "edge {e:?} twice");
        }
    }
    assert!(edges.iter().all(|&(a, b)| edges.contains(&(b, a))));
    // Outward: positive enclosed volume.
    let p = |i: u16| KNOT_MESH.positions[usize::from(i)].map(f64::from);
    let volume: f64 = KNOT_INDICES
        .iter()
        .map(|&[a, b, c]| {
            let (a, b, c) = (p(a), p(b), p(c));
            a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0])
        })
        .sum::<f64>()
        / 6.0;
    assert!(volume > 0.0, "{volume}");
    for n in KNOT_MESH.normals {
        let len = n.iter().map(|&x| f64::from(x).powi(2)).sum::<f64>().sqrt();
        assert!((len - 1.0).abs() < 1e-4, "{n:?}");
    }
}

/// Clusters are full (≥ 60 of 64 vertices for 90 % of them) and small: the
/// mean cluster radius is below 1/6 of the mesh's bounding radius.
#[test]
fn knot_clusters_are_full_and_small_and_match_the_indices() {
    let n = KNOT.meshlets.len() as f64;
    let full = KNOT.meshlets.iter().filter(|c| c.vertex_count >= 60).count() as f64;
    assert!(full / n >= 0.9, "{full} of {n}");
    let mean_radius = KNOT.meshlets.iter().map(|c| f64::from(c.sphere.1)).sum::<f64>() / n;
    assert!(mean_radius < f64::from(KNOT_MESH.bounding_sphere.1) / 6.0, "{mean_radius}");
    let mut expanded = Vec::new();
    for c in KNOT.meshlets {
        let local = &KNOT.vertices[c.vertex_offset as usize..][..usize::from(c.vertex_count)];
        for t in &KNOT.triangles[c.triangle_offset as usize..][..usize::from(c.triangle_count)] {
            expanded.push(t.map(|k| local[usize::from(k)]));
        }
    }
    assert_eq!(expanded, KNOT_INDICES);
}

/// The tube does not pass through itself: centre-line points more than 20
/// samples apart (an arc of about 1.5, four tube radii) are more than two
/// (ridged) tube radii apart.
#[test]
fn knot_tube_does_not_intersect_itself() {
    let tau = core::f32::consts::TAU;
    let c: Vec<[f32; 3]> =
        (0..ALONG).map(|i| gen_bench_mesh::centre_line(tau * i as f32 / ALONG as f32).0).collect();
    let a_max = TUBE.0 * (1.0 + TUBE.1);
    let mut min = f32::INFINITY;
    for i in 0..ALONG {
        for j in i + 20..ALONG {
            if ALONG - (j - i) >= 20 {
                let d = (0..3).map(|k| (c[i][k] - c[j][k]).powi(2)).sum::<f32>().sqrt();
                min = min.min(d);
            }
        }
    }
    assert!(min > 2.0 * a_max * 1.2, "{min} vs tube {a_max} (torus {KNOT_R:?})");
}

#[test]
fn knot_covers_one_to_two_pixels_per_front_facing_triangle() {
    let (ppt, front) = gen_bench_mesh::pixels_per_triangle(&KNOT_MESH);
    assert!((1.0..=2.0).contains(&ppt), "{ppt} px at scale {SCALE}");
    assert!(front > KNOT_MESH.triangle_count() * 2 / 5);
}

/// The one-call front draws the knot exactly as the explicit meshlet path
/// does, given the same camera, lens, light and shading: `View3d::draw`
/// against `Direct3d` + `Pipeline::draw_meshlets` with the standard scene's
/// pipeline (the `knot20k` rows of `examples/fw_bench`, where the two frame
/// CRCs agree on the Cortex-M4F too).
#[test]
fn the_front_draws_the_knot_as_the_explicit_meshlet_path() {
    use embedded_graphics::framebuffer::{Framebuffer, buffer_size};
    use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
    use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    use microraster::depth::{Depth16, DepthBand, DepthState};
    use microraster::light::Lighting;
    use microraster::math::{Vec3, transform};
    use microraster::pipeline::{ClusterCache, Shade};
    use microraster::raster3d::PerspectiveCorrect;
    use microraster::render::Direct3d;
    use microraster::view3d::{Camera, Object, View3d};
    use microraster::{Band, Renderer};
    use microraster_scenes::scenes3d::Scene3d;
    type Fb = Framebuffer<Rgb565, RawU16, LittleEndian, 320, 240, { buffer_size::<Rgb565>(320, 240) }>;
    let (angle, color) = (0.6, Rgb565::new(27, 46, 12));

    let mut explicit = Fb::new();
    let pipeline = Scene3d::pipeline::<f32, 4>(320, 240).unwrap();
    let model = transform::rotation_y(angle);
    let mut cache = Box::new(ClusterCache::<f32, 4>::new());
    let mut band = Box::new(Band::<Rgb565, 320, 16>::new(Rgb565::BLACK));
    let mut depth = Box::new(DepthBand::<Depth16, 320, 16>::new());
    let frame = Direct3d::new(&mut *depth, DepthState::LESS_WRITE, PerspectiveCorrect, |band| {
        pipeline.draw_meshlets(&VALID_KNOT, &model, color, &mut cache, band).map(|_| ())
    });
    Renderer::new(240, Rgb565::BLACK).render(frame, &mut *band, &mut explicit).unwrap();

    let mut front = Fb::new();
    let mut view = Box::new(View3d::<Rgb565, 320, 16>::new(Rgb565::BLACK));
    view.set_lighting(Some(Lighting::new(0.25, Vec3::new(-0.4, 0.7, 0.6), 0.75).with_specular(0.4, 24)));
    view.set_shade(Shade::Gouraud);
    let camera = Camera::look_at([0.0, 1.9, 5.6], [0.0; 3]).perspective(0.9, 1.0, 20.0);
    view.draw(&camera, &[Object::new(&VALID_KNOT, color).rotate_y(angle)], &mut front).unwrap();

    let lit = explicit.data().chunks(2).filter(|p| p != &[0, 0]).count();
    assert!(lit > 10_000, "the knot covers {lit} pixels");
    assert!(front.data() == explicit.data(), "the front's frame differs from the explicit path's");
}

/// The knot in 16.16 (`KNOT_FX`, read by the fixed-point stage without a
/// conversion): its values are `Fx::from_f32` of the `f32` knot's, and its
/// own clusters pass the checks and hold every triangle once.
#[test]
fn fx_knot_holds_the_f32_knot_values() {
    assert_eq!(ValidMeshletMesh::new_fx(KNOT_FX), Ok(VALID_KNOT_FX));
    let (f, x) = (KNOT.mesh, KNOT_FX.mesh);
    assert_eq!((f.positions.len(), f.normals.len()), (x.positions.len(), x.normals.len()));
    for (a, b) in f.positions.iter().zip(x.positions).chain(f.normals.iter().zip(x.normals)) {
        assert_eq!(a.map(Fx::from_f32), *b);
    }
    let mut got: Vec<[u16; 3]> = Vec::new();
    for c in KNOT_FX.meshlets {
        let local = &KNOT_FX.vertices[c.vertex_offset as usize..][..usize::from(c.vertex_count)];
        for t in &KNOT_FX.triangles[c.triangle_offset as usize..][..usize::from(c.triangle_count)] {
            let t = t.map(|k| local[usize::from(k)]);
            let k = (0..3).min_by_key(|&k| t[k]).unwrap_or(0);
            got.push([t[k], t[(k + 1) % 3], t[(k + 2) % 3]]);
        }
    }
    let mut want: Vec<[u16; 3]> = KNOT_INDICES
        .iter()
        .map(|&t| {
            let k = (0..3).min_by_key(|&k| t[k]).unwrap_or(0);
            [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
        })
        .collect();
    got.sort_unstable();
    want.sort_unstable();
    assert_eq!(got, want);
}
