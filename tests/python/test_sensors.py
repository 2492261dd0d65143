"""Sensors: latest(), since_last() as structured arrays, bounds, and bit-for-bit equality with
`airis run`."""

import csv
import os

import numpy as np
import pytest

import airis
from conftest import HOVER_MISSION, SENSOR_SCENE, run


def test_latest_is_none_before_the_first_sample_then_a_record(write):
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE))
    imu = sim.vehicles["drone1"].sensors["imu"]
    assert imu.latest() is None
    sim.step()
    rec = imu.latest()
    assert rec["time_ns"] == 1_000_000
    assert rec.dtype.names == tuple(imu.columns)
    assert "specific_force_sensor_z_m_s2" in imu.columns


def test_since_last_returns_each_sample_once_in_order(write):
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE))
    sensors = sim.vehicles["drone1"].sensors
    sim.run_for(1.0)
    imu = sensors["imu"].since_last()
    baro = sensors["barometer"].since_last()
    gps = sensors["gps"].since_last()
    # Over the first second: one IMU sample per tick; the slower ones sample at their due times
    # 1/rate, 2/rate, ... 1 s (the first one period after the start, docs/sensors.md).
    assert len(imu) == 1000 and len(baro) == 50 and len(gps) == 10
    assert list(baro["time_ns"][:3]) == [20_000_000, 40_000_000, 60_000_000]
    assert list(gps["time_ns"][:2]) == [100_000_000, 200_000_000]
    # Before its first fix the GPS reports no position: fix type 1, NaN latitude.
    assert np.all(gps["fix_type"] == 1) and np.all(np.isnan(gps["latitude_deg"]))
    assert np.all(np.diff(imu["time_ns"]) == 1_000_000)
    assert len(sensors["imu"].since_last()) == 0
    sim.step(5)
    again = sensors["imu"].since_last()
    assert list(again["time_ns"]) == [1_001_000_000 + k * 1_000_000 for k in range(5)]
    assert gps.dtype["latitude_deg"] == np.float64 and gps.dtype["fix_type"] == np.int64


def test_samples_are_returned_without_a_copy(write):
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE))
    sim.run_for(0.1)
    rows = sim.vehicles["drone1"].sensors["imu"].since_last()
    # The array views the buffer C++ filled (moved out, not copied): it owns no data of its own.
    assert not rows.flags.owndata and type(rows.base).__name__ == "PyCapsule"


def test_stationary_imu_reads_gravity(write):
    # On the ground at rest the accelerometer reads the ground's push: -g along body z (FRD).
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE))
    sim.run_for(2.0)
    f = sim.vehicles["drone1"].sensors["imu"].since_last()["specific_force_sensor_z_m_s2"][500:]
    g = airis.env_at(47.641468, -122.140165, 0.0)["gravity_m_s2"]
    # The mean of 1500 samples of a noise of ~0.02 m/s^2 (plus bias) is within 0.1 m/s^2.
    assert float(np.mean(f)) == pytest.approx(-g, abs=0.1)


def test_unread_samples_are_bounded(write):
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE), max_samples=100)
    sim.run_for(1.0)
    imu = sim.vehicles["drone1"].sensors["imu"]
    assert imu.pending <= 100 and imu.dropped >= 900
    rows = imu.since_last()
    assert rows["time_ns"][-1] == 1_000_000_000  # the newest are kept


def _read_csv(path):
    with open(path, newline="") as f:
        r = csv.reader(f)
        header = next(r)
        return header, [row for row in r]


def test_state_and_sensors_equal_airis_run_bit_for_bit(write, airis_bin, tmp_path):
    scene = write("s.yaml", SENSOR_SCENE)
    mission = write("m.yaml", HOVER_MISSION)
    out = tmp_path / "log"
    run([airis_bin, "run", scene, "--mission", mission, "--out", str(out)])

    sim = airis.Simulation(scene)
    v = sim.vehicles["drone1"]
    sim.start_mission(mission)
    header, rows = _read_csv(out / "drone1.truth.csv")
    assert header[0] == "time_ns"
    truth = []
    while sim.mission["state"] == "running":
        truth.append(v.truth())
        sim.step(10)  # the log's truth rows are at 100 Hz
    n = min(len(truth), len(rows))
    assert n > 100
    names = truth[0].dtype.names
    for k in range(n):
        row = dict(zip(header, rows[k]))
        for name in names:
            want = truth[k].dtype[name].type(row[name])
            assert truth[k][name] == want, (k, name, truth[k][name], row[name])

    imu = v.sensors["imu"].since_last()
    header, rows = _read_csv(out / "drone1.imu.csv")
    # The loop above may step up to 10 ticks past the mission's end, where airis run stops.
    assert len(rows) > 1000 and 0 <= len(imu) - len(rows) <= 10
    for k in range(0, len(rows), 97):
        row = dict(zip(header, rows[k]))
        for name in imu.dtype.names:
            assert imu[k][name] == imu.dtype[name].type(row[name]), (k, name)


def test_the_same_seed_gives_the_same_samples_and_another_seed_others(write):
    scene = write("s.yaml", SENSOR_SCENE)
    streams = []
    for seed in (4, 4, 5):
        sim = airis.Simulation(scene, seed=seed)
        sim.vehicles["drone1"].set_position([0, 0, -2])
        sim.run_for(1.0)
        streams.append(sim.vehicles["drone1"].sensors["imu"].since_last())
    assert streams[0].tobytes() == streams[1].tobytes()
    assert streams[0].tobytes() != streams[2].tobytes()


def test_a_camera_is_not_a_sensor_stream():
    from conftest import CAMERA_SCENE
    sim = airis.Simulation(CAMERA_SCENE)
    v = sim.vehicles["drone1"]
    assert "front" in v.cameras and "front" not in v.sensors
