#!/usr/bin/env python3
"""Every Boost test case is reached by a test that ctest runs.

ctest runs each top-level suite of the unit-test executables by name (`--run_test=SUITE`,
tests/CMakeLists.txt), so a case outside every suite, or in a suite the scan did not register,
would never run. This compares each executable's `--list_content` with the filters of the ctest
commands that run it: every case must lie under a selected suite. A case a build excludes on
purpose (`--run_test=!SUITE/CASE`, DLPVERIFY_UNIT_TEST_SKIP) is listed as skipped, not a failure.
A case disabled in the source is a failure too: a suite's filter does not run it.

usage: check_unreached_cases.py BUILD_DIR EXECUTABLE...   (exit 1 naming every unreached case)
       check_unreached_cases.py --self-test
"""
import json
import os
import subprocess
import sys


def listed_cases(listing):
    """(path, enabled) of every leaf of Boost's --list_content tree (4 spaces per level, '*' = enabled)."""
    rows = []
    for line in listing.splitlines():
        if not line.strip():
            continue
        depth = (len(line) - len(line.lstrip(" "))) // 4
        name = line.strip()
        rows.append((depth, name.rstrip("*"), name.endswith("*")))
    cases, path = [], []
    for i, (depth, name, enabled) in enumerate(rows):
        path = path[:depth] + [name]
        leaf = i + 1 == len(rows) or rows[i + 1][0] <= depth
        if leaf:
            cases.append(("/".join(path), enabled))
    return cases


def ctest_filters(commands, executable):
    """The --run_test values of every ctest command that runs the executable."""
    filters = []
    for command in commands:
        if command and os.path.realpath(command[0]) == os.path.realpath(executable):
            filters += [a.split("=", 1)[1] for a in command[1:] if a.startswith("--run_test=")]
    return filters


def under(case, unit):
    return case == unit or case.startswith(unit + "/")


def verdicts(cases, filters):
    """unreached and skipped case paths."""
    selected = [f for f in filters if not f.startswith("!")]
    excluded = [f[1:] for f in filters if f.startswith("!")]
    unreached, skipped = [], []
    for case, enabled in cases:
        if any(under(case, e) for e in excluded):
            skipped.append(case)
        elif not enabled or not any(under(case, s) for s in selected):
            unreached.append(case + ("" if enabled else " (disabled)"))
    return unreached, skipped


def self_test():
    listing = "cvode_reference*\n    rtol_meets_closed_form*\n    tightened*\nstray_case*\nplot*\n    figure*\n    off\n"
    cases = listed_cases(listing)
    assert cases == [("cvode_reference/rtol_meets_closed_form", True), ("cvode_reference/tightened", True),
                     ("stray_case", True), ("plot/figure", True), ("plot/off", False)], cases
    unreached, skipped = verdicts(cases, ["cvode_reference", "plot", "!plot/figure"])
    assert unreached == ["stray_case", "plot/off (disabled)"], unreached
    assert skipped == ["plot/figure"], skipped
    assert verdicts(cases[:2], ["cvode_reference"]) == ([], [])
    print("self-test: a stray case, a disabled case and a skipped case are told apart")
    return 0


def main(build, executables):
    shown = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"], capture_output=True, text=True, check=True)
    commands = [t.get("command", []) for t in json.loads(shown.stdout)["tests"]]
    failed = False
    for executable in executables:
        listing = subprocess.run([executable, "--list_content"], capture_output=True, text=True, check=True)
        cases = listed_cases(listing.stderr + listing.stdout)
        unreached, skipped = verdicts(cases, ctest_filters(commands, executable))
        name = os.path.basename(executable)
        for case in unreached:
            print(f"FAIL: {name}: {case} is run by no ctest test (outside every registered suite?)")
        for case in skipped:
            print(f"note: {name}: {case} is skipped by this build (DLPVERIFY_UNIT_TEST_SKIP)")
        print(f"{name}: {len(cases) - len(unreached) - len(skipped)} of {len(cases)} cases reached by ctest")
        failed = failed or bool(unreached) or not cases
    return 1 if failed else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(main(sys.argv[1], sys.argv[2:]))
