//! The Cortex-M instruction counts (issue 5, part 2; the firmware
//! benchmark's rows, issue 12: [`FwBench`]).
//!
//! `bash scripts/firmware.sh sweep` (`examples/fw_sweep`) writes
//! `docs/data/cortex-m.tsv`, one measurement per line, tab-separated, `#`
//! comments allowed:
//!
//! ```text
//! # core  key                                        instructions_per_frame
//! m4f     mesh3d/f32/D16/persp/band16/S4             12345678
//! m0      scatter/band16/S4/flat                     23456789
//! ```
//!
//! `core` is `m4f` or `m0`; `key` is one of the configuration keys printed
//! in the tables of `docs/tradeoffs.md` (column "key"). The report fills its
//! Cortex-M columns from this file (per frame, per triangle and per covered
//! pixel, dividing by the host's triangle and pixel counts, which do not
//! depend on the CPU) and prints "pending" where no count exists. No count
//! is ever estimated here.

use std::collections::HashMap;
use std::path::Path;

/// Instructions per frame by `(core, key)`.
#[derive(Default)]
pub struct Counts(HashMap<(String, String), u64>);

impl Counts {
    /// Reads the file if it exists (an absent file means: all pending).
    pub fn load(path: &Path) -> Result<Self, String> {
        let Ok(text) = std::fs::read_to_string(path) else { return Ok(Counts::default()) };
        let mut map = HashMap::new();
        for (i, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let f: Vec<&str> = line.split_whitespace().collect();
            let [core, key, n] = f[..] else {
                return Err(format!("{}:{}: expected 3 fields", path.display(), i + 1));
            };
            let n = n.parse().map_err(|e| format!("{}:{}: {e}", path.display(), i + 1))?;
            map.insert((core.to_string(), key.to_string()), n);
        }
        Ok(Counts(map))
    }

    /// True if any count was loaded.
    pub fn any(&self) -> bool {
        !self.0.is_empty()
    }

    /// Instructions per frame, if measured.
    pub fn get(&self, core: &str, key: &str) -> Option<u64> {
        self.0.get(&(core.to_string(), key.to_string())).copied()
    }

    /// The table cell for `core` and `key`: instructions per frame, or "pending".
    pub fn cell(&self, core: &str, key: &str) -> String {
        self.get(core, key).map_or("pending".into(), |n| n.to_string())
    }
}

/// One configuration of `examples/fw_bench` (the README's firmware table),
/// as `bash scripts/firmware.sh table` writes it to `docs/data/fw-bench.tsv`:
/// `core key instructions triangles covered static_ram stack`, tab-separated.
#[derive(Clone, Copy, Debug)]
pub struct FwRow {
    /// Instructions per frame.
    pub instructions: u64,
    /// Triangles of the frame (the mesh's, for the knot).
    pub triangles: u64,
    /// Pixels unlike the background (0 where nothing is drawn).
    pub covered: u64,
    /// Bytes of the static buffers the configuration uses.
    pub static_ram: u64,
}

/// The firmware benchmark's rows by `(core, key)`, and the peer counts
/// they are judged against ([`FwBench::with_tgx`]).
#[derive(Default)]
pub struct FwBench(HashMap<(String, String), FwRow>, HashMap<String, FwRow>);

impl FwBench {
    /// Reads the file if it exists (an absent file means: all pending).
    pub fn load(path: &Path) -> Result<Self, String> {
        let Ok(text) = std::fs::read_to_string(path) else { return Ok(FwBench::default()) };
        let mut map = HashMap::new();
        for (i, line) in text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'))
        {
            let bad = |e: &dyn std::fmt::Display| format!("{}:{}: {e}", path.display(), i + 1);
            let f: Vec<&str> = line.split('\t').collect();
            let [core, key, n @ ..] = &f[..] else { return Err(bad(&"expected 7 fields")) };
            let n: Vec<u64> = n.iter().map(|x| x.parse().map_err(|e| bad(&e))).collect::<Result<_, _>>()?;
            let [instructions, triangles, covered, static_ram, _stack] = n[..] else {
                return Err(bad(&"expected 7 fields"));
            };
            map.insert(
                (core.to_string(), key.to_string()),
                FwRow { instructions, triangles, covered, static_ram },
            );
        }
        Ok(FwBench(map, HashMap::new()))
    }

    /// With TGX's fixed counts on the same knot (`docs/data/peers-tgx.tsv`:
    /// `eye instructions triangles covered buffers_ram`, tab-separated; its
    /// header says how and where they were measured). An absent file
    /// leaves them pending.
    pub fn with_tgx(mut self, path: &Path) -> Result<Self, String> {
        let Ok(text) = std::fs::read_to_string(path) else { return Ok(self) };
        for (i, line) in text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'))
        {
            let bad = |e: &dyn std::fmt::Display| format!("{}:{}: {e}", path.display(), i + 1);
            let f: Vec<&str> = line.split('\t').collect();
            let [eye, n @ ..] = &f[..] else { return Err(bad(&"expected 5 fields")) };
            let n: Vec<u64> = n.iter().map(|x| x.parse().map_err(|e| bad(&e))).collect::<Result<_, _>>()?;
            let [instructions, triangles, covered, static_ram] = n[..] else {
                return Err(bad(&"expected 5 fields"));
            };
            self.1.insert(eye.to_string(), FwRow { instructions, triangles, covered, static_ram });
        }
        Ok(self)
    }

    /// TGX's frame from `eye` (`standard` or `close`), if loaded.
    pub fn tgx(&self, eye: &str) -> Option<FwRow> {
        self.1.get(eye).copied()
    }

    /// The first row of `core` whose key starts with `prefix` and contains
    /// every one of `words` (rows another change may name a little
    /// differently).
    pub fn find(&self, core: &str, prefix: &str, words: &[&str]) -> Option<(String, FwRow)> {
        let mut hits: Vec<_> = self
            .0
            .iter()
            .filter(|((c, k), _)| c == core && k.starts_with(prefix) && words.iter().all(|w| k.contains(w)))
            .map(|((_, k), r)| (k.clone(), *r))
            .collect();
        hits.sort_by(|a, b| a.0.cmp(&b.0));
        hits.into_iter().next()
    }

    /// One configuration, if measured.
    pub fn get(&self, core: &str, key: &str) -> Option<FwRow> {
        self.0.get(&(core.to_string(), key.to_string())).copied()
    }
}
