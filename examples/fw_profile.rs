//! Where a firmware benchmark spends its instructions, by source location:
//! the per-function and per-line counts behind `docs/setup_cost.md`.
//!
//! `bash scripts/firmware.sh profile ROWS` builds `examples/fw_bench` for
//! the Cortex-M4F with line tables and in its profile mode (the selected
//! rows, one frame each, no clock calibration, stack painting or CRC pass),
//! runs it on QEMU with `-icount shift=0 -d in_asm,exec,nochain` and pipes
//! the log into this program:
//!
//! ```text
//! fw_profile ELF [ROWS_SHOWN] < qemu-log
//! ```
//!
//! QEMU lists each translation block's instructions once (`in_asm`) and
//! logs every execution of a block (`exec`; `nochain` keeps blocks from
//! jumping to each other unlogged), so a block's instructions times its
//! executions is what it costs; the total equals the `-icount` count of the
//! run. Each block is attributed to the source location of its first
//! instruction (`addr2line -i`: the innermost frame inside the crate's
//! `src/`, through inlining): blocks are a few instructions long, so a
//! location's count is exact up to the blocks that straddle two.
//!
//! With `MICRORASTER_PROFILE_BLOCKS=FILE` it also writes each block's start
//! address, instructions executed and length to `FILE`, costliest first.
//!
//! The total includes the start-up, listed as `Reset`: zeroing `.bss`,
//! about one instruction per byte (for `fw_bench`, whose `.bss` is about
//! 452 KB, 0.46 M), and the output of the row line.

use std::collections::HashMap;
use std::io::{BufRead, BufReader};
use std::process::Command;

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let elf = args.next().ok_or("usage: fw_profile ELF [ROWS_SHOWN] < qemu-log")?;
    let shown: usize = args.next().map_or(Ok(30), |s| s.parse()).map_err(|e| format!("rows shown: {e}"))?;
    let symbols = symbols(&elf)?;
    let (counts, calls, sizes) = read_log(BufReader::new(std::io::stdin().lock()), &symbols)?;
    let total: u64 = counts.values().sum();
    if let Ok(path) = std::env::var("MICRORASTER_PROFILE_BLOCKS") {
        // Per block: start address, instructions executed and the block's
        // length in instructions, costliest first
        // (to read beside `llvm-objdump -d` of the same ELF).
        let mut blocks: Vec<(u32, u64)> = counts.iter().map(|(&pc, &n)| (pc, n)).collect();
        blocks.sort_unstable_by_key(|&(pc, n)| (core::cmp::Reverse(n), pc));
        let text: String = blocks
            .iter()
            .map(|(pc, n)| format!("{pc:08x} {n} {}\n", sizes.get(pc).copied().unwrap_or(0)))
            .collect();
        std::fs::write(&path, text).map_err(|e| format!("writing {path}: {e}"))?;
    }
    let mut pcs: Vec<u32> = counts.keys().copied().collect();
    pcs.extend(calls.keys().map(|(caller, _)| *caller));
    pcs.sort_unstable();
    pcs.dedup();
    let locations = locate(&elf, pcs)?;
    let (mut by_function, mut by_line) = (HashMap::new(), HashMap::new());
    for (pc, n) in &counts {
        let (mut function, line) = locations.get(pc).cloned().unwrap_or_default();
        // No debug information (`$t`, a mapping symbol, or `??`): the
        // symbol the address lies in.
        if function.is_empty() || function.starts_with('$') || function.starts_with("??") {
            function = symbol_of(&symbols, *pc).map_or_else(|| "(unknown)".into(), short_function);
        }
        let file = line.split(':').next().unwrap_or_default();
        *by_function.entry(format!("{function} — {file}")).or_insert(0u64) += n;
        *by_line.entry(line).or_insert(0u64) += n;
    }
    // Library calls (compiler-builtins: soft float, 64-bit products and
    // shifts, divisions) by the source line that made them, each charged
    // its routine's mean cost: where the Cortex-M0's library time comes from.
    let mut by_routine: HashMap<&str, (u64, u64)> = HashMap::new();
    for ((_, callee), n) in &calls {
        by_routine.entry(callee.as_str()).or_default().1 += n;
    }
    for (pc, n) in &counts {
        if let Some(name) = symbol_of(&symbols, *pc).filter(|s| is_library(s)) {
            if let Some(r) = by_routine.get_mut(name) {
                r.0 += n;
            }
        }
    }
    let mut by_caller = HashMap::new();
    for ((caller, callee), n) in &calls {
        let (cost, entries) = by_routine.get(callee.as_str()).copied().unwrap_or_default();
        let line = locations.get(caller).map_or_else(String::new, |l| l.1.clone());
        *by_caller.entry(format!("{line} → {callee}")).or_insert(0u64) += cost * n / entries.max(1);
    }
    println!("{total} instructions executed ({elf})\n");
    print_table("function (innermost inside the crate's src/) — file", by_function, total, shown);
    print_table("source line", by_line, total, shown);
    print_table("library calls by calling line (each at its routine's mean cost)", by_caller, total, shown);
    Ok(())
}

