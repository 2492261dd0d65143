"""Shared fixtures of the Python module's tests: the repository, the airis binary, small scenes."""

import os
import shutil
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
if os.path.join(REPO, "build", "python") not in sys.path and "PYTHONPATH" not in os.environ:
    sys.path.insert(0, os.path.join(REPO, "build", "python"))

# A quadrotor with the four standard sensors on the empty ground (a file, so `airis run` can fly it).
SENSOR_SCENE = """\
scene:
  name: sensors
  seed: 5
ground:
  size_ne_m: [200, 200]
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -0.2], yaw_deg: 0}
    sensors:
      - imu: {rate_hz: 1000}
      - barometer: {rate_hz: 50}
      - magnetometer: {}
      - gps: {rate_hz: 10}
"""

HOVER_MISSION = """\
name: short hover
steps:
  - takeoff: {height_above_start_m: 3}
  - goto: {position_ned_m: [2, 1, -3], speed_m_s: 2}
  - hover: {duration_s: 0.5}
"""

# A box 10 m north of a drone 2 m up, seen by a forward camera and a stereo pair.
CAMERA_SCENE = """\
scene:
  name: camera_box
  seed: 2
ground:
  size_ne_m: [200, 200]
objects:
  - name: wall
    class: building
    primitive: box
    scale: [2, 20, 20]
    position_ned_m: [11, 0, -10]
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -2], yaw_deg: 0}
    sensors:
      - name: front
        camera:
          rate_hz: 5
          width_px: 64
          height_px: 48
          hfov_deg: 90
          far_m: 100
          outputs: {rgb: true, depth_planar: true, segmentation: true, normals: true}
          mount: {position_frd_m: [0, 0, 0]}
      - name: pair
        stereo_camera:
          baseline_m: 0.25
          camera:
            rate_hz: 5
            width_px: 64
            height_px: 48
            hfov_deg: 90
            far_m: 100
            outputs: {rgb: true, depth_planar: true}
            mount: {position_frd_m: [0, 0, 0]}
"""

CAPTURE_MISSION = """\
name: capture
steps:
  - takeoff: {height_above_start_m: 1}
  - capture: {enabled: true}
  - hover: {duration_s: 1}
  - capture: {enabled: false}
"""


@pytest.fixture(scope="session")
def airis_bin():
    path = os.environ.get("AIRIS_BIN", os.path.join(REPO, "build", "airis"))
    if not os.path.exists(path):
        pytest.skip(f"{path} not built")
    return path


@pytest.fixture
def write(tmp_path):
    """write(name, text) -> path of a file in the test's temporary folder."""
    def _write(name, text):
        path = tmp_path / name
        path.write_text(text)
        return str(path)
    return _write


def run(args, **kwargs):
    return subprocess.run(args, check=True, capture_output=True, text=True, cwd=REPO, **kwargs)


def pytest_unconfigure(config):
    """Removes the run's own --basetemp folder (tests/python/CMakeLists.txt): nothing left behind."""
    if config.option.basetemp:
        shutil.rmtree(config.option.basetemp, ignore_errors=True)
