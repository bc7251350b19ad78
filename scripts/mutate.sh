#!/usr/bin/env bash
# Mutation score (issue #16): applies each planted bug of tests/mutants.txt, one at a time, to a copy
# of the tree, rebuilds incrementally, runs the tests, reverts it, and prints caught or missed per
# mutant and a final "caught X of Y (Z%)". Too slow for CI: run it before resolving an issue that
# touches the algorithms or `check`, and add a mutant whenever a real bug slips through.
#
# Usage: bash scripts/mutate.sh [--only N[,N...]] [--list] [--check] [--full | --quick] [--jobs J]
#   --only    run only these mutants (1-based numbers, ranges N-M or ids, comma-separated)
#   --list    print the mutants and exit
#   --check   only check that every mutant's original text occurs once, and exit
# Each mutant first runs the tests its "tests:" regex names and, only when they all pass, the rest
# of the suite, so the verdict is always the whole suite's (a missed mutant ran every test).
#   --full    run the whole suite at once instead (slower: the regex usually catches it sooner)
#   --quick   skip the second phase: "missed" then means missed by the regex's tests only
# The copy and its build live in ${TMPDIR:-/tmp}/stepwise-mutate and are reused by the next run
# (ccache, which it requires, makes reverting a mutant nearly free). The list's format is described at
# the top of tests/mutants.txt.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
LIST=$ROOT/tests/mutants.txt
WORK=${TMPDIR:-/tmp}/stepwise-mutate
SRC=$WORK/src
BUILD=$WORK/build
JOBS=2
ONLY=""
LIST_ONLY=0
CHECK_ONLY=0
FULL=0
QUICK=0
BUILD_TIMEOUT=3600   # seconds for one mutant's rebuild (the unmutated tree's first build has none)
TEST_TIMEOUT=900     # seconds for one ctest run (each test also has its own 120 s limit)

while (($#)); do
  case $1 in
    --only) ONLY=$2; shift 2 ;;
    --list) LIST_ONLY=1; shift ;;
    --check) CHECK_ONLY=1; shift ;;
    --full) FULL=1; shift ;;
    --quick) QUICK=1; shift ;;
    --jobs) JOBS=$2; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "mutate: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

