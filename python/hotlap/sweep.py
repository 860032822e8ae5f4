"""Set-up sweeps: many cases of hotlap's laps, on dask.distributed or as shards of a Slurm array.

A case is one row of a case table: the car and track, the method (``qss``, ``ocp``, ``compare``;
``stint``; ``race``), the method's options, and any car parameter overridden by its dotted
key (``brake_system.front_share``, ``brakes.fl.duct_factor``, ``tyre_forces.rr.pressure_kPa``:
docs/overrides.md). Each case runs in a worker process of its own (Ipopt with MUMPS is not
thread-safe: one solve per process at a time) and writes its folder ``OUT/cases/<case>/``
atomically; ``OUT/results.csv`` (every case's inputs, status and headline outputs) and
``OUT/report.html`` (each output against each varied input, the table sorted by lap time) are
written from those folders at the end, and again by ``merge``. A case already done with the same
resolved inputs (their hash) is skipped, so a sweep that stopped can be run again on the same
``OUT``. Optimal laps (``ocp``) start from the nearest lap already solved (a lap cache on disk,
by the inputs' hash: the same inputs reuse their lap, others start from the closest in the varied
values), and the cases run in an order that gives each a solved neighbour. docs/sweeps.md has the
table format, warm starts, the recipes for a cluster and for Slurm.

    hotlap sweep --cases cases.csv --out study [--local-workers N | --scheduler tcp://HOST:8786]
                 [--shard I/N] [--lap-cache DIR | --cold] [--json PATH]
    hotlap sweep merge study
"""

import argparse
import csv
import difflib
import hashlib
import itertools
import json
import math
import os
import shutil
import sys
import time

import hotlap

METHODS = ("qss", "ocp", "compare", "stint", "race")

# Case-table columns besides the car parameter overrides: name -> (type, methods it applies to).
OPTIONS = {
    "laps": (int, ("qss", "stint", "race")),
    "step_m": (float, ("qss", "ocp", "compare", "stint", "race")),
    "stages": (str, ("race",)),
    "fuel_capacity_kg": (float, ("race",)),
    "fuel_per_lap_kg": (float, ("race",)),
    "tyre_sets": (int, ("race",)),
    "pit_loss_s": (float, ("race",)),
    "caution_pit_loss_s": (float, ("race",)),
    "fall_off_laps": (int, ("race",)),
    "cautions": (str, ("race",)),
    "races": (int, ("race",)),
    "line": (str, ("qss",)),
    "tolerance_s": (float, ("ocp", "compare")),
    "coarse_step_m": (float, ("ocp", "compare", "stint")),
    "collocation": (str, ("ocp", "compare")),
    "disc_limit_C": (float, ("ocp", "stint")),
    "compare_disc_limit_C": (float, ("compare",)),
    "wear_scale": (float, ("stint",)),
    "fuel_kg": (float, ("stint",)),
    "thermal_start": (str, ("ocp", "compare", "stint")),
    "max_iterations": (int, ("ocp", "compare", "stint")),
    "wear_in_programme": ("bool", ("ocp", "compare")),
    "ambient_temp_C": (float, ("qss", "ocp", "compare", "stint")),
    "track_temp_C": (float, ("qss", "ocp", "compare", "stint")),
}
BASE_COLUMNS = ("case", "car", "track", "method")
DEFAULTS = {"car": "gen7", "track": "darlington", "method": "qss"}
COMPARE_DEFAULT_LIMIT_C = 500.0


class CaseTableError(ValueError):
    """A case table that cannot be read: the message names the file, the row and the column."""


# ---- the case table ----


def _number_or_text(text):
    text = text.strip()
    if text == "":
        return None
    try:
        value = float(text)
    except ValueError:
        return text
    return int(value) if value.is_integer() and "." not in text and "e" not in text.lower() else value


