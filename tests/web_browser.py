#!/usr/bin/env python3
"""The browser page (out/web/stepwise.html, scripts/web.sh) in headless Chromium, from file://.

Usage: web_browser.py PAGE STEPWISE SOURCE_DIR WORKDIR [required|optional]

Checks what a student does, through the page's own input (keys, the mouse) and its URL fragment,
reading what the app shows from its test hook sw_state() (visualizer/web/web_main.cpp):
- the page opens on the first lesson, with no console message of level SEVERE; the first frame's
  time is printed;
- ArrowRight five times goes five steps on, ArrowLeft one back;
- dragging the first declared handle on the canvas moves that input point and re-records the run;
- #lesson=NN&numeric=exact opens a lesson in exact arithmetic;
- for three lessons, the variables shown at step N are `stepwise trace`'s at step N (same input,
  same number type), exactly: the same rationals, the same doubles;
- in quiz mode (#lesson=03&quiz), answering with the answer buttons is graded; the name typed in the
  quiz panel goes with the answers; "Download answers" downloads the JSONL file, and `stepwise quiz`
  grades it as that student's;
- a page written by `stepwise lesson export LESSON --html DIR --from 3` opens on that lesson at step 3;
- every lesson of the manifest opens (#lesson=NN) with steps and no error, and every quiz takes an
  answer in the page (#lesson=NN&quiz), downloads it, and `stepwise quiz` grades the download.
Exits 1 (never skips) when chromium or chromedriver is missing; a missing page fails too, unless
the last argument is "optional" (a build configured with -DSW_REQUIRE_PEERS=OFF): then it exits 77,
which ctest reports as skipped.
"""
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from webdriver import LEFT, RIGHT, chromium_session, fail  # noqa: E402

CTRL, END = "\ue009", "\ue010"
STATE = "return (window.Module && Module.swFrames > 0) ? JSON.parse(Module.ccall('sw_state', 'string')) : null;"


def wait_state(d, what, ok=lambda st: True, tries=400):
    """Polls sw_state() until the app has drawn a frame and ok(state); bounded: tries x 50 ms."""
    st = None
    for _ in range(tries):
        st = d.js(STATE)
        if st is not None and ok(st):
            return st
        time.sleep(0.05)
    fail("%s: the page never showed it (last state: %s)" % (what, json.dumps(st)[:600] if st else None))


def open_page(d, page, fragment=""):
    # Through a blank page, so that a change of the fragment alone is a fresh load too (the page
    # itself reloads on one, shell.html, but after the navigation has returned).
    d.s("POST", "/url", {"url": "about:blank"})
    d.s("POST", "/url", {"url": "file://" + page + ("#" + fragment if fragment else "")})
    return wait_state(d, "the page at #" + fragment)


def follow_link(d, fragment, lesson):
    """A link within the running page (a new fragment): it opens without a reload, so a mark left on
    the page's window survives it. Returns the state once the page shows `lesson`."""
    d.js("window.swSamePage = true; location.hash = arguments[0];", fragment)
    st = wait_state(d, "#" + fragment, lambda s: s["lesson"] == lesson)
    if d.js("return window.swSamePage === true;") is not True:
        fail("#%s reloaded the page (a link within it should open in place)" % fragment)
    return st


def components(value):
    """A trace variable's value as its list of components (scalars, vectors, colours, lists)."""
    if isinstance(value, dict):
        value = value["rgb"]
    return value if isinstance(value, list) else [value]


def text_components(text):
    """The state panel's lossless text of a value: "x", "(x, y)", "rgb(r, g, b)", "[a, b]"."""
    for head in ("rgb(", "(", "["):
        if text.startswith(head):
            inner = text[len(head):-1]
            return [p for p in inner.split(", ")] if inner else []
    return [text]


def same_component(shown, traced):
    if isinstance(traced, str):  # an exact "p/q", or a non-finite value's name
        return shown == traced
    if isinstance(traced, bool):
        traced = int(traced)
    try:
        return float(shown) == float(traced) and (not isinstance(traced, int) or shown == str(traced))
    except ValueError:
        return False


