#!/usr/bin/env python3
"""The student contract, end to end (ctest: student_contract).

usage: student_contract.py STEPWISE SOURCE_DIR WORK_DIR

1. The helpers: student/stepwise_trace.h (compiled as C99 by `cc` and as C++ by `c++`) and
   student/stepwise_trace.py write JSON strings and numbers that read back as what was given.
2. The reference student programs (student/examples/dda.c in double, dda.py in exact rationals)
   pass `stepwise check` (in full, --decisions-only and --results-only) on dda-line and
   dda-grid-walk over steep, negative-direction, single-point and corner-crossing inputs.
3. Three planted bugs (each patched into both programs) fail `check` at the first step where the
   buggy program's trace differs from the correct program's, computed here from the two traces,
   with a message naming that step's listing line (number and name, from `list --listing`) and a
   second line naming the step before it.
4. `list --contract ALG --json` covers every listing line (`list --listing`) and every step form
   (line, kind, variable names and types, geometry kinds) of real traces of inputs the contract did
   not sample, for several algorithms, two with nested callees (bezier-forward-diff calls dda-line,
   whitted calls refract and scene-hit).
5. The contracts quoted in docs/assignment-dda.md equal `list --contract`'s output.
"""
import json
import os
import re
import shutil
import subprocess
import sys
from fractions import Fraction

EXE, SRC, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
STUDENT = os.path.join(SRC, "student")
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def run(args, env=None, stdin=None):
    p = subprocess.run(args, capture_output=True, text=True, env=env, input=stdin, timeout=120)
    return p.returncode, p.stdout, p.stderr


def listing(alg):
    """The listing's line names, in order, from `stepwise list --listing`."""
    rc, out, err = run([EXE, "list", "--listing", alg])
    if rc != 0:
        fail(f"list --listing {alg}: exit {rc}: {err.strip()}")
        return []
    names = []
    for row in out.splitlines()[1:]:
        m = re.match(r"\s*(\d+) (\S+)", row)
        if m:
            names.append(m.group(2))
    return names


def compile_c(source, out):
    rc, _, err = run(["cc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-I", STUDENT, source, "-lm", "-o", out])
    if rc != 0:
        fail(f"cc {source}: {err.strip()[:400]}")
        return False
    return True


# 1. The helpers' strings and numbers.
os.makedirs(WORK, exist_ok=True)
ODD = 'quote " backslash \\ newline \n tab \t bell \x07 unicode \u00e9'
REALS = [0.1, 1 / 3, -2.5e-300, 1e300, 123456789.125, 2.0 ** -1074, -0.0]
probe_c = os.path.join(WORK, "probe.c")
with open(probe_c, "w") as f:
    f.write('#include "stepwise_trace.h"\nint main(void) {\n  sw_trace t;\n'
            '  sw_trace_begin(&t, stdout, "dda-line", "double", "{}");\n  sw_step(&t, 1, "init");\n')
    for k, v in enumerate(REALS):
        f.write(f'  sw_real(&t, "r{k}", {v!r});\n')
    f.write('  sw_exact(&t, "e", 7, -2);\n  sw_real(&t, "nan", 0.0 / 0.0);\n  sw_real(&t, "inf", -1.0 / 0.0);\n')
    c_literal = "".join(chr(b) if 32 <= b < 127 and chr(b) not in '"\\' else "\\%03o" % b for b in ODD.encode("utf-8"))
    f.write('  sw_point(&t, 1, 2);\n  sw_label(&t, "%s");\n' % c_literal)
    f.write('  sw_result_begin(&t);\n  sw_result_int(&t, "n", 3);\n  sw_result_list_begin(&t, "pixels");\n'
            '  sw_result_pixel(&t, 1, -2);\n  sw_result_pixel(&t, 3, 4);\n  sw_result_list_end(&t);\n'
            '  sw_result_real(&t, "x", 0.5);\n  return sw_trace_end(&t);\n}\n')
