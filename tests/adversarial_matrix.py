#!/usr/bin/env python3
"""Adversarial matrix: every bad input, on every algorithm and every subcommand, is refused the project's way.

    python3 tests/adversarial_matrix.py STEPWISE_EXE SOURCE_DIR SCRATCH_DIR
        [--jobs N] [--sample K] [--only TEXT] [--list] [--verbose] [--timing]

The contract (docs/cli.md, "Errors"): bad input prints ONE line on stderr, `stepwise: error: ...`, exits 2, prints
nothing on standard output and leaves no output file, partial or temporary. Each case runs in an empty directory of
its own, which is also its working directory and its TMPDIR; `--out`, `--gif`, `--plot`, `--html` and `--frames` point into it,
and it must still be empty afterwards. A case fails when it runs longer than 20 s, when its stderr line is longer
than 4 KiB (echoed input is cut to a short prefix) or when it peaks above 1 GiB of memory (a refusal comes before any
work; every command runs with RLIMIT_DATA at 1.5 GiB, so an unbounded read ends instead of filling the machine).

The matrix is derived from the binary and the tree, so a new algorithm, lesson, scene or subcommand is covered
without editing this file:
  - algorithms and their examples come from `stepwise list --json`. Each example must be accepted, and each case
    breaks exactly one thing in it: malformed, not an object, empty, (in turn) a duplicate key, a NUL byte or 100
    levels of nesting, each key of each kind of object left out, an unknown key in each, a tuple one element short,
    the faults of a number ("nan", "abc", a huge array, an object; 1e999, which the JSON reader refuses before any
    field, on the first number) on the first leaf of every field (a path with its list indices as *), one fault in
    turn on the last coordinate of its first tuple, rarer faults ("Infinity", "1/0", null, a 5000-character exact
    number) on the first number; bad paths (a directory, /dev/zero, a FIFO, a missing or garbage file) where the
    input names a file or a mesh; unknown and unsupported --numeric modes. `run` gets a two-line file whose line 2
    is broken (so nothing at all may be written); `check` gets the example's trace (in the first mode check agrees
    with) broken one way at a time; `render` and `bench` one or two faults each;
  - subcommands, and their budget options (`--max-*`, given -1, 2^64, 1e9, ...), come from `--help`; a subcommand
    with no cases of its own is a failure ("coverage");
  - lessons are SOURCE_DIR/lessons/*.md (questions from `quiz --list --json`), scenes SOURCE_DIR/scenes/*.json
    (copied beside links to the tree, so their relative files resolve). A bad line in a file of quiz answers is the
    one documented exception (docs/cli.md, "Grading a class"): it is skipped and named on one stderr line,
    `stepwise: skipped FILE:LINE: ...`, the rest is graded and the exit status is 1;
  - a key may be left out of an input only if the source declares it optional (the third argument of
    `only_keys_optional` under SOURCE_DIR); leaving it out is then a probe: accepted, or refused the project's way.
Rarer variants are spread over the algorithms in turn (`rot`), so the whole matrix stays near 3300 runs (about a
minute on two idle cores: each run of the binary costs some 30 ms of CPU, mostly loading its libraries).

Prints one line per failed case (the command, what went wrong, the first 200 characters of stderr) and a summary;
exit 0 only when every case held. Stdlib only; cases run on a pool of --jobs workers (default 2).
"""
import argparse
import concurrent.futures
import copy
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import threading
import time

TIMEOUT_S = 20                # a case's time limit
HUGE_ARRAY = 1 << 17          # elements of the "huge array" put where a number belongs (about 256 KiB of JSON)
LONG_EXACT = 5000             # characters of an exact number string: over the 4096 bound
DEAR_S = 1.0                  # a lesson or trace whose run takes longer than this gets only its cheap cases
MAX_ERR_BYTES = 4096          # the one stderr line: echoed input is cut to a short prefix (docs/cli.md)
MAX_RSS = 1 << 30             # a refusal comes before any work: a case that peaks above 1 GiB read or built too much
DATA_LIMIT = 3 << 29          # RLIMIT_DATA of every command run (1.5 GiB): an unbounded read ends, not the machine
BUDGET_VALUES = ["-1", "18446744073709551616", "", "1e9", "0x10", "abc", "4611686018427387905"]
BAD_SIZES = ["0x0", "-1x-1", "1099511627776x1099511627776", "0x240", "320x-1", "abc", "", "320x240x1", "319x240",
             "4097x4096"]
RAW = "@@adversarial-raw@@"   # a placeholder replaced by raw JSON text (1e999, a huge array)
ERR_PREFIX = "stepwise: error: "
NUMBER_STRING = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?$")


# ----------------------------------------------------------------------------------------------------------------
# Cases


class Case:
    """One command line. expect: REFUSE (exit 2, one error line), PROBE (a declared-optional key left out: accepted,
    or refused as REFUSE) or SKIP (a bad quiz answer line: skipped and named, exit 1, the rest graded)."""
    __slots__ = ("idx", "sub", "alg", "name", "argv", "files", "expect", "out_dir", "in_dir")

    def __init__(self, idx, sub, alg, name, argv, files, expect, out_dir, in_dir):
        self.idx, self.sub, self.alg, self.name = idx, sub, alg, name
        self.argv, self.files, self.expect = argv, files, expect
        self.out_dir, self.in_dir = out_dir, in_dir


class Matrix:
    """Collects cases; each gets an empty output directory and an input directory of its own."""

    def __init__(self, exe, root):
        self.exe, self.root, self.cases = exe, root, []

    def dirs(self):
        idx = len(self.cases)
        return idx, os.path.join(self.root, "out", "%05d" % idx), os.path.join(self.root, "in", "%05d" % idx)

    def add(self, sub, alg, name, make, expect="refuse"):
        """make(out_dir, in_dir) -> (argv without the exe, {path: bytes} to write before the run)."""
        idx, out_dir, in_dir = self.dirs()
        args, files = make(out_dir, in_dir)
        files = {p: (d.encode() if isinstance(d, str) else d) for p, d in (files or {}).items()}
        self.cases.append(Case(idx, sub, alg, name, [self.exe] + [str(a) for a in args], files, expect, out_dir,
                               in_dir))


# ----------------------------------------------------------------------------------------------------------------
# JSON helpers


def dumps(v):
    return json.dumps(v, separators=(",", ":"), ensure_ascii=False)


def with_raw(doc, path, raw):
    """The JSON text of doc with the value at path replaced by the raw text `raw`."""
    d = copy.deepcopy(doc)
    set_at(d, path, RAW)
    text = dumps(d)
    assert text.count('"%s"' % RAW) == 1
    return text.replace('"%s"' % RAW, raw)


def set_at(doc, path, value):
    cur = doc
    for p in path[:-1]:
        cur = cur[p]
    cur[path[-1]] = value


def del_at(doc, path):
    cur = doc
    for p in path[:-1]:
        cur = cur[p]
    del cur[path[-1]]


def get_at(doc, path):
    cur = doc
    for p in path:
        cur = cur[p]
    return cur


def path_name(path):
    s = "input"
    for p in path:
        s += "[%d]" % p if isinstance(p, int) else "." + p
    return s


def picked(lst):
    """The indices of a list to mutate: all of a short tuple (a point, a triangle); first and last of a long list of
    containers (the same parser reads every element)."""
    n = len(lst)
    if n > 4 and any(isinstance(x, (list, dict)) for x in lst):
        return [0, n - 1]
    return list(range(n))


def walk(v, path=()):
    """Yields (path, value) for every object and leaf to mutate, objects before their members."""
    if isinstance(v, dict):
        yield path, v
        for k, x in v.items():
            yield from walk(x, path + (k,))
    elif isinstance(v, list):
        yield path, v
        for i in picked(v):
            yield from walk(v[i], path + (i,))
    else:
        yield path, v


def is_numeric_leaf(v):
    if isinstance(v, bool) or v is None:
        return False
    if isinstance(v, (int, float)):
        return True
    return isinstance(v, str) and bool(NUMBER_STRING.match(v))


def is_path_leaf(key, v):
    return isinstance(v, str) and (key in ("file", "mesh", "scene") or "/" in v or
                                   re.search(r"\.(json|off|obj|png|md)$", v) is not None)


def huge_array():
    return "[" + ",".join(["0"] * HUGE_ARRAY) + "]"


def deep_array(levels=100):
    return "[" * levels + "0" + "]" * levels


def optional_keys(source_dir):
    """Key names the source declares optional: the third argument of every only_keys_optional(...) call."""
    names = set()
    for top in ("runtime", "algorithms", "cli", "visualizer"):
        base = os.path.join(source_dir, top)
        for dirpath, _, files in os.walk(base):
            for f in files:
                if not f.endswith((".cpp", ".hpp", ".h", ".cc")):
                    continue
                try:
                    text = open(os.path.join(dirpath, f), encoding="utf-8", errors="replace").read()
                except OSError:
                    continue
                for m in re.finditer(r"\bonly_keys_optional\s*\(", text):
                    args = split_call_args(text, m.end())
                    if len(args) >= 3 and args[2].strip().startswith("{"):
                        names.update(re.findall(r'"([^"\\]*)"', args[2]))
    return names


