"""airis.Simulation and airis.Vehicle: loading, stepping, state, setpoints, errors."""

import signal

import numpy as np
import pytest

import airis
from conftest import SENSOR_SCENE


def test_loads_from_a_file_a_string_and_a_dict_alike():
    a = airis.Simulation("scenes/empty.yaml", seed=1)
    text = open("scenes/empty.yaml").read()
    b = airis.Simulation(text, seed=1)
    c = airis.Simulation({
        "scene": {"name": "empty", "seed": 1},
        "ground": {"size_ne_m": [500, 500]},
        "vehicles": [{"name": "drone1", "preset": "quad_x",
                      "start": {"position_ned_m": np.array([0, 0, -0.2]),
                                "yaw_deg": np.float64(0)}}],
    })
    for sim in (a, b, c):
        sim.vehicles["drone1"].set_position([1.0, 2.0, -3.0])
        sim.run_for(2.0)
    pa, pb, pc = (s.vehicles["drone1"].state.position_ned_m for s in (a, b, c))
    assert np.array_equal(pa, pb) and np.array_equal(pa, pc)
    assert a.seed == 1


def test_clock_counts_whole_ticks():
    sim = airis.Simulation("scenes/empty.yaml")
    assert sim.time_s == 0.0 and sim.dt_s == 0.001
    sim.step()
    sim.step(9)
    assert sim.tick == 10 and sim.time_ns == 10_000_000
    sim.run_for(0.0105)  # covered by whole ticks: 11 more
    assert sim.tick == 21


def test_free_fall_follows_the_closed_form():
    # GIVEN a vehicle 100 m up with its rotors stopped WHEN it falls for 0.5 s
    sim = airis.Simulation("scenes/empty.yaml")
    v = sim.vehicles["drone1"]
    v.set_state(position_ned_m=[0, 0, -100], velocity_ned_m_s=[0, 0, 0])
    v.set_rotor_commands(np.zeros(v.actuator_count))
    sim.run_for(0.5)
    # THEN z = z0 + g t^2 / 2 and v = g t, with g the model's gravity at the site; drag at < 5 m/s
    # on a 1 kg quad costs under 1% over this time (tolerance).
    origin = airis.env_at(47.641468, -122.140165, 100.0)
    g = origin["gravity_m_s2"]
    s = v.state
    assert s.velocity_ned_m_s[2] == pytest.approx(g * 0.5, rel=0.01)
    assert s.position_ned_m[2] == pytest.approx(-100 + 0.5 * g * 0.25, abs=0.02)
    assert s.acceleration_ned_m_s2[2] == pytest.approx(g, rel=0.02)
    assert v.command_mode == "motors"


@pytest.mark.parametrize("setpoint", ["position", "velocity", "attitude", "rates"])
def test_each_setpoint_flies(setpoint):
    sim = airis.Simulation("scenes/empty.yaml")
    v = sim.vehicles["drone1"]
    if setpoint == "position":
        v.set_position([2.0, -1.0, -4.0], yaw_deg=30)
        sim.run_for(8.0)
        assert np.allclose(v.state.position_ned_m, [2.0, -1.0, -4.0], atol=0.1)
        assert v.state.euler_deg[2] == pytest.approx(30, abs=1.0)
    elif setpoint == "velocity":
        v.set_velocity([0.0, 0.0, -1.0])
        sim.run_for(3.0)
        assert v.state.velocity_ned_m_s[2] == pytest.approx(-1.0, abs=0.05)
    elif setpoint == "attitude":
        v.set_attitude([1, 0, 0, 0], thrust_fraction=0.9)
        sim.run_for(1.0)
        assert v.state.velocity_ned_m_s[2] < -1.0  # more thrust than weight: climbs, level
        assert abs(v.state.euler_deg[0]) < 1 and abs(v.state.euler_deg[1]) < 1
    else:
        v.set_rates([0, 0, 1.0], thrust_fraction=0.6)
        sim.run_for(1.0)
        assert v.state.angular_velocity_frd_rad_s[2] == pytest.approx(1.0, abs=0.05)


def test_land_disarms_on_touchdown():
    sim = airis.Simulation("scenes/empty.yaml")
    v = sim.vehicles["drone1"]
    v.set_position([0, 0, -2])
    sim.run_for(4.0)
    assert not v.landed
    v.land()
    sim.run_for(10.0)
    assert v.landed


def test_collisions_are_reported():
    sim = airis.Simulation("scenes/empty.yaml")
    v = sim.vehicles["drone1"]
    v.set_state(position_ned_m=[0, 0, -3])
    v.set_rotor_commands([0, 0, 0, 0])
    sim.run_for(2.0)
    hits = v.collisions
    assert hits and hits[0]["object"] == "ground"
    assert hits[0]["normal_ned"][2] == pytest.approx(-1.0)


