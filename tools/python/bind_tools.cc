// airis.env_at and the scene summaries: the environment models and scene loader on their own.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "engine/core/config.h"
#include "scenes/scene_stats.h"
#include "tools/jobs/environment_query.h"
#include "tools/jobs/simulation_job.h"
#include "tools/python/bindings.h"

namespace airis::python {

void BindTools(py::module_& m) {
  m.def(
      "env_at",
      [](double lat_deg, double lon_deg, double alt_m, double date_year,
         const std::string& magnetic) {
        tools::EnvironmentQuery q;
        q.latitude_deg = lat_deg;
        q.longitude_deg = lon_deg;
        q.altitude_m = alt_m;
        q.date_decimal_year = date_year;
        const auto kind = engine::ParseEnum<engine::MagneticModelKind>(magnetic);
        if (!kind) {
          throw py::value_error("magnetic: expected " +
                                engine::EnumChoices<engine::MagneticModelKind>() + " (got '" +
                                magnetic + "')");
        }
        q.magnetic = *kind;
        const tools::EnvironmentReport r = tools::CalcEnvironmentAt(q);
        py::dict d;
        d["gravity_m_s2"] = r.gravity_m_s2;
        d["temperature_k"] = r.air.temperature_k;
        d["pressure_pa"] = r.air.pressure_pa;
        d["density_kg_m3"] = r.air.density_kg_m3;
        d["speed_of_sound_m_s"] = r.air.speed_of_sound_m_s;
        d["magnetic_field_ned_nt"] = r.field.field_ned_nt;
        d["declination_deg"] = engine::RadToDeg(r.field.declination_rad);
        d["inclination_deg"] = engine::RadToDeg(r.field.inclination_rad);
        d["horizontal_intensity_nt"] = r.field.horizontal_nt;
        d["total_intensity_nt"] = r.field.total_intensity_nt;
        d["magnetic_model"] = r.magnetic_model;
        return d;
      },
      py::arg("lat_deg"), py::arg("lon_deg"), py::arg("alt_m"), py::arg("date_year") = 2026.0,
      py::arg("magnetic") = "wmm",
      "Gravity, U.S. Standard Atmosphere 1976 and the magnetic field (WMM2025 or the tilted "
      "dipole) at a WGS84 point, as `airis env` prints them. ConfigError outside a model's range");

  m.def(
      "_scene_stats",
      [](const std::string& path, const std::string& text, std::optional<std::uint64_t> seed) {
        const scenes::Scene scene = tools::LoadSceneSource({path, text, seed});
        const scenes::SceneStats s = scenes::CalcSceneStats(scene);
        py::dict d;
        d["scene"] = scene.name;
        d["file"] = scene.path;
        d["files"] = scene.files;
        d["seed"] = scene.seed;
        d["objects"] = s.objects;
        d["models"] = s.models;
        d["meshes"] = s.meshes;
        d["materials"] = s.materials;
        d["stored_triangles"] = s.stored_triangles;
        d["drawn_triangles"] = s.drawn_triangles;
        d["vehicles"] = s.vehicles;
        d["memory_bytes"] = s.memory_bytes;
        py::dict classes;
        for (const auto& c : s.classes) classes[py::str(c.name)] = c.objects;
        d["classes"] = classes;
        if (!s.bounds_W.isEmpty()) {
          d["bounds_ned_m"] = std::vector<engine::Vec3>{s.bounds_W.min(), s.bounds_W.max()};
        }
        return d;
      },
      py::arg("path"), py::arg("text") = "", py::arg("seed") = py::none());
}

}  // namespace airis::python
