#!/usr/bin/env bash
# Runs the libFuzzer harnesses of a SW_FUZZ build on their seed corpora (fuzz/corpus/<name>).
# Usage: scripts/fuzz.sh BUILD_DIR [-time SECONDS | -runs N] [harness...]   (default: -time 20, all)
# New inputs go to BUILD_DIR/fuzz-work/<name>, crashes to BUILD_DIR/fuzz-artifacts. The two
# harnesses run side by side on two cores; exit status 1 if any finds a crash, a hang, a leak or
# an out-of-memory.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=$1; shift
limit=(-max_total_time=20)
case "${1:-}" in
  -time) limit=(-max_total_time="$2"); shift 2 ;;
  -runs) limit=(-runs="$2"); shift 2 ;;
esac
names=("$@")
((${#names[@]})) || names=(run check lesson scene files)
mkdir -p "$BUILD/fuzz-artifacts"
status=0
pids=()
for name in "${names[@]}"; do
  mkdir -p "$BUILD/fuzz-work/$name"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$BUILD/fuzz/fuzz_$name" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -dict=fuzz/stepwise.dict -artifact_prefix="$BUILD/fuzz-artifacts/$name-" -print_final_stats=1 \
      "$BUILD/fuzz-work/$name" "fuzz/corpus/$name" > "$BUILD/fuzz-$name.log" 2>&1 &
  pids+=($!)
  if ((${#pids[@]} == $(nproc))); then wait "${pids[0]}" || status=1; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || status=1; done
for name in "${names[@]}"; do
  log="$BUILD/fuzz-$name.log"
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  secs=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | grep -o 'in [0-9]*' | grep -o '[0-9]*' || echo "?")
  if grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY: ' "$log"; then
    echo "fuzz_$name: FAILED after $runs runs; see $log and $BUILD/fuzz-artifacts/"
    grep -m3 -E 'ERROR|runtime error|SUMMARY' "$log" | sed 's/^/  /'
    status=1
  else
    echo "fuzz_$name: $runs runs in ${secs}s, corpus $(ls "$BUILD/fuzz-work/$name" | wc -l) new + $(ls "fuzz/corpus/$name" | wc -l) seeds, no crash, hang or leak"
  fi
done
exit $status
