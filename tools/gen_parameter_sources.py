#!/usr/bin/env python3
"""Writes docs/reference/parameters.md and docs/reference/parameters/*.md: every value of every
shipped parameter file (data/**/*.yaml) with where it comes from, read from the files' own
comments.

    /usr/bin/python3 tools/gen_parameter_sources.py [--check]

A value is classed by the comment on its line; without one that names a source, by the comment
of the section it is in (on the section's line, or the comment block just above it), then by the
file's header. The classes, by the words the comments use:

    tuned    "tuned" (set so that a result matches: the comment says to what)
    assumed  "assumed", "guess"
    public   "public" (a published fact about the car or track: the comment gives it)
    paper    a paper's table or equation: "000" (the NASCAR paper), "001" (UniTire), "002" (FE/ABS),
             "Table", "paper"; the F1 car's "xml:" (Perantoni and Limebeer 2014 as fastest-lap encodes it)
    unmarked the file says nothing about this value's source

--check writes nothing and fails (exit 1) when the committed pages differ from what the files
give now (CI runs it, so the pages cannot go stale). Run from the repository root.
"""
import argparse
import glob
import os
import re
import sys

PAGE = "docs/reference/parameters.md"
DIR = "docs/reference/parameters"
SKIP = {"data/motec_channels.yaml"}  # a channel-name map, not parameters
PAPER = r"\b00[0-2]\b|\btable\s+\d|\bpaper|\bxml:|fastest-lap"
ORDER = ["public", "paper", "assumed", "tuned", "unmarked"]


def own_class(comment):
    """The class a comment states for the value on its own line, or None."""
    c = comment.lower()
    if re.search(r"\btuned\b", c):
        return "tuned"
    if re.search(r"\bassumed\b|\bguess\b", c):
        return "assumed"
    if re.search(r"\bpublic\b", c):
        return "public"
    if re.search(PAPER, c):
        return "paper"
    return None


def block_class(comment):
    """The class a section's or file's comment block gives by default: the first source word in it."""
    c = comment.lower()
    hits = []
    for cls, pattern in [("tuned", r"\btuned\b"), ("assumed", r"\bassumed\b|\bguess\b"),
                         ("public", r"\bpublic\b"), ("paper", PAPER)]:
        m = re.search(pattern, c)
        if m:
            hits.append((m.start(), cls))
    return min(hits)[1] if hits else None


