#!/usr/bin/env python3
"""Runs the studies recorded in l2-norms.json and compares every level's L2 norms with the values
recorded before the harness was made problem-independent (issue 8), re-recorded when the norms'
sums became compensated (issue 9: they moved by at most 6.2e-15 relative, to the exactly rounded
sums), and full-rk2 re-recorded when the C_D(Re) law became one power of Re instead of powers of
d and ‖w‖ (issue 10: its errors moved by at most 2.4e-9 relative, 9.3e-16 of the solution's own
size, a few ulp of round-off in the states), and full-rk2 again when the CVODE reference's
vector sums were split into sixteen partial sums and its Adams order capped at 7 (issue 10: the
reference moved within its tolerance; the errors by at most 1.5e-9 relative, 5.6e-16 of the
solution's size): a refactor must reproduce them to 1e-12 relative, variable by variable and
level by level.

usage: compare_norms.py DLPVERIFY RECORDED_JSON
"""
import json
import os
import subprocess
import sys
import tempfile

TOLERANCE = 1e-12


def main():
    binary, recorded_path = sys.argv[1], sys.argv[2]
    recorded = json.load(open(recorded_path))
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        for name, run in recorded.items():
            out = os.path.join(folder, name + ".json")
            subprocess.run([binary, *run["arguments"], "--json", out], check=True, stdout=subprocess.DEVNULL)
            levels = json.load(open(out))["levels"]
            if len(levels) != len(run["l2"]):
                print(f"FAIL {name}: {len(levels)} levels, recorded {len(run['l2'])}")
                failures += 1
                continue
            worst = 0.0
            for k, (level, expected) in enumerate(zip(levels, run["l2"])):
                for variable, value in expected.items():
                    got = level["norms_" + variable]["l2"]
                    deviation = abs(got - value) / abs(value)
                    worst = max(worst, deviation)
                    if deviation > TOLERANCE:
                        print(f"FAIL {name} level {k} {variable}: {got!r}, recorded {value!r} ({deviation:.2e})")
                        failures += 1
            print(f"{name}: worst relative deviation {worst:.2e} over {len(levels)} levels")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
