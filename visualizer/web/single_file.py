#!/usr/bin/env python3
"""Makes the browser page one file: PAGE.html with its script and its wasm inside.

Usage: single_file.py BUILT.html OUT.html

emcc writes BUILT.html with <script async src="NAME.js"></script> beside NAME.js and NAME.wasm. This
puts the wasm in the page as base64 in a script element of a type the browser does not run, which
its HTML reader only scans to the end tag, and the script after it. The page hands the decoded bytes
to the module (Module.wasmBinary) before its script runs. emcc's own -sSINGLE_FILE writes the wasm
into a JavaScript string literal instead, which a cold Chromium here took about 0.8 s longer to read
at this size (docs/web.md).
"""
import base64
import os
import re
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: single_file.py BUILT.html OUT.html")
    built, out = sys.argv[1], sys.argv[2]
    html = open(built, encoding="utf-8").read()
    tags = re.findall(r'<script async type="text/javascript" src="([^"]+\.js)"></script>', html)
    if len(tags) != 1:
        sys.exit("single_file.py: %s has %d script tags of emcc's, not one" % (built, len(tags)))
    base = os.path.join(os.path.dirname(built), tags[0][:-3])
    js = open(base + ".js", encoding="utf-8").read()
    wasm = base64.b64encode(open(base + ".wasm", "rb").read()).decode("ascii")
    if "</script" in js.lower():
        sys.exit("single_file.py: the script holds '</script', which would end it early")
    inline = ('<script id="stepwise-wasm" type="application/octet-stream">' + wasm + '</script>\n'
              '<script>\n'
              '  (function () {  // the wasm, decoded once, before the module\'s script starts it\n'
              '    var text = atob(document.getElementById("stepwise-wasm").textContent);\n'
              '    var bytes = new Uint8Array(text.length);\n'
              '    for (var i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);\n'
              '    Module.wasmBinary = bytes;\n'
              '  })();\n'
              '</script>\n'
              '<script>' + js + '</script>')
    html = html.replace(
        '<script async type="text/javascript" src="%s"></script>' % tags[0], inline)
    tmp = out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(html)
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
