#!/usr/bin/env python3
"""Runs the notebook tutorials of examples/notebooks/ headless (nbclient) and checks them.

    PYTHONPATH=build/python /usr/bin/python3 tools/run_notebooks.py [--out DIR] [NOTEBOOK ...]

For each notebook: the committed file has no outputs (so the repository holds the tutorial, not a
run of it); every cell runs without error; it shows at least one figure; it finishes within
--max-seconds (default 300). --out DIR keeps the executed notebooks, with their figures. Run from
the repository root after the build (the notebooks find build/hotlap and build/python themselves).
"""
import argparse
import glob
import os
import sys
import time

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError


def outputs_committed(nb):
    return [i for i, c in enumerate(nb.cells)
            if c.cell_type == "code" and (c.get("outputs") or c.get("execution_count") is not None)]


def figures(nb):
    return sum(1 for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
               if o.get("output_type") in ("display_data", "execute_result") and "image/png" in o.get("data", {}))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("notebooks", nargs="*")
    ap.add_argument("--out")
    ap.add_argument("--max-seconds", type=float, default=300)
    args = ap.parse_args()
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    paths = args.notebooks or sorted(glob.glob(os.path.join(root, "examples", "notebooks", "*.ipynb")))
    if not paths:
        print("run_notebooks: no notebooks found", file=sys.stderr)
        return 1
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger's start-up note
    bad = 0
    for path in paths:
        name = os.path.relpath(path, root)
        nb = nbformat.read(path, as_version=4)
        dirty = outputs_committed(nb)
        if dirty:
            print(f"run_notebooks: {name}: committed with outputs in cells {dirty} (clear them)", file=sys.stderr)
            bad = 1
        client = NotebookClient(nb, timeout=int(args.max_seconds), kernel_name="python3",
                                resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}})
        start = time.monotonic()
        try:
            client.execute()
        except CellExecutionError as e:
            print(f"run_notebooks: {name}: a cell failed:\n{e}", file=sys.stderr)
            bad = 1
            continue
        finally:
            if args.out:
                os.makedirs(args.out, exist_ok=True)
                nbformat.write(nb, os.path.join(args.out, os.path.basename(path)))
        seconds = time.monotonic() - start
        n = figures(nb)
        if n == 0:
            print(f"run_notebooks: {name}: ran, but showed no figure", file=sys.stderr)
            bad = 1
        if seconds > args.max_seconds:
            print(f"run_notebooks: {name}: took {seconds:.0f} s, over {args.max_seconds:.0f} s", file=sys.stderr)
            bad = 1
        print(f"run_notebooks: {name}: {len(nb.cells)} cells ran, {n} figures, {seconds:.0f} s")
    return bad


if __name__ == "__main__":
    sys.exit(main())