def check_against_trace(d, page, stepwise, lesson_number, step, work):
    st = open_page(d, page, "lesson=%s&step=%d" % (lesson_number, step))
    if st["error"] or st["step"] != step:
        fail("#lesson=%s&step=%d shows step %d, error %r" % (lesson_number, step, st["step"], st["error"]))
    trace_file = os.path.join(work, "trace-%s.jsonl" % lesson_number)
    r = subprocess.run([stepwise, "trace", st["algorithm"], "--input", json.dumps(st["input"]), "--numeric", st["numeric"],
                        "--out", trace_file], capture_output=True, text=True)
    if r.returncode != 0:
        fail("stepwise trace %s exited %d: %s" % (st["algorithm"], r.returncode, r.stderr))
    latest = {}
    with open(trace_file) as f:
        lines = [json.loads(line) for line in f]
    steps = [l for l in lines if "vars" in l]
    if len(steps) != st["steps"]:
        fail("lesson %s: the page recorded %d steps, stepwise trace %d" % (lesson_number, st["steps"], len(steps)))
    for s in steps[:step + 1]:
        latest.update(s["vars"])
    if set(latest) != set(st["vars"]):
        fail("lesson %s step %d: the page shows variables %s, the trace has %s" % (lesson_number, step, sorted(st["vars"]), sorted(latest)))
    for name, value in latest.items():
        shown, traced = text_components(st["vars"][name]), components(value)
        if len(shown) != len(traced) or not all(same_component(a, b) for a, b in zip(shown, traced)):
            fail("lesson %s step %d: %s is %s in the page, %s in the trace" % (lesson_number, step, name, st["vars"][name], json.dumps(value)))
    return len(latest)


def press(d, st, label):
    """Clicks the quiz panel's widget of that label (a button, the name field)."""
    for w in st["widgets"]:
        if w["label"] == label:
            x0, y0, x1, y1 = w["rect"]
            d.pointer([("move", (x0 + x1) / 2, (y0 + y1) / 2), ("down",), ("pause", 60), ("up",)])
            return
    fail("no %r on the page (the quiz panel has: %s)" % (label, [w["label"] for w in st["widgets"]]))


def type_keys(d, text, ctrl_a=False):
    actions = []
    if ctrl_a:  # select the field's text, to be replaced
        actions += [{"type": "keyDown", "value": CTRL}, {"type": "keyDown", "value": "a"}, {"type": "pause", "duration": 60},
                    {"type": "keyUp", "value": "a"}, {"type": "keyUp", "value": CTRL}]
    for ch in text:  # each held a few frames, as Driver.key does
        actions += [{"type": "keyDown", "value": ch}, {"type": "pause", "duration": 60}, {"type": "keyUp", "value": ch}]
    d.s("POST", "/actions", {"actions": [{"type": "key", "id": "kb", "actions": actions}]})


def grade(stepwise, lesson, saved):
    """Waits for the download `saved`, then grades it: `stepwise quiz`'s line for its student."""
    for _ in range(200):  # bounded: 10 s
        if os.path.isfile(saved):
            break
        time.sleep(0.05)
    else:
        fail("no download %s (the folder has %s)" % (saved, os.listdir(os.path.dirname(saved))))
    time.sleep(0.2)  # the browser renames the file into place when it is complete
    r = subprocess.run([stepwise, "quiz", lesson, "--answers", saved, "--json"], capture_output=True, text=True)
    if r.returncode != 0:
        fail("stepwise quiz on the downloaded %s exited %d: %s" % (saved, r.returncode, r.stderr))
    return json.loads(r.stdout.splitlines()[0])


def answer_one(d, number):
    """Steps on to the quiz's first question and answers it: its first button, or a cell of the canvas."""
    d.key(END)  # in a quiz, a jump stops at the first question still waiting
    for _ in range(200):  # bounded: 200 steps, or presses
        time.sleep(0.1)  # a frame or two to lay the panel out at this step
        st = d.js(STATE)
        if st["answered"] == 1:
            return
        if st["question"]:
            labels = [w["label"] for w in st["widgets"] if w["label"] not in ("Download answers", "Your name")]
            if labels:
                press(d, st, labels[0])
            elif st["question"] == "pixel":
                x0, y0, x1, y1 = st["canvas"]
                d.pointer([("move", (x0 + x1) / 2 + 7, (y0 + y1) / 2 + 5), ("down",), ("pause", 60), ("up",)])
            continue  # the buttons show on the next frame; a press that missed is tried again
        d.key(RIGHT)
    fail("lesson %s: no quiz question within 200 steps (state: %s)" % (number, json.dumps(d.js(STATE))[:300]))


