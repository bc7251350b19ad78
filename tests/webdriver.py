"""Headless Chromium through chromedriver's WebDriver HTTP API, for the browser tests
(lesson_export_browser.py, web_browser.py). Standard library only (urllib, json).

    with chromium_session(work_dir) as d:
        d.s("POST", "/url", {"url": "file:///..."})
        d.js("return document.title;")

Fails (exit 1, never skips) when chromium or chromedriver is missing."""
import contextlib
import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request

RIGHT, LEFT = "\ue014", "\ue012"


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Driver:
    def __init__(self, base):
        self.base = base
        self.sid = None

    def call(self, method, path, body=None, timeout=60):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as r:
                return json.loads(r.read() or b"null")["value"]
        except urllib.error.HTTPError as e:
            fail("%s %s: HTTP %d %s" % (method, path, e.code, e.read()[:400]))

    def s(self, method, path, body=None):
        return self.call(method, "/session/%s%s" % (self.sid, path), body)

    def js(self, script, *args):
        return self.s("POST", "/execute/sync", {"script": script, "args": list(args)})

    def key(self, k):
        # Held a few frames: an app that polls key state once a frame (ImGui 1.86) misses a press
        # released within one.
        actions = [{"type": "keyDown", "value": k}, {"type": "pause", "duration": 60}, {"type": "keyUp", "value": k}]
        self.s("POST", "/actions", {"actions": [{"type": "key", "id": "kb", "actions": actions}]})

    def pointer(self, actions):
        """Mouse actions in CSS pixels of the viewport: [("move", x, y), ("down",), ("up",), ("pause", ms)]."""
        out = []
        for a in actions:
            if a[0] == "move":
                out.append({"type": "pointerMove", "duration": 50, "origin": "viewport", "x": int(a[1]), "y": int(a[2])})
            elif a[0] == "pause":
                out.append({"type": "pause", "duration": a[1]})
            else:
                out.append({"type": "pointerDown" if a[0] == "down" else "pointerUp", "button": 0})
        self.s("POST", "/actions", {"actions": [{"type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"},
                                                 "actions": out}]})
        self.s("DELETE", "/actions")

    def logs(self):
        return self.s("POST", "/se/log", {"type": "browser"})


@contextlib.contextmanager
def chromium_session(work, window="1400,1000", downloads=None):
    chromium, chromedriver = shutil.which("chromium"), shutil.which("chromedriver")
    if not chromium or not chromedriver:
        fail("chromium and chromedriver are needed (scripts/setup.sh installs them)")
    # chromedriver reaches Chromium's DevTools at ws://localhost; where the name does not resolve (a
    # root without /etc/hosts) the session fails with "unable to connect to renderer".
    try:
        socket.getaddrinfo("localhost", None)
    except socket.gaierror:
        fail("'localhost' does not resolve (is /etc/hosts missing?): chromedriver reaches Chromium through it")
    port = free_port()
    log = open(os.path.join(work, "chromedriver.log"), "w")
    proc = subprocess.Popen([chromedriver, "--port=%d" % port], stdout=log, stderr=subprocess.STDOUT)
    d = Driver("http://127.0.0.1:%d" % port)
    try:
        for _ in range(300):  # bounded: up to 30 s for chromedriver to listen
            try:
                if d.call("GET", "/status")["ready"]:
                    break
            except (urllib.error.URLError, ConnectionError):
                pass
            time.sleep(0.1)
        else:
            fail("chromedriver did not start")
        options = {"binary": chromium, "args": [
            # Shared memory in /tmp, not /dev/shm, which a container or a bare root may lack; no
            # background connections (this machine's network is closed).
            "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=" + window,
            "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
            "--user-data-dir=" + os.path.join(work, "profile")]}
        if downloads:
            options["prefs"] = {"download.default_directory": downloads, "download.prompt_for_download": False}
        caps = {"browserName": "chrome", "goog:loggingPrefs": {"browser": "ALL"}, "goog:chromeOptions": options}
        d.sid = d.call("POST", "/session", {"capabilities": {"alwaysMatch": caps}})["sessionId"]
        yield d
    finally:
        if d.sid:
            try:
                d.call("DELETE", "/session/" + d.sid)
            except SystemExit:
                pass
        proc.terminate()
        proc.wait(timeout=30)
        log.close()
