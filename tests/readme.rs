//! The README and the rustdoc front page, checked:
//!
//! * each recipe the README quotes (a `rust` block after a
//!   `<!-- recipe: examples/recipes/NAME.rs -->` marker) is, line for line,
//!   the code between `// recipe:begin` and `// recipe:end` of that example
//!   (which `cargo test` compiles), and every example in `examples/recipes/`
//!   is quoted;
//! * each recipe still draws the picture the README shows
//!   (`docs/img/dashboard.png`, `docs/img/mesh_hud.png`, pixel for pixel);
//! * the README has at most 400 lines, no doctest scaffolding (`# ` lines
//!   in a `rust` block) and no link to a file that does not exist;
//! * the front page (`src/lib.rs`'s `//!` text, what rustdoc and a package
//!   registry show) has no image and no link into the repository: those do
//!   not resolve there (`docs/` is not packaged). Broken intra-doc links are
//!   `cargo doc`'s job (`RUSTDOCFLAGS="-D warnings"` in CI).

use std::path::Path;

#[allow(dead_code)] // `main` is the example's
#[path = "../examples/recipes/dashboard.rs"]
mod dashboard;

#[allow(dead_code)]
#[path = "../examples/recipes/mesh_hud.rs"]
mod mesh_hud;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn read(path: &str) -> String {
    std::fs::read_to_string(Path::new(ROOT).join(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The README's recipe blocks: (example path, the block's lines).
fn recipes(readme: &str) -> Vec<(String, Vec<String>)> {
    let lines: Vec<&str> = readme.lines().collect();
    let mut out = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        let Some(path) = l.trim().strip_prefix("<!-- recipe: ").and_then(|r| r.strip_suffix(" -->")) else {
            continue;
        };
        let start = (i + 1..lines.len())
            .find(|&j| !lines[j].trim().is_empty())
            .unwrap_or_else(|| panic!("{path}: no code block after its marker"));
        assert_eq!(lines[start], "```rust", "{path}: the marker must be followed by a ```rust block");
        let end = (start + 1..lines.len())
            .find(|&j| lines[j] == "```")
            .unwrap_or_else(|| panic!("{path}: unterminated block"));
        out.push((path.to_string(), lines[start + 1..end].iter().map(|s| s.to_string()).collect()));
    }
    out
}

/// The lines strictly between `// recipe:begin` and `// recipe:end`.
fn region(source: &str, path: &str) -> Vec<String> {
    let lines: Vec<&str> = source.lines().collect();
    let at = |m: &str| lines.iter().position(|l| l.trim() == m).unwrap_or_else(|| panic!("{path}: no `{m}`"));
    let (b, e) = (at("// recipe:begin"), at("// recipe:end"));
    assert!(b < e, "{path}: `recipe:begin` after `recipe:end`");
    lines[b + 1..e].iter().map(|s| s.to_string()).collect()
}

#[test]
fn readme_recipes_are_the_examples_code() {
    let readme = read("README.md");
    let quoted = recipes(&readme);
    assert!(!quoted.is_empty(), "the README quotes no recipe");
    for (path, block) in &quoted {
        let want = region(&read(path), path);
        for (n, (got, want)) in block.iter().zip(&want).enumerate() {
            assert_eq!(got, want, "README's block for {path}, line {} differs from the example", n + 1);
        }
        assert_eq!(block.len(), want.len(), "README's block for {path} has another length than its region");
    }
    let dir = Path::new(ROOT).join("examples/recipes");
    for entry in std::fs::read_dir(&dir).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if name.ends_with(".rs") {
            let path = format!("examples/recipes/{name}");
            assert!(quoted.iter().any(|(p, _)| *p == path), "the README does not quote {path}");
        }
    }
}

/// How many pixels of `drawn` (8-bit RGB) differ from the committed PNG `path`
/// of `size`.
fn differ_from_committed(path: &str, size: (u32, u32), drawn: &[u8]) -> usize {
    let file = std::fs::File::open(Path::new(ROOT).join(path)).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut reader = png::Decoder::new(std::io::BufReader::new(file)).read_info().unwrap();
    let mut committed = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut committed).unwrap();
    assert_eq!((info.width, info.height, info.color_type), (size.0, size.1, png::ColorType::Rgb), "{path}");
    assert_eq!(drawn.len(), committed.len(), "{path}");
    drawn.chunks(3).zip(committed.chunks(3)).filter(|(a, b)| a != b).count()
}

