#!/usr/bin/env bash
# The compile-time profile of a clean build (docs/build.md): configures a fresh build directory
# whose compiler launcher records each translation unit's CPU time (user + sys, so other load on
# the machine does not inflate it) and wall time, builds every target, and prints the slowest
# units and the totals per folder. Without ccache: every unit is compiled for real.
# Usage: scripts/compile_profile.sh [BUILD_DIR (default /tmp/stepwise-profile)] [TOP (default 20)]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-/tmp/stepwise-profile}
TOP=${2:-20}
rm -rf "$BUILD"
mkdir -p "$BUILD"
LOG=$BUILD/units.tsv
LAUNCHER=$BUILD/timed-compile
cat >"$LAUNCHER" <<'LAUNCH'
#!/usr/bin/env bash
# Runs the compiler; appends "cpu_seconds wall_seconds source" for the unit it compiles (-c).
src="" prev=""
for a in "$@"; do [ "$prev" = "-c" ] && src=$a; prev=$a; done
t=$(mktemp)
TIMEFORMAT='%3U %3S %3R'
{ time "$@" 2>&4; } 4>&2 2>"$t"
status=$?
if [ -n "$src" ]; then
  read -r u s r <"$t"
  f=${src#"$SW_PROFILE_ROOT"/}
  case $f in */Unity/unity_*_cxx.cxx) f=${f##*/unity_}; f="batch/${f%_cxx.cxx}" ;; esac  # a unity batch (sw_unity_batches)
  awk -v u="$u" -v s="$s" -v r="$r" -v f="$f" 'BEGIN {printf "%.3f %.3f %s\n", u + s, r, f}' >>"$SW_PROFILE_LOG"
fi
rm -f "$t"
exit $status
LAUNCH
chmod +x "$LAUNCHER"
export SW_PROFILE_LOG=$LOG SW_PROFILE_ROOT=$PWD
start=$SECONDS
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER="$LAUNCHER" "${@:3}" >/dev/null
cmake --build "$BUILD" -j"$(nproc)" >"$BUILD/build.log" 2>&1 || { tail -20 "$BUILD/build.log"; exit 1; }
wall=$((SECONDS - start))
echo "clean build: ${wall} s wall on $(nproc) cores; $(wc -l <"$LOG") units"
awk '{cpu += $1} END {printf "compile CPU: %.0f s in all\n", cpu}' "$LOG"
echo
echo "CPU seconds by folder:"
awk '{split($3, p, "/"); d = p[1]; if (d == "tests" || d == "runtime" || d == "visualizer") d = d "/" p[2]; cpu[d] += $1; n[d]++}
     END {for (d in cpu) printf "%8.1f  %4d units  %s\n", cpu[d], n[d], d}' "$LOG" | sort -rn
echo
echo "The $TOP slowest units (CPU seconds, wall seconds):"
sort -rn "$LOG" | head -"$TOP" | awk '{printf "%8.1f %8.1f  %s\n", $1, $2, $3}'
