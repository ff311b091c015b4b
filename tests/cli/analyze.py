#!/usr/bin/env python3
"""`dlpverify analyze` against `converge` on the same runs (docs/analyze.md).

The runs are written by the Python exchange example (examples/external/python/midpoint.py) while
`converge` drives it as its `exec:` integrator: a shell wrapper keeps a copy of every output file,
named by its step count. `analyze` on those copies must then give converge's numbers: the same
states, measured by the same library code, give the same bits (norms, pairwise orders, statuses)
and the same fitted orders up to the last bits of Δt (converge's Δt is t_end/n, analyze's is
(t_end − t0)/n from the files' attributes, which may differ by an ulp).

usage: analyze.py DLPVERIFY SOURCE_DIR MODE
  reference     analyze RUN… --reference REF [--reference-check REF2]  ==  converge --reference
                integrator:exec:…@DT (whose error estimate solves again at DT/2)
  self          analyze RUN… (no reference)   ==  converge's self-convergence of the same levels
  check         analyze --expect-order 2: exit 0 on midpoint's runs, 1 on its slipped (order 1) copy;
                its error constant fitted at order 2, with no --order or --order 1
  mismatch      a field, the member count, the end time that differ: exit 2 with one line naming
                it, nothing written
  csv           CSV runs (--dt, --t-end): the same numbers as HDF5; shuffled members matched by an
                id column (CSV, or HDF5 /fields/id int64) give them again, without one they do not
"""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

import h5py
import numpy as np

DLPVERIFY, SOURCE, MODE = sys.argv[1], sys.argv[2], sys.argv[3]
PYTHON = "/usr/bin/python3"  # Debian's, with python3-h5py and python3-numpy
MIDPOINT = os.path.join(SOURCE, "examples/external/python/midpoint.py")
STUDY = ["--case", "drag", "--outer", "4", "--levels", "5"]  # 256 particles, 20 … 320 steps
VARIABLES = ["--variable", "position=x,y,z", "--variable", "velocity=vx,vy,vz"]  # converge's variables of drag
REFERENCE_DT = 0.01 / 1280  # the integrator reference: 1280 steps, its error estimate at 2560
failures = []


def fail(message):
    failures.append(message)
    print("FAIL:", message)


def run(args, expect):
    result = subprocess.run([DLPVERIFY] + args, capture_output=True, text=True)
    if result.returncode != expect:
        print(result.stdout[-3000:], result.stderr[-3000:])
        sys.exit("FAIL: exit %d, expected %d: %s" % (result.returncode, expect, " ".join(args)))
    return result


def keeping(folder, slip=False):
    """The exec: command of midpoint.py that keeps its every output as FOLDER/run-<steps>.h5."""
    script = os.path.join(folder, "keep.sh")
    with open(script, "w") as f:
        f.write('%s %s "$1" "$2" %s && cp "$2" "%s/run-$3.h5"\n' % (PYTHON, MIDPOINT, "--slip" if slip else "", folder))
    return "exec:sh %s {input} {output} {steps}" % script


def converge(folder, extra, slip=False):
    """converge with midpoint.py as exec: integrator (keeping), against the closed form unless `extra` says."""
    out = os.path.join(folder, "converge.json")
    run(["converge"] + STUDY + ["--exec-order", "2", "--integrator", keeping(folder, slip), "--json", out] + extra, 0)
    with open(out) as f:
        return json.load(f)


def analyze(args, expect=0):
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "analyze.json")
        run(["analyze"] + args + ["--json", out], expect)
        with open(out) as f:
            return json.load(f)


def runs(folder, steps=(20, 40, 80, 160, 320)):
    return [os.path.join(folder, "run-%d.h5" % n) for n in steps]


def same(what, a, b, relative=0.0):
    if a is None or b is None:
        if a is not b:
            fail("%s: %r against %r" % (what, a, b))
    elif abs(a - b) > relative * abs(b):
        fail("%s: %.17g against %.17g" % (what, a, b))


