#!/usr/bin/env python3
"""Learns to hover at a point with the vectorized environment, in about a minute on 2 cores.

    PYTHONPATH=build/python /usr/bin/python3 examples/train_hover.py [--out out/train_hover]

The policy, a PyTorch linear layer and tanh (18 weights), maps the observation's goal vector and
velocity to a velocity action. It is trained with the cross-entropy method in PyTorch (Debian 12's
python3-torch): each generation, 64 candidate weight sets fly one episode each, in the 64
environments of one airis.VectorEnv stepped together in C++, all from the same seeded start; the
best eighth define the next generation's distribution. Observations come from airis as NumPy arrays
and become tensors without a copy (torch.from_numpy).

Writes OUT/learning_curve.png (mean and best episode return per generation) and
OUT/flight.png (a contact sheet of the trained policy's flight: top views, north up, the goal red).
"""

import argparse
import os

import numpy as np
from PIL import Image, ImageDraw

try:
    import torch
except ImportError:  # the example is about training with PyTorch
    raise SystemExit("examples/train_hover.py needs PyTorch: apt-get install python3-torch")

import airis

NUM_ENVS = 64
EPISODE_STEPS = 150  # 3 s at 50 Hz


def features(obs):
    # vector to the goal (NED, m), velocity (NED, m/s): a view of airis's array, no copy
    return torch.from_numpy(obs)[:, 0:6].double()


def act(weights, obs):
    # weights: (N, 3, 6) tensor; obs: (N, 13) array -> actions (N, 3) in [-1, 1] for airis
    with torch.no_grad():
        return torch.tanh(torch.einsum("nij,nj->ni", weights, features(obs))).float().numpy()


def evaluate(env, weights, seed):
    obs, _ = env.reset(seed=[seed] * NUM_ENVS)  # every candidate from the same start
    total = np.zeros(NUM_ENVS)
    alive = np.ones(NUM_ENVS, bool)
    for _ in range(EPISODE_STEPS):
        obs, reward, terminated, truncated, _ = env.step(act(weights, obs))
        total += reward * alive
        alive &= ~(terminated | truncated)
        if not alive.any():
            break
    return total


def plot_curve(means, bests, path):
    w, h, m = 640, 360, 40
    img = Image.new("RGB", (w, h), "white")
    d = ImageDraw.Draw(img)
    lo, hi = min(means), max(bests)
    span = max(hi - lo, 1e-9)

    def xy(i, v):
        return (m + i * (w - 2 * m) / max(len(means) - 1, 1),
                h - m - (v - lo) / span * (h - 2 * m))

    d.rectangle([m, m, w - m, h - m], outline="black")
    for series, colour in ((means, (40, 90, 200)), (bests, (200, 60, 40))):
        d.line([xy(i, v) for i, v in enumerate(series)], fill=colour, width=2)
    d.text((m, 10), f"episode return per generation: mean (blue), best (red); "
                    f"{lo:.1f} .. {hi:.1f}", fill="black")
    d.text((m, h - m + 10), f"generation 0 .. {len(means) - 1}", fill="black")
    img.save(path)


def fly(weights, seed, path):
    env = airis.HoverEnv(start_radius_m=2.0, max_episode_steps=EPISODE_STEPS)
    obs, _ = env.reset(seed=seed)

    def view():  # top view, north up, +-2.5 m around the target
        return airis.envs.top_view(env.position_ned_m(), env.goal_ned_m(), 2.5)

    tiles = [view()]
    for k in range(EPISODE_STEPS):
        a = act(weights[None], obs[None])[0]
        obs, _, terminated, truncated, _ = env.step(a)
        if k % 10 == 9:
            tiles.append(view())
        if terminated or truncated:
            break
    cols = 8
    rows = (len(tiles) + cols - 1) // cols
    sheet = np.full((rows * 130, cols * 130, 3), 255, np.uint8)
    for i, t in enumerate(tiles):
        r, c = divmod(i, cols)
        sheet[r * 130 + 1:r * 130 + 129, c * 130 + 1:c * 130 + 129] = t
    Image.fromarray(sheet).save(path)
    return float(np.linalg.norm(env.goal_ned_m() - env.position_ned_m()))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default="out/train_hover")
    parser.add_argument("--generations", type=int, default=25)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    env = airis.VectorEnv("hover", NUM_ENVS, threads=args.threads, start_radius_m=2.0,
                          max_episode_steps=EPISODE_STEPS)
    torch.manual_seed(0)
    mean = torch.zeros(3, 6, dtype=torch.float64)
    std = torch.full((3, 6), 0.5, dtype=torch.float64)
    means, bests = [], []
    for gen in range(args.generations):
        weights = mean + std * torch.randn(NUM_ENVS, 3, 6, dtype=torch.float64)
        returns = evaluate(env, weights, seed=gen)
        elite = weights[torch.from_numpy(np.argsort(returns)[-NUM_ENVS // 8:])]
        mean, std = elite.mean(dim=0), elite.std(dim=0, unbiased=False) + 0.02
        means.append(float(returns.mean()))
        bests.append(float(returns.max()))
        print(f"generation {gen:2d}: mean return {means[-1]:7.2f}, best {bests[-1]:7.2f}")
    plot_curve(means, bests, os.path.join(args.out, "learning_curve.png"))
    miss_m = fly(mean, seed=1000, path=os.path.join(args.out, "flight.png"))
    print(f"trained policy ends {miss_m:.3f} m from the target (an unseen start); "
          f"wrote {args.out}/learning_curve.png and {args.out}/flight.png")


if __name__ == "__main__":
    main()
