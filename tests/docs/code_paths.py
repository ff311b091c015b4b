#!/usr/bin/python3
"""Every source path the documentation and the code's comments name exists, so a file that moves
cannot leave a page or a comment pointing at where it was.

A path is a token such as src/references/cvode.cpp, include/dlpverify/study.hpp, tests/cli/,
verification/drag-rk2.toml or, inside src/, a short form such as harness/study.cpp or
families/family.hpp (resolved under src/ and include/, and beside the file that names it);
src/cli/command_line.{hpp,cpp} names both files.
Read are README.md, CONTRIBUTING.md, docs/*.md (outside fenced code blocks: those are commands
and outputs) and the comments of the sources, tests, scripts and CMake files (after // or #).
Patterns are skipped (a `*`, `NAME`, `…`); CHANGELOG.md names files as they were.

Usage: code_paths.py SOURCE_DIR     exit 0 when every named path exists, 1 otherwise
       code_paths.py --self-test    a page naming a missing file must be reported
"""
import os
import re
import sys
import tempfile

ROOTS = ('src', 'include', 'tests', 'verification', 'examples', 'bench', 'cmake', 'scripts', 'plots')
SHORT = ('harness', 'io', 'cli', 'case_study', 'study', 'references', 'families', 'problems', 'integrators', 'sundials',
         'exchange', 'plot', 'mpi', 'simd', 'dlpverify')
# Names shaped like paths that are none: a Boost.Test case, a user's own study file in an example.
# SUNDIALS' own source file.
NOT_PATHS = {'sundials/cvode_with_sundials_vector_operations_agrees', 'verification/our-rk2.toml',
             'src/nvector/serial/nvector_serial.c'}
COMMENT = {'.cpp': '//', '.hpp': '//', '.h': '//', '.c': '//', '.py': '#', '.sh': '#', '.cmake': '#', '.txt': '#',
           '.toml': '#', '.in': '#'}
TOKEN = re.compile(r'(?<![\w./-])((?:%s)/[\w./+-]*[\w/])' % '|'.join(ROOTS + SHORT))
FENCE = re.compile(r'^\s*(```|~~~)')


def paths_in(text):
    """The path tokens of one line of prose or comment."""
    for m in TOKEN.finditer(text):
        token, after = m.group(1), text[m.end():m.end() + 2]
        if re.search(r'[A-Z]{3,}', token) or re.match(r'-?[*…]', after) or token in NOT_PATHS:
            continue  # a pattern (src/problems/NAME/, verification/adiabat-*.toml) or no path
        braces = re.match(r'\.\{([\w,]+)\}', text[m.end():])
        if braces:  # src/cli/command_line.{hpp,cpp}: each file
            yield from (f'{token}.{ext}' for ext in braces.group(1).split(','))
        else:
            yield token


def named_paths(page):
    """(line, token) of a page's prose, or of a source file's comments."""
    mark = COMMENT.get(os.path.splitext(page)[1])
    fence = None
    with open(page, encoding='utf-8', errors='replace') as f:
        for number, line in enumerate(f, 1):
            if mark:
                at = line.find(mark)
                if at >= 0:
                    yield from ((number, token) for token in paths_in(line[at:]))
                continue
            m = FENCE.match(line)
            if m:
                fence = m.group(1) if fence is None else (None if m.group(1) == fence else fence)
                continue
            if fence is not None:
                continue
            yield from ((number, token) for token in paths_in(line))


def exists(source, token, page):
    token = token.rstrip('.')
    candidates = [os.path.join(source, token), os.path.join(os.path.dirname(page), token)]
    if token.split('/')[0] in SHORT:
        candidates += [os.path.join(source, 'src', token), os.path.join(source, 'include', token)]
    return any(os.path.exists(c) for c in candidates)


def pages(source):
    yield from (os.path.join(source, p) for p in ('README.md', 'CONTRIBUTING.md'))
    docs = os.path.join(source, 'docs')
    yield from sorted(os.path.join(docs, p) for p in os.listdir(docs) if p.endswith('.md'))
    for top in ('src', 'include', 'tests', 'verification', 'examples', 'bench', 'cmake', 'scripts'):
        for folder, _, files in sorted(os.walk(os.path.join(source, top))):
            yield from sorted(os.path.join(folder, f) for f in files if os.path.splitext(f)[1] in COMMENT)
    yield os.path.join(source, 'CMakeLists.txt')


def check(source, only=None):
    missing = []
    for page in only or pages(source):
        for number, token in named_paths(page):
            if not exists(source, token, page):
                missing.append(f'{os.path.relpath(page, source)}:{number}: {token} does not exist')
    return missing


def self_test():
    with tempfile.TemporaryDirectory() as source:
        os.makedirs(os.path.join(source, 'src', 'harness'))
        open(os.path.join(source, 'src', 'harness', 'study.cpp'), 'w').close()
        page = os.path.join(source, 'page.md')
        with open(page, 'w', encoding='utf-8') as f:
            f.write('The loop is harness/study.{cpp,hpp}; the reference is `src/sundials/reference.cpp`.\n'
                    '```\nbuild/dlpverify converge --json src/nowhere.json\n```\n'
                    'A new problem goes in src/problems/NAME/.\n')
        code = os.path.join(source, 'src', 'harness', 'study.cpp')
        with open(code, 'w', encoding='utf-8') as f:
            f.write('int loop;  // the loop; the journal is study/journal.hpp\n')
        missing = check(source, [page, code])
        ok = (len(missing) == 3 and 'harness/study.hpp' in missing[0] and 'src/sundials/reference.cpp' in missing[1]
              and 'study/journal.hpp' in missing[2])
        print('self-test:', 'ok' if ok else 'FAILED', missing)
        return 0 if ok else 1


if __name__ == '__main__':
    if sys.argv[1:] == ['--self-test']:
        sys.exit(self_test())
    missing = check(sys.argv[1])
    for line in missing:
        print(line)
    print(f'{len(missing)} missing' if missing else 'every named path exists')
    sys.exit(1 if missing else 0)