def same_levels(a, b, levels, shift=0, statuses=True):
    """Norms and statuses bit for bit, pairwise orders to the last bits of dt."""
    for k in range(levels):
        la, lb = a["levels"][k], b["levels"][k + shift]
        same("level %d steps" % k, la["steps"], lb["steps"])
        same("level %d dt" % k, la["dt"], lb["dt"], 1e-15)
        for v in ("position", "velocity"):
            for norm in ("l2", "rms", "relative", "max"):
                same("level %d %s %s" % (k, v, norm), la["norms_" + v][norm], lb["norms_" + v][norm])
            if statuses:
                same("level %d %s status" % (k, v), la["status_by_variable"][v]["status"] == lb["status_by_variable"][v]["status"], True)
            same("level %d %s order" % (k, v), la["order_" + v], lb["order_" + v], 1e-12)


def same_fits(a, b):
    for v in ("position", "velocity"):
        fa, fb = a["fitted_order"][v], b["fitted_order"][v]
        same(v + " fitted levels", fa["levels_used"] == fb["levels_used"], True)
        same(v + " fitted order", fa["value"], fb["value"], 1e-12)
        same(v + " stderr", fa["stderr"], fb["stderr"], 1e-9)  # a difference of slopes: cancellation
        for i in range(2):
            same(v + " ci95", fa["ci95"][i], fb["ci95"][i], 1e-12)


def test_reference(folder):
    c = converge(folder, ["--reference", "integrator:%s@%r" % (keeping(folder), REFERENCE_DT)])
    a = analyze(runs(folder) + ["--reference", os.path.join(folder, "run-1280.h5"), "--order", "2"] + VARIABLES)
    same("levels", len(a["levels"]), 5)
    # Without its error, analyze cannot tell the levels that measure the reference (statuses and
    # fits follow below, with it).
    same_levels(a, c, 5, statuses=False)
    # The reference's error against its run at half the step, as converge estimates an integrator
    # reference's: by Richardson's rule at the declared order 2 (converge's exec: reference takes
    # --exec-order as its integrator does; analyze takes --order).
    ref = [os.path.join(folder, "run-%d.h5" % n) for n in (1280, 2560)]
    a = analyze(runs(folder) + ["--reference", ref[0], "--reference-check", ref[1], "--order", "2"] + VARIABLES)
    same_levels(a, c, 5)
    same_fits(a, c)
    for v in ("position", "velocity"):
        same(v + " reference error", a["reference_error"][v], c["reference_error"][v])
        same(v + " reference margin", a["reference_margin"][v], c["reference_margin"][v])
    same("trusted", a["reference_trusted"], c["reference_trusted"])
    expect_refusal(runs(folder) + ["--reference", ref[0], "--reference-check", runs(folder)[-1]],
                   ["--reference-check", "320 steps", "1280"])


def test_self(folder):
    c = converge(folder, [])
    a = analyze(VARIABLES + ["--order", "2"] + runs(folder))  # options before the runs take one value each
    same("levels", len(a["levels"]), 4)  # the finest run is the last level's reference
    for k in range(4):  # level k against run k + 1 is converge's difference d_{k+1} = ‖y_k − y_{k+1}‖
        for v in ("position", "velocity"):
            same("level %d %s" % (k, v), a["levels"][k]["l2_" + v], c["levels"][k + 1]["self_difference_" + v])
            same("level %d %s self-difference" % (k, v), a["levels"][k]["self_difference_" + v],
                 c["levels"][k]["self_difference_" + v])
    for v in ("position", "velocity"):
        sa, sc = a["self_convergence"][v], c["self_convergence"][v]
        same(v + " self-convergence order", sa["order"], sc["order"])
        same(v + " Richardson error", sa["richardson_error"], sc["richardson_error"])
        # GCI = 1.25 (d/‖y‖)/(r^p − 1): converge's ‖y‖ is the exact solution's, analyze's the finest
        # run's; they differ by the finest error, 4e-6 of ‖y‖ here.
        same(v + " GCI", sa["gci"], sc["gci"], 1e-3)
        fit = a["fitted_order"][v]["value"]  # of the differences, ∝ Δt^p as the errors are
        if not abs(fit - 2.0) <= 0.1:
            fail("%s: the differences' fitted order %r is not midpoint's 2 ± 0.1" % (v, fit))