def read_cases(path):
    """The case table at ``path`` as a list of dicts (one per case, None for an empty cell).

    CSV: a header row of column names, one row per case. YAML: ``cases:`` (a list of mappings),
    and/or ``base:`` (a mapping every case starts from) with ``grid:`` (a mapping of column ->
    list of values, expanded to every combination, the last column varying fastest).
    """
    path = os.fspath(path)
    if path.endswith((".yaml", ".yml")):
        import yaml

        try:
            with open(path) as f:
                doc = yaml.safe_load(f)
        except (OSError, yaml.YAMLError) as e:
            raise CaseTableError("%s: %s" % (path, e)) from None
        if not isinstance(doc, dict) or not ({"cases", "grid"} & set(doc)):
            raise CaseTableError("%s: a mapping with 'cases:' and/or 'base:' and 'grid:' is needed" % path)
        unknown = set(doc) - {"cases", "base", "grid"}
        if unknown:
            raise CaseTableError("%s: unknown key(s) %s (the keys are cases, base, grid)" % (path, ", ".join(sorted(unknown))))
        base = doc.get("base") or {}
        rows = [dict(base, **row) for row in doc.get("cases") or []]
        grid = doc.get("grid") or {}
        if grid:
            for column, values in grid.items():
                if not isinstance(values, list) or not values:
                    raise CaseTableError("%s: grid.%s must be a non-empty list of values" % (path, column))
            columns = list(grid)
            for combination in itertools.product(*(grid[c] for c in columns)):
                rows.append(dict(base, **dict(zip(columns, combination))))
        return rows
    try:
        with open(path, newline="") as f:
            lines = [row for row in csv.reader(f) if row and not row[0].lstrip().startswith("#")]
    except OSError as e:
        raise CaseTableError("%s: %s" % (path, e.strerror or e)) from None
    if len(lines) < 2:
        raise CaseTableError("%s: a header row and at least one case are needed" % path)
    header = [h.strip() for h in lines[0]]
    for n, row in enumerate(lines[1:], start=2):
        if len(row) != len(header):
            raise CaseTableError("%s: row %d has %d cells, the header %d" % (path, n, len(row), len(header)))
    return [{h: _number_or_text(cell) for h, cell in zip(header, row)} for row in lines[1:]]


def resolve_cases(rows, source="cases"):
    """Each row with its defaults filled in, checked, named and hashed (see resolve_case)."""
    cases = [resolve_case(row, n, source) for n, row in enumerate(rows)]
    seen = {}
    for case in cases:
        if case["case"] in seen:
            raise CaseTableError("%s: case name '%s' given twice (cases %d and %d)"
                                 % (source, case["case"], seen[case["case"]] + 1, case["index"] + 1))
        seen[case["case"]] = case["index"]
    return cases


