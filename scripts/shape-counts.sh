#!/usr/bin/env bash
# Instructions per frame of the shapes bench's filled shapes (examples/shape_counts.rs)
# under Valgrind's callgrind: embedded-graphics against microraster direct, in 16-row
# bands and prepared, each the difference of a 30- and a 10-frame run divided by 20
# (start-up cancels out). Deterministic, unlike the bench's times on a shared host.
#   bash scripts/shape-counts.sh            # prints the table, writes docs/data/shape-counts.tsv
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { apt-get update -qq && apt-get install -y -qq valgrind >/dev/null; }
cargo build --quiet --release --example shape_counts
bin=target/release/examples/shape_counts
count() { # shape way frames -> instructions
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$1" "$2" "$3" 2>&1 |
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
per_frame() { echo $(( ($(count "$1" "$2" 30) - $(count "$1" "$2" 10)) / 20 )); }
out=docs/data/shape-counts.tsv
printf 'shape\teg\tdirect\tbands\tprepared\tempty\n' > "$out"
printf '%-8s %10s %10s %10s %10s %10s  %s\n' shape eg direct bands prepared empty "e-g/direct e-g/bands e-g/prepared"
for s in rect rounded circle ellipse; do
  eg=$(per_frame "$s" eg); d=$(per_frame "$s" direct); b=$(per_frame "$s" bands)
  p=$(per_frame "$s" prepared); e=$(per_frame "$s" empty)
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$s" "$eg" "$d" "$b" "$p" "$e" >> "$out"
  r() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
  printf '%-8s %10s %10s %10s %10s %10s  %s %s %s\n' "$s" "$eg" "$d" "$b" "$p" "$e" "$(r "$eg" "$d")" "$(r "$eg" "$b")" "$(r "$eg" "$p")"
done
echo "written: $out"
