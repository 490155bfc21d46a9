//! Host side of the firmware benchmark: what each configuration draws
//! (triangles, lines, covered pixels, frame CRC), and the table that joins
//! it with the target runs (instructions, stack) and the ELF sizes.

use std::collections::BTreeMap;
use std::fmt::{self, Write as _};

use embedded_graphics_core::pixelcolor::Rgb565;
use microraster::depth::DepthBand;
use microraster::pipeline::{ClusterCache, VertexCache};
use microraster::{Band, Error};

use crate::benches::{self, BACKGROUND, Bench, Buffers, Mode, Sink};
#[path = "../common/group.rs"]
mod digits;
use digits::group;

/// What the host knows of one configuration.
pub struct HostRecord {
    /// Index in the target's list.
    pub index: usize,
    /// The configuration.
    pub bench: Bench,
    /// Triangles drawn in a frame (each counted once).
    pub triangles: u32,
    /// Lines drawn in a frame.
    pub lines: u32,
    /// Frame pixels that differ from the background (none for work that
    /// draws nothing).
    pub covered: Option<u32>,
    /// Frame pixels.
    pub pixels: u32,
    /// CRC-32 of the frame.
    pub crc: u32,
}

impl fmt::Display for HostRecord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let covered = self.covered.map_or("-".to_string(), |c| c.to_string());
        write!(
            f,
            "host {} triangles={} lines={} covered={} pixels={} crc={:08x} # {} / {}",
            self.index,
            self.triangles,
            self.lines,
            covered,
            self.pixels,
            self.crc,
            self.bench.scene,
            self.bench.work.describe()
        )
    }
}

/// Two backgrounds that no scene draws (checked: the covered counts with
/// either must agree).
const SENTINELS: [Rgb565; 2] = [Rgb565::new(31, 0, 31), Rgb565::new(0, 63, 1)];

fn records<const W: usize, const H: usize, const N: usize, const P: usize>(
    list: &[Bench],
    height: u32,
) -> Result<Vec<HostRecord>, String> {
    let mut prims = Box::new(heapless::Vec::new());
    let mut band = Box::new(Band::new(BACKGROUND));
    let mut depth = Box::new(DepthBand::new());
    let mut bins = Box::new(heapless::Vec::new());
    let mut cache = Box::new(benches::Cache::new());
    let (mut cluster, mut cluster_fx) = (Box::new(ClusterCache::new()), Box::new(ClusterCache::new()));
    let mut chunk = Box::new(VertexCache::new());
    let (mut band20, mut depth20) = (Box::new(Band::new(BACKGROUND)), Box::new(DepthBand::new()));
    let (mut band32, mut depth32) = (Box::new(Band::new(BACKGROUND)), Box::new(DepthBand::new()));
    let (mut band48, mut depth48) = (Box::new(Band::new(BACKGROUND)), Box::new(DepthBand::new()));
    let (mut band240, mut depth240) = (Box::new(Band::new(BACKGROUND)), Box::new(DepthBand::new()));
    let mut view = Box::new(benches::View::new(BACKGROUND));
    let (mut knot_bins, mut knot5k_bins) = (Box::new(heapless::Vec::new()), Box::new(heapless::Vec::new()));
    let mut b: Buffers<'_, W, H, N, P> = Buffers {
        prims: &mut prims,
        band: &mut band,
        depth: &mut depth,
        bins: &mut bins,
        cache: Some(&mut cache),
        cluster: Some((&mut cluster, &mut cluster_fx)),
        chunk: Some(&mut chunk),
        tall: Some(benches::Tall {
            band20: &mut band20,
            depth20: &mut depth20,
            band32: &mut band32,
            depth32: &mut depth32,
            band48: &mut band48,
            depth48: &mut depth48,
            band240: &mut band240,
            depth240: &mut depth240,
        }),
        view: Some(&mut view),
        knot_bins: Some((&mut knot_bins, &mut knot5k_bins)),
    };
    let mut out = Vec::new();
    let select = std::env::var(benches::SELECT_VAR).ok();
    for (index, &bench) in
        list.iter().enumerate().filter(|(i, b)| benches::selected(select.as_deref(), *i, b))
    {
        let fail =
            |e: Error| format!("configuration {index} ({}, {}): {e}", bench.scene, bench.work.describe());
        benches::prepare(bench.work, height, &mut b).map_err(fail)?;
        let (triangles, lines) = benches::primitives(bench.work, height, &mut b).map_err(fail)?;
        let mut crc = Sink::new(W as u32, height, Mode::Crc);
        benches::frame(bench.work, height, BACKGROUND, &mut b, &mut crc).map_err(fail)?;
        let mut covered = [0; 2];
        for (c, bg) in covered.iter_mut().zip(SENTINELS) {
            let mut sink = Sink::new(W as u32, height, Mode::Covered(bg));
            benches::frame(bench.work, height, bg, &mut b, &mut sink).map_err(fail)?;
            *c = sink.covered;
        }
        if covered[0] != covered[1] {
            return Err(fail(Error::InvalidParameter(microraster::Param::User))
                + ": a scene draws a sentinel background colour");
        }
        // The drive sends its damaged areas; every other row whole frames.
        let pixels = match bench.work {
            benches::Work::DashboardDrive => {
                benches::drive::drive_pixels(W as u32, height).map_err(fail)? as u32
            }
            _ => W as u32 * height,
        };
        if bench.work.draws() && crc.pixels != pixels {
            return Err(format!("configuration {index}: {} pixels sent, not {pixels}", crc.pixels));
        }
        let covered = bench.work.draws().then_some(covered[0]);
        out.push(HostRecord { index, bench, triangles, lines, covered, pixels, crc: crc.crc() });
    }
    Ok(out)
}

