"""Helpers of the value tests (tests/cli/values_*.py): run dlpverify, compare numbers, fail with
the number that differs. Nothing here computes a value the tests check."""
import os
import subprocess
import sys
import tempfile

failures = []
_folder = None


def run(dlpverify, *args, expect_exit=0):
    """Runs `dlpverify ARGS`; returns its standard output, fails the test on another exit code."""
    done = subprocess.run([dlpverify, *map(str, args)], capture_output=True, text=True)
    if done.returncode != expect_exit:
        print(f"FAIL: {' '.join(map(str, args))} exited {done.returncode}, expected {expect_exit}")
        print(done.stderr, end="")
        sys.exit(1)
    return done.stdout


def folder():
    """A temporary folder removed when the test ends."""
    global _folder
    _folder = tempfile.TemporaryDirectory()
    return _folder.name


def path(name):
    return os.path.join(_folder.name, name)


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAIL: {what}")


def close(measured, expected, tolerance, what):
    """|measured - expected| <= tolerance * |expected| (relative)."""
    ok = measured is not None and abs(measured - expected) <= tolerance * abs(expected)
    check(ok, f"{what}: {measured!r}, expected {expected!r} within {tolerance:g} relative")


def finish(summary):
    if _folder is not None:
        left = [name for name in os.listdir(_folder.name) if name.startswith(".")]
        check(not left, f"temporary files left behind: {left}")
    if failures:
        print(f"{len(failures)} value(s) wrong")
        sys.exit(1)
    print(f"ok: {summary}")
