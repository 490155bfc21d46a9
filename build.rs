//! Linker memory layout for the firmware examples, and nothing else.
//!
//! On the host (any target whose `target_os` is not `none`) this script does
//! nothing but tell Cargo that it depends on itself alone. For bare-metal Cortex-M targets it hands one memory layout
//! to cortex-m-rt's `link.x` (`-Tlink.x` in `.cargo/config.toml`), which
//! `INCLUDE`s `memory.x`, for this package's examples only (crates that depend
//! on microraster keep their own `memory.x`).
//!
//! `MICRORASTER_BOARD` picks the layout:
//!
//! | value | file | used for |
//! |---|---|---|
//! | `stm32f405` (default on thumbv7em) | `memory.x` | a real STM32F405 board; QEMU `netduinoplus2` |
//! | `mps2-an386` | `memory/mps2-an386.x` | QEMU `mps2-an386` (instruction counting) |
//! | `microbit` (default on thumbv6m) | `memory/microbit.x` | BBC micro:bit v1 (nRF51822); QEMU `microbit` |
//!
//! The examples also see `cfg(microraster_board = "…")` with the chosen value.
//!
//! The chosen file is copied to `OUT_DIR/memory.x`, which goes on the link
//! search path. The linker, though, looks for an `INCLUDE`d file in its
//! working directory (the package root, where the real board's `memory.x`
//! lives) before the search path; so for any other board the script also
//! passes `--remap-inputs=memory.x=<file>`, which needs LLD 17 or later
//! (rustup's `rust-lld`, or Debian's `lld-19`: `scripts/firmware.sh` takes
//! care of it).

use std::{env, fs, path::PathBuf};

fn main() {
    // Without this line Cargo would rerun the script, and so rebuild the
    // library, whenever any file of the package changes.
    println!("cargo:rerun-if-changed=build.rs");
    // The firmware examples pick their timer by board (examples/fw_bench/clock.rs).
    println!(
        "cargo:rustc-check-cfg=cfg(microraster_board, values(\"stm32f405\", \"mps2-an386\", \"microbit\"))"
    );
    if env::var("CARGO_CFG_TARGET_OS").as_deref() != Ok("none") {
        return;
    }
    println!("cargo:rerun-if-env-changed=MICRORASTER_BOARD");
    let target = env::var("TARGET").unwrap_or_default();
    let default = if target.starts_with("thumbv6m") { "microbit" } else { "stm32f405" };
    let board = env::var("MICRORASTER_BOARD").unwrap_or_else(|_| default.to_string());
    let file = match board.as_str() {
        "stm32f405" => "memory.x",
        "mps2-an386" => "memory/mps2-an386.x",
        "microbit" => "memory/microbit.x",
        other => panic!("MICRORASTER_BOARD={other}: expected stm32f405, mps2-an386 or microbit"),
    };
    println!("cargo:rerun-if-changed={file}");
    println!("cargo:rustc-cfg=microraster_board=\"{board}\"");
    let root = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy(root.join(file), out.join("memory.x")).expect("copy the memory layout");
    println!("cargo:rustc-link-arg-examples=-L{}", out.display());
    if file != "memory.x" {
        println!("cargo:rustc-link-arg-examples=--remap-inputs=memory.x={}", out.join("memory.x").display());
    }
}
