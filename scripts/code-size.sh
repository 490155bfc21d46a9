#!/usr/bin/env bash
# Shows that a scene pays only for what it uses: builds a 2D-only program, the
# same program with the standard 3D scene, and the 3D program with the whole
# fragment stage (textures, per-pixel lighting, blending, 2x2 supersampling;
# examples/size/), then lists the microraster code each one links, by module.
# The demo scenes the programs draw come from the development-only scenes/
# crate (microraster-scenes); they are listed too, as the modules `scenes` and
# `scenes3d`, so the totals still show what each program pays for its scene.
# Run: bash scripts/code-size.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --quiet --release -p microraster --example size_2d --example size_3d --example size_frag

sizes() { # bytes of microraster (and demo scene) code per module in binary $1
  nm -C --size-sort -S "target/release/examples/$1" | grep -E ' microraster(_scenes)?::' | while read -r _ size _ name; do
    module=${name#microraster_scenes::}
    module=${module#microraster::}
    # The stage folders (src/geometry/ ...) are private modules: count by
    # the public module under them.
    module=${module#geometry::}; module=${module#raster::}
    module=${module#pixel::}; module=${module#output::}
    module=${module%%::*}
    module=${module%%<*}
    [[ $module =~ ^[a-z_0-9]+$ ]] || module=other
    echo "$module $((16#$size))"
  done | sort | awk '{s[$1]+=$2} END {for (m in s) print m, s[m]}' | sort
}

sizes size_2d > target/size_2d.txt
sizes size_3d > target/size_3d.txt
sizes size_frag > target/size_frag.txt
echo "| module | 2D-only build (bytes of code and static data) | 3D build (bytes) | 3D + fragment stage (bytes) |"
echo "|---|---|---|---|"
join -a1 -a2 -e 0 -o 0,1.2,2.2 target/size_2d.txt target/size_3d.txt >target/size_23.txt
join -a1 -a2 -e 0 -o 0,1.2,1.3,2.2 target/size_23.txt target/size_frag.txt | while read -r m a b c; do
  echo "| $m | $a | $b | $c |"
done
total() { awk '{s+=$2} END {print s+0}' "$1"; }
echo "| **total** | $(total target/size_2d.txt) | $(total target/size_3d.txt) | $(total target/size_frag.txt) |"
for m in clip3d depth raster3d pipeline; do
  if grep -q "^$m " target/size_2d.txt; then
    echo "FAIL: the 2D-only build links microraster::$m" >&2
    exit 1
  fi
done
for m in texture blend fragment aa line_aa shape; do
  for b in size_2d size_3d; do
    if grep -q "^$m " "target/$b.txt"; then
      echo "FAIL: $b links microraster::$m, which it does not use" >&2
      exit 1
    fi
  done
done
# The display link's async half (feature `async`, on in these builds through
# the dev-dependency) is generic: a program that does not call it links none.
# The symbols go to a file first: `nm | grep -q` under `pipefail` reports
# nm's SIGPIPE when grep stops at the first match, and the check never fails.
for b in size_2d size_3d size_frag; do
  nm -C "target/release/examples/$b" >"target/$b.syms"
done
for b in size_2d size_3d size_frag; do
  if grep -qE 'microraster::(output::)?render::(link_async|spi_panel)' "target/$b.syms"; then
    echo "FAIL: $b links the async display link, which it does not use" >&2
    exit 1
  fi
done
# Nor the rest of the display link they do not call: dirty-band skipping
# (`DirtyBands` and its signature hashing, src/output/render/dirty.rs) and
# bands on host threads (src/output/render/threads.rs, feature `std`, on in
# these builds through the dev-dependency). The stage folders are private
# modules re-exported flat, so the symbols read `microraster::output::render::
# dirty::…` (`render::dirty::…` is matched too, should the path change).
# `DirtyBands` itself inlines into its caller; its `signature` stays out of
# line (`#[inline(never)]`) so that this grep sees it, and the threads' entry
# closures are always out of line. Checked once by hand: size_3d drawing
# through `render_linked` into `DirtyBands` links
# `microraster::output::render::dirty::signature` and fails here.
# Not checked, because it is shared on purpose: the blocking `Renderer::render`
# (and every older entry point) *is* the linked band loop (`render::link::run`)
# with one band and the `Blocking` sink, so `render::link` code is linked by
# every program, double-banded or not.
for b in size_2d size_3d size_frag; do
  if grep -E 'microraster::(output::)?render::(dirty|threads)::|DirtyBands' "target/$b.syms" >&2; then
    echo "FAIL: $b links the dirty-band or threaded rendering code above, which it does not use" >&2
    exit 1
  fi
done
echo
echo "The 2D-only build links no clip3d, depth, raster3d or pipeline code, and neither"
echo "the 2D nor the 3D build links texture, blend, fragment, aa, line_aa or shape code,"
echo "and none of the three links the async display link, the dirty-band code"
echo "(DirtyBands, render::dirty) or threaded rendering (render::threads) (checked)."

# The same two programs built without the fragment stage's modules at all
# (`--no-default-features --features fx`: `shapes`, `textures` and
# `fragment` off): their code must be byte for byte the same size. `fx` stays
# on: it is a scalar, not a stage, and leaving the `fixed` crate out moves
# the 2D program's `main` by 16 bytes of stack layout (measured on the host,
# x86-64), which is code generation, not linked code.
# `-p microraster`: with the whole workspace selected, the tools crate's
# dev-dependencies would turn them back on.
CARGO_TARGET_DIR=target/size-without-fragment \
  cargo build --quiet --release -p microraster --no-default-features --features fx --example size_2d --example size_3d
text() { size "$1" | awk 'NR == 2 { print $1 + $2 }'; }
echo
echo "| program | text + data (bytes) | the same without the fragment stage's modules (bytes) |"
echo "|---|---|---|"
for b in size_2d size_3d; do
  with=$(text "target/release/examples/$b")
  without=$(text "target/size-without-fragment/release/examples/$b")
  echo "| $b | $with | $without |"
  if [ "$with" != "$without" ]; then
    echo "FAIL: $b changes size when the unused fragment stage exists" >&2
    exit 1
  fi
done
echo "| size_frag (fragment stage on) | $(text target/release/examples/size_frag) | – |"
