#!/usr/bin/env python3
"""Checks the shape of the documentation (docs/ and README.md):

- no page in docs/ outside docs/validation/ is over 400 lines (a guide or reference that long
  has a measurement history or an explanation to move out);
- no page speaks of the work's sessions: the words "session"/"sessions" in lower case (MoTeC's
  own "Session" field, capitalised, is a log's metadata and is allowed).

- with --site DIR (the built MkDocs site), every link to a section (`page.md#anchor`) lands on
  a heading that exists (MkDocs checks the pages, not the anchors).

    /usr/bin/python3 tools/check_docs_pages.py [--site build/site]

Exit 1 with one line per finding. Run from the repository root.
"""
import glob
import os
import re
import sys

MAX_LINES = 400


def anchors(site):
    """Findings for links to sections that the built site does not have."""
    bad = []
    for page in sorted(glob.glob("docs/**/*.md", recursive=True)):
        for m in re.finditer(r"\]\(([^)\s]*?)#([^)\s]+)\)", open(page).read()):
            target = os.path.normpath(os.path.join(os.path.dirname(page), m.group(1))) if m.group(1) else page
            rel = os.path.relpath(target, "docs")[: -len(".md")]
            html = os.path.join(site, os.path.dirname(rel) if rel.endswith("index") else rel, "index.html")
            if not os.path.exists(html) or f'id="{m.group(2)}"' not in open(html).read():
                bad.append(f"{page}: link to {m.group(0)[2:-1]}: no such section in the site")
    return bad


def main():
    site = sys.argv[sys.argv.index("--site") + 1] if "--site" in sys.argv else None
    if site:
        bad = anchors(site)
        for b in bad:
            print("check_docs_pages: " + b, file=sys.stderr)
        if not bad:
            print(f"check_docs_pages: every link to a section lands on one in {site}")
        return 1 if bad else 0
    bad = []
    pages = sorted(glob.glob("docs/**/*.md", recursive=True))
    for page in pages:
        n = sum(1 for _ in open(page))
        if not page.startswith("docs/validation/") and n > MAX_LINES:
            bad.append(f"{page}: {n} lines (at most {MAX_LINES} outside docs/validation/)")
    for page in pages + ["README.md"]:
        for i, line in enumerate(open(page), 1):
            if re.search(r"\bsessions?\b", line):
                bad.append(f"{page}:{i}: speaks of sessions: {line.strip()[:100]}")
    for b in bad:
        print("check_docs_pages: " + b, file=sys.stderr)
    if bad:
        return 1
    print(f"check_docs_pages: {len(pages)} pages, none over {MAX_LINES} lines outside docs/validation/, "
          "none speaks of sessions")
    return 0


if __name__ == "__main__":
    sys.exit(main())