def test_truth_row_has_the_dataset_columns():
    sim = airis.Simulation("scenes/empty.yaml")
    row = sim.vehicles["drone1"].truth()
    assert row.dtype.names[:4] == ("time_ns", "position_ned_x_m", "position_ned_y_m",
                                   "position_ned_z_m")
    assert row["position_ned_z_m"] == sim.vehicles["drone1"].state.position_ned_m[2]
    assert row.dtype["velocity_ned_x_m_s"] == np.float32


def test_mission_flies_to_success(write):
    from conftest import HOVER_MISSION
    scene = write("s.yaml", SENSOR_SCENE)
    sim = airis.Simulation(scene)
    out = sim.run_mission(write("m.yaml", HOVER_MISSION))
    assert out["state"] == "succeeded" and out["succeeded"], out
    assert out["distance_flown_m"] > 3.0
    assert np.allclose(sim.vehicles["drone1"].state.position_ned_m, [2, 1, -3], atol=0.3)


def test_run_mission_flies_a_track_per_vehicle(write):
    scene = write("two.yaml", "vehicles:\n"
                  "  - {name: a, preset: quad_x, start: {position_ned_m: [0, 0, -0.2]}}\n"
                  "  - {name: b, preset: quad_x, start: {position_ned_m: [0, 5, -0.2]}}\n")
    mission = write("two_m.yaml", "vehicles:\n"
                    "  a: {steps: [{takeoff: {height_above_start_m: 2}}, {barrier: {label: up}},"
                    " {land: }]}\n"
                    "  b: {steps: [{takeoff: {height_above_start_m: 4}}, {barrier: {label: up}},"
                    " {land: }]}\n")
    sim = airis.Simulation(scene)
    out = sim.run_mission(mission)
    assert out["succeeded"], out
    assert [t["vehicle"] for t in out["tracks"]] == ["a", "b"]
    assert all(t["state"] == "succeeded" and t["collisions"] == 0 for t in out["tracks"])
    assert out["contacts"] == sum(t["contacts"] for t in out["tracks"]) > 0  # the landings
    assert out["vehicle"] == "a" and out["steps"] == 3  # the first track's


def test_step_flies_a_started_mission(write):
    from conftest import HOVER_MISSION
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE))
    sim.start_mission(write("m.yaml", HOVER_MISSION))
    sim.step(500)
    assert sim.mission["state"] == "running"
    assert sim.vehicles["drone1"].state.position_ned_m[2] < -0.5  # taking off
    assert sim.run_mission(timeout_s=60)["succeeded"]


def test_bad_scene_raises_config_error_with_file_line_and_key(write):
    path = write("bad.yaml", "scene:\n  name: x\nvehicles:\n  - name: d\n    preset: quad_x\n"
                             "    start: {position_ned_mm: [0, 0, -1]}\n")
    with pytest.raises(airis.ConfigError) as e:
        airis.Simulation(path)
    msg = str(e.value)
    assert f"{path}:6:" in msg and "position_ned_mm" in msg and "did you mean" in msg
    assert isinstance(e.value, ValueError)


def test_bad_dict_scene_names_the_key_and_line():
    with pytest.raises(airis.ConfigError) as e:
        airis.Simulation({"scene": {"name": "x", "sede": 3}})
    assert "<dict>:3:" in str(e.value) and "sede" in str(e.value)


def test_overrides_replace_scene_keys_as_set_does():
    scene = {"scene": {"name": "o"}, "vehicles": [{"name": "d", "preset": "quad_x"}]}
    start = {"vehicles[0].start.position_ned_m": [1, 2, -3]}
    windy = airis.Simulation(scene, overrides={**start,
                                               "scene.environment.wind.mean_ned_m_s": np.array([5, -2, 0])})
    calm = airis.Simulation(scene, overrides=start)
    assert windy.vehicles["d"].state.position_ned_m.tolist() == [1.0, 2.0, -3.0]
    assert airis.Simulation(scene).vehicles["d"].state.position_ned_m.tolist() != [1.0, 2.0, -3.0]
    # the wind reaches the world: a falling body drifts west of one in calm air, which falls straight
    windy.run_for(0.5)
    calm.run_for(0.5)
    assert calm.vehicles["d"].state.position_ned_m[1] == 2.0
    assert windy.vehicles["d"].state.position_ned_m[1] < 2.0
    with pytest.raises(airis.ConfigError) as e:
        airis.Simulation(scene, overrides={"scene.environment.wnd.mean_ned_m_s": [5, 0, 0]})
    assert str(e.value) == ("--set scene.environment.wnd.mean_ned_m_s=[5, 0, 0]: "
                            "scene.environment.wnd: unknown key 'wnd' (did you mean 'wind'?)")
    with pytest.raises(TypeError):
        airis.Simulation(scene, overrides=["scene.lighting.ambient=0.5"])


