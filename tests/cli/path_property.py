#!/usr/bin/env python3
"""No output path can harm what the user has: a property over every command that writes a file.

For every command x every output option x every target below, the run is refused before any
work: exit 2 (bad input: an input of the run, another output under another spelling, the run's
own journal FILE.journal.jsonl beside --json, a link to another study's journal — or, for
--json, a journal's place that is one —, a link into a folder that does not exist, a FIFO, a
character device, a folder, standard output named twice) or 4 (a file in a read-only folder,
tried as the unprivileged user nobody when the test runs as root), one line on stderr naming the
option, nothing on standard output, and afterwards every file and node of the working folder is
what it was, byte for byte, and nothing was added, inside it or through the dangling link.
/dev/null, which discards, has its own test (cli.output-devnull, in a private /dev). docs/cli.md,
"What a path may name".

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
JOURNAL = ".journal.jsonl"
# Another study's journal, as a stopped study leaves it: its header and one finished level.
THEIR_JOURNAL = "other/theirs.json" + JOURNAL


def commands():
    """(command's arguments, its output options, its input files, whether --json keeps a journal)."""
    study = ["--json", "--csv", "--table", "--plot", "--history", "--per-particle"]
    return [
        (["converge", "--config", "conv.toml", "--integrator", "tableau:t.toml"], study, ["conv.toml", "t.toml"], True),
        (["converge", "--config", "conv.toml", "--reference", "integrator:tableau:t.toml@1e-4"], study,
         ["conv.toml", "t.toml"], True),
        (["check", "--config", "check.toml", "--baseline", "b.json"], study + ["--junit", "--html", "--summary"],
         ["check.toml", "b.json"], True),
        (["converge", "--case", "drag", "--outer", "4", "--levels", "2",
          "--integrator", "exec:python3 prog.py {input} {output}"], ["--json", "--csv"], ["prog.py"], True),
        (["precision", "--config", "prec.toml"], ["--json", "--csv", "--table", "--plot"], ["prec.toml"], True),
        (["analyze", "r1.csv", "r2.csv", "r3.csv", "--dt", "1e-3", "--dt", "5e-4", "--dt", "2.5e-4", "--t-end", "1", "--expect-order", "1"],
         ["--json", "--csv", "--table", "--plot", "--junit", "--html"], ["r1.csv", "r2.csv", "r3.csv"], False),
        (["suite", "s1.toml", "s2.toml"], ["--json", "--junit", "--html", "--summary", "--table"], ["s1.toml", "s2.toml"], True),
        (["tableau", "t.toml"], ["--json", "--plot"], ["t.toml"], False),
        (["sharpness", "--integrator", "tableau:t.toml", "--case", "drag", "--outer", "4"], ["--json"], ["t.toml"], False),
        (["plot", "b.json"], ["-o"], ["b.json"], False),
        (["compare", "b.json", "b2.json"], ["--json"], ["b.json", "b2.json"], False),
        (["audit"], ["--json"], [], False),
        (["stagger", "--systems", "4", "--dt", "0.3"], ["--json", "--csv", "--table"], [], False),
        (["compress", "--runs", "1"], ["--json", "--plot"], [], False),
        (["bench", "--outer", "4", "--seconds", "0.01"], ["--json"], [], False),
    ]


def snapshot(root):
    """Every entry below root: its type and its bytes (a file), target (a link) or device number."""
    found = {}
    for folder, dirs, files in os.walk(root):
        for name in dirs + files:
            path = os.path.join(folder, name)
            st = os.lstat(path)
            if stat.S_ISREG(st.st_mode):
                what = hashlib.sha256(open(path, "rb").read()).hexdigest()
            elif stat.S_ISLNK(st.st_mode):
                what = os.readlink(path)
            else:
                what = st.st_rdev
            found[os.path.relpath(path, root)] = (stat.S_IFMT(st.st_mode), what)
    return found


def prepare(work, dlpverify, source):
    shutil.copy(os.path.join(source, "examples/tableaux/rk4.toml"), "t.toml")
    shutil.copy(os.path.join(source, "examples/external/python/midpoint.py"), "prog.py")
    open("conv.toml", "w").write('case = "drag"\nouter = 4\nlevels = 2\n')
    open("check.toml", "w").write('case = "drag"\nouter = 4\nlevels = 2\nexpect-order = 2\n')
    for name in ("s1.toml", "s2.toml"):
        shutil.copy("check.toml", name)
    open("prec.toml", "w").write('case = "drag"\nouter = 4\nlevels = 2\nrtol-max = 1e-4\nrtol-min = 1e-5\n')
    for r in ("r1.csv", "r2.csv", "r3.csv"):
        open(r, "w").write("x,v\n0.5,1.0\n")
    for name in ("b.json", "b2.json"):
        subprocess.run([dlpverify, "converge", "--case", "drag", "--outer", "4", "--levels", "2", "--json", name],
                       stdout=subprocess.DEVNULL, check=True)
    os.mkdir("other")
    open(THEIR_JOURNAL, "w").write('{"dlpverify_journal": 1, "command": "converge", "options": {}, "study": {}, "build": {}}\n'
                                   '{"level": 0}\n')
    for ending in (".json", ".png"):  # .png: a figure option checks the ending first
        os.symlink(THEIR_JOURNAL, "their-journal" + ending)
    os.symlink("../" + THEIR_JOURNAL, "other/x.json" + JOURNAL)  # --json other/x.json: its journal's place
    # A figure's name cannot end in .journal.jsonl: it reaches the run's own journal, not made yet, by a link.
    os.symlink("out.json" + JOURNAL, "own-journal.png")
    os.mkfifo("fifo")
    # A device of the test's own as root (a regression would replace it, not the machine's /dev/full);
    # a root that may not make one leaves the device out rather than risk the machine's.
    if os.geteuid() != 0:
        os.symlink("/dev/full", "device.png")
    else:
        try:
            os.mknod("device.png", 0o644 | stat.S_IFCHR, os.makedev(1, 7))
        except OSError as e:
            print(f"note: no character device can be made here ({e}): the device is left out")
    os.mkdir("folder")
    os.mkdir("readonly")
    os.symlink(f"/nonexistent-dlpverify-{os.getpid()}/dir/file.png", "dangling.png")
    for name in os.listdir("."):
        if os.path.isfile(name) and not os.path.islink(name):
            os.chmod(name, 0o644)
    os.chmod("readonly", 0o555)
    os.chmod(work, 0o755)


def targets(outputs, option, inputs, journaled):
    """(what, extra arguments, expected exit, the options one of which the line names) for one output option."""
    name = "out.png" if option in FIGURES else "out.json"
    named = [option]
    found = []
    if inputs:
        found.append(("an input", [option, "./" + inputs[-1]], 2, named))
    others = [o for o in outputs if o != option]
    if others:
        found.append(("another output by another spelling", [option, name, others[0], "./" + name], 2, named))
    if journaled and option != "--json":
        own = "own-journal.png" if option in FIGURES else "./out.json" + JOURNAL
        found.append(("the run's own journal", ["--json", "out.json", option, own], 2, named))
    found.append(("a link to another study's journal", [option, "their-journal" + (".png" if option in FIGURES else ".json")],
                  2, named))
    if journaled and option == "--json":
        found.append(("a journal's place that is a link to another study's journal", [option, "other/x.json"], 2, named))
    found += [("a link into a missing folder", [option, "dangling.png"], 2, named),
              ("a FIFO", [option, "fifo"], 2, named)]
    if os.path.lexists("device.png"):
        found.append(("a device", [option, "device.png"], 2, named))
    found += [("a folder", [option, "folder"], 2, named), ("a read-only folder", [option, "readonly/" + name], 4, named)]
    if others:
        found.append(("standard output twice", [others[0], "-", option, "-"], 2, [option, others[0]]))
    return found


def main(dlpverify, source):
    dlpverify = os.path.realpath(dlpverify)
    source = os.path.realpath(source)
    work = tempfile.mkdtemp()
    os.chdir(work)
    failures, runs = [], 0
    try:
        prepare(work, dlpverify, source)
        before = snapshot(work)
        nobody = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"] if os.geteuid() == 0 else []
        for arguments, outputs, inputs, journaled in commands():
            for option in outputs:
                for what, extra, expected, named in targets(outputs, option, inputs, journaled):
                    prefix = nobody if expected == 4 else []
                    run = subprocess.run(prefix + [dlpverify] + arguments + extra, capture_output=True, timeout=120)
                    runs += 1
                    said = run.stderr.decode("utf-8", "replace").strip()
                    where = f"{arguments[0]} {option} into {what}"
                    names = any(o in said or o == "-o" and "--output" in said for o in named)
                    if run.returncode != expected:
                        failures.append(f"{where}: exit {run.returncode}, expected {expected}: {said[:300]}")
                    elif len(said.splitlines()) != 1 or not names:
                        failures.append(f"{where}: the refusal is not one line naming {' or '.join(named)}: {said[:300]}")
                    elif run.stdout:
                        failures.append(f"{where}: output on stdout, so the run went on")
                    after = snapshot(work)
                    if after != before:
                        changed = sorted(n for n in before if after.get(n) != before[n])
                        added = sorted(set(after) - set(before))
                        failures.append(f"{where}: changed {changed}, added {added}")
                        for n in sorted(added, reverse=True):  # deepest first
                            p = os.path.join(work, n)
                            shutil.rmtree(p) if os.path.isdir(p) and not os.path.islink(p) else os.remove(p)
                        before = snapshot(work)
        if os.path.lexists(f"/nonexistent-dlpverify-{os.getpid()}"):
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
