#!/usr/bin/python3
"""docs/cli.md against the program's own --help: the same commands, the same options, the same defaults.

Usage: help_vs_cli.py DLPVERIFY CLI_MD

The --help side is CLI11's text (one option a line, two spaces in: "  -o,--output TEXT REQUIRED",
"  --case TEXT=drag"; a default is the "=VALUE" after the type). The cli.md side follows the
convention docs/cli.md states in its last section:
  - "### dlpverify" holds the options of the program itself, "### dlpverify COMMAND" those of one
    command; "### Options: GROUP" a group that several commands share;
  - options are the rows of a Markdown table whose first cell names them in backticks
    (`--case NAME`, `-o`, `--output FILE`) and whose last cell is the default;
  - a line "Options also: [..](#options-group), [..](#dlpverify-command)" in a command's section adds
    every option of the sections it links to;
  - -h, --help is in every command and in no table.
Fails, listing every difference, when a command of `dlpverify --help` has no section (or a section
names no command), when a command's --help lists an option its section does not (or the reverse),
when a default of --help is not in the option's default cell, or when a usage line does not name
the program ("Usage: dlpverify [OPTIONS] SUBCOMMAND", "Usage: dlpverify COMMAND [OPTIONS]").
"""
import re
import subprocess
import sys

HELP = {"-h", "--help"}
NAME = re.compile(r"(?<![\w-])(--?[A-Za-z][\w-]*)")


def run_help(dlpverify, *command):
    done = subprocess.run([dlpverify, *command, "--help"], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(['dlpverify', *command, '--help'])} exited {done.returncode}: {done.stderr}")
    return done.stdout


def help_options(text):
    """{option name: default or None} and the usage line of one CLI11 help text."""
    options, usage = {}, None
    for line in text.splitlines():
        if line.startswith("Usage:"):
            usage = line
        m = re.match(r"^  (-[^\s]+)(?:\s+(\S+))?", line)
        if not m:
            continue
        default = None
        if m.group(2):
            d = re.match(r"^[A-Z]+=(\S+)$", m.group(2))
            default = d.group(1) if d else None
        for name in m.group(1).split(","):
            if name not in HELP:
                options[name] = default
    return options, usage


def help_subcommands(text):
    names, inside = [], False
    for line in text.splitlines():
        if line.rstrip() == "Subcommands:":
            inside = True
        elif inside and re.match(r"^  \S", line):
            names.append(line.split()[0])
        elif inside and line.strip() and not line.startswith(" "):
            inside = False
    return names


def anchor(heading):
    """GitHub's anchor of a heading: lower case, punctuation but '-' and '_' dropped, spaces to '-'."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def markdown_sections(path):
    """{anchor: (heading, {option: default cell}, [included anchors])} for every ### section."""
    sections, current = {}, None
    in_code = also = False  # also: inside an "Options also:" paragraph, which may run over lines
    for line in open(path, encoding="utf-8"):
        line = line.rstrip("\n")
        if line.startswith("```"):
            in_code = not in_code
            continue
        if in_code:
            continue
        h = re.match(r"^(#{1,6})\s+(.*)$", line)
        if h:
            current, also = None, False
            if len(h.group(1)) == 3:
                heading = h.group(2).strip().replace("`", "")
                current = sections.setdefault(anchor(heading), (heading, {}, []))
            continue
        if current is None:
            continue
        if line.startswith("Options also:") or (also and line.strip()):
            current[2].extend(re.findall(r"\]\(#([^)]+)\)", line))
            also = True
            continue
        also = False
        if line.startswith("|") and not re.match(r"^\|[\s:|-]+\|?$", line):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            code = " ".join(re.findall(r"`([^`]*)`", cells[0]))
            names = [n for n in NAME.findall(code)]
            for name in names:
                if name in current[1]:
                    print(f"FAIL: cli.md section '{current[0]}' lists {name} twice")
                    markdown_sections.twice = True
                current[1][name] = cells[-1] if len(cells) > 1 else ""
    return sections


markdown_sections.twice = False


def documented(sections, key, seen=()):
    """Every option of section `key` with its default cell, following "Options also:" links."""
    heading, options, includes = sections[key]
    merged = dict(options)
    for included in includes:
        if included in seen or included not in sections:
            if included not in sections:
                print(f"FAIL: cli.md section '{heading}' includes #{included}, which is no ### section")
                documented.broken = True
            continue
        for name, cell in documented(sections, included, seen + (key,)).items():
            merged.setdefault(name, cell)
    return merged


documented.broken = False


def default_in_cell(default, cell):
    """The cell names the default: as a code span or a word of its own."""
    spans = re.findall(r"`([^`]*)`", cell)
    return default in spans or re.search(r"(?<![\w.+-])" + re.escape(default) + r"(?![\w.+-])", cell) is not None


def main():
    dlpverify, cli_md = sys.argv[1], sys.argv[2]
    failures = []
    sections = markdown_sections(cli_md)

    top = run_help(dlpverify)
    _, usage = help_options(top)
    if usage != "Usage: dlpverify [OPTIONS] SUBCOMMAND":
        failures.append(f"the program's usage line is {usage!r}, not 'Usage: dlpverify [OPTIONS] SUBCOMMAND'")
    commands = help_subcommands(top)
    if not commands:
        failures.append("dlpverify --help lists no subcommand")

    expected = {"dlpverify": ((), top)}
    for command in commands:
        expected["dlpverify-" + command] = ((command,), run_help(dlpverify, command))
    for key, (heading, _, _) in sections.items():
        if heading.startswith("dlpverify") and key not in expected:
            failures.append(f"cli.md has a section '{heading}', but dlpverify --help lists no such command")

    for key, (command, text) in expected.items():
        title = " ".join(("dlpverify",) + command)
        options, usage = help_options(text)
        if command and not (usage or "").startswith(f"Usage: {title} [OPTIONS]"):
            failures.append(f"{title} --help: usage line {usage!r} does not start with 'Usage: {title} [OPTIONS]'")
        if key not in sections:
            failures.append(f"cli.md has no section '### {title}'")
            continue
        docs = documented(sections, key)
        for name in sorted(set(options) - set(docs)):
            failures.append(f"{title} --help lists {name}, cli.md's section does not")
        for name in sorted(set(docs) - set(options)):
            failures.append(f"cli.md lists {name} for {title}, its --help does not")
        for name in sorted(set(options) & set(docs)):
            if options[name] is not None and not default_in_cell(options[name], docs[name]):
                failures.append(f"{title} {name}: --help's default {options[name]} is not in cli.md's cell {docs[name]!r}")
        print(f"{title}: {len(options)} options in --help, {len(docs)} in cli.md")

    if documented.broken or markdown_sections.twice:
        failures.append("cli.md's sections are malformed (above)")
    for f in failures:
        print("FAIL:", f)
    if failures:
        sys.exit(1)
    print(f"PASS: {len(expected)} help texts (the program and {len(commands)} commands) match docs/cli.md")


if __name__ == "__main__":
    main()
