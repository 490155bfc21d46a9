//! The knots the firmware benchmark's `ways` rows and the `ways` integration
//! test draw are exactly what `obj2rs`'s default command makes of the
//! generator's OBJ files: the committed sources equal a fresh conversion,
//! and they compile (their clusters pass the compile-time check).

#[path = "../../examples/gen_bench_mesh.rs"]
#[allow(dead_code)]
mod gen_bench_mesh;

#[allow(dead_code)]
mod generated {
    include!("../../examples/common/knot5k_obj2rs.rs");
}

use microraster_tools::obj::{Options, convert_bytes};

#[test]
fn committed_knot_conversions_are_current() {
    for (along, around, name, committed) in [
        (160, 16, "knot5k", include_str!("../../examples/common/knot5k_obj2rs.rs")),
        (320, 32, "knot20k", include_str!("../../examples/common/knot20k_obj2rs.rs")),
    ] {
        let obj = gen_bench_mesh::obj_text(along, around);
        let c = convert_bytes(obj.as_bytes(), name, &format!("{name}.obj"), &Options::default()).unwrap();
        assert_eq!((c.winding_warning, c.mesh.indices.len()), (None, 2 * along * around));
        // No diff of a megabyte on failure: just how to fix it.
        assert!(
            c.source == committed,
            "stale: cargo run --example gen_bench_mesh -- --obj {along} {around} > {name}.obj && \
             obj2rs {name}.obj --name {} > examples/common/{name}_obj2rs.rs",
            name.to_uppercase()
        );
    }
    assert_eq!(generated::KNOT5K.get().mesh, generated::KNOT5K_MESH);
}
