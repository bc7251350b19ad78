#!/usr/bin/env python3
"""A student's DDA line and grid walk in Python, in exact rationals (fractions.Fraction), traced
with stepwise_trace.py to the contract of `stepwise list --contract dda-line` and
`--contract dda-grid-walk` (docs/assignment-dda.md).

    python3 student/examples/dda.py dda-line 1.25 2.5 12.75 7.25 > line.jsonl && stepwise check line.jsonl

Coordinates may be decimals or fractions ("5/4").
"""
import math
import os
import sys
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from stepwise_trace import Trace, pixel, point, segment  # noqa: E402

# The listing's line names, in order (stepwise list --listing dda-line, --listing dda-grid-walk).
DDA_LINE = ["delta", "major", "swap", "empty", "slope", "offset", "test", "plot", "advance", "done"]
GRID_WALK = ["delta", "start", "setup", "first_exit", "pick", "test", "up", "visit_up", "down", "visit_down", "done"]


def round_half(v):
    """round(v) = floor(v + 1/2): ties round up."""
    return math.floor(v + Fraction(1, 2))


def dda_line(t, p0, p1):
    out = []
    d = [p1[0] - p0[0], p1[1] - p0[1]]
    t.step("delta", "init", {"dx": d[0], "dy": d[1]}, [segment(*p0, *p1)])
    a = 0 if abs(d[0]) > abs(d[1]) else 1
    t.step("major", "decide", {"a": a})
    swapped = d[a] < 0
    if swapped:
        p0, p1 = p1, p0
        d = [-d[0], -d[1]]
    t.step("swap", "decide", {"swapped": swapped, "dx": d[0], "dy": d[1]})
    if d[a] == 0:
        t.step("empty", "done")
        return out
    dp = [Fraction(0), Fraction(0)]
    dp[a] = Fraction(1)
    dp[1 - a] = d[1 - a] / d[a]
    t.step("slope", "init", {"dpx": dp[0], "dpy": dp[1]})
    offset = math.ceil(p0[a]) - p0[a]
    q = [p0[0] + offset * dp[0], p0[1] + offset * dp[1]]
    t.step("offset", "init", {"dp0x": offset * dp[0], "dp0y": offset * dp[1], "qx": q[0], "qy": q[1]}, [point(*q)])
    # One column per pass, and one more pass that stops the walk.
    for _ in range(math.ceil(p1[a]) - math.ceil(p0[a]) + 1):
        if not q[a] < p1[a]:
            t.step("done", "done", {"qx": q[0], "qy": q[1]}, [point(*q)])
            return out
        i, j = round_half(q[0]), round_half(q[1])
        out.append((i, j))
        t.step("plot", "plot", {"qx": q[0], "qy": q[1], "i": i, "j": j}, [pixel(i, j), point(*q)])
        q = [q[0] + dp[0], q[1] + dp[1]]
        t.step("advance", "advance", {"qx": q[0], "qy": q[1]}, [point(*q)])
    t.step("done", "done", {"qx": q[0], "qy": q[1], "bound_hit": 1})
    return out


def sign(v):
    return (v > 0) - (v < 0)


def grid_walk(t, p0, p1):
    d = [p1[0] - p0[0], p1[1] - p0[1]]
    t.step("delta", "init", {"dx": d[0], "dy": d[1]}, [segment(*p0, *p1)])
    if d[0] == 0 and d[1] == 0:
        t.step("done", "done")
        return []
    cell = [round_half(p0[0]), round_half(p0[1])]
    last = [round_half(p1[0]), round_half(p1[1])]
    out = [tuple(cell)]
    t.step("start", "visit", {"i": cell[0], "j": cell[1]}, [pixel(*cell), point(*p0)])
    step = [sign(d[0]), sign(d[1])]
    t_max, t_delta = [Fraction(0), Fraction(0)], [Fraction(0), Fraction(0)]
    bound = 4
    for a in (0, 1):
        if step[a] == 0:
            continue
        t_delta[a] = step[a] / d[a]
        t_max[a] = (cell[a] + Fraction(step[a], 2) - p0[a]) / d[a]
        bound += math.floor(abs(d[a])) + 2
    t.step("setup", "init", {"step_x": step[0], "step_y": step[1], "tDelta_x": t_delta[0], "tDelta_y": t_delta[1]})
    t.step("first_exit", "init", {"tMax_x": t_max[0], "tMax_y": t_max[1]})
    for _ in range(bound):
        # Which axes leave the cell first: x, y, or both at a corner.
        x_first = step[1] == 0 or (step[0] != 0 and t_max[0] < t_max[1])
        y_first = not x_first and (step[0] == 0 or t_max[1] < t_max[0])
        hit = (not y_first, not x_first)
        tt = t_max[0] if hit[0] else t_max[1]
        t.step("pick", "decide", {"t": tt, "tMax_x": t_max[0], "tMax_y": t_max[1]},
               [point(p0[0] + tt * d[0], p0[1] + tt * d[1])])
        past = any(hit[a] and step[a] != 0 and (cell[a] + step[a] - last[a]) * step[a] > 0 for a in (0, 1))
        reached = not tt < 1
        if reached or past:
            t.step("test", "done", {"t": tt, "past_p1": not reached})
            return out
        # Upward moves first: an upward boundary belongs to the new cell, a downward one to the old.
        for direction in (1, -1):
            moved = False
            for a in (0, 1):
                if hit[a] and step[a] == direction:
                    cell[a] += direction
                    t_max[a] += t_delta[a]
                    moved = True
            if moved:
                out.append(tuple(cell))
                t.step("visit_up" if direction > 0 else "visit_down", "visit",
                       {"i": cell[0], "j": cell[1], "tMax_x": t_max[0], "tMax_y": t_max[1]}, [pixel(*cell)])
    t.step("done", "done", {"bound_hit": 1})
    return out


def main(argv):
    if len(argv) != 6 or argv[1] not in ("dda-line", "dda-grid-walk"):
        sys.stderr.write(f"usage: {argv[0]} dda-line|dda-grid-walk X0 Y0 X1 Y1\n")
        return 2
    x0, y0, x1, y1 = (Fraction(v) for v in argv[2:])
    line = argv[1] == "dda-line"
    with Trace(argv[1], "exact", {"p0": [x0, y0], "p1": [x1, y1]}, sys.stdout, listing=DDA_LINE if line else GRID_WALK) as t:
        pixels = (dda_line if line else grid_walk)(t, [x0, y0], [x1, y1])
        t.result({"pixels" if line else "cells": pixels})
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
