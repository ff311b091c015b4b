#!/usr/bin/env python3
"""The block kernels build without a warning for any x86-64, not only for this CPU.

GCC's -Wmaybe-uninitialized depends on what it inlines and vectorises, and so on -march: the
portable build (-DDLPVERIFY_NATIVE=OFF, the Debian package's) warned where the native one did
not, and CI builds native only. Each file below is compiled again with this build's own command
(compile_commands.json), its -march=native replaced by -march=x86-64 and warnings made errors;
the test fails, quoting the compiler, on any warning. The files are the kernels whose code GCC
vectorises per ISA, kept to the quick ones (a few seconds in all).

usage: portable_warnings.py BUILD_DIR
"""
import json
import os
import shlex
import subprocess
import sys
import tempfile

FILES = ["src/problems/dlp/block_rates.cpp", "src/simd/vector_math.cpp"]


def main(build):
    with open(os.path.join(build, "compile_commands.json")) as f:
        commands = json.load(f)
    failed = 0
    for name in FILES:
        entry = next((e for e in commands if e["file"].endswith("/" + name)), None)
        if entry is None:
            print(f"FAIL: {name} is not in {build}/compile_commands.json")
            failed += 1
            continue
        words = [w for w in shlex.split(entry["command"]) if w not in ("-march=native", "-Werror")]
        with tempfile.TemporaryDirectory() as scratch:
            words[words.index("-o") + 1] = os.path.join(scratch, "portable.o")
            words[1:1] = ["-march=x86-64", "-Werror"]
            done = subprocess.run(words, cwd=entry["directory"], capture_output=True, text=True)
        if done.returncode != 0 or "warning" in done.stderr:
            print(f"FAIL: {name} with -march=x86-64 (exit {done.returncode}):\n{done.stderr}")
            failed += 1
        else:
            print(f"ok: {name} builds for x86-64 without a warning")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
