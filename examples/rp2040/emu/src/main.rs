//! Runs microraster's RP2040 example (examples/rp2040 built with
//! `--features emu`) in the `rp2040-emu` crate and checks it:
//!
//! ```text
//! microraster-rp2040-emu ROM ELF EXPECTED BUDGET [FRAMES]
//! ```
//!
//! * ROM: the 16 KB RP2040 boot ROM (rp2040-hal calls its routines, the
//!   float ones among them); `bash scripts/firmware.sh rp2040` fetches it.
//! * ELF: the firmware. Its loadable segments are laid at their flash
//!   addresses into an image of the XIP flash, which the emulator boots
//!   directly (its `direct_boot_from_flash`: stack pointer, VTOR and reset
//!   vector from the vector table after the 256-byte boot2, which is
//!   skipped: the emulator models no QSPI flash for it).
//! * EXPECTED: the host's records (`cargo run -- crc N` of examples/rp2040):
//!   `FRAME scene band y0 rows crc32 pixels`, one line per band and one per
//!   frame.
//! * BUDGET: `CORES MAX_CYCLES` lines, the emulator cycles a steady frame
//!   (every frame after the first) may take.
//!
//! The firmware runs twice, with core 0 alone and with both cores (the
//! host tells it through the mailbox, ../src/mailbox.rs, where the firmware
//! also reports each band's record and what each core is doing). Each run
//! renders FRAMES frames (default 4); every band's record must equal the
//! host's, every steady frame must stay within the budget, and a frame must
//! arrive within [`TIMEOUT`] cycles. It prints each frame's emulator cycles,
//! how each core spent them, and a table of both runs. Exit status 1 on any
//! failure.
//!
//! The counts are the emulator's: its cores run in lockstep (each step
//! advances the clock by the longer of the two cores' instructions), it
//! charges branches 3/3/4 cycles where the Cortex-M0+ takes 2/2/3, and
//! flash costs nothing.

use std::collections::BTreeMap;
use std::process::ExitCode;
use std::time::Instant;

use rp2040_emu::{Config, Emulator};

#[path = "../../src/mailbox.rs"]
#[allow(dead_code)]
mod mailbox;

use mailbox::*;

/// Emulator cycles without a new frame after which the run fails: the
/// first frame boots and waits 250 ms for the panel (31 M cycles at
/// 125 MHz) before it renders.
const TIMEOUT: u64 = 400_000_000;
/// Where the firmware's flash image starts (XIP).
const FLASH: u32 = 0x1000_0000;
/// Offset of the vector table in flash (after boot2).
const VECTORS: u32 = 0x100;

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("rp2040-emu run: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<bool, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (rom, elf, expected, budget, frames) = match args.as_slice() {
        [r, e, x, b] => (r, e, x, b, 4),
        [r, e, x, b, n] => (r, e, x, b, n.parse().map_err(|e| format!("FRAMES: {e}"))?),
        _ => return Err("usage: microraster-rp2040-emu ROM ELF EXPECTED BUDGET [FRAMES]".into()),
    };
    let rom = std::fs::read(rom).map_err(|e| format!("{rom}: {e}"))?;
    if rom.len() != 16 * 1024 {
        return Err(format!("the boot ROM has {} bytes, not 16384", rom.len()));
    }
    let flash = flash_image(&std::fs::read(elf).map_err(|e| format!("{elf}: {e}"))?)?;
    let expected = read_expected(expected)?;
    let budget = read_budget(budget)?;
    let mut ok = true;
    let mut runs = Vec::new();
    for cores in [1, 2] {
        let limit = *budget.get(&cores).ok_or_else(|| format!("no budget for {cores} core(s)"))?;
        let run = emulate(&rom, &flash, cores, frames, limit, &expected)?;
        ok &= run.failed.is_empty();
        runs.push(run);
    }
    table(&runs);
    Ok(ok)
}