def split_call_args(text, start):
    """The top-level arguments of a call whose '(' ends just before start."""
    depth, args, cur, i, quote = 0, [], [], start, None
    while i < len(text):
        c = text[i]
        if quote:
            cur.append(c)
            if c == "\\":
                cur.append(text[i + 1])
                i += 1
            elif c == quote:
                quote = None
        elif c in "\"'":
            quote = c
            cur.append(c)
        elif c in "({[":
            depth += 1
            cur.append(c)
        elif c in ")}]":
            if depth == 0:
                args.append("".join(cur))
                return args
            depth -= 1
            cur.append(c)
        elif c == "," and depth == 0:
            args.append("".join(cur))
            cur = []
        else:
            cur.append(c)
        i += 1
    return args


# ----------------------------------------------------------------------------------------------------------------
# Running


def sh(argv, limit=300):
    """A command line for a report: shell-quoted, each argument cut at `limit` characters, on one line."""
    out = []
    for a in argv:
        q = shlex.quote(a)
        q = q if len(q) <= limit else q[:limit] + "...(%d chars)" % len(a)
        out.append(q.replace("\n", "\\n").replace("\r", "\\r").replace("\t", "\\t"))
    return " ".join(out)


def run_plain(argv, cwd=None, timeout=60):
    try:
        r = subprocess.run(argv, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
        return r.returncode, r.stdout.decode("utf-8", "replace"), r.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return None, "", "timed out"


def verdict(case, rc, out, err, timed_out, leftovers):
    """The problems of one case's run (an empty list when it was refused the project's way)."""
    if timed_out:
        return ["no answer within %d s" % TIMEOUT_S] + (["left %s" % leftovers] if leftovers else [])
    skip = case.expect == "skip"
    want_rc, prefix = (1, "stepwise: skipped ") if skip else (2, ERR_PREFIX)
    problems = []
    if rc != want_rc:
        problems.append("could not be run" if rc == -1000 else "killed by signal %d" % -rc if rc < 0
                        else "exit %d, not %d" % (rc, want_rc))
    if out and not skip:
        problems.append("%d bytes on stdout" % len(out))
    text = err.decode("utf-8", "replace")
    n = text.count("\n")
    if not text:
        problems.append("nothing on stderr")
    elif n != 1 or not text.endswith("\n"):
        problems.append("%d lines on stderr, not one" % (n + (0 if text.endswith("\n") else 1)))
    else:
        line = text[:-1]
        if not line.strip():
            problems.append("an empty stderr line")
        elif not line.startswith(prefix):
            problems.append("stderr line does not start with '%s'" % prefix)
        elif skip and not re.match(r"^stepwise: skipped \S+:\d+: ", line):
            problems.append("the skipped line is not named FILE:LINE")
        if len(err) > MAX_ERR_BYTES:
            problems.append("stderr line of %d bytes: echoed input not cut" % len(err))
    if "terminate called" in text or "Aborted" in text or "what():" in text:
        problems.append("an uncaught exception")
    if "bad_alloc" in text:
        problems.append("out of memory (std::bad_alloc)")
    if leftovers:
        problems.append("left %s in the output directory" % ", ".join(sorted(leftovers)[:5]))
    return problems


def spawn(argv, cwd, io_dir, timeout):
    """Runs argv with stdin empty and stdout, stderr into files of io_dir; kills it after timeout seconds.
    Returns (exit status or None when killed for time, stdout, stderr, seconds, max resident set in bytes)."""
    os.makedirs(io_dir, exist_ok=True)
    out_path, err_path = os.path.join(io_dir, ".stdout"), os.path.join(io_dir, ".stderr")
    t0 = time.monotonic()
    try:
        with open(out_path, "wb") as fo, open(err_path, "wb") as fe:
            # TMPDIR is the case's directory too, so a temporary file left anywhere the command puts one is seen.
            p = subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL, stdout=fo, stderr=fe,
                                 env=dict(os.environ, TMPDIR=cwd))
    except OSError as e:
        return -1000, b"", ("cannot run %s: %s\n" % (argv[0], e)).encode(), 0.0, 0
    state = {"done": False, "killed": False}
    lock = threading.Lock()

    def kill():
        with lock:
            if not state["done"]:
                state["killed"] = True
                os.kill(p.pid, 9)
    timer = threading.Timer(timeout, kill)
    timer.start()
    _, status, usage = os.wait4(p.pid, 0)   # the child's own rusage: its peak memory
    with lock:
        state["done"] = True
    timer.cancel()
    p.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.monotonic() - t0
    with open(out_path, "rb") as f:
        out = f.read()
    with open(err_path, "rb") as f:
        err = f.read()
    os.remove(out_path)
    os.remove(err_path)
    return (None if state["killed"] else p.returncode), out, err, seconds, usage.ru_maxrss * 1024


def run_case(case):
    """Runs one case; a failed case's files stay (its command line can be run again), a passing one's go."""
    os.makedirs(case.out_dir)
    for p, data in case.files.items():
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, "wb") as f:
            f.write(data)
    rc, out, err, seconds, rss = spawn(case.argv, case.out_dir, case.in_dir, TIMEOUT_S)
    leftovers = os.listdir(case.out_dir)
    if case.expect == "probe" and rc == 0:
        problems, accepted = [], True          # a declared-optional key left out: a valid input
    else:
        problems, accepted = verdict(case, rc, out, err, rc is None, leftovers), False
        if rss > MAX_RSS:
            problems.append("a peak of %d MB of memory" % (rss >> 20))
    if not problems:
        shutil.rmtree(case.out_dir, ignore_errors=True)
        for p in case.files:
            if os.path.isdir(p) and not os.path.islink(p):
                shutil.rmtree(p, ignore_errors=True)
            elif os.path.lexists(p):
                os.remove(p)
        shutil.rmtree(case.in_dir, ignore_errors=True)
    return case, problems, accepted, err.decode("utf-8", "replace"), seconds


# ----------------------------------------------------------------------------------------------------------------
# Discovering the CLI


def subcommands_of(exe, path):
    out = run_plain([exe] + path + ["--help"])[1]
    subs, in_section = [], False
    for line in out.splitlines():
        if line.strip() == "Subcommands:":
            in_section = True
            continue
        if in_section:
            m = re.match(r"^\s{2}(\S+)\s{2,}", line)
            if m:
                subs.append(m.group(1))
            elif line.strip() and not line.startswith(" "):
                in_section = False
    return subs


def budget_options_of(exe, path):
    _, out, _ = run_plain([exe] + path + ["--help"])
    return sorted(set(re.findall(r"^\s+(--max-[a-z-]+)\s+UINT", out, re.M)))


def numeric_modes_of(exe):
    _, out, _ = run_plain([exe, "trace", "--help"])
    m = re.search(r"--numeric TEXT\s+([a-z| ]+)", out)
    modes = [x.strip() for x in m.group(1).split("|")] if m else []
    return [x for x in modes if x] or ["float", "double", "int", "filtered", "exact", "reference"]


# ----------------------------------------------------------------------------------------------------------------
# The matrix