def resolve_case(row, index, source="cases"):
    """A case as it runs: {case, index, car, track, method, options, overrides, hash}.

    Columns other than case, car, track, method and the method options (OPTIONS) must be dotted
    car parameter keys; an unknown plain column is refused with the closest names. The override
    keys themselves are checked when the case loads its car (a bad one fails that case only).
    """
    where = "%s, case %d" % (source, index + 1)
    case = {"index": index, "options": {}, "overrides": {}}
    for column, value in row.items():
        if value is None:
            continue
        if column in BASE_COLUMNS:
            case[column] = value
        elif column in OPTIONS:
            kind = OPTIONS[column][0]
            if kind == "bool":
                if value not in (True, False, 0, 1) and str(value).lower() not in ("true", "false"):
                    raise CaseTableError("%s: %s = %r is not true, false, 1 or 0" % (where, column, value))
                case["options"][column] = value in (True, 1) or str(value).lower() == "true"
                continue
            try:
                case["options"][column] = kind(value)
            except (TypeError, ValueError):
                raise CaseTableError("%s: %s = %r is not a%s %s" % (where, column, value, "n" if kind is int else "", kind.__name__)) from None
        elif "." in column:
            if isinstance(value, str):
                raise CaseTableError("%s: %s = %r: an override's value is a number" % (where, column, value))
            case["overrides"][column] = float(value)
        else:
            names = list(BASE_COLUMNS) + list(OPTIONS)
            close = difflib.get_close_matches(column, names, n=2)
            raise CaseTableError("%s: unknown column '%s'%s; a column is one of %s or a car parameter's dotted key"
                                 % (where, column, " (did you mean %s?)" % " or ".join("'%s'" % c for c in close) if close else "",
                                    ", ".join(names)))
    for key, value in DEFAULTS.items():
        case.setdefault(key, value)
    case["case"] = str(case.get("case") or "case-%04d" % (index + 1))
    if any(c in case["case"] for c in "/\\") or case["case"].startswith("."):
        raise CaseTableError("%s: case name '%s' must not hold a slash or start with a dot" % (where, case["case"]))
    if case["method"] not in METHODS:
        raise CaseTableError("%s: method '%s' is not one of %s" % (where, case["method"], ", ".join(METHODS)))
    for option in case["options"]:
        if case["method"] not in OPTIONS[option][1]:
            raise CaseTableError("%s: option %s does not apply to method %s" % (where, option, case["method"]))
    if case["method"] == "compare":
        case["options"].setdefault("compare_disc_limit_C", COMPARE_DEFAULT_LIMIT_C)
    if case["method"] in ("ocp", "compare"):
        # The wear as states: a lap solved from another's point is then the same programme as
        # from the guess (frozen, the wear would be the start's; docs/sweeps.md).
        case["options"].setdefault("wear_in_programme", True)
    resolved = {k: case[k] for k in ("car", "track", "method", "options", "overrides")}
    resolved["hotlap"] = hotlap.__version__
    case["hash"] = hashlib.sha256(json.dumps(resolved, sort_keys=True).encode()).hexdigest()[:16]
    return case


# ---- warm starts: the lap cache, the nearest solved lap, the order ----

# Methods whose cases start from a solved neighbour (one solve; the comparison's two laps and a
# stint's greedy laps have their own starts).
WARM_START_METHODS = ("ocp",)
# Options that pose another programme (another mesh or thermal start): a solved lap is a start
# for a case only where these are equal. The other options that are numbers are coordinates.
PROGRAMME_OPTIONS = ("step_m", "collocation", "thermal_start", "tolerance_s", "wear_in_programme")


def warm_startable(case):
    """Whether ``case`` starts from a solved lap: an optimal lap on a fixed mesh."""
    return case["method"] in WARM_START_METHODS and not case["options"].get("tolerance_s")


def coordinates(case):
    """A case's position among its neighbours: its overrides and its options that are numbers but
    pose no other programme, {key: value}."""
    out = {k: float(v) for k, v in case["overrides"].items()}
    for k, v in case["options"].items():
        if k not in PROGRAMME_OPTIONS and isinstance(v, (int, float)) and not isinstance(v, bool):
            out[k] = float(v)
    return out


def family(case):
    """The cases that are neighbours (ordered together): the same car, track, method, options
    that pose the programme, and coordinates given. (The lap cache keys a lap itself by the car's
    files; docs/sweeps.md.)"""
    return json.dumps({"car": case["car"], "track": case["track"], "method": case["method"],
                       "programme": {k: case["options"].get(k) for k in PROGRAMME_OPTIONS},
                       "keys": sorted(coordinates(case))}, sort_keys=True)


def coordinate_scales(cases):
    """Each coordinate's scale: its spread over ``cases`` (max - min), else its size (at least 1)."""
    values = {}
    for case in cases:
        for k, v in coordinates(case).items():
            values.setdefault(k, []).append(v)
    return {k: (max(v) - min(v)) or max(abs(max(v)), 1.0) for k, v in values.items()}


def distance(a, b, scales):
    """The scaled distance between two coordinate dicts of the same keys (the lap cache's own,
    ocp::CoordinateDistance, for ordering the cases)."""
    return math.sqrt(sum(((a[k] - b[k]) / scales.get(k, max(abs(a[k]), 1.0))) ** 2 for k in a))


