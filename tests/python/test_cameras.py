"""Cameras: capture() arrays, zero copy, geometry, stereo, and equality with the dataset's PNGs."""

import numpy as np
import pytest

import airis
from conftest import CAMERA_SCENE, CAPTURE_MISSION, run


@pytest.fixture(scope="module")
def sim():
    return airis.Simulation(CAMERA_SCENE)


def test_capture_gives_every_plane_with_its_shape_and_type(sim):
    f = sim.vehicles["drone1"].cameras["front"].capture()
    assert f.rgb.shape == (48, 64, 3) and f.rgb.dtype == np.uint8
    assert f.depth.shape == (48, 64) and f.depth.dtype == np.float32
    assert f.class_id.dtype == np.uint8 and f.instance_id.dtype == np.uint32
    assert f.normals.shape == (48, 64, 3) and f.normals.dtype == np.float32
    assert f.depth_perspective is None  # not configured
    assert f.time_ns == sim.time_ns
    assert f.intrinsics["width_px"] == 64 and f.K[0, 0] == pytest.approx(32.0)


def test_depth_and_labels_see_the_wall_where_it_is(sim):
    # The wall's south face is 10 m north of the camera (box centred 11 m north, 2 m thick).
    f = sim.vehicles["drone1"].cameras["front"].capture()
    centre = f.depth[24, 32]
    assert centre == pytest.approx(10.0, abs=0.01)
    building = [k for k, name in airis.scene_stats(CAMERA_SCENE)["classes"].items()]
    assert "building" in building
    assert f.class_id[24, 32] != 0 and f.instance_id[24, 32] != 0
    # The face's normal points back at the camera: -z in the optical frame.
    assert f.normals[24, 32] == pytest.approx([0, 0, -1], abs=1e-3)
    # T_WC: optical z (forward) is world north, at the vehicle's position.
    assert f.T_WC[:3, 2] == pytest.approx([1, 0, 0], abs=1e-6)
    assert f.T_WC[:3, 3] == pytest.approx(sim.vehicles["drone1"].state.position_ned_m, abs=1e-9)


def test_arrays_view_the_frame_without_copies(sim):
    cam = sim.vehicles["drone1"].cameras["front"]
    f = cam.capture()
    assert not f.rgb.flags.owndata and type(f.rgb.base).__name__ == "PyCapsule"
    assert np.shares_memory(f.rgb, f.rgba)  # RGB is a strided view of the RGBA readback
    assert f.rgb.strides == (64 * 4, 4, 1)
    assert np.shares_memory(f.depth, f.depth)
    # A frame still held keeps its buffers: the next capture renders into new ones.
    g = cam.capture()
    assert not np.shares_memory(f.depth, g.depth)
    depth = f.depth.copy()
    sim.vehicles["drone1"].set_state(position_ned_m=[5, 0, -2])
    cam.capture()
    assert np.array_equal(f.depth, depth)


def test_stereo_pair_is_captured_at_one_instant_a_baseline_apart(sim):
    s = sim.vehicles["drone1"].cameras["pair"].capture()
    assert isinstance(s, airis.StereoFrame) and s.baseline_m == 0.25
    assert s.left.time_ns == s.right.time_ns
    offset = s.right.T_WC[:3, 3] - s.left.T_WC[:3, 3]
    assert np.linalg.norm(offset) == pytest.approx(0.25, abs=1e-9)
    assert offset @ s.left.T_WC[:3, 0] == pytest.approx(0.25, abs=1e-9)  # along image x