/// The XIP flash image of a little-endian ELF32: every loadable segment's
/// file bytes at its physical (load) address.
fn flash_image(elf: &[u8]) -> Result<Vec<u8>, String> {
    let u16_at = |o: usize| elf.get(o..o + 2).map(|b| u16::from_le_bytes([b[0], b[1]]));
    let u32_at = |o: usize| elf.get(o..o + 4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    if elf.get(..6) != Some(&[0x7F, b'E', b'L', b'F', 1, 1]) {
        return Err("not a little-endian ELF32 file".into());
    }
    let bad = || "truncated ELF".to_string();
    let phoff = u32_at(0x1C).ok_or_else(bad)? as usize;
    let phentsize = u16_at(0x2A).ok_or_else(bad)? as usize;
    let phnum = u16_at(0x2C).ok_or_else(bad)? as usize;
    let mut image = Vec::new();
    for i in 0..phnum {
        let ph = phoff + i * phentsize;
        let [kind, offset, _, paddr, filesz] = [0, 4, 8, 12, 16].map(|f| u32_at(ph + f));
        let (Some(kind), Some(offset), Some(paddr), Some(filesz)) = (kind, offset, paddr, filesz) else {
            return Err(bad());
        };
        if kind != 1 || filesz == 0 {
            continue; // not PT_LOAD, or nothing to load (.bss)
        }
        if !(FLASH..FLASH + 0x0100_0000).contains(&paddr) {
            return Err(format!("a segment loads at {paddr:#010x}, outside the flash"));
        }
        let at = (paddr - FLASH) as usize;
        let bytes = elf.get(offset as usize..(offset + filesz) as usize).ok_or_else(bad)?;
        if image.len() < at + bytes.len() {
            image.resize(at + bytes.len(), 0xFF);
        }
        image[at..at + bytes.len()].copy_from_slice(bytes);
    }
    if image.len() <= VECTORS as usize {
        return Err("no program after boot2".into());
    }
    Ok(image)
}

/// The host's records, by frame: `FRAME record...` lines.
fn read_expected(path: &str) -> Result<BTreeMap<usize, Vec<String>>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut frames: BTreeMap<usize, Vec<String>> = BTreeMap::new();
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        let (frame, record) = line.split_once(' ').ok_or_else(|| format!("{path}: bad line {line:?}"))?;
        let frame = frame.parse().map_err(|_| format!("{path}: bad line {line:?}"))?;
        frames.entry(frame).or_default().push(record.to_string());
    }
    Ok(frames)
}

/// `CORES MAX_CYCLES` lines; `#` starts a comment.
fn read_budget(path: &str) -> Result<BTreeMap<usize, u64>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut budget = BTreeMap::new();
    for line in text.lines().map(|l| l.split('#').next().unwrap_or("").trim()).filter(|l| !l.is_empty()) {
        let bad = || format!("{path}: bad line {line:?}");
        let (cores, cycles) = line.split_once(char::is_whitespace).ok_or_else(bad)?;
        budget.insert(cores.parse().map_err(|_| bad())?, cycles.trim().parse().map_err(|_| bad())?);
    }
    Ok(budget)
}

/// The states a core reports, in the order they are printed: the vertex
/// stage, rasterising its bands, waiting for its turn at the panel,
/// sending its band (SPI and CRC).
const STATES: [u32; 4] = [VERTEX, RENDER, WAIT, SEND];

/// Emulator cycles of one frame, and how each core spent them.
#[derive(Clone, Copy, Default)]
struct Frame {
    /// Master-clock cycles since the previous frame (since reset for the first).
    cycles: u64,
    /// Per core, master-clock cycles in each of [`STATES`] (the rest of the
    /// frame is before the core started).
    state: [[u64; 4]; 2],
    /// Per core, its own cycles (the sum of its instructions' costs) in each
    /// of [`STATES`]: below `state` when the lockstep clock waited for the
    /// other core's longer instructions.
    own: [[u64; 4]; 2],
}

struct Run {
    cores: usize,
    frames: Vec<Frame>,
    budget: u64,
    /// What failed: empty if every frame passed.
    failed: Vec<&'static str>,
    seconds: f64,
}

