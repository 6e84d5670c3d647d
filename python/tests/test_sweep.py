"""Sweeps as a user runs them: from Python on threads, from the command line, and on a Dask cluster of two worker
processes, which must all give the same rows; physics checked against VALIDATION.md R1's closed form."""
import csv
import os
import pickle
import subprocess
import sys
import tempfile

import pytest

import shotlab
from scenes import SOURCE, STUN

CUT = os.path.join(SOURCE, "presets", "cut.json")
G = 9.81


def stun_x(mu, t, v0=2.0):
    """R1's stun shot (2 m/s, no spin, cloth friction mu, no rolling resistance) slides until tau = 2 v0 / (7 mu g),
    then rolls at 5/7 v0: where it is at t."""
    tau = 2 * v0 / (7 * mu * G)
    return v0 * tau - mu * G * tau**2 / 2 + 5 / 7 * v0 * (t - tau)


def without_wall(rows):
    return [{k: v for k, v in r.items() if k != "wall_seconds"} for r in rows]


def test_a_grid_of_cloth_frictions_follows_r1():
    rows = shotlab.sweep(STUN, ["materials.ball_cloth.friction=0.2,0.3,0.4"], duration=1.0, jobs=2)
    assert [r["materials.ball_cloth.friction"] for r in rows] == [0.2, 0.3, 0.4]
    for r in rows:
        assert r["status"] == "ok" and r["time"] == pytest.approx(1.0)
        assert r["cue.x"] == pytest.approx(stun_x(r["materials.ball_cloth.friction"], 1.0), abs=5e-4)
        assert r["cue.motion"] == "rolling"


def test_ball_names_stay_text():
    """The cut's object ball is called "1": the columns naming it hold the text "1", the numbers stay numbers."""
    (row,) = shotlab.sweep(CUT, ["cue.speed=2"])
    assert row["first_ball"] == "1" and row["first_contact"] == "1"
    assert row["pocketed"] == "1@pocket-right-front"
    assert row["cue.speed"] == 2 and isinstance(row["steps"], int) and isinstance(row["1.x"], float)


def test_rows_do_not_depend_on_the_number_of_threads():
    vary = ["cue.speed=1:4:4", "cue.aim_deg=-76,-75,-74"]
    one, two = (shotlab.sweep(CUT, vary, jobs=j) for j in (1, 2))
    assert len(one) == 12 and [r["run"] for r in two] == list(range(12))
    assert without_wall(one) == without_wall(two)
    assert [r["cue.speed"] for r in one[:4]] == [1, 1, 1, 2]  # the first --vary varies slowest
    pots = [r for r in one if r["cue.speed"] == 2 and r["cue.aim_deg"] == -75]
    assert pots[0]["pocketed"] == "1@pocket-right-front" and pots[0]["first_ball"] == "1"


def test_the_command_writes_the_same_rows():
    vary = ["cue.speed=1.5:2.5:3", "materials.ball_ball.friction=0,0.06"]
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "sweep.csv")
        args = [os.environ["SHOTLAB_BIN"], "sweep", CUT, "--jobs", "2", "--out", out, "-q"]
        subprocess.run(args + [a for v in vary for a in ("--vary", v)], check=True)
        with open(out, newline="") as f:
            theirs = list(csv.DictReader(f))
    mine = shotlab.sweep(CUT, vary)
    assert without_wall(mine) == without_wall(shotlab.rows(",".join(theirs[0].keys()) + "\n",
                                                           [",".join(r.values()) + "\n" for r in theirs]))


def test_wide_random_sampling_finishes_with_a_row_per_run():
    vary = ["cue.speed=0.01:40", "cue.aim_deg=-180:180", "cue.side=-0.9:0.9", "cue.elevation_deg=0:60",
            "materials.ball_cloth.friction=-0.5:3", "materials.ball_ball.stiffness=1e3:1e12"]
    rows = shotlab.sweep(os.path.join(SOURCE, "presets", "break.json"), vary, samples=24, seed=7, timeout=5,
                         max_events=20000, jobs=2)
    assert len(rows) == 24
    statuses = {r["status"] for r in rows}
    assert statuses <= {"ok", "error", "limit", "step_limit", "non_finite", "unstable"}, statuses
    assert "ok" in statuses and "error" in statuses  # negative frictions are refused, row by row
    for r in rows:
        assert (r["status"] == "ok") == (r["reason"] == "")
    again = shotlab.sweep(os.path.join(SOURCE, "presets", "break.json"), vary, samples=24, seed=7, timeout=5,
                          max_events=20000, jobs=1)
    assert [r["cue.speed"] for r in again] == [r["cue.speed"] for r in rows]  # the seed fixes the plan


def test_bad_sweeps_are_input_errors():
    with pytest.raises(shotlab.InputError, match="PATH=VALUES"):
        shotlab.Sweep(CUT, ["cue.speed"])
    with pytest.raises(shotlab.InputError, match="lo:hi:n"):
        shotlab.Sweep(CUT, ["cue.speed=1:2"])
    with pytest.raises(shotlab.InputError, match="more than"):
        shotlab.Sweep(CUT, ["cue.speed=0:1:100000", "cue.aim_deg=0:1:1000"])
    with pytest.raises(ValueError, match="jobs"):  # the command refuses --jobs -1 too
        shotlab.sweep(CUT, ["cue.speed=1,2"], jobs=-1)


def test_a_sweep_pickles_to_the_same_rows():
    s = shotlab.Sweep(CUT, ["cue.speed=1,2"])
    t = pickle.loads(pickle.dumps(s))
    assert len(t) == 2 and t.header == s.header
    assert [l.split(",")[2:4] for l in t.lines()] == [l.split(",")[2:4] for l in s.lines()]


def test_dask_cluster_gives_the_threaded_rows():
    try:
        from dask import distributed
    except ImportError:
        pytest.fail("Dask is missing: scripts/setup.sh installs python3-distributed")
    import shotlab.cluster

    vary = ["cue.speed=1:3:5", "cue.aim_deg=-76:-74:3"]
    threaded = shotlab.sweep(CUT, vary, jobs=2)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as lc, \
            distributed.Client(lc) as client:
        assert len(client.nthreads()) == 2
        farmed = shotlab.cluster.sweep(client, CUT, vary, chunk_size=4)  # 4 chunks over 2 workers
        workers = client.run(os.getpid)
        assert len(set(workers.values())) == 2 and os.getpid() not in workers.values()
        with tempfile.TemporaryDirectory() as d:  # the command-line form, pointed at the cluster's scheduler
            out = os.path.join(d, "rows.csv")
            args = [sys.executable, "-m", "shotlab.cluster", CUT, "--scheduler", lc.scheduler_address, "--out", out]
            subprocess.run(args + [a for v in vary for a in ("--vary", v)], check=True)
            with open(out, newline="") as f:
                text = f.read()
    assert without_wall(farmed) == without_wall(threaded)
    header, *lines = text.splitlines(keepends=True)
    assert without_wall(shotlab.rows(header, lines)) == without_wall(threaded)
