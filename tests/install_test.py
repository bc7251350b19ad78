#!/usr/bin/env python3
"""The install, as a user gets it (docs/build.md#install): `cmake --install` into a temporary prefix, then the
installed binaries run from an unrelated directory with no STEPWISE_* variable set. They must find share/stepwise
beside their bin/ on their own, not the source tree they were built from: `--version` names the data root in use.
Then the .deb: `cpack -G DEB` builds it, and its control fields and contents are checked.

    install_test.py BUILD_DIR SCRATCH_DIR
"""
import os, pathlib, shutil, subprocess, sys

BUILD, SCRATCH = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def run(cmd, cwd, env=None, timeout=300):
    return subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


shutil.rmtree(SCRATCH, ignore_errors=True)
prefix, elsewhere = SCRATCH / "prefix", SCRATCH / "elsewhere"
elsewhere.mkdir(parents=True)
r = run(["cmake", "--install", str(BUILD), "--prefix", str(prefix)], cwd=SCRATCH)
check(r.returncode == 0, "cmake --install into a temporary prefix" + ("" if r.returncode == 0 else ": " + r.stderr[-300:]))
share = prefix / "share" / "stepwise"
for f in ["bin/stepwise", "bin/stepwise-gl", "bin/stepwise-gui", "share/stepwise/lessons/manifest.txt", "share/stepwise/lessons/01-dda-line.md",
          "share/stepwise/scenes/glass-spheres.json", "share/stepwise/out/meshes/elephant.off", "share/doc/stepwise/README.md"]:
    check((prefix / f).is_file(), f"installed {f}")

env = {k: v for k, v in os.environ.items() if not k.startswith("STEPWISE_")}
sw, gui = str(prefix / "bin" / "stepwise"), str(prefix / "bin" / "stepwise-gui")
r = run([sw, "--version"], cwd=elsewhere, env=env)
check(r.returncode == 0 and r.stdout.startswith("stepwise ") and f"data: {share}" in r.stdout,
      f"installed stepwise --version names its own data ({share}): {r.stdout.strip()!r}")
# A scene named relative to the data root, and a lesson whose mesh is relative to the lesson.
r = run([sw, "trace", "whitted", "--input", '{"scene":"scenes/glass-spheres.json","size":[16,12],"pixel":[8,6]}', "--out", "w.jsonl"],
        cwd=elsewhere, env=env)
check(r.returncode == 0 and (elsewhere / "w.jsonl").stat().st_size > 0, "installed stepwise traces a scene of its data: " + r.stderr.strip())
r = run([sw, "check", "w.jsonl"], cwd=elsewhere, env=env)
check(r.returncode == 0, "installed stepwise checks that trace: " + r.stderr.strip())
r = run([sw, "render", "--lesson", str(share / "lessons" / "18-kd-ray-mesh.md"), "--out", "mesh.png", "--size", "640x400"], cwd=elsewhere, env=env)
check(r.returncode == 0 and (elsewhere / "mesh.png").is_file(), "installed stepwise renders the mesh lesson: " + r.stderr.strip())
# The browser page, where scripts/web.sh has built it (test.sh does, before the tests): installed, and
# `lesson export --html` of the installed binary starts from it.
source = next(l.split("=", 1)[1].strip() for l in open(BUILD / "CMakeCache.txt") if l.startswith("CMAKE_HOME_DIRECTORY:"))
if (pathlib.Path(source) / "out" / "web" / "stepwise.html").is_file():
    check((share / "out" / "web" / "stepwise.html").is_file(), "installed share/stepwise/out/web/stepwise.html")
    r = run([sw, "lesson", "export", str(share / "lessons" / "03-bresenham.md"), "--html", "page"], cwd=elsewhere, env=env)
    exported = elsewhere / "page" / "index.html"
    check(r.returncode == 0 and exported.is_file() and "stepwiseLesson = {" in exported.read_text(errors="replace"),
          "installed stepwise exports a lesson as the app's page: " + r.stderr.strip()[-300:])
# The app with no arguments opens the first lesson of the installed manifest (exit 0: it loaded).
if shutil.which("xvfb-run"):
    r = run(["xvfb-run", "-a", "-s", "-screen 0 800x500x24", gui, "--size", "800x500", "--frames", "3", "--screenshot", "gui.png"],
            cwd=elsewhere, env=env)
    check(r.returncode == 0 and (elsewhere / "gui.png").is_file(), "installed stepwise-gui opens its first lesson: " + r.stderr.strip()[-300:])
else:
    check(False, "xvfb-run is missing (scripts/setup.sh installs it)")

# The .deb: built by CPack, with its runtime dependencies and the same layout under /usr.
debs = SCRATCH / "deb"
r = run(["cpack", "-G", "DEB", "-B", str(debs)], cwd=BUILD, timeout=600)
found = sorted(debs.glob("stepwise_*.deb"))
check(r.returncode == 0 and len(found) == 1, "cpack -G DEB writes one stepwise_*.deb" + ("" if r.returncode == 0 else ": " + r.stderr[-300:]))
if found:
    depends = run(["dpkg-deb", "-f", str(found[0]), "Depends"], cwd=SCRATCH).stdout
    for lib in ["libgmp10", "libmpfr6", "libglfw3", "libosmesa6", "libgif7", "libmd4c", "fonts-dejavu-core"]:
        check(lib in depends, f".deb depends on {lib}")
    print("      Depends: " + depends.strip())
    contents = run(["dpkg-deb", "-c", str(found[0])], cwd=SCRATCH).stdout
    for f in ["./usr/bin/stepwise", "./usr/bin/stepwise-gl", "./usr/bin/stepwise-gui", "./usr/share/stepwise/lessons/manifest.txt", "./usr/share/stepwise/scenes/bunny.json"]:
        check(f in contents, f".deb holds {f}")

print(f"install test: {len(failures)} failed" if failures else "install test: all passed")
sys.exit(1 if failures else 0)
