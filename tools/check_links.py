#!/usr/bin/env python3
"""Check the links of the project's documentation (python3 standard library only).

    tools/check_links.py [--root DIR] [--max-readme-lines N]

Reads README.md, CHANGELOG.md and every docs/**/*.md and checks that

- every relative link [text](path#anchor) names a file or directory that exists,
  relative to the file that holds the link;
- every #anchor names a heading of the target file (GitHub's slug of the heading:
  lower case, punctuation dropped, spaces to hyphens, -1, -2 ... for repeats) or an
  explicit <a name="..."> / id="...";
- every repository path quoted as code (`docs/user/namelist.md`, `bench/peer/fluid.md`)
  exists (paths under results/, build/, sweeps/ and ones with wildcards are skipped);
- no link or path points outside the repository (an absolute path, ../shared/, PHYSICS.md);
- no heading carries "(issue N)";
- README.md has at most N lines (300).

Links inside fenced code blocks and inline code are not links. Exit 0 when all hold,
1 with one line per problem (file:line: what) otherwise.
"""
import argparse
import os
import re
import sys
import unicodedata

LINK = re.compile(r'!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+"[^"]*")?\s*\)')
REFDEF = re.compile(r'^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$')
HEADING = re.compile(r'^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$')
HTML_ANCHOR = re.compile(r'<a\s+[^>]*(?:name|id)\s*=\s*"([^"]+)"', re.I)
CODE_SPAN = re.compile(r'(`+)(.+?)\1')
FENCE = re.compile(r'^\s{0,3}(`{3,}|~{3,})')
ISSUE_TITLE = re.compile(r'\(issues?\s+\d+', re.I)
REPO_DIRS = ('docs/', 'bench/', 'src/', 'input/', 'tools/', 'test/', 'plots/', 'batch/',
             'example/', 'mk/', 'app/')
PATH_EXT = re.compile(r'\.(md|py|sh|f90|gp|nml|txt|csv|tsv|dat|png|json|toml|mk|sbatch)$')
FORBIDDEN = (('PHYSICS.md', 'a file outside the repository'),
             ('/work/', 'an absolute path of the development machine'),
             ('../shared/', 'a path outside the repository'))


def slug(text):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r'!?\[([^\]]*)\]\([^)]*\)', r'\1', text)    # a link: its text
    text = re.sub(r'<[^>]+>', '', text)                        # inline HTML
    text = text.replace('`', '')
    text = text.strip().lower()
    out = []
    for ch in text:
        cat = unicodedata.category(ch)
        if ch in ' -_' or cat[0] in 'LN':
            out.append('-' if ch == ' ' else ch)
        # other punctuation and symbols are dropped
    return ''.join(out)


def strip_code(line):
    return CODE_SPAN.sub(lambda m: ' ' * len(m.group(0)), line)


def scan(path):
    """(links with line numbers, code spans with line numbers, anchors, headings) of a file."""
    links, spans, anchors, headings = [], [], set(), []
    counts = {}
    fence = None
    with open(path, encoding='utf-8') as f:
        for no, line in enumerate(f, 1):
            m = FENCE.match(line)
            if fence:
                if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence):
                    fence = None
                continue
            if m:
                fence = m.group(1)
                continue
            for a in HTML_ANCHOR.findall(line):
                anchors.add(a)
            h = HEADING.match(line)
            if h:
                s = slug(h.group(2))
                n = counts.get(s, 0)
                counts[s] = n + 1
                anchors.add(s if n == 0 else f'{s}-{n}')
                headings.append((no, h.group(2)))
            for cm in CODE_SPAN.finditer(line):
                spans.append((no, cm.group(2).strip()))
            bare = strip_code(line)
            for lm in LINK.finditer(bare):
                links.append((no, lm.group(1)))
            r = REFDEF.match(bare)
            if r:
                links.append((no, r.group(1)))
    return links, spans, anchors, headings


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--root', default=os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
    ap.add_argument('--max-readme-lines', type=int, default=300)
    args = ap.parse_args()
    root = os.path.realpath(args.root)

    files = [p for p in ('README.md', 'CHANGELOG.md') if os.path.isfile(os.path.join(root, p))]
    for d, _, names in os.walk(os.path.join(root, 'docs')):
        files += [os.path.relpath(os.path.join(d, n), root) for n in sorted(names) if n.endswith('.md')]
    files.sort()

    cache = {}

    def info(rel):
        if rel not in cache:
            cache[rel] = scan(os.path.join(root, rel))
        return cache[rel]

    problems = []
    nlinks = 0
    for rel in files:
        links, spans, anchors, headings = info(rel)
        here = os.path.dirname(rel)
        for no, text in headings:
            if ISSUE_TITLE.search(text):
                problems.append(f'{rel}:{no}: heading names an issue: "{text}"')
        with open(os.path.join(root, rel), encoding='utf-8') as f:
            for no, line in enumerate(f, 1):
                for bad, why in FORBIDDEN:
                    if bad in line:
                        problems.append(f'{rel}:{no}: mentions {bad} ({why})')
        for no, target in links:
            nlinks += 1
            if re.match(r'^[a-z][a-z0-9+.-]*:', target, re.I):     # http:, https:, mailto:
                continue
            path, _, anchor = target.partition('#')
            if path.startswith('/'):
                problems.append(f'{rel}:{no}: absolute link {target}')
                continue
            dest = os.path.normpath(os.path.join(here, path)) if path else rel
            full = os.path.join(root, dest)
            if not os.path.realpath(full).startswith(root + os.sep) and os.path.realpath(full) != root:
                problems.append(f'{rel}:{no}: link leaves the repository: {target}')
                continue
            if not os.path.exists(full):
                problems.append(f'{rel}:{no}: no such file: {target}')
                continue
            if anchor:
                if not dest.endswith('.md') or not os.path.isfile(full):
                    continue          # anchors into other kinds of file are not checked
                if anchor not in info(dest)[2]:
                    problems.append(f'{rel}:{no}: no heading #{anchor} in {dest}')
        for no, span in spans:
            p = span.split()[0] if span.split() else ''
            p = p.rstrip('.,:;')
            if not p.startswith(REPO_DIRS) or not PATH_EXT.search(p) or re.search(r'[<>*{}$\[\]]', p):
                continue
            if not os.path.exists(os.path.join(root, p)):
                problems.append(f'{rel}:{no}: no such file in the repository: `{p}`')

    readme = os.path.join(root, 'README.md')
    if os.path.isfile(readme):
        with open(readme, encoding='utf-8') as f:
            n = sum(1 for _ in f)
        if n > args.max_readme_lines:
            problems.append(f'README.md: {n} lines, more than {args.max_readme_lines}')

    for p in problems:
        print(p)
    if problems:
        print(f'check_links: {len(problems)} problem(s) in {len(files)} files', file=sys.stderr)
        return 1
    print(f'check_links: {len(files)} files, {nlinks} links, all resolve; README.md within '
          f'{args.max_readme_lines} lines')
    return 0


if __name__ == '__main__':
    sys.exit(main())