def constant_at(result, v, order):
    """C of e = C Δt^P from the result's own levels: exp of the mean of ln e_k − P ln Δt_k over
    the levels its constant was fitted on (docs/verification.md, the error constant)."""
    logs = [math.log(result["levels"][k]["l2_" + v]) - order * math.log(result["levels"][k]["dt"])
            for k in result["error_constant"][v]["levels_used"]]
    return math.exp(sum(logs) / len(logs))


def test_check(folder):
    converge(folder, [])
    # --expect-order P, not --order, is the P of the level rules and of e = C Δt^P, as for check:
    # without --order, and with another one.
    for declared in ([], ["--order", "1"]):
        a = analyze(runs(folder) + ["--expect-order", "2"] + declared + VARIABLES, expect=0)
        same("midpoint passes", a["check"]["passed"], True)
        for v in ("position", "velocity"):
            what = "%s %s: the error constant" % (" ".join(declared) or "no --order", v)
            c = a["error_constant"][v]
            if c is None:
                fail(what + " is null")
                continue
            same(what + "'s order", c["order"], 2.0)
            used = c["levels_used"]
            same(what + "'s levels", bool(used) and used == a["fitted_order"][v]["levels_used"], True)
            same(what, c["value"], constant_at(a, v, 2.0), 1e-12)
    slipped = os.path.join(folder, "slipped")
    os.mkdir(slipped)
    converge(slipped, [], slip=True)
    verdict = analyze(runs(slipped) + ["--expect-order", "2"] + VARIABLES, expect=1)["check"]
    same("slipped midpoint (order 1) fails", verdict["passed"], False)


def expect_refusal(args, named):
    """Exit 2, one line on stderr naming `named`, no output written."""
    with tempfile.TemporaryDirectory() as out:
        outputs = ["--json", out + "/a.json", "--csv", out + "/a.csv", "--table", out + "/a.txt"]
        result = subprocess.run([DLPVERIFY, "analyze"] + args + outputs, capture_output=True, text=True)
        lines = result.stderr.splitlines()
        if result.returncode != 2 or len(lines) != 1 or any(n not in result.stderr for n in named):
            fail("%s: exit %d, stderr %r; expected exit 2 naming %s" % (args, result.returncode, result.stderr, named))
        if os.listdir(out) or result.stdout:
            fail("%s: wrote %s" % (args, os.listdir(out) or "on stdout"))


def altered(path, name, change):
    copy = os.path.join(os.path.dirname(path), name)
    with h5py.File(path, "r") as f, h5py.File(copy, "w") as g:
        for key, value in f.attrs.items():
            g.attrs[key] = value
        for field in f["fields"]:
            g.create_dataset("fields/" + field, data=f["fields"][field][...])
        change(g)
    return copy


def test_mismatch(folder):
    converge(folder, [])
    first, *rest = runs(folder)

    def no_vz(g):
        del g["fields/vz"]
        g.attrs["fields"] = [n for n in g.attrs["fields"] if n != "vz"]

    def short(g):
        for field in list(g["fields"]):
            data = g["fields/" + field][:-1]
            del g["fields/" + field]
            g.create_dataset("fields/" + field, data=data)

    def later(g):
        g.attrs["t_end"] = g.attrs["t_end"] * 1.5

    expect_refusal([altered(first, "no-vz.h5", no_vz)] + rest, ["no-vz.h5", "vz"])
    expect_refusal([altered(first, "short.h5", short)] + rest, ["short.h5", "256 members", "255"])
    expect_refusal(rest + [altered(first, "later.h5", later)], ["later.h5", "t_end"])
    expect_refusal(runs(folder)[:-1] + [runs(folder)[-1]] + ["--reference", altered(first, "ref-short.h5", short)],
                   ["--reference", "ref-short.h5", "255 members", "256"])
    expect_refusal(runs(folder) + ["--variable", "position=x,y,w"], ["variable position", "w"])
    expect_refusal(runs(folder) + ["--variable", "a=x", "--variable", "a=y"], ["variable a", "twice"])
    expect_refusal(runs(folder, (20, 40, 160)), ["run-160.h5", "160 steps"])  # not one ratio