/// A compiler-builtins routine (`__aeabi_lmul`, `__addsf3`, …).
fn is_library(symbol: &str) -> bool {
    symbol.starts_with("__") && !symbol.starts_with("__cortex")
}

/// Instructions executed per block start address, from QEMU's log, and the
/// entries into library routines ([`is_library`]) per `(calling block,
/// routine)`: the block logged before a routine's first block; and each
/// block's length in instructions.
type Calls = HashMap<(u32, String), u64>;
type Log = (HashMap<u32, u64>, Calls, HashMap<u32, u64>);
fn read_log(log: impl BufRead, symbols: &[(u32, u32, String)]) -> Result<Log, String> {
    let (mut size, mut counts) = (HashMap::<u32, u64>::new(), HashMap::<u32, u64>::new());
    let (mut calls, mut previous) = (Calls::new(), None::<u32>);
    // The block being listed: its first address and instructions so far.
    let mut listing: Option<(u32, u64)> = None;
    for line in log.lines() {
        let line = line.map_err(|e| format!("reading the log: {e}"))?;
        if let Some(hex) = line.strip_prefix("0x") {
            // `0x000012a4:  b580  push {r7, lr}`: one instruction of a listing.
            let pc = hex.get(..8).and_then(|h| u32::from_str_radix(h, 16).ok());
            listing = match (listing, pc) {
                (Some((start, n)), _) => Some((start, n + 1)),
                (None, Some(pc)) => Some((pc, 1)),
                (None, None) => None,
            };
            continue;
        }
        if let Some((start, n)) = listing.take() {
            size.insert(start, n);
        }
        // `Trace 0: 0x7f.. [00800408/000012a4/00000110/ff000200] name`
        if line.starts_with("Trace") {
            let pc = line
                .split_once('[')
                .and_then(|(_, rest)| rest.split('/').nth(1))
                .and_then(|h| u32::from_str_radix(h, 16).ok())
                .ok_or_else(|| format!("unreadable trace line: {line}"))?;
            let n =
                size.get(&pc).copied().ok_or_else(|| format!("block {pc:#x} ran before it was listed"))?;
            *counts.entry(pc).or_insert(0) += n;
            if let Some(i) =
                symbols.binary_search_by_key(&pc, |s| s.0).ok().filter(|&i| is_library(&symbols[i].2))
            {
                if let Some(caller) =
                    previous.filter(|&c| symbol_of(symbols, c) != Some(symbols[i].2.as_str()))
                {
                    *calls.entry((caller, symbols[i].2.clone())).or_insert(0) += 1;
                }
            }
            previous = Some(pc);
        }
    }
    Ok((counts, calls, size))
}

/// `(function, file:line)` of each address: its innermost inlined frame
/// inside `src/`, else its outermost frame.
fn locate(elf: &str, pcs: Vec<u32>) -> Result<HashMap<u32, (String, String)>, String> {
    let mut out = HashMap::new();
    for chunk in pcs.chunks(4096) {
        let output = Command::new("addr2line")
            .args(["-a", "-i", "-f", "-C", "-e", elf])
            .args(chunk.iter().map(|pc| format!("{pc:#x}")))
            .output()
            .map_err(|e| format!("addr2line (binutils): {e}"))?;
        let text = String::from_utf8_lossy(&output.stdout);
        let mut lines = text.lines().peekable();
        while let Some(address) = lines.next() {
            let pc = u32::from_str_radix(address.trim_start_matches("0x"), 16)
                .map_err(|_| format!("addr2line: unexpected line {address}"))?;
            let mut frames = Vec::new();
            while let Some(next) = lines.peek() {
                if next.starts_with("0x") {
                    break;
                }
                let function = lines.next().unwrap_or_default();
                let place = lines.next().unwrap_or_default();
                frames.push((function.to_string(), place.to_string()));
            }
            let pick = frames
                .iter()
                .find(|(_, place)| in_crate(place).is_some())
                .or(frames.last())
                .cloned()
                .unwrap_or_default();
            out.insert(pc, (short_function(&pick.0), short_place(&pick.1)));
        }
    }
    Ok(out)
}

/// The ELF's function symbols: `(start, size, name)`, sorted (`nm`).
fn symbols(elf: &str) -> Result<Vec<(u32, u32, String)>, String> {
    let output = Command::new("nm")
        .args(["-C", "-S", "--defined-only", elf])
        .output()
        .map_err(|e| format!("nm (binutils): {e}"))?;
    let mut out: Vec<_> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|l| {
            let mut f = l.splitn(4, ' ');
            let (a, s, kind, name) = (f.next()?, f.next()?, f.next()?, f.next()?);
            let (a, s) = (u32::from_str_radix(a, 16).ok()?, u32::from_str_radix(s, 16).ok()?);
            matches!(kind, "t" | "T" | "w" | "W").then(|| (a & !1, s, name.to_string()))
        })
        .collect();
    out.sort();
    Ok(out)
}

/// The symbol whose extent holds `pc`.
fn symbol_of(symbols: &[(u32, u32, String)], pc: u32) -> Option<&str> {
    let i = symbols.partition_point(|s| s.0 <= pc).checked_sub(1)?;
    let (start, size, name) = &symbols[i];
    (pc < start + size.max(&1)).then_some(name.as_str())
}