fn word(i: usize) -> u32 {
    BASE + 4 * i as u32
}

/// A failure: a band record differs from the host's.
const CRC: &str = "band records differ from the host's";
/// A failure: a steady frame took more cycles than the budget.
const BUDGET: &str = "a steady frame over the cycle budget";

/// One run: `cores` cores, `frames` frames.
fn emulate(
    rom: &[u8],
    flash: &[u8],
    cores: usize,
    frames: usize,
    budget: u64,
    expected: &BTreeMap<usize, Vec<String>>,
) -> Result<Run, String> {
    let start = Instant::now();
    let mut emu = Emulator::new(Config::default());
    emu.load_bootrom(rom);
    emu.load_flash(flash);
    emu.reset();
    emu.direct_boot_from_flash(VECTORS);
    for i in 0..SLOT0 + SLOTS * SLOT_WORDS {
        emu.poke(word(i), 0);
    }
    emu.poke(word(CONFIG), MAGIC);
    emu.poke(word(CORES), cores as u32);

    let mut failed = Vec::new();
    let mut done = Vec::new();
    let mut frame = Frame::default();
    let mut last = 0u64; // master cycle of the previous frame's end
    let mut own = [emu.core_cycles(0), emu.core_cycles(1)];
    while done.len() < frames {
        let states = [emu.peek(word(STATE)), emu.peek(word(STATE + 1))];
        let consumed = emu.step().map_err(|e| e.to_string())?;
        let now_own = [emu.core_cycles(0), emu.core_cycles(1)];
        for core in 0..2 {
            if let Some(s) = STATES.iter().position(|&s| s == states[core]) {
                frame.state[core][s] += consumed;
                frame.own[core][s] += now_own[core] - own[core];
            }
        }
        own = now_own;
        if emu.peek(word(PANIC)) == PANICKED {
            println!("rp2040-emu {cores} core(s): the firmware panicked in frame {}", done.len());
            return Ok(Run {
                cores,
                frames: done,
                budget,
                failed: vec!["the firmware panicked"],
                seconds: start.elapsed().as_secs_f64(),
            });
        }
        let now = emu.cycles();
        let finished = emu.peek(word(FRAMES)) as usize;
        if finished == done.len() {
            if now - last > TIMEOUT {
                println!(
                    "rp2040-emu {cores} core(s): no frame {} within {TIMEOUT} emulator cycles (timeout)",
                    done.len()
                );
                return Ok(Run {
                    cores,
                    frames: done,
                    budget,
                    failed: vec!["timeout: a frame did not arrive"],
                    seconds: start.elapsed().as_secs_f64(),
                });
            }
            continue;
        }
        if finished != done.len() + 1 {
            return Err(format!("frame count jumped from {} to {finished}", done.len()));
        }
        let n = done.len();
        frame.cycles = now - last;
        last = now;
        let records = records(&emu, n);
        let want = expected.get(&n).map(Vec::as_slice).unwrap_or(&[]);
        let same = records == want;
        if !same && !failed.contains(&CRC) {
            failed.push(CRC);
        }
        if !same {
            println!(
                "rp2040-emu {cores} core(s), frame {n}: records differ from the host's (emulator | host):"
            );
            for i in 0..records.len().max(want.len()) {
                let (got, host) = (records.get(i).map_or("-", |s| s), want.get(i).map_or("-", |s| s));
                println!("  {}{got} | {host}", if got == host { "  " } else { "! " });
            }
        }
        let over = n > 0 && frame.cycles > budget;
        if over && !failed.contains(&BUDGET) {
            failed.push(BUDGET);
        }
        println!(
            "rp2040-emu {cores} core(s), frame {n}: {} emulator cycles{}{}; {} band records {}; \
             vertex/raster/wait/send: {}",
            group(frame.cycles),
            if n == 0 { " (boot, panel set-up and frame)" } else { "" },
            if over { format!(", OVER the budget of {}", group(budget)) } else { String::new() },
            records.len(),
            if same { "identical to the host's" } else { "DIFFERENT from the host's" },
            (0..cores).map(|c| spent(c, &frame.state[c], &frame.own[c])).collect::<Vec<_>>().join("; "),
        );
        done.push(frame);
        frame = Frame::default();
    }
    Ok(Run { cores, frames: done, budget, failed, seconds: start.elapsed().as_secs_f64() })
}

