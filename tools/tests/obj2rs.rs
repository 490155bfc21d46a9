//! Tests of `obj2rs` (OBJ → Rust source for a static `Mesh`): its parser
//! and emitter (`microraster_tools::obj`), and the committed outputs for the
//! test assets, compiled in and compared with a fresh conversion (round trip).

use microraster_tools::obj::{Options, convert_bytes, emit, meshlets, parse};

/// The converter's output for the assets, compiled as part of this test
/// (the tetrahedron as converted by default, in clusters; the cube plain).
/// Regenerate after changing the emitter:
/// `cargo run -p microraster-tools --bin obj2rs -- assets/tetra.obj --name TETRA > assets/tetra.rs`
/// `cargo run -p microraster-tools --bin obj2rs -- assets/cube_quads.obj --name CUBE_QUADS --plain > assets/cube_quads.rs`
/// (the clusters' outputs: `tests/obj2rs_meshlets.rs`)
mod generated {
    include!("../../assets/tetra.rs");
    include!("../../assets/cube_quads.rs");
}

use microraster::Error;
use microraster::mesh::{Mesh, MeshletMesh};
use parse::{ObjMesh, ParseError, parse_obj};
use proptest::prelude::*;

const TETRA_OBJ: &str = include_str!("../../assets/tetra.obj");
const CUBE_OBJ: &str = include_str!("../../assets/cube_quads.obj");

fn signed_volume(m: &Mesh<'_>) -> f64 {
    let p = |i: u16| m.positions[usize::from(i)].map(f64::from);
    let det = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0])
    };
    m.indices.iter().map(|&[a, b, c]| det(p(a), p(b), p(c))).sum::<f64>() / 6.0
}

/// Counts, validity and unit normals of a converted mesh.
fn check(m: &ObjMesh, vertices: usize, triangles: usize) {
    assert_eq!((m.positions.len(), m.normals.len(), m.indices.len()), (vertices, vertices, triangles));
    assert_eq!(m.mesh().validate(), Ok(()));
    for n in &m.normals {
        let len = n.iter().map(|&x| f64::from(x) * f64::from(x)).sum::<f64>().sqrt();
        assert!((len - 1.0).abs() < 1e-6, "{n:?}");
    }
}

fn err(text: &str) -> ParseError {
    parse_obj(text).expect_err("should be rejected")
}

const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

#[test]
fn tetra_gets_computed_area_weighted_normals() {
    let m = parse_obj(TETRA_OBJ).unwrap();
    check(&m, 4, 4);
    assert_eq!((m.computed_normals, m.arbitrary_normals, m.dropped_triangles), (4, 0, 0));
    assert!((signed_volume(&m.mesh()) - 8.0 / 3.0).abs() < 1e-12);
    // By symmetry each vertex normal points away from the centre.
    for (p, n) in m.positions.iter().zip(&m.normals) {
        for k in 0..3 {
            assert!((n[k] - p[k] / 3f32.sqrt()).abs() < 1e-6);
        }
    }
    assert_eq!(m.bounding_sphere.0, [0.0; 3]);
}

#[test]
fn cube_quads_keeps_file_normals_and_splits_vertices_by_normal() {
    let m = parse_obj(CUBE_OBJ).unwrap();
    // 8 positions × 3 face normals each; 6 quads → 12 triangles.
    check(&m, 24, 12);
    assert_eq!((m.computed_normals, m.dropped_triangles), (0, 0));
    assert_eq!(signed_volume(&m.mesh()), 8.0);
    for (i, tri) in m.indices.iter().enumerate() {
        // Flat faces: every corner carries the face normal from the file.
        let face = m.mesh().face_normal(i).unwrap();
        for &v in tri {
            assert_eq!(m.normals[usize::from(v)], face);
        }
    }
    let (c, r) = m.bounding_sphere;
    assert_eq!(c, [0.0; 3]);
    assert!(r * r >= 3.0 && r < 1.7320511);
}

#[test]
fn generated_sources_are_current_and_compile() {
    let tetra = convert_bytes(TETRA_OBJ.as_bytes(), "tetra", "tetra.obj", &Options::default()).unwrap();
    let cube = parse_obj(CUBE_OBJ).unwrap();
    let plain = emit::rust_source(&cube, "Cube_Quads", "cube_quads.obj", emit::DEFAULT_MESH_TYPE).unwrap();
    for (src, golden, file, mesh, converted) in [
        (&tetra.source, include_str!("../../assets/tetra.rs"), "tetra", &generated::TETRA_MESH, &tetra.mesh),
        (&plain, include_str!("../../assets/cube_quads.rs"), "cube_quads", &generated::CUBE_QUADS, &cube),
    ] {
        assert_eq!(*src, golden, "assets/{file}.rs: regenerate it (see `mod generated`)");
        // The compiled statics hold exactly the converted data.
        assert_eq!(*mesh, converted.mesh());
        assert_eq!(mesh.validate(), Ok(()));
    }
    // By default `NAME` is the mesh in its clusters, checked at compile time.
    assert_eq!(generated::TETRA.get().mesh, generated::TETRA_MESH);
    assert_eq!(generated::TETRA.get().meshlets.len(), 1);
    assert_eq!(generated::TETRA_POSITIONS.len(), 4);
    assert_eq!(generated::CUBE_QUADS_INDICES.len(), 12);
    assert_eq!(generated::CUBE_QUADS_NORMALS[0], [0.0, 0.0, 1.0]);
}

