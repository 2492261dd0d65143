"""Gymnasium environments over airis's vectorized C++ environments (docs/python.md).

Every environment is a batch of independent worlds stepped in C++ (airis._airis._VectorEnv): the
single environments (HoverEnv, WaypointsEnv, ForestEnv) are a batch of one, VectorEnv is a batch
of N with Gymnasium's vector conventions. With the gymnasium package installed the classes derive
from gymnasium.Env / gymnasium.vector.VectorEnv and use its spaces; without it they provide the
same methods and attributes with airis.spaces.Box / Dict.
"""

import os

import numpy as np

from . import _airis
from ._build_info import SOURCE_DIR
from .spaces import make_box, make_dict

try:  # pragma: no cover - depends on the machine
    import gymnasium as _gym
    _EnvBase = _gym.Env
    _VectorBase = _gym.vector.VectorEnv
except ImportError:
    _gym = None
    _EnvBase = object
    _VectorBase = object

__all__ = ["HoverEnv", "WaypointsEnv", "ForestEnv", "VectorEnv", "make", "make_vec"]



def _default_scene(name):
    """A scene of the repository's scenes/ folder: AIRIS_SCENES, else beside the source tree."""
    root = os.environ.get("AIRIS_SCENES")
    if root is None:
        # The source tree the package was built from (written by CMake), then the working folder.
        for candidate in (os.path.join(SOURCE_DIR, "scenes"), os.path.join(os.getcwd(), "scenes")):
            if os.path.isdir(candidate):
                root = candidate
                break
    if root is None:
        raise FileNotFoundError(f"cannot find scenes/{name}: set AIRIS_SCENES or pass scene=")
    return os.path.join(root, name)


# Default settings of each task (docs/python.md, "Environments").
_TASK_DEFAULTS = {
    "hover": {"scene": "empty.yaml"},
    "waypoints": {"scene": "empty.yaml", "target_ned_m": [0.0, 0.0, -4.0]},
    "forest": {"scene": "forest_flight.yaml", "camera": "front", "image": "depth",
               "target_ned_m": [0.0, 0.0, -3.0], "goal_distance_m": 60.0,
               "max_distance_m": 6.0, "max_episode_steps": 400, "control_rate_hz": 10.0},
}


class _Batch:
    """The C++ batch and the spaces of one of its environments."""

    def __init__(self, task, num_envs, scene, seed, options):
        settings = dict(_TASK_DEFAULTS[task])
        settings.update(options)
        scene = settings.pop("scene") if scene is None else scene
        if isinstance(scene, str) and "\n" not in scene and not os.path.exists(scene) \
                and not os.path.isabs(scene) and os.sep not in scene:
            scene = _default_scene(scene)
        from . import _scene_source
        path, text = _scene_source(scene, None)
        settings["task"] = task
        settings["num_envs"] = num_envs
        self.env = _airis._VectorEnv(path, text, seed, settings)
        obs = self.env.observation_size
        self.state_space = make_box(-np.inf, np.inf, (obs,), np.float32)
        low, high = self.env.action_bounds()
        self.action_space = make_box(low, high, low.shape, np.float32)
        shape = self.env.image_shape
        if shape is None:
            self.observation_space = self.state_space
        else:
            if self.env.image_kind == "rgb":
                image = make_box(0, 255, shape, np.uint8)
            else:
                image = make_box(0.0, self.env.max_depth_m, shape, np.float32)
            self.observation_space = make_dict({"state": self.state_space, "image": image})

    def observation(self, state, images):
        if images is None:
            return state
        return {"state": state, "image": images}


