#!/usr/bin/env python3
"""The Problem contract stays slim (include/dlpverify/problem.hpp): at most 8 virtual member
functions besides the destructor, the class on one screen (at most 60 lines), and a `///`
comment on every public member. Hooks that only some consumers need are capabilities declared
beside them (docs/verification.md, "Your problem").

usage: problem_contract.py SOURCE_DIR"""
import re
import sys

MAX_VIRTUAL = 8
MAX_LINES = 60

lines = open(f"{sys.argv[1]}/include/dlpverify/problem.hpp", encoding="utf-8").read().split("\n")
start = next(i for i, l in enumerate(lines) if l.startswith("class Problem"))
end = next(i for i in range(start, len(lines)) if lines[i].startswith("};"))
body = lines[start : end + 1]
virtual = [l.strip() for l in body if re.match(r"\s*virtual\b", l) and "~" not in l]
failures = []
if len(virtual) > MAX_VIRTUAL:
    failures.append(f"{len(virtual)} virtual functions, at most {MAX_VIRTUAL}: " + "; ".join(virtual))
if len(body) > MAX_LINES:
    failures.append(f"class Problem is {len(body)} lines, at most {MAX_LINES}")
for i, l in enumerate(body):
    if re.match(r"\s*virtual\b", l) and "~" not in l and not body[i - 1].strip().startswith("///") and "///" not in l:
        failures.append(f"no /// comment on: {l.strip()}")
for f in failures:
    print("FAIL:", f)
print(f"{len(virtual)} virtual functions, {len(body)} lines" if not failures else "")
sys.exit(1 if failures else 0)
