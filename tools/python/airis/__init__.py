"""airis: in-process aerial-robot simulation for Python (docs/python.md).

    import airis
    sim = airis.Simulation("scenes/empty.yaml", seed=1)
    v = sim.vehicles["drone1"]
    v.set_position([0, 0, -5])
    sim.run_for(5.0)
    print(v.state.position_ned_m, v.sensors["imu"].since_last()[-3:])

Everything runs in this process, on the calling thread: no server, no RPC. Arrays are NumPy; frames
and units are in the names (NED world, FRD body, metres, seconds, radians unless `_deg`).
"""

import os as _os

from . import _airis
from ._airis import (  # noqa: F401  (re-exported)
    AutopilotLinkError,
    Camera,
    ConfigError,
    DatasetIoError,
    Frame,
    Sensor,
    SimulationError,
    StereoFrame,
    Vehicle,
    VehicleState,
    env_at,
)
from ._yaml import dump as _dump_yaml
from ._yaml import flow as _flow_yaml

__version__ = _airis.__version__

__all__ = [
    "Simulation", "Vehicle", "VehicleState", "Sensor", "Camera", "Frame", "StereoFrame",
    "ConfigError", "SimulationError", "DatasetIoError", "AutopilotLinkError", "env_at", "scene_stats", "check_scene",
    "Dataset", "HoverEnv", "WaypointsEnv", "ForestEnv", "VectorEnv", "make", "make_vec",
]


def _scene_source(scene, name):
    """(path, text) for a scene given as a file path, YAML text or a dict."""
    if isinstance(scene, dict):
        return (name or "<dict>"), _dump_yaml(scene)
    if isinstance(scene, _os.PathLike):
        return _os.fspath(scene), ""
    if not isinstance(scene, str):
        raise TypeError(f"scene: expected a path, YAML text or a dict (got {type(scene).__name__})")
    if "\n" in scene or (":" in scene and not scene.endswith((".yaml", ".yml"))):
        return (name or "<string>"), scene
    return scene, ""


class _Mapping(dict):
    """A dict whose missing keys raise KeyError listing the names there are."""

    def __init__(self, kind, owner, items):
        super().__init__(items)
        self._what = f"{kind} of {owner}"

    def __missing__(self, key):
        raise KeyError(f"no {self._what} named {key!r} (there are: {', '.join(self) or 'none'})")


class Simulation(_airis._Simulation):
    """A scene loaded and built, stepped in lockstep at its physics rate (1 kHz by default).

    `scene` is a file path, YAML text or a dict with the file's keys; `seed` replaces the scene's
    seed before any generator runs (same scene + seed = the same numbers, bit for bit, as `airis
    run`). `name` names text or dict scenes in error messages and anchors their relative paths
    (default "<string>" / "<dict>", relative to the working directory). Each sensor keeps at most
    `max_samples` unread samples (the oldest are dropped beyond it, counted in Sensor.dropped).
    `overrides` replaces keys of the scene before it is validated, as `airis run --set` does:
    `{"scene.lighting.sun_elevation_deg": 20, "scene.environment.wind.mean_ned_m_s": [5, 0, 0]}`
    (docs/scene-format.md, "Overrides"). `threads` (1 to 64) step the vehicles (their physics,
    sensors and controllers) as `airis run --threads` does: worth it from a few dozen vehicles, and
    the results do not depend on it. Raises ConfigError (`file:line:col: key: problem`, or
    `--set KEY=VALUE: key: problem`) for bad input.
    """

    def __init__(self, scene, seed=None, *, name=None, max_samples=100000, overrides=None,
                 threads=1):
        path, text = _scene_source(scene, name)
        if overrides is not None and not isinstance(overrides, dict):
            raise TypeError(f"overrides: expected a dict of key path -> value "
                            f"(got {type(overrides).__name__})")
        texts = [f"{key}={_flow_yaml(value)}" for key, value in (overrides or {}).items()]
        super().__init__(path, text, seed, max_samples, texts, threads)
        self._text = text
        handles = self.vehicle_handles
        for v in handles:
            sensors, cameras = {}, {}
            for s in v.sensor_handles:
                if s.is_camera:
                    cameras[s.name] = Camera(s)
                else:
                    sensors[s.name] = s
            v.sensors = _Mapping("sensor", f"vehicle '{v.name}'", sensors)
            v.cameras = _Mapping("camera", f"vehicle '{v.name}'", cameras)
        self._vehicles = _Mapping("vehicle", "the scene", {h.name: h for h in handles})

    @property
    def vehicles(self):
        """Vehicles by name (airis.Vehicle), in the scene's order."""
        return self._vehicles

    def stats(self):
        """Counts and sizes of this simulation's scene (as `airis scene stats --json`)."""
        return _airis._scene_stats(self.scene_path, self._text, self.seed)

    def __repr__(self):
        return (f"<airis.Simulation {self.scene_path!r} t={self.time_s:.3f} s, "
                f"{len(self._vehicles)} vehicle(s)>")



def scene_stats(scene, seed=None, *, name=None):
    """Counts and sizes of a scene (path, YAML text or dict), as `airis scene stats --json`."""
    path, text = _scene_source(scene, name)
    return _airis._scene_stats(path, text, seed)


def check_scene(scene, seed=None, *, name=None):
    """Loads a scene to check it: True, or ConfigError naming file, line, column and key."""
    scene_stats(scene, seed, name=name)
    return True


from .dataset import Dataset  # noqa: E402
from .envs import ForestEnv, HoverEnv, VectorEnv, WaypointsEnv, make, make_vec  # noqa: E402