def main():
    if len(sys.argv) not in (5, 6) or sys.argv[5:] not in ([], ["required"], ["optional"]):
        fail("usage: web_browser.py PAGE STEPWISE SOURCE_DIR WORKDIR [required|optional]")
    page, stepwise, source, work = (os.path.abspath(a) for a in sys.argv[1:5])
    if not os.path.isfile(page):
        if sys.argv[5:] == ["optional"]:
            print("skipped: %s is missing (scripts/web.sh builds it), as this build allows" % page)
            sys.exit(77)
        fail("%s is missing: scripts/web.sh builds it" % page)
    shutil.rmtree(work, ignore_errors=True)
    downloads = os.path.join(work, "downloads")
    os.makedirs(downloads)
    with open(os.path.join(source, "lessons", "manifest.txt")) as f:
        manifest = [l.split()[0] for l in f if l.strip() and not l.startswith("#")]
    with chromium_session(work, window="1280,800", downloads=downloads) as d:
        # Opens, and the first frame's time (from the navigation's start, as the browser counts).
        st = open_page(d, page)
        first_ms = d.js("return performance.now();")
        print("first frame within %.0f ms of the page's start (%.1f MB page)" % (first_ms, os.path.getsize(page) / 1e6))
        if st["lesson"] != os.path.basename(manifest[0]) or st["steps"] < 10 or st["error"]:
            fail("the page opened on %s (%d steps, error %r), not the first lesson %s" % (st["lesson"], st["steps"], st["error"], manifest[0]))
        severe = [e for e in d.logs() if e.get("level") == "SEVERE"]
        if severe:
            fail("console errors on opening: %s" % severe)

        # Keys.
        start = st["step"]
        for _ in range(5):
            d.key(RIGHT)
            time.sleep(0.05)
        wait_state(d, "five steps on from %d" % start, lambda s: s["step"] == start + 5)
        d.key(LEFT)
        wait_state(d, "one step back", lambda s: s["step"] == start + 4)

        # A drag of the first handle: the input point moves, and the run is recorded anew.
        st = d.js(STATE)
        if not st["handles"]:
            fail("the first lesson's canvas shows no handle to drag")
        hx, hy = st["handles"][0]
        before = json.dumps(st["input"], sort_keys=True)
        d.pointer([("move", hx, hy), ("down",), ("pause", 80), ("move", hx + 60, hy - 40), ("pause", 80), ("move", hx + 120, hy - 80),
                   ("pause", 80), ("up",)])
        moved = wait_state(d, "the input after the drag", lambda s: json.dumps(s["input"], sort_keys=True) != before)
        if moved["error"] or moved["steps"] == 0:
            fail("after the drag: error %r, %d steps" % (moved["error"], moved["steps"]))
        print("dragged the first handle: %s -> %s" % (before, json.dumps(moved["input"], sort_keys=True)))

        # Exact arithmetic, and the state against the trace.
        st = open_page(d, page, "lesson=%s&numeric=exact" % manifest[0].split("-")[0])
        if st["numeric"] != "exact" or st["lesson"] != os.path.basename(manifest[0]) or st["error"]:
            fail("#lesson=..&numeric=exact shows %s in lesson %r, error %r (the lesson should stay open)" % (st["numeric"], st["lesson"], st["error"]))
        for number, step in (("01", 12), ("03", 9), ("05", 4)):
            n = check_against_trace(d, page, stepwise, number, step, work)
            print("lesson %s at step %d: %d variables as stepwise trace writes them" % (number, step, n))

        # The quiz: answer, name, download, grade.
        st = open_page(d, page, "lesson=03&quiz&student=alice")
        if not st["quiz"]:
            fail("#lesson=03&quiz did not start the quiz")
        answered = 0
        for _ in range(40):  # bounded: step on until two questions are answered (by buttons)
            st = d.js(STATE)
            labels = [w["label"] for w in st["widgets"] if w["label"] not in ("Download answers", "Your name")]
            if labels:
                press(d, st, labels[0])
                answered = wait_state(d, "the answer graded", lambda s: s["answered"] > answered)["answered"]
                if answered >= 2:
                    break
            d.key(RIGHT)
            time.sleep(0.05)
        if answered < 2:
            fail("could not answer two quiz questions with the buttons (state: %s)" % json.dumps(st)[:400])
        st = wait_state(d, "the download button", lambda s: any(w["label"] == "Download answers" for w in s["widgets"]))
        if st["student"] != "alice":
            fail("#student=alice: the answers go under %r" % st["student"])
        press(d, st, "Your name")  # the name the answers carry, typed over the address's "alice"
        time.sleep(0.3)  # the field takes the keys from the frame after the click
        type_keys(d, "Ada L", ctrl_a=True)
        d.key("\ue007")  # Enter
        st = wait_state(d, "the name typed", lambda s: s["student"] == "Ada L")
        press(d, st, "Download answers")
        graded = grade(stepwise, os.path.join(source, "lessons", "03-bresenham.md"), os.path.join(downloads, "03-bresenham.jsonl"))
        print("stepwise quiz graded the downloaded answers: %s" % json.dumps(graded)[:300])
        if graded.get("student") != "Ada L" or graded.get("answered") != answered:
            fail("the graded file says %s, not %d answers by 'Ada L'" % (json.dumps(graded)[:300], answered))
        # A link to another lesson's quiz opens in the page, and the typed name stays.
        st = follow_link(d, "lesson=04&quiz", "04-float-drift.md")
        if not st["quiz"] or st["student"] != "Ada L" or st["error"]:
            fail("after a link to #lesson=04&quiz: quiz %s, student %r, error %r" % (st["quiz"], st["student"], st["error"]))
        print("a link to #lesson=04&quiz opened in the page, the name %r kept" % st["student"])

        # A lesson handed out as one file: `stepwise lesson export --html` opens on it, at --from.
        exported = os.path.join(work, "exported")
        r = subprocess.run([stepwise, "lesson", "export", os.path.join(source, "lessons", "02-grid-walk.md"), "--html", exported,
                            "--from", "3"], capture_output=True, text=True)
        if r.returncode != 0:
            fail("lesson export --html exited %d: %s" % (r.returncode, r.stderr))
        d.s("POST", "/url", {"url": "file://" + os.path.join(exported, "index.html")})
        st = wait_state(d, "the exported page")
        if st["lesson"] != "02-grid-walk.md" or st["step"] != 3 or st["error"]:
            fail("the exported page shows %s at step %d, error %r" % (st["lesson"], st["step"], st["error"]))

        # Every lesson opens; each quiz takes an answer (a button, or a click on the canvas for a
        # pixel), its file downloads and `stepwise quiz` grades it.
        # One fresh page, then a link each (as a course page's links would).
        quizzes = 0
        for k, entry in enumerate(manifest):
            number = os.path.basename(entry).split("-")[0]
            lesson_file = os.path.join(source, "lessons", os.path.basename(entry))
            with open(lesson_file, encoding="utf-8") as f:
                has_quiz = "\n## quiz " in f.read()
            fragment = "lesson=" + number + ("&quiz" if has_quiz else "")
            st = open_page(d, page, fragment) if k == 0 else follow_link(d, fragment, os.path.basename(entry))
            if st["lesson"] != os.path.basename(entry) or st["steps"] == 0 or st["error"]:
                fail("#lesson=%s shows %s with %d steps, error %r" % (number, st["lesson"], st["steps"], st["error"]))
            if has_quiz:
                answer_one(d, number)
                saved = os.path.join(downloads, os.path.basename(entry)[:-3] + ".jsonl")
                if os.path.exists(saved):
                    os.remove(saved)  # else the browser names the new one "... (1).jsonl"
                press(d, wait_state(d, "lesson %s's download button" % number,
                                    lambda s: any(w["label"] == "Download answers" for w in s["widgets"])), "Download answers")
                graded = grade(stepwise, lesson_file, saved)
                if graded.get("answered") != 1 or graded.get("student") != "student":
                    fail("lesson %s: the graded download says %s" % (number, json.dumps(graded)[:300]))
                quizzes += 1
        print("all %d lessons open; %d quizzes answered in the page, downloaded and graded" % (len(manifest), quizzes))
        severe = [e for e in d.logs() if e.get("level") == "SEVERE"]
        if severe:
            fail("console errors: %s" % severe)
    print("ok: the page opens from file://, steps, drags, runs exact, matches the traces, grades a downloaded quiz")


if __name__ == "__main__":
    main()
