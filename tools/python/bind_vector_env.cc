// airis._VectorEnv: N environments of one task stepped in C++ in one call, with NumPy arrays in
// and out. The Gymnasium-style classes of airis/envs.py are built on it.
#include <pybind11/stl.h>

#include <atomic>
#include <optional>
#include <vector>

#include "tools/python/bindings.h"
#include "tools/python/kwargs_reader.h"
#include "tools/python/vector_env.h"

namespace airis::python {
namespace {

// The environment and a flag that refuses a second call while one runs without the GIL.
struct VectorEnvHandle {
  std::unique_ptr<VectorEnv> env;
  std::atomic<bool> busy{false};
};

class BusyGuard {
 public:
  explicit BusyGuard(std::atomic<bool>& busy) : busy_(busy) {
    if (busy_.exchange(true)) {
      throw std::runtime_error("this environment is already being stepped by another thread");
    }
  }
  ~BusyGuard() { busy_ = false; }
  BusyGuard(const BusyGuard&) = delete;
  BusyGuard& operator=(const BusyGuard&) = delete;

 private:
  std::atomic<bool>& busy_;
};

template <class T>
std::span<T> SpanOf(py::array& a) {
  return {static_cast<T*>(a.mutable_data()), static_cast<std::size_t>(a.nbytes()) / sizeof(T)};
}

// The arrays of one call's results, made fresh (the caller may keep them).
struct Outputs {
  py::array observations, images, rewards, terminated, truncated, success, collided, diverged;
  py::array has_final, final_observations, final_images;
  EnvOutputs spans;
};

std::vector<py::ssize_t> ImageShape(const VectorEnv& env) {
  std::vector<py::ssize_t> shape{env.num_envs(), env.image_height(), env.image_width()};
  if (env.image_channels() > 1) shape.push_back(env.image_channels());
  return shape;
}

py::array MakeImages(const VectorEnv& env, bool present) {
  if (!present || env.image_kind() == ImageKind::kNone) return py::array_t<std::uint8_t>(0);
  if (env.image_kind() == ImageKind::kRgb) return py::array_t<std::uint8_t>(ImageShape(env));
  return py::array_t<float>(ImageShape(env));
}

Outputs MakeOutputs(const VectorEnv& env, bool with_final) {
  const py::ssize_t n = env.num_envs();
  Outputs o;
  o.observations = py::array_t<float>({n, static_cast<py::ssize_t>(env.observation_size())});
  o.images = MakeImages(env, true);
  o.rewards = py::array_t<double>(n);
  o.terminated = py::array_t<bool>(n);
  o.truncated = py::array_t<bool>(n);
  o.success = py::array_t<bool>(n);
  o.collided = py::array_t<bool>(n);
  o.diverged = py::array_t<bool>(n);
  o.spans.observations = SpanOf<float>(o.observations);
  o.spans.images = SpanOf<std::uint8_t>(o.images);
  o.spans.rewards = SpanOf<double>(o.rewards);
  o.spans.terminated = SpanOf<std::uint8_t>(o.terminated);
  o.spans.truncated = SpanOf<std::uint8_t>(o.truncated);
  o.spans.success = SpanOf<std::uint8_t>(o.success);
  o.spans.collided = SpanOf<std::uint8_t>(o.collided);
  o.spans.diverged = SpanOf<std::uint8_t>(o.diverged);
  if (with_final) {
    o.has_final = py::array_t<bool>(n);
    o.final_observations =
        py::array_t<float>({n, static_cast<py::ssize_t>(env.observation_size())});
    o.final_images = MakeImages(env, true);
    o.spans.has_final = SpanOf<std::uint8_t>(o.has_final);
    o.spans.final_observations = SpanOf<float>(o.final_observations);
    o.spans.final_images = SpanOf<std::uint8_t>(o.final_images);
  }
  return o;
}

py::object ImagesOrNone(const VectorEnv& env, const py::array& images) {
  if (env.image_kind() == ImageKind::kNone) return py::none();
  return images;
}

}  // namespace

void BindVectorEnv(py::module_& m) {
  py::class_<VectorEnvHandle>(m, "_VectorEnv")
      .def(py::init([](const std::string& path, const std::string& text,
                       std::optional<std::uint64_t> seed, const py::dict& options) {
             VectorEnvConfig config;
             TaskConfig task;
             ActionConfig action;
             KwargsReader reader(options);
             reader.Read(config);
             reader.Read(task);
             reader.Read(action);
             reader.Finish();
             auto h = std::make_unique<VectorEnvHandle>();
             h->env = std::make_unique<VectorEnv>(tools::SceneSource{path, text, seed}, config,
                                                  task, action);
             return h;
           }),
           py::arg("path"), py::arg("text"), py::arg("seed"), py::arg("options"))
      .def_property_readonly("num_envs", [](const VectorEnvHandle& h) { return h.env->num_envs(); })
      .def_property_readonly("observation_size",
                             [](const VectorEnvHandle& h) { return h.env->observation_size(); })
      .def_property_readonly("action_size",
                             [](const VectorEnvHandle& h) { return h.env->action_size(); })
      .def_property_readonly("image_shape",
                             [](const VectorEnvHandle& h) -> py::object {
                               if (h.env->image_kind() == ImageKind::kNone) return py::none();
                               std::vector<py::ssize_t> s = ImageShape(*h.env);
                               s.erase(s.begin());
                               return py::tuple(py::cast(s));
                             })
      .def_property_readonly("image_kind",
                             [](const VectorEnvHandle& h) {
                               return std::string(engine::ToString(h.env->image_kind()));
                             })
      .def_property_readonly("autoreset",
                             [](const VectorEnvHandle& h) {
                               return std::string(engine::ToString(h.env->config().autoreset));
                             })
      .def_property_readonly("action_mode",
                             [](const VectorEnvHandle& h) {
                               return std::string(engine::ToString(h.env->action().mode));
                             })
      .def_property_readonly("task",
                             [](const VectorEnvHandle& h) {
                               return std::string(engine::ToString(h.env->task().kind));
                             })
      .def_property_readonly("max_depth_m",
                             [](const VectorEnvHandle& h) { return h.env->config().max_depth_m; })
      .def_property_readonly(
          "max_episode_steps",
          [](const VectorEnvHandle& h) { return h.env->config().max_episode_steps; })
      .def_property_readonly("threads",
                             [](const VectorEnvHandle& h) { return h.env->config().threads; })
      .def_property_readonly(
          "control_dt_s",
          [](const VectorEnvHandle& h) { return 1.0 / h.env->config().control_rate_hz; })
      .def_property_readonly("ticks_per_step",
                             [](const VectorEnvHandle& h) { return h.env->ticks_per_step(); })
      .def("action_bounds",
           [](const VectorEnvHandle& h) {
             std::vector<float> low, high;
             h.env->ActionBounds(low, high);
             return py::make_tuple(py::array_t<float>(low.size(), low.data()),
                                   py::array_t<float>(high.size(), high.data()));
           })
      .def(
          "reset",
          [](VectorEnvHandle& h, const std::vector<std::optional<std::uint64_t>>& seeds) {
            VectorEnv& env = *h.env;
            if (static_cast<int>(seeds.size()) != env.num_envs()) {
              throw py::value_error("reset: expected " + std::to_string(env.num_envs()) +
                                    " seeds (or None), got " + std::to_string(seeds.size()));
            }
            BusyGuard guard(h.busy);
            Outputs o = MakeOutputs(env, false);
            {
              py::gil_scoped_release release;
              env.Reset(seeds, o.spans);
            }
            return py::make_tuple(o.observations, ImagesOrNone(env, o.images));
          },
          py::arg("seeds"))
      .def(
          "step",
          [](VectorEnvHandle& h,
             const py::array_t<float, py::array::c_style | py::array::forcecast>& actions) {
            VectorEnv& env = *h.env;
            if (actions.ndim() != 2 || actions.shape(0) != env.num_envs() ||
                actions.shape(1) != env.action_size()) {
              throw py::value_error("step: actions must have shape (" +
                                    std::to_string(env.num_envs()) + ", " +
                                    std::to_string(env.action_size()) + ")");
            }
            BusyGuard guard(h.busy);
            const bool with_final = env.config().autoreset == AutoReset::kSameStep;
            Outputs o = MakeOutputs(env, with_final);
            const std::span<const float> a(actions.data(),
                                           static_cast<std::size_t>(actions.size()));
            {
              py::gil_scoped_release release;
              env.Step(a, o.spans);
            }
            py::dict info;
            info["success"] = o.success;
            info["collided"] = o.collided;
            info["diverged"] = o.diverged;
            if (with_final) {
              info["has_final"] = o.has_final;
              info["final_observations"] = o.final_observations;
              info["final_images"] = ImagesOrNone(env, o.final_images);
            }
            return py::make_tuple(o.observations, ImagesOrNone(env, o.images), o.rewards,
                                  o.terminated, o.truncated, info);
          },
          py::arg("actions"))
      .def(
          "goal_ned_m",
          [](const VectorEnvHandle& h, int i) {
            const engine::Vec3& g = h.env->goal_W(i);
            return std::vector<double>{g.x(), g.y(), g.z()};
          },
          py::arg("i"))
      .def(
          "position_ned_m",
          [](const VectorEnvHandle& h, int i) {
            const engine::Simulation& sim = h.env->simulation(i);
            const engine::Vec3& p = sim.world().vehicle(h.env->vehicle_index()).state().p_W;
            return std::vector<double>{p.x(), p.y(), p.z()};
          },
          py::arg("i"))
      .def("episode_steps",
           [](const VectorEnvHandle& h, int i) { return h.env->episode_steps(i); });
}

}  // namespace airis::python
