#!/usr/bin/env python3
"""Drives an exported lesson page in headless Chromium through chromedriver's WebDriver HTTP API.

Usage: lesson_export_browser.py STEPWISE LESSON WORKDIR [WxH]

Exports LESSON with `stepwise lesson export --frames` (the flip-book), opens DIR/index.html from file://, and checks: no
console message of level SEVERE; ArrowRight pressed N times shows step start + N, and its frame is
byte-identical to `stepwise render --lesson LESSON --step N --size WxH`; ArrowLeft goes back; the
narration shown is the page data's for that step, and a step on a narrated line shows that
section's text. Exits 1 (never skips) when chromium or chromedriver is missing.
Standard library only (urllib, json).
"""
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from webdriver import LEFT, RIGHT, chromium_session, fail  # noqa: E402


def shown(d):
    return d.js("""
      const img = document.getElementById('frame');
      return {step: Number(document.getElementById('step').textContent), src: img.getAttribute('src'),
              loaded: img.complete && img.naturalWidth, kind: document.getElementById('kind').textContent,
              line: Number((document.querySelector('#listing li.current') || {dataset: {line: 0}}).dataset.line),
              narration: document.getElementById('narration').innerHTML};""")


def wait_loaded(d):
    for _ in range(200):  # bounded: 200 x 50 ms
        st = shown(d)
        if st["loaded"]:
            return st
        time.sleep(0.05)
    fail("the frame %s never loaded" % st["src"])


def main():
    if len(sys.argv) < 4:
        fail("usage: lesson_export_browser.py STEPWISE LESSON WORKDIR [WxH]")
    stepwise, lesson, work = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    size = sys.argv[4] if len(sys.argv) > 4 else "1024x640"  # the smallest layout the app supports
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    page_dir = os.path.join(work, "page")
    r = subprocess.run([stepwise, "lesson", "export", lesson, "--frames", page_dir, "--size", size],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail("export exited %d: %s" % (r.returncode, r.stderr))

    with chromium_session(work) as d:
        check_page(d, stepwise, lesson, work, page_dir, size)
    print("ok: the exported page steps, shows the rendered frames and the narration")


def check_page(d, stepwise, lesson, work, page_dir, size):
    d.s("POST", "/url", {"url": "file://" + os.path.join(page_dir, "index.html")})
    data = d.js("return JSON.parse(document.getElementById('page-data').textContent);")
    steps = data["steps"]
    start = wait_loaded(d)
    first = steps[0]["step"]
    at = steps[data["start"]]["step"]
    if start["step"] != at or start["src"] != steps[data["start"]]["frame"]:
        fail("the page opened on %s, not on the lesson's start step %d" % (start, at))
    n = min(5, steps[-1]["step"] - at)
    if n < 2:
        fail("the lesson is too short to step through (start %d, last %d)" % (at, steps[-1]["step"]))
    for _ in range(n):
        d.key(RIGHT)
    st = wait_loaded(d)
    want = at + n
    entry = steps[want - first]
    if st["step"] != want or st["src"] != entry["frame"] or st["src"] != "frames/%04d.png" % want:
        fail("after %d x ArrowRight from step %d: showing %s, expected step %d" % (n, at, st, want))
    if st["kind"] != entry["kind"] or st["line"] != entry["line"]:
        fail("step %d shows kind %s line %d; the page data says %s line %d" % (want, st["kind"], st["line"], entry["kind"], entry["line"]))
    same = d.js("const t = document.createElement('div'); t.innerHTML = arguments[0];"
                "return t.innerHTML === document.getElementById('narration').innerHTML;", data["narrations"][entry["narration"]])
    if not same:
        fail("step %d shows narration %r, the page data has %r" % (want, st["narration"], data["narrations"][entry["narration"]]))

    png = os.path.join(work, "render.png")
    r = subprocess.run([stepwise, "render", "--lesson", lesson, "--step", str(want), "--size", size, "--out", png],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail("render exited %d: %s" % (r.returncode, r.stderr))
    with open(png, "rb") as a, open(os.path.join(page_dir, st["src"]), "rb") as b:
        if a.read() != b.read():
            fail("the page's frame for step %d differs from `stepwise render --step %d`" % (want, want))

    d.key(LEFT)
    back = wait_loaded(d)
    if back["step"] != want - 1 or back["src"] != steps[want - 1 - first]["frame"]:
        fail("ArrowLeft from step %d shows %s" % (want, back))

    # A narrated line: the lesson's section text must show there (narrate's Markdown as HTML).
    names = [l["name"] for l in data["listings"][0]["lines"]]
    with open(lesson, encoding="utf-8") as f:
        text = f.read()
    narrated = [s for s in steps if s["listing"] == 0 and "## on line %s\n" % names[s["line"] - 1] in text]
    if not narrated:
        fail("no step of %s is on a line the lesson narrates" % lesson)
    s = narrated[-1]
    section = text.split("## on line %s\n" % names[s["line"] - 1], 1)[1].split("\n## ", 1)[0]
    # The words before the first {template}: the rest is filled with the step's values.
    first_words = " ".join(section.split("{", 1)[0].split()[:3]).replace("`", "").replace("**", "")
    d.js("document.getElementById('slider').value = arguments[0];"
         "document.getElementById('slider').dispatchEvent(new Event('input'));", s["step"] - first)
    shown_text = d.js("return document.getElementById('narration').textContent;")
    if first_words not in " ".join(shown_text.split()):
        fail("step %d (line %s) shows %r, not its section starting %r" % (s["step"], names[s["line"] - 1], shown_text, first_words))
    if shown(d)["step"] != s["step"]:
        fail("the slider did not move to step %d" % s["step"])

    d.js("document.getElementById('last').click();")
    if wait_loaded(d)["step"] != steps[-1]["step"]:
        fail("the last-step button did not show step %d" % steps[-1]["step"])
    severe = [e for e in d.logs() if e.get("level") == "SEVERE"]
    if severe:
        fail("console errors: %s" % severe)


if __name__ == "__main__":
    main()
