#!/usr/bin/env python3
"""Measure the work budget of `stepwise trace|run` (README, "The `stepwise` command").

For each algorithm of `stepwise list --json` and each of its modes, grow an input with one integer size s (derived
from the algorithm's example), find the largest s the default budget accepts (galloping, then bisection, probing with
`trace --max-output 1`: a budget refusal names "implies up to N steps", an accepted input fails on "the output passes
the budget"), then time `run` and `trace` there under /usr/bin/time. The most exact mode is also measured with
~4000-character exact strings ("long") where the input takes them. Algorithms with no estimate (constant steps, or
bounded at parse) are timed on their example and on the largest input the parser takes ("max"). Stdlib only.

    python3 bench/budget_sweep.py [--stepwise PATH] [--only ALG]... [--modes all|best,double,...] [--out FILE.jsonl]
    python3 bench/budget_sweep.py --commands     # scene render, render --gif and lesson export at their budgets

It prints a Markdown table (docs/cli.md holds the last one) and takes about 20 minutes for the whole catalog.
"""
import argparse, json, math, os, random, re, shutil, signal, subprocess, sys, threading, time
from fractions import Fraction as F
from pathlib import Path

LIMIT_S, LIMIT_KB, TIMEOUT = 10.0, 1 << 20, 120
D = 10**2000 + 7  # a 2001-digit denominator: v + 1/D is a ~4000-character "p/q" of the same value scale
SW = WORK = None


def J(f):  # a Fraction as JSON: an int, the exact double, or "p/q"
    f = F(f)
    if f.denominator == 1 and abs(f) < 2**53: return int(f)
    if f.denominator & (f.denominator - 1) == 0 and abs(f.numerator) < 2**53: return float(f)
    return f"{f.numerator}/{f.denominator}"


def is_num(v): return isinstance(v, (int, float)) and not isinstance(v, bool) or isinstance(v, str) and bool(re.fullmatch(r"-?[0-9.]+(/[0-9]+)?", v))
def scale(o, s): return [scale(v, s) for v in o] if isinstance(o, list) else J(F(o) * s)
def longify(v): g = F(v) + F(1, D); return f"{g.numerator}/{g.denominator}"


def leaves(o, path=()):  # paths of the numeric leaves
    if isinstance(o, dict): return [p for k in sorted(o) for p in leaves(o[k], path + (k,))]
    if isinstance(o, list): return [p for i, v in enumerate(o) for p in leaves(v, path + (i,))]
    return [path] if is_num(o) else []


def with_long(o, paths):
    o = json.loads(json.dumps(o))
    for p in paths:
        box = o
        for k in p[:-1]: box = box[k]
        box[p[-1]] = longify(box[p[-1]])
    return o


# ---- size families: gen(example, s) -> input; s = 1 is about the example ----
def seg(ex, s):  # p1 = p0 + s (p1 - p0)
    return {"p0": ex["p0"], "p1": [J(F(a) + s * (F(b) - F(a))) for a, b in zip(ex["p0"], ex["p1"])]}


def implicit(ex, s):  # P(x/s, y/s) s^deg: the same curve s times larger; start and max_steps scale with it
    deg = max(i + j for _, i, j in ex["P"])
    return {"P": [[J(F(c) * s ** (deg - i - j)), i, j] for c, i, j in ex["P"]], "start": [v * s for v in ex["start"]],
            "max_steps": ex["max_steps"] * s}


def rpts(n, lo, hi, seed=1):  # seeded, prefix-stable, on the 1/1024 grid
    r = random.Random(seed)
    return [[r.randrange(int(a * 1024), int(b * 1024)) / 1024 for a, b in zip(lo, hi)] for _ in range(n)]


def rtris(n, lo, hi, size, seed=2):
    return [[[c + d for c, d in zip(cen, off)] for off in rpts(3, [-size] * 3, [size] * 3, seed * 7919 + i)]
            for i, cen in enumerate(rpts(n, lo, hi, seed))]


