#!/usr/bin/env python3
"""No output path can harm what the user has: a property over every command that writes a file.

For every command x every output option x every target below, the run is refused before any
work: exit 2 (bad input: an input of the run, another output under another spelling, a link
into a folder that does not exist, a FIFO, a folder) or 4 (a file in a read-only folder, tried
as the unprivileged user nobody when the test runs as root), one line on stderr naming the
option, and afterwards every input is byte for byte what it was, the FIFO and the folder are
untouched, and no folder was made. /dev/null, which discards, has its own test
(cli.output-devnull, in a private /dev). docs/cli.md, "What a path may name".

usage: path_property.py DLPVERIFY SOURCE_DIR
"""
import hashlib
import os
import shutil
import stat
import subprocess
import sys
import tempfile

FIGURES = {"--plot", "-o"}


def commands(source):
    """(command's arguments, its output options, its input files)."""
    return [
        (["converge", "--config", "conv.toml", "--integrator", "tableau:t.toml"],
         ["--json", "--csv", "--table", "--plot", "--history", "--per-particle"], ["conv.toml", "t.toml"]),
        (["converge", "--config", "conv.toml", "--reference", "integrator:tableau:t.toml@1e-4"],
         ["--json", "--csv", "--table", "--plot", "--history", "--per-particle"], ["conv.toml", "t.toml"]),
        (["check", "--config", "check.toml", "--baseline", "b.json"],
         ["--json", "--csv", "--table", "--plot", "--history", "--per-particle"], ["check.toml", "b.json"]),
        (["converge", "--case", "drag", "--outer", "4", "--levels", "2",
          "--integrator", "exec:python3 prog.py {input} {output}"], ["--json", "--csv"], ["prog.py"]),
        (["precision", "--config", "prec.toml"], ["--json", "--csv", "--table", "--plot"], ["prec.toml"]),
        (["analyze", "r1.csv", "r2.csv", "r3.csv", "--dt", "1e-3", "--dt", "5e-4", "--dt", "2.5e-4"],
         ["--json", "--csv", "--table", "--plot"], ["r1.csv", "r2.csv", "r3.csv"]),
        (["tableau", "t.toml"], ["--json"], ["t.toml"]),
        (["sharpness", "--integrator", "tableau:t.toml", "--case", "drag", "--outer", "4"], ["--json"], ["t.toml"]),
        (["plot", "b.json"], ["-o"], ["b.json"]),
        (["compare", "b.json", "b2.json"], ["--json"], ["b.json", "b2.json"]),
        (["audit"], ["--json"], []),
        (["stagger", "--systems", "4", "--dt", "0.3"], ["--json", "--csv", "--table"], []),
        (["compress", "--runs", "1"], ["--json", "--plot"], []),
        (["bench", "--outer", "4", "--seconds", "0.01"], ["--json"], []),
    ]


def digest(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def prepare(work, dlpverify, source):
    shutil.copy(os.path.join(source, "examples/tableaux/rk4.toml"), "t.toml")
    shutil.copy(os.path.join(source, "examples/external/python/midpoint.py"), "prog.py")
    os.chmod("prog.py", 0o755)
    open("conv.toml", "w").write('case = "drag"\nouter = 4\nlevels = 2\n')
    open("check.toml", "w").write('case = "drag"\nouter = 4\nlevels = 2\nexpect-order = 2\n')
    open("prec.toml", "w").write('case = "drag"\nouter = 4\nlevels = 2\nrtol-max = 1e-4\nrtol-min = 1e-5\n')
    for r in ("r1.csv", "r2.csv", "r3.csv"):
        open(r, "w").write("x,v\n0.5,1.0\n")
    for name in ("b.json", "b2.json"):
        subprocess.run([dlpverify, "converge", "--case", "drag", "--outer", "4", "--levels", "2", "--json", name],
                       stdout=subprocess.DEVNULL, check=True)
    os.mkfifo("fifo")
    os.mkdir("folder")
    os.mkdir("readonly")
    os.chmod("readonly", 0o555)
    os.symlink(f"/nonexistent-dlpverify-{os.getpid()}/dir/file.png", "dangling.png")
    for name in os.listdir("."):
        if os.path.isfile(name) and not os.path.islink(name):
            os.chmod(name, 0o644 if name != "prog.py" else 0o755)
    os.chmod(work, 0o755)


def targets(outputs, option, inputs):
    """(what, extra arguments, expected exit) for one output option."""
    name = "out.png" if option in FIGURES else "out.json"
    found = []
    if inputs:
        found.append(("an input", [option, "./" + inputs[-1]], 2))
    others = [o for o in outputs if o != option]
    if others:
        found.append(("another output by another spelling", [option, name, others[0], "./" + name], 2))
    found += [("a link into a missing folder", [option, "dangling.png"], 2),
              ("a FIFO", [option, "fifo"], 2),
              ("a folder", [option, "folder"], 2),
              ("a read-only folder", [option, "readonly/" + name], 4)]
    return found


def main(dlpverify, source):
    dlpverify = os.path.realpath(dlpverify)
    work = tempfile.mkdtemp()
    os.chdir(work)
    failures, runs = [], 0
    try:
        prepare(work, dlpverify, source)
        before = {n: digest(n) for n in os.listdir(".") if os.path.isfile(n) and not os.path.islink(n) and n != "fifo"}
        nobody = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"] if os.geteuid() == 0 else []
        for arguments, outputs, inputs in commands(source):
            for option in outputs:
                for what, extra, expected in targets(outputs, option, inputs):
                    prefix = nobody if expected == 4 else []
                    run = subprocess.run(prefix + [dlpverify] + arguments + extra, capture_output=True, text=True, timeout=120)
                    runs += 1
                    said = run.stderr.strip()
                    where = f"{arguments[0]} {option} into {what}"
                    if run.returncode != expected:
                        failures.append(f"{where}: exit {run.returncode}, expected {expected}: {said[:200]}")
                    elif len(said.splitlines()) != 1 or option not in said and not (option == "-o" and "--output" in said):
                        failures.append(f"{where}: the refusal is not one line naming {option}: {said[:200]}")
                    elif run.stdout:
                        failures.append(f"{where}: output on stdout, so the run went on")
                    changed = [n for n, d in before.items() if not os.path.isfile(n) or digest(n) != d]
                    if changed:
                        failures.append(f"{where}: changed {changed}")
                        before = {n: digest(n) for n in before if os.path.isfile(n)}
                    if not stat.S_ISFIFO(os.lstat("fifo").st_mode) or os.listdir("folder") or os.listdir("readonly"):
                        failures.append(f"{where}: the FIFO, the folder or the read-only folder changed")
                    extras = set(os.listdir(".")) - set(before) - {"fifo", "folder", "readonly", "dangling.png"}
                    if extras:
                        failures.append(f"{where}: wrote {sorted(extras)}")
                        for e in extras:
                            shutil.rmtree(e) if os.path.isdir(e) and not os.path.islink(e) else os.remove(e)
        if os.path.exists(f"/nonexistent-dlpverify-{os.getpid()}"):
            failures.append("a folder was made through the dangling link")
    finally:
        os.chmod(os.path.join(work, "readonly"), 0o755)
        shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    print(f"{runs} runs, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
