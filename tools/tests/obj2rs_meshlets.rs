//! Tests of `obj2rs`'s clustered output (the default, and `--fx`): the
//! committed outputs for the cube asset, compiled in and compared with a
//! fresh conversion, the clusters they hold, and `NAME` drawn by `View3d`.

use microraster_tools::obj::{Options, convert_bytes, emit, meshlets, parse};

/// The converter's clustered output for the cube, compiled as part of this
/// test. Regenerate after changing the emitter:
/// `cargo run -p microraster-tools --bin obj2rs -- assets/cube_quads.obj --name CUBE_M > assets/cube_quads_meshlets.rs`
/// `cargo run -p microraster-tools --bin obj2rs -- assets/cube_quads.obj --name CUBE_FX --fx > assets/cube_quads_fx.rs`
mod generated {
    include!("../../assets/cube_quads_meshlets.rs");
    include!("../../assets/cube_quads_fx.rs");
}

use microraster::mesh::MeshletMesh;
use parse::parse_obj;

const CUBE_OBJ: &str = include_str!("../../assets/cube_quads.obj");

/// Each triangle as its rotation with the smallest index first (winding
/// kept), sorted.
fn canonical(triangles: &[[u16; 3]]) -> Vec<[u16; 3]> {
    let canon = |t: &[u16; 3]| (0..3).map(|r| [t[r], t[(r + 1) % 3], t[(r + 2) % 3]]).min().unwrap();
    let mut v: Vec<[u16; 3]> = triangles.iter().map(canon).collect();
    v.sort_unstable();
    v
}

/// The triangles of `mm`'s clusters in mesh indices, [`canonical`].
fn cluster_triangles<P>(mm: &MeshletMesh<'_, P>) -> Vec<[u16; 3]> {
    let mut got = Vec::new();
    for cl in mm.meshlets {
        let local = &mm.vertices[cl.vertex_offset as usize..][..usize::from(cl.vertex_count)];
        for t in &mm.triangles[cl.triangle_offset as usize..][..usize::from(cl.triangle_count)] {
            got.push(t.map(|k| local[usize::from(k)]));
        }
    }
    canonical(&got)
}

#[test]
fn meshlet_output_is_current_compiles_and_validates() {
    let m = parse_obj(CUBE_OBJ).unwrap();
    let mut src =
        emit::mesh_source(&m, "CUBE_M", "cube_quads.obj", emit::DEFAULT_MESH_TYPE, false, true).unwrap();
    let c = meshlets::build(&m).unwrap();
    src += &meshlets::rust_source(&c, "CUBE_M", emit::DEFAULT_MESH_TYPE).unwrap();
    assert_eq!(src, include_str!("../../assets/cube_quads_meshlets.rs"), "regenerate (see `mod generated`)");
    // The default conversion is this output.
    let default =
        convert_bytes(CUBE_OBJ.as_bytes(), "CUBE_M", "cube_quads.obj", &Options::default()).unwrap();
    assert_eq!(default.source, src);
    let mm = *generated::CUBE_M.get();
    assert_eq!(mm.mesh, m.mesh());
    assert_eq!(mm.validate(), Ok(()));
    // Every triangle once, winding kept (up to rotation).
    assert_eq!(cluster_triangles(&mm), canonical(&m.indices));
    // The types follow `--mesh-type`'s module.
    let crate_src = meshlets::rust_source(&c, "X", "crate::mesh::Mesh").unwrap();
    assert!(crate_src.contains("pub static X: crate::mesh::ValidMeshletMesh<'static> ="));
    assert!(crate_src.contains("crate::mesh::ValidMeshletMesh::new_const(crate::mesh::MeshletMesh {"));
    assert!(meshlets::rust_source(&c, "2x", "Mesh").is_err());
}

/// `--fx`: the positions and normals in 16.16 are `Fx::from_f32` of the
/// converted values, the clusters hold them and pass the checks, and every
/// triangle is there once; with `--plain` it is an error.
#[test]
fn fx_output_is_current_compiles_and_validates() {
    use microraster::math::{Fx, Scalar};
    use microraster::mesh::ValidMeshletMesh;
    let fx = Options { fx: true, ..Options::default() };
    let c = convert_bytes(CUBE_OBJ.as_bytes(), "CUBE_FX", "cube_quads.obj", &fx).unwrap();
    assert_eq!(c.source, include_str!("../../assets/cube_quads_fx.rs"), "regenerate (see `mod generated`)");
    let mm = *generated::CUBE_FX.get();
    let m = parse_obj(CUBE_OBJ).unwrap();
    let to_fx = |rows: &[[f32; 3]]| rows.iter().map(|r| r.map(Fx::from_f32)).collect::<Vec<_>>();
    assert_eq!(mm.mesh.positions, &to_fx(&m.positions)[..]);
    assert_eq!(mm.mesh.normals, &to_fx(&m.normals)[..]);
    assert_eq!(mm.mesh.indices, &m.indices[..]);
    assert!(ValidMeshletMesh::new_fx(mm).is_ok());
    assert_eq!(cluster_triangles(&mm), canonical(&m.indices));
    let alone = Options { fx: true, meshlets: false, ..Options::default() };
    assert!(convert_bytes(CUBE_OBJ.as_bytes(), "CUBE_FX", "cube_quads.obj", &alone).is_err());
}

