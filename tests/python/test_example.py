"""examples/train_hover.py learns: run with a few generations, the trained PyTorch policy ends
closer to the target than the untrained one starts, and the learning curve improves."""

import os
import re
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_train_hover_learns_with_pytorch(tmp_path):
    pytest.importorskip("torch")  # Debian python3-torch (scripts/install-deps.sh installs it)
    out = tmp_path / "train"
    run = subprocess.run(
        [sys.executable, os.path.join(REPO, "examples", "train_hover.py"), "--out", str(out),
         "--generations", "12", "--threads", "2"],
        capture_output=True, text=True, timeout=300, env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    means = [float(m) for m in re.findall(r"mean return\s+(-?[0-9.]+)", run.stdout)]
    assert len(means) == 12
    assert max(means[-3:]) > means[0] + 1.0, run.stdout  # the population got better
    miss = float(re.search(r"ends ([0-9.]+) m from the target", run.stdout).group(1))
    assert miss < 0.5, run.stdout  # from an unseen start 2 m away
    assert (out / "learning_curve.png").stat().st_size > 0
    assert (out / "flight.png").stat().st_size > 0
