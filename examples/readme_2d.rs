//! Writes docs/shapes.md's 2D numbers from their sources, between markers:
//!
//! * `dashboard`: the line counts of the two dashboard functions in
//!   `examples/common/dashboard.rs` (non-blank, non-comment lines between
//!   the `dashboard:mr:*` and `dashboard:eg:*` markers), the verdict against
//!   the target (microraster's no longer than plain embedded-graphics'),
//!   and microraster's code itself;
//! * `shapes-ratios`: the ratios of `cargo bench --bench shapes` (criterion's
//!   medians of its last run, in `target/criterion`), each shape and the
//!   dashboard frame against their peers, with the verdicts;
//! * `shape-counts`: the instruction counts per frame of the filled shapes
//!   (`docs/data/shape-counts.tsv`, written by `bash scripts/shape-counts.sh`);
//! * `sprites-ratios`: the ratios of `cargo bench --bench sprites` (the same
//!   criterion medians), each sprite against its peer.
//!
//! ```text
//! cargo bench --bench shapes        # optional: refreshes the shape ratios
//! cargo bench --bench sprites       # optional: refreshes the sprite ratios
//! bash scripts/shape-counts.sh      # optional: refreshes the instruction counts
//! cargo run --example readme_2d     # rewrites the docs/shapes.md sections
//! ```
//!
//! A section whose numbers are missing (no bench run yet) is left as it is.

use std::error::Error;

#[path = "../benches/common/criterion_median.rs"]
mod criterion_median;
use criterion_median::median;
#[path = "common/group.rs"]
mod digits;
#[path = "common/shapes_ratios.rs"]
mod shapes_ratios;
use digits::group;
use shapes_ratios::ratio;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

const SCENE: &str = "examples/common/dashboard.rs";
/// The file the sections are in (the README links it).
const DOC: &str = "docs/shapes.md";

fn main() -> Result<()> {
    let source = std::fs::read_to_string(SCENE)?;
    let mut readme = std::fs::read_to_string(DOC)?;
    let (mr, eg) = (block(&source, "mr")?, block(&source, "eg")?);
    let (n_mr, n_eg) = (count(&mr), count(&eg));
    let verdict = if n_mr <= n_eg { "met" } else { "missed" };
    println!("dashboard: microraster {n_mr} lines, plain embedded-graphics {n_eg} lines: target {verdict}");
    let text = format!(
        "![the dashboard with microraster](dashboard.png) \
         ![the same screen in plain embedded-graphics](dashboard_eg.png)\n\n\
         Left: microraster, {n_mr} lines; right: plain embedded-graphics, {n_eg} lines \
         (non-blank, non-comment lines of `dashboard_showing` and `dashboard_eg_showing`, the speed and its readout as arguments, in \
         [`{SCENE}`](../{SCENE}); target, no more lines than e-g: **{verdict}**).\n\n\
         ```rust,ignore\n{}```\n",
        mr.iter().map(|l| format!("{l}\n")).collect::<String>()
    );
    replace(&mut readme, "dashboard", &text)?;
    match shapes_ratios::table("[below](#the-dashboard)") {
        Some(table) => {
            println!("shapes-ratios (cargo bench --bench shapes):\n{table}");
            replace(&mut readme, "shapes-ratios", &table)?
        }
        None => println!(
            "shapes-ratios: no complete `cargo bench --bench shapes` run found; section left as it is"
        ),
    }
    match shape_counts() {
        Some(table) => replace(&mut readme, "shape-counts", &table)?,
        None => println!(
            "shape-counts: no docs/data/shape-counts.tsv (bash scripts/shape-counts.sh); section left as it is"
        ),
    }
    match sprite_ratios() {
        Some(table) => replace(&mut readme, "sprites-ratios", &table)?,
        None => println!(
            "sprites-ratios: no complete `cargo bench --bench sprites` run found; section left as it is"
        ),
    }
    std::fs::write(DOC, readme)?;
    println!("{DOC} rewritten");
    Ok(())
}