/// What a user of the default output writes: `Object::new(&NAME, colour)`
/// in a `View3d` scene draws the clusters, and the same pixels as the plain
/// `NAME_MESH` (a closed convex mesh: no triangle order can matter).
#[test]
fn default_output_is_a_view3d_object() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    use embedded_graphics::prelude::Point;
    use microraster::view3d::{Camera, Geometry, Object, View3d};
    let camera = Camera::look_at([2.0, 1.5, 3.0], [0.0; 3]);
    let mut view = View3d::<Rgb565, 48, 8>::new(Rgb565::BLACK);
    let frame = |view: &mut View3d<Rgb565, 48, 8>, o: Object<'_, Rgb565>| {
        let mut display = MockDisplay::new();
        display.set_allow_overdraw(true);
        view.draw(&camera, &[o.rotate_y(0.4)], &mut display).unwrap();
        (0..48)
            .flat_map(|y| (0..48).map(move |x| Point::new(x, y)))
            .map(|p| display.get_pixel(p))
            .collect::<Vec<_>>()
    };
    let clustered = Object::new(&generated::CUBE_M, Rgb565::CYAN);
    assert!(matches!(clustered.geometry(), Geometry::Meshlets(_)));
    let (a, b) =
        (frame(&mut view, clustered), frame(&mut view, Object::new(&generated::CUBE_M_MESH, Rgb565::CYAN)));
    assert!(a.iter().filter(|&&c| c != Some(Rgb565::BLACK)).count() > 300, "the cube is drawn");
    assert_eq!(a, b);
}

/// The default output builds `NAME` with `ValidMeshletMesh::new_const`
/// (its compile-time panic names the cause): the same statics as the older
/// `match` form, no `match` and no hand-written message.
#[test]
fn new_const_output_is_the_match_output_with_the_constructor_call() {
    use meshlets::{VALIDATION, Validation, rust_source_validated};
    let m = parse_obj(CUBE_OBJ).unwrap();
    let c = meshlets::build(&m).unwrap();
    let ty = emit::DEFAULT_MESH_TYPE;
    let matched = rust_source_validated(&c, "CUBE_M", ty, false, Validation::Match).unwrap();
    assert_eq!(VALIDATION, Validation::NewConst);
    assert_eq!(
        rust_source_validated(&c, "CUBE_M", ty, false, Validation::NewConst).unwrap(),
        meshlets::rust_source(&c, "CUBE_M", ty).unwrap()
    );
    let (prefix, tail) = matched.split_once("pub static CUBE_M: ").unwrap();
    for fx in [false, true] {
        let src = rust_source_validated(&c, "CUBE_M", ty, fx, Validation::NewConst).unwrap();
        let (storage, new) = if fx { (", microraster::math::Fx", "new_fx_const") } else { ("", "new_const") };
        let want = format!(
            "{prefix}pub static CUBE_M: microraster::mesh::ValidMeshletMesh<'static{storage}> = \
             microraster::mesh::ValidMeshletMesh::{new}(microraster::mesh::MeshletMesh {{\n    \
             mesh: CUBE_M_MESH,\n    meshlets: &CUBE_M_MESHLETS,\n    vertices: &CUBE_M_MESHLET_VERTICES,\n    \
             triangles: &CUBE_M_MESHLET_TRIANGLES,\n}});\n"
        );
        assert_eq!(src, want, "fx {fx}");
        assert!(!src.contains("match") && !src.contains("panic!"));
    }
    assert!(tail.contains("Err(_) => panic!(\"CUBE_M: the mesh fails validation"));
    // The types follow `--mesh-type`'s module.
    let krate = rust_source_validated(&c, "X", "crate::mesh::Mesh", false, Validation::NewConst).unwrap();
    assert!(krate.contains("pub static X: crate::mesh::ValidMeshletMesh<'static> = crate::mesh::ValidMeshletMesh::new_const(crate::mesh::MeshletMesh {\n"));
}
