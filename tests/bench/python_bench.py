#!/usr/bin/env python3
"""Speed of the Python module through Python (docs/performance.md, "Python module").

    PYTHONPATH=build/python /usr/bin/python3 tests/bench/python_bench.py [--json]

Prints: the call overhead of sim.step() beyond the tick, vectorized hover environment steps per
second (64 vehicles, 50 Hz control over 1 kHz physics) on 1 and 2 threads, and capture() of RGB +
depth + segmentation at 640x480 in scenes/city.yaml next to `airis bench render`'s frame rate.
Each figure is the best of 3 runs after a warm-up (a busy machine only slows runs down).
"""

import json
import subprocess
import sys
import time

import numpy as np

import airis


def best_of(fn, repeats=3):
    return min(fn() for _ in range(repeats))


def step_overhead_ns():
    sim = airis.Simulation("scenes/empty.yaml")
    sim.vehicles["drone1"].set_position([0, 0, -5])
    sim.step(2000)
    n = 200_000

    # CPU time of this (single-threaded) process: a busy machine slows wall time, not this.
    def one_by_one():
        t = time.process_time()
        step = sim.step
        for _ in range(n):
            step()
        return (time.process_time() - t) / n

    def batched():
        t = time.process_time()
        sim.step(n)
        return (time.process_time() - t) / n

    per_call = best_of(one_by_one)
    per_tick = best_of(batched)
    return per_call * 1e9, per_tick * 1e9


def vector_env_steps_per_s(threads, num_envs=64, steps=2000):
    env = airis.VectorEnv("hover", num_envs, threads=threads)
    env.reset(seed=0)
    a = np.full((num_envs, 3), 0.1, np.float32)
    for _ in range(100):
        env.step(a)

    # Wall time (the figure that matters with threads) and CPU time of the process (all threads).
    def run():
        t, c = time.perf_counter(), time.process_time()
        for _ in range(steps):
            env.step(a)
        return ((time.perf_counter() - t) / (steps * num_envs),
                (time.process_time() - c) / (steps * num_envs))

    runs = [run() for _ in range(3)]
    return 1.0 / min(r[0] for r in runs), 1.0 / min(r[1] for r in runs)


def capture_fps(frames=100):
    # The scene and flight of `airis bench render`'s city case: 640x480, 90 deg, far 2,000 m,
    # RGB + depth + segmentation, camera pitched down 15 deg, 30 m up flying north over 300 m.
    text = open("scenes/city.yaml").read()
    text = text.replace("pitch_deg: -45", "pitch_deg: -15").replace("far_m: 1500", "far_m: 2000")
    sim = airis.Simulation(text, name="scenes/city.yaml")
    v = sim.vehicles["drone1"]
    cam = v.cameras["front"]

    def run():
        t = time.perf_counter()
        for k in range(frames):
            v.set_state(position_ned_m=[1.5 * (k % 200), 0.0, -30.0])
            f = cam.capture()
            _ = f.rgb, f.depth, f.class_id, f.instance_id
        return (time.perf_counter() - t) / frames

    for _ in range(5):
        cam.capture()
    return 1.0 / best_of(run)


def bench_render_fps():
    try:
        out = subprocess.run(["build/airis", "bench", "render", "--json"], check=True,
                             capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    data = json.loads(out)
    return data


def main():
    per_call, per_tick = step_overhead_ns()
    results = {
        "step_call_ns": per_call,
        "tick_ns": per_tick,
        "step_overhead_ns": per_call - per_tick,
    }
    for threads in (1, 2):
        wall, cpu = vector_env_steps_per_s(threads)
        results[f"vector_hover_64_env_steps_per_s_{threads}_thread_wall"] = wall
        results[f"vector_hover_64_env_steps_per_cpu_s_{threads}_thread"] = cpu
    results.update({
        "capture_city_640x480_fps": capture_fps(),
    })
    render = bench_render_fps()
    if render is not None:
        results["airis_bench_render_city_640x480_fps"] = render["city_640x480_fps"]
        results["airis_bench_render_city_640x480_pipelined_fps"] = render["city_640x480_pipelined_fps"]
        results["capture_vs_bench_render"] = (results["capture_city_640x480_fps"]
                                              / render["city_640x480_fps"])
    if "--json" in sys.argv:
        print(json.dumps(results, indent=2))
        return
    for k, v in results.items():
        print(f"{k:48s} {v:,.2f}")


if __name__ == "__main__":
    main()