/// The host records of target `m4f` or `m0`.
pub fn host(target: &str) -> Result<Vec<HostRecord>, String> {
    use benches::*;
    match target {
        "m4f" => records::<{ M4F_SIZE.0 }, M4F_BAND, BINS, PRIMS>(M4F, M4F_SIZE.1),
        "m0" => records::<{ M0_SIZE.0 }, M0_BAND, BAND_BINS, 0>(M0, M0_SIZE.1),
        _ => Err(format!("unknown target {target}")),
    }
}

/// One target's measurements, as `scripts/firmware.sh table` collects them.
#[derive(Default)]
struct TargetRun {
    /// `bench` lines: index → fields.
    benches: BTreeMap<usize, BTreeMap<String, String>>,
    /// `#` notes of the run.
    notes: Vec<String>,
    /// Static buffer sizes from the ELF's symbols (`nm -S`, hexadecimal).
    symbols: BTreeMap<String, u64>,
    /// `size` of each ELF: name → (text, data, bss).
    sizes: Vec<(String, u64, u64, u64)>,
    /// `key value` facts: the QEMU machine.
    facts: BTreeMap<String, String>,
}

fn parse(input: &str) -> Result<BTreeMap<String, TargetRun>, String> {
    let mut runs: BTreeMap<String, TargetRun> = BTreeMap::new();
    for line in input.lines().filter(|l| !l.trim().is_empty()) {
        let bad = || format!("cannot read {line:?}");
        let (target, rest) = line.split_once(' ').ok_or_else(bad)?;
        let run = runs.entry(target.to_string()).or_default();
        let mut words = rest.split_whitespace();
        match words.next().ok_or_else(bad)? {
            "bench" => {
                let index = words.next().and_then(|w| w.parse().ok()).ok_or_else(bad)?;
                let fields = words
                    .map(|w| w.split_once('=').map(|(k, v)| (k.to_string(), v.to_string())).ok_or_else(bad))
                    .collect::<Result<_, _>>()?;
                run.benches.insert(index, fields);
            }
            "#" => run.notes.push(rest[1..].trim().to_string()),
            "sym" => {
                let name = words.next().ok_or_else(bad)?;
                let size = words.next().and_then(|w| u64::from_str_radix(w, 16).ok()).ok_or_else(bad)?;
                run.symbols.insert(name.to_string(), size);
            }
            "size" => {
                // `size NAME... TEXT DATA BSS`
                let w: Vec<&str> = words.collect();
                let n = w.len().checked_sub(3).filter(|&n| n > 0).ok_or_else(bad)?;
                let v: Vec<u64> =
                    w[n..].iter().map(|x| x.parse().map_err(|_| bad())).collect::<Result<_, _>>()?;
                run.sizes.push((w[..n].join(" "), v[0], v[1], v[2]));
            }
            "fact" => {
                let key = words.next().ok_or_else(bad)?;
                run.facts.insert(key.to_string(), words.collect::<Vec<_>>().join(" "));
            }
            "error:" => return Err(format!("{target}: {rest}")),
            other => return Err(format!("{target}: unexpected {other:?} in {line:?}")),
        }
    }
    Ok(runs)
}

