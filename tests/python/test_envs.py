"""Gymnasium rules of the environments: spaces, seeding, termination vs truncation, autoreset,
determinism across threads, errors, memory."""

import numpy as np
import pytest

import airis


def _rollout(env, seed, steps, actions=None):
    obs, info = env.reset(seed=seed)
    trace = [obs.copy()]
    rng = np.random.default_rng(0)
    for _ in range(steps):
        a = rng.uniform(-1, 1, env.action_space.shape).astype(np.float32)
        obs, reward, terminated, truncated, info = env.step(a)
        trace.append(np.append(obs, reward))
        if terminated or truncated:
            break
    return np.concatenate(trace)


def test_reset_returns_an_observation_in_the_space_and_an_info_dict():
    env = airis.HoverEnv()
    obs, info = env.reset(seed=1)
    assert isinstance(info, dict)
    assert obs.shape == (13,) and obs.dtype == np.float32
    assert env.observation_space.contains(obs)
    assert env.action_space.shape == (3,)
    for _ in range(20):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        assert env.observation_space.contains(obs)
        assert isinstance(reward, float) and isinstance(terminated, bool)


def test_the_same_reset_seed_gives_the_same_episode_bit_for_bit():
    env = airis.WaypointsEnv()
    a = _rollout(env, 7, 100)
    _rollout(env, 8, 30)  # whatever happened in between
    b = _rollout(env, 7, 100)
    assert a.tobytes() == b.tobytes()
    c = _rollout(airis.WaypointsEnv(), 8, 100)
    assert a.tobytes() != c.tobytes()


def test_truncation_is_not_termination():
    # Hovering at the target with zero velocity never fails: the episode is truncated.
    env = airis.HoverEnv(max_episode_steps=25, start_radius_m=0.0, start_yaw_deg=0.0)
    env.reset(seed=0)
    for k in range(25):
        _, reward, terminated, truncated, _ = env.step(np.zeros(3, np.float32))
        assert not terminated
        assert truncated == (k == 24)
    assert reward > 0.9  # 1 - distance / max_distance, at the target
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros(3, np.float32))  # single envs do not autoreset


def test_flying_away_terminates():
    env = airis.HoverEnv(max_distance_m=2.0, max_speed_m_s=5.0)
    env.reset(seed=0)
    for _ in range(200):
        _, _, terminated, truncated, _ = env.step(np.array([1, 0, 0], np.float32))
        if terminated or truncated:
            break
    assert terminated and not truncated


@pytest.mark.parametrize("action,size", [("rotors", 4), ("rates_thrust", 4), ("velocity", 3)])
def test_action_modes(action, size):
    env = airis.HoverEnv(action=action)
    assert env.action_space.shape == (size,)
    env.reset(seed=0)
    obs, *_ = env.step(env.action_space.sample())
    assert np.all(np.isfinite(obs))


def test_vector_env_batches_and_autoresets_on_the_next_step():
    env = airis.VectorEnv("hover", 4, max_episode_steps=3)
    obs, info = env.reset(seed=10)
    assert obs.shape == (4, 13) and env.observation_space.contains(obs)
    assert env.metadata["autoreset_mode"] == "next_step"
    a = np.zeros((4, 3), np.float32)
    for _ in range(3):
        obs, r, term, trunc, info = env.step(a)
    assert trunc.all() and not term.any()
    obs, r, term, trunc, info = env.step(a)  # this step resets them (action ignored)
    assert (r == 0).all() and not trunc.any()
    assert env.observation_space.contains(obs)


def test_vector_env_same_step_autoreset_keeps_the_final_observation():
    env = airis.VectorEnv("hover", 2, max_episode_steps=2, autoreset="same_step")
    env.reset(seed=3)
    a = np.zeros((2, 3), np.float32)
    env.step(a)
    obs, r, term, trunc, info = env.step(a)
    assert trunc.all() and info["_final_obs"].all()
    assert info["final_obs"][0].shape == (13,)
    assert not np.array_equal(info["final_obs"][0], obs[0])


def test_vector_env_results_do_not_depend_on_threads():
    runs = []
    for threads in (1, 2):
        env = airis.VectorEnv("waypoints", 8, threads=threads, max_episode_steps=20)
        obs, _ = env.reset(seed=5)
        trace = [obs]
        rng = np.random.default_rng(1)
        for _ in range(50):
            obs, r, term, trunc, _ = env.step(rng.uniform(-1, 1, (8, 3)).astype(np.float32))
            trace += [obs, r, term, trunc]
        runs.append(b"".join(np.asarray(t).tobytes() for t in trace))
    assert runs[0] == runs[1]


def test_vector_env_seeds_each_environment_apart():
    env = airis.VectorEnv("hover", 3)
    obs, _ = env.reset(seed=[1, 1, 2])
    assert np.array_equal(obs[0], obs[1]) and not np.array_equal(obs[0], obs[2])