def write_csv(path, h5, order, ids):
    with h5py.File(h5, "r") as f:
        names = list(f.attrs["fields"])
        columns = [f["fields"][n][...] for n in names]
    with open(path, "w") as out:
        out.write(",".join((["id"] if ids else []) + names) + "\n")
        for p in order:
            out.write(",".join(([str(p)] if ids else []) + [repr(float(c[p])) for c in columns]) + "\n")


def test_csv(folder):
    converge(folder, [])
    steps = (20, 40, 80, 160, 320)
    h5 = analyze(runs(folder) + VARIABLES)
    with h5py.File(runs(folder)[0], "r") as f:
        members = len(f["fields/x"])
    shuffled = list(range(members))
    random.Random(27).shuffle(shuffled)  # a fixed seed: the same test every time
    dt = ["--dt", ",".join(repr(0.01 / n) for n in steps), "--t-end", "0.01"]
    csv = {}
    for kind, ids in (("in-order", False), ("by-id", True), ("by-position", False)):
        paths = []
        for k, n in enumerate(steps):
            order = range(members) if kind == "in-order" or k == 0 else shuffled  # the first run keeps its order
            paths.append(os.path.join(folder, "%s-%d.csv" % (kind, n)))
            write_csv(paths[-1], runs(folder)[k], order, ids)
        csv[kind] = analyze(dt + paths + VARIABLES)  # --dt before the runs takes one list
    for kind in ("in-order", "by-id"):
        for k in range(4):
            for v in ("position", "velocity"):
                same("%s level %d %s" % (kind, k, v), csv[kind]["levels"][k]["l2_" + v], h5["levels"][k]["l2_" + v])
    # HDF5 runs with an int64 /fields/id, members shuffled: the same numbers again.
    by_id = []
    for k, path in enumerate(runs(folder)):
        by_id.append(os.path.join(folder, "id-%d.h5" % steps[k]))
        order = np.arange(members) if k == 0 else np.array(shuffled)
        with h5py.File(path, "r") as f, h5py.File(by_id[-1], "w") as g:
            g.attrs.update(dict(f.attrs))
            g.create_dataset("fields/id", data=order.astype(np.int64))
            for name in f.attrs["fields"]:
                g.create_dataset("fields/" + name, data=f["fields"][name][...][order])
    h5_by_id = analyze(by_id + VARIABLES)
    for k in range(4):
        for v in ("position", "velocity"):
            same("HDF5 by id level %d %s" % (k, v), h5_by_id["levels"][k]["l2_" + v], h5["levels"][k]["l2_" + v])
    # Shuffled rows without ids are compared member by position: other particles, far larger differences.
    if not csv["by-position"]["levels"][0]["l2_position"] > 10 * h5["levels"][0]["l2_position"]:
        fail("shuffled CSV rows without an id column were matched anyway")
    expect_refusal([os.path.join(folder, "in-order-%d.csv" % n) for n in steps], ["--t-end"])
    expect_refusal([os.path.join(folder, "in-order-%d.csv" % n) for n in steps] + ["--dt", "0.0005,0.00025", "--t-end", "0.01"],
                   ["--dt", "one step per run"])


with tempfile.TemporaryDirectory() as folder:
    {"reference": test_reference, "self": test_self, "check": test_check, "mismatch": test_mismatch,
     "csv": test_csv}[MODE](folder)
if failures:
    sys.exit("%d failure(s)" % len(failures))
print("ok:", MODE)