/// A ratio with one decimal below 100, none above.
fn per(n: u64, d: u64) -> String {
    if d == 0 {
        return "–".to_string();
    }
    let x = n as f64 / d as f64;
    if x < 100.0 { format!("{x:.1}") } else { group(x.round() as u64) }
}

/// The key of a configuration in `docs/data/fw-bench.tsv`: the scene and
/// its description, lower case, runs of other characters as one `-`
/// (`knot20k/meshlets-per-band-f32-affine`).
pub fn key(b: &Bench) -> String {
    let mut k = String::new();
    for c in b.work.describe().chars() {
        if c.is_ascii_alphanumeric() {
            k.push(c.to_ascii_lowercase());
        } else if !k.is_empty() && !k.ends_with('-') {
            k.push('-');
        }
    }
    format!("{}/{}", b.scene.replace(' ', "-"), k.trim_end_matches('-'))
}

/// docs/firmware.md's table from the collected target runs (`input`), and the same
/// rows as the tab-separated data the report reads (`docs/data/fw-bench.tsv`).
pub fn table(input: &str) -> Result<(String, String), String> {
    let runs = parse(input)?;
    let mut out = String::new();
    let mut tsv = String::from(
        "# Cortex-M counts of examples/fw_bench (docs/firmware.md's table), one frame each.\n\
         # Written by `bash scripts/firmware.sh table`; do not edit. QEMU -icount shift=0:\n\
         # m4f on mps2-an386 (320x240, 16-row bands), m0 on microbit (160x128, 4-row bands).\n\
         # triangles: mesh triangles for the knot; covered: pixels unlike the background (0: none drawn);\n\
         # static_ram: bytes of the buffers the configuration uses; stack: high-water mark, bytes.\n\
         # core\tkey\tinstructions\ttriangles\tcovered\tstatic_ram\tstack\n",
    );
    let w = &mut out;
    let targets = [("m4f", "Cortex-M4F"), ("m0", "Cortex-M0")];
    writeln!(
        w,
        "| target | scene | configuration | instructions / frame | triangles | instr. / triangle \
         | covered px | instr. / covered px | static RAM (B) | stack (B) |"
    )
    .unwrap();
    writeln!(w, "|---|---|---|--:|--:|--:|--:|--:|--:|--:|").unwrap();
    // Only the targets that ran (`scripts/firmware.sh table m4f` runs one).
    let targets: Vec<_> = targets.into_iter().filter(|(t, _)| runs.contains_key(*t)).collect();
    if targets.is_empty() {
        return Err("no target run in the input".to_string());
    }
    for &(t, label) in &targets {
        let run = &runs[t];
        let host = host(t)?;
        if run.benches.len() != host.len() {
            return Err(format!(
                "{t}: {} configurations on the target, {} on the host",
                run.benches.len(),
                host.len()
            ));
        }
        let frame = match t {
            "m4f" => format!("{}×{}", benches::M4F_SIZE.0, benches::M4F_SIZE.1),
            _ => format!("{}×{}", benches::M0_SIZE.0, benches::M0_SIZE.1),
        };
        for h in &host {
            let f = run.benches.get(&h.index).ok_or_else(|| format!("{t}: no record {}", h.index))?;
            let get = |k: &str| f.get(k).ok_or_else(|| format!("{t} record {}: no {k}", h.index));
            let crc = u32::from_str_radix(get("crc")?, 16).map_err(|e| e.to_string())?;
            if h.bench.work.draws() && crc != h.crc {
                return Err(format!(
                    "{t}: configuration {} ({} / {}): target frame CRC {crc:08x}, host {:08x}",
                    h.index,
                    h.bench.scene,
                    h.bench.work.describe(),
                    h.crc
                ));
            }
            // Per frame: a row that renders several (the drive) is divided.
            let instr: u64 =
                get("instr")?.parse::<u64>().map_err(|_| format!("{t}: bad instr"))? / h.bench.work.frames();
            let stack: u64 = get("stack")?.parse().map_err(|_| format!("{t}: bad stack"))?;
            let ram = h.bench.work.buffers().split(',').try_fold(0, |sum, name| {
                run.symbols
                    .get(name)
                    .map(|s| sum + s)
                    .ok_or_else(|| format!("{t}: no symbol size for {name}"))
            })?;
            let prims = u64::from(h.triangles + h.lines);
            let triangles = match (h.triangles, h.lines) {
                (0, 0) => "–".to_string(),
                (t, 0) => group(t.into()),
                (t, l) => format!("{} + {} lines", group(t.into()), group(l.into())),
            };
            let (covered, per_px) = match h.covered {
                Some(c) if c > 0 => (group(c.into()), per(instr, c.into())),
                _ => ("–".to_string(), "–".to_string()),
            };
            writeln!(
                tsv,
                "{t}\t{}\t{instr}\t{}\t{}\t{ram}\t{stack}",
                key(&h.bench),
                h.triangles,
                h.covered.unwrap_or(0)
            )
            .unwrap();
            writeln!(
                w,
                "| {label} | {} {frame} | {} | {} | {triangles} | {} | {covered} | {per_px} | {} | {} |",
                h.bench.scene,
                h.bench.work.describe(),
                group(instr),
                per(instr, prims),
                group(ram),
                group(stack),
            )
            .unwrap();
        }
    }
    writeln!(w).unwrap();
    writeln!(w, "| target | ELF | flash: text + data (B) | static RAM: data + bss (B) | buffers (B) |")
        .unwrap();
    writeln!(w, "|---|---|--:|--:|---|").unwrap();
    for &(t, label) in &targets {
        let run = &runs[t];
        // The symbols are fw_bench's; the CRC firmware has the same buffers
        // but the taller bands (`BAND20`, `BAND32`, `BAND48`, `BAND240` and their
        // depth rows) and the front's (`VIEW`).
        let list = |all: bool| {
            let own = |k: &str| ["20", "32", "48", "240"].iter().any(|n| k.ends_with(n)) || k == "VIEW";
            let b = run.symbols.iter().filter(|(k, _)| all || !own(k));
            b.map(|(k, v)| format!("{k} {}", group(*v))).collect::<Vec<_>>().join(", ")
        };
        for (name, text, data, bss) in &run.sizes {
            let buffers = list(name.starts_with("fw_bench"));
            writeln!(w, "| {label} | {name} | {} | {} | {buffers} |", group(text + data), group(data + bss))
                .unwrap();
        }
    }
    writeln!(w).unwrap();
    for &(t, label) in &targets {
        let run = &runs[t];
        let machine = run.facts.get("machine").map_or("?", String::as_str);
        for n in &run.notes {
            writeln!(w, "- {label} (QEMU `{machine}`): {n}").unwrap();
        }
    }
    Ok((out, tsv))
}

/// Replaces docs/firmware.md's firmware table (between its
/// `<!-- fw-table:begin -->` and `<!-- fw-table:end -->` markers) with `table`.
pub fn update_readme(path: &str, table: &str) -> Result<(), String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let (begin, end) = ("<!-- fw-table:begin -->", "<!-- fw-table:end -->");
    let (Some(a), Some(b)) = (text.find(begin), text.find(end)) else {
        return Err(format!("{path}: no {begin} … {end} markers"));
    };
    let text = format!("{}{begin}\n{table}{}", &text[..a], &text[b..]);
    std::fs::write(path, text).map_err(|e| format!("{path}: {e}"))
}
