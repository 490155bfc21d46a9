//! Configuration mistakes caught at compile time: each `tests/compile_fail/*.rs`
//! is compiled against this build of microraster with `rustc`, and must fail
//! with the message its first line names (`// error: <text>`), or compile
//! (`// pass`: the control case; `// pass (gap)`: a mistake that should be
//! a compile error but is not yet, see the file).
//!
//! No extra dependency: the harness finds the `.rlib`s Cargo built for this
//! test binary next to it (`target/<profile>/deps`) and calls the `rustc` on
//! `PATH` (under `cargo +toolchain test`, rustup's proxy picks the same
//! toolchain). Code generation is needed (`--emit=obj`): the checks are
//! `const` assertions evaluated at monomorphization, which `cargo check`
//! (`--emit=metadata`) does not reach.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::SystemTime;

/// Every `lib<name>-*.rlib` in `dir`, newest first.
fn rlibs(dir: &Path, name: &str) -> Vec<PathBuf> {
    let prefix = format!("lib{name}-");
    let mut v: Vec<(SystemTime, PathBuf)> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            let f = p.file_name().unwrap().to_string_lossy();
            f.starts_with(&prefix) && f.ends_with(".rlib")
        })
        .map(|p| (p.metadata().and_then(|m| m.modified()).unwrap_or(SystemTime::UNIX_EPOCH), p))
        .collect();
    v.sort_by_key(|e| std::cmp::Reverse(e.0));
    assert!(!v.is_empty(), "no {prefix}*.rlib in {}", dir.display());
    v.into_iter().map(|(_, p)| p).collect()
}

/// A deps directory can hold several builds of each crate (profiles, other
/// tools); find one consistent set: the first combination, newest first,
/// with which the control case compiles.
fn consistent_externs(deps: &Path, compiles: impl Fn(&[String]) -> bool) -> Vec<String> {
    let names = ["microraster", "embedded_graphics_core", "embedded_graphics", "heapless"];
    let cands: Vec<Vec<PathBuf>> = names.iter().map(|n| rlibs(deps, n)).collect();
    let mut idx = [0usize; 4];
    loop {
        let ext: Vec<String> =
            (0..4).map(|i| format!("{}={}", names[i], cands[i][idx[i]].display())).collect();
        if compiles(&ext) {
            return ext;
        }
        // Next combination (odometer, the last crate fastest).
        let mut i = 3;
        loop {
            idx[i] += 1;
            if idx[i] < cands[i].len() {
                break;
            }
            idx[i] = 0;
            if i == 0 {
                panic!("no consistent set of rlibs in {} compiles the control case", deps.display());
            }
            i -= 1;
        }
    }
}

enum Expect {
    Error(String),
    Pass { gap: bool },
}

fn expectation(src: &str) -> Expect {
    let first = src.lines().next().unwrap_or_default();
    if let Some(msg) = first.strip_prefix("// error: ") {
        Expect::Error(msg.trim().to_owned())
    } else if first.starts_with("// pass") {
        Expect::Pass { gap: first.contains("gap") }
    } else {
        panic!("first line must be `// error: <text>` or `// pass`: {first:?}")
    }
}

#[test]
fn configuration_mistakes_are_compile_errors() {
    let deps = std::env::current_exe().unwrap().parent().unwrap().to_path_buf();
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("compile_fail");
    std::fs::create_dir_all(&out).unwrap();
    let cases_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/compile_fail");
    let mut cases: Vec<PathBuf> = std::fs::read_dir(&cases_dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect();
    cases.sort();
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let compile = |case: &Path, externs: &[String]| {
        let mut cmd = Command::new(&rustc);
        cmd.args([
            "--edition",
            "2024",
            "--crate-type",
            "bin",
            "--emit=obj",
            "-C",
            "opt-level=0",
            "--cap-lints",
            "allow",
        ])
        .arg("-L")
        .arg(format!("dependency={}", deps.display()))
        .arg("-o")
        .arg(out.join(case.file_stem().unwrap()).with_extension("o"))
        .arg(case);
        for e in externs {
            cmd.arg("--extern").arg(e);
        }
        cmd.output().unwrap()
    };
    let control = cases_dir.join("ok_valid_configurations.rs");
    let externs = consistent_externs(&deps, |ext| compile(&control, ext).status.success());
    let run = |case: &Path| compile(case, &externs);
    // Two at a time (the test machine has two cores).
    let results: Vec<_> = std::thread::scope(|s| {
        let handles: Vec<_> = cases
            .chunks(cases.len().div_ceil(2).max(1))
            .map(|chunk| s.spawn(|| chunk.iter().map(|c| (c.clone(), run(c))).collect::<Vec<_>>()))
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let (mut errors, mut passes, mut gaps) = (0, 0, 0);
    for (case, output) in &results {
        let name = case.file_name().unwrap().to_string_lossy();
        let stderr = String::from_utf8_lossy(&output.stderr);
        match expectation(&std::fs::read_to_string(case).unwrap()) {
            Expect::Error(msg) => {
                assert!(!output.status.success(), "{name}: compiled, but must fail with `{msg}`");
                assert!(stderr.contains(&msg), "{name}: failed, but without `{msg}`:\n{stderr}");
                println!("compile_fail {name}: error `{msg}` as expected");
                errors += 1;
            }
            Expect::Pass { gap } => {
                assert!(
                    output.status.success(),
                    "{name}: must compile{}:\n{stderr}",
                    if gap {
                        " (a documented gap: if it is now an error, the gap is fixed; update the header)"
                    } else {
                        ""
                    }
                );
                println!("compile_fail {name}: compiles{}", if gap { " (documented gap)" } else { "" });
                if gap { gaps += 1 } else { passes += 1 }
            }
        }
    }
    println!(
        "compile_fail: {errors} configuration mistakes rejected, {passes} control case(s) compile, {gaps} documented gap(s)"
    );
    assert!(errors >= 10 && passes >= 1, "cases missing in {}", cases_dir.display());
}
