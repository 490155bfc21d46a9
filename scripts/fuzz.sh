#!/usr/bin/env bash
# Fuzzing microraster with cargo-fuzz (libFuzzer) on the host. See docs/fuzzing.md.
#
#   bash scripts/fuzz.sh <target> <seconds>  fuzz one target (triangle, line, pipeline, meshlet, shape, sprite, view3d, closed, shape_aa, sinks) or `all`
#   bash scripts/fuzz.sh ci [seconds]        CI mode: build, replay the committed corpus, then fuzz
#                                            each target for about `seconds` (default 60; 0 = replay
#                                            only) with a fixed seed and run count (repeatable)
#   bash scripts/fuzz.sh regress             replay every target's committed corpus once
#   bash scripts/fuzz.sh merge <target>      add the inputs of the last runs that reach new
#                                            coverage to the committed corpus (fuzz/corpus/<target>)
#   bash scripts/fuzz.sh build               build the targets only
#   bash scripts/fuzz.sh long <runs> [targets…]  a long run: <runs> executions per target (all
#                                            targets by default; each also capped at
#                                            LONG_MAX_SECONDS, default 86400), its numbers
#                                            (executions, time, coverage, features, corpus,
#                                            result) appended to docs/fuzzing.md with the command
#
# Works with the stable toolchain: cargo-fuzz needs nightly-only flags
# (-Zsanitizer, -Cpasses=sancov), which RUSTC_BOOTSTRAP=1 unlocks on stable.
# Builds are optimised with debug assertions and overflow checks on
# (`-O -a`, plus overflow-checks in fuzz/Cargo.toml), under AddressSanitizer.
# New corpus entries go to fuzz/target/work-corpus/<target> (not committed);
# crashes go to fuzz/artifacts/<target>/ and the script exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"

TARGETS=(triangle line pipeline meshlet shape sprite view3d closed shape_aa sinks)
export RUSTC_BOOTSTRAP=1
FLAGS=(-O -a)
# Inputs longer than this add nothing: every target reads at most ~200 bytes.
LIBFUZZER=(-max_len=512 -print_final_stats=1)

ensure_cargo_fuzz() {
  if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "installing cargo-fuzz from crates.io" >&2
    cargo install cargo-fuzz --version 0.13.2 --locked
  fi
}

build() {
  cargo fuzz build "${FLAGS[@]}"
}

# fuzz <target> <seconds> [libFuzzer options…]
fuzz() {
  local t=$1 secs=$2 work="target/work-corpus/$1"
  shift 2
  mkdir -p "$work" "corpus/$t" "artifacts/$t"
  echo "=== fuzzing $t for ${secs}s $*" >&2
  set +e
  cargo fuzz run "${FLAGS[@]}" "$t" "$work" "corpus/$t" -- "${LIBFUZZER[@]}" -max_total_time="$secs" "$@" \
    > "target/fuzz-$t.log" 2>&1
  local status=$?
  set -e
  grep -E '^(Done|stat::number_of_executed_units|==[0-9]+==ERROR|thread .* panicked)' "target/fuzz-$t.log" || true
  if [ "$status" -ne 0 ]; then
    grep -A6 'panicked' "target/fuzz-$t.log" | head -20 >&2 || true
    echo "FAIL: $t found a crash (fuzz/target/fuzz-$t.log, fuzz/artifacts/$t/)" >&2
    return 1
  fi
}

# regress <target>: every committed corpus file once, no mutation.
regress() {
  local t=$1
  echo "=== replaying fuzz/corpus/$t ($(ls "corpus/$t" | wc -l) inputs)" >&2
  cargo fuzz run "${FLAGS[@]}" "$t" "corpus/$t" -- "${LIBFUZZER[@]}" -runs=0 2>&1 | tail -n 3
}

check_target() {
  case " ${TARGETS[*]} " in *" $1 "*) ;; *) echo "unknown target '$1' (${TARGETS[*]})" >&2; exit 2 ;; esac
}