/// Frame `n`'s records from its mailbox slot, as the host prints them.
fn records(emu: &Emulator, n: usize) -> Vec<String> {
    const SCENE: &str = "rp2040/320x240";
    let slot = SLOT0 + (n % SLOTS) * SLOT_WORDS;
    let bands = 240 / 16;
    let mut out = Vec::new();
    for band in 0..bands {
        let w = |k: usize| emu.peek(word(slot + 4 * band + k));
        out.push(format!("{SCENE} {band} {} {} {:08x} {}", w(0) as i32, w(1), w(2), w(3)));
    }
    let w = |k: usize| emu.peek(word(slot + 4 * bands + k));
    out.push(format!("{SCENE} frame 0 {} {:08x} {}", w(0), w(1), w(2)));
    out
}

/// Core `c`'s cycles by state, its own in parentheses.
fn spent(c: usize, state: &[u64; 4], own: &[u64; 4]) -> String {
    let all = |v: &[u64; 4]| v.iter().map(|&n| group(n)).collect::<Vec<_>>().join(" / ");
    format!("core {c} {} (own {})", all(state), all(own))
}

/// `1234567` as `1,234,567`.
fn group(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// The README's rows: steady frames (all but the first) of each run, means.
fn table(runs: &[Run]) {
    let mean = |run: &Run, f: &dyn Fn(&Frame) -> u64| {
        let steady = &run.frames[1.min(run.frames.len())..];
        steady.iter().map(f).sum::<u64>() / steady.len().max(1) as u64
    };
    println!();
    println!(
        "| cores | steady frame | core | vertex stage | rasterising | waiting for the panel | sending | \
         own cycles (the same four) | budget |"
    );
    println!("|--:|--:|--:|--:|--:|--:|--:|--:|--:|");
    for run in runs {
        for c in 0..run.cores {
            let state = |s: usize| group(mean(run, &|f| f.state[c][s]));
            let own = (0..4).map(|s| group(mean(run, &|f| f.own[c][s]))).collect::<Vec<_>>().join(" / ");
            let (cores, cycles, budget) = if c == 0 {
                (run.cores.to_string(), group(mean(run, &|f| f.cycles)), group(run.budget))
            } else {
                (String::new(), String::new(), String::new())
            };
            println!(
                "| {cores} | {cycles} | {c} | {} | {} | {} | {} | {own} | {budget} |",
                state(0),
                state(1),
                state(2),
                state(3)
            );
        }
    }
    println!();
    if let [one, two] = runs {
        let (a, b) = (mean(one, &|f| f.cycles), mean(two, &|f| f.cycles));
        if b > 0 {
            println!("speed-up of the second core in the emulator's model: {:.2}×", a as f64 / b as f64);
            // Each core's own cycles: what its frame would take if the
            // clock did not wait for the other core's longer instructions
            // (an estimate: the waits for the panel would shift too).
            let own = (0..2).map(|c| mean(two, &|f| f.own[c].iter().sum())).max().unwrap_or(0);
            println!(
                "without the lockstep (the busier core's own cycles, an estimate): {} cycles a frame, \
                 speed-up {:.2}×",
                group(own),
                a as f64 / own.max(1) as f64
            );
        }
    }
    for run in runs {
        println!(
            "rp2040-emu {} core(s): {} frames ({} steady), {}; {:.1} s of host time",
            run.cores,
            run.frames.len(),
            run.frames.len().saturating_sub(1),
            if run.failed.is_empty() {
                "band CRCs identical to the host's, within the budget".to_string()
            } else {
                format!("FAILED: {}", run.failed.join(", "))
            },
            run.seconds
        );
    }
}
