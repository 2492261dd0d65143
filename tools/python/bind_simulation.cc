// airis.Simulation and airis.Vehicle: loading, stepping, missions, state and setpoints.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/frames.h"
#include "engine/dataset/telemetry_recorder.h"
#include "scenes/scene_overrides.h"
#include "tools/python/bindings.h"
#include "tools/python/handles.h"

namespace airis::python {
namespace {

using engine::Vec3;

// The vehicle's state, copied when read (docs/python.md, "State"): frames and units in the names.
struct StateSnapshot {
  engine::TimeNs time_ns = 0;
  Vec3 position_ned_m = Vec3::Zero();
  Vec3 velocity_ned_m_s = Vec3::Zero();
  Eigen::Vector4d attitude_wxyz = Eigen::Vector4d(1, 0, 0, 0);  // q_WB: FRD body -> NED world
  Vec3 angular_velocity_frd_rad_s = Vec3::Zero();
  Vec3 acceleration_ned_m_s2 = Vec3::Zero();
  Vec3 euler_deg = Vec3::Zero();  // roll, pitch, yaw (ZYX)
};

const char* StateName(engine::MissionRunner::State s) {
  switch (s) {
    case engine::MissionRunner::State::kSucceeded:
      return "succeeded";
    case engine::MissionRunner::State::kFailed:
      return "failed";
    case engine::MissionRunner::State::kRunning:
      break;
  }
  return "running";
}

Vec3 Vec3Arg(const Eigen::VectorXd& v, const char* name) {
  if (v.size() != 3 || !v.allFinite()) {
    throw py::value_error(std::string(name) + ": expected 3 finite numbers (got " +
                          std::to_string(v.size()) + " values" +
                          (v.allFinite() ? "" : ", not all finite") + ")");
  }
  return Vec3(v[0], v[1], v[2]);
}

double FiniteArg(double value, const char* name) {
  if (!std::isfinite(value)) throw py::value_error(std::string(name) + ": must be finite");
  return value;
}

double ThrustArg(double value) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw py::value_error("thrust_fraction: must be in [0, 1] (got " + std::to_string(value) + ")");
  }
  return value;
}

engine::Quat QuatArg(const Eigen::VectorXd& q, const char* name) {
  if (q.size() != 4 || !q.allFinite() || q.norm() < 1e-9) {
    throw py::value_error(std::string(name) +
                          ": expected a non-zero quaternion [w, x, y, z] of 4 finite numbers");
  }
  return engine::Quat(q[0], q[1], q[2], q[3]).normalized();
}

StateSnapshot Snapshot(const VehicleHandle& h) {
  engine::World& w = h.sim->world();
  const engine::RigidBodyState& s = w.vehicle(h.vehicle).state();
  StateSnapshot out;
  out.time_ns = h.sim->simulation().clock().now_ns();
  out.position_ned_m = s.p_W;
  out.velocity_ned_m_s = s.v_W;
  out.attitude_wxyz = Eigen::Vector4d(s.q_WB.w(), s.q_WB.x(), s.q_WB.y(), s.q_WB.z());
  out.angular_velocity_frd_rad_s = s.w_B;
  out.acceleration_ned_m_s2 = w.accelerations(h.vehicle).a_W;
  const engine::EulerAngles e = engine::EulerFromQuat(s.q_WB);
  out.euler_deg = Vec3(engine::RadToDeg(e.roll_rad), engine::RadToDeg(e.pitch_rad),
                       engine::RadToDeg(e.yaw_rad));
  return out;
}