/// The lines between `// dashboard:<name>:begin` and `…:end`.
fn block<'a>(source: &'a str, name: &str) -> Result<Vec<&'a str>> {
    let (begin, end) = (format!("// dashboard:{name}:begin"), format!("// dashboard:{name}:end"));
    let lines: Vec<&str> = source.lines().collect();
    let at = |m: &str| lines.iter().position(|l| l.trim() == m).ok_or(format!("no `{m}` in {SCENE}"));
    let (b, e) = (at(&begin)?, at(&end)?);
    if b >= e {
        return Err(format!("`{begin}` after `{end}`").into());
    }
    Ok(lines[b + 1..e].to_vec())
}

/// Non-blank lines that are not comments (`//`, `///`).
fn count(lines: &[&str]) -> usize {
    lines.iter().filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with("//")).count()
}

/// Replaces the text between `<!-- name:begin -->` and `<!-- name:end -->`.
fn replace(readme: &mut String, name: &str, text: &str) -> Result<()> {
    let (begin, end) = (format!("<!-- {name}:begin -->\n"), format!("<!-- {name}:end -->"));
    let b = readme.find(&begin).ok_or(format!("no `{begin}` in {DOC}"))? + begin.len();
    let e = readme[b..].find(&end).ok_or(format!("no `{end}` in {DOC}"))? + b;
    readme.replace_range(b..e, text);
    Ok(())
}

/// The instruction-count table of `bash scripts/shape-counts.sh`
/// (`docs/data/shape-counts.tsv`), with e-g / microraster ratios.
fn shape_counts() -> Option<String> {
    let tsv = std::fs::read_to_string("docs/data/shape-counts.tsv").ok()?;
    let mut rows = String::from(
        "| shape | e-g | direct | 16-row bands | prepared bands | e-g / direct | e-g / bands | e-g / prepared bands |\n\
         |---|--:|--:|--:|--:|--:|--:|--:|\n",
    );
    let mut empty = None;
    for line in tsv.lines().skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        let n: Vec<u64> = f.get(1..6)?.iter().map(|v| v.parse().ok()).collect::<Option<_>>()?;
        let r = |a: u64, b: u64| a as f64 / b as f64;
        rows += &format!(
            "| {} | {} | {} | {} | {} | {:.2} | {:.2} | {:.2} |\n",
            f[0],
            group(n[0]),
            group(n[1]),
            group(n[2]),
            group(n[3]),
            r(n[0], n[1]),
            r(n[0], n[2]),
            r(n[0], n[3])
        );
        empty = Some(group(n[4]));
    }
    rows += &format!(
        "\nThe empty frame in 16-row bands (each band cleared and copied out): {} instructions.\n",
        empty?
    );
    Some(rows)
}

/// The sprite ratio table (`benches/sprites.rs`), if all four were measured.
fn sprite_ratios() -> Option<String> {
    let m = |id: &str| median("sprite", id);
    let mut rows = String::from("| microraster sprite | peer | peer / microraster |\n|---|---|---|\n");
    let mut eg_faster = false;
    for (peer, ours, what, against) in [
        (
            "skia",
            "mr_bilinear",
            "scaled 1.5×, rotated 0.3 rad, bilinear, blended",
            "tiny-skia `draw_pixmap`, same transform and filter",
        ),
        (
            "eg",
            "mr_nearest",
            "unscaled, nearest, blended through the alpha mask",
            "e-g `Image` of opaque pixels (e-g has no alpha, scale or rotation)",
        ),
    ] {
        let r = ratio(m(peer), m(ours))?;
        eg_faster |= peer == "eg" && r < 1.0;
        rows += &format!("| {what} | {against} | **{r:.2}** |\n");
    }
    if eg_faster {
        rows += "\ne-g is faster unscaled: a sprite maps and blends every pixel of its box, where e-g copies rows.\n";
    }
    Some(rows)
}
