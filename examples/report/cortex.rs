//! The Cortex-M instruction counts (issue 5, part 2).
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