def test_bad_arguments_raise_clear_errors():
    sim = airis.Simulation("scenes/empty.yaml")
    v = sim.vehicles["drone1"]
    with pytest.raises(ValueError, match="expected 4 commands"):
        v.set_rotor_commands([0.5, 0.5])
    with pytest.raises(ValueError, match="not finite"):
        v.set_rotor_commands([0.5, float("nan"), 0.5, 0.5])
    with pytest.raises(ValueError, match="position_ned_m"):
        v.set_position([1, 2])
    with pytest.raises(ValueError, match="thrust_fraction"):
        v.set_rates([0, 0, 0], thrust_fraction=1.5)
    with pytest.raises(ValueError, match="seconds"):
        sim.run_for(-1)
    with pytest.raises(KeyError, match="drone1"):
        sim.vehicles["drone9"]
    with pytest.raises(KeyError, match="no sensor"):
        v.sensors["imu"]
    with pytest.raises(airis.ConfigError):
        airis.Simulation("scenes/does_not_exist.yaml")


def test_two_threads_give_the_numbers_of_one():
    # The swarm (100 quads with four sensors each), each one flying to its own point above the
    # grid, on one thread and on two: every state and IMU sample the same, bit for bit.
    runs = []
    for threads in (1, 2):
        sim = airis.Simulation("scenes/swarm.yaml", threads=threads)
        assert sim.threads == threads
        for k, v in enumerate(sim.vehicles.values()):
            v.set_position([k % 10 - 5.0, k // 10 - 5.0, -3.0 - 0.05 * k])
        sim.run_for(1.0)
        runs.append([(v.state.position_ned_m, v.state.velocity_ned_m_s,
                      v.sensors["imu"].since_last()) for v in sim.vehicles.values()])
    for (p1, v1, imu1), (p2, v2, imu2) in zip(*runs):
        assert np.array_equal(p1, p2) and np.array_equal(v1, v2)
        assert np.array_equal(imu1, imu2)
    with pytest.raises(ValueError, match="threads"):
        airis.Simulation("scenes/empty.yaml", threads=0)


def test_divergence_raises_simulation_error():
    sim = airis.Simulation("scenes/empty.yaml")
    v = sim.vehicles["drone1"]
    v.set_state(position_ned_m=[0, 0, -10], velocity_ned_m_s=[1e5, 0, 0])
    with pytest.raises(airis.SimulationError, match="drone1"):
        sim.run_for(1.0)


def test_ctrl_c_stops_a_long_run_with_keyboard_interrupt():
    sim = airis.Simulation("scenes/empty.yaml")

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(KeyboardInterrupt):
            sim.run_for(1e6)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    t = sim.time_s
    assert 0 < t < 1e6
    sim.step()  # still usable
    assert sim.time_s > t


def test_ctrl_c_stops_a_mission_in_flight(write):
    sim = airis.Simulation(write("s.yaml", SENSOR_SCENE))
    mission = write("m.yaml", "name: long\nsteps:\n  - takeoff: {height_above_start_m: 2}\n"
                              "  - hover: {duration_s: 100000}\n")

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(KeyboardInterrupt):
            sim.run_mission(mission)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    assert sim.mission["state"] == "running" and 0 < sim.time_s < 100000


def test_objects_outlive_the_simulation():
    v = airis.Simulation("scenes/empty.yaml").vehicles["drone1"]
    assert v.state.position_ned_m.shape == (3,)


def test_a_px4_vehicle_is_flown_by_px4_and_its_absence_is_a_connection_error():
    # autopilot: px4 is honoured from Python as by `airis run`: no PX4 on instance 39, so the first
    # step waits connect_timeout_s and raises, naming the port.
    sim = airis.Simulation("""
scene: {name: px4_python}
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -0.2]}
    autopilot: {kind: px4, instance: 39, connect_timeout_s: 0.2}
    sensors: [{imu: {}}, {barometer: {}}, {magnetometer: {}}, {gps: {}}]
""")
    with pytest.raises(airis.AutopilotLinkError, match="127.0.0.1:4599 within 0.2 s"):
        sim.step(10)
    assert isinstance(airis.AutopilotLinkError("x"), ConnectionError)
