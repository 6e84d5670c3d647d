"""The Python module as a user calls it: VALIDATION.md R1 through it, numpy arrays, overrides, run() against the
command line's own --out, and errors as Python exceptions."""
import json
import os
import subprocess
import tempfile
import warnings

import numpy as np
import pytest

import shotlab
from scenes import R, SOURCE, STUN


def test_stun_shot_slides_then_rolls():
    sim = shotlab.Simulation(STUN)
    while not any(e["kind"] == "rolling" for e in sim.events):
        sim.advance(1 / 60)
    tau = next(e["time"] for e in sim.events if e["kind"] == "rolling")
    again = shotlab.Simulation(json.dumps(STUN))  # JSON text works as well as a dict
    again.advance(tau)
    assert tau == pytest.approx(0.29125, rel=0.005)
    assert again.positions[0, 0] == pytest.approx(0.49928, rel=0.005)
    assert again.velocities[0, 0] == pytest.approx(1.42857, rel=0.005)


def test_a_frame_loop_with_no_time_to_spare_gets_the_same_break():
    """advance_within with no wall time takes a step a call: the break's first 0.3 s in many calls ends where one
    advance puts it."""
    scene = os.path.join(SOURCE, "presets", "break.json")
    whole = shotlab.Simulation(scene)
    whole.advance(0.3)
    sliced = shotlab.Simulation(scene)
    calls = 0
    while sliced.time < 0.3:
        reached = sliced.advance_within(0.3 - sliced.time, 0.0, go_on=calls > 0)
        assert reached == sliced.time
        calls += 1
    assert calls > 100 and sliced.time == 0.3
    assert np.abs(sliced.positions - whole.positions).max() < 1e-9
    assert np.abs(sliced.velocities - whole.velocities).max() < 1e-9
    with pytest.raises(ValueError, match="wall_seconds"):
        sliced.advance_within(0.1, float("nan"))


def test_states_are_numpy_arrays():
    sim = shotlab.Simulation(os.path.join(SOURCE, "presets", "break.json"))
    n = len(sim.ids)
    assert n == 16 and sim.ids[0] == "cue"
    for a in (sim.positions, sim.velocities, sim.spins):
        assert isinstance(a, np.ndarray) and a.shape == (n, 3)
    assert sim.in_play.dtype == bool and sim.in_play.all()
    sim.advance(0.5)
    assert np.linalg.norm(sim.velocities, axis=1).max() > 0.1  # the rack is broken
    assert sim.stats["steps"] > 0


def test_overrides_by_path_as_set_takes_them():
    slow = shotlab.Simulation(STUN, ["materials.ball_cloth.friction=0.4"])
    while not any(e["kind"] == "rolling" for e in slow.events):
        slow.advance(1 / 60)
    tau = next(e["time"] for e in slow.events if e["kind"] == "rolling")
    assert tau == pytest.approx(0.29125 / 2, rel=0.005)  # twice the friction, half the time


def test_run_returns_what_the_command_writes():
    scene = os.path.join(SOURCE, "presets", "cut.json")
    mine = shotlab.run(scene, until_rest=True)
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "r.json")
        subprocess.run([os.environ["SHOTLAB_BIN"], "run", scene, "--until-rest", "--out", out, "-q"], check=True)
        theirs = json.load(open(out))
    for result in (mine, theirs):
        result["stats"].pop("wall_seconds")
    assert mine == theirs
    assert any(e["kind"] == "pocketed" for e in mine["events"])


def test_errors_are_exceptions_that_name_the_field():
    bad = dict(STUN, balls=[{"id": "a", "position": [0, R, 0], "mass": -1}])
    with pytest.raises(ValueError, match=r"balls\[0\]\.mass"):
        shotlab.Simulation(bad)
    with pytest.raises(ValueError, match="frction"):
        shotlab.Simulation(STUN, ["materials.ball_cloth.frction=0.3"])
    with pytest.raises(ValueError):
        shotlab.Simulation(STUN).advance(-1)
    for endless in (float("inf"), float("nan")):  # a user trial's advance(inf) left the clock at inf
        with pytest.raises(ValueError, match="finite"):
            shotlab.Simulation(STUN).advance(endless)
    with pytest.raises(ValueError, match="cannot open"):
        shotlab.run("/nonexistent/scene.json")