class _SingleEnv(_EnvBase):
    """One environment of a task, Gymnasium's Env API (reset / step / render / close)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 25}
    _task = None

    def __init__(self, scene=None, seed=None, render_mode=None, **options):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: expected None or 'rgb_array' (got {render_mode!r})")
        options.setdefault("autoreset", "disabled")
        self._batch = _Batch(self._task, 1, scene, seed, options)
        self.observation_space = self._batch.observation_space
        self.action_space = self._batch.action_space
        self.render_mode = render_mode
        self.spec = None
        self._seeded = False
        self._last_image = None

    @property
    def unwrapped(self):
        return self

    def reset(self, *, seed=None, options=None):
        """Starts an episode: `seed` restarts the environment's random stream (the same seed gives
        the same episode, bit for bit); None goes on from the last one (0 on the first reset).
        `options` takes no keys. Returns (observation, info)."""
        if options:
            raise ValueError(f"reset: options takes no keys (got {sorted(options)})")
        if seed is None and not self._seeded:
            seed = 0
        if seed is not None:
            self._seeded = True
            seed = int(seed)
        state, images = self._batch.env.reset([seed])
        self._last_image = None if images is None else images[0]
        return self._batch.observation(state[0], self._last_image), {}

    def step(self, action):
        """One control step (the action held for ticks_per_step physics ticks). Returns
        (observation, reward, terminated, truncated, info)."""
        a = np.asarray(action, dtype=np.float32)
        if a.shape != self.action_space.shape:
            raise ValueError(f"step: action must have shape {self.action_space.shape} "
                             f"(got {a.shape})")
        state, images, rewards, terminated, truncated, info = self._batch.env.step(a[None, :])
        self._last_image = None if images is None else images[0]
        obs = self._batch.observation(state[0], self._last_image)
        return (obs, float(rewards[0]), bool(terminated[0]), bool(truncated[0]),
                {k: bool(v[0]) for k, v in info.items()})

    def render(self):
        """An RGB picture (H, W, 3) uint8: the observed camera image, else a top view (north up,
        128 x 128 px over +-max_distance_m) with the goal (red) and the vehicle (white)."""
        if self.render_mode is None:
            return None
        if self._last_image is not None:
            return _image_to_rgb(self._last_image, self._batch.env.max_depth_m)
        env = self._batch.env
        return top_view(env.position_ned_m(0), env.goal_ned_m(0), 8.0)

    def close(self):
        pass

    @property
    def control_dt_s(self):
        return self._batch.env.control_dt_s

    def position_ned_m(self):
        """The vehicle's position now (world NED, m)."""
        return np.array(self._batch.env.position_ned_m(0))

    def goal_ned_m(self):
        """The point the task wants the vehicle at now (target, waypoint or goal line point)."""
        return np.array(self._batch.env.goal_ned_m(0))


def _image_to_rgb(image, max_depth_m):
    if image.dtype == np.uint8:
        return image
    grey = (255.0 * (1.0 - np.clip(image / max_depth_m, 0.0, 1.0))).astype(np.uint8)
    return np.repeat(grey[:, :, None], 3, axis=2)


def top_view(position_ned_m, goal_ned_m, half_extent_m, size_px=128):
    """A north-up top view centred on the goal: goal red, vehicle white, on dark grey."""
    img = np.full((size_px, size_px, 3), 40, np.uint8)
    scale = size_px / (2.0 * half_extent_m)

    def pixel(p):
        u = int(round((p[1] - goal_ned_m[1]) * scale + size_px / 2))
        v = int(round(-(p[0] - goal_ned_m[0]) * scale + size_px / 2))
        return u, v

    for p, colour, r in ((goal_ned_m, (220, 40, 40), 3), (position_ned_m, (255, 255, 255), 2)):
        u, v = pixel(p)
        img[max(v - r, 0):max(v + r + 1, 0), max(u - r, 0):max(u + r + 1, 0)] = colour
    return img


class HoverEnv(_SingleEnv):
    """Hold a point (target_ned_m, default [0, 0, -2]) from a random start within start_radius_m.
    Reward per step: 1 - distance / max_distance_m - rate_penalty * |body rates|; terminated beyond
    max_distance_m or on a collision; truncated after max_episode_steps."""
    _task = "hover"


class WaypointsEnv(_SingleEnv):
    """Fly through waypoint_count random waypoints in turn. Reward: progress toward the current
    waypoint (m) + 1 per waypoint reached - rate penalty; terminated when the last is reached,
    beyond max_distance_m of the current one, or on a collision."""
    _task = "waypoints"


class ForestEnv(_SingleEnv):
    """Fly north through the trees of scenes/forest_flight.yaml to a goal line goal_distance_m
    ahead, seeing them with the front camera's depth image. Reward: metres gained north - rate
    penalty - collision_penalty per collision; terminated on a collision, at the goal line or
    beyond max_distance_m off the line."""
    _task = "forest"


