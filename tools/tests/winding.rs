//! `obj2rs` and triangles wound against their normals: the binary warns on
//! stderr with the count and still writes the mesh; `--flip-winding`
//! reverses exactly those triangles.

use std::process::Command;

use microraster::Error;
use microraster_tools::obj::{Options, convert_bytes, meshlets, parse};

/// Two triangles counter-clockwise seen from +z (the first with normals
/// towards −z, against its winding; the second towards +z) and a third
/// clockwise from +z with normals towards +z (against its winding too).
const MIXED: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 0\nv 6 5 0\nv 5 6 0\nv 9 9 0\nv 10 9 0\nv 9 10 0\n\
                     vn 0 0 -1\nvn 0 0 1\n\
                     f 1//1 2//1 3//1\nf 4//2 5//2 6//2\nf 7//2 9//2 8//2\n";

/// Runs the installed-to-be binary on `obj` (written to a temporary file).
fn obj2rs(obj: &str, extra: &[&str]) -> (bool, String, String) {
    let dir = std::env::temp_dir().join(format!("obj2rs-winding-{}-{}", std::process::id(), extra.len()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mixed.obj");
    std::fs::write(&path, obj).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_obj2rs"))
        .arg(&path)
        .args(["--name", "mixed"])
        .args(extra)
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.success(), text(out.stdout), text(out.stderr))
}

#[test]
fn binary_warns_with_the_count_and_still_writes_the_mesh() {
    let (ok, stdout, stderr) = obj2rs(MIXED, &[]);
    assert!(ok, "{stderr}");
    assert!(stderr.contains("warning: 2 of 3 triangles are wound clockwise"), "{stderr}");
    assert!(stderr.contains("--flip-winding"), "the warning names the fix: {stderr}");
    // The file's winding, unchanged (vertices are numbered in order of
    // first use, so every triangle reads `[k, k + 1, k + 2]`).
    assert!(stdout.contains("[0, 1, 2]") && stdout.contains("[6, 7, 8]"), "{stdout}");
}

#[test]
fn flip_winding_reverses_exactly_the_disagreeing_triangles() {
    let (ok, stdout, stderr) = obj2rs(MIXED, &["--flip-winding"]);
    assert!(ok, "{stderr}");
    assert!(!stderr.contains("warning"), "{stderr}");
    assert!(stderr.contains("reversed 2 triangles"), "{stderr}");
    // First and third reversed (two corners swapped), the second kept.
    assert!(
        stdout.contains("[0, 2, 1]") && stdout.contains("[3, 4, 5]") && stdout.contains("[6, 8, 7]"),
        "{stdout}"
    );

    let flip = Options { flip_winding: true, ..Options::default() };
    let c = convert_bytes(MIXED.as_bytes(), "mixed", "mixed.obj", &flip).unwrap();
    assert_eq!((c.flipped, c.winding_warning), (2, None));
    assert_eq!(c.mesh.mesh().check_winding(), Ok(()));
    let plain = parse::parse_obj(MIXED).unwrap();
    assert_eq!(plain.mesh().check_winding(), Err(Error::WindingMismatch));
    // Same triangles as sets of corners: only the order changed.
    for (a, b) in plain.indices.iter().zip(&c.mesh.indices) {
        let (mut a, mut b) = (*a, *b);
        a.sort_unstable();
        b.sort_unstable();
        assert_eq!(a, b);
    }
    // A consistent mesh is left alone.
    let mut tetra = parse::parse_obj(include_str!("../../assets/tetra.obj")).unwrap();
    let before = tetra.indices.clone();
    assert_eq!(meshlets::flip_mismatches(&mut tetra), 0);
    assert_eq!(tetra.indices, before);
}

#[test]
fn flip_winding_lets_the_meshlet_output_validate() {
    let c = convert_bytes(MIXED.as_bytes(), "m", "m.obj", &Options { meshlets: true, ..Options::default() });
    assert!(c.unwrap().winding_warning.unwrap().ends_with("(WindingMismatch)"));
    let opts = Options { meshlets: true, flip_winding: true, ..Options::default() };
    let c = convert_bytes(MIXED.as_bytes(), "m", "m.obj", &opts).unwrap();
    assert_eq!(c.winding_warning, None);
    let clusters = meshlets::build(&c.mesh).unwrap();
    assert!(!clusters.meshlets.is_empty());
}