def test_a_dict_may_hold_numpy_values_and_its_bad_numbers_are_named():
    """A user trial's dict with a NaN was reported as malformed JSON, and one with a numpy array was refused."""
    scene = dict(STUN, balls=[{"id": "cue", "position": np.array([0, R, 0]), "velocity": [np.float64(2), 0, 0]}])
    moving = shotlab.Simulation(scene)
    moving.advance(0.1)
    assert moving.velocities[0, 0] == pytest.approx(2 - 0.2 * 9.81 * 0.1, rel=1e-3)  # sliding: a = mu g
    for bad in (float("nan"), np.inf):
        with pytest.raises(shotlab.InputError, match=r"balls\[0\]\.velocity\[1\]: must be a finite number"):
            shotlab.Simulation(dict(STUN, balls=[{"id": "cue", "position": [0, R, 0], "velocity": [2, bad, 0]}]))
    with pytest.raises(TypeError, match=r"balls\[0\]\.id: a set is not a scene value"):
        shotlab.Simulation(dict(STUN, balls=[{"id": {"cue"}, "position": [0, R, 0]}]))
    # A review's cases: a list holding itself, an integer past 64 bits, numpy's booleans.
    endless = []
    endless.append(endless)
    with pytest.raises(shotlab.InputError, match="nested deeper than 64 levels"):
        shotlab.Simulation(dict(STUN, balls=endless))
    with pytest.raises(shotlab.InputError, match=r"balls\[0\]\.mass: the integer 18446744073709551616 is past 64 bits"):
        shotlab.Simulation(dict(STUN, balls=[{"id": "cue", "position": [0, R, 0], "mass": 2 ** 64}]))
    allowed = dict(STUN, allow_overlap=np.array([True]).any(),
                   balls=[{"id": "a", "position": [0, R, 0]}, {"id": "b", "position": [0.01, R, 0]}])
    assert shotlab.Simulation(allowed).ids == ["a", "b"]


def test_the_scenes_miscue_is_an_event_and_misspellings_get_the_nearest_name():
    cut = os.path.join(SOURCE, "presets", "cut.json")
    sim = shotlab.Simulation(cut, ["cue.side=0.6"])
    assert sim.events[0] == {"time": 0.0, "kind": "miscue", "bodies": ["cue"]}
    with pytest.raises(shotlab.InputError, match="cue.sped: unknown field \\(did you mean 'speed'\\?\\)"):
        shotlab.Simulation(cut, ["cue.sped=3"])
    with pytest.raises(TypeError, match="vary: a list of PATH=VALUES strings, got a lone string"):
        shotlab.sweep(cut, "cue.speed=1:3:3")


def test_a_scene_is_a_path_text_or_a_dict_and_nothing_else():
    import pathlib
    cut = os.path.join(SOURCE, "presets", "cut.json")
    assert list(shotlab.Simulation(pathlib.Path(cut)).ids) == ["cue", "1"]
    for wrong in (None, 3, b"{}"):
        with pytest.raises(TypeError, match="scene: a path, JSON text or a dict, got " + type(wrong).__name__):
            shotlab.Simulation(wrong)


def test_the_rigid_model_is_a_switch_away():
    # A developer sweeping cut shots picks the rigid model for speed and checks where it lands against the soft one.
    scene = os.path.join(SOURCE, "presets", "cut.json")
    soft = shotlab.run(scene, until_rest=True)
    rigid = shotlab.run(scene, ["model.contact=rigid"], until_rest=True)
    assert rigid["stats"]["rhs_evaluations"] == 0 and soft["stats"]["rhs_evaluations"] > 0
    pocketed = [[b["id"] for b in r["balls"] if b["motion"] == "pocketed"] for r in (soft, rigid)]
    assert pocketed[0] == pocketed[1] == ["1"]
    # The stun preset: both models stop the cue ball dead on the object ball, which they pocket.
    stun = os.path.join(SOURCE, "presets", "stun.json")
    ends = [shotlab.run(stun, o, until_rest=True)["balls"][0]["position"] for o in ([], ["model.contact=rigid"])]
    assert np.linalg.norm(np.subtract(ends[0], ends[1])[[0, 2]]) < 0.005  # m
    with pytest.raises(ValueError, match="model.contact.*hop"):
        shotlab.run(os.path.join(SOURCE, "presets", "jump.json"), ["model.contact=rigid"])


def test_a_run_to_rest_cut_short_says_so_as_the_command_does():
    scene = os.path.join(SOURCE, "presets", "cut.json")  # its balls rest at about 5.8 s
    with pytest.warns(RuntimeWarning, match=r"balls still move at t = 1 s, where the run ends"):
        shotlab.run(scene, duration=1.0, until_rest=True)
    done = subprocess.run([os.environ["SHOTLAB_BIN"], "run", scene, "--until-rest", "--duration", "1", "-q"],
                          capture_output=True, text=True, check=True)
    assert "balls still move at t = 1 s, where the run ends" in done.stderr
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # neither a run to its rest nor one of a set length warns
        shotlab.run(scene, until_rest=True)
        shotlab.run(scene, duration=1.0)
