#!/usr/bin/python3
"""Every relative link in README.md and docs/*.md must point at something.

A link [text](target) or image ![alt](target) whose target is not a URL names a file relative
to the page that holds it (it must exist in the source tree) and optionally a #fragment, which
must be the GitHub slug of a heading of that file (of the page itself for a bare #fragment).
GitHub's slug: the heading's text, lower-cased, every character that is not a letter, digit,
space, hyphen or underscore removed, each space made a hyphen; a repeated slug gets -1, -2, ...
Links inside fenced code blocks and inline code are not links and are skipped.

Usage: check_links.py SOURCE_DIR          exit 0 when every link resolves, 1 otherwise
       check_links.py --self-test         a page with a broken file link and a broken anchor
                                          must be reported (exit 0 when both are found)
"""
import os
import re
import sys
import tempfile

LINK = re.compile(r'!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)')
FENCE = re.compile(r'^\s*(```|~~~)')
HEADING = re.compile(r'^(#{1,6})\s+(.*?)\s*#*\s*$')
INLINE_CODE = re.compile(r'(`+)(.+?)\1')


def prose_lines(path):
    """Yields (line number, text) outside fenced code blocks."""
    fence = None
    with open(path, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            m = FENCE.match(line)
            if m:
                if fence is None:
                    fence = m.group(1)
                elif m.group(1) == fence:
                    fence = None
                continue
            if fence is None:
                yield number, line.rstrip('\n')


def slug(heading):
    text = INLINE_CODE.sub(lambda m: m.group(2), heading)
    text = re.sub(r'!?\[([^\]]*)\]\([^)]*\)', r'\1', text)   # a link in a heading: its text
    text = re.sub(r'<[^>]+>', '', text).strip().lower()
    text = ''.join(c for c in text if c.isalnum() or c in ' -_')
    return text.replace(' ', '-')


def anchors(path):
    seen = {}
    result = set()
    for _, line in prose_lines(path):
        m = HEADING.match(line)
        if not m:
            continue
        base = slug(m.group(2))
        count = seen.get(base, 0)
        seen[base] = count + 1
        result.add(base if count == 0 else f'{base}-{count}')
    return result


def broken_links(root, pages):
    problems = []
    cache = {}
    for page in pages:
        page_path = os.path.join(root, page)
        for number, line in prose_lines(page_path):
            for m in LINK.finditer(INLINE_CODE.sub('', line)):
                target = m.group(1)
                if re.match(r'^[a-zA-Z][a-zA-Z0-9+.-]*:', target):   # http:, https:, mailto:
                    continue
                file_part, _, fragment = target.partition('#')
                if file_part:
                    resolved = os.path.normpath(os.path.join(os.path.dirname(page_path), file_part))
                    if not os.path.exists(resolved):
                        problems.append(f'{page}:{number}: {target}: no file {file_part}')
                        continue
                else:
                    resolved = page_path
                if fragment:
                    if not resolved.endswith('.md') or os.path.isdir(resolved):
                        continue
                    if resolved not in cache:
                        cache[resolved] = anchors(resolved)
                    if fragment not in cache[resolved]:
                        problems.append(f'{page}:{number}: {target}: no heading #{fragment} in '
                                        f'{os.path.relpath(resolved, root)}')
    return problems


def pages_of(root):
    pages = ['README.md'] if os.path.exists(os.path.join(root, 'README.md')) else []
    docs = os.path.join(root, 'docs')
    if os.path.isdir(docs):
        pages += sorted(os.path.join('docs', n) for n in os.listdir(docs) if n.endswith('.md'))
    return pages


def self_test():
    with tempfile.TemporaryDirectory() as root:
        os.mkdir(os.path.join(root, 'docs'))
        with open(os.path.join(root, 'README.md'), 'w', encoding='utf-8') as f:
            f.write('# Top\n\n## The journal and `--resume`\n\n'
                    '[ok](docs/a.md) [ok](#the-journal-and---resume) [ok](docs/a.md#δt-levels)\n'
                    '[gone](docs/missing.md) [bad anchor](docs/a.md#no-such-heading)\n'
                    '```\n[in code](nowhere.md)\n```\n`[inline](nowhere.md)`\n')
        with open(os.path.join(root, 'docs', 'a.md'), 'w', encoding='utf-8') as f:
            f.write('# A\n\n## Δt levels\n\n[up](../README.md#top)\n')
        found = broken_links(root, pages_of(root))
        expected = ['README.md:6: docs/missing.md: no file docs/missing.md',
                    'README.md:6: docs/a.md#no-such-heading: no heading #no-such-heading in docs/a.md']
        if found != expected:
            print('self-test: expected', expected, 'found', found)
            return 1
        print('self-test: both broken links found, no false report')
        return 0


def main():
    if sys.argv[1:] == ['--self-test']:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    root = sys.argv[1]
    pages = pages_of(root)
    problems = broken_links(root, pages)
    for p in problems:
        print(p)
    print(f'{len(pages)} pages checked, {len(problems)} broken link(s)')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
