#!/usr/bin/python3
"""Checks that the project's cross-references resolve, so that moving or renaming a section of the
documentation cannot leave a dangling pointer behind:

- every relative Markdown link in README.md and docs/*.md names an existing file and, with #anchor,
  an existing heading of a Markdown file (GitHub's anchors);
- every section cited as `NAME.md, "Title"` (or `NAME.md "Title"`, or a list `NAME.md, "A", "B"
  and "C"`), in the pages or in a source comment, exists in docs/NAME.md: a heading or a
  paragraph's bold lead whose title starts with the cited words (comments wrap long titles, so a
  citation may stop short).

Usage: check_references.py [ROOT]. Prints what does not resolve and exits 1 if anything does not."""
import os
import re
import sys
import unicodedata


def anchor_of(title):
    """GitHub's anchor for a heading: lower case; letters, marks, numbers, connectors (_), spaces and
    hyphens kept, the rest (punctuation, symbols such as ∆) dropped; spaces to hyphens."""
    kept = ''.join(c for c in title.strip().lower()
                   if c in ' -' or unicodedata.category(c)[0] in 'LMN' or unicodedata.category(c) == 'Pc')
    return kept.replace(' ', '-')


def squeeze(text):
    return ' '.join(text.replace('`', '').split())


class Page:
    """A Markdown page's section titles and heading anchors."""

    def __init__(self, path):
        self.titles, self.anchors, seen, fenced = [], set(), {}, False
        with open(path, encoding='utf-8') as f:
            for line in f:
                if line.startswith('```'):
                    fenced = not fenced
                if fenced:
                    continue
                heading = re.match(r'#{1,6} (.*)', line)
                if heading:
                    title = heading.group(1).strip()
                    base = anchor_of(title)
                    count = seen.get(base, 0)
                    seen[base] = count + 1
                    self.anchors.add(base if count == 0 else f'{base}-{count}')
                    self.titles.append(squeeze(title))
                    continue
                lead = re.match(r'(?:- )?\*\*([^*]+)\*\*', line)
                if lead:
                    self.titles.append(squeeze(lead.group(1)))

    def has_section(self, cited):
        cited = squeeze(cited)
        return any(title.startswith(cited) for title in self.titles)


def main(root):
    pages = {}

    def page(path):
        if path not in pages:
            pages[path] = Page(path)
        return pages[path]

    docs = [os.path.join(root, 'README.md')] + sorted(
        os.path.join(root, 'docs', n) for n in os.listdir(os.path.join(root, 'docs')) if n.endswith('.md'))
    sources = list(docs)
    for top in ('src', 'include', 'apps', 'bench', 'tests', 'python', 'scripts', 'fuzz', 'examples'):
        for dirpath, _, names in sorted(os.walk(os.path.join(root, top))):
            sources += [os.path.join(dirpath, n) for n in sorted(names)
                        if n.endswith(('.h', '.cpp', '.py', '.sh', '.cmake', '.txt'))]

    problems = []
    link = re.compile(r'\]\(([^)\s]+)\)')
    # The title may run on over a comment's next line ("//", "///", "#" and the indent dropped).
    citation = re.compile(r'\b([A-Za-z_-]+)\.md,?\s+\\?"([^"\\]+)')
    next_title = re.compile(r'\\?"?(?:,\s*|\s+and\s+|,\s+and\s+)\\?"([^"\\]+)"')
    for path in sources:
        with open(path, encoding='utf-8') as f:
            text = f.read()
        where = os.path.relpath(path, root)
        if path in docs:
            for target in link.findall(text):
                if re.match(r'[a-z]+:', target):
                    continue
                file_part, _, anchor = target.partition('#')
                full = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
                if not os.path.exists(full):
                    problems.append(f'{where}: link to a missing file: {target}')
                elif anchor and full.endswith('.md') and anchor not in page(full).anchors:
                    problems.append(f'{where}: link to a missing heading: {target}')
        joined = re.sub(r'\n\s*(?:///|//|#)?\s*', ' ', text)
        for match in citation.finditer(joined):
            doc = os.path.join(root, 'docs', match.group(1) + '.md')
            if not os.path.exists(doc):
                continue
            cited, end = [match.group(2)], match.end()
            # A list: NAME.md, "A", "B" and "C".
            while more := next_title.match(joined, end + 1):
                cited.append(more.group(1))
                end = more.end() - 1
            for title in cited:
                if not page(doc).has_section(title):
                    problems.append(f'{where}: cites a section docs/{match.group(1)}.md does not have: '
                                    f'"{squeeze(title)}"')

    for problem in problems:
        print(problem)
    print(f'{len(problems)} unresolved cross-references' if problems else
          f'all cross-references resolve ({len(sources)} files)')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else os.getcwd()))