def test_arrays_equal_the_dataset_pngs_of_the_same_frame(write, airis_bin, tmp_path):
    scene = write("cam.yaml", CAMERA_SCENE)
    mission = write("m.yaml", CAPTURE_MISSION)
    out = tmp_path / "ds"
    run([airis_bin, "dataset", scene, "--mission", mission, "--out", str(out), "--cameras",
         "front", "--formats", "npy"])
    ds = airis.Dataset(str(out))
    frames = ds.cameras["front"]
    assert len(frames) >= 4
    sim = airis.Simulation(scene)
    cam = sim.vehicles["drone1"].cameras["front"]
    sim.start_mission(mission)
    for i in range(len(frames)):
        want = frames[i]
        sim.step((want["time_ns"] - sim.time_ns) // 1_000_000)
        assert sim.time_ns == want["time_ns"]
        got = cam.capture()
        assert np.array_equal(got.rgb, want["rgb"]), i
        assert np.array_equal(got.class_id, want["class_id"]), i
        assert np.array_equal(got.instance_id, want["instance_id"]), i
        assert np.array_equal(got.depth, want["depth_m"]), i
        assert np.allclose(got.T_WC, want["T_WC"], atol=1e-6), i


def test_capture_many_frames_without_memory_growth(sim):
    cam = sim.vehicles["drone1"].cameras["front"]
    for _ in range(50):
        cam.capture()
    before = _rss_kib()
    for _ in range(1000):
        f = cam.capture()
        _ = f.rgb, f.depth, f.class_id
    assert _rss_kib() - before < 4096, "more than 4 MiB growth over 1,000 captures"


def _rss_kib():
    with open("/proc/self/status") as s:
        for line in s:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def _small_dataset(write, airis_bin, tmp_path):
    scene = write("cam.yaml", CAMERA_SCENE)
    out = tmp_path / "ds"
    run([airis_bin, "dataset", scene, "--mission", write("m.yaml", CAPTURE_MISSION), "--out",
         str(out), "--cameras", "front"])
    return scene, airis.Dataset(str(out))


def test_dataset_reader_gives_streams_labels_and_frames(write, airis_bin, tmp_path):
    scene, ds = _small_dataset(write, airis_bin, tmp_path)
    assert ds.complete and "drone1.truth" in ds.streams
    truth = ds.stream("drone1.truth")
    assert truth.dtype.names == airis.Simulation(scene).vehicles["drone1"].truth().dtype.names
    assert "building" in ds.classes.values()
    f = ds.cameras["front"][0]
    # 16-bit PNG depth decoded with the manifest's unit: within half a unit of the wall's 10 m.
    unit = ds.cameras["front"].depth_unit_m
    assert f["depth_m"][24, 32] == pytest.approx(10.0, abs=unit / 2 + 0.01)
    assert f["rgb"].shape == (48, 64, 3) and f["instance_id"].dtype == np.uint32
    with pytest.raises(IndexError):
        ds.cameras["front"][len(ds.cameras["front"])]
    with pytest.raises(FileNotFoundError, match="manifest"):
        airis.Dataset(str(tmp_path))


def test_dataset_reader_decodes_both_instance_formats(write, airis_bin, tmp_path):
    # The same flight written with the default rgb24 instance images and with gray16 ones: the
    # files differ (8-bit RGB vs 16-bit grey), the ids the reader decodes do not.
    from PIL import Image
    _, rgb24 = _small_dataset(write, airis_bin, tmp_path)
    gray16_scene = CAMERA_SCENE.replace("          mount: {position_frd_m: [0, 0, 0]}\n",
                                        "          mount: {position_frd_m: [0, 0, 0]}\n"
                                        "          instance_format: gray16\n", 1)
    assert gray16_scene != CAMERA_SCENE
    out = tmp_path / "gray16"
    run([airis_bin, "dataset", write("gray16.yaml", gray16_scene), "--mission",
         write("m.yaml", CAPTURE_MISSION), "--out", str(out), "--cameras", "front"])
    gray16 = airis.Dataset(str(out))
    a, b = rgb24.cameras["front"], gray16.cameras["front"]
    assert a.info["seg_instance"]["format"] == "rgb24"
    assert b.info["seg_instance"]["format"] == "gray16"
    with Image.open(a._file("seg_instance", a[0]["index"], "png")) as im:
        assert im.mode == "RGB"
    with Image.open(b._file("seg_instance", b[0]["index"], "png")) as im:
        assert im.mode.startswith("I")
    assert len(a) == len(b) > 0
    for i in range(len(a)):
        assert a[i]["instance_id"].dtype == np.uint32
        assert np.array_equal(a[i]["instance_id"], b[i]["instance_id"]), i
    assert a[0]["instance_id"][24, 32] != 0  # the wall


def test_instance_png_decoding_carries_24_bit_ids(tmp_path):
    # COCO panoptic's encoding written by PIL (independent of airis's encoder): id = R + 256 G +
    # 65536 B, here ids that need all three bytes.
    from PIL import Image
    from airis.dataset import _read_instance_png
    ids = np.array([[0, 1, 65535], [65536, 0x123456, 16_777_215]], dtype=np.uint32)
    rgb = np.stack([ids & 255, (ids >> 8) & 255, ids >> 16], axis=-1).astype(np.uint8)
    path = str(tmp_path / "ids.png")
    Image.fromarray(rgb, "RGB").save(path)
    assert np.array_equal(_read_instance_png(path, "rgb24"), ids)
    with pytest.raises(ValueError, match="16-bit grey"):
        _read_instance_png(path, "gray16")


def test_dataset_as_a_torch_dataset(write, airis_bin, tmp_path):
    torch = pytest.importorskip("torch")  # Debian python3-torch, when installed
    _, ds = _small_dataset(write, airis_bin, tmp_path)
    item = ds.cameras["front"].torch()[0]
    assert item["rgb"].dtype == torch.float32 and item["rgb"].shape == (3, 48, 64)
    assert item["instance_id"].dtype == torch.int64
