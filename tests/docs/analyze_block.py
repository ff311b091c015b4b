#!/usr/bin/env python3
"""docs/analyze.md's worked example prints what the page shows, byte for byte.

examples/analyze/run.sh (the page's runs and its `dlpverify analyze` command) is run into a
scratch folder; its standard output must equal the first bare code block under the page's
"## A worked example", the table, orders, constants and verdict the page quotes.

usage: analyze_block.py SOURCE_DIR DLPVERIFY
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from readme_study import block_under  # noqa: E402


def main(source, dlpverify):
    with open(os.path.join(source, "docs", "analyze.md"), encoding="utf-8") as f:
        block = block_under(f.read(), "## A worked example")
    with tempfile.TemporaryDirectory(prefix="analyze-block-") as scratch:
        done = subprocess.run(["sh", os.path.join(source, "examples", "analyze", "run.sh"), dlpverify, scratch],
                              capture_output=True, text=True)
    if done.returncode != 0:
        print(f"FAIL: run.sh exited {done.returncode}\n{done.stderr}")
        return 1
    if done.stdout != block:
        print(f"FAIL: docs/analyze.md's worked example is not what run.sh prints\n--- page:\n{block}--- printed:\n{done.stdout}", end="")
        return 1
    print(f"ok: docs/analyze.md's block is the {len(block.splitlines())} lines run.sh prints")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
