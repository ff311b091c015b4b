#!/usr/bin/env python3
"""The README's main-study block is what the main study prints, byte for byte.

The command is scripts/study.sh's `build/dlpverify converge …` (continuation lines joined), run
as written in a scratch folder (build/ a link to this build, results/ made as study.sh makes it);
its standard output must equal the first code block under the README's "## The main study", and
the files it names must be written. Kuhl & Grote's full sphere: about 10 s and 0.8 GB.

usage: readme_study.py SOURCE_DIR BUILD_DIR
       readme_study.py --self-test
"""
import os
import re
import subprocess
import sys
import tempfile

HEADING = "## The main study"


def study_command(script_text):
    """The converge command of study.sh, its continuation lines joined."""
    joined = re.sub(r"\s*\\\n\s*", " ", script_text)
    lines = [line.strip() for line in joined.splitlines() if line.strip().startswith("build/dlpverify converge")]
    if len(lines) != 1:
        raise ValueError(f"study.sh has {len(lines)} converge commands, not one")
    return lines[0]


def block_under(text, heading, n=0):
    """The text of fenced block n (from 0), of those opened by a bare ``` line, after `heading`."""
    blocks, opening, lines = [], None, []
    for line in text[text.index(heading):].splitlines(keepends=True):
        if opening is None:
            if line.startswith("```"):
                opening, lines = line.strip(), []
        elif line.strip() == "```":
            if opening == "```":
                blocks.append("".join(lines))
            opening = None
        else:
            lines.append(line)
    return blocks[n]


def readme_block(readme_text):
    """The first fenced block under the main study's heading."""
    return block_under(readme_text, HEADING)


def self_test():
    command = study_command("set -e\nbuild/dlpverify converge --case drag \\\n  --table t.txt \\\n  --plot p.png\n")
    text = "x\n## The main study\n\ntext\n\n```sh\nnot this\n```\n\n```\nline 1\nline 2\n```\n\n```\nother\n```\n"
    block, second = readme_block(text), block_under(text, HEADING, 1)
    if (command != "build/dlpverify converge --case drag --table t.txt --plot p.png" or block != "line 1\nline 2\n" or
            second != "other\n"):
        print(f"FAIL: self-test read {command!r}, {block!r} and {second!r}")
        return 1
    print("ok: the command's continuation lines joined, the blocks under the heading read")
    return 0


def main(source, build):
    with open(os.path.join(source, "scripts", "study.sh")) as f:
        command = study_command(f.read())
    with open(os.path.join(source, "README.md"), encoding="utf-8") as f:
        block = readme_block(f.read())
    outputs = re.findall(r"--(?:table|csv|json|plot) (\S+)", command)
    with tempfile.TemporaryDirectory(prefix="readme-study-") as scratch:
        os.symlink(os.path.abspath(build), os.path.join(scratch, "build"))
        os.mkdir(os.path.join(scratch, "results"))
        done = subprocess.run(["bash", "-c", command], cwd=scratch, capture_output=True, text=True)
        if done.returncode != 0:
            print(f"FAIL: `{command}` exited {done.returncode}\n{done.stderr}")
            return 1
        missing = [o for o in outputs if not os.path.isfile(os.path.join(scratch, o))]
    if len(outputs) != 4 or missing:
        print(f"FAIL: the study names {outputs}; not written: {missing}")
        return 1
    if done.stdout != block:
        print("FAIL: the README's main-study block is not what the study prints")
        for label, text in (("README", block), ("printed", done.stdout)):
            print(f"--- {label}:\n{text}", end="")
        return 1
    print(f"ok: the README's block is the {len(block.splitlines())} lines `{command}` prints")
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(main(sys.argv[1], sys.argv[2]))