cmd=${1:-}
case "$cmd" in
  build)
    ensure_cargo_fuzz; build ;;
  regress)
    ensure_cargo_fuzz; build
    for t in "${TARGETS[@]}"; do regress "$t"; done ;;
  ci)
    secs=${2:-60}
    start=$SECONDS
    ensure_cargo_fuzz; build
    for t in "${TARGETS[@]}"; do regress "$t"; done
    if [ "$secs" -gt 0 ]; then
      # CI must be repeatable: a fixed seed and a fixed number of runs (from a
      # fresh work corpus) explore the same inputs on every machine; the time
      # is only a cap. Longer exploratory runs: `fuzz.sh <target> <seconds>`.
      rm -rf target/work-corpus
      # view3d draws each input five times (four band heights and the binned
      # path, up to 96 rows): a fifth of the runs keeps it inside the cap;
      # closed draws a cut cube's clusters one by one, whole and as a mesh
      # (50,000 runs took 79 s of its 80 s cap): two fifths.
      for t in "${TARGETS[@]}"; do
        runs=$((secs * 2500))
        [ "$t" = view3d ] && runs=$((secs * 500))
        [ "$t" = closed ] && runs=$((secs * 1000))
        fuzz "$t" "$((secs * 4))" -seed=1 -runs="$runs"
      done
    fi
    echo "fuzz ci: done in $((SECONDS - start)) s" ;;
  merge)
    t=${2:?usage: fuzz.sh merge <target>}; check_target "$t"
    ensure_cargo_fuzz; build
    cargo fuzz run "${FLAGS[@]}" "$t" "corpus/$t" "target/work-corpus/$t" -- -merge=1 -set_cover_merge=1 -use_counters=0 "${LIBFUZZER[@]}" ;;
  long)
    runs=${2:?usage: fuzz.sh long <runs per target> [targets…]}
    shift 2
    targets=("$@")
    [ ${#targets[@]} -eq 0 ] && targets=("${TARGETS[@]}")
    for t in "${targets[@]}"; do check_target "$t"; done
    ensure_cargo_fuzz; build
    commit=$(git -C .. rev-parse --short HEAD)
    dirty=$(git -C .. status --porcelain -- src | head -1)
    [ -n "$dirty" ] && commit="$commit+changes"
    status=0
    for t in "${targets[@]}"; do
      start=$SECONDS
      r=0
      fuzz "$t" "${LONG_MAX_SECONDS:-86400}" -runs="$runs" || r=$?
      secs=$((SECONDS - start))
      log="target/fuzz-$t.log"
      execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
      last=$(grep -E '^#[0-9]+' "$log" | tail -1)
      cov=$(echo "$last" | grep -o 'cov: [0-9]*' | grep -o '[0-9]*')
      ft=$(echo "$last" | grep -o 'ft: [0-9]*' | grep -o '[0-9]*')
      corp=$(echo "$last" | grep -o 'corp: [0-9]*' | grep -o '[0-9]*')
      if [ "$r" -eq 0 ]; then result="no finding"; else result="**crash** (fuzz/artifacts/$t/)"; status=1; fi
      row="| $(date -u +%F) | \`$t\` (library at $commit) | ${secs} s | ${execs:-?} | cov ${cov:-?}, ft ${ft:-?}, corpus ${corp:-?} | $result | \`${LONG_MAX_SECONDS:+LONG_MAX_SECONDS=$LONG_MAX_SECONDS }bash scripts/fuzz.sh long $runs $t\` |"
      echo "$row"
      echo "$row" >> ../docs/fuzzing.md
    done
    exit "$status" ;;
  all)
    secs=${2:?usage: fuzz.sh all <seconds per target>}
    ensure_cargo_fuzz; build
    for t in "${TARGETS[@]}"; do fuzz "$t" "$secs"; done ;;
  "" | -h | --help)
    sed -n '2,25p' "$0"; exit 2 ;;
  *)
    check_target "$cmd"
    secs=${2:?usage: fuzz.sh <target> <seconds>}
    ensure_cargo_fuzz; build
    fuzz "$cmd" "$secs" ;;
esac
