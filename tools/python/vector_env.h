#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/config.h"
#include "engine/core/worker_pool.h"
#include "engine/world/image_sensor.h"
#include "engine/world/simulation.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "tools/jobs/simulation_job.h"
#include "tools/python/env_actions.h"
#include "tools/python/env_tasks.h"

namespace airis::engine {
class CameraRenderer;
}  // namespace airis::engine

namespace airis::python {

/// When a finished environment of a VectorEnv starts its next episode (Gymnasium's vector
/// autoreset modes).
enum class AutoReset {
  kNextStep,  ///< the step after the one that ended it resets it (its action is ignored)
  kSameStep,  ///< the step that ends it resets it; the last observation is kept apart
  kDisabled,  ///< never: a finished environment must be reset before it is stepped again
};
/// Spellings: next_step, same_step, disabled.
std::span<const engine::EnumName<AutoReset>> EnumNames(AutoReset);

/// What kind of image an environment observes, if any.
enum class ImageKind { kNone, kDepth, kRgb };
/// Spellings: none, depth, rgb.
std::span<const engine::EnumName<ImageKind>> EnumNames(ImageKind);

/// Settings of a VectorEnv (the Python environments' constructor options).
struct VectorEnvConfig {
  int num_envs = 1;
  int threads = 1;                ///< 1 to 64; results do not depend on it
  double control_rate_hz = 50.0;  ///< steps per simulated second; divides the physics rate
  int max_episode_steps = 500;    ///< truncated after this many steps
  AutoReset autoreset = AutoReset::kNextStep;
  std::string vehicle;                 ///< the scene's vehicle that learns ("": its first)
  std::string camera;                  ///< a mono camera of that vehicle whose images are observed
  ImageKind image = ImageKind::kNone;  ///< with `camera`: what is observed
  double max_depth_m = 20.0;           ///< depth observations are clipped to this (sky too)

  template <class V>
  void Visit(V& v) {
    v.Field("num_envs", num_envs, "environments stepped together");
    v.Field("threads", threads, "threads that step them (results do not depend on it)");
    v.Field("control_rate_hz", control_rate_hz, "steps per simulated second");
    v.Field("max_episode_steps", max_episode_steps, "steps before an episode is truncated");
    v.Field("autoreset", autoreset, "when a finished environment restarts");
    v.Field("vehicle", vehicle, "the learning vehicle (default the scene's first)");
    v.Field("camera", camera, "camera of the vehicle whose images are observed");
    v.Field("image", image, "image observed from the camera");
    v.Field("max_depth_m", max_depth_m, "depth observations are clipped to this (m)");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
};

/// Where a VectorEnv writes one call's results. Each span holds num_envs entries of its kind
/// (observations: num_envs x observation_size(), images: num_envs x image_size()); spans a call
/// does not fill may be empty (final_* outside kSameStep, images without a camera).
struct EnvOutputs {
  std::span<float> observations;
  std::span<std::uint8_t> images;  ///< raw bytes: float32 depth or uint8 RGB, per image_kind()
  std::span<double> rewards;
  std::span<std::uint8_t> terminated;
  std::span<std::uint8_t> truncated;
  std::span<std::uint8_t> success;    ///< the task succeeded in this step
  std::span<std::uint8_t> collided;   ///< the vehicle touched something new in this step
  std::span<std::uint8_t> diverged;   ///< the simulation failed (SimulationError): terminated
  std::span<std::uint8_t> has_final;  ///< kSameStep: this environment ended and was reset
  std::span<float> final_observations;
  std::span<std::uint8_t> final_images;
};

/// N independent copies of one task, stepped together (docs/python.md, "Vectorized
/// environments"). Each environment has a World of its own (its vehicle, clock, contacts, random
/// streams), built from one loaded scene; they share the immutable parts (static scene, ray
/// caster, GPU scene), so vehicles of different environments never meet. The episode worlds hold
/// the learning vehicle alone and without sensors: observations are its ground truth. A reset
/// builds the environment's World again from the scene with a seed drawn from the environment's own
/// random stream, so an episode depends only on that stream: the same reset seed gives the same
/// episode, whatever happened before, on any thread count. Physics runs on `threads` threads;
/// images are rendered afterwards on the calling thread (one GL context).
class VectorEnv {
 public:
  /// Loads the scene (ConfigError), checks the options (ConfigError naming the option) and builds
  /// every environment (not yet reset).
  VectorEnv(const tools::SceneSource& scene, const VectorEnvConfig& config, const TaskConfig& task,
            const ActionConfig& action);
  ~VectorEnv();
  VectorEnv(const VectorEnv&) = delete;
  VectorEnv& operator=(const VectorEnv&) = delete;

  int num_envs() const { return config_.num_envs; }
  int observation_size() const { return Task::ObservationSize(task_.kind); }
  int action_size() const { return action_.size(actuator_count_); }
  /// Image shape (height, width, channels: 1 depth, 3 RGB) and bytes per image; 0 without one.
  int image_height() const;
  int image_width() const;
  int image_channels() const { return config_.image == ImageKind::kRgb ? 3 : 1; }
  std::size_t image_size() const;
  ImageKind image_kind() const { return camera_ ? config_.image : ImageKind::kNone; }
  int ticks_per_step() const { return ticks_per_step_; }
  const VectorEnvConfig& config() const { return config_; }
  const TaskConfig& task() const { return task_; }
  const ActionConfig& action() const { return action_; }
  void ActionBounds(std::vector<float>& low, std::vector<float>& high) const {
    action_.Bounds(actuator_count_, low, high);
  }

  /// Starts a new episode in every environment: seeds[i], when set, restarts environment i's
  /// random stream (else it goes on). Fills observations and images. Requires seeds.size() ==
  /// num_envs().
  void Reset(std::span<const std::optional<std::uint64_t>> seeds, const EnvOutputs& out);
  /// One step of every environment: actions (num_envs x action_size(), clamped to the bounds) are
  /// held for ticks_per_step() physics ticks. Throws std::invalid_argument on a non-finite action
  /// (naming the environment), std::logic_error when an environment was never reset or, with
  /// autoreset disabled, has finished.
  void Step(std::span<const float> actions, const EnvOutputs& out);

  /// Environment i's simulation and vehicle index (tests, rendering a flight).
  const engine::Simulation& simulation(int i) const;
  std::size_t vehicle_index() const { return vehicle_; }
  /// Environment i's current goal point and steps taken in its episode.
  const Vec3& goal_W(int i) const;
  int episode_steps(int i) const;

 private:
  struct Slot;
  void ResetSlot(Slot& slot, std::optional<std::uint64_t> seed);
  void StepSlot(Slot& slot, std::span<const float> action, std::size_t i, const EnvOutputs& out);
  void Observe(const Slot& slot, std::size_t i, std::span<float> observations) const;
  void RenderImage(Slot& slot, std::span<std::uint8_t> image);

  tools::SceneSource source_;
  scenes::Scene scene_;
  VectorEnvConfig config_;
  TaskConfig task_;
  ActionConfig action_;
  scenes::WorldResources resources_;
  std::size_t vehicle_ = 0;
  int actuator_count_ = 0;
  int ticks_per_step_ = 1;
  std::optional<engine::ImageStream> camera_;
  std::unique_ptr<engine::CameraRenderer> renderer_;
  std::vector<std::unique_ptr<Slot>> slots_;
  engine::WorkerPool pool_;
};

}  // namespace airis::python