def poly(ex, s):
    k = 2 * s + 3  # two regular polygons, the clip one (convex, <= 32 vertices) slightly turned
    ngon = lambda m, r, a: [[round(r * math.cos(a + 2 * math.pi * i / m), 3), round(r * math.sin(a + 2 * math.pi * i / m), 3)] for i in range(m)]
    return {"polygon": ngon(k, 1000, 0), "clip": ngon(min(32, k), 900, 0.05)}


def bsp_grid(ex, s):  # s short disjoint segments on a grid
    segs = [[[4 * (i % 64), 3 * (i // 64)], [4 * (i % 64) + 2, 3 * (i // 64) + 1]] for i in range(s)]
    return {**{k: v for k, v in ex.items() if k != "segments"}, "segments": segs}


def bsp_cross(ex, s):  # s long random segments: fragments grow as s^2
    p = rpts(2 * s, [0, 0], [1000, 1000], 5)
    return {**{k: v for k, v in ex.items() if k != "segments"}, "segments": [[p[2 * i], p[2 * i + 1]] for i in range(s)]}


def shade_max(ex):  # 8 lights (the bound), cycling the example's
    return {**ex, "lights": [ex["lights"][i % len(ex["lights"])] for i in range(8)]}


tri = lambda ex, s: {**ex, "triangle": scale(ex["triangle"], s)}
GEN = {
    "dda-line": seg, "dda-grid-walk": seg, "bresenham-line": seg, "grid-traverse-3d": seg,
    "poly-forward-diff": lambda ex, s: {**ex, "xs": ex["xs"] * s, "xe": ex["xe"] * s},
    "circle-interior": lambda ex, s: {**ex, "r": s},
    "implicit-curve": implicit,
    "bezier-forward-diff": lambda ex, s: {"bezier": scale(ex["bezier"], s), "n": min(1024, ex["n"] * s)},
    "bezier-de-casteljau": lambda ex, s: {"bezier": scale(ex["bezier"], s), "depth": min(10, ex["depth"] + s.bit_length() - 1)},
    "triangle-dda": tri, "triangle-dda-no-offset": tri, "triangle-edge": tri,
    "scanline-polygon": lambda ex, s: {**ex, "polygon": scale(ex["polygon"], s)},
    "perspective-interp": lambda ex, s: {**ex, "triangle": [[J(F(x) * s), J(F(y) * s), z, w] for x, y, z, w in ex["triangle"]]},
    "raster-clip": lambda ex, s: {**tri(ex, s), "viewport": {"min": ex["viewport"]["min"], "max": scale(ex["viewport"]["max"], s)}},
    "cohen-sutherland": lambda ex, s: {"segment": scale(ex["segment"], s), "window": {k: scale(v, s) for k, v in ex["window"].items()}},
    "sutherland-hodgman": poly,
    "quadtree-build": lambda ex, s: {**ex, "points": ex["points"] + rpts(10 * (s - 1), [0, 0], [8, 8])},
    "octree-build": lambda ex, s: {**ex, "triangles": ex["triangles"] + rtris(5 * (s - 1), [0] * 3, [4] * 3, 0.25)},
    "kd-build": lambda ex, s: {**ex, "points": ex["points"] + rpts(14 * (s - 1), [0, 0], [9, 8])},
    "kd-traverse": lambda ex, s: {**ex, "triangles": ex["triangles"] + rtris(18 * (s - 1), [0, 0, -0.5], [3, 3, 0], 0.05)},
    "kd-nearest": lambda ex, s: {**ex, "points": ex["points"] + rpts(14 * (s - 1), [0, 0], [9, 8])},
    "bvh-build": lambda ex, s: {**ex, "triangles": ex["triangles"] + rtris(10 * (s - 1), [0] * 3, [7] * 3, 0.3)},
    "bvh-traverse": lambda ex, s: {**ex, "triangles": ex["triangles"] + rtris(8 * (s - 1), [0, 0, -2], [3, 3, 1], 0.1)},
    "gouraud-vs-phong": lambda ex, s: {**ex, "vertices": [{**v, "xy": scale(v["xy"], s)} for v in ex["vertices"]]},
}
GEN["poly-horner"], GEN["circle-midpoint"], GEN["affine-interp"] = GEN["poly-forward-diff"], GEN["circle-interior"], GEN["perspective-interp"]
def poly_int(ex, s):  # int mode takes integer coefficients only: the example's times the common denominator
    c = [F(v) for v in ex["coeffs"]]
    m = math.lcm(*(v.denominator for v in c))
    return {**GEN["poly-forward-diff"](ex, s), "coeffs": [J(v * m) for v in c]}


# name -> [(variant, gen, the modes it runs in or None for all)]
VARIANTS = {"bsp-build": [("disjoint", bsp_grid, None), ("crossing", bsp_cross, None)],
            "poly-forward-diff": [("size", GEN["poly-forward-diff"], {"float", "double", "filtered", "exact"}), ("int-coeffs", poly_int, {"int"})]}
VARIANTS["bsp-painter"], VARIANTS["poly-horner"] = VARIANTS["bsp-build"], VARIANTS["poly-forward-diff"]
MAXGEN = {"shade": shade_max}  # structural maximum of a constant-step input, before the long strings


# ---- running stepwise ----
def write_input(obj, name):
    path = WORK / f"{name}.json"
    path.write_text(json.dumps(obj, separators=(",", ":")) + "\n")
    return path


def probe(alg, mode, path, *extra):
    """('ok'|'budget'|'other', message, (steps, weight) or None) for a trace that writes at most 1 byte."""
    r = subprocess.run([SW, "trace", alg, "--numeric", mode, "--input", str(path), "--max-output", "1", "--out", "/dev/null", *extra],
                       capture_output=True, text=True)
    err = r.stderr.strip().removeprefix("stepwise: error: ")
    m = re.search(r"implies up to (\d+) steps(?: x (\d+))?", err)
    if "output passes the budget" in err: return "ok", err, None
    if m and "more than the budget of" in err: return "budget", err, (int(m[1]), int(m[2] or 1))
    return "other", err or f"exit {r.returncode}", None


def search(ok, hint=1, cap=2**31):
    """Largest s >= 1 with ok(s) true (0 if none), galloping from hint, and the refusal at s + 1."""
    st, msg = ok(1)
    if not st: return 0, msg
    lo = hint if hint > 1 and ok(hint)[0] else 1
    step, why = 1, None
    while lo + step <= cap:  # gallop: lo accepted, lo + step tried
        st, why = ok(lo + step)
        if not st: break
        lo, step = lo + step, step * 2
    else: return lo, f"no refusal up to s = {cap}"
    hi = lo + step
    while hi - lo > 1:
        mid = (lo + hi) // 2
        st, m = ok(mid)
        lo, hi, why = (mid, hi, why) if st else (lo, mid, m)
    return lo, why


def timed(cmd, count=False):
    """Run under /usr/bin/time: {status, s, kb[, bytes, lines]}; stdout counted when count, else discarded."""
    tf, ef = WORK / "time.txt", WORK / "stderr.txt"
    with open(ef, "w") as err:
        p = subprocess.Popen(["/usr/bin/time", "-f", "%e %M", "-o", str(tf), *cmd], stdout=subprocess.PIPE if count else subprocess.DEVNULL,
                             stderr=err, start_new_session=True)
        n = {"bytes": 0, "lines": 0}
        def drain():
            for chunk in iter(lambda: p.stdout.read(1 << 20), b""): n["bytes"] += len(chunk); n["lines"] += chunk.count(b"\n")
        t = threading.Thread(target=drain) if count else None
        if t: t.start()
        try: rc = p.wait(TIMEOUT)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL); p.wait()
            if t: t.join()
            return {"status": "timeout", "s": TIMEOUT, "kb": None}
        if t: t.join()
    wall, kb = tf.read_text().strip().splitlines()[-1].split()
    msg = ef.read_text().strip().removeprefix("stepwise: error: ")
    return {"status": "ok" if rc == 0 else msg[:160], "s": float(wall), "kb": int(kb), **(n if count else {})}


def measure(alg, mode, path):
    run = timed([SW, "run", alg, "--numeric", mode, "--inputs", str(path), "--out", "/dev/null"])
    tr = timed([SW, "trace", alg, "--numeric", mode, "--input", str(path)], count=True)
    steps = tr["lines"] - 2 if tr["status"] == "ok" else None
    return {"run": run, "trace": tr, "steps": steps}


def long_paths(alg, mode, obj):
    """The numeric leaves that take a ~4000-character exact string in this mode (all at once, else one by one)."""
    ps = leaves(obj)
    if not ps or probe(alg, mode, write_input(with_long(obj, ps), "longprobe"))[0] != "other": return ps
    return [p for p in ps if probe(alg, mode, write_input(with_long(obj, [p]), "longprobe"))[0] != "other"]


def sweep_alg(a, modes, rows):
    alg, ex = a["id"], a["example"]
    best = "exact" if "exact" in a["modes"] else "reference" if "reference" in a["modes"] else a["modes"][-1]
    gens = VARIANTS.get(alg) or ([("size", GEN[alg], None)] if alg in GEN else [])
    if gens:
        lp = long_paths(alg, best, gens[0][1](ex, 1))
        if lp: gens = gens + [("long", lambda e, s, g=gens[0][1]: with_long(g(e, s), lp), {best})]
    hints, fixed = {}, {}
    if not gens:  # constant steps or bounded at parse: the example, and the largest input the parser takes
        big = MAXGEN.get(alg, lambda e: e)(ex)
        fixed = {"example": ex, "max": with_long(big, long_paths(alg, best, big))}
    for var, gen, only in gens or [(v, None, None) for v in fixed]:
        for mode in (m for m in a["modes"] if (m in modes or "best" in modes and m == best) and (only is None or m in only)):
            row = {"alg": alg, "mode": mode, "variant": var, "s": None, "limit": None}
            if gen:
                def ok(s):
                    st, msg, _ = probe(alg, mode, write_input(gen(ex, s), "probe"))
                    return st == "ok", ("budget" if st == "budget" else msg)
                s, why = search(ok, hints.get(var, 1))
                hints[var] = s
                row.update(s=s, limit=why)
                if s == 0: rows.append(row); print(f"{alg} {mode} {var}: refused at s=1: {why}", file=sys.stderr); continue
                obj = gen(ex, s)
            else: obj = fixed[var]
            path = write_input(obj, f"{alg}.{var}.{mode}")
            est = probe(alg, mode, path, "--max-steps", "0")[2]
            row.update(est=est and est[0], weight=est and est[1], input=str(path), chars=path.stat().st_size, **measure(alg, mode, path))
            if gen and mode == best and var != "long" and row["s"] >= 2:  # the estimate against a medium trace
                mid = max(1, row["s"] // 8)
                mp = write_input(gen(ex, mid), f"{alg}.{var}.mid")
                me, mt = probe(alg, mode, mp, "--max-steps", "0")[2], timed([SW, "trace", alg, "--numeric", mode, "--input", str(mp)], count=True)
                row["mid"] = {"s": mid, "est": me and me[0], "steps": mt["lines"] - 2 if mt["status"] == "ok" else None}
            row["flag"] = flags(row)
            rows.append(row)
            print(f"{alg} {mode} {var} s={row['s']} est={row['est']} run={row['run']['s']}s trace={row['trace']['s']}s {row['flag']}", file=sys.stderr)


def flags(r):
    out = []
    for k in ("run", "trace"):
        m = r[k]
        if m["status"] == "timeout": out.append(f"{k} TIMEOUT")
        elif m["s"] > LIMIT_S: out.append(f"{k} > 10 s")
        if m["kb"] and m["kb"] > LIMIT_KB: out.append(f"{k} > 1 GB")
        if m["status"] not in ("ok", "timeout"): out.append(f"{k} exit 2: {m['status'][:70]}")
    return "; ".join(out)


def table(rows):
    mb = lambda kb: "-" if kb is None else f"{kb / 1024:.0f}"
    print("| algorithm | mode | input | s | stopped by | estimate | run s | run MB | trace s | trace MB | trace bytes | steps traced | flag |")
    print("|---|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|")
    for r in rows:
        if "run" not in r:
            print(f"| {r['alg']} | {r['mode']} | {r['variant']} | 0 | {r['limit'][:60]} | | | | | | | | refused at s=1 |"); continue
        lim = "-" if r["limit"] is None else "budget" if r["limit"] == "budget" else r["limit"][:60].replace("|", "/")
        est = "-" if r["est"] is None else f"{r['est']:,}" + (f" x{r['weight']}" if r["weight"] > 1 else "")
        t = r["trace"]
        print(f"| {r['alg']} | {r['mode']} | {r['variant']} | {r['s'] or '-'} | {lim} | {est} | {r['run']['s']:.2f} | {mb(r['run']['kb'])} | "
              f"{t['s']:.2f} | {mb(t['kb'])} | {t.get('bytes', 0):,} | {'-' if r['steps'] is None else format(r['steps'], ',')} | {r['flag']} |")
    mids = [r for r in rows if r.get("mid") and r["mid"]["est"] and r["mid"]["steps"]]
    print("\nEstimate against the steps of a medium trace (s_max / 8, most exact mode):\n")
    print("| algorithm | input | s | estimate | steps traced | estimate / steps |\n|---|---|---:|---:|---:|---:|")
    for r in mids:
        m = r["mid"]
        print(f"| {r['alg']} | {r['variant']} | {m['s']} | {m['est']:,} | {m['steps']:,} | {m['est'] / m['steps']:.1f} |")


def summary(rows):
    """Per algorithm and input family, the slowest run and trace over the modes (docs/cli.md's table)."""
    print("\n| algorithm | input | estimated steps | limited by | run: s, MB (mode) | trace: s, MB (mode) |\n|---|---|---:|---|---|---|")
    groups, fixed = {}, []
    for r in rows:
        if "run" in r: (groups.setdefault((r["alg"], r["variant"]), []) if r["s"] else fixed).append(r)
    if fixed:  # constant steps or bounded at parse: one row, the slowest of them
        groups[(", ".join(dict.fromkeys(r["alg"] for r in fixed)), "example and max")] = fixed
    for (alg, var), rs in groups.items():
        def worst(k):
            r = max(rs, key=lambda r: r[k]["s"])
            kb = max(x[k]["kb"] or 0 for x in rs)
            st = r[k]["status"]
            end = "" if st in ("ok", "timeout") else ", output budget reached" if "output passes" in st else ", refused: " + st[:40]
            return f"{r[k]['s']:.1f}, {kb / 1024:.0f} ({r['mode']}" + (f", {r['alg']}" if var == "example and max" else "") + end + ")"
        lims = dict.fromkeys("-" if r["limit"] is None else "step budget" if r["limit"] == "budget" else r["limit"].split(":")[0] for r in rs)
        lim = " or ".join(lims)
        est = max((r for r in rs if r.get("est")), key=lambda r: r["est"] * r["weight"], default=None)
        est = "-" if est is None else f"{est['est']:,}" + (f" x {est['weight']}" if est["weight"] > 1 else "")
        print(f"| {alg} | {var} | {est} | {lim} | {worst('run')} | {worst('trace')} |")


# ---- commands with budgets of their own: scene render (rays), render --gif and lesson export (frames x pixels) ----
def render_estimate(scene, side, extra):
    r = subprocess.run([SW, "scene", "render", scene, "--out", str(WORK / "probe.png"), "--size", f"{side}x{side}", "--max-rays", "0", *extra],
                       capture_output=True, text=True)
    m = re.search(r"implies up to (\d+) rays", r.stderr)
    return int(m[1]) if m else None


def sweep_commands(root):
    """Each example scene at the largest square size the default ray budget (2^26) accepts, as planned and with
    --all-effects; GIFs and pages at the largest frame count the default pixel budgets accept, at the largest and
    the smallest frame size. Returns table rows."""
    rows = []
    for scene in sorted((root / "scenes").glob("*.json")):
        for extra in ([], ["--all-effects"]):
            side, _ = search(lambda s: ((e := render_estimate(str(scene), s, extra)) is not None and e <= 2**26, "budget"), 64, 8192)
            m = timed([SW, "scene", "render", str(scene), "--out", str(WORK / "render.png"), "--size", f"{side}x{side}", "--quiet", *extra])
            rows.append(("scene render", f"{scene.stem} {side}x{side}" + (" --all-effects" if extra else ""),
                         f"{render_estimate(str(scene), side, extra):,} rays", m))
            print(f"scene render {scene.stem} {side} {extra}: {m}", file=sys.stderr)
    lesson = root / "lessons" / "04-float-drift.md"  # thousands of steps: the frame budget, not the lesson, binds
    for cmd, budget, cap in (("render --gif", 2**27, 2000), ("lesson export", 2**26, 600)):
        for w, h in ((1280, 800), (320, 240)):
            n = min(cap, budget // (w * h))
            out = WORK / ("frames.gif" if cmd == "render --gif" else "page")
            shutil.rmtree(out, ignore_errors=True)
            args = ["render", "--lesson", str(lesson), "--gif", str(out)] if cmd == "render --gif" else ["lesson", "export", str(lesson), "--html", str(out)]
            m = timed([SW, *args, "--size", f"{w}x{h}", "--from", "0", "--to", str(n - 1)])
            rows.append((cmd, f"{lesson.stem}, {n} frames of {w}x{h}", f"{n * w * h:,} pixels", m))
            print(f"{cmd} {w}x{h} {n}: {m}", file=sys.stderr)
    print("\n| command | largest input the defaults accept | estimate | s, MB |\n|---|---|---:|---|")
    for cmd, what, est, m in rows:
        print(f"| {cmd} | {what} | {est} | {m['s']:.1f}, {(m['kb'] or 0) / 1024:.0f}" + ("" if m["status"] == "ok" else f" ({m['status'][:60]})") + " |")
    return rows


def main():
    global SW, WORK
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--stepwise", default=str(Path(__file__).resolve().parent.parent / "build" / "stepwise"))
    ap.add_argument("--only", action="append", help="an algorithm id (repeatable)")
    ap.add_argument("--modes", default="all", help="all, or a comma list of modes; 'best' is the most exact mode")
    ap.add_argument("--out", default="/tmp/budget/sweep.jsonl")
    ap.add_argument("--work", default="/tmp/budget/inputs", help="where the inputs are written (kept, to reproduce a row)")
    ap.add_argument("--commands", action="store_true", help="only scene render, render --gif and lesson export (their own budgets)")
    args = ap.parse_args()
    SW, WORK = args.stepwise, Path(args.work)
    WORK.mkdir(parents=True, exist_ok=True)
    if args.commands:
        sweep_commands(Path(__file__).resolve().parent.parent)
        return
    catalog = [json.loads(l) for l in subprocess.run([SW, "list", "--json"], capture_output=True, text=True, check=True).stdout.splitlines() if l.strip()]
    if args.only: catalog = [a for a in catalog if a["id"] in args.only]
    modes = {m for a in catalog for m in a["modes"]} | {"best"} if args.modes == "all" else set(args.modes.split(","))
    rows, t0 = [], time.time()
    for a in catalog: sweep_alg(a, modes, rows)
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text("".join(json.dumps(r) + "\n" for r in rows))
    table(rows)
    summary(rows)
    print(f"\n{len(rows)} rows in {time.time() - t0:.0f} s; rows in {args.out}; inputs in {WORK}", file=sys.stderr)


if __name__ == "__main__":
    main()