def order_for_warm_starts(cases, scales):
    """``cases`` in an order that gives each warm-startable case a solved neighbour: per family,
    a nearest-neighbour path from its first case in the table (on a grid, a serpentine); the
    other cases as they are, first."""
    others = [c for c in cases if not warm_startable(c)]
    families = {}
    for c in cases:
        if warm_startable(c):
            families.setdefault(family(c), []).append(c)
    ordered = list(others)
    for members in families.values():
        left = list(members)
        path = [left.pop(0)]
        while left:
            here = coordinates(path[-1])
            k = min(range(len(left)), key=lambda i: (distance(here, coordinates(left[i]), scales), left[i]["index"]))
            path.append(left.pop(k))
        ordered += path
    return ordered


# ---- one case ----


def _flatten(summary, prefix=""):
    """The summary's numbers and short texts as {dotted.key: value} (lists left out)."""
    out = {}
    for key, value in summary.items():
        name = prefix + key
        if isinstance(value, dict):
            out.update(_flatten(value, name + "."))
        elif isinstance(value, bool) or isinstance(value, (int, float, str)) or value is None:
            out[name] = value
    return out


def _write_channels(path, channels):
    names = list(channels)
    columns = [channels[n] for n in names]
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        for row in zip(*columns):
            f.write(",".join("" if math.isnan(v) else repr(float(v)) for v in row) + "\n")


