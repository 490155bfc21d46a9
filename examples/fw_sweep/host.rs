//! The host side of the sweep: the same configurations rendered on the host
//! (their frames' CRCs), and the check and write-out of the target counts.

use std::collections::HashMap;
use std::fmt::Write as _;

use crate::configs::{BG, Meter, all};
use crate::frame::FrameBuffer;

/// One configuration's frame on the host.
pub struct Frame {
    /// The report key.
    pub key: &'static str,
    /// CRC-32 of the frame.
    pub crc: u32,
    /// Pixels that differ from the background.
    pub covered: usize,
}

struct Untimed;

impl Meter for Untimed {
    fn start(&mut self) {}
    fn stop(&mut self) {}
}

/// Every configuration rendered on the host.
pub fn frames() -> Result<Vec<Frame>, String> {
    // The configurations keep a full-frame band and up to 10,000 primitives
    // on the stack, as on the target (4 MB of RAM): give them room.
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(|| {
            let mut fb = Box::new(FrameBuffer::new());
            all()
                .map(|c| {
                    (c.run)(&mut Untimed, &mut fb).map_err(|e| format!("{}: {e}", c.key))?;
                    Ok(Frame {
                        key: c.key,
                        crc: crate::crc(&fb),
                        covered: fb.pixels().iter().filter(|&&c| c != BG).count(),
                    })
                })
                .collect()
        })
        .map_err(|e| e.to_string())?
        .join()
        .map_err(|_| "the host run panicked".to_string())?
}

/// One target log: instructions by key, and its `#` notes.
struct Log {
    counts: HashMap<String, (u64, u32)>,
    notes: Vec<String>,
}

fn read_log(path: &str) -> Result<Log, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut log = Log { counts: HashMap::new(), notes: Vec::new() };
    for line in text.lines() {
        if let Some(note) = line.strip_prefix("# ") {
            log.notes.push(note.to_string());
            continue;
        }
        let bad = || format!("{path}: unexpected line {line:?}");
        let f: Vec<&str> = line.split_whitespace().collect();
        let ["sweep", key, instr, crc] = f[..] else { return Err(bad()) };
        let instr = instr.strip_prefix("instr=").and_then(|v| v.parse().ok()).ok_or_else(bad)?;
        let crc = crc.strip_prefix("crc=").and_then(|v| u32::from_str_radix(v, 16).ok()).ok_or_else(bad)?;
        log.counts.insert(key.to_string(), (instr, crc));
    }
    Ok(log)
}

/// Checks both logs against the host's frames (every key present, every CRC
/// equal) and writes the counts file the report reads.
pub fn write_tsv(out: &str, m4f: &str, m0: &str) -> Result<(), String> {
    let host = frames()?;
    let logs =
        [("m4f", read_log(m4f)?, "thumbv7em-none-eabihf"), ("m0", read_log(m0)?, "thumbv6m-none-eabi")];
    let mut text = String::from(
        "# Cortex-M instructions per frame of the report's configurations (keys: docs/tradeoffs.md).\n\
         # Written by `bash scripts/firmware.sh sweep` (examples/fw_sweep); do not edit.\n\
         # m4f: thumbv7em-none-eabihf (Cortex-M4F), m0: thumbv6m-none-eabi (Cortex-M0), both\n\
         # run on QEMU mps2-an386 with -icount shift=0; every frame's CRC equals the host's.\n",
    );
    for (core, log, triple) in &logs {
        for note in &log.notes {
            writeln!(text, "# {core} ({triple}): {note}").unwrap();
        }
    }
    text.push_str("# core\tkey\tinstructions_per_frame\n");
    for (core, log, _) in &logs {
        for f in &host {
            let (instr, crc) =
                log.counts.get(f.key).ok_or_else(|| format!("{core}: no count for {}", f.key))?;
            if *crc != f.crc {
                return Err(format!("{core}: {}: frame CRC {crc:08x}, host {:08x}", f.key, f.crc));
            }
            writeln!(text, "{core}\t{}\t{instr}", f.key).unwrap();
        }
        if log.counts.len() != host.len() {
            return Err(format!("{core}: {} counts for {} configurations", log.counts.len(), host.len()));
        }
    }
    std::fs::write(out, text).map_err(|e| format!("{out}: {e}"))?;
    eprintln!(
        "fw_sweep: {} configurations × 2 cores, frames identical to the host's; wrote {out}",
        host.len()
    );
    Ok(())
}
