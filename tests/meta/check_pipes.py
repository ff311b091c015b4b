#!/usr/bin/env python3
"""Every test keeps the exit status of the command it tests.

In a pipeline `dlpverify … | grep …` the shell reports the status of the last command only, so a
crash after the matching line passes unless the script sets `pipefail` (or reads PIPESTATUS).
Under pipefail a reader that stops early (`grep -q`, `grep -m`, `head`) makes the writer's SIGPIPE
a failure that depends on timing; such a test reads the output into a variable or a file first.

Rules, over every shell script under tests/ and every `bash -c "…"` in the tests' CMake files:
  1. a script or command holding a pipe sets pipefail (or reads PIPESTATUS);
  2. no pipe feeds a reader that stops early.
Heredoc bodies (Python, TOML) and quoted text are not shell and are skipped; a `case` pattern's
`a|b)` is not a pipe.

usage: check_pipes.py TESTS_DIR   (exit 1 with one line per finding, 0 when clean)
       check_pipes.py --self-test
"""
import pathlib
import re
import sys

HEREDOC = re.compile(r"<<-?\s*(['\"]?)([A-Za-z_][A-Za-z0-9_]*)\1")
CASE_PATTERN = re.compile(r"(^\s*|\bin\s+|;;\s*)\(?\s*[^\s()|;]*(\s*\|\s*[^\s()|;]*)+\s*\)")
# `head -c -N` prints all but the last N bytes: it reads to the end.
EARLY_READER = re.compile(r"^\s*(grep\s+(-[A-Za-z]*[qm]|--quiet|--max-count)|head\b(?!\s+-c\s+-))")


def shell_lines(text):
    """The script's lines with heredoc bodies removed (their opening line kept)."""
    lines, out, i = text.splitlines(), [], 0
    while i < len(lines):
        out.append((i + 1, lines[i]))
        ends = [m.group(2) for m in HEREDOC.finditer(lines[i])]
        i += 1
        for end in ends:
            while i < len(lines) and lines[i].strip() != end:
                i += 1
            i += 1
    return out


def unquoted(text):
    """The text with quoted text and comments blanked (newlines kept, a quote may span lines), so
    only the shell's own syntax is left."""
    out, quote, comment, i = [], None, False, 0
    while i < len(text):
        c = text[i]
        if c == "\n":
            comment = False
            out.append(c)
        elif comment:
            out.append(" ")
        elif quote:
            if c == "\\" and quote == '"':
                out.append(" " + ("\n" if text[i + 1:i + 2] == "\n" else " "))
                i += 2
                continue
            if c == quote:
                quote = None
            out.append(" ")
        elif c in "'\"":
            quote = c
            out.append(" ")
        elif c == "\\":  # an escaped character; a line continuation keeps its newline
            out.append(" " + ("\n" if text[i + 1:i + 2] == "\n" else " "))
            i += 1
        elif c == "#" and (i == 0 or text[i - 1] in " \t;\n"):
            comment = True
            out.append(" ")
        else:
            out.append(c)
        i += 1
    return "".join(out)


def pipes(code):
    """The text after each pipe `|` (not `||`) of one line of unquoted shell, case patterns removed."""
    code = CASE_PATTERN.sub(" ", code)
    return [code[m.end():] for m in re.finditer(r"(?<!\|)\|(?!\|)&?", code)]


def findings(name, text):
    """Each lost status in one script (or one bash -c command) TEXT."""
    keeps_status = re.search(r"pipefail|PIPESTATUS", text) is not None
    code = unquoted("\n".join(line for _, line in shell_lines(text)))
    numbers = [number for number, _ in shell_lines(text)]
    for number, line, shown in zip(numbers, code.splitlines(), [l for _, l in shell_lines(text)]):
        after = pipes(line)
        if after and not keeps_status:
            yield f"{name}:{number}: pipes without pipefail or PIPESTATUS: {shown.strip()[:120]}"
        for tail in after:
            if EARLY_READER.match(tail):
                yield f"{name}:{number}: pipes into a reader that stops early ({tail.split()[0]}…); read the output first: {shown.strip()[:120]}"


def cmake_commands(text):
    """Each `bash -c "…"` of a CMake file: (line number, the command as bash reads it)."""
    for m in re.finditer(r'bash\s+-c\s+"((?:[^"\\]|\\.)*)"', text):
        body = re.sub(r'\\(["$\\])', r"\1", m.group(1))
        yield text.count("\n", 0, m.start()) + 1, body


def self_test():
    """The checker finds each kind of lost status in a small tree of its own, and passes the good forms."""
    import tempfile
    bad = {
        "cli/a.sh": "set -u\n\"$bin\" check | grep 'FAIL'\n",
        "cli/b.sh": "set -euo pipefail\nout=$(\"$bin\" check | head -1)\n",
        "cli/c.cmake": 'add_test(NAME x COMMAND bash -c "$<TARGET_FILE:d> check | grep -c ok")\n',
    }
    good = {
        "cli/d.sh": "set -euo pipefail\ncase $m in a|b) x ;; Z | \"\") y ;; esac\npython3 - <<'EOF'\nprint(1 | 2)\nEOF\n"
                    "grep -q 'a|b' f\nprintf x | head -c -1 >f\n",
        "cli/e.cmake": 'add_test(NAME y COMMAND bash -c "set -o pipefail; $<TARGET_FILE:d> a | grep ok >/dev/null || true")\n',
    }
    with tempfile.TemporaryDirectory() as d:
        for name, text in {**bad, **good}.items():
            path = pathlib.Path(d, "tests", name)
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        found = list(scan(pathlib.Path(d, "tests")))
    files = sorted({line.split(":")[0] for line in found})
    assert files == ["tests/cli/a.sh", "tests/cli/b.sh", "tests/cli/c.cmake"], found
    assert len(found) == 3, found
    print("self-test: a pipe without pipefail, a reader that stops early and a bare bash -c pipe are found;"
          " case patterns, heredocs, quoted bars and head -c -N are not")
    return 0


def scan(root):
    """Every finding under the tests folder ROOT."""
    found = []
    for script in sorted(root.rglob("*.sh")):
        text = script.read_text()
        found += findings(script.relative_to(root.parent), text)
    for cmake in sorted(list(root.rglob("*.cmake")) + list(root.rglob("CMakeLists.txt"))):
        for number, body in cmake_commands(cmake.read_text()):
            for line in findings(cmake.relative_to(root.parent), body):
                found.append(re.sub(r":\d+:", f":{number}:", line, count=1))
    return found


def main(tests):
    found = scan(pathlib.Path(tests))
    for line in found:
        print(line)
    print(f"{len(found)} pipes that lose a status" if found else "every pipe keeps its status")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(self_test() if sys.argv[1:] == ["--self-test"] else main(sys.argv[1]))