#[test]
fn winding_against_file_normals_is_a_warning() {
    for obj in [TETRA_OBJ, CUBE_OBJ] {
        let m = parse_obj(obj).unwrap();
        assert_eq!((meshlets::winding_mismatches(&m), meshlets::winding_warning(&m, true)), (0, None));
    }
    // One triangle counter-clockwise from +z, normals towards −z; and a second,
    // degenerate-free, that agrees.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 0\nv 6 5 0\nv 5 6 0\nvn 0 0 -1\nvn 0 0 1\n\
                f 1//1 2//1 3//1\nf 4//2 5//2 6//2\n";
    let m = parse_obj(text).unwrap();
    assert_eq!(meshlets::winding_mismatches(&m), 1);
    let warning = meshlets::winding_warning(&m, false).unwrap();
    assert!(warning.starts_with("warning: 1 of 2 triangles are wound clockwise"), "{warning}");
    let clustered = meshlets::winding_warning(&m, true).unwrap();
    assert!(clustered.ends_with("(WindingMismatch)") && clustered.contains("`--plain`"), "{clustered}");
    assert_eq!(m.mesh().check_winding(), Err(Error::WindingMismatch));
    // Normals computed from the winding always agree, even inside out.
    let reversed = TETRA_OBJ.replace("f 1 2 3", "f 1 3 2").replace("f 1 3 4", "f 1 4 3");
    let reversed = reversed.replace("f 1 4 2", "f 1 2 4").replace("f 2 4 3", "f 2 3 4");
    let m = parse_obj(&reversed).unwrap();
    assert!(signed_volume(&m.mesh()) < 0.0);
    assert_eq!(meshlets::winding_mismatches(&m), 0);
}

#[test]
fn emitter_checks_names_and_paths() {
    let m = parse_obj(TETRA_OBJ).unwrap();
    assert_eq!(emit::static_name("teapot_2"), Ok("TEAPOT_2".into()));
    for bad in ["", "_", "2x", "a-b", "a b", "é"] {
        assert!(emit::static_name(bad).is_err(), "{bad:?}");
        assert!(emit::rust_source(&m, bad, "x", emit::DEFAULT_MESH_TYPE).is_err());
    }
    assert!(emit::is_type_path("crate::mesh::Mesh"));
    assert!(!emit::is_type_path("crate::mesh::"));
    let src = emit::rust_source(&m, "T", "we\"ird\nname.obj", "crate::mesh::Mesh").unwrap();
    assert!(src.starts_with("// Generated by obj2rs from \"we\\\"ird\\nname.obj\"; do not edit."));
    assert!(src.contains("pub static T: crate::mesh::Mesh<'static> = crate::mesh::Mesh::new("));
    assert!(emit::rust_source(&m, "T", "x", "Mesh<'a>").is_err());
}

#[test]
fn polygons_are_fans_and_indices_may_be_negative() {
    let pentagon = "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\nf -5 -1 -2\n";
    let m = parse_obj(pentagon).unwrap();
    assert_eq!(m.indices, [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 3]]);
    // One position, two normals → two vertices; a repeated pair → one.
    let m =
        parse_obj(&format!("{TRI}vn 0 0 2\nvn 0 0 -1\nf 1//1 2//1 3//1\nf 1//2 3//2 2//2\nf 1//1 2//1 3//1"))
            .unwrap();
    assert_eq!(m.positions.len(), 6);
    assert_eq!(m.indices, [[0, 1, 2], [3, 4, 5], [0, 1, 2]]);
    assert_eq!(m.normals[0], [0.0, 0.0, 1.0]); // normalised
    assert_eq!(m.normals[3], [0.0, 0.0, -1.0]);
    // Unused positions are dropped; output order is first use.
    let m = parse_obj("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 4 3 2").unwrap();
    assert_eq!(m.positions, [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]);
    assert_eq!(m.normals, [[0.0, 0.0, -1.0]; 3]);
}

