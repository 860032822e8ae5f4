#!/usr/bin/env python3
"""Runs the commands the guides show and compares what they print with the page.

    /usr/bin/python3 tools/check_doc_commands.py [--update] [PAGE.md ...]

A checked example in a page is a ```console block right after the line `<!-- check-output -->`:

    <!-- check-output -->
    ```console
    $ hotlap track info --track darlington
    track 'darlington' (segments: data/tracks/darlington.yaml)
    ...
    ```

The pages' commands run in page order. Lines starting with `$ ` are commands (a trailing backslash continues one), run by bash from the
repository root with build/ first on PATH (so `hotlap` is the program just built) and
PYTHONPATH=build/python and HOTLAP_CACHE_DIR a fresh folder for the whole check; the lines after a command, up to the next, are what it must print
(its standard output, then its standard error: warnings come last on the page, whatever their
order on a terminal). A line `...` stands for any number of lines. Before comparing, the
repository's absolute path is removed and run times (`in 0.44 s`, `done in 3 ms`, `(180 times real time)`) are blanked, so
a page shows the real output of a real run. Every command must exit 0. --update rewrites the
pages' expected output with what the commands print now, keeping their `...` elisions (then read
the diff). Run from the
repository root; the default pages are docs/**/*.md.
"""
import argparse
import atexit
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

MARK = "<!-- check-output -->"
TIME = re.compile(r"\b(done )?in \d+(\.\d+)? ?(s|ms|min|h)\b")
SPEED = re.compile(r"\(\d+(\.\d+)? times real time\)")


def blocks(text):
    """[(start line index of the first content line, end line index of the closing fence)]."""
    lines = text.split("\n")
    out = []
    for i, line in enumerate(lines):
        if line.strip() == MARK:
            if i + 1 >= len(lines) or not lines[i + 1].startswith("```console"):
                raise SystemExit(f"check_doc_commands: '{MARK}' not followed by a ```console block")
            end = next(j for j in range(i + 2, len(lines)) if lines[j].startswith("```"))
            out.append((i + 2, end))
    return lines, out


def parse(body):
    """[(command, [expected lines])]."""
    steps, i = [], 0
    while i < len(body):
        line = body[i]
        if not line.startswith("$ "):
            raise SystemExit(f"check_doc_commands: output before any command: {line!r}")
        cmd = line[2:]
        while cmd.endswith("\\") and i + 1 < len(body):
            i += 1
            cmd = cmd + "\n" + body[i]
        i += 1
        expected = []
        while i < len(body) and not body[i].startswith("$ "):
            expected.append(body[i])
            i += 1
        steps.append((cmd, expected))
    return steps


def normalise(line, root):
    line = line.replace(root + "/", "").replace(root, ".")
    line = SPEED.sub("(<speed> times real time)", line)
    return TIME.sub(lambda m: (m.group(1) or "") + "in <time>", line).rstrip()


def matches(expected, actual):
    """Whether actual fits expected, where an expected '...' matches any run of lines."""
    if not expected:
        return not actual
    if expected[0].strip() == "...":
        return any(matches(expected[1:], actual[k:]) for k in range(len(actual) + 1))
    return bool(actual) and expected[0] == actual[0] and matches(expected[1:], actual[1:])


def keep_elisions(expected, raw):
    """The program's lines `raw` with the page's `...` elisions kept: the lines before the first
    `...` and after the last are the program's first and last lines, each middle run of expected
    lines the program's run that shares most of their first words."""
    segments = [[]]
    for line in expected:
        if line.strip() == "...":
            segments.append([])
        else:
            segments[-1].append(line)
    if len(segments) == 1 or sum(len(s) for s in segments) > len(raw):
        return raw
    out = list(raw[:len(segments[0])])
    cursor = len(segments[0])
    tail = len(segments[-1])
    for segment in segments[1:-1]:
        out.append("...")
        last = len(raw) - tail - len(segment)
        best = max(range(cursor, max(cursor, last) + 1),
                   key=lambda j: sum((a.split()[:1] == b.split()[:1]) + (a.split()[:2] == b.split()[:2])
                                  for a, b in zip(segment, raw[j:j + len(segment)])))
        out += raw[best:best + len(segment)]
        cursor = best + len(segment)
    out.append("...")
    out += raw[len(raw) - tail:] if tail else []
    return out


# One fresh cache folder for the whole check (`hotlap race` caches its fall-off): the pages'
# commands run in page order, so what they read from it is the same on every run.
CACHE = tempfile.mkdtemp(prefix="hotlap-doc-cache-")
atexit.register(shutil.rmtree, CACHE, True)


def run(cmd, root):
    env = dict(os.environ)
    env["HOTLAP_CACHE_DIR"] = CACHE
    env["PATH"] = os.path.join(root, "build") + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.path.join(root, "build", "python")
    env["COLUMNS"] = "100"
    r = subprocess.run(["bash", "-c", "set -o pipefail; " + cmd], cwd=root, env=env,
                       capture_output=True, text=True)
    text = (r.stdout + r.stderr).rstrip("\n")  # stdout, then stderr: the same order on every run
    return r.returncode, text.split("\n") if text.strip() else []


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--update", action="store_true")
    ap.add_argument("pages", nargs="*")
    args = ap.parse_args()
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    pages = args.pages or sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True))
    failures = checked = 0
    for page in pages:
        text = open(page).read()
        lines, found = blocks(text)
        if not found:
            continue
        new = list(lines)
        done = []  # (start, end, rendered): run in page order, put back from the end
        for start, end in found:
            rendered = []
            for cmd, expected in parse(lines[start:end]):
                checked += 1
                rc, actual = run(cmd, root)
                raw = [l.replace(root + "/", "").rstrip() for l in actual]
                actual = [normalise(l, root) for l in actual]
                want = [normalise(l, root) for l in expected]
                name = os.path.relpath(page, root)
                if rc != 0:
                    failures += 1
                    print(f"{name}: '{cmd}' exited {rc}:\n  " + "\n  ".join(actual[-20:]), file=sys.stderr)
                elif not matches(want, actual):
                    failures += 1
                    print(f"{name}: '{cmd}' printed something else than the page shows:", file=sys.stderr)
                    import difflib
                    for d in difflib.unified_diff(want, actual, "page", "program", lineterm="", n=1):
                        print("  " + d, file=sys.stderr)
                shown = expected if (rc == 0 and matches(want, actual)) else keep_elisions(expected, raw)
                rendered += ("$ " + cmd).split("\n") + (shown if args.update and rc == 0 else expected)
            done.append((start, end, rendered))
        for start, end, rendered in reversed(done):
            new[start:end] = rendered
        if args.update and new != lines:
            with open(page, "w") as f:
                f.write("\n".join(new))
            print(f"check_doc_commands: updated {os.path.relpath(page, root)}")
    if failures and not args.update:
        print(f"check_doc_commands: {failures} of {checked} commands differ from their pages "
              "(run tools/check_doc_commands.py --update and read the diff)", file=sys.stderr)
        return 1
    print(f"check_doc_commands: {checked} commands checked against their pages")
    return 0


if __name__ == "__main__":
    sys.exit(main())