/// A function name without its generic arguments' paths.
fn short_function(f: &str) -> String {
    let mut out = String::new();
    let mut depth = 0;
    for c in f.chars() {
        match c {
            '<' => {
                if depth == 0 {
                    out.push_str("<…>");
                }
                depth += 1;
            }
            '>' => depth -= 1,
            _ if depth == 0 => out.push(c),
            _ => {}
        }
    }
    out
}

/// A source place inside this crate's `src/` (the ELF and this program are
/// built from the same checkout), as `src/path/file.rs:line`; `None` for
/// the standard library, dependencies (whose registry paths also hold a
/// `/src/`) and the examples.
fn in_crate(place: &str) -> Option<&str> {
    place.strip_prefix(concat!(env!("CARGO_MANIFEST_DIR"), "/")).filter(|p| p.starts_with("src/"))
}

/// `src/path/file.rs:line` inside this crate ([`in_crate`]), else the file
/// name and line.
fn short_place(p: &str) -> String {
    let p = p.split(" (").next().unwrap_or(p);
    in_crate(p).unwrap_or_else(|| p.rsplit('/').next().unwrap_or(p)).to_string()
}

fn print_table(title: &str, counts: HashMap<String, u64>, total: u64, shown: usize) {
    let mut rows: Vec<_> = counts.into_iter().collect();
    rows.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    println!("| {title} | instructions | share |\n|---|--:|--:|");
    for (name, n) in rows.iter().take(shown) {
        let name = if name.is_empty() { "(no line information)" } else { name };
        println!("| `{name}` | {n} | {:.1} % |", *n as f64 * 100.0 / total.max(1) as f64);
    }
    println!();
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Blocks cost their length times their runs; a block re-listed
    /// (retranslated) counts with its new length from then on.
    #[test]
    fn counts_block_lengths_times_executions() {
        let log = "\
----------------
IN: main
0x00000400:  f049 ffa5  bl       #0x4a34e
0x00000404:  480e       ldr      r0, [pc, #0x38]

Trace 0: 0x7f5954000100 [00800408/00000400/00000110/ff000200] main
----------------
IN: f
0x00001000:  b580       push     {r7, lr}
0x00001002:  466f       mov      r7, sp
0x00001004:  bd80       pop      {r7, pc}

Trace 0: 0x7f5954000240 [00800408/00001000/00000110/ff000200] f
Trace 0: 0x7f5954000240 [00800408/00001000/00000110/ff000200] f
Trace 0: 0x7f5954000100 [00800408/00000400/00000110/ff000200] main
----------------
IN: main
0x00000400:  f049 ffa5  bl       #0x4a34e

Trace 0: 0x7f5954000300 [00800408/00000400/00000110/ff000200] main
";
        // `f` as a library routine: entered once from `main`'s block (its
        // second run follows its own block, not a call).
        let symbols = vec![(0x400, 0x10, "main".to_string()), (0x1000, 0x10, "__f".to_string())];
        let (counts, calls, sizes) = read_log(log.as_bytes(), &symbols).unwrap();
        assert_eq!(counts.get(&0x1000), Some(&6));
        assert_eq!(counts.get(&0x400), Some(&(2 + 2 + 1)));
        assert_eq!(counts.values().sum::<u64>(), 11);
        assert_eq!(calls.into_iter().collect::<Vec<_>>(), [((0x400, "__f".to_string()), 1)]);
        // Block lengths: as listed last (`main`'s second listing is one instruction).
        assert_eq!(sizes.get(&0x1000), Some(&3));
        let (_, none, _) = read_log(log.as_bytes(), &[]).unwrap();
        assert!(none.is_empty());
    }

    #[test]
    fn a_block_run_before_its_listing_is_an_error() {
        let log = "Trace 0: 0x7f59 [00800408/00002000/00000110/ff000200] g\n";
        assert!(read_log(log.as_bytes(), &[]).unwrap_err().contains("0x2000"));
    }

    #[test]
    fn names_and_places_are_shortened() {
        assert_eq!(short_function("draw_cached<f32, microraster::X<4>>"), "draw_cached<…>");
        assert_eq!(
            short_place(concat!(env!("CARGO_MANIFEST_DIR"), "/src/raster/attr.rs:188 (discriminator 2)")),
            "src/raster/attr.rs:188"
        );
        assert_eq!(short_place("/x/rustlib/src/rust/library/core/src/slice/index.rs:219"), "index.rs:219");
        // A dependency's `src/` is not the crate's.
        let dep = "/root/.cargo/registry/src/index/embedded-graphics-core-0.4.0/src/draw_target/mod.rs:52";
        assert_eq!(short_place(dep), "mod.rs:52");
        let symbols = vec![(0x100, 0x20, "a".to_string()), (0x200, 0x10, "b".to_string())];
        assert_eq!(symbol_of(&symbols, 0x110), Some("a"));
        assert_eq!(symbol_of(&symbols, 0x150), None);
        assert_eq!(symbol_of(&symbols, 0x20f), Some("b"));
    }
}