#[test]
fn comments_continuations_and_other_statements() {
    let text = "# header\r\nmtllib x.mtl\r\no thing # named\r\nv 0 0 0 1\r\nv 1 0 0 0.5 0.5 0.5\r\nv 0 \\\r\n 1 0\r\n\
                vt 0.5\r\nvt 0 1 0\r\nvp 1 2\r\ncstype bezier\r\ns 1\r\nl 1 2\r\nf 1/1 2/2 \\\r\n3/1 # tri\r\n";
    let m = parse_obj(text).unwrap();
    check(&m, 3, 1);
    assert_eq!(m.normals, [[0.0, 0.0, 1.0]; 3]);
    // A continued statement is reported at its first line.
    assert_eq!(err("v 0 0 0\nf 1 \\\n 2 3").line, 2);
}

#[test]
fn computed_normals_mix_with_file_normals_and_degenerates() {
    // Corner 3 has no normal in the file: it gets the computed one.
    let m = parse_obj(&format!("{TRI}vn 1 0 0\nf 1//1 2//1 3")).unwrap();
    assert_eq!((m.computed_normals, m.normals[2]), (1, [0.0, 0.0, 1.0]));
    assert_eq!(m.normals[0], [1.0, 0.0, 0.0]);
    // A zero file normal falls back to the computed normal.
    let m = parse_obj(&format!("{TRI}vn 0 0 0\nf 1//1 2//1 3//1")).unwrap();
    assert_eq!((m.computed_normals, m.normals), (3, vec![[0.0, 0.0, 1.0]; 3]));
    // Repeated positions: dropped. Collinear (zero-area) triangles are kept,
    // and vertices with only those around them get +z.
    let m = parse_obj(&format!("{TRI}v 2 0 0\nf 1 2 1\nf 1 2 3\nf 1 2 4")).unwrap();
    assert_eq!((m.indices.len(), m.dropped_triangles, m.arbitrary_normals), (2, 1, 1));
    assert_eq!(m.normals[3], [0.0, 0.0, 1.0]);
    // Area weighting: a big and a small triangle around vertex 1.
    let m = parse_obj("v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 -1\nf 1 2 3\nf 1 4 2").unwrap();
    let n = m.normals[0];
    assert!(n[2] > 0.99 && n[1] < 0.0, "{n:?}");
}

#[test]
fn errors_name_the_line() {
    let cases: &[(&str, usize, &str)] = &[
        ("v 1 2\n", 1, "`v` needs 3 to 7 numbers, found 2"),
        ("v 1 2 3 4 5 6 7 8\n", 1, "`v` needs 3 to 7 numbers, found 8"),
        ("\n\nv 1 x 3", 3, "`x` is not a number"),
        ("v 1 nan 3", 1, "`nan` is not a finite f32"),
        ("v 1 inf 3", 1, "`inf` is not a finite f32"),
        ("v 1 1e39 3", 1, "`1e39` is not a finite f32"),
        ("vn 0 1", 1, "`vn` needs 3 numbers, found 2"),
        ("vt", 1, "`vt` needs 1 to 3 numbers, found 0"),
        ("vt 0 y", 1, "`y` is not a number"),
        ("f 1 2 3", 1, "position index 1 is out of range (0 positions defined so far)"),
        ("v 0 0 0\nv 1 0 0\nf 1 2", 3, "a face needs at least 3 corners, found 2"),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4",
            4,
            "position index 4 is out of range (3 positions defined so far)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4",
            4,
            "position index -4 is out of range (3 positions defined so far)",
        ),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0", 4, "position index 0 is invalid (OBJ indices start at 1)"),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1",
            4,
            "texture coordinate index 1 is out of range (0 texture coordinates defined so far)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2",
            5,
            "normal index 2 is out of range (1 normals defined so far)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3",
            4,
            "bad face corner `1/2/3/4` (expected v, v/vt, v//vn or v/vt/vn)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2 3",
            4,
            "bad face corner `1/` (expected v, v/vt, v//vn or v/vt/vn)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1// 2 3",
            4,
            "bad face corner `1//` (expected v, v/vt, v//vn or v/vt/vn)",
        ),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf a 2 3", 4, "`a` is not a valid position index"),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 99999999999999999999 2 3",
            4,
            "`99999999999999999999` is not a valid position index",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808",
            4,
            "position index -9223372036854775808 is out of range (3 positions defined so far)",
        ),
        // Forward references are not allowed (as in the OBJ spec).
        (
            "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0",
            3,
            "position index 3 is out of range (2 positions defined so far)",
        ),
        ("# empty\n", 0, "no (non-degenerate) faces in the file"),
        (TRI, 0, "no (non-degenerate) faces in the file"),
        ("v 0 0 0\nf 1 1 1", 0, "no (non-degenerate) faces in the file"),
        (
            "v 0 0 0\nv 4e19 0 0\nv 0 1 0\nf 1 2 3",
            0,
            "coordinates too large: the bounding radius must stay below 1.8e19",
        ),
    ];
    for &(text, line, message) in cases {
        assert_eq!(err(text), ParseError { line, message: message.into() }, "{text:?}");
    }
    assert_eq!(err("\nv 1 2").to_string(), "line 2: `v` needs 3 to 7 numbers, found 2");
    assert_eq!(err("").to_string(), "no (non-degenerate) faces in the file");
}