probe = os.path.join(WORK, "probe")
if compile_c(probe_c, probe):
    rc, out, err = run([probe])
    lines = [json.loads(x) for x in out.splitlines()]
    step = lines[1]
    for k, v in enumerate(REALS):
        got = step["vars"][f"r{k}"]
        if float(got) != v:  # the value; the trace format has no signed zero (numbers are rationals)
            fail(f"C helper: {v!r} written as {got!r}")
    if step["vars"]["e"] != "-7/2" or step["vars"]["nan"] != "NaN" or step["vars"]["inf"] != "-Infinity":
        fail(f"C helper: exact or non-finite values: {step['vars']}")
    if step["geo"] != [{"point": [1, 2], "label": ODD}]:
        fail(f"C helper: the label did not read back: {step['geo']!r}")
    if lines[2] != {"result": {"n": 3, "pixels": [[1, -2], [3, 4]], "x": 0.5}}:
        fail(f"C helper: result line {lines[2]!r}")
cxx = shutil.which("c++")
rc, _, err = run([cxx or "c++", "-x", "c++", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-I", STUDENT, probe_c])
if rc != 0:
    fail(f"stepwise_trace.h as C++: {err.strip()[:400]}")
py_probe = (
    "import io, sys\nfrom fractions import Fraction\nfrom stepwise_trace import Trace, point\n"
    "out = io.StringIO()\n"
    f"t = Trace('dda-line', 'exact', {{'p0': [Fraction(5, 4), 0]}}, out, listing=['delta', 'major'])\n"
    f"t.step('major', 'decide', {{'e': Fraction(-7, 2), 'b': True, 'v': (0.1, float('nan'))}}, [point(1, 2, label={ODD!r})])\n"
    "t.result(pixels=[(1, 2)])\nsys.stdout.write(out.getvalue())\n")
rc, out, err = run(["/usr/bin/python3", "-c", py_probe], env=dict(os.environ, PYTHONPATH=STUDENT))
if rc != 0:
    fail(f"Python helper: {err.strip()[:400]}")
else:
    h, s, r = [json.loads(x) for x in out.splitlines()]
    if h["input"] != {"p0": ["5/4", 0]} or h["listing"] != ["delta", "major"]:
        fail(f"Python helper: header {h!r}")
    if s != {"step": 0, "line": 2, "kind": "decide", "vars": {"e": "-7/2", "b": 1, "v": [0.1, "NaN"]},
             "geo": [{"point": [1, 2], "label": ODD}]}:
        fail(f"Python helper: step {s!r}")
    if r != {"result": {"pixels": [[1, 2]]}}:
        fail(f"Python helper: result {r!r}")

# 2. The reference student programs pass check.
LINE_INPUTS = [
    ("the example", "1.25 2.5 12.75 7.25"),
    ("steep", "2 2 4 9"),
    ("steep, negative direction", "4 9 2 2"),
    ("shallow, negative direction", "12.75 7.25 1.25 2.5"),
    ("falling through pixel corners", "-0.5 0.5 4.5 -2.5"),
    ("ties: the minor axis at exactly 1/2", "0 0 4 2"),
    ("vertical", "3 -2 3 8"),
    ("a single point at a centre", "3 3 3 3"),
    ("a single point at a corner", "0.5 0.5 0.5 0.5"),
]
WALK_INPUTS = [
    ("the example", "1.25 2.5 9.5 6.5"),
    ("45 degrees through corners", "0.5 0.5 8.5 8.5"),
    ("anti-diagonal through corners", "0.5 -0.5 -7.5 7.5"),
    ("slope 1/2 through corners", "0.5 0.5 8.5 4.5"),
    ("slope -2 through corners, negative direction", "1.5 -3.5 -0.5 0.5"),
    ("steep, negative direction", "4 9 2 2"),
    ("vertical on a column boundary", "2.5 -3.25 2.5 4.75"),
    ("a single point", "3 3 3 3"),
    ("a single point at a corner", "0.5 0.5 0.5 0.5"),
]
c_prog = os.path.join(WORK, "dda")
compile_c(os.path.join(STUDENT, "examples", "dda.c"), c_prog)
PY_ENV = dict(os.environ, PYTHONPATH=STUDENT)
PROGRAMS = {"C": [c_prog], "Python": ["/usr/bin/python3", os.path.join(STUDENT, "examples", "dda.py")]}


def trace_of(program, alg, args, env=None):
    rc, out, err = run(program + [alg] + args.split(), env=env)
    if rc != 0:
        fail(f"{program[-1]} {alg} {args}: exit {rc}: {err.strip()[:300]}")
    return out


def steps_of(text):
    return [json.loads(x) for x in text.splitlines()[1:-1]]


def check(text, *flags):
    return run([EXE, "check", "-"] + list(flags), stdin=text)


passed = 0
for alg, inputs in [("dda-line", LINE_INPUTS), ("dda-grid-walk", WALK_INPUTS)]:
    for what, args in inputs:
        for lang, program in PROGRAMS.items():
            text = trace_of(program, alg, args, PY_ENV)
            for flags in [(), ("--decisions-only",), ("--results-only",)]:
                rc, out, err = check(text, *flags)
                if rc != 0 or not out.startswith("ok: "):
                    fail(f"{lang} {alg} ({what}: {args}) {' '.join(flags)}: check exit {rc}: {(out + err).strip()[:300]}")
                else:
                    passed += 1
            # The corner inputs must cross a corner exactly: a pick with tMax_x = tMax_y.
            if "corner" in what and alg == "dda-grid-walk" and args.split()[:2] != args.split()[2:]:
                if not any(s["line"] == 5 and Fraction(str(s["vars"]["tMax_x"])) == Fraction(str(s["vars"]["tMax_y"]))
                           for s in steps_of(text)):
                    fail(f"{lang} {alg} ({what}): no step crosses a corner exactly")
print(f"correct programs: {passed} checks passed")

# 3. Planted bugs: (name, algorithm, inputs, C patch, Python patch), each patch (old, new) unique.
BUGS = [
    ("off by one: the walk runs one column past p1", "dda-line", ["0 0 7 3", "4 9 2 2"],
     ("if (!(q[a] < p1[a])) {", "if (!(q[a] <= p1[a])) {"),
     ("        if not q[a] < p1[a]:", "        if not q[a] <= p1[a]:")),
    ("truncation instead of round-half", "dda-line", ["1.25 2.5 12.75 7.25", "2 2 4.5 9"],
     ("return (long long)floor(v + 0.5);", "return (long long)v;"),
     ("return math.floor(v + Fraction(1, 2))", "return math.trunc(v)")),
    ("corner tie-break: x steps before y where both leave at once", "dda-grid-walk", ["0.5 0.5 8.5 4.5", "0.5 -0.5 -7.5 7.5"],
     ("t_max[0] < t_max[1]);", "t_max[0] <= t_max[1]);"),
     ("t_max[0] < t_max[1])", "t_max[0] <= t_max[1])")),
]
caught = []
for k, (bug, alg, inputs, c_patch, py_patch) in enumerate(BUGS):
    names = listing(alg)
    for lang, patch in [("C", c_patch), ("Python", py_patch)]:
        source = os.path.join(STUDENT, "examples", "dda.c" if lang == "C" else "dda.py")
        text = open(source).read()
        if text.count(patch[0]) != 1:
            fail(f"bug '{bug}': the {lang} patch's text occurs {text.count(patch[0])} times in {source}")
            continue
        mutant = os.path.join(WORK, f"bug{k}_{os.path.basename(source)}")
        with open(mutant, "w") as f:
            f.write(text.replace(patch[0], patch[1]))
        if lang == "C":
            if not compile_c(mutant, mutant[:-2]):
                continue
            program = [mutant[:-2]]
        else:
            program = ["/usr/bin/python3", mutant]
        for args in inputs:
            good = steps_of(trace_of(PROGRAMS[lang], alg, args, PY_ENV))
            bad_text = trace_of(program, alg, args, PY_ENV)
            bad = steps_of(bad_text)
            # The first step where the buggy trace differs from the correct one.
            first = next((i for i, (g, b) in enumerate(zip(good, bad)) if g != b), min(len(good), len(bad)))
            if good == bad:
                fail(f"bug '{bug}' ({lang}, {args}): the buggy program's trace equals the correct one's")
                continue
            line = good[first]["line"] if first < len(good) else None
            for flags in [(), ("--decisions-only",)]:
                rc, out, err = check(bad_text, *flags)
                rows = err.splitlines()
                want = rf"^step {first} diverges at line {line} \({re.escape(names[line - 1])}: " if line else rf"^step {first} diverges"
                if rc != 1 or not rows or not re.match(want, rows[0]):
                    fail(f"bug '{bug}' ({lang}, {args}) {' '.join(flags)}: expected exit 1 and /{want}/, got exit {rc}: {err.strip()[:400]}")
                    continue
                prev = good[first - 1]
                want_prev = rf"^  after step {first - 1} at line {prev['line']} \({re.escape(names[prev['line'] - 1])}: "
                if len(rows) != 2 or not re.match(want_prev, rows[1]):
                    fail(f"bug '{bug}' ({lang}, {args}) {' '.join(flags)}: the second line should name step {first - 1}: {err.strip()[:400]}")
                    continue
                for var in prev["vars"]:
                    if f" {var} = " not in rows[1]:
                        fail(f"bug '{bug}' ({lang}, {args}): the step before does not show {var}: {rows[1]}")
                if "(trace: " in rows[1]:  # the step before agrees within the tolerance: nothing beside it
                    fail(f"bug '{bug}' ({lang}, {args}): a value of the step before is shown as differing: {rows[1]}")
                # Under --decisions-only a number of the step before may be far off: shown beside the replay's.
                far = next((n for n, v in prev["vars"].items() if not isinstance(v, int)), None)
                if flags and far:
                    lines = bad_text.splitlines()
                    step_before = json.loads(lines[first])  # lines[0] is the header
                    step_before["vars"][far] = 1000
                    lines[first] = json.dumps(step_before)
                    rc, out, err = check("\n".join(lines) + "\n", *flags)
                    rows = err.splitlines()
                    if rc != 1 or len(rows) != 2 or not re.search(rf" {far} = [^,]*\(trace: 1000\)", rows[1]):
                        fail(f"bug '{bug}' ({lang}, {args}) --decisions-only with {far} = 1000 at step {first - 1}: {err.strip()[:400]}")
                if not flags:
                    caught.append(f"{bug} [{lang}, {alg} {args}]: step {first}: {rows[0][:160]}")
            rc, out, err = check(bad_text, "--results-only")
            if rc != 1 or not err.startswith("result diverges"):
                fail(f"bug '{bug}' ({lang}, {args}) --results-only: expected 'result diverges', got exit {rc}: {err.strip()[:300]}")
for c in caught:
    print("caught: " + c)

# 4. The contract against real traces of inputs it did not sample.
EXTRA = {
    "dda-line": [{"p0": [0.5, 0.5], "p1": [7.5, 3.5]}, {"p0": [-0.5, 0.5], "p1": [4.5, -2.5]}, {"p0": [0.2, 0.2], "p1": [0.7, 0.4]},
                 {"p0": [2.5, -3.25], "p1": [2.5, 4.75]}, {"p0": [0.5, 0.5], "p1": [0.5, 0.5]}],
    "dda-grid-walk": [{"p0": [0.5, 0.5], "p1": [8.5, 8.5]}, {"p0": [0.5, -0.5], "p1": [-6.5, 6.5]}, {"p0": [0.1, -0.1], "p1": [0.3, 0.2]},
                      {"p0": [0, 0], "p1": [0, 0]}],
    "bresenham-line": [{"p0": [0, 0], "p1": [-8, 8]}, {"p0": [3, -2], "p1": [3, 8]}, {"p0": [5, 5], "p1": [5, 5]}],
    "bezier-forward-diff": [{"bezier": [[12, 6], [9.5, "-5/3"], [3, "29/4"], [0.5, 0]], "n": 4}, {"bezier": [[0, 0], [0, 0], [0, 0], [0, 0]], "n": 2}],
    "circle-midpoint": [{"c": [0, 0], "r": 0}, {"c": [-7, 3], "r": 2}, {"c": [2, -1], "r": 5}],
    "whitted": [{"scene": "scenes/glass-spheres.json", "size": [80, 60], "pixel": [30, 17]},
                {"scene": "scenes/glass-spheres.json", "size": [80, 60], "pixel": [60, 45]}],
}
callees_seen = set()


def type_fits(t, v, mode):
    """A trace value against the contract's type: integers are JSON integers; an exact replay's
    numbers are "p/q" strings; a real (double) replay's are JSON numbers or non-finite strings."""
    if t.startswith("{\"rgb\": "):
        return isinstance(v, dict) and type_fits(t[len("{\"rgb\": "):-1], v.get("rgb"), mode)
    if t.startswith("["):
        inner = t[1:-1].split(", ")
        if not isinstance(v, list):
            return False
        if inner[-1] == "...":
            return all(type_fits(inner[0], x, mode) for x in v)
        return len(v) == len(inner) and all(type_fits(a, x, mode) for a, x in zip(inner, v))
    if t == "integer":
        return isinstance(v, int) and not isinstance(v, bool)
    if mode == "exact":
        return isinstance(v, str)
    return isinstance(v, (int, float, str))
for alg, inputs in EXTRA.items():
    rc, out, err = run([EXE, "list", "--contract", alg, "--json"])
    if rc != 0:
        fail(f"list --contract {alg} --json: exit {rc}: {err.strip()[:300]}")
        continue
    contract = json.loads(out)
    rc, text, err = run([EXE, "list", "--contract", alg])
    if rc != 0 or not text.startswith(alg + ": "):
        fail(f"list --contract {alg}: exit {rc}: {err.strip()[:300]}")
    forms = {}
    by_scope = {}
    for entry in contract["lines"]:
        scope = entry.get("in", "")
        by_scope.setdefault(scope, []).append(entry["name"])
        forms[(scope, entry["line"])] = entry["steps"]
        # The text form lists the same line with its name.
        if f" {entry['line']} {entry['name']}: " not in text:
            fail(f"list --contract {alg}: the text has no line '{entry['line']} {entry['name']}:'")
    for scope, names in by_scope.items():
        if names != listing(scope or alg):
            fail(f"list --contract {alg}: the lines of {scope or alg} are {names}, `list --listing` says {listing(scope or alg)}")
    mode = contract["replay"]
    for inp in EXTRA[alg]:
        rc, tr, err = run([EXE, "trace", alg, "--input", json.dumps(inp), "--numeric", mode])
        if rc != 0:
            fail(f"trace {alg} {json.dumps(inp)}: exit {rc}: {err.strip()[:300]}")
            continue
        for s in steps_of(tr):
            scope = s.get("in", "")
            if scope:
                callees_seen.add(scope)
            cands = forms.get((scope, s["line"]))
            if cands is None:
                fail(f"{alg}: a trace step on line {s['line']} of '{scope or alg}', which the contract does not list")
                continue
            geo = [next(k for k in g if k not in ("label", "life", "value")) for g in s["geo"]]

            def fits(f):
                kinds = [g.split(" ")[0] for g in f["geo"]]
                many = [g.endswith(" ...") for g in f["geo"]]
                pattern = "".join(f"(?:{k},)+" if m else f"{k}," for k, m in zip(kinds, many))
                types_ok = all(type_fits(f["vars"][n], v, mode) for n, v in s["vars"].items() if n in f["vars"])
                return (f["kind"] == s["kind"] and list(f["vars"]) == list(s["vars"]) and types_ok
                        and re.fullmatch(pattern, "".join(g + "," for g in geo)) is not None)
            if not any(fits(f) for f in cands):
                fail(f"{alg} {json.dumps(inp)}: step {s['step']} (line {s['line']} of '{scope or alg}', {s['kind']}, vars {list(s['vars'])}, "
                     f"geo {geo}) fits none of the contract's forms there: {cands}")
# 5. The contracts pasted into docs/assignment-dda.md are the command's output.
rc, out, err = run(["/usr/bin/python3", os.path.join(SRC, "scripts", "contract_docs.py"), EXE, "--check"])
if rc != 0:
    fail(f"scripts/contract_docs.py --check: {(out + err).strip()[:300]}")

for callee in ["dda-line", "refract"]:
    if callee not in callees_seen:
        fail(f"no trace stepped inside {callee}: the nested-callee part of the test tested nothing")

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("ok")
