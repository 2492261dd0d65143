#include "tools/python/vector_env.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/render_scene.h"

namespace airis::python {
namespace {

constexpr std::array<engine::EnumName<AutoReset>, 3> kAutoResetNames{{
    {AutoReset::kNextStep, "next_step"},
    {AutoReset::kSameStep, "same_step"},
    {AutoReset::kDisabled, "disabled"},
}};
constexpr std::array<engine::EnumName<ImageKind>, 3> kImageNames{{
    {ImageKind::kNone, "none"},
    {ImageKind::kDepth, "depth"},
    {ImageKind::kRgb, "rgb"},
}};

// Options are checked as the Python constructor's keyword arguments: the message names the option.
template <class Config>
const Config& Checked(const Config& config) {
  try {
    config.Validate();
  } catch (const engine::InvalidField& e) {
    throw engine::ConfigError({}, e.field(), e.problem());
  }
  return config;
}

// The heading of q_WB (rad).
double YawOf(const engine::Quat& q_WB) { return engine::EulerFromQuat(q_WB).yaw_rad; }

}  // namespace

std::span<const engine::EnumName<AutoReset>> EnumNames(AutoReset) { return kAutoResetNames; }
std::span<const engine::EnumName<ImageKind>> EnumNames(ImageKind) { return kImageNames; }

void VectorEnvConfig::Validate() const {
  engine::Require(num_envs >= 1 && num_envs <= 100000, "num_envs",
                  "must be between 1 and 100000 (got " + std::to_string(num_envs) + ")");
  engine::Require(threads >= 1 && threads <= 64, "threads",
                  "must be between 1 and 64 (got " + std::to_string(threads) + ")");
  engine::RequirePositive("control_rate_hz", control_rate_hz);
  engine::Require(max_episode_steps >= 1, "max_episode_steps",
                  "must be >= 1 (got " + std::to_string(max_episode_steps) + ")");
  engine::Require(camera.empty() == (image == ImageKind::kNone),
                  camera.empty() ? "image" : "camera",
                  camera.empty() ? "an image observation needs a camera (set camera=...)"
                                 : "a camera needs an image kind (image='depth' or 'rgb')");
  engine::RequirePositive("max_depth_m", max_depth_m);
}

// One environment: its world, task and episode bookkeeping. Heap-allocated, so the collision
// listener's pointer stays valid.
struct VectorEnv::Slot {
  explicit Slot(const TaskConfig& task) : task(task) {}
  engine::RandomStream random{0};  // replaced by the first seeded reset
  std::unique_ptr<engine::Simulation> sim;
  Task task;
  double yaw_rad = 0.0;
  int steps = 0;
  bool needs_reset = true;  // before the first reset, and after an episode ends
  bool collided = false;    // set by the world's collision listener during a step
  bool diverged = false;
  engine::CameraFrame frame;  // the last image rendered (buffers reused)
};

VectorEnv::VectorEnv(const tools::SceneSource& scene, const VectorEnvConfig& config,
                     const TaskConfig& task, const ActionConfig& action)
    : source_(scene),
      scene_(tools::LoadSceneSource(scene)),
      config_(Checked(config)),
      task_(Checked(task)),
      action_(Checked(action)),
      pool_(config_.threads) {
  const double ticks = scene_.physics.rate_hz / config_.control_rate_hz;
  if (std::abs(ticks - std::round(ticks)) > 1e-9 || ticks < 1.0) {
    throw engine::ConfigError({}, "control_rate_hz",
                              "must divide the scene's physics rate of " +
                                  engine::FormatNumber(scene_.physics.rate_hz) + " Hz (got " +
                                  engine::FormatNumber(config_.control_rate_hz) + ")");
  }
  ticks_per_step_ = static_cast<int>(std::round(ticks));

  // A first world shows which vehicle learns and what its camera is; its cameras, if any, make
  // the GPU scene that the observations are rendered with.
  std::unique_ptr<engine::World> first = scenes::BuildWorld(scene_, scene_.seed, resources_);
  if (first->vehicle_count() == 0) {
    throw engine::ConfigError({scene_.path, 0, 0}, "vehicles", "the scene has no vehicle");
  }
  if (!config_.vehicle.empty()) {
    const int found = first->FindVehicle(config_.vehicle);
    if (found < 0) {
      throw engine::ConfigError({}, "vehicle",
                                "no vehicle '" + config_.vehicle + "' in the scene " + scene_.path);
    }
    vehicle_ = static_cast<std::size_t>(found);
  }
  actuator_count_ = first->vehicle(vehicle_).actuator_count();
  if (actuator_count_ > engine::kMaxActuators) {
    throw engine::ConfigError({}, "vehicle", "has more than 12 actuators");
  }
  if (!config_.camera.empty()) {
    for (const auto& sensor : first->sensors(vehicle_)) {
      const engine::ImageSensor* image = sensor->image();
      if (!image) continue;
      for (const engine::ImageStream& s : image->streams()) {
        if (s.name == config_.camera && s.rig == s.name) camera_ = s;
      }
    }
    if (!camera_) {
      throw engine::ConfigError({}, "camera",
                                "vehicle '" + first->vehicle(vehicle_).name() +
                                    "' has no mono camera '" + config_.camera + "'");
    }
    engine::RenderOutputs outputs;
    outputs.rgb = config_.image == ImageKind::kRgb;
    outputs.depth_planar = config_.image == ImageKind::kDepth;
    renderer_ = std::make_unique<engine::CameraRenderer>(resources_.render_scene->context(),
                                                         camera_->intrinsics, outputs,
                                                         camera_->detail_tolerance_px);
  }
  // The worlds of the episodes hold the learning vehicle alone, without sensors: observations are
  // its ground truth (the flight controller reads truth too) and images are rendered by
  // renderer_ (GL objects may not be made on worker threads). Other vehicles of the scene would
  // only cost time.
  scenes::VehicleDescription learner = scene_.vehicles[vehicle_];
  learner.sensors.clear();
  scene_.vehicles.assign(1, learner);
  vehicle_ = 0;
  for (int i = 0; i < config_.num_envs; ++i) slots_.push_back(std::make_unique<Slot>(task_));
}

VectorEnv::~VectorEnv() = default;

int VectorEnv::image_height() const { return camera_ ? camera_->intrinsics.height_px : 0; }
int VectorEnv::image_width() const { return camera_ ? camera_->intrinsics.width_px : 0; }

std::size_t VectorEnv::image_size() const {
  if (!camera_) return 0;
  const std::size_t pixels = static_cast<std::size_t>(image_width()) * image_height();
  return config_.image == ImageKind::kRgb ? pixels * 3 : pixels * sizeof(float);
}

const engine::Simulation& VectorEnv::simulation(int i) const {
  const Slot& slot = *slots_.at(static_cast<std::size_t>(i));
  if (!slot.sim) throw std::logic_error("environment " + std::to_string(i) + " was never reset");
  return *slot.sim;
}

const Vec3& VectorEnv::goal_W(int i) const {
  return slots_.at(static_cast<std::size_t>(i))->task.goal_W();
}

int VectorEnv::episode_steps(int i) const { return slots_.at(static_cast<std::size_t>(i))->steps; }

void VectorEnv::ResetSlot(Slot& slot, std::optional<std::uint64_t> seed) {
  if (seed) slot.random = engine::RandomStream(*seed);
  const std::uint64_t world_seed = slot.random.NextU64();
  const engine::RigidBodyState start = slot.task.Reset(slot.random);
  std::unique_ptr<engine::World> world = scenes::BuildWorld(scene_, world_seed, resources_);
  world->vehicle(vehicle_).state() = start;
  Slot* target = &slot;
  const std::size_t vehicle = vehicle_;
  world->AddCollisionListener([target, vehicle](const engine::CollisionEvent& e) {
    if (e.vehicle == vehicle) target->collided = true;
  });
  slot.sim = std::make_unique<engine::Simulation>(std::move(world),
                                                  engine::SimulationConfig{scene_.physics.rate_hz});
  slot.yaw_rad = YawOf(start.q_WB);
  slot.steps = 0;
  slot.needs_reset = false;
  slot.collided = false;
  slot.diverged = false;
}

void VectorEnv::Observe(const Slot& slot, std::size_t i, std::span<float> observations) const {
  const auto n = static_cast<std::size_t>(observation_size());
  const std::span<float> out = observations.subspan(i * n, n);
  slot.task.Observe(slot.sim->world().vehicle(vehicle_).state(), out);
  // A diverged state is not a valid observation; zeros keep it inside the space.
  for (float& v : out) {
    if (!std::isfinite(v)) v = 0.0f;
  }
}

void VectorEnv::RenderImage(Slot& slot, std::span<std::uint8_t> image) {
  const engine::Simulation& sim = *slot.sim;
  const engine::RigidBodyState& state = sim.world().vehicle(vehicle_).state();
  renderer_->Render(resources_.render_scene->gpu_scene(),
                    engine::CalcImageStreamPose(*camera_, &state), sim.clock().now_ns(),
                    slot.frame);
  if (config_.image == ImageKind::kRgb) {
    const std::vector<std::uint8_t>& rgba = slot.frame.rgba.pixels;
    for (std::size_t p = 0, n = rgba.size() / 4; p < n; ++p) {
      std::memcpy(&image[p * 3], &rgba[p * 4], 3);
    }
    return;
  }
  const std::vector<float>& depth = slot.frame.depth_planar_m.pixels;
  const auto max_m = static_cast<float>(config_.max_depth_m);
  for (std::size_t p = 0; p < depth.size(); ++p) {
    const float d = std::isfinite(depth[p]) ? std::min(depth[p], max_m) : max_m;
    std::memcpy(&image[p * sizeof(float)], &d, sizeof(float));
  }
}

void VectorEnv::Reset(std::span<const std::optional<std::uint64_t>> seeds, const EnvOutputs& out) {
  const auto n = static_cast<std::size_t>(num_envs());
  AIRIS_DEMAND(seeds.size() == n && out.observations.size() == n * observation_size());
  AIRIS_DEMAND(out.images.size() == n * image_size());
  pool_.Run(n, [&](std::size_t i) {
    ResetSlot(*slots_[i], seeds[i]);
    Observe(*slots_[i], i, out.observations);
  });
  if (camera_) {
    for (std::size_t i = 0; i < n; ++i) {
      RenderImage(*slots_[i], out.images.subspan(i * image_size(), image_size()));
    }
  }
}

void VectorEnv::StepSlot(Slot& slot, std::span<const float> action, std::size_t i,
                         const EnvOutputs& out) {
  out.rewards[i] = 0.0;
  out.terminated[i] = out.truncated[i] = out.success[i] = out.collided[i] = out.diverged[i] = 0;
  if (!out.has_final.empty()) out.has_final[i] = 0;
  if (slot.needs_reset) {
    // kNextStep: this step starts the next episode (and ignores the action).
    ResetSlot(slot, std::nullopt);
    Observe(slot, i, out.observations);
    return;
  }
  engine::Simulation& sim = *slot.sim;
  engine::Vehicle& vehicle = sim.world().vehicle(vehicle_);
  vehicle.SetCommand(action_.ToCommand(action, actuator_count_, slot.yaw_rad));
  slot.collided = false;
  try {
    for (int k = 0; k < ticks_per_step_; ++k) sim.Step();
  } catch (const engine::SimulationError&) {
    slot.diverged = true;
  }
  ++slot.steps;
  TaskOutcome outcome = slot.task.Evaluate(vehicle.state(), slot.collided);
  if (slot.diverged) outcome = TaskOutcome{0.0, true, false};
  out.rewards[i] = outcome.reward;
  out.terminated[i] = outcome.terminated;
  out.truncated[i] = !outcome.terminated && slot.steps >= config_.max_episode_steps;
  out.success[i] = outcome.success;
  out.collided[i] = slot.collided;
  out.diverged[i] = slot.diverged;
  Observe(slot, i, out.observations);
  if (out.terminated[i] || out.truncated[i]) slot.needs_reset = true;
}

void VectorEnv::Step(std::span<const float> actions, const EnvOutputs& out) {
  const auto n = static_cast<std::size_t>(num_envs());
  const auto a = static_cast<std::size_t>(action_size());
  AIRIS_DEMAND(actions.size() == n * a && out.observations.size() == n * observation_size());
  AIRIS_DEMAND(out.images.size() == n * image_size() && out.rewards.size() == n);
  AIRIS_DEMAND(config_.autoreset != AutoReset::kSameStep ||
               (out.has_final.size() == n &&
                out.final_observations.size() == out.observations.size() &&
                out.final_images.size() == out.images.size()));
  for (std::size_t i = 0; i < n; ++i) {
    const Slot& slot = *slots_[i];
    if (!slot.sim) {
      throw std::logic_error("environment " + std::to_string(i) +
                             " was never reset: call reset() before step()");
    }
    if (slot.needs_reset && config_.autoreset == AutoReset::kDisabled) {
      throw std::logic_error("environment " + std::to_string(i) +
                             " has finished its episode: call reset() before step()");
    }
    for (std::size_t k = 0; k < a; ++k) {
      if (!std::isfinite(actions[i * a + k])) {
        throw std::invalid_argument("action of environment " + std::to_string(i) +
                                    " is not finite (value " + std::to_string(k) + ")");
      }
    }
  }
  pool_.Run(n, [&](std::size_t i) { StepSlot(*slots_[i], actions.subspan(i * a, a), i, out); });
  const std::size_t image = image_size();
  if (camera_) {
    for (std::size_t i = 0; i < n; ++i)
      RenderImage(*slots_[i], out.images.subspan(i * image, image));
  }
  if (config_.autoreset != AutoReset::kSameStep) return;
  // kSameStep: the observations of the finished environments become their final ones, and the
  // first observations of their next episodes take their place.
  const auto obs = static_cast<std::size_t>(observation_size());
  pool_.Run(n, [&](std::size_t i) {
    Slot& slot = *slots_[i];
    if (!slot.needs_reset) return;
    out.has_final[i] = 1;
    std::copy_n(&out.observations[i * obs], obs, &out.final_observations[i * obs]);
    if (image > 0) std::copy_n(&out.images[i * image], image, &out.final_images[i * image]);
    ResetSlot(slot, std::nullopt);
    Observe(slot, i, out.observations);
  });
  if (camera_) {
    for (std::size_t i = 0; i < n; ++i) {
      if (out.has_final[i]) RenderImage(*slots_[i], out.images.subspan(i * image, image));
    }
  }
}

}  // namespace airis::python
