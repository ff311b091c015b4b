#!/usr/bin/env python3
"""analyze blames a bad run on its own file, in one line: t_end = NaN in a run but the first,
steps = -50 in the last run, and a CSV run naming one column twice (docs/analyze.md). Each exits
2 with one stderr line naming the file at fault and what is wrong; no output is written.

usage: analyze_runs_checked.py DLPVERIFY   (Debian's python3 with python3-h5py)
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np


def run_file(path, steps, t_end):
    with h5py.File(path, "w") as f:
        f.attrs["t0"] = 0.0
        f.attrs["t_end"] = t_end
        f.attrs["steps"] = np.int64(steps)
        f.create_group("fields")["x"] = np.linspace(0.0, 1.0, 4)


def refused(dlpverify, args, culprit, words):
    """exit 2, one line naming the culprit file and every word of `words`; '' when so, else why not."""
    run = subprocess.run([dlpverify, "analyze", *args, "--json", "out.json"], capture_output=True, text=True)
    said = run.stderr.strip()
    if run.returncode != 2:
        return f"exit {run.returncode}, expected 2: {said}"
    if len(said.splitlines()) != 1 or culprit not in said or not all(w in said for w in words):
        return f"the line does not name {culprit} and {words}: {said}"
    if os.path.exists("out.json"):
        return "an output was written"
    print("ok:", said)
    return ""


def main(dlpverify):
    os.chdir(tempfile.mkdtemp())
    failures = []
    run_file("a.h5", 10, 0.01)
    run_file("b.h5", 20, float("nan"))
    run_file("c.h5", 40, 0.01)
    run_file("d.h5", -50, 0.01)
    for args, culprit, words in [
        (["a.h5", "b.h5", "c.h5"], "b.h5", ["t_end = nan", "finite"]),
        (["a.h5", "c.h5", "d.h5"], "d.h5", ["steps = -50"]),
    ]:
        why = refused(dlpverify, args, culprit, words)
        if why:
            failures.append(f"{' '.join(args)}: {why}")
    for name in ("e.csv", "f.csv", "g.csv"):
        open(name, "w").write("x,v,x\n1,2,3\n")
    why = refused(dlpverify, ["e.csv", "f.csv", "g.csv", "--dt", "1e-3", "--dt", "5e-4", "--dt", "2.5e-4", "--t-end", "0.01"],
                  "e.csv", ["column 3 (x)", "given before"])
    if why:
        failures.append(f"duplicate column: {why}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
