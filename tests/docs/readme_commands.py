#!/usr/bin/env python3
"""Every command of the README's "The first commands" block, run as printed.

In a scratch copy of the tree (the README's relative paths, build/ a link to this build), one
after another in the README's order, so that a command reading a file (compare base.json …) gets
it from the commands before it. Each command's exit code is checked against its comment: the
first "exit N" it names, else 0; a comment that quotes the cloud's size ("(4,168 particles)") must
be what the command prints. PATH starts with a pyenv-style python3 that has none of Debian's
modules (numpy, h5py), so that an exec: example depending on whichever python3 comes first fails.

usage: readme_commands.py SOURCE_DIR BUILD_DIR [--only SUBSTRING]
       readme_commands.py --self-test
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

BLOCK_HEADING = "## The first commands"


def entries(readme_text):
    """(command, comment) of each command of the block, continuation lines joined."""
    start = readme_text.index(BLOCK_HEADING)
    fence = readme_text.index("```sh\n", start) + len("```sh\n")
    block = readme_text[fence:readme_text.index("```", fence)]
    joined, pending = [], ""
    for line in block.splitlines():
        pending += line.rstrip()
        if pending.endswith("\\"):
            pending = pending[:-1] + " "
            continue
        if pending.strip():
            joined.append(pending)
        pending = ""
    out = []
    for line in joined:
        command, _, comment = line.partition("   #")
        if not comment:
            command, _, comment = line.partition(" # ")
        out.append((command.strip(), comment))
    return out


def commands(readme_text):
    """(command, expected exit code) of each command of the block: the first "exit N" its comment
    names, else 0."""
    out = []
    for command, comment in entries(readme_text):
        m = re.search(r"\bexit (\d+)", comment)
        out.append((command, int(m.group(1)) if m else 0))
    return out


def quoted_counts(readme_text):
    """{command: "N particles"} for each comment that quotes the command's cloud, commas dropped."""
    out = {}
    for command, comment in entries(readme_text):
        m = re.search(r"\(([\d,]+) particles\)", comment)
        if m:
            out[command] = m.group(1).replace(",", "") + " particles"
    return out


def self_test():
    text = BLOCK_HEADING + "\n\n```sh\na --x   # plain\nb \\\n    --y   # exit 1: shown\nc   # exit 0 pass, 1 fail\n```\n"
    got = commands(text)
    want = [("a --x", 0), ("b  --y", 1), ("c", 0)]
    if [(re.sub(r"\s+", " ", c), e) for c, e in got] != [(re.sub(r"\s+", " ", c), e) for c, e in want]:
        print(f"FAIL: self-test parsed {got}")
        return 1
    print("ok: continuation lines joined, exit codes read from the comments")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    source, build = argv[1], os.path.abspath(argv[2])
    only = argv[argv.index("--only") + 1] if "--only" in argv else None
    with open(os.path.join(source, "README.md"), encoding="utf-8") as f:
        text = f.read()
    listed, counts = commands(text), quoted_counts(text)
    if len(listed) < 15:
        print(f"FAIL: the README's block lists {len(listed)} commands")
        return 1
    scratch = tempfile.mkdtemp(prefix="readme-")
    try:
        tree = os.path.join(scratch, "tree")
        shutil.copytree(source, tree, symlinks=True,
                        ignore=shutil.ignore_patterns(".git", "build*", ".deps", "results"))
        os.symlink(build, os.path.join(tree, "build"))
        shim = os.path.join(scratch, "foreign-python")
        os.mkdir(shim)
        with open(os.path.join(shim, "python3"), "w") as f:
            f.write("#!/bin/sh\n# a python3 without Debian's site packages, as a pyenv or venv one\nexec /usr/bin/python3 -S \"$@\"\n")
        os.chmod(os.path.join(shim, "python3"), 0o755)
        env = dict(os.environ, PATH=shim + os.pathsep + os.environ.get("PATH", ""))
        failed = 0
        for command, expected in listed:
            if only and only not in command:
                continue
            run = subprocess.run(["bash", "-c", command], cwd=tree, env=env,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            # A comment that quotes the cloud's size ("(4,168 particles)") is held to the output.
            count_ok = command not in counts or counts[command] in run.stdout
            verdict = "ok" if run.returncode == expected and count_ok else "FAIL"
            print(f"{verdict}: exit {run.returncode} (README: {expected}): {command}")
            if not count_ok:
                print(f"  the output does not say '{counts[command]}', as the README's comment does")
            if run.returncode != expected or not count_ok:
                failed += 1
                print("  " + "\n  ".join(run.stdout.splitlines()[-8:]))
        return 1 if failed else 0
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
