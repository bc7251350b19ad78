#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz harnesses (fuzz/corpus/{run,check,lesson,scene,files}) and fuzz/stepwise.dict
from the catalog's examples, the hard cases in tests/cases, the lessons, the scenes and their files. Usage: make_corpus.py STEPWISE"""
import json, pathlib, shutil, struct, subprocess, sys, tempfile, zlib

ROOT = pathlib.Path(__file__).resolve().parent.parent
STEPWISE = sys.argv[1]
OUT = ROOT / "fuzz" / "corpus"
PER_ALGORITHM = 6          # hard cases per algorithm, beyond its example in every mode
MAX_SEED = 8 * 1024        # bytes: larger seeds make slow runs and long mutations


def sh(*args):
    return subprocess.run([STEPWISE, *args], capture_output=True, text=True)


def accepts(alg, mode, line):
    with tempfile.NamedTemporaryFile("w", suffix=".jsonl") as f:
        f.write(line + "\n")
        f.flush()
        return sh("run", alg, "--numeric", mode, "--inputs", f.name).returncode == 0


catalog = [json.loads(l) for l in sh("list", "--json").stdout.splitlines()]
shutil.rmtree(OUT, ignore_errors=True)
for d in ("run", "check", "lesson", "scene", "files"):
    (OUT / d).mkdir(parents=True)

cases = {}  # family -> [(algorithm or None, input line)]
for f in sorted((ROOT / "tests" / "cases").glob("*/*.jsonl")):
    for line in f.read_text().splitlines():
        if line.startswith("{"):
            c = json.loads(line)
            if "input" in c:
                cases.setdefault(f.parent.name, []).append((c.get("algorithm"), json.dumps(c["input"])))

keys = set()
def collect_keys(v):
    if isinstance(v, dict):
        for k, x in v.items():
            keys.add(k)
            collect_keys(x)
    elif isinstance(v, list):
        for x in v:
            collect_keys(x)

for a in catalog:
    alg, example = a["id"], json.dumps(a["example"])
    collect_keys(a["example"])
    for mode in a["modes"]:
        (OUT / "run" / f"{alg}-{mode}").write_text(f"{alg} {mode}\n{example}\n")
        trace = sh("trace", alg, "--numeric", mode, "--input", example).stdout
        if 0 < len(trace) <= MAX_SEED:
            (OUT / "check" / f"{alg}-{mode}").write_text(trace)
    mode = a["modes"][-1]
    taken = 0
    for named, line in cases.get(a["family"], []):
        if taken == PER_ALGORITHM:
            break
        if named in (None, alg) and len(line) <= MAX_SEED and accepts(alg, mode, line):
            taken += 1
            (OUT / "run" / f"{alg}-case{taken}").write_text(f"{alg} {mode}\n{line}\n")

for lesson in sorted((ROOT / "lessons").glob("*.md")):
    shutil.copy(lesson, OUT / "lesson" / lesson.name)
for lesson in sorted((ROOT / "tests" / "cases" / "lessons-broken").glob("*.md")):
    shutil.copy(lesson, OUT / "lesson" / ("broken-" + lesson.name))
for scene in sorted((ROOT / "scenes").glob("*.json")):
    shutil.copy(scene, OUT / "scene" / scene.name)
    collect_keys(json.loads(scene.read_text()))

# fuzz_files: a first byte choosing the reader (0 OFF, 1 OBJ, 2 PNG), then the file.
def png(w, h, rows, colour_type=2):
    def chunk(t, b): return struct.pack(">I", len(b)) + t + b + struct.pack(">I", zlib.crc32(t + b) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", w, h, 8, colour_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(b"".join(b"\0" + r for r in rows))) + chunk(b"IEND", b"")

files = {
    "tetra-off": b"\0OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n",
    "quad-off": b"\0OFF\n# a quad, split into a fan\n4 1 0\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n",
    "tetra-obj": b"\1# tetra\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3/1 4//2\nf -1 -2 -3\n",
    "one-texel-png": b"\2" + png(1, 1, [b"\xff\0\0"]),
    "grey-2x2-png": b"\2" + png(2, 2, [b"\x10\x20", b"\x30\x40"], colour_type=0),
}
for png_file in sorted((ROOT / "scenes").glob("**/*.png")):
    if png_file.stat().st_size <= MAX_SEED:
        files[png_file.stem + "-png"] = b"\2" + png_file.read_bytes()
for name, data in files.items():
    (OUT / "files" / name).write_bytes(data)

tokens = sorted(keys) + [a["id"] for a in catalog] + ["float", "double", "int", "filtered", "exact", "reference"]
words = ["{", "}", "[", "]", ",", ":", "\"", "1/3", "-0", "1e308", "5e-324", "NaN", "Infinity", "-Infinity", "\\u0000",
         "format", "stepwise-trace", "version", "algorithm", "numeric", "input", "result", "line", "kind", "vars",
         "geometry", "---", "## on line ", "## on kind ", "## on step ", " for float", " if ", " and ", " < ", " >= ", " == ", "{", "}", ":exact}",
         "## quiz pixel on ", "## quiz branch on ", "## quiz sign e on ", "## quiz hit on ", "**", "`", "1. ", "- ", "title: ", "input: ", "numeric: ", "compare: ", "step: "]
with open(ROOT / "fuzz" / "stepwise.dict", "w") as d:
    d.write("# Tokens of stepwise's inputs, traces and lessons (written by fuzz/make_corpus.py).\n")
    for t in dict.fromkeys(words + tokens):
        d.write(json.dumps(t) + "\n")
print({d: len(list((OUT / d).iterdir())) for d in ("run", "check", "lesson", "scene", "files")})