void Command(const VehicleHandle& h, const engine::VehicleCommand& c) {
  try {
    h.get().SetCommand(c);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

py::dict CollisionDict(const engine::CollisionEvent& e) {
  py::dict d;
  d["time_ns"] = e.time_ns;
  d["time_s"] = engine::ToSeconds(e.time_ns);
  d["vehicle"] = e.vehicle_name;
  d["object"] = e.object_name;
  d["class_id"] = e.class_id;
  d["instance_id"] = e.instance_id;
  d["other_vehicle"] = e.other_vehicle;
  d["point_ned_m"] = e.point_W;
  d["normal_ned"] = e.normal_W;
  d["impulse_n_s"] = e.impulse_Ns;
  return d;
}

// One track of the mission in flight.
py::dict TrackDict(const engine::MissionSession& s, std::size_t t) {
  const engine::MissionRunner& r = s.runner(t);
  py::dict d;
  d["vehicle"] = r.track().vehicle;
  d["state"] = StateName(r.state());
  d["failure"] = r.failure();
  d["step"] = r.current_step();
  d["steps"] = static_cast<int>(r.track().steps.size());
  d["distance_flown_m"] = s.distance_flown_m(t);
  d["contacts"] = r.contacts();
  d["collisions"] = r.collisions();
  return d;
}

// The mission as a whole, with "vehicle", "step", "steps" and "distance_flown_m" of its first
// track (the only one of a single-vehicle mission) and every track in "tracks".
py::dict MissionDict(PythonSimulation& sim) {
  const engine::MissionSession& s = sim.session();
  py::dict d = TrackDict(s, 0);
  d["state"] = StateName(s.state());
  d["succeeded"] = s.state() == engine::MissionRunner::State::kSucceeded;
  d["failure"] = s.failure();
  d["time_s"] = sim.simulation().clock().now_s();
  int contacts = 0;
  int collisions = 0;
  py::list tracks;
  for (std::size_t t = 0; t < s.track_count(); ++t) {
    contacts += s.runner(t).contacts();
    collisions += s.runner(t).collisions();
    tracks.append(TrackDict(s, t));
  }
  d["contacts"] = contacts;
  d["collisions"] = collisions;
  d["tracks"] = tracks;
  return d;
}

std::int64_t TicksFor(const engine::Simulation& sim, double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) {
    throw py::value_error("seconds: must be finite and >= 0 (got " + std::to_string(seconds) + ")");
  }
  const engine::TimeNs span = engine::SecondsToNs(seconds, "seconds");
  const engine::TimeNs step = sim.clock().step_ns();
  return (span + step - 1) / step;  // as Simulation::RunFor: whole ticks covering the span
}

const std::function<bool()> kCheckSignals = [] { return CheckSignals(); };

}  // namespace

