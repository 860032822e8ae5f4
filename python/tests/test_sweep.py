"""hotlap.sweep on a real dask LocalCluster (two worker processes): the same results as a serial
run, a killed worker's case run again, a failing case recorded, a resumed sweep redoing nothing;
optimal laps started from their solved neighbours and the lap cache reused."""

import json
import os
import signal
import threading
import time

import pytest

import hotlap.sweep as sweep

distributed = pytest.importorskip("distributed")

QSS = [{"case": "c%d" % k, "method": "qss", "laps": 1, "ambient_temp_C": 15.0 + 5.0 * k} for k in range(4)]


def _results(out):
    """{case: (result.json without its timing, bytes of every other file)}."""
    found = {}
    for name in sorted(os.listdir(os.path.join(out, "cases"))):
        folder = os.path.join(out, "cases", name)
        with open(os.path.join(folder, "result.json")) as f:
            result = json.load(f)
        result.pop("elapsed_s")
        files = {}
        for file in sorted(os.listdir(folder)):
            if file != "result.json":
                with open(os.path.join(folder, file), "rb") as f:
                    files[file] = f.read()
        found[name] = (result, files)
    return found


def test_two_workers_give_the_serial_results_bit_for_bit(tmp_path):
    parallel = sweep.sweep(QSS, tmp_path / "dask", local_workers=2, progress=None)
    serial = sweep.sweep(QSS, tmp_path / "serial", shard=(1, 1), progress=None)
    assert parallel["by_status"] == {"ok": 4} == serial["by_status"]
    assert _results(tmp_path / "dask") == _results(tmp_path / "serial")
    assert (tmp_path / "dask" / "report.html").stat().st_size > 10000
    with open(tmp_path / "dask" / "results.csv") as f:
        rows = f.read().splitlines()
    assert rows[0].startswith("case,status,message,method,car,track,elapsed_s,hash,warm_start_from,"
                              "warm_start_distance,ambient_temp_C,laps,")
    assert len(rows) == 5 and rows[1].startswith("c0,ok,,qss,gen7,darlington,")


def test_a_failing_case_is_recorded_and_the_rest_finish(tmp_path):
    cases = QSS[:2] + [{"case": "no-laps", "method": "qss", "laps": 0},
                       {"case": "worn-out", "method": "stint", "laps": 2, "wear_scale": -1.0},
                       {"case": "typo", "method": "qss", "laps": 1, "brakes.fl.duct_factr": 0.8}]
    summary = sweep.sweep(cases, tmp_path, local_workers=2, progress=None)
    assert summary["by_status"] == {"ok": 2, "bad input": 3}
    with open(tmp_path / "cases" / "worn-out" / "result.json") as f:
        assert "wear scale: -1" in json.load(f)["message"]
    with open(tmp_path / "cases" / "no-laps" / "result.json") as f:
        result = json.load(f)
    assert result["status"] == "bad input" and "laps 0 must be in [1, 1000]" in result["message"]
    with open(tmp_path / "cases" / "typo" / "result.json") as f:
        result = json.load(f)
    assert result["status"] == "bad input" and "brakes.fl.duct_factor" in result["message"]


def test_overrides_vary_the_car(tmp_path):
    cases = [{"case": "d%d" % k, "method": "qss", "laps": 1, "brakes.fl.duct_factor": f} for k, f in enumerate((0.5, 1.0, 2.0))]
    summary = sweep.sweep(cases, tmp_path, shard=(1, 1), progress=None)
    assert summary["by_status"] == {"ok": 3}
    disc = []
    for k in range(3):
        with open(tmp_path / "cases" / ("d%d" % k) / "result.json") as f:
            result = json.load(f)
        assert result["summary"]["overrides.brakes.fl.duct_factor"] == (0.5, 1.0, 2.0)[k]
        disc.append(result["summary"]["corners.fl.peak_disc_temp_C"])
    # Less cooling air, a hotter front-left disc.
    assert disc[0] > disc[1] > disc[2]


def test_a_resumed_sweep_redoes_nothing(tmp_path):
    sweep.sweep(QSS, tmp_path, shard=(1, 1), progress=None)
    stamps = {n: os.stat(tmp_path / "cases" / n / "result.json").st_mtime_ns for n in ("c0", "c1", "c2", "c3")}
    again = sweep.sweep(QSS, tmp_path, local_workers=2, progress=None)
    assert again["skipped"] == 4 and again["ran"] == 0 and again["by_status"] == {"ok": 4}
    assert stamps == {n: os.stat(tmp_path / "cases" / n / "result.json").st_mtime_ns for n in stamps}
    # A changed case (its inputs' hash) is run again; the others are not.
    changed = [dict(c) for c in QSS]
    changed[2]["ambient_temp_C"] = 40.0
    third = sweep.sweep(changed, tmp_path, shard=(1, 1), progress=None)
    assert third["skipped"] == 3 and third["ran"] == 1


def _processing_transitions(dask_scheduler, key):
    """How many times the scheduler sent the task `key` to a worker (its transition log)."""
    return sum(1 for t in dask_scheduler.transition_log if t[0] == key and t[2] == "processing")


