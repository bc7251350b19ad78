"""Write a stepwise trace (JSONL, docs/trace-format.md) from Python, standard library only, so
that `stepwise check FILE` can replay it against the reference algorithm step by step.

    from fractions import Fraction
    from stepwise_trace import Trace, pixel, point, segment

    with Trace("dda-line", "exact", {"p0": ["5/4", "5/2"], "p1": [12.75, 7.25]}, out) as t:
        t.step(1, "init", {"dx": dx, "dy": dy}, [segment(x0, y0, x1, y1)])
        ...
        t.result(pixels=[(i, j), ...])

What each step records (its line, kind, variables and geometry) is the algorithm's contract:
`stepwise list --contract ALG`. Values: int (and bool) are JSON integers; fractions.Fraction is an
exact "p/q" string; float is the shortest decimal that reads back as the same double (NaN and
infinities as the strings the format uses); tuples and lists are vectors. geometry=False leaves
out every step's "geo" (for `check --decisions-only`).
"""

import json
import math
import sys
from fractions import Fraction

__all__ = ["Trace", "item", "pixel", "point", "segment", "value"]


def value(v):
    """A Python value as the trace format writes it."""
    if isinstance(v, bool):
        return int(v)
    if isinstance(v, int):
        return v
    if isinstance(v, Fraction):
        return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
    if isinstance(v, float):
        if math.isnan(v):
            return "NaN"
        if math.isinf(v):
            return "Infinity" if v > 0 else "-Infinity"
        return v  # json writes repr(v): the shortest text that reads back as v
    if isinstance(v, (list, tuple)):
        return [value(x) for x in v]
    if isinstance(v, dict):
        return {str(k): value(x) for k, x in v.items()}
    if isinstance(v, str):
        return v
    raise TypeError(f"no trace value for {type(v).__name__}: {v!r}")


def item(kind, *values, label=None, life=None):
    """A geometry item: item("point", x, y, label="q") is {"point": [x, y], "label": "q"}."""
    it = {kind: [value(x) for x in values]}
    if label is not None:
        it["label"] = label
    if life is not None:
        it["life"] = life
    return it


def pixel(i, j, **mods):
    return item("pixel", int(i), int(j), **mods)


def point(x, y, **mods):
    return item("point", x, y, **mods)


def segment(x0, y0, x1, y1, **mods):
    return item("segment", x0, y0, x1, y1, **mods)


def _line(obj):
    return json.dumps(obj, separators=(",", ":"), ensure_ascii=False, allow_nan=False) + "\n"


class Trace:
    """One trace: the header when made, a line per step(), the result line from result().

    line may be the listing line's number, or its name when `listing` (the names in order, as
    `stepwise list --contract` prints them) is given."""

    def __init__(self, algorithm, numeric, input, out=None, listing=None, geometry=True):
        self.out = out if out is not None else sys.stdout
        self.listing = list(listing) if listing is not None else None
        self.geometry = geometry
        self.steps = 0
        self.done = False
        header = {"format": "stepwise-trace", "version": 2, "algorithm": algorithm,
                  "numeric": numeric, "input": value(input)}
        if self.listing is not None:
            header["listing"] = self.listing
        self.out.write(_line(header))

    def step(self, line, kind, vars=None, geo=None, callee=None):
        """One step: its listing line, kind, variables {name: value} and geometry items. callee:
        the id of the nested listing the step is in (its "in"), else None."""
        if self.done:
            raise RuntimeError("a step after the result")
        if isinstance(line, str):
            if self.listing is None or line not in self.listing:
                raise ValueError(f"no listing line named {line!r}")
            line = self.listing.index(line) + 1
        s = {"step": self.steps}
        if callee is not None:
            s["in"] = callee
        s.update({"line": int(line), "kind": kind, "vars": value(vars or {})})
        if self.geometry:
            s["geo"] = list(geo or [])
        self.out.write(_line(s))
        self.steps += 1

    def result(self, members=None, **more):
        """The last line: result(pixels=[(i, j), ...]) writes {"result": {"pixels": [[i, j], ...]}}."""
        if self.done:
            raise RuntimeError("a second result")
        r = dict(members or {})
        r.update(more)
        self.out.write(_line({"result": value(r)}))
        self.done = True

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.out.flush()
        return False