void BindSimulation(py::module_& m) {
  py::class_<StateSnapshot>(m, "VehicleState",
                            "A vehicle's state at time_ns (a copy). Frames: NED world, FRD body.")
      .def_readonly("time_ns", &StateSnapshot::time_ns)
      .def_property_readonly("time_s",
                             [](const StateSnapshot& s) { return engine::ToSeconds(s.time_ns); })
      .def_readonly("position_ned_m", &StateSnapshot::position_ned_m)
      .def_readonly("velocity_ned_m_s", &StateSnapshot::velocity_ned_m_s)
      .def_readonly("attitude_wxyz", &StateSnapshot::attitude_wxyz,
                    "quaternion q_WB [w, x, y, z]: rotates FRD body vectors into NED")
      .def_readonly("angular_velocity_frd_rad_s", &StateSnapshot::angular_velocity_frd_rad_s)
      .def_readonly("acceleration_ned_m_s2", &StateSnapshot::acceleration_ned_m_s2,
                    "over the last tick, contacts included, gravity included")
      .def_readonly("euler_deg", &StateSnapshot::euler_deg, "roll, pitch, yaw (ZYX), degrees")
      .def("__repr__", [](const StateSnapshot& s) {
        const auto& p = s.position_ned_m;
        return "VehicleState(t=" + std::to_string(engine::ToSeconds(s.time_ns)) +
               " s, position_ned_m=[" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
               ", " + std::to_string(p.z()) + "])";
      });

  py::class_<VehicleHandle>(m, "Vehicle", py::dynamic_attr())
      .def_property_readonly("name", [](const VehicleHandle& h) { return h.get().name(); })
      .def_property_readonly("index", [](const VehicleHandle& h) { return h.vehicle; })
      .def_property_readonly("actuator_count",
                             [](const VehicleHandle& h) { return h.get().actuator_count(); })
      .def_property_readonly("state", &Snapshot)
      .def(
          "truth",
          [](const VehicleHandle& h) -> py::object {
            static const RecordLayout layout(engine::TelemetryRecorder::TruthColumns());
            std::vector<double> row;
            engine::TelemetryRecorder::CopyTruthRow(h.sim->world(), h.vehicle, row);
            std::vector<std::uint8_t> bytes(layout.record_bytes());
            layout.Pack(h.sim->simulation().clock().now_ns(), row, bytes.data());
            return RecordsArray(std::move(bytes), DtypeOf(layout))[py::int_(0)];
          },
          "The ground-truth row now, with the columns and types of <vehicle>.truth in a dataset")
      .def(
          "set_state",
          [](const VehicleHandle& h, std::optional<Eigen::VectorXd> p,
             std::optional<Eigen::VectorXd> v, std::optional<Eigen::VectorXd> q,
             std::optional<Eigen::VectorXd> w) {
            engine::RigidBodyState& s = h.get().state();
            if (p) s.p_W = Vec3Arg(*p, "position_ned_m");
            if (v) s.v_W = Vec3Arg(*v, "velocity_ned_m_s");
            if (q) s.q_WB = QuatArg(*q, "attitude_wxyz");
            if (w) s.w_B = Vec3Arg(*w, "angular_velocity_frd_rad_s");
          },
          py::arg("position_ned_m") = py::none(), py::arg("velocity_ned_m_s") = py::none(),
          py::arg("attitude_wxyz") = py::none(), py::arg("angular_velocity_frd_rad_s") = py::none(),
          "Moves the body (the next tick integrates from there)")
      .def(
          "set_rotor_commands",
          [](const VehicleHandle& h, const Eigen::VectorXd& u) {
            const int n = h.get().actuator_count();
            if (u.size() != n) {
              throw py::value_error("set_rotor_commands: expected " + std::to_string(n) +
                                    " commands for vehicle '" + h.get().name() + "' (got " +
                                    std::to_string(u.size()) + ")");
            }
            engine::VehicleCommand c;
            c.mode = engine::CommandMode::kMotors;
            for (int i = 0; i < n; ++i) {
              if (!std::isfinite(u[i])) {
                throw py::value_error("set_rotor_commands: command " + std::to_string(i) +
                                      " is not finite");
              }
              c.motors[static_cast<std::size_t>(i)] = std::clamp(u[i], 0.0, 1.0);
            }
            Command(h, c);
          },
          py::arg("u"), "Normalised actuator commands in [0, 1] (clamped), one per actuator")
      .def(
          "set_position",
          [](const VehicleHandle& h, const Eigen::VectorXd& p, double yaw_deg,
             double speed_limit_m_s, std::optional<Eigen::VectorXd> v) {
            engine::VehicleCommand c;
            c.mode = engine::CommandMode::kPosition;
            c.position_W = Vec3Arg(p, "position_ned_m");
            c.yaw_rad = engine::DegToRad(FiniteArg(yaw_deg, "yaw_deg"));
            if (!(speed_limit_m_s >= 0.0)) throw py::value_error("speed_limit_m_s: must be >= 0");
            c.speed_limit_m_s = speed_limit_m_s;
            if (v) c.velocity_W = Vec3Arg(*v, "velocity_ned_m_s");
            Command(h, c);
          },
          py::arg("position_ned_m"), py::arg("yaw_deg") = 0.0, py::arg("speed_limit_m_s") = 0.0,
          py::arg("velocity_ned_m_s") = py::none(),
          "Position setpoint (world NED, m) with yaw (0 = north) and an optional speed limit")
      .def(
          "set_velocity",
          [](const VehicleHandle& h, const Eigen::VectorXd& v, double yaw_deg) {
            engine::VehicleCommand c;
            c.mode = engine::CommandMode::kVelocity;
            c.velocity_W = Vec3Arg(v, "velocity_ned_m_s");
            c.yaw_rad = engine::DegToRad(FiniteArg(yaw_deg, "yaw_deg"));
            Command(h, c);
          },
          py::arg("velocity_ned_m_s"), py::arg("yaw_deg") = 0.0,
          "Velocity setpoint (world NED, m/s) with yaw")
      .def(
          "set_attitude",
          [](const VehicleHandle& h, const Eigen::VectorXd& q, double thrust) {
            engine::VehicleCommand c;
            c.mode = engine::CommandMode::kAttitudeThrust;
            c.attitude_WB = QuatArg(q, "attitude_wxyz");
            c.thrust_fraction = ThrustArg(thrust);
            Command(h, c);
          },
          py::arg("attitude_wxyz"), py::arg("thrust_fraction"),
          "Attitude setpoint q_WB [w, x, y, z] and collective thrust fraction in [0, 1]")
      .def(
          "set_rates",
          [](const VehicleHandle& h, const Eigen::VectorXd& w, double thrust) {
            engine::VehicleCommand c;
            c.mode = engine::CommandMode::kRatesThrust;
            c.rates_B = Vec3Arg(w, "rates_frd_rad_s");
            c.thrust_fraction = ThrustArg(thrust);
            Command(h, c);
          },
          py::arg("rates_frd_rad_s"), py::arg("thrust_fraction"),
          "Body-rate setpoint (FRD, rad/s) and collective thrust fraction in [0, 1]")
      .def(
          "land",
          [](const VehicleHandle& h) {
            engine::VehicleCommand c;
            c.mode = engine::CommandMode::kLand;
            c.position_W = h.get().state().p_W;
            c.yaw_rad = engine::EulerFromQuat(h.get().state().q_WB).yaw_rad;
            Command(h, c);
          },
          "Descends where it is and disarms on touchdown (landed becomes true)")
      .def("disarm", [](const VehicleHandle& h) { Command(h, engine::VehicleCommand{}); })
      .def_property_readonly("command_mode",
                             [](const VehicleHandle& h) {
                               return std::string(engine::ToString(h.get().command().mode));
                             })
      .def_property_readonly("rotor_commands",
                             [](const VehicleHandle& h) {
                               const auto u = h.get().actuator_commands();
                               return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
                                   u.data(), static_cast<Eigen::Index>(u.size())));
                             })
      .def_property_readonly("landed", [](const VehicleHandle& h) { return h.get().landed(); })
      .def_property_readonly("collisions",
                             [](const VehicleHandle& h) {
                               py::list out;
                               for (const auto& e : h.sim->collisions(h.vehicle)) {
                                 out.append(CollisionDict(e));
                               }
                               return out;
                             })
      .def_property_readonly("sensor_handles",
                             [](const VehicleHandle& h) {
                               py::list out;
                               const auto sensors = h.sim->world().sensors(h.vehicle);
                               for (std::size_t i = 0; i < sensors.size(); ++i) {
                                 out.append(SensorHandle{h.sim, h.vehicle, i});
                               }
                               return out;
                             })
      .def("__repr__",
           [](const VehicleHandle& h) { return "<airis.Vehicle '" + h.get().name() + "'>"; });

  py::class_<PythonSimulation, std::shared_ptr<PythonSimulation>>(m, "_Simulation")
      .def(py::init([](const std::string& path, const std::string& text,
                       std::optional<std::uint64_t> seed, std::size_t max_samples,
                       const std::vector<std::string>& overrides, int threads) {
             if (max_samples < 1) throw py::value_error("max_samples: must be >= 1");
             return std::make_shared<PythonSimulation>(
                 tools::SceneSource{path, text, seed, scenes::ParseSceneOverrides(overrides)},
                 max_samples, threads);
           }),
           py::arg("path"), py::arg("text") = "", py::arg("seed") = py::none(),
           py::arg("max_samples") = 100000, py::arg("overrides") = std::vector<std::string>{},
           py::arg("threads") = 1)
      .def_property_readonly("threads",
                             [](PythonSimulation& s) { return s.simulation().threads(); })
      .def_property_readonly("time_ns",
                             [](PythonSimulation& s) { return s.simulation().clock().now_ns(); })
      .def_property_readonly("time_s",
                             [](PythonSimulation& s) { return s.simulation().clock().now_s(); })
      .def_property_readonly("tick",
                             [](PythonSimulation& s) { return s.simulation().clock().tick(); })
      .def_property_readonly("dt_s",
                             [](PythonSimulation& s) { return s.simulation().clock().step_s(); })
      .def_property_readonly("seed", [](PythonSimulation& s) { return s.job().scene().seed; })
      .def_property_readonly("scene_path", [](PythonSimulation& s) { return s.job().scene().path; })
      // step() without arguments first: pybind11 tries overloads in order, and this is the call
      // whose overhead matters (one tick per call from a Python control loop).
      .def("step",
           [](PythonSimulation& s) {
             if (s.has_mission()) {
               s.RunTicks(1, {});
             } else {
               s.simulation().Step();
             }
           })
      .def(
          "step",
          [](PythonSimulation& s, std::int64_t n) {
            if (n < 0) throw py::value_error("n: must be >= 0 (got " + std::to_string(n) + ")");
            s.RunTicks(n, kCheckSignals);
          },
          py::arg("n"),
          "Runs n physics ticks (a mission in flight is flown through them). Ctrl-C stops it "
          "between ticks (KeyboardInterrupt)")
      .def(
          "run_for",
          [](PythonSimulation& s, double seconds) {
            s.RunTicks(TicksFor(s.simulation(), seconds), kCheckSignals);
          },
          py::arg("seconds"), "Runs whole ticks covering `seconds` of simulated time")
      .def(
          "start_mission",
          [](const std::shared_ptr<PythonSimulation>& s, const std::string& path) {
            s->StartMission(path);
          },
          py::arg("path"), "Starts flying a mission file; step() and run_for() fly it")
      .def(
          "run_mission",
          [](PythonSimulation& s, std::optional<std::string> path,
             std::optional<double> timeout_s) {
            if (path) s.StartMission(*path);
            if (!s.has_mission()) throw py::value_error("run_mission: no mission (give a path)");
            engine::TimeNs until = std::numeric_limits<engine::TimeNs>::max();
            if (timeout_s) {
              until = s.simulation().clock().now_ns() +
                      TicksFor(s.simulation(), *timeout_s) * s.simulation().clock().step_ns();
            }
            s.RunMission(until, kCheckSignals);
            return MissionDict(s);
          },
          py::arg("path") = py::none(), py::arg("timeout_s") = py::none(),
          "Flies the mission (a file, or the one started) until it ends or timeout_s passes; "
          "returns its outcome")
      .def_property_readonly("mission",
                             [](PythonSimulation& s) -> py::object {
                               if (!s.has_mission()) return py::none();
                               return MissionDict(s);
                             })
      .def_property_readonly("vehicle_handles", [](const std::shared_ptr<PythonSimulation>& s) {
        py::list out;
        for (std::size_t i = 0; i < s->world().vehicle_count(); ++i) {
          out.append(VehicleHandle{s, i});
        }
        return out;
      });
}

}  // namespace airis::python