class VectorEnv(_VectorBase):
    """num_envs independent environments of one task stepped together in C++ (Gymnasium's vector
    API): observations (num_envs, ...), rewards, terminated, truncated arrays, and autoreset
    ('next_step' by default, Gymnasium's default; 'same_step' puts the final observation in
    info["final_obs"]; 'disabled'). `threads` threads step the physics; results do not depend on
    it. Each environment has its own world: vehicles of different environments never meet."""

    metadata = {"autoreset_mode": "next_step", "render_modes": []}

    def __init__(self, task="hover", num_envs=1, scene=None, seed=None, **options):
        if task not in _TASK_DEFAULTS:
            raise ValueError(f"task: expected one of {sorted(_TASK_DEFAULTS)} (got {task!r})")
        self._batch = _Batch(task, int(num_envs), scene, seed, options)
        self.num_envs = self._batch.env.num_envs
        self.single_observation_space = self._batch.observation_space
        self.single_action_space = self._batch.action_space
        n = self.num_envs
        a = self._batch.action_space
        self.action_space = make_box(np.broadcast_to(a.low, (n,) + a.shape),
                                     np.broadcast_to(a.high, (n,) + a.shape), (n,) + a.shape,
                                     np.float32)
        self.observation_space = _batched(self._batch.observation_space, n)
        self.metadata = dict(self.metadata, autoreset_mode=self._batch.env.autoreset)
        self.render_mode = None
        self.spec = None
        self.closed = False
        self._seeded = False

    @property
    def unwrapped(self):
        return self

    def reset(self, *, seed=None, options=None):
        """Resets every environment. `seed`: an int (environment i gets seed + i), a list of
        num_envs ints or Nones, or None (streams go on; 0 + i on the first reset)."""
        if options:
            raise ValueError(f"reset: options takes no keys (got {sorted(options)})")
        if seed is None and not self._seeded:
            seed = 0
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, (list, tuple)):
            if len(seed) != self.num_envs:
                raise ValueError(f"reset: expected {self.num_envs} seeds (got {len(seed)})")
            seeds = [None if s is None else int(s) for s in seed]
        else:
            seeds = [int(seed) + i for i in range(self.num_envs)]
        self._seeded = self._seeded or any(s is not None for s in seeds)
        state, images = self._batch.env.reset(seeds)
        return self._batch.observation(state, images), {}

    def step(self, actions):
        state, images, rewards, terminated, truncated, info = self._batch.env.step(actions)
        if "has_final" in info:  # same_step: Gymnasium's final_obs / final_info keys
            mask = info.pop("has_final")
            final_state = info.pop("final_observations")
            final_images = info.pop("final_images")
            final = self._batch.observation(final_state, final_images)
            info["final_obs"] = np.array(
                [_take(final, i) if mask[i] else None for i in range(self.num_envs)],
                dtype=object)
            info["_final_obs"] = mask
        return self._batch.observation(state, images), rewards, terminated, truncated, info

    def render(self):
        return None

    def close(self, **kwargs):
        self.closed = True

    @property
    def control_dt_s(self):
        return self._batch.env.control_dt_s

    @property
    def threads(self):
        return self._batch.env.threads

    def goal_ned_m(self, i):
        return np.array(self._batch.env.goal_ned_m(i))

    def position_ned_m(self, i):
        return np.array(self._batch.env.position_ned_m(i))


def _take(obs, i):
    if isinstance(obs, dict):
        return {k: v[i] for k, v in obs.items()}
    return obs[i]


def _batched(space, n):
    if hasattr(space, "spaces"):
        return make_dict({k: _batched(s, n) for k, s in space.spaces.items()})
    return make_box(np.broadcast_to(space.low, (n,) + space.shape),
                    np.broadcast_to(space.high, (n,) + space.shape), (n,) + space.shape,
                    space.dtype)


_SINGLE = {"hover": HoverEnv, "waypoints": WaypointsEnv, "forest": ForestEnv}


def make(task, **kwargs):
    """One environment of `task` ('hover', 'waypoints', 'forest')."""
    if task not in _SINGLE:
        raise ValueError(f"task: expected one of {sorted(_SINGLE)} (got {task!r})")
    return _SINGLE[task](**kwargs)


def make_vec(task, num_envs, **kwargs):
    """A VectorEnv of num_envs environments of `task`."""
    return VectorEnv(task, num_envs, **kwargs)