def build(exe, source, root, setup_failures, notes):
    M = Matrix(exe, root)
    shared = os.path.join(root, "shared")
    os.makedirs(shared)
    fifo = os.path.join(shared, "fifo.json")
    os.mkfifo(fifo)
    adir = os.path.join(shared, "a-directory.json")
    os.mkdir(adir)
    garbage = os.path.join(shared, "garbage.json")
    with open(garbage, "w") as f:
        f.write("this is not json nor a mesh\n\x01\x02")
    missing = os.path.join(shared, "does-not-exist.json")
    bad_paths = [("a directory", adir), ("/dev/zero", "/dev/zero"), ("a FIFO", fifo), ("a missing file", missing),
                 ("a file of garbage", garbage)]
    # The same for a mesh, named .off so that the file, not its name, is what is wrong.
    os.mkdir(os.path.join(shared, "a-directory.off"))
    os.symlink("/dev/zero", os.path.join(shared, "zero.off"))
    os.mkfifo(os.path.join(shared, "fifo.off"))
    with open(os.path.join(shared, "garbage.off"), "w") as f:
        f.write("OFF\n3 1 0\nzz not numbers\n")
    bad_meshes = [("a directory", os.path.join(shared, "a-directory.off")), ("/dev/zero", "/dev/zero"),
                  ("a link to /dev/zero", os.path.join(shared, "zero.off")), ("a FIFO", os.path.join(shared, "fifo.off")),
                  ("a missing file", os.path.join(shared, "missing.off")),
                  ("a file of garbage", os.path.join(shared, "garbage.off"))]

    _, listing, err = run_plain([exe, "list", "--json"])
    algs = []
    for line in listing.splitlines():
        if line.strip():
            algs.append(json.loads(line))
    if not algs:
        setup_failures.append("setup: `list --json` gave no algorithms (%s)" % err.strip()[:200])
        return M
    all_modes = numeric_modes_of(exe)
    optional = optional_keys(source)
    if not optional:
        notes.append("note: no only_keys_optional(...) found under %s: every key is taken as required" % source)

    # Each example must be accepted (so a case's fault is its own), and its trace is the base of check's cases.
    base = os.path.join(shared, "base")
    os.makedirs(base)

    def trace_base(a):
        """The example traced in its default mode, or else in the first mode whose trace `check` agrees with."""
        t = os.path.join(base, a["id"] + ".jsonl")
        order = ["exact", "reference", "int", "filtered", "double", "float"]
        modes = sorted(a.get("modes", []), key=lambda m: order.index(m) if m in order else len(order))
        for m in [None] + modes:
            rc, _, e = run_plain([exe, "trace", a["id"], "--input", dumps(a["example"]), "--out", t] +
                                 (["--numeric", m] if m else []), cwd=shared)
            if rc != 0:
                if m is None:
                    return a, "the example is refused: exit %s: %s" % (rc, e.strip()[:200]), None
                continue
            t0 = time.monotonic()
            if run_plain([exe, "check", t], cwd=shared)[0] == 0:
                return a, None, (open(t, encoding="utf-8").read(), time.monotonic() - t0)
        return a, "no trace of the example passes check: check's cases left out", None

    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        bases = list(pool.map(trace_base, algs))
    traces = {}
    for a, problem, text in bases:
        if problem:
            setup_failures.append("setup: %s: %s" % (a["id"], problem))
        else:
            traces[a["id"]] = text

    for k, a in enumerate(algs):
        algorithm_cases(M, k, a, all_modes, optional, bad_paths, bad_meshes, traces.get(a["id"]))
    traces = {aid: text for aid, (text, _) in traces.items()}

    first = algs[0]
    lessons = sorted(os.path.join(source, "lessons", f) for f in os.listdir(os.path.join(source, "lessons"))
                     if f.endswith(".md")) if os.path.isdir(os.path.join(source, "lessons")) else []
    questions = lesson_questions(exe, lessons, setup_failures)
    command_cases(M, first, missing, adir)
    check_global_cases(M, missing, adir)
    render_cases(M, algs, lessons, missing, adir)
    bench_cases(M, algs)
    # A good answers file for the first lesson (its first question answered in the right form).
    good_answers = os.path.join(shared, "answers.jsonl")
    with open(good_answers, "w") as f:
        qs = questions.get(lessons[0], ([], 0))[0] if lessons else []
        f.write(dumps({"step": qs[0]["step"], "answer": good_answer(qs[0])}) + "\n" if qs else "")
    lesson_cases(M, lessons, questions, missing, adir, fifo, good_answers)
    scene_cases(M, exe, source, shared, notes)
    budget_cases(M, exe, first, lessons, source, traces, setup_failures)
    generic_cases(M, exe, setup_failures)
    return M


def rot(k, items):
    """Item k of a rotation: a variant every algorithm need not get, spread over the algorithms."""
    return items[k % len(items)]


def tail_leaf(path, doc):
    """True for the last element of a tuple whose other list indices on the path are all 0 (p0[1], triangle[0][2])."""
    ints = [i for i, p in enumerate(path) if isinstance(p, int)]
    if not ints or ints[-1] != len(path) - 1 or path[-1] == 0:
        return False
    if any(path[i] != 0 for i in ints[:-1]):
        return False
    return path[-1] == len(get_at(doc, path[:-1])) - 1


# The faults of a number, each put on the first leaf of every field. 1e999 is among them only for the first number of
# an input and in the rotation: the JSON reader refuses it before any field is read, so its field does not matter.
LEAF_FAULTS = [('"nan"', '"nan"'), ("1e999", "1e999"), ('"abc"', '"abc"'), ("a huge array", None), ("an object", '{"x":1}')]
FIELD_FAULTS = [f for f in LEAF_FAULTS if f[0] != "1e999"]


def leaf_faults():
    return [(what, raw if raw is not None else huge_array()) for what, raw in LEAF_FAULTS]