def test_bad_options_and_actions_raise_clear_errors():
    with pytest.raises(airis.ConfigError, match="max_episode_stepz.*did you mean 'max_episode_steps'"):
        airis.HoverEnv(max_episode_stepz=3)
    with pytest.raises(airis.ConfigError, match="action.*rotors, rates_thrust or velocity"):
        airis.HoverEnv(action="thrust")
    with pytest.raises(airis.ConfigError, match="control_rate_hz"):
        airis.HoverEnv(control_rate_hz=300.0)
    with pytest.raises(airis.ConfigError, match="threads"):
        airis.VectorEnv("hover", 2, threads=0)
    env = airis.VectorEnv("hover", 2)
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"shape \(2, 3\)"):
        env.step(np.zeros((2, 4), np.float32))
    with pytest.raises(ValueError, match="not finite"):
        env.step(np.full((2, 3), np.nan, np.float32))
    with pytest.raises(ValueError, match="task"):
        airis.VectorEnv("juggle", 2)


def test_forest_env_observes_a_depth_image():
    env = airis.ForestEnv(max_episode_steps=5)
    obs, _ = env.reset(seed=0)
    assert set(obs) == {"state", "image"}
    assert obs["image"].shape == (48, 64) and obs["image"].dtype == np.float32
    assert env.observation_space.contains(obs)
    obs, reward, terminated, truncated, info = env.step(np.array([1, 0, 0], np.float32))
    assert env.observation_space.contains(obs)
    # Looking north into the band of trees, some pixels see wood within the clip distance.
    assert (obs["image"] < env.observation_space["image"].high).any()


def test_forest_episodes_repeat_with_their_images():
    env = airis.ForestEnv(max_episode_steps=10)
    runs = []
    for _ in range(2):
        obs, _ = env.reset(seed=4)
        frames = [obs["image"].copy()]
        for _ in range(5):
            obs, *_ = env.step(np.array([1, 0.2, 0], np.float32))
            frames.append(obs["image"].copy())
        runs.append(np.stack(frames))
    assert runs[0].tobytes() == runs[1].tobytes()
    assert not np.array_equal(runs[0][0], runs[0][-1])  # it moved: the view changed


def test_render_gives_an_rgb_picture():
    env = airis.HoverEnv(render_mode="rgb_array")
    env.reset(seed=0)
    img = env.render()
    assert img.shape == (128, 128, 3) and img.dtype == np.uint8


def test_no_memory_growth_over_ten_thousand_steps():
    env = airis.VectorEnv("hover", 4, max_episode_steps=100)
    env.reset(seed=0)
    a = np.zeros((4, 3), np.float32)
    for _ in range(500):
        env.step(a)
    before = _rss_kib()
    for _ in range(10_000):
        env.step(a)
    assert _rss_kib() - before < 2048


def test_simulation_steps_without_memory_growth():
    from conftest import SENSOR_SCENE
    sim = airis.Simulation(SENSOR_SCENE)
    imu = sim.vehicles["drone1"].sensors["imu"]
    for _ in range(1000):
        sim.step()
        imu.since_last()
    before = _rss_kib()
    for _ in range(10_000):
        sim.step()
        _ = sim.vehicles["drone1"].state
        imu.since_last()
    assert _rss_kib() - before < 2048


def _rss_kib():
    with open("/proc/self/status") as s:
        for line in s:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


GYMNASIUM_STUB = {
    "gymnasium/__init__.py": "from . import spaces, vector\nclass Env:\n    pass\n",
    "gymnasium/vector.py": "class VectorEnv:\n    pass\n",
    "gymnasium/spaces.py": (
        "class Box:\n"
        "    def __init__(self, low, high, shape=None, dtype=None):\n"
        "        self.low, self.high, self.shape, self.dtype = low, high, shape, dtype\n"
        "class Dict:\n"
        "    def __init__(self, spaces):\n"
        "        self.spaces = spaces\n"),
}


def test_with_gymnasium_installed_the_classes_and_spaces_are_gymnasiums(tmp_path):
    # Debian 12 has no python3-gymnasium: a stand-in package shows the import-time switch.
    import os
    import subprocess
    import sys
    for name, text in GYMNASIUM_STUB.items():
        (tmp_path / name).parent.mkdir(exist_ok=True)
        (tmp_path / name).write_text(text)
    code = ("import gymnasium, airis\n"
            "env = airis.HoverEnv()\n"
            "assert isinstance(env, gymnasium.Env)\n"
            "assert isinstance(env.observation_space, gymnasium.spaces.Box)\n"
            "venv = airis.VectorEnv('hover', 2)\n"
            "assert isinstance(venv, gymnasium.vector.VectorEnv)\n"
            "obs, info = env.reset(seed=0)\n"
            "print('ok', obs.shape)\n")
    path = os.pathsep.join([str(tmp_path)] + sys.path)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ, PYTHONPATH=path))
    assert out.returncode == 0, out.stderr
    assert "ok (13,)" in out.stdout
