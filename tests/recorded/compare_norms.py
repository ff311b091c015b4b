#!/usr/bin/env python3
"""Runs the studies recorded in l2-norms.json and compares every level's L2 norm of every
variable with the recorded one.

l2-norms.json holds the program's own output for three studies (drag with RK2, `full` with its
CVODE reference, an ARKODE table on drag), the build that recorded them ("provenance": commit,
compiler, flags, SIMD width, SUNDIALS, date) and, per study, the largest relative deviation
allowed ("tolerance") with the drift that justifies it ("why"). A change that is meant to move
round-off only must reproduce each within its tolerance; one that moves a number further is a
change of results, and re-recording is then one command from the repository's root:

    python3 tests/recorded/record_norms.py build/dlpverify tests/recorded/l2-norms.json

which replaces the norms and the provenance and keeps the arguments, tolerances and reasons.

usage: compare_norms.py DLPVERIFY RECORDED_JSON    exit 0 all within, 1 one is out, 2 bad input
"""
import json
import os
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        sys.exit(2)
    binary, recorded_path = sys.argv[1], sys.argv[2]
    recorded = json.load(open(recorded_path))
    p = recorded["provenance"]
    print(f"recorded by commit {p['git_commit']}, {p['compiler']}, {p['build_type']} {p['cxx_flags']}, "
          f"{p['simd_isa']} x{p['simd_lanes']}, SUNDIALS {p['sundials']}, {p['date']}")
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        for name, study in recorded["studies"].items():
            tolerance = study["tolerance"]
            if not (isinstance(tolerance, float) and 0 < tolerance < 1e-6):
                print(f"{recorded_path}: {name}: tolerance {tolerance!r} is not a number in (0, 1e-6)", file=sys.stderr)
                sys.exit(2)
            out = os.path.join(folder, name + ".json")
            run = subprocess.run([binary, *study["arguments"], "--json", out], stdout=subprocess.DEVNULL)
            if run.returncode != 0:
                print(f"FAIL {name}: dlpverify exited {run.returncode}")
                failures += 1
                continue
            levels = json.load(open(out))["levels"]
            if len(levels) != len(study["l2"]):
                print(f"FAIL {name}: {len(levels)} levels, recorded {len(study['l2'])}")
                failures += 1
                continue
            worst, where = 0.0, ""
            for k, (level, expected) in enumerate(zip(levels, study["l2"])):
                measured = {key[len("l2_"):] for key in level if key.startswith("l2_")}
                if measured != set(expected):
                    print(f"FAIL {name} level {k}: variables {sorted(measured)}, recorded {sorted(expected)}")
                    failures += 1
                    continue
                for variable, value in expected.items():
                    got = level["norms_" + variable]["l2"]
                    deviation = abs(got - value) / abs(value)
                    if deviation > worst:
                        worst, where = deviation, f"level {k} {variable}"
                    if not deviation <= tolerance:
                        print(f"FAIL {name} level {k} {variable}: {got!r}, recorded {value!r}: "
                              f"relative deviation {deviation:.2e} > tolerance {tolerance:.0e}")
                        failures += 1
            print(f"{name}: largest relative deviation {worst:.2e}{f' ({where})' if worst else ''}, "
                  f"tolerance {tolerance:.0e}, {len(levels)} levels")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
