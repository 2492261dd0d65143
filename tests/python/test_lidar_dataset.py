"""airis.Dataset reads lidar scans: the PCD fields typed, the pose per scan, world points."""

import numpy as np
import pytest

import airis
from conftest import CAPTURE_MISSION, run

# A lidar-only drone 3 m up, 10 m south of a wall whose south face is the plane north = 10 m.
LIDAR_SCENE = """\
scene:
  name: lidar_wall
  seed: 3
ground:
  size_ne_m: [200, 200]
objects:
  - name: wall
    class: building
    primitive: box
    scale: [2, 40, 30]
    position_ned_m: [11, 0, -15]
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -2], yaw_deg: 0}
    sensors:
      - lidar: {range_noise_m: 0, horizontal_fov_deg: 90, horizontal_resolution_deg: 2}
"""


def test_a_lidar_only_dataset_reads_back_as_typed_points_on_the_wall(write, airis_bin, tmp_path):
    out = tmp_path / "ds"
    run([airis_bin, "dataset", write("s.yaml", LIDAR_SCENE), "--mission",
         write("m.yaml", CAPTURE_MISSION), "--out", str(out)])
    ds = airis.Dataset(str(out))
    assert ds.complete and not ds.cameras
    scans = ds.lidars["drone1.lidar"]
    # 1 s of capture at 10 scans per second; the summary stream has a row per scan recorded.
    assert len(scans) == len(ds.stream("drone1.lidar")) >= 10
    scan = scans[0]
    points = scan["points"]
    assert points.dtype["x"] == np.float32 and points.dtype["ring"] == np.uint16
    assert points.dtype["instance_id"] == np.uint32 and points.dtype["class_id"] == np.uint8
    wall = points[points["class_id"] == [c for c, n in ds.classes.items() if n == "building"][0]]
    assert len(wall) > 100
    # The wall's face is 10 m north: every wall return lands on it in the world (float32 points,
    # Embree's single precision: 1 mm).
    world = scans.world_points(0)[points["class_id"] == wall["class_id"][0]]
    assert world[:, 0] == pytest.approx(10.0, abs=1e-3)
    assert ((0 <= points["intensity"]) & (points["intensity"] <= 1)).all()


def test_open3d_reads_every_field_of_a_scan_with_its_type(write, airis_bin, tmp_path):
    o3d = pytest.importorskip("open3d")  # Debian python3-open3d, when installed
    out = tmp_path / "ds"
    run([airis_bin, "dataset", write("s.yaml", LIDAR_SCENE), "--mission",
         write("m.yaml", CAPTURE_MISSION), "--out", str(out)])
    scans = airis.Dataset(str(out)).lidars["drone1.lidar"]
    points = scans[0]["points"]
    cloud = o3d.t.io.read_point_cloud(str(out / "drone1.lidar" / "000000.pcd"))
    xyz = np.stack([points["x"], points["y"], points["z"]], axis=1)
    assert np.array_equal(cloud.point["positions"].numpy(), xyz)
    for name in ("range_m", "intensity", "time_offset_s", "ring", "column", "instance_id",
                 "class_id"):
        values = cloud.point[name].numpy().reshape(-1)
        assert values.dtype == points.dtype[name], name
        assert np.array_equal(values, points[name]), name