def test_a_worker_killed_during_a_case_leaves_every_case_done(tmp_path):
    import dask
    from distributed import Client, LocalCluster

    # Optimal laps on a coarse mesh: a few seconds each, long enough to be killed in.
    cases = [{"case": "o%d" % k, "method": "ocp", "step_m": 30.0, "coarse_step_m": 0.0, "ambient_temp_C": 20.0 + k}
             for k in range(3)]
    with dask.config.set({"distributed.scheduler.allowed-failures": 2}):
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    killed = []  # (pid, the cases its worker was running when it was killed)

    def kill_one_busy_worker():
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not killed:
            busy = [w for w, tasks in client.processing().items() if tasks]
            if busy:
                time.sleep(0.5)  # well inside the case
                pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
                running = list(client.processing().get(busy[0], ()))
                if running:  # still in a case: killed in it
                    os.kill(pid, signal.SIGKILL)
                    killed.append((pid, running))
            time.sleep(0.05)

    killer = threading.Thread(target=kill_one_busy_worker)
    killer.start()
    try:
        summary = sweep.sweep(cases, tmp_path, scheduler=client, progress=None)
        # What the scheduler did with the cases the killed worker was running.
        sent = {key: client.run_on_scheduler(_processing_transitions, key=key)
                for _, running in killed for key in running}
    finally:
        killer.join()
        client.close()
        cluster.close()
    assert killed, "no worker was busy to kill"
    assert summary["by_status"] == {"ok": 3} and summary["lost"] == [] and summary["ran"] == 3
    # The case it was running went to a worker again (not just finished before the kill), and
    # every case has its result.
    assert sent and all(n >= 2 for n in sent.values()), "the killed case was not run again: %s" % sent
    for case in cases:
        with open(tmp_path / "cases" / case["case"] / "result.json") as f:
            assert json.load(f)["status"] == "ok"


def test_case_tables_are_checked_with_suggestions(tmp_path):
    table = tmp_path / "cases.csv"
    table.write_text("case,method,ambient_temp,brake_system.front_share\na,qss,20,0.6\n")
    with pytest.raises(ValueError, match=r"unknown column 'ambient_temp' \(did you mean 'ambient_temp_C'"):
        sweep.sweep(table, tmp_path / "out", shard=(1, 1), progress=None)
    with pytest.raises(ValueError, match="method 'lap' is not one of"):
        sweep.resolve_cases([{"method": "lap"}])
    with pytest.raises(ValueError, match="option disc_limit_C does not apply to method qss"):
        sweep.resolve_cases([{"method": "qss", "disc_limit_C": 500}])
    # The adaptive mesh is for single laps; a stint keeps its fixed mesh.
    assert sweep.resolve_cases([{"method": "ocp", "tolerance_s": 1e-3}])[0]["options"]["tolerance_s"] == 1e-3
    with pytest.raises(ValueError, match="option tolerance_s does not apply to method stint"):
        sweep.resolve_cases([{"method": "stint", "tolerance_s": 1e-3}])
    afile = tmp_path / "afile"
    afile.write_text("")
    with pytest.raises(ValueError, match="exists and is not a folder"):
        sweep.sweep(QSS[:1], afile, shard=(1, 1), progress=None)
    grid = tmp_path / "grid.yaml"
    grid.write_text("base: {method: qss, laps: 1}\ngrid:\n  ambient_temp_C: [20, 30]\n  track_temp_C: [30, 40, 50]\n")
    rows = sweep.read_cases(grid)
    assert len(rows) == 6 and rows[1] == {"method": "qss", "laps": 1, "ambient_temp_C": 20, "track_temp_C": 40}


def test_a_stint_case_runs_and_reports_its_totals(tmp_path):
    cases = [{"case": "s", "method": "stint", "laps": 2, "step_m": 30.0, "coarse_step_m": 0.0,
              "wear_scale": 5.0, "fuel_kg": 20.0}]
    summary = sweep.sweep(cases, tmp_path, shard=(1, 1), progress=None)
    assert summary["by_status"] == {"ok": 1}
    with open(tmp_path / "cases" / "s" / "result.json") as f:
        result = json.load(f)
    total = result["summary"]["total_time_s"]
    assert 50.0 < total < 70.0
    assert result["summary"]["greedy_total_time_s"] >= total - 2e-3
    with open(tmp_path / "results.csv") as f:
        header = f.readline().strip().split(",")
    assert "total_time_s" in header and "managing_gain_s" in header
    assert (tmp_path / "cases" / "s" / "stint.csv").stat().st_size > 10000


