//! Criterion's median of one benchmark from its last run, read back from
//! `target/criterion/<group>/<id>/new/estimates.json` (or under
//! `$CARGO_TARGET_DIR`). Shared (`#[path]`) by `benches/shapes.rs`, which
//! prints its ratios, and `examples/readme_2d.rs`, which writes them into
//! the README.

/// The median (ns) of `group/id`, if criterion has measured it.
pub fn median(group: &str, id: &str) -> Option<f64> {
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| std::path::PathBuf::from("target"), Into::into);
    let text =
        std::fs::read_to_string(target.join("criterion").join(group).join(id).join("new/estimates.json"))
            .ok()?;
    let rest = &text[text.find("\"median\"")?..];
    rest[rest.find("\"point_estimate\":")? + 17..].split([',', '}']).next()?.trim().parse().ok()
}