def run_case(case, out, lap_cache=None, scales=None):
    """Runs one case and writes OUT/cases/<case>/ (result.json and the channels) atomically.

    Returns the result: the case, status ("ok", "not converged", "bad input", "numerical failure",
    "not available"), message, elapsed_s, the flattened summary and, for an optimal lap with a
    ``lap_cache`` folder, ``warm_start_from`` and ``warm_start_distance`` (the cached lap it
    started from, "" and None if none; its converged lap goes into the cache). Runs in a worker
    process.
    """
    started = time.perf_counter()
    result = {"case": case["case"], "hash": case["hash"], "index": case["index"], "inputs": {
        k: case[k] for k in ("car", "track", "method", "options", "overrides")},
        "warm_start_from": "", "warm_start_distance": None}
    channels = {}
    warm = lap_cache is not None and warm_startable(case)
    try:
        car = hotlap.load_car(case["car"], overrides=case["overrides"]) if case["overrides"] else hotlap.load_car(case["car"])
        track = hotlap.load_track(case["track"])
        options = dict(case["options"])
        if case["method"] == "qss":
            r = hotlap.qss_lap(car, track, **options)
            channels = {"lap.csv": r["channels"]}
        elif case["method"] == "stint":
            r = hotlap.stint(car, track, **options)
            channels = {"stint.csv": r["channels"]}
        elif case["method"] == "race":
            summary = hotlap.race(car, track, **options)
            fall_off = summary["fall_off"]
            ages = list(range(len(fall_off["lap_time_s"])))
            channels = {"fall_off.csv": {"age_laps": ages, "lap_time_s": fall_off["lap_time_s"],
                                         "heat_only_lap_time_s": fall_off["heat_only_lap_time_s"]}}
            r = {"summary": summary}
        else:
            if warm:  # from the nearest laps solved before it (the library's lap cache)
                # (its two nearest in turn, 150 iterations each, then the default start)
                options.update(lap_cache=lap_cache, lap_cache_name=case["case"], lap_cache_scales=scales or {})
            r = hotlap.optimal_lap(car, track, **options)
            if warm and r["summary"].get("warm_start_from"):
                result.update(warm_start_from=r["summary"]["warm_start_from"],
                              warm_start_distance=r["summary"]["warm_start_distance"])
            channels = {"%s.csv" % label.replace(" ", "_").replace("<=", "le").replace("/", "_"): c
                        for label, c in r["channels"].items()}
        summary = r["summary"]
        status = "ok"
        statuses = [summary.get("status")] + [summary.get(k, {}).get("status") for k in ("unconstrained", "constrained")]
        if any(s not in (None, "converged") for s in statuses):
            status = "not converged"
        result.update(status=status, message="", summary=_flatten(summary),
                      failed_start_iterations=sum(f.get("ipopt_iterations", 0) for f in summary.get("failed_starts") or []))
    except ValueError as e:
        result.update(status="bad input", message=str(e), summary={})
    except hotlap.NumericalError as e:
        result.update(status="numerical failure", message=str(e), summary={})
    except NotImplementedError as e:
        result.update(status="not available", message=str(e), summary={})
    result["elapsed_s"] = round(time.perf_counter() - started, 3)
    # Atomic: everything into a temporary folder beside the case's, then renamed into place.
    cases_dir = os.path.join(out, "cases")
    os.makedirs(cases_dir, exist_ok=True)
    final = os.path.join(cases_dir, case["case"])
    tmp = os.path.join(cases_dir, ".tmp-%s-%d" % (case["case"], os.getpid()))
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    for name, c in channels.items():
        _write_channels(os.path.join(tmp, name), c)
    with open(os.path.join(tmp, "result.json"), "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    if os.path.exists(final):
        old = final + ".old-%d" % os.getpid()
        os.replace(final, old)
        os.replace(tmp, final)
        shutil.rmtree(old, ignore_errors=True)
    else:
        os.replace(tmp, final)
    return result


def load_result(out, case):
    """The stored result of ``case`` if its folder holds one of the same inputs (hash), else None."""
    path = os.path.join(out, "cases", case["case"], "result.json")
    try:
        with open(path) as f:
            result = json.load(f)
    except (OSError, ValueError):
        return None
    return result if result.get("hash") == case["hash"] else None


# ---- the sweep ----


def _progress_line(total, done, running, failed, started):
    elapsed = time.monotonic() - started
    remaining = (total - done) * elapsed / done if done else float("nan")
    return "cases: %d/%d done, %d running, %d failed; %.0f s elapsed, about %s left" % (
        done, total, running, failed, elapsed, "?" if math.isnan(remaining) else "%.0f s" % remaining)


def sweep(cases, out, *, local_workers=None, scheduler=None, shard=None, progress=print,
          worker_retries=2, warm_starts=True, lap_cache=None):
    """Runs every case of ``cases`` (a case-table path, or a list of row dicts) into ``out``.

    Default: a local dask cluster of ``local_workers`` single-threaded worker processes (one per
    core if None); ``scheduler`` ("tcp://host:port", or a ``distributed.Client``) uses an existing
    cluster instead; ``shard=(i, n)`` runs cases i, i + n, ... (1-based i) in this process without
    dask. A case already done with the same inputs is skipped; a failing case is recorded and the
    rest go on; a case whose worker dies is run again on another (at most ``worker_retries``
    times). With ``warm_starts`` each optimal lap starts from the nearest lap solved before it in
    the lap cache (``lap_cache``, default OUT/laps; run_case), the cases ordered so that each has
    a solved neighbour (order_for_warm_starts); else every case from its default start. Returns
    the summary dict (also written to OUT/sweep.json) after writing results.csv and report.html.
    """
    source = os.fspath(cases) if not isinstance(cases, list) else "cases"
    rows = read_cases(cases) if not isinstance(cases, list) else cases
    resolved = resolve_cases(rows, source)
    out = os.fspath(out)
    if os.path.exists(out) and not os.path.isdir(out):
        raise ValueError("--out %s: exists and is not a folder" % out)
    try:
        os.makedirs(os.path.join(out, "cases"), exist_ok=True)
    except OSError as e:
        raise ValueError("--out %s: cannot create the folder: %s" % (out, e.strerror or e)) from None
    mine = resolved
    if shard is not None:
        i, n = shard
        if not (1 <= i <= n):
            raise ValueError("shard %d/%d: I must be in 1..N" % (i, n))
        mine = [c for c in resolved if c["index"] % n == i - 1]
    todo = [c for c in mine if load_result(out, c) is None]
    skipped = len(mine) - len(todo)
    scales = coordinate_scales(resolved)
    if warm_starts:
        lap_cache = os.path.abspath(lap_cache or os.path.join(out, "laps"))
        todo = order_for_warm_starts(todo, scales)
    else:
        lap_cache = None
    started = time.monotonic()
    done = failed = 0
    lost = []
    interrupted = False

    def record(result, slots=1):
        # slots: cases that can run at once (the workers); running = those of the rest that do.
        nonlocal done, failed
        done += 1
        if result["status"] != "ok":
            failed += 1
        if progress:
            progress(_progress_line(len(todo), done, min(len(todo) - done, slots), failed, started))

    try:
        if shard is not None or not todo:
            for case in todo:
                record(run_case(case, out, lap_cache, scales))
        else:
            lost = _run_on_dask(todo, out, local_workers, scheduler, worker_retries, record, lap_cache, scales)
    except KeyboardInterrupt:
        interrupted = True
    summary = merge(out, resolved if shard is None else mine, write_report=shard is None)
    if interrupted and progress:
        progress("stopped: %d of %d cases done, in results.csv; the same command again does the rest"
                 % (summary["results"], summary["cases"]))
    summary.update(skipped=skipped, ran=done, lost=lost, interrupted=interrupted,
                   wall_time_s=round(time.monotonic() - started, 3),
                   shard=None if shard is None else "%d/%d" % shard)
    name = "sweep.json" if shard is None else "sweep-shard-%d-of-%d.json" % shard
    _write_json_atomically(os.path.join(out, name), summary)
    if interrupted:
        raise KeyboardInterrupt
    return summary


def _write_json_atomically(path, value):
    tmp = "%s.tmp-%d" % (path, os.getpid())
    with open(tmp, "w") as f:
        json.dump(value, f, indent=1, sort_keys=True)
    os.replace(tmp, path)


def _run_on_dask(todo, out, local_workers, scheduler, worker_retries, record, lap_cache, scales):
    import dask
    from distributed import Client, LocalCluster, as_completed
    from distributed.scheduler import KilledWorker

    cluster = None
    own_client = not hasattr(scheduler, "submit")
    if scheduler is None:
        # A worker that dies mid-case has the case rescheduled; after worker_retries + 1 deaths
        # the scheduler gives up on it (KilledWorker).
        with dask.config.set({"distributed.scheduler.allowed-failures": worker_retries}):
            cluster = LocalCluster(n_workers=local_workers or os.cpu_count() or 1, threads_per_worker=1,
                                   processes=True, dashboard_address=None)
        client = Client(cluster)
    elif own_client:
        client = Client(scheduler)
    else:
        client = scheduler
    lost = []
    try:
        # Submitted in the warm starts' order; the scheduler hands them out first come, first served.
        futures = {client.submit(run_case, case, os.path.abspath(out), lap_cache, scales, pure=False,
                                 key="hotlap-case-%s-%s" % (case["case"], case["hash"])): case for case in todo}
        for future in as_completed(futures):
            case = futures[future]
            slots = max(1, sum(w.get("nthreads", 1) for w in client.scheduler_info()["workers"].values()))
            try:
                record(future.result(), slots)
            except KilledWorker:
                lost.append(case["case"])
                record({"status": "worker died"}, slots)
    finally:
        if own_client:
            client.close()
        if cluster is not None:
            cluster.close()
    return lost


RESULT_COLUMNS = ("case", "status", "message", "method", "car", "track", "elapsed_s", "hash",
                  "warm_start_from", "warm_start_distance")


def merge(out, cases=None, write_report=True):
    """Writes OUT/results.csv (and report.html) from the case folders: of ``cases`` (resolved)
    where given, else of every folder there (the shards of a Slurm array joined). Returns the
    counts by status."""
    out = os.fspath(out)
    results = []
    missing = []
    if cases is not None:
        for case in cases:
            r = load_result(out, case)
            if r is None:
                missing.append(case["case"])
            else:
                results.append(r)
    else:
        cases_dir = os.path.join(out, "cases")
        for name in sorted(os.listdir(cases_dir)) if os.path.isdir(cases_dir) else []:
            try:
                with open(os.path.join(cases_dir, name, "result.json")) as f:
                    results.append(json.load(f))
            except (OSError, ValueError):
                continue
    results.sort(key=lambda r: r["index"])
    option_keys = sorted({k for r in results for k in r["inputs"]["options"]})
    override_keys = sorted({k for r in results for k in r["inputs"]["overrides"]})
    output_keys = sorted({k for r in results for k, v in r["summary"].items() if isinstance(v, (int, float)) and not isinstance(v, bool)})
    header = list(RESULT_COLUMNS) + option_keys + override_keys + output_keys
    tmp = os.path.join(out, ".results.csv.tmp-%d" % os.getpid())  # shards may merge at once
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for r in results:
            row = [r["case"], r["status"], r["message"], r["inputs"]["method"], r["inputs"]["car"],
                   r["inputs"]["track"], r["elapsed_s"], r["hash"], r.get("warm_start_from", ""),
                   _cell(r.get("warm_start_distance"))]
            row += [r["inputs"]["options"].get(k, "") for k in option_keys]
            row += [r["inputs"]["overrides"].get(k, "") for k in override_keys]
            row += [_cell(r["summary"].get(k)) for k in output_keys]
            w.writerow(row)
    os.replace(tmp, os.path.join(out, "results.csv"))
    counts = {}
    for r in results:
        counts[r["status"]] = counts.get(r["status"], 0) + 1
    if write_report and results:
        _write_report(out, results, option_keys + override_keys)
    return {"cases": len(results) + len(missing), "results": len(results), "missing": missing,
            "by_status": counts, "warm_started": sum(1 for r in results if r.get("warm_start_from")),
            "results_csv": os.path.join(out, "results.csv")}


def _cell(v):
    return "" if v is None else repr(v) if isinstance(v, float) else v


HEADLINE = ("lap_time_s", "total_time_s", "greedy_total_time_s", "managing_gain_s", "delta_s", "top_speed_mps", "max_front_disc_temp_C",
            "corners.fl.peak_disc_temp_C", "corners.fr.peak_disc_temp_C",
            "corners.fl.peak_tread_temp_C", "corners.rr.peak_tread_temp_C", "corners.rr.wear_total_mm",
            "corners.rr.wear_mm")


def _write_report(out, results, varied_candidates):
    ok = [r for r in results if r["status"] == "ok"]

    def given(r, k):
        return r["inputs"]["options"].get(k, r["inputs"]["overrides"].get(k))

    # The inputs that vary among the cases that ran, and the headline outputs they have.
    inputs = [k for k in varied_candidates if len({str(given(r, k)) for r in ok}) > 1]
    outputs = [k for k in HEADLINE if any(k in r["summary"] for r in ok)]

    def value(r, k):
        v = given(r, k)
        return float(v) if isinstance(v, (int, float)) else float("nan")

    charts = []
    for x in inputs:
        # One line per combination of the other varied inputs (a grid's other axes).
        others = [k for k in inputs if k != x]
        for y in outputs:
            groups = {}
            for r in ok:
                if y in r["summary"] and not math.isnan(value(r, x)):
                    label = ", ".join("%s = %s" % (k, given(r, k)) for k in others) or y
                    groups.setdefault(label, []).append((value(r, x), r["summary"][y]))
            series = [{"label": label, "x": [p[0] for p in sorted(points)], "y": [p[1] for p in sorted(points)]}
                      for label, points in groups.items() if len(points) >= 2]
            if series:
                charts.append({"title": "%s against %s" % (y, x), "x_label": x, "x_unit": "", "y_label": y,
                               "y_unit": "", "series": series})
    order = sorted(results, key=lambda r: (r["status"] != "ok", r["summary"].get("lap_time_s", float("inf"))))
    header = ["case", "status"] + inputs + outputs
    rows = [[r["case"], r["status"]] + ["" if given(r, k) is None else str(given(r, k)) for k in inputs]
            + ["%.6g" % r["summary"][k] if k in r["summary"] else "" for k in outputs] for r in order]
    failed = [r for r in results if r["status"] != "ok"]
    texts = ["%d cases: %d ok, %d not ok. Each output against each varied input (successful cases); the table is sorted by lap time."
             % (len(results), len(ok), len(failed))]
    texts += ["%s: %s: %s" % (r["case"], r["status"], r["message"]) for r in failed]
    hotlap._hotlap._write_report(os.path.join(out, "report.html"), "hotlap sweep: %s" % os.path.basename(os.path.abspath(out)),
                                 [("cases", str(len(results))), ("results", "results.csv")], texts,
                                 [{"title": "Cases by lap time", "header": header, "rows": rows}], charts)


# ---- command line (`hotlap sweep`, or python3 -m hotlap.sweep) ----


def _shard(text):
    try:
        i, n = (int(p) for p in text.split("/"))
    except ValueError:
        raise argparse.ArgumentTypeError("--shard %s: I/N, e.g. 3/16" % text) from None
    if not (1 <= i <= n):
        raise argparse.ArgumentTypeError("--shard %s: I must be in 1..N" % text)
    return i, n


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] == ["merge"]:
        p = argparse.ArgumentParser(prog="hotlap sweep merge", description="Join the case folders of a sweep's shards into results.csv and report.html")
        p.add_argument("out", help="the sweep's --out folder")
        p.add_argument("--json", help="write the summary as JSON")
        a = p.parse_args(argv[1:])
        if not os.path.isdir(os.path.join(a.out, "cases")):
            print("hotlap: error: %s has no cases/ folder" % a.out, file=sys.stderr)
            return 2
        summary = merge(a.out)
        print("merged %d cases: %s; wrote %s and %s" % (summary["results"], summary["by_status"], summary["results_csv"], os.path.join(a.out, "report.html")))
        if a.json:
            _write_json_atomically(a.json, summary)
        return 0
    p = argparse.ArgumentParser(prog="hotlap sweep", description="Run a case table of laps (docs/sweeps.md)")
    p.add_argument("--cases", required=True, help="case table: CSV, or YAML with cases and/or base + grid")
    p.add_argument("--out", required=True, help="output folder (a re-run skips cases already done)")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--local-workers", type=int, help="worker processes of the local dask cluster (default: one per core)")
    where.add_argument("--scheduler", help="an existing dask scheduler, tcp://HOST:PORT")
    where.add_argument("--shard", type=_shard, help="I/N: run cases I, I+N, ... here without dask (a Slurm array task)")
    cache = p.add_mutually_exclusive_group()
    cache.add_argument("--lap-cache", help="the folder of solved laps optimal-lap cases start from and add to (default OUT/laps; may be shared by sweeps)")
    cache.add_argument("--cold", action="store_true", help="every optimal lap from its default start, no lap cache")
    p.add_argument("--json", help="write the summary as JSON")
    a = p.parse_args(argv)
    if a.local_workers is not None and a.local_workers < 1:
        p.error("--local-workers must be >= 1")
    try:
        summary = sweep(a.cases, a.out, local_workers=a.local_workers, scheduler=a.scheduler, shard=a.shard,
                        progress=lambda line: print(line, flush=True), warm_starts=not a.cold,
                        lap_cache=a.lap_cache)
    except KeyboardInterrupt:
        return 130
    except ValueError as e:
        print("hotlap: error: %s" % e, file=sys.stderr)
        return 2
    print("%d cases: %s (%d skipped as done, %d started from a solved lap); wrote %s" % (
        summary["cases"], summary["by_status"], summary["skipped"], summary["warm_started"], summary["results_csv"]))
    if a.json:
        _write_json_atomically(a.json, summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