def test_race_cases_run_and_more_pit_loss_never_adds_a_stop(tmp_path):
    base = {"method": "race", "laps": 60, "stages": "20,40", "fall_off_laps": 6, "step_m": 4.0,
            "races": 200}
    cases = [dict(base, case="cheap", pit_loss_s=20.0), dict(base, case="dear", pit_loss_s=60.0)]
    summary = sweep.sweep(cases, tmp_path, shard=(1, 1), progress=None)
    assert summary["by_status"] == {"ok": 2}
    stops = {}
    for name in ("cheap", "dear"):
        with open(tmp_path / "cases" / name / "result.json") as f:
            result = json.load(f)
        assert result["summary"]["policy.monte_carlo.races"] == 200
        stops[name] = result["summary"]["policy.monte_carlo.mean_stops"]
        with open(tmp_path / "cases" / name / "fall_off.csv") as f:
            assert f.readline().strip() == "age_laps,lap_time_s,heat_only_lap_time_s"
            assert len(f.readlines()) == 6
    assert stops["dear"] <= stops["cheap"]
    with open(tmp_path / "results.csv") as f:
        assert "plan.race_time_s" in f.readline().strip().split(",")


# ---- warm starts ----


def test_a_grid_is_ordered_so_each_case_has_a_solved_neighbour():
    rows = [{"case": "g%d%d" % (i, j), "method": "ocp", "brakes.fl.duct_factor": 0.8 + 0.2 * i,
             "brake_system.front_share": 0.55 + 0.05 * j} for i in range(3) for j in range(3)]
    rows.insert(4, {"case": "q", "method": "qss"})
    cases = sweep.resolve_cases(rows)
    scales = sweep.coordinate_scales(cases)
    ordered = sweep.order_for_warm_starts(cases, scales)
    assert sorted(c["case"] for c in ordered) == sorted(c["case"] for c in cases)
    assert ordered[0]["case"] == "q"  # cases without warm starts first
    grid = ordered[1:]
    assert grid[0]["case"] == "g00"  # the family's first case of the table
    # One grid step is half the spread: every case is one step from the case before it.
    for before, case in zip(grid, grid[1:]):
        assert sweep.distance(sweep.coordinates(before), sweep.coordinates(case), scales) == pytest.approx(0.5)


def _lap(out, name):
    with open(os.path.join(out, "cases", name, "result.json")) as f:
        r = json.load(f)
    return r, r["summary"]


def test_optimal_laps_start_from_their_solved_neighbours_and_the_cache_is_reused(tmp_path):
    cases = [{"case": "b%d" % k, "method": "ocp", "step_m": 30.0, "coarse_step_m": 0.0, "disc_limit_C": 500.0,
              "brake_system.front_share": 0.55 + 0.05 * k} for k in range(3)]
    warm = sweep.sweep(cases, tmp_path / "warm", shard=(1, 1), progress=None)
    cold = sweep.sweep(cases, tmp_path / "cold", shard=(1, 1), progress=None, warm_starts=False)
    assert warm["by_status"] == cold["by_status"] == {"ok": 3}
    assert (warm["warm_started"], cold["warm_started"]) == (2, 0)
    assert not os.path.exists(tmp_path / "cold" / "laps")
    for k, source in ((0, ""), (1, "b0"), (2, "b1")):
        w, ws = _lap(tmp_path / "warm", "b%d" % k)
        c, cs = _lap(tmp_path / "cold", "b%d" % k)
        assert w["warm_start_from"] == source
        assert cs["started_from"] == "the QSS guess"
        if source:
            assert w["warm_start_distance"] == pytest.approx(0.5)
            # b1 had one cached lap to try (b0's), b2 two (b1's nearest)
            assert ws["started_from"] == ("the saved lap" if k == 1 else "saved lap 1")
            # From a neighbour a fraction of the iterations, to a lap within 10 ms of the cold one
            # (another local optimum of the same lap is a few ms away on a 30 m mesh).
            assert ws["ipopt_iterations"] < 0.5 * cs["ipopt_iterations"]
            assert abs(ws["lap_time_s"] - cs["lap_time_s"]) < 0.01
    with open(tmp_path / "warm" / "results.csv") as f:
        header = f.readline().strip().split(",")
    assert header[8:10] == ["warm_start_from", "warm_start_distance"]
    # Another sweep on the same lap cache: the same inputs start from their own laps.
    again = sweep.sweep(cases[1:2], tmp_path / "again", shard=(1, 1), progress=None,
                        lap_cache=tmp_path / "warm" / "laps")
    r, s = _lap(tmp_path / "again", "b1")
    assert again["warm_started"] == 1
    assert (r["warm_start_from"], r["warm_start_distance"]) == ("b1", 0.0)
    assert s["ipopt_iterations"] <= 5
    assert s["lap_time_s"] == pytest.approx(_lap(tmp_path / "warm", "b1")[1]["lap_time_s"], abs=1e-4)
    # A cached lap that cannot be read is no start: the next nearest is.
    laps = tmp_path / "warm" / "laps"
    b0 = [p for p in laps.glob("*.json") if json.loads(p.read_text())["name"] == "b0"]
    assert len(b0) == 1
    b0[0].with_suffix(".lap").write_bytes(b"not a lap")
    near_b0 = [dict(cases[0], case="c", **{"brake_system.front_share": 0.56})]
    sweep.sweep(near_b0, tmp_path / "after", shard=(1, 1), progress=None, lap_cache=laps)
    r, s = _lap(tmp_path / "after", "c")
    # b0's lap was the nearest: b1's is left, the only one to try.
    assert (r["status"], r["warm_start_from"], s["started_from"]) == ("ok", "b1", "the saved lap")
