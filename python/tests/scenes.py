"""Scenes the Python tests share."""
import os

SOURCE = os.environ.get("SHOTLAB_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
R = 0.028575

# R1: a pool ball at 2 m/s without spin on a cloth of friction 0.2 (no rolling resistance or spin friction while it
# slides, friction smoothing 1e4 s/m) rolls from t = 2 v0 / (7 mu g) = 0.29125 s at x = 0.49928 m, v = 1.42857 m/s.
STUN = {
    "colliders": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "ball_cloth"}],
    "materials": {"ball_cloth": {"friction": 0.2, "rolling_resistance": 0, "spin_friction": 0}},
    "model": {"friction_sharpness": 1e4},
    "integrator": {"method": "dopri5", "abs_tol": 1e-10, "rel_tol": 1e-10, "max_steps_per_call": 1000000},
    "balls": [{"id": "cue", "position": [0, R, 0], "velocity": [2, 0, 0]}],
}
