#!/usr/bin/env python3
"""Writes the output of `stepwise list --contract ALG` into the docs that quote it, or checks it.

usage: contract_docs.py STEPWISE [--check] [DOC...]      (default DOC: docs/assignment-dda.md)

A quoted contract is the fenced block after a line `<!-- contract ALG -->`. Without --check the
blocks are rewritten in place; with --check nothing is written and the exit status is 1 when a
block differs from the command's output (tests/student_contract.py runs it so).
"""
import os
import re
import subprocess
import sys

args = [a for a in sys.argv[1:] if a != "--check"]
check = "--check" in sys.argv[1:]
if not args:
    sys.exit(__doc__)
exe, docs = args[0], args[1:] or [os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "assignment-dda.md")]
BLOCK = re.compile(r"(<!-- contract ([a-z0-9-]+) -->\n```text\n)(.*?)(```\n)", re.S)
stale = 0
for doc in docs:
    text = open(doc).read()

    def fresh(m):
        out = subprocess.run([exe, "list", "--contract", m.group(2)], capture_output=True, text=True, check=True).stdout
        return m.group(1) + out + m.group(4)

    new = BLOCK.sub(fresh, text)
    if not BLOCK.search(text):
        print(f"{doc}: no <!-- contract ALG --> block")
        stale += 1
    elif new != text:
        stale += 1
        if check:
            print(f"{doc}: a quoted contract differs from `stepwise list --contract` (run scripts/contract_docs.py {exe})")
        else:
            open(doc, "w").write(new)
            print(f"{doc}: updated")
sys.exit(1 if check and stale else 0)