#[test]
fn dashboard_recipe_draws_the_committed_picture() {
    let differ = differ_from_committed("docs/img/dashboard.png", (320, 240), &dashboard::picture());
    assert_eq!(
        differ, 0,
        "{differ} pixels differ from docs/img/dashboard.png: `cargo run --example dashboard` rewrites it"
    );
}

#[test]
fn mesh_hud_recipe_draws_the_committed_picture() {
    let drawn = mesh_hud::picture();
    // Not a blank frame: the knot and the HUD's text light many colours.
    let mut colours: Vec<&[u8]> = drawn.chunks(3).collect();
    colours.sort();
    colours.dedup();
    assert!(colours.len() > 50, "the recipe drew {} colours", colours.len());
    let differ = differ_from_committed("docs/img/mesh_hud.png", (240, 240), &drawn);
    assert_eq!(
        differ, 0,
        "{differ} pixels differ from docs/img/mesh_hud.png: `cargo run --example mesh_hud` rewrites it"
    );
}

/// Link and image targets in markdown text: `](target)` and `[label]: target`.
fn link_targets(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("](") {
        let tail = &rest[i + 2..];
        let end = tail.find(')').unwrap_or(tail.len());
        out.push(tail[..end].trim().to_string());
        rest = &tail[end..];
    }
    for line in text.lines() {
        let l = line.trim_start();
        if let Some(close) = l.strip_prefix('[').and_then(|r| r.find("]: ")) {
            out.push(l[close + 4..].trim().to_string());
        }
    }
    out
}

/// A rustdoc intra-doc target (`crate::x::Y`, `Type::method`, `mod@x`) or
/// an absolute URL: resolves on docs.rs.
fn resolves_anywhere(target: &str) -> bool {
    target.starts_with("http://")
        || target.starts_with("https://")
        || (!target.contains('/') && !target.contains('.') && !target.starts_with('#'))
}

#[test]
fn front_page_has_no_repository_link_or_image() {
    let lib = read("src/lib.rs");
    let doc: String = lib
        .lines()
        .filter_map(|l| l.strip_prefix("//!"))
        .map(|l| format!("{}\n", l.strip_prefix(' ').unwrap_or(l)))
        .collect();
    assert!(doc.len() > 500, "src/lib.rs has lost its front page");
    assert!(!lib.contains("include_str!(\"../README.md\")"), "the README links into the repository");
    assert!(!doc.contains("<img"), "an HTML image on the front page");
    for t in link_targets(&doc) {
        assert!(resolves_anywhere(&t), "front page link `{t}` does not resolve on docs.rs");
    }
    // The check itself: a relative link and a relative image fail it.
    assert!(!resolves_anywhere("docs/img/dashboard.png") && !resolves_anywhere("README.md"));
    assert!(link_targets("![x](docs/a.png) and [y](#z)").iter().all(|t| !resolves_anywhere(t)));
}

#[test]
fn readme_is_short_plain_and_its_links_exist() {
    let readme = read("README.md");
    let n = readme.lines().count();
    assert!(n <= 400, "README.md has {n} lines (at most 400: details go to docs/)");
    let mut in_rust = false;
    for (i, l) in readme.lines().enumerate() {
        if l.starts_with("```") {
            in_rust = !in_rust && l.starts_with("```rust");
        } else if in_rust {
            assert!(!(l == "#" || l.starts_with("# ")), "README.md:{}: doctest scaffolding `{l}`", i + 1);
        }
    }
    for t in link_targets(&readme) {
        if t.starts_with("http") || t.starts_with('#') {
            continue;
        }
        let file = t.split('#').next().unwrap();
        assert!(Path::new(ROOT).join(file).exists(), "README.md links `{t}`, which does not exist");
    }
}