def algorithm_cases(M, k, a, all_modes, optional, bad_paths, bad_meshes, trace_text):
    aid, ex = a["id"], a["example"]
    good = dumps(ex)
    first_key = next(iter(ex))
    duplicate = "{%s:%s,%s" % (dumps(first_key), dumps(ex[first_key]), good[1:])

    def trace(name, text, expect="refuse", via_file=None, extra=()):
        if via_file is None:
            via_file = len(text) > 60000 or not text.startswith("{") or "\0" in text

        def make(out_dir, in_dir):
            files = {}
            arg = text
            if via_file:
                arg = os.path.join(in_dir, "input.json")
                files[arg] = text
            return ["trace", aid, "--input", arg, "--out", os.path.join(out_dir, "t.jsonl")] + list(extra), files
        M.add("trace", aid, name, make, expect)

    def run(name, line2, extra=()):
        def make(out_dir, in_dir):
            f = os.path.join(in_dir, "in.jsonl")
            return (["run", aid, "--inputs", f, "--out", os.path.join(out_dir, "r.jsonl")] + list(extra),
                    {f: good + "\n" + line2 + "\n"})
        M.add("run", aid, "line 2: " + name, make)

    # The whole text; the rarer forms in turn.
    half = good[:len(good) // 2]
    trace("malformed JSON (truncated in the middle)", half)
    trace("not an object: [1,2]", "[1,2]", via_file=True)
    trace("an empty object", "{}")
    for what, text, via_file in [rot(k, [("a duplicate key", duplicate, None),
                                         ("a NUL byte inside", good[:-1] + "\0}", True),
                                         ("nested 100 levels deep", deep_array(), True)]),
                                 rot(k, [("malformed JSON (last brace missing)", good[:-1], None),
                                         ("trailing garbage after the object", good + " x", None),
                                         ("a UTF-16 text", good.encode("utf-16").decode("latin-1"), True)]),
                                 rot(k, [("not an object: an empty file", "", True), ("not an object: 42", "42", True),
                                         ('not an object: "text"', '"text"', True), ("not an object: null", "null", True),
                                         ("not an object: [example]", "[%s]" % good, True),
                                         ("%s nested 100 levels deep" % path_name((first_key,)),
                                          with_raw(ex, (first_key,), deep_array()), None)])]:
        trace(what, text, via_file=via_file)
    # Numeric modes.
    trace("an unknown --numeric mode", good, extra=["--numeric", "quad"])
    lacking = [m for m in all_modes if m not in a.get("modes", [])]
    if lacking:
        trace("a --numeric mode it lacks (%s)" % lacking[0], good, extra=["--numeric", lacking[0]])
    elif k % 2:
        trace("an empty --numeric mode", good, extra=["--numeric", ""])

    # Every field (a path with its list indices as *): an unknown key in each kind of object, each key left out,
    # each fault on the field's first leaf, and one fault (in turn) on the last coordinate of its first tuple.
    # (The reader-level faults above, a duplicate key, a NUL byte, deep nesting, are the reader's and not the
    # algorithm's: each algorithm gets one of them, in turn.)
    first_numeric, spread, seen, short_left = None, k, set(), 2   # "one element short": two fields an algorithm

    def first_time(path):
        field = tuple("*" if isinstance(p, int) else p for p in path)
        if field in seen:
            return False
        seen.add(field)
        return True

    for path, v in walk(ex):
        if isinstance(v, dict):
            if first_time(path):
                trace("an unknown key in %s" % path_name(path), with_raw(ex, path + ("zz_unknown",), "1"))
                for key in v:
                    d = copy.deepcopy(ex)
                    del_at(d, path + (key,))
                    trace("%s removed" % path_name(path + (key,)), dumps(d),
                          expect="probe" if key in optional else "refuse")
            continue
        if isinstance(v, list):
            if (first_time(path) and path and len(v) >= 2 and all(not isinstance(x, (list, dict)) for x in v)
                    and short_left > 0):
                short_left -= 1
                trace("%s one element short" % path_name(path), with_raw(ex, path, dumps(v[:-1])))
            continue
        key = path[-1] if path else None
        if is_numeric_leaf(v):
            if first_numeric is None:
                first_numeric = path
            if first_time(path):
                faults = LEAF_FAULTS if path == first_numeric else FIELD_FAULTS
            elif tail_leaf(path, ex):   # the last coordinate of the field's first tuple: one fault, in turn
                faults = [rot(spread, LEAF_FAULTS)]
                spread += 1
            else:
                faults = []
            for what, raw in faults:
                trace("%s = %s" % (path_name(path), what), with_raw(ex, path, raw if raw is not None else huge_array()))
        elif isinstance(v, str):
            if not first_time(path):
                continue
            if is_path_leaf(key, v):
                for what, p in bad_paths:
                    trace("%s = %s" % (path_name(path), what), with_raw(ex, path, dumps(p)))
                trace("%s = {}" % path_name(path), with_raw(ex, path, "{}"))
            else:
                for what, raw in [('"zz-unknown"', '"zz-unknown"'), ("a number", "7"), ('""', '""')]:
                    trace("%s = %s" % (path_name(path), what), with_raw(ex, path, raw))

    if first_numeric is not None:   # the rarer faults of a number, on the first one, in turn
        p = first_numeric
        for what, raw in [rot(k, [('"Infinity"', '"Infinity"'), ('"NaN"', '"NaN"'), ('"-Infinity"', '"-Infinity"'),
                                  ("-1e999", "-1e999")]),
                          rot(k, [('"1/0"', '"1/0"'), ("null", "null"), ("true", "true"), ("[]", "[]"), ('""', '""')]),
                          ("an exact number of %d characters" % LONG_EXACT, '"1%s"' % ("0" * (LONG_EXACT - 1)))]:
            trace("%s = %s" % (path_name(p), what), with_raw(ex, p, raw))
    # A mesh file in place of the listed geometry.
    for listed in ("triangles", "points"):
        if listed in ex:
            for what, p in bad_meshes:
                d = copy.deepcopy(ex)
                del d[listed]
                d["mesh"] = p
                trace("mesh = %s in place of %s" % (what, listed), dumps(d))

    # run: line 1 is the example, line 2 the fault; nothing at all may be written.
    run("malformed JSON", half)
    run("an unknown key", with_raw(ex, ("zz_unknown",), "1"))
    run(*rot(k, [("not an object", "[1,2]"), ("a number", "42"), ("a NUL byte", good[:-1] + "\0}"),
                 ("a duplicate key", duplicate), ("nested 100 levels deep", deep_array()),
                 ("trailing garbage", good + " x"), ("an empty object", "{}")]))
    required = [key for key in ex if key not in optional]
    if required:
        key = rot(k, required)
        d = copy.deepcopy(ex)
        del d[key]
        run("%s removed" % path_name((key,)), dumps(d))
    if first_numeric is not None:
        what, raw = leaf_faults()[k % len(LEAF_FAULTS)]
        run("%s = %s" % (path_name(first_numeric), what), with_raw(ex, first_numeric, raw))

    def run_whole(name, extra=()):
        def make(out_dir, in_dir):
            f = os.path.join(in_dir, "in.jsonl")
            return (["run", aid, "--inputs", f, "--out", os.path.join(out_dir, "r.jsonl")] + list(extra),
                    {f: good + "\n" + good + "\n"})
        M.add("run", aid, name, make)
    run_whole("an unknown --numeric mode", ["--numeric", "quad"])
    if lacking:
        run_whole("a --numeric mode it lacks (%s)" % lacking[0], ["--numeric", lacking[0]])

    # check: the example's own trace (one that check agrees with), broken one way at a time.
    if trace_text is not None:
        check_cases(M, k, aid, *trace_text)


def check_cases(M, k, aid, text, seconds):
    """seconds: how long check took to agree with the trace. A dear replay (over DEAR_S) gets only the faults in
    the header, which are found before it."""
    lines = text.splitlines(keepends=True)
    header = json.loads(lines[0])

    def hdr(**kw):
        h = dict(header)
        for key, v in kw.items():
            if v is None:
                h.pop(key, None)
            else:
                h[key] = v
        return dumps(h) + "\n"

    rest = "".join(lines[1:])
    hin = header.get("input")
    variants = [
        ("no result line", "".join(lines[:-1])),
        ("an unknown algorithm in the header", hdr(algorithm="zz-no-such-algorithm") + rest),
        ("an unknown key in the header's input",
         hdr(input=dict(hin, zz_unknown=1) if isinstance(hin, dict) else {"zz_unknown": 1}) + rest),
        ("trailing garbage after the result line", text + "garbage\n"),
        rot(k, [("cut inside its last step", "".join(lines[:-2]) + lines[-2][:len(lines[-2]) // 2]),
                ("a step line that is not JSON", lines[0] + '{"step":0,\n' + "".join(lines[2:])),
                ("cut inside the header", lines[0][:len(lines[0]) // 2]),
                ("the header only", lines[0]),
                ("an unknown numeric mode in the header", hdr(numeric="quad") + rest),
                ("no input in the header", hdr(input=None) + rest),
                ("another format in the header", hdr(format="not-a-trace") + rest),
                ("version 99 in the header", hdr(version=99) + rest),
                ("garbage on the result line", "".join(lines[:-1]) + lines[-1].rstrip("\n") + " garbage\n"),
                ("a NUL byte in a step", lines[0] + lines[1][:-2] + "\0" + lines[1][-2:] + "".join(lines[2:])),
                ("the header's input malformed", lines[0].replace('"input":', '"input":{', 1) + rest)]),
    ]
    if seconds > DEAR_S:
        variants = [v for v in variants if "header" in v[0]]
    for name, body in variants:
        def make(out_dir, in_dir, body=body):
            f = os.path.join(in_dir, "t.jsonl")
            return ["check", f], {f: body}
        M.add("check", aid, "a trace with " + name, make)


def check_global_cases(M, missing, adir):
    for name, arg in [("a missing file", missing), ("a directory", adir), ("/dev/zero", "/dev/zero"),
                      ("empty standard input", "-")]:
        M.add("check", None, name, lambda o, i, arg=arg: (["check", arg], {}))

    def empty(o, i):
        f = os.path.join(i, "t.jsonl")
        return ["check", f], {f: ""}
    M.add("check", None, "an empty file", empty)


def command_cases(M, first, missing, adir):
    aid, good = first["id"], dumps(first["example"])
    # trace and run themselves.
    for name, args in [
        ("an unknown algorithm", ["trace", "zz-no-such-algorithm", "--input", good]),
        ("an empty algorithm", ["trace", "", "--input", good]),
        ("a newline in the algorithm", ["trace", aid + "\nx", "--input", good]),
        ("a missing input file", ["trace", aid, "--input", missing]),
        ("a directory as input", ["trace", aid, "--input", adir]),
        ("/dev/zero as input", ["trace", aid, "--input", "/dev/zero"]),
        ("no --input", ["trace", aid]),
        ("an unknown option", ["trace", aid, "--input", good, "--zz-bogus", "1"]),
        ("an extra positional", ["trace", aid, "extra", "--input", good]),
    ]:
        M.add("trace", aid if "algorithm" not in name else None, name,
              lambda o, i, args=args: (args + ["--out", os.path.join(o, "t.jsonl")], {}))
    M.add("trace", aid, "--out is a directory", lambda o, i: (["trace", aid, "--input", good, "--out", o], {}))
    M.add("trace", aid, "--out in a missing directory",
          lambda o, i: (["trace", aid, "--input", good, "--out", os.path.join(o, "missing", "t.jsonl")], {}))
    M.add("trace", aid, "--out /dev/full", lambda o, i: (["trace", aid, "--input", good, "--out", "/dev/full"], {}))
    M.add("trace", aid, "an output budget of 10 bytes",
          lambda o, i: (["trace", aid, "--input", good, "--max-output", "10", "--out", os.path.join(o, "t.jsonl")], {}))
    for name, args in [
        ("a missing inputs file", ["run", aid, "--inputs", missing]),
        ("a directory of inputs", ["run", aid, "--inputs", adir]),
        ("/dev/zero as inputs", ["run", aid, "--inputs", "/dev/zero"]),
        ("no --inputs", ["run", aid]),
    ]:
        M.add("run", None if "algorithm" in name else aid, name,
              lambda o, i, args=args: (args + ["--out", os.path.join(o, "r.jsonl")], {}))

    def run_zz(o, i):
        f = os.path.join(i, "in.jsonl")
        return ["run", "zz-no-such-algorithm", "--inputs", f, "--out", os.path.join(o, "r.jsonl")], {f: good + "\n"}
    M.add("run", None, "an unknown algorithm with a good inputs file", run_zz)

    def run_budget(o, i):
        f = os.path.join(i, "in.jsonl")
        return (["run", aid, "--inputs", f, "--max-output", "10", "--out", os.path.join(o, "r.jsonl")],
                {f: good + "\n" + good + "\n"})
    M.add("run", aid, "an output budget of 10 bytes", run_budget)
    # list and schema.
    for name, args in [("--listing an unknown algorithm", ["list", "--listing", "zz-no-such-algorithm"]),
                       ("--listing an empty name", ["list", "--listing", ""]),
                       ("--listing without a name", ["list", "--listing"]),
                       ("--contract an unknown algorithm", ["list", "--contract", "zz-no-such-algorithm"]),
                       ("--contract an unknown algorithm, --json", ["list", "--contract", "zz-no-such-algorithm", "--json"]),
                       ("--contract a callee, which has no input of its own", ["list", "--contract", "refract"]),
                       ("--contract an empty name", ["list", "--contract", ""]),
                       ("--contract without a name", ["list", "--contract"]),
                       ("--contract with --listing", ["list", "--contract", aid, "--listing", aid]),
                       ("--contract with --markdown", ["list", "--contract", aid, "--markdown"]),
                       ("an extra positional", ["list", "extra"]),
                       ("an unknown option", ["list", "--zz-bogus"])]:
        M.add("list", None, name, lambda o, i, args=args: (args, {}))
    for name, args in [("an unknown name", ["schema", "zz-no-such-algorithm"]),
                       ("an algorithm's name", ["schema", aid]),
                       ("an unknown option", ["schema", "--zz-bogus"])]:
        M.add("schema", None, name, lambda o, i, args=args: (args, {}))
    for name, args in [("an unknown subcommand", ["zz-no-such-command"]), ("no subcommand", []),
                       ("an empty subcommand", [""]), ("an unknown option", ["--zz-bogus"])]:
        M.add("(top level)", None, name, lambda o, i, args=args: (args, {}))


def render_cases(M, algs, lessons, missing, adir):
    for k, a in enumerate(algs):
        aid, ex = a["id"], a["example"]
        for name, extra in [("an unknown key in the input", ["--input", with_raw(ex, ("zz_unknown",), "1")]),
                            rot(k, [("malformed input", ["--input", dumps(ex)[:len(dumps(ex)) // 2]]),
                                    ("an unknown --view", ["--input", dumps(ex), "--view", "zz-bogus"]),
                                    ("--step 2^40", ["--input", dumps(ex), "--step", str(1 << 40)]),
                                    ("an unknown --numeric mode", ["--input", dumps(ex), "--numeric", "quad"]),
                                    ("an empty input", ["--input", "{}"])])]:
            M.add("render", aid, name,
                  lambda o, i, aid=aid, extra=extra: (["render", "--algorithm", aid] + extra +
                                                      ["--out", os.path.join(o, "x.png")], {}))
    a = algs[0]
    aid, good = a["id"], dumps(a["example"])
    base = ["render", "--algorithm", aid, "--input", good]
    cases = [("an unknown algorithm", ["render", "--algorithm", "zz-no-such-algorithm", "--input", good], "png"),
             ("--input without --algorithm", ["render", "--input", good], "png"),
             ("--lesson and --algorithm", ["render", "--algorithm", aid, "--input", good, "--lesson",
                                           lessons[0] if lessons else missing], "png"),
             ("a missing lesson", ["render", "--lesson", missing], "png"),
             ("a directory as lesson", ["render", "--lesson", adir], "png"),
             ("/dev/zero as lesson", ["render", "--lesson", "/dev/zero"], "png"),
             ("an unknown --compare", base + ["--compare", "zz-bogus"], "png"),
             ("--compare an algorithm of another group", base + ["--compare", algs[-1]["id"]], "png"),
             ("--scale 0", base + ["--scale", "0"], "png"),
             ("--scale 100", base + ["--scale", "100"], "png"),
             ("--scale nan", base + ["--scale", "nan"], "png"),
             ("--scale -1", base + ["--scale", "-1"], "png"),
             ("--step -1", base + ["--step", "-1"], "png"),
             ("--step 2^64", base + ["--step", "18446744073709551616"], "png"),
             ("--out and --gif", base, "both"),
             ("--from after --to", base + ["--from", "5", "--to", "2"], "gif"),
             ("--to past the last step", base + ["--to", str(1 << 40)], "gif"),
             ("--delay 0", base + ["--delay", "0"], "gif"),
             ("--delay 100000", base + ["--delay", "100000"], "gif"),
             ("--max-pixels 1", base + ["--max-pixels", "1"], "gif"),
             ("--from without --gif", base + ["--from", "1"], "png"),
             ("an unknown option", base + ["--zz-bogus"], "png"),
             ("--out is a directory", base, "dir"),
             ("--out in a missing directory", base, "missing-dir")]
    for s in BAD_SIZES:
        cases.append(("--size %r" % s, base + ["--size", s], "png"))
    for name, args, kind in cases:
        def make(o, i, args=args, kind=kind):
            outs = {"png": ["--out", os.path.join(o, "x.png")], "gif": ["--gif", os.path.join(o, "x.gif")],
                    "both": ["--out", os.path.join(o, "x.png"), "--gif", os.path.join(o, "x.gif")],
                    "dir": ["--out", o], "missing-dir": ["--out", os.path.join(o, "missing", "x.png")]}[kind]
            return args + outs, {}
        M.add("render", None if "algorithm" in name else aid, name, make)


def bench_cases(M, algs):
    # The sets belong to a family: an unknown set on the first algorithm of each (every set is generated before the
    # name is looked up, up to 0.9 s an algorithm).
    families = set()
    for a in algs:
        aid = a["id"]
        if a.get("family") in families:
            continue
        families.add(a.get("family"))
        M.add("bench", aid, "an unknown --set",
              lambda o, i, aid=aid: (["bench", aid, "--set", "zz-no-such-set", "--repeats", "1", "--plot",
                                      os.path.join(o, "p.svg")], {}))
    aid = algs[0]["id"]
    quick = ["--set", "random", "--repeats", "1"]
    for name, args in [("an unknown algorithm", ["bench", "zz-no-such-algorithm"] + quick),
                       ("--repeats 0", ["bench", aid, "--set", "random", "--repeats", "0"]),
                       ("--repeats 101", ["bench", aid, "--set", "random", "--repeats", "101"]),
                       ("--repeats -1", ["bench", aid, "--set", "random", "--repeats", "-1"]),
                       ("--repeats abc", ["bench", aid, "--set", "random", "--repeats", "abc"]),
                       ("an unknown --numeric mode", ["bench", aid, "--numeric", "quad"] + quick),
                       ("an empty --set", ["bench", aid, "--set", "", "--repeats", "1"]),
                       ("--full given a value", ["bench", aid, "--full=maybe"] + quick),
                       ("--full with an unknown --set", ["bench", aid, "--full", "--set", "zz-no-such-set", "--repeats", "1"]),
                       ("an unknown option", ["bench", aid, "--zz-bogus"] + quick)]:
        M.add("bench", None if "algorithm" in name else aid, name, lambda o, i, args=args: (args, {}))
    for name, plot, size in [("--plot FILE.txt", "p.txt", None), ("--plot without an extension", "p", None),
                             ("--plot in a missing directory", os.path.join("missing", "p.svg"), None),
                             ("--plot is a directory", "", None),
                             ("--plot-size 10x10", "p.svg", "10x10"), ("--plot-size 5000x5000", "p.svg", "5000x5000"),
                             ("--plot-size -1x-1", "p.png", "-1x-1"), ("--plot-size abc", "p.svg", "abc"),
                             ("--plot-size 2^40", "p.svg", "1099511627776x1099511627776")]:
        def make(o, i, plot=plot, size=size):
            args = ["bench", aid] + quick + ["--plot", os.path.join(o, plot) if plot else o]
            return args + (["--plot-size", size] if size else []), {}
        M.add("bench", aid, name, make)


def lesson_questions(exe, lessons, setup_failures):
    """{lesson: ([question], seconds `quiz --list` took)}."""
    def ask(path):
        t0 = time.monotonic()
        rc, out, err = run_plain([exe, "quiz", path, "--list", "--json"])
        return path, rc, out, err, time.monotonic() - t0
    result = {}
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        for path, rc, out, err, seconds in pool.map(ask, lessons):
            if rc != 0:
                setup_failures.append("setup: `quiz %s --list --json` failed: exit %s: %s" % (path, rc, err.strip()[:200]))
                continue
            result[path] = ([json.loads(l) for l in out.splitlines() if l.strip()], seconds)
    return result


def good_answer(q):
    t = q.get("type", "")
    if t == "pixel":
        return [0, 0]
    if t == "branch":
        return (q.get("choices") or ["x"])[0]
    if t.startswith("sign"):
        return 0
    if t == "diverge":
        return q["step"] + 1
    return True  # hit, flag, same


def wrong_form(q):
    t = q.get("type", "")
    if t == "pixel":
        return "zz-not-a-cell"
    if t == "branch":
        return "zz-no-such-line"
    if t.startswith("sign"):
        return 5
    if t == "diverge":
        return -1
    return 7


def lesson_cases(M, lessons, questions, missing, adir, fifo, good_answers):
    # quiz: a line of answers broken one way at a time, after a good first line.
    for k, (path, (qs, seconds)) in enumerate(sorted(questions.items())):
        name = os.path.basename(path)
        steps = {q["step"] for q in qs}
        free = next(s for s in range(0, 1 << 20) if s not in steps)
        lines2 = [("a step with no question", dumps({"step": free, "answer": 0}))]
        if qs:
            q = qs[0]
            first = dumps({"step": q["step"], "answer": good_answer(q)})
            lines2 += [("malformed JSON", '{"step":%d,' % q["step"]),
                       ("an answer of the wrong form", dumps({"step": q["step"], "answer": wrong_form(q)})),
                       rot(k, [("not an object", "[1]"),
                               ("an unknown field", dumps({"step": q["step"], "answer": good_answer(q), "zz": 1})),
                               ("no answer", dumps({"step": q["step"]})),
                               ("no step", dumps({"answer": good_answer(q)})),
                               ("step -1", dumps({"step": -1, "answer": good_answer(q)})),
                               ("step 1e999", '{"step":1e999,"answer":%s}' % dumps(good_answer(q))),
                               ("step 2^64", '{"step":18446744073709551616,"answer":%s}' % dumps(good_answer(q))),
                               ("a student that is not a string",
                                dumps({"step": q["step"], "answer": good_answer(q), "student": 5}))])]
        else:
            first = None
        if seconds > DEAR_S:   # a dear lesson (its run takes seconds): the malformed line and the free step only
            lines2 = lines2[:2]
        for what, line in lines2:
            def make(o, i, path=path, first=first, line=line):
                f = os.path.join(i, "answers.jsonl")
                return ["quiz", path, "--answers", f], {f: (first + "\n" if first else "") + line + "\n"}
            # docs/cli.md, "Grading a class": a bad answer line is skipped and named (exit 1), not a refusal.
            M.add("quiz", None, "%s: answers line %d: %s" % (name, 2 if first else 1, what), make, "skip")
    first_lesson = lessons[0] if lessons else missing
    for what, args in [("a missing lesson", ["quiz", missing, "--list"]),
                       ("a directory as lesson", ["quiz", adir, "--list"]),
                       ("/dev/zero as lesson", ["quiz", "/dev/zero", "--list"]),
                       ("a missing answers file", ["quiz", first_lesson, "--answers", missing]),
                       ("a directory holding no answers", ["quiz", first_lesson, "--answers", adir]),
                       ("/dev/zero as answers", ["quiz", first_lesson, "--answers", "/dev/zero"]),
                       ("a FIFO as answers", ["quiz", first_lesson, "--answers", fifo]),
                       ("a good answers file and a missing one", ["quiz", first_lesson, "--answers", good_answers,
                                                                  "--answers", missing]),
                       ("--answers and --list", ["quiz", first_lesson, "--list", "--answers", good_answers]),
                       ("--csv and --json", ["quiz", first_lesson, "--answers", good_answers, "--csv", "--json"]),
                       ("--csv and --list", ["quiz", first_lesson, "--list", "--csv"]),
                       ("neither --answers nor --list", ["quiz", first_lesson]),
                       ("an unknown option", ["quiz", first_lesson, "--list", "--zz-bogus"])]:
        M.add("quiz", None, what, lambda o, i, args=args: (args, {}))

    # Broken lessons: each real lesson with its algorithm or its input broken, then one lesson broken many ways.
    def front(text):
        m = re.match(r"^---\n(.*?)\n---\n", text, re.S)
        return m
    readers = [("quiz", lambda f, o: ["quiz", f, "--list"]),
               ("render", lambda f, o: ["render", "--lesson", f, "--out", os.path.join(o, "x.png")]),
               ("lesson export", lambda f, o: ["lesson", "export", f, "--frames", os.path.join(o, "page")])]
    broken = []   # (what, text, the readers that get it)
    for k, path in enumerate(lessons):
        text = open(path, encoding="utf-8").read()
        name = os.path.basename(path)
        m = front(text)
        if not m:
            continue
        broken.append((name + " with an unknown algorithm",
                       re.sub(r"(?m)^algorithm:.*$", "algorithm: zz-no-such-algorithm", text, count=1),
                       [rot(k, readers)]))
        broken.append((name + " with its input line truncated",
                       re.sub(r"(?m)^(input: )(.*)$", lambda mm: mm.group(1) + mm.group(2)[:len(mm.group(2)) // 2],
                              text, count=1), [rot(k + 1, readers)]))
    if lessons:
        text = open(lessons[0], encoding="utf-8").read()
        name = os.path.basename(lessons[0])
        body = text[front(text).end():] if front(text) else text

        def sub_key(key, value):
            return re.sub(r"(?m)^%s:.*$" % key, "%s: %s" % (key, value), text, count=1)

        def drop_key(key):
            return re.sub(r"(?m)^%s:.*\n" % key, "", text, count=1)
        generic = [
            (name + " without front matter", body),
            (name + " with unterminated front matter", "---" + text[3:].replace("\n---\n", "\n", 1)),
            (name + " without algorithm", drop_key("algorithm")),
            (name + " without input", drop_key("input")),
            (name + " with an unknown numeric", sub_key("numeric", "quad") if re.search(r"(?m)^numeric:", text)
             else text.replace("\n---\n", "\nnumeric: quad\n---\n", 1)),
            (name + " with an unknown front-matter key", text.replace("\n---\n", "\nzz_unknown: 1\n---\n", 1)),
            (name + " with a duplicate front-matter key", text.replace("\n---\n", "\ntitle: again\ntitle: twice\n---\n", 1)),
            (name + " with an unknown key in its input",
             re.sub(r"(?m)^input: \{", 'input: {"zz_unknown":1,', text, count=1)),
            (name + " with 1e400 in its input",
             re.sub(r"(?m)^input: \{(\"[^\"]+\"):\[", r"input: {\1:[1e400,", text, count=1)),
            (name + " with an unknown compare", text.replace("\n---\n", "\ncompare: zz-bogus\n---\n", 1)),
            (name + " with an unknown show", text.replace("\n---\n", "\nshow: zz-bogus\n---\n", 1)),
            (name + " with step -1", sub_key("step", "-1") if re.search(r"(?m)^step:", text)
             else text.replace("\n---\n", "\nstep: -1\n---\n", 1)),
            (name + " with a section heading at level 3", text + "\n### on line zz\nx\n"),
            (name + " with a section on an unknown line", text + "\n## on line zz-no-such-line\nx\n"),
            (name + " with a quiz of an unknown type", text + "\n## quiz zz on step 1: what?\nx\n"),
            (name + " with a NUL byte", text.replace("\n---\n", "\n\0\n---\n", 1)),
            (name + ", empty", ""),
        ]
        broken += [(what, text, readers) for what, text in generic]
    for what, text, subs in broken:
        for sub, args in subs:
            def make(o, i, text=text, args=args):
                f = os.path.join(i, "lesson.md")
                return args(f, o), {f: text}
            M.add(sub, None, what, make)

    # lesson export and lint options.
    if lessons:
        L = lessons[0]
        export_cases = [("a missing lesson", [missing], "page"), ("a directory as lesson", [adir], "page"),
                        ("/dev/zero as lesson", ["/dev/zero"], "page"),
                        ("--from after --to", [L, "--from", "5", "--to", "2"], "page"),
                        ("--to past the last step", [L, "--from", "0", "--to", str(1 << 40)], "page"),
                        ("--from past the last step", [L, "--from", str(1 << 40)], "page"),
                        ("--from -1", [L, "--from", "-1"], "page"),
                        ("the directory in a missing directory", [L], "missing"),
                        ("an empty directory name", [L], "empty"),
                        ("an unknown option", [L, "--zz-bogus"], "page")]
        for s in BAD_SIZES:
            export_cases.append(("--size %r" % s, [L, "--size", s], "page"))
        # The flip-book (--frames) takes every case; the app's page (--html) those without frame options.
        for flag in ("--frames", "--html"):
            for what, args, html in export_cases:
                if flag == "--html" and ("--size" in args or "--to" in args):
                    continue
                def make(o, i, args=args, html=html, flag=flag):
                    dest = {"page": os.path.join(o, "page"), "missing": os.path.join(o, "missing", "page"),
                            "empty": ""}[html]
                    return ["lesson", "export"] + args + [flag, dest], {}
                M.add("lesson export", None, flag + ": " + what, make)
        for what, args in [("a missing lesson", [missing]), ("a directory as lesson", [adir]),
                           ("/dev/zero as lesson", ["/dev/zero"]), ("a good lesson and a missing one", [L, missing]),
                           ("an unknown option", [L, "--zz-bogus"])]:
            M.add("lesson lint", None, what, lambda o, i, args=args: (["lesson", "lint"] + args, {}))


def scene_cases(M, exe, source, shared, notes):
    scenes_dir = os.path.join(source, "scenes")
    if not os.path.isdir(scenes_dir):
        notes.append("note: no scenes directory: scene cases left out")
        return
    # A mirror of the source tree's layout, so a copied scene's relative files (textures, ../out/meshes) resolve.
    mirror = os.path.join(shared, "tree")
    os.makedirs(mirror)
    for entry in os.listdir(source):
        if entry != "scenes":
            os.symlink(os.path.join(source, entry), os.path.join(mirror, entry))
    sdir = os.path.join(mirror, "scenes")
    os.makedirs(sdir)
    for entry in os.listdir(scenes_dir):
        if not entry.endswith(".json"):
            os.symlink(os.path.join(scenes_dir, entry), os.path.join(sdir, entry))
    os.mkdir(os.path.join(sdir, "mesh-dir.off"))
    os.symlink("/dev/zero", os.path.join(sdir, "zero.off"))
    os.mkfifo(os.path.join(sdir, "fifo.off"))
    with open(os.path.join(sdir, "garbage.off"), "w") as f:
        f.write("OFF\n3 1 0\nzz not numbers\n")
    mesh_paths = [("a directory", "mesh-dir.off"), ("/dev/zero (a link to it)", "zero.off"),
                  ("/dev/zero (absolute)", "/dev/zero"), ("a FIFO", "fifo.off"), ("a missing file", "missing.off"),
                  ("a file of garbage", "garbage.off")]

    def probe(f):
        """(name, the scene) when its copy beside the mirror is accepted, as each case's copy will be."""
        try:
            doc = json.load(open(os.path.join(scenes_dir, f), encoding="utf-8"))
        except ValueError:
            return f, None, "not JSON"
        copy_path = os.path.join(sdir, "probe-" + f)
        with open(copy_path, "w") as fh:
            fh.write(dumps(doc))
        rc, _, err = run_plain([exe, "scene", "check", copy_path])
        os.remove(copy_path)
        return f, doc, None if rc == 0 else "its copy is refused (exit %s: %s)" % (rc, err.strip()[:120])

    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        probed = list(pool.map(probe, sorted(f for f in os.listdir(scenes_dir) if f.endswith(".json"))))
    bases = []
    for f, doc, problem in probed:
        if problem:
            notes.append("note: scenes/%s left out: %s" % (f, problem))
        else:
            bases.append((f, doc))
    if not bases:
        return

    def mutations(doc, full):
        out = []
        text = dumps(doc)
        out.append(("malformed JSON (truncated)", text[:len(text) // 2]))
        d = copy.deepcopy(doc)
        d.pop("camera", None)
        out.append(("no camera", dumps(d)))
        mat = next(iter(doc.get("materials", {"m": {}})))
        objs = doc.get("objects", [])
        d = copy.deepcopy(doc)
        spheres = [k for k, o in enumerate(objs) if o.get("type") == "sphere"]
        if spheres:
            d["objects"][spheres[0]]["radius"] = -1
        else:
            d["objects"].append({"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": mat})
        out.append(("a negative radius", dumps(d)))
        d = copy.deepcopy(doc)
        d["objects"][0]["type"] = "zz-no-such-type"
        out.append(("an unknown object type", dumps(d)))
        for what, p in mesh_paths if full else mesh_paths[:2]:
            d = copy.deepcopy(doc)
            d["objects"][0] = {"type": "mesh", "file": p, "material": mat}
            out.append(("a mesh that is " + what, dumps(d)))
        if not full:
            return out
        out += [("not an object", "[]"), ("an empty object", "{}"), ("an empty file", ""),
                ("nested 100 levels deep", deep_array()), ("an unknown key", with_raw(doc, ("zz_unknown",), "1")),
                ("a duplicate key", '{"camera":%s,%s' % (dumps(doc["camera"]), text[1:]))]
        for k in ("objects", "materials", "lights"):
            d = copy.deepcopy(doc)
            d.pop(k, None)
            out.append(("no " + k, dumps(d)))
        d = copy.deepcopy(doc)
        d["objects"][0]["material"] = "zz-no-such-material"
        out.append(("an unknown material", dumps(d)))
        d = copy.deepcopy(doc)
        d["objects"] = []
        out.append(("an empty list of objects", dumps(d)))
        cam = doc["camera"]
        for k in ("eye", "vpn", "vup", "d", "resolution"):
            if k in cam:
                d = copy.deepcopy(doc)
                del d["camera"][k]
                out.append(("a camera without %s" % k, dumps(d)))
        for what, raw in [('"nan"', '"nan"'), ("1e999", "1e999"), ('"abc"', '"abc"'), ("a huge array", huge_array()),
                          ("an object", '{"x":1}')]:
            out.append(("camera.eye[0] = " + what, with_raw(doc, ("camera", "eye", 0), raw)))
        out.append(("resolution 0x0", with_raw(doc, ("camera", "resolution"), "[0,0]")))
        out.append(("vup parallel to vpn", with_raw(doc, ("camera", "vup"), dumps(cam["vpn"]))))
        d = copy.deepcopy(doc)
        d["objects"][0] = {"type": "sphere", "center": [0, 0, 0], "radius": 0, "material": mat}
        out.append(("a zero radius", dumps(d)))
        d = copy.deepcopy(doc)
        d["objects"][0] = {"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": mat}
        out.append(("a collinear triangle", dumps(d)))
        d = copy.deepcopy(doc)
        d["materials"][mat] = {"kr": 0.1, "kt": 0.9}
        out.append(("kr 0.1 + kt 0.9 over 1", dumps(d)))
        d = copy.deepcopy(doc)
        d["lights"] = [{"type": "point", "position": [0, 0, 0]}] * 9
        out.append(("nine lights", dumps(d)))
        d = copy.deepcopy(doc)
        d["materials"][mat] = {"texture": "zz-no-such-texture"}
        out.append(("an unknown texture", dumps(d)))
        d = copy.deepcopy(doc)
        d["textures"] = {"t": {"type": "image", "file": "zero.off"}}
        d["materials"][mat] = {"texture": "t"}
        out.append(("an image texture that is /dev/zero", dumps(d)))
        return out

    subcommands = [("scene check", lambda f, o: ["scene", "check", f]),
                   ("scene plan", lambda f, o: ["scene", "plan", f]),
                   ("scene render", lambda f, o: ["scene", "render", f, "--size", "8x6", "--quiet", "--threads", "1",
                                                  "--out", os.path.join(o, "x.png")]),
                   ("scene export-pov", lambda f, o: ["scene", "export-pov", f, "--out", os.path.join(o, "x.pov")]),
                   ("scene raster", lambda f, o: ["scene", "raster", f, "--size", "8x6", "--quiet", "--out", os.path.join(o, "x.png")])]
    full_base = next((b for b in bases if b[0] == "cornell-box.json"), bases[0])
    turn = 0
    for f, doc in bases:
        full = f == full_base[0]
        for what, text in mutations(doc, full):
            # One scene gets every fault on every reader; the others each fault on one reader, in turn.
            turn += 1
            for sub, args in subcommands if full else [rot(turn, subcommands)]:
                def make(o, i, text=text, args=args):
                    # Beside the mirrored scenes, so relative files resolve as in scenes/.
                    p = os.path.join(sdir, "case-%s.json" % os.path.basename(i))
                    return args(p, o), {p: text}
                M.add(sub, None, "%s: %s" % (f, what), make)
    missing = os.path.join(sdir, "missing.json")
    for what, p in [("a missing scene file", missing), ("a directory as scene", sdir), ("/dev/zero as scene", "/dev/zero")]:
        for sub, args in subcommands:
            M.add(sub, None, what, lambda o, i, p=p, args=args: (args(p, o), {}))
    good = os.path.join(source, "scenes", full_base[0])
    render = ["scene", "render", good, "--quiet"]
    cases = [("--spp 0", ["--spp", "0"]), ("--spp 3 (not a square)", ["--spp", "3"]), ("--spp 1024", ["--spp", "1024"]),
             ("--spp -1", ["--spp", "-1"]), ("--threads 999", ["--threads", "999"]), ("--threads -1", ["--threads", "-1"]),
             ("an unknown --offset", ["--offset", "zz-bogus"]), ("--max-rays 1", ["--max-rays", "1"]),
             ("an unknown option", ["--zz-bogus"])]
    for s in ["0x0", "-1x-1", "1099511627776x1099511627776", "8193x1", "abc", "", "8x"]:
        cases.append(("--size %r" % s, ["--size", s]))
    for what, extra in cases:
        M.add("scene render", None, what,
              lambda o, i, extra=extra: (render + extra + ["--out", os.path.join(o, "x.png")], {}))
    M.add("scene render", None, "--out is a directory", lambda o, i: (render + ["--size", "8x6", "--out", o], {}))
    M.add("scene render", None, "--out in a missing directory",
          lambda o, i: (render + ["--size", "8x6", "--out", os.path.join(o, "missing", "x.png")], {}))
    M.add("scene render", None, "no --out", lambda o, i: (render + ["--size", "8x6"], {}))
    pov = ["scene", "export-pov", good]
    for what, extra in [("an unknown --mode", ["--mode", "zz-bogus"]),
                        ("--mode shadow --light 99", ["--mode", "shadow", "--light", "99"]),
                        ("--light -1", ["--mode", "shadow", "--light", "-1"]),
                        ("--size 0x0", ["--size", "0x0"]), ("--size -1x5", ["--size", "-1x5"]),
                        ("--size 2^40", ["--size", "1099511627776x1099511627776"]), ("--size abc", ["--size", "abc"]),
                        ("--size ''", ["--size", ""]), ("an unknown option", ["--zz-bogus"])]:
        M.add("scene export-pov", None, what, lambda o, i, extra=extra: (pov + extra + ["--out", os.path.join(o, "x.pov")], {}))
    M.add("scene export-pov", None, "--out is a directory", lambda o, i: (pov + ["--out", o], {}))
    raster = ["scene", "raster", good, "--quiet"]
    cases = [("--stacks %s" % v, ["--stacks", v]) for v in ["0", "1", "257", "-1", "abc", "99999999999"]]
    cases += [("--numeric int", ["--numeric", "int"]), ("--numeric reference", ["--numeric", "reference"]),
              ("an unknown --shading", ["--shading", "zz-bogus"]), ("an unknown option", ["--zz-bogus"])]
    cases += [("--size %r" % v, ["--size", v]) for v in ["0x0", "-1x-1", "8193x1", "abc", "", "8x", "4096x8192"]]
    for what, extra in cases:
        M.add("scene raster", None, what, lambda o, i, extra=extra: (raster + extra + ["--out", os.path.join(o, "x.png")], {}))
    M.add("scene raster", None, "--out is a directory", lambda o, i: (raster + ["--size", "8x6", "--out", o], {}))
    M.add("scene raster", None, "--out in a missing directory",
          lambda o, i: (raster + ["--size", "8x6", "--out", os.path.join(o, "missing", "x.png")], {}))
    M.add("scene raster", None, "--depth in a missing directory",
          lambda o, i: (raster + ["--size", "8x6", "--out", os.path.join(o, "x.png"), "--depth", os.path.join(o, "missing", "d.png")], {}))
    M.add("scene raster", None, "no --out", lambda o, i: (raster + ["--size", "8x6"], {}))
    fisheye = os.path.join(source, "scenes", "tiny-scale.json")
    M.add("scene raster", None, "a fisheye camera", lambda o, i: (["scene", "raster", fisheye, "--size", "8x6", "--out", os.path.join(o, "x.png")], {}))
    for sub in ("check", "plan"):
        M.add("scene " + sub, None, "an unknown option", lambda o, i, sub=sub: (["scene", sub, good, "--zz-bogus"], {}))


def budget_cases(M, exe, first, lessons, source, traces, setup_failures):
    """Every --max-* option of every command, given -1, 2^64 and other non-counts, on an otherwise good command."""
    aid, good = first["id"], dumps(first["example"])
    scene = os.path.join(source, "scenes", "cornell-box.json")
    lesson = lessons[0] if lessons else None
    base_trace = traces.get(aid)

    def templates(sub, opt):
        """(argv, files) of a good command of `sub` for option `opt`, given the case's directories."""
        if sub == "trace":
            return lambda o, i: (["trace", aid, "--input", good, "--out", os.path.join(o, "t.jsonl")], {})
        if sub == "run":
            def make(o, i):
                f = os.path.join(i, "in.jsonl")
                return ["run", aid, "--inputs", f, "--out", os.path.join(o, "r.jsonl")], {f: good + "\n"}
            return make
        if sub == "check" and base_trace is not None:
            def make(o, i):
                f = os.path.join(i, "t.jsonl")
                return ["check", f], {f: base_trace}
            return make
        if sub == "render":
            if opt == "--max-pixels":
                return lambda o, i: (["render", "--algorithm", aid, "--input", good, "--gif", os.path.join(o, "x.gif")], {})
            return lambda o, i: (["render", "--algorithm", aid, "--input", good, "--out", os.path.join(o, "x.png")], {})
        if sub == "quiz" and lesson:
            return lambda o, i: (["quiz", lesson, "--list"], {})
        if sub == "lesson export" and lesson:
            return lambda o, i: (["lesson", "export", lesson, "--from", "0", "--to", "1", "--size", "320x240", "--frames",
                                  os.path.join(o, "page")], {})
        if sub == "lesson lint" and lesson:
            return lambda o, i: (["lesson", "lint", lesson], {})
        if sub == "scene render" and os.path.exists(scene):
            return lambda o, i: (["scene", "render", scene, "--size", "8x6", "--quiet", "--out", os.path.join(o, "x.png")], {})
        if sub == "scene raster" and os.path.exists(scene):
            return lambda o, i: (["scene", "raster", scene, "--size", "8x6", "--identity", "--quiet", "--out", os.path.join(o, "x.png")], {})
        return None

    for path in leaf_subcommands(exe):
        sub = " ".join(path)
        for opt in budget_options_of(exe, path):
            t = templates(sub, opt)
            if t is None:
                setup_failures.append("coverage: %s takes %s but the matrix has no good command of it to break" % (sub, opt))
                continue
            for v in BUDGET_VALUES:
                def make(o, i, t=t, opt=opt, v=v):
                    args, files = t(o, i)
                    return args + [opt, v], files
                M.add(sub, None, "%s %r" % (opt, v), make)
            M.add(sub, None, "%s without a value" % opt, lambda o, i, t=t, opt=opt: (t(o, i)[0] + [opt], t(o, i)[1]))


_LEAVES = None


def leaf_subcommands(exe):
    global _LEAVES
    if _LEAVES is None:
        leaves = []
        for s in subcommands_of(exe, []):
            inner = subcommands_of(exe, [s])
            leaves += [[s, x] for x in inner] if inner else [[s]]
        _LEAVES = leaves
    return _LEAVES


def generic_cases(M, exe, setup_failures):
    """Every subcommand the help lists: an unknown option; and each must have cases of its own above."""
    covered = {c.sub for c in M.cases}
    for path in leaf_subcommands(exe):
        sub = " ".join(path)
        M.add(sub, None, "an unknown option and nothing else", lambda o, i, path=path: (path + ["--zz-bogus"], {}))
        if sub not in covered:
            setup_failures.append("coverage: subcommand '%s' has no cases of its own in the matrix" % sub)
    for group in {p[0] for p in leaf_subcommands(exe) if len(p) > 1}:
        M.add(group, None, "no subcommand", lambda o, i, group=group: ([group], {}))
        M.add(group, None, "an unknown subcommand", lambda o, i, group=group: ([group, "zz-no-such-subcommand"], {}))


# ----------------------------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("exe")
    ap.add_argument("source")
    ap.add_argument("scratch")
    ap.add_argument("--jobs", type=int, default=2, help="cases run at once (default 2)")
    ap.add_argument("--sample", type=int, default=1, help="run every K-th case only (for development)")
    ap.add_argument("--only", default="", help="run only cases whose subcommand, algorithm or name holds this text")
    ap.add_argument("--list", action="store_true", help="print the cases instead of running them")
    ap.add_argument("--timing", action="store_true", help="also print the time taken per subcommand")
    ap.add_argument("--verbose", action="store_true", help="also print every passing case with its stderr line")
    args = ap.parse_args()

    t0 = time.monotonic()
    try:   # inherited by every command run: an unbounded read fails at 1.5 GiB instead of filling the machine
        import resource
        hard = resource.getrlimit(resource.RLIMIT_DATA)[1]
        if hard == resource.RLIM_INFINITY or hard > DATA_LIMIT:
            resource.setrlimit(resource.RLIMIT_DATA, (DATA_LIMIT, hard))
    except (ImportError, ValueError, OSError):
        pass
    exe = os.path.abspath(args.exe)
    source = os.path.abspath(args.source)
    root = os.path.join(os.path.abspath(args.scratch), "adversarial-matrix")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    setup_failures, notes = [], []
    M = build(exe, source, root, setup_failures, notes)
    cases = M.cases
    if args.only:
        cases = [c for c in cases if args.only in c.sub or args.only in (c.alg or "") or args.only in c.name]
    cases = cases[::max(1, args.sample)]
    if args.list:
        for c in cases:
            print("%s | %s | %s" % (c.sub, c.alg or "-", c.name))
        print("%d cases" % len(cases))
        return 0

    failures, accepted, slowest, per_sub = [], 0, (0.0, None), {}
    lock = threading.Lock()
    with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
        for case, problems, was_accepted, err, seconds in pool.map(run_case, cases):
            with lock:
                accepted += was_accepted
                n, total = per_sub.get(case.sub, (0, 0.0))
                per_sub[case.sub] = (n + 1, total + seconds)
                if seconds > slowest[0]:
                    slowest = (seconds, case)
                if problems:
                    failures.append((case, problems, err))
                elif args.verbose:
                    print("ok [%s%s: %s] %s" % (case.sub, " " + case.alg if case.alg else "", case.name,
                                                "accepted (an optional key)" if was_accepted else json.dumps(err[:300])))

    for line in notes:
        print(line)
    if args.timing:
        for sub, (n, total) in sorted(per_sub.items(), key=lambda x: -x[1][1]):
            print("timing: %-18s %5d cases %7.1f s  %5.1f ms a case" % (sub, n, total, 1000 * total / n))
        if slowest[1] is not None:
            print("timing: slowest %.2f s: %s" % (slowest[0], sh(slowest[1].argv[1:], 120)))
    for line in setup_failures:
        print(line)
    for case, problems, err in failures:
        what = "%s%s: %s" % (case.sub, " " + case.alg if case.alg else "", case.name)
        print("FAIL [%s] %s: %s; stderr: %s" % (what.replace("\n", "\\n"), sh(case.argv[1:]), "; ".join(problems),
                                                json.dumps(err[:200])))
    leaves = {" ".join(p) for p in leaf_subcommands(exe)}
    subs = {c.sub for c in cases if c.sub in leaves}
    algs = {c.alg for c in cases if c.alg}
    elapsed = time.monotonic() - t0
    skipped = sum(c.expect == "skip" for c in cases)
    print("adversarial matrix: %.1f s (slowest case %.1f s)%s%s" % (
        elapsed, slowest[0], "; %d optional keys left out were accepted" % accepted if accepted else "",
        "; %d of the cases are bad quiz answer lines, skipped as documented (exit 1)" % skipped if skipped else ""))
    if setup_failures:
        print("adversarial matrix: %d setup or coverage problems" % len(setup_failures))
    if failures or setup_failures:
        if failures:
            print("adversarial matrix: the failed cases' files are under %s" % root)
        print("adversarial matrix: %d cases, %d failed" % (len(cases), len(failures)))
        return 1
    shutil.rmtree(root, ignore_errors=True)
    print("adversarial matrix: %d cases over %d algorithms and %d subcommands, all refused with one line, exit 2, "
          "no file" % (len(cases), len(algs), len(subs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
