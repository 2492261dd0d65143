"""airis.env_at, scene stats and checks, against `airis env` / `airis scene stats`."""

import json

import pytest

import airis
from conftest import run


def test_env_at_equals_airis_env(airis_bin):
    got = airis.env_at(47.6, -122.1, 120.0)
    out = json.loads(run([airis_bin, "env", "--latitude-deg", "47.6", "--longitude-deg", "-122.1",
                          "--altitude-m", "120", "--json"]).stdout)
    flat = json.dumps(out)
    assert f"{got['pressure_pa']!r}" in flat or str(round(got["pressure_pa"], 3)) in flat
    assert got["magnetic_model"].startswith("WMM")


def test_env_at_sea_level_is_the_standard_atmosphere():
    e = airis.env_at(0.0, 0.0, 0.0)
    assert e["pressure_pa"] == pytest.approx(101325.0, rel=1e-6)
    assert e["temperature_k"] == pytest.approx(288.15, abs=1e-6)
    assert e["density_kg_m3"] == pytest.approx(1.225, rel=1e-3)
    assert 9.77 < e["gravity_m_s2"] < 9.84
    assert 20_000 < e["total_intensity_nt"] < 70_000


def test_env_at_refuses_points_outside_the_models():
    with pytest.raises(airis.ConfigError, match="latitude_deg"):
        airis.env_at(95.0, 0.0, 0.0)
    with pytest.raises(ValueError, match="magnetic"):
        airis.env_at(0.0, 0.0, 0.0, magnetic="igrf")


def test_scene_stats_equal_airis_scene_stats(airis_bin):
    got = airis.scene_stats("scenes/city.yaml")
    out = json.loads(run([airis_bin, "scene", "stats", "scenes/city.yaml", "--json"]).stdout)
    for key in ("objects", "models", "meshes", "materials", "drawn_triangles", "seed"):
        assert got[key] == out[key], key


def test_check_scene_raises_with_the_location(write):
    assert airis.check_scene("scenes/forest.yaml")
    bad = write("bad.yaml", "scene:\n  name: x\nground:\n  size_ne_m: [10, -5]\n")
    with pytest.raises(airis.ConfigError) as e:
        airis.check_scene(bad)
    assert f"{bad}:4:" in str(e.value) and "ground.size_ne_m" in str(e.value)
