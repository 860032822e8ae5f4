#!/usr/bin/env python3
"""Checks the shape of the documentation (docs/ and README.md):

- no page in docs/ outside docs/validation/ is over 400 lines (a guide or reference that long
  has a measurement history or an explanation to move out);
- no page speaks of the work's sessions: the words "session"/"sessions" in lower case (MoTeC's
  own "Session" field, capitalised, is a log's metadata and is allowed).

    /usr/bin/python3 tools/check_docs_pages.py

Exit 1 with one line per finding. Run from the repository root.
"""
import glob
import re
import sys

MAX_LINES = 400


def main():
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