#[test]
fn at_most_65536_vertices() {
    // 65536 distinct vertices fit u16 indices; the face bringing the 65537th
    // is reported.
    let mut text = String::new();
    for i in 0..65538 {
        text.push_str(&format!("v {} {} 0\n", i % 256, i / 256));
    }
    let faces = |n: usize| {
        (0..n).map(|t| format!("f {} {} {}\n", 3 * t + 1, 3 * t + 2, 3 * t + 3)).collect::<String>()
    };
    let m = parse_obj(&format!("{text}{}f 65535 65536 1\n", faces(21845))).unwrap();
    assert_eq!((m.positions.len(), m.indices.len()), (65536, 21846));
    assert_eq!(m.mesh().validate(), Ok(()));
    let e = err(&format!("{text}{}f 65535 65536 65537\n", faces(21845)));
    assert_eq!(
        e,
        ParseError {
            line: 65538 + 21846,
            message: "more than 65536 distinct vertices (indices are u16)".into()
        }
    );
}

/// Keeps the data small: OBJ-like statements, valid and invalid.
fn obj_line() -> impl Strategy<Value = String> {
    prop_oneof![
        "v( -?[0-9]{1,2}(\\.[0-9])?){2,5}",
        "vn( -?[01](\\.5)?){2,4}",
        "vt( [01](\\.5)?){0,4}",
        "f( -?[0-9]{1,2}(/-?[0-9]{0,2}){0,3}){0,6}",
        "f( [1-9]){3,5}",
        "f( [1-9]//[1-3]){3,4}",
        "#.*",
        "[a-z]{1,7}( [a-z0-9]{1,4}){0,3}",
        "v (nan|inf|1e40|-0) 0 0",
        ".*\\\\",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// Never a panic, whatever the input.
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,300}") {
        let _ = parse_obj(&text);
    }

    /// Whatever parses is a valid mesh with unit normals, and the emitted
    /// source is well formed enough to count its rows.
    #[test]
    fn obj_like_text_parses_to_valid_meshes(lines in prop::collection::vec(obj_line(), 0..40)) {
        let text = lines.join("\n");
        if let Ok(m) = parse_obj(&text) {
            check(&m, m.positions.len(), m.indices.len());
            prop_assert!(m.indices.iter().flatten().all(|&i| usize::from(i) < m.positions.len()));
            let src = emit::rust_source(&m, "M", "x.obj", emit::DEFAULT_MESH_TYPE).unwrap();
            // Clusters always build and validate, unless the file's normals
            // disagree with the winding (which the converter warns about).
            let c = meshlets::build(&m).unwrap();
            let mm = MeshletMesh { mesh: m.mesh(), meshlets: &c.meshlets, vertices: &c.vertices, triangles: &c.triangles };
            let expect = if meshlets::winding_mismatches(&m) == 0 { Ok(()) } else { Err(Error::WindingMismatch) };
            prop_assert_eq!(mm.validate(), expect);
            prop_assert_eq!(meshlets::winding_warning(&m, false).is_some(), expect.is_err());
            prop_assert_eq!(src.lines().filter(|l| l.starts_with("    [")).count(), 2 * m.positions.len() + m.indices.len());
        }
    }
}

/// The build-script route reads the file, names it in errors, and refuses a
/// winding against the normals (which the binary only warns about).
#[test]
fn convert_for_build_scripts_rejects_a_winding_mismatch() {
    let dir = std::env::temp_dir().join(format!("obj2rs-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("good.obj");
    let bad = dir.join("bad.obj");
    std::fs::write(&good, format!("{TRI}vn 0 0 1\nf 1//1 2//1 3//1\n")).unwrap();
    std::fs::write(&bad, format!("{TRI}vn 0 0 -1\nf 1//1 2//1 3//1\n")).unwrap();
    let src = microraster_tools::obj::convert(&good, "good").unwrap();
    assert!(src.contains("pub static GOOD: microraster::mesh::ValidMeshletMesh<'static>"), "{src}");
    assert!(src.contains("pub static GOOD_MESH: microraster::mesh::Mesh<'static>"), "{src}");
    let e = microraster_tools::obj::convert(&bad, "bad").unwrap_err().to_string();
    assert!(
        e.starts_with(&bad.display().to_string()) && e.contains("1 of 1 triangles are wound clockwise"),
        "{e}"
    );
    let missing = microraster_tools::obj::convert(dir.join("missing.obj"), "m").unwrap_err().to_string();
    assert!(missing.contains("missing.obj"), "{missing}");
    std::fs::remove_dir_all(&dir).unwrap();
}