def split_comment(line):
    """(code, comment) of a YAML line; a '#' inside quotes is not a comment."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1] in " \t"):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def parse(path):
    """[(dotted key, value, class, source comment)] for every value of the file."""
    lines = open(path).read().split("\n")
    header = []
    for line in lines:
        if line.startswith("#"):
            header.append(line[1:].strip())
        else:
            break
    file_cls = block_class(" ".join(header))
    rows = []
    stack = []  # (indent, key, class or None, comment)
    pending = []  # comment lines just above the current line
    list_index = {}
    i = 0
    while i < len(lines):
        raw = lines[i]
        i += 1
        code, comment = split_comment(raw)
        if not code.strip():
            pending = pending + [comment] if comment and raw.lstrip().startswith("#") else []
            continue
        if raw.lstrip().startswith("#"):
            continue
        indent = len(code) - len(code.lstrip())
        text = code.strip()
        # a flow mapping may continue on the next lines
        while text.count("{") > text.count("}") and i < len(lines):
            more, more_comment = split_comment(lines[i])
            i += 1
            text += " " + more.strip()
            comment = (comment + " " + more_comment).strip()
        while stack and stack[-1][0] >= indent and not (text.startswith("- ") and stack[-1][0] == indent
                                                         and stack[-1][1] is None):
            stack.pop()
        above = " ".join(pending)
        pending = []
        if text.startswith("- "):
            parent = ".".join(k for _, k, _, _ in stack if k)
            n = list_index.get(parent, 0)
            list_index[parent] = n + 1
            key, value = f"{parent}[{n}]", text[2:].strip()
            own = comment or above
        else:
            m = re.match(r"([^:]+):\s*(.*)$", text)
            if not m:
                continue
            key = ".".join([k for _, k, _, _ in stack if k] + [m.group(1).strip()])
            value = m.group(2).strip()
            own = comment
            if not value:  # a section
                cls = own_class(comment) if comment else None
                cls = cls or (block_class(above) if above else None)
                stack.append((indent, m.group(1).strip(), cls, comment or above))
                continue
        cls = own_class(own) if own else None
        source = own
        if cls is None:
            for _, _, scls, scomment in reversed(stack):
                if scls:
                    cls, source = scls, (own + "; " if own else "") + "section: " + scomment
                    break
        if cls is None and file_cls:
            cls, source = file_cls, (own + "; " if own else "") + "file: " + " ".join(header)[:160]
        if re.search(r"\d", value) and not re.search(r"\.(yaml|tir|xml|csv)\b", value):
            rows.append((key, value, cls or "unmarked", source))  # a number, not a name or a file
    return rows


def cell(text):
    return text.replace("|", "\\|").replace("\n", " ")


def render():
    files = sorted(p for p in glob.glob("data/**/*.yaml", recursive=True) if p not in SKIP)
    pages = {}
    index = ["# Where every number comes from", "",
             "Each shipped parameter file's numbers, classed by the source the file itself gives: **public**",
             "(a published fact about the car or track), **paper** (a table or equation of the papers: `000`",
             "the NASCAR paper, `001` UniTire, `002` the FE/ABS paper), **assumed** (chosen to be plausible,",
             "not measured), **tuned** (set so that a result matches what the comment names), or",
             "**unmarked** (the file does not say). Generated by `tools/gen_parameter_sources.py` from",
             "`data/**/*.yaml`; CI checks that these pages are current. How the Gen-7-like car's assumed",
             "and tuned values were settled: [vehicle.md](../vehicle.md).", "",
             "| file | values | " + " | ".join(ORDER) + " |",
             "|---|---|" + "---|" * len(ORDER)]
    total = {c: 0 for c in ORDER}
    for path in files:
        rows = parse(path)
        name = path[len("data/"):-len(".yaml")].replace("/", "-")
        counts = {c: sum(1 for r in rows if r[2] == c) for c in ORDER}
        for c in ORDER:
            total[c] += counts[c]
        index.append(f"| [`{path}`](parameters/{name}.md) | {len(rows)} | "
                     + " | ".join(str(counts[c]) for c in ORDER) + " |")
        page = [f"# `{path}`", "", "Generated by `tools/gen_parameter_sources.py`; the classes are explained in",
                "[Where every number comes from](../parameters.md).", "",
                "| key | value | source | the file's comment |", "|---|---|---|---|"]
        for key, value, cls, source in rows:
            page.append(f"| `{cell(key)}` | `{cell(value)}` | {cls} | {cell(source)} |")
        pages[f"{DIR}/{name}.md"] = page
    index.append(f"| all | {sum(total.values())} | " + " | ".join(str(total[c]) for c in ORDER) + " |")
    pages[PAGE] = index
    return {p: "\n".join(lines).rstrip() + "\n" for p, lines in pages.items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    pages = render()
    if args.check:
        committed = {p: open(p).read() for p in [PAGE] + sorted(glob.glob(DIR + "/*.md")) if os.path.exists(p)}
        stale = sorted(p for p in set(pages) | set(committed) if pages.get(p) != committed.get(p))
        if stale:
            print("gen_parameter_sources: not what data/ gives now: " + ", ".join(stale)
                  + "; regenerate with /usr/bin/python3 tools/gen_parameter_sources.py", file=sys.stderr)
            return 1
        print(f"gen_parameter_sources: {PAGE} and {len(pages) - 1} file pages are current")
        return 0
    os.makedirs(DIR, exist_ok=True)
    for old in glob.glob(DIR + "/*.md"):
        if old not in pages:
            os.remove(old)
    for path, text in pages.items():
        with open(path, "w") as f:
            f.write(text)
    print(f"gen_parameter_sources: wrote {PAGE} and {len(pages) - 1} file pages")
    return 0


if __name__ == "__main__":
    sys.exit(main())