# Parses the list into $WORK/mutants/N/{id,file,why,tests,old,new}: old and new are written
# byte-exact (no trailing newline added), so the check below compares exact text.
parse_list() {
  rm -rf "$WORK/mutants"
  mkdir -p "$WORK/mutants"
  perl -e '
    use strict; use warnings;
    my ($list, $dir) = @ARGV;
    open(my $in, "<", $list) or die "mutate: cannot read $list\n";
    my (@m, $cur, $last);
    while (my $line = <$in>) {
      chomp $line;
      next if $line =~ /^#/;
      if ($line =~ /^---\s*$/) { push @m, $cur if $cur; $cur = undef; next; }
      next if $line =~ /^\s*$/ && !$cur;
      if ($line =~ /^(id|file|why|tests|old|new): ?(.*)$/) { $cur //= {}; $cur->{$1} = $2; $last = $1; next; }
      if ($line =~ /^ *\| ?(.*)$/ && $cur && defined $last) { $cur->{$last} .= "\n$1"; next; }
      die "mutate: $list line $.: cannot read \"$line\"\n";
    }
    push @m, $cur if $cur;
    my %seen; my $n = 0;
    for my $x (@m) {
      $n++;
      for my $k (qw(id file why old new)) { die "mutate: mutant $n has no \"$k:\"\n" unless defined $x->{$k}; }
      die "mutate: mutant $n: duplicate id $x->{id}\n" if $seen{$x->{id}}++;
      die "mutate: mutant $n ($x->{id}): old and new are the same\n" if $x->{old} eq $x->{new};
      mkdir "$dir/$n";
      for my $k (qw(id file why tests old new)) {
        open(my $o, ">", "$dir/$n/$k") or die; print $o ($x->{$k} // ""); close $o;
      }
    }
    print "$n\n";
  ' "$LIST" "$WORK/mutants"
}

# Exactly one occurrence of old in the file (prints the count otherwise).
occurrences() {  # file old-file
  perl -e 'local $/; open(my $f, "<", $ARGV[0]) or do { print "0 (no such file)"; exit 1 };
           my $t = <$f>; open(my $o, "<", $ARGV[1]) or die; my $s = <$o>;
           my $n = () = $t =~ /\Q$s\E/g; print $n; exit($n == 1 ? 0 : 1)' "$1" "$2"
}

apply_mutant() {  # file old-file new-file: writes the file anew (fresh mtime)
  perl -e 'local $/; open(my $f, "<", $ARGV[0]) or die; my $t = <$f>; close $f;
           open(my $o, "<", $ARGV[1]) or die; my $s = <$o>; open(my $r, "<", $ARGV[2]) or die; my $n = <$r>;
           my $i = index($t, $s); die "mutate: text not found\n" if $i < 0;
           substr($t, $i, length $s) = $n; open($f, ">", $ARGV[0]) or die; print $f $t; close $f' "$1" "$2" "$3"
}

mkdir -p "$WORK"
COUNT=$(parse_list)
field() { cat "$WORK/mutants/$1/$2"; }
# The ids, read once without a process each (the selection below compares every name with all).
IDS=()
for ((n = 1; n <= COUNT; n++)); do IFS= read -r 'IDS[n]' <"$WORK/mutants/$n/id" || true; done

if ((LIST_ONLY)); then
  for ((n = 1; n <= COUNT; n++)); do
    printf '%3d  %-28s %-40s %s\n' "$n" "${IDS[n]}" "$(field $n file)" "$(field $n why)"
  done
  exit 0
fi

# The selected mutants, by number.
SELECTED=()
if [[ -n $ONLY ]]; then
  IFS=, read -ra wanted <<<"$ONLY"
  expanded=()
  for w in "${wanted[@]}"; do  # N-M: a range of numbers
    if [[ $w =~ ^([0-9]+)-([0-9]+)$ ]]; then
      for ((n = BASH_REMATCH[1]; n <= BASH_REMATCH[2]; n++)); do expanded+=("$n"); done
    else
      expanded+=("$w")
    fi
  done
  for w in "${expanded[@]}"; do
    found=0
    for ((n = 1; n <= COUNT; n++)); do
      if [[ $w == "$n" || $w == "${IDS[n]}" ]]; then SELECTED+=("$n"); found=1; fi
    done
    ((found)) || { echo "mutate: no mutant '$w'" >&2; exit 2; }
  done
else
  for ((n = 1; n <= COUNT; n++)); do SELECTED+=("$n"); done
fi

# The list must match the code: every original text exactly once, checked before any build.
stale=0
for n in "${SELECTED[@]}"; do
  if ! c=$(occurrences "$ROOT/$(field $n file)" "$WORK/mutants/$n/old"); then
    echo "mutate: mutant $n (${IDS[n]}): its original text occurs $c times in $(field $n file), not once; refresh tests/mutants.txt" >&2
    stale=1
  fi
done
((stale == 0)) || exit 2
if ((CHECK_ONLY)); then echo "mutate: all ${#SELECTED[@]} mutants match the code"; exit 0; fi

# The copy: tracked and untracked-but-not-ignored files. Files whose content changed are copied
# with a fresh mtime (so make rebuilds them); files no longer in the tree are removed.
echo "mutate: copying the tree to $SRC"
rm -rf "$WORK/stage"
mkdir -p "$WORK/stage" "$SRC"
if git -C "$ROOT" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git -C "$ROOT" ls-files -z --cached --others --exclude-standard |
    while IFS= read -r -d '' f; do if [[ -f $ROOT/$f ]]; then printf '%s\0' "$f"; fi; done >"$WORK/files"
else
  (cd "$ROOT" && find . -type f ! -path './.git/*' ! -path './build*' ! -path './out/*' -printf '%P\0') >"$WORK/files"
fi
tar -C "$ROOT" --null -T "$WORK/files" -cf - | tar -C "$WORK/stage" -xf -
(cd "$WORK/stage" && find . -type f -printf '%P\n' | sort) >"$WORK/stage.list"
(cd "$SRC" && find . -type f ! -path './out/*' -printf '%P\n' | sort) >"$WORK/src.list"
comm -13 "$WORK/stage.list" "$WORK/src.list" | while IFS= read -r f; do rm -f "$SRC/$f"; done
while IFS= read -r f; do
  if ! cmp -s "$WORK/stage/$f" "$SRC/$f"; then
    mkdir -p "$(dirname "$SRC/$f")"
    cp "$WORK/stage/$f" "$SRC/$f"
  fi
done <"$WORK/stage.list"
rm -rf "$WORK/stage"
# The git-ignored meshes the scenes name (scripts/setup.sh extracts them into out/meshes).
bash "$SRC/scripts/meshes.sh" "$SRC/out/meshes" >/dev/null

# ccache makes each revert a cache hit: without it, every mutant of a header included everywhere
# costs two full rebuilds. scripts/setup.sh installs it.
command -v ccache >/dev/null || { echo "mutate: ccache is missing; run scripts/setup.sh first" >&2; exit 2; }
LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSW_BENCH=OFF "${LAUNCHER[@]}" >"$WORK/configure.log" 2>&1 ||
  { cat "$WORK/configure.log"; echo "mutate: configure failed" >&2; exit 2; }

build() { timeout "${1:-$BUILD_TIMEOUT}" nice -n 10 cmake --build "$BUILD" --target sw_tests -j"$JOBS" >"$WORK/build.log" 2>&1; }
# Runs ctest on the tests matching $1 (all if empty) and not matching $2 (none if empty); $3 adds
# ctest options. Leaves the failed tests' names in $WORK/failed, sorted.
run_tests() {
  local args=(--test-dir "$BUILD" -j"$JOBS")
  [[ -n $1 ]] && args+=(-R "$1")
  [[ -n $2 ]] && args+=(-E "$2")
  rm -f "$BUILD/Testing/Temporary/LastTestsFailed.log"
  timeout "$TEST_TIMEOUT" nice -n 10 ctest "${args[@]}" ${3:-} >"$WORK/ctest.log" 2>&1 || true
  if grep -q "No tests were found" "$WORK/ctest.log"; then
    : >"$WORK/failed"  # an empty phase (the regex left nothing to run)
  elif grep -q "tests passed" "$WORK/ctest.log"; then
    sed -n 's/^[0-9]*://p' "$BUILD/Testing/Temporary/LastTestsFailed.log" 2>/dev/null | sort >"$WORK/failed" || true
  else
    echo "(ctest did not finish)" >"$WORK/failed"  # a hang, or ctest itself crashed
  fi
}
# A regex that matches exactly the names in file $1 (each non-alphanumeric character as ".").
names_regex() { [[ -s $1 ]] && sed 's/[^A-Za-z0-9 ]/./g; s/^/^/; s/$/$/' "$1" | paste -sd'|'; }

echo "mutate: building the unmutated tree"
t0=$SECONDS
build 0 || { tail -30 "$WORK/build.log"; echo "mutate: the unmutated tree does not build" >&2; exit 2; }
echo "mutate: built in $((SECONDS - t0)) s; running the tests"
t0=$SECONDS
run_tests "" ""
cp "$WORK/failed" "$WORK/baseline-failed"
BASELINE_RE=$(names_regex "$WORK/baseline-failed" || true)
echo "mutate: the unmutated suite took $((SECONDS - t0)) s"
if [[ -s $WORK/baseline-failed ]]; then
  echo "mutate: these tests fail without any mutant and are not counted:" >&2
  sed 's/^/  /' "$WORK/baseline-failed" >&2
fi

# Reverts the current mutant if the script stops half-way.
CURRENT=""
restore() {
  if [[ -n $CURRENT ]]; then cp "$WORK/original" "$SRC/$CURRENT"; CURRENT=""; fi
}
trap restore EXIT
trap 'exit 130' INT TERM

caught=0 total=0 missed=()
started=$SECONDS
for n in "${SELECTED[@]}"; do
  id=${IDS[n]} file=$(field $n file) regex=""
  ((FULL)) || regex=$(field $n tests)
  t0=$SECONDS
  cp "$SRC/$file" "$WORK/original"
  CURRENT=$file
  apply_mutant "$SRC/$file" "$WORK/mutants/$n/old" "$WORK/mutants/$n/new"
  total=$((total + 1))
  if ! build; then
    # A build stopped by a signal or the timeout says nothing about the mutant: stop there.
    grep -q "error:" "$WORK/build.log" || { echo "mutate: the build of mutant $n stopped without a compile error; see $WORK/build.log" >&2; exit 3; }
    status=caught detail="(compile)"
  else
    # The mutant's own tests first; only if they pass, the rest of the suite. Either way the
    # verdict is the whole suite's; tests that fail unmutated are left out.
    status=MISSED detail=""
    for phase in 1 2; do
      if [[ -z $regex ]]; then
        ((phase == 1)) && run_tests "" "$BASELINE_RE" --stop-on-failure
        ((phase == 2)) && break
      elif ((phase == 1)); then
        run_tests "$regex" "$BASELINE_RE" --stop-on-failure
      else
        ((QUICK)) && break
        run_tests "" "$regex${BASELINE_RE:+|$BASELINE_RE}" --stop-on-failure
      fi
      comm -23 "$WORK/failed" "$WORK/baseline-failed" >"$WORK/new-failures"
      if [[ -s $WORK/new-failures ]]; then
        status=caught
        detail="(phase $phase: $(head -2 "$WORK/new-failures" | cut -c1-60 | paste -sd'|'))"
        break
      fi
    done
    [[ $status == MISSED ]] && missed+=("$n $id")
  fi
  [[ $status == caught ]] && caught=$((caught + 1))
  restore
  printf '[%2d/%d] %3d %-30s %-6s %4d s  %s\n' "$total" "${#SELECTED[@]}" "$n" "$id" "$status" $((SECONDS - t0)) "$detail"
done

echo
echo "mutate: $total mutants in $(((SECONDS - started) / 60)) min $(((SECONDS - started) % 60)) s"
for m in "${missed[@]}"; do echo "  missed: $m"; done
echo "caught $caught of $total ($((total ? 100 * caught / total : 0))%)"
