#!/usr/bin/env bash
# What each cargo feature costs a firmware crate to build (the README's
# feature table): a scratch `no_std` library crate with a path dependency on
# this checkout and `pub use microraster::Renderer;` is built with
# `cargo build --release` from an empty target directory, once per feature
# set, and the wall time and the number of crates compiled are printed as
# table rows. Offline: the dependencies must be in cargo's cache already
# (any earlier build of this repository fetched them).
# Run: bash scripts/build-times.sh   (about five minutes on two idle cores)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

row() { # $1: label, $2: the dependency's feature options (TOML)
  local dir="$scratch/crate"
  rm -rf "$dir"
  mkdir -p "$dir/src"
  cat >"$dir/Cargo.toml" <<EOF
[package]
name = "firmware-like"
version = "0.1.0"
edition = "2021"

[dependencies]
microraster = { path = "$root", $2 }

[workspace]
EOF
  printf '#![no_std]\npub use microraster::Renderer;\n' >"$dir/src/lib.rs"
  local start end crates
  start=$(date +%s%N)
  crates=$(cd "$dir" && CARGO_TARGET_DIR="$scratch/target" cargo build --release --offline 2>&1 | grep -c '^ *Compiling ')
  end=$(date +%s%N)
  rm -rf "$scratch/target"
  printf '| %s | %d s | %d |\n' "$1" $(((end - start + 500000000) / 1000000000)) "$crates"
}

echo "| features | clean build | crates compiled |"
echo "|---|--:|--:|"
row "none" 'default-features = false'
row "shapes" 'default-features = false, features = ["shapes"]'
row "textures" 'default-features = false, features = ["textures"]'
row "fragment" 'default-features = false, features = ["fragment"]'
row "fx" 'default-features = false, features = ["fx"]'
row "all defaults" 'default-features = true'
echo
echo "measured on: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load average $(cut -d' ' -f1-3 /proc/loadavg), $(git -C "$root" rev-parse --short HEAD)"
