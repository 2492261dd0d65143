#include "engine/mavlink/px4/px4_autopilot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include "engine/core/error.h"
#include "engine/mavlink/enums.h"
#include "engine/mavlink/messages.h"
#include "engine/mavlink/px4/link_spec.h"

namespace airis::engine::mavlink {
namespace {

using Clock = std::chrono::steady_clock;

int Milliseconds(double seconds) { return static_cast<int>(std::ceil(seconds * 1000.0)); }

// Simulated time in messages, to the millisecond: "0.144".
std::string SimTime(TimeNs t_ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", ToSeconds(t_ns));
  return text;
}

}  // namespace

Px4Autopilot::Px4Autopilot(Options options, std::span<const std::unique_ptr<Sensor>> sensors)
    : options_(std::move(options)),
      feed_(sensors, options_.utc_start_us, options_.config.satellites_visible),
      encoder_(static_cast<std::uint8_t>(options_.config.instance + 1), 200),
      sensor_schedule_(options_.config.sensor_rate_hz,
                       SecondsToNs(1.0 / options_.config.sensor_rate_hz, "sensor_rate_hz")) {
  const AutopilotConfig& c = options_.config;
  c.Validate();
  AIRIS_DEMAND(options_.frame != nullptr);
  AIRIS_DEMAND(options_.actuator_count >= 0 && options_.actuator_count <= 16);
  if (!c.motor_map.empty() && static_cast<int>(c.motor_map.size()) != options_.actuator_count) {
    throw InvalidField("motor_map", "has " + std::to_string(c.motor_map.size()) +
                                        " channels but vehicle '" + options_.vehicle + "' has " +
                                        std::to_string(options_.actuator_count) + " actuators");
  }
  for (int i = 0; i < options_.actuator_count; ++i) {
    channel_of_[static_cast<std::size_t>(i)] =
        c.motor_map.empty() ? i : c.motor_map[static_cast<std::size_t>(i)] - 1;
  }
  if (c.lockstep()) {
    const int port = options_.tcp_port >= 0 ? options_.tcp_port : c.tcp_port();
    auto tcp = std::make_unique<TcpServerLink>(c.host, port);
    tcp_ = tcp.get();
    link_ = std::move(tcp);
  } else {
    link_ = OpenHilLink(ParseLinkSpec(c.link, "link"));
  }
}

void Px4Autopilot::Log(const std::string& line) const {
  if (options_.log) options_.log(line);
}

template <class M>
void Px4Autopilot::Queue(const M& message) {
  AIRIS_DEMAND(out_used_ + kMaxEncodedLength<M> <= out_.size());
  out_used_ += encoder_.Encode(
      message, std::span<std::uint8_t>(out_.data() + out_used_, out_.size() - out_used_));
}

void Px4Autopilot::Flush() {
  if (out_used_ == 0) return;
  const bool sent = link_->Send(std::span<const std::uint8_t>(out_.data(), out_used_));
  out_used_ = 0;
  if (!sent) {
    throw LinkError("PX4 link of vehicle '" + options_.vehicle + "' (" + link_->Describe() +
                    ") closed at t = " + SimTime(now_ns_) + " s");
  }
}

void Px4Autopilot::Connect() {
  if (link_->connected()) return;
  const AutopilotConfig& c = options_.config;
  Log("vehicle '" + options_.vehicle + "': waiting for PX4 instance " + std::to_string(c.instance) +
      " on " + link_->Describe());
  if (!tcp_ || !tcp_->Accept(Milliseconds(c.connect_timeout_s))) {
    throw LinkError("PX4 (instance " + std::to_string(c.instance) + ") did not connect to " +
                    link_->Describe() + " within " + FormatNumber(c.connect_timeout_s) +
                    " s of wall time: start PX4 SITL with 'px4 -i " + std::to_string(c.instance) +
                    "' and an airframe that uses the TCP simulator (docs/px4.md)");
  }
  Log("vehicle '" + options_.vehicle + "': PX4 connected on " + link_->Describe());
  wall_anchor_.reset();
}

void Px4Autopilot::Publish(const ControlContext& context) {
  now_ns_ = context.now_ns;
  exchange_ = false;
  if (sensor_schedule_.ConsumeDue(context.now_ns) == 0) return;
  const TimeNs tick_ns = SecondsToNs(context.dt_s, "dt_s");
  const TimeNs period_ns = sensor_schedule_.DueTime(1) - sensor_schedule_.DueTime(0);
  if (options_.config.lockstep() && period_ns % tick_ns != 0) {
    throw InvalidField("sensor_rate_hz", "must make a whole number of physics ticks (" +
                                             FormatNumber(options_.config.sensor_rate_hz) +
                                             " Hz against " + FormatNumber(1.0 / context.dt_s) +
                                             " Hz physics)");
  }
  Connect();
  const std::uint64_t time_usec = static_cast<std::uint64_t>(context.now_ns / 1000);
  // One write per exchange, HIL_SENSOR last: PX4 steps its clock on it, with the GPS, range and
  // truth of the same instant already read.
  HilGps gps;
  if (feed_.TakeHilGps(&gps)) {
    Queue(gps);
    ++stats_.gps_messages;
  }
  DistanceSensor distance;
  if (feed_.TakeDistanceSensor(static_cast<std::uint32_t>(context.now_ns / 1'000'000), &distance)) {
    Queue(distance);
  }
  if (state_interval_ns_ > 0 && context.now_ns >= next_state_ns_) {
    const Vec3 gravity_W(0.0, 0.0, context.gravity_m_s2);
    Queue(HilSensorFeed::MakeState(time_usec, *context.state, *context.accelerations,
                                   *options_.frame, gravity_W,
                                   context.environment->wind().CalcVelocity_W(context.state->p_W)));
    // On average at the rate asked for (HIL_SENSOR times are its only chances); no burst after
    // a pause.
    next_state_ns_ = std::max(next_state_ns_ + state_interval_ns_, context.now_ns);
  }
  HilSensor sensor;
  if (feed_.TakeHilSensor(time_usec, &sensor)) {
    Queue(sensor);
    ++stats_.sensor_messages;
  }
  Flush();
  exchange_ = true;
  answered_ = false;
  exchange_time_usec_ = time_usec;
  if (mission_) mission_->Update(context.now_ns);
}

bool Px4Autopilot::ReadFrames(int timeout_ms) {
  std::array<std::uint8_t, 4096> buffer;
  for (int wait = timeout_ms;; wait = 0) {
    const std::ptrdiff_t n = link_->Receive(buffer, wait);
    if (n < 0) return false;
    if (n == 0) return true;
    std::span<const std::uint8_t> bytes(buffer.data(), static_cast<std::size_t>(n));
    while (const Frame* frame = parser_.Next(bytes)) HandleFrame(*frame);
    if (answered_) return true;
  }
}

void Px4Autopilot::HandleFrame(const Frame& frame) {
  HilActuatorControls controls;
  CommandLong command;
  if (Decode(frame, &controls)) {
    controls_ = controls.controls;
    controls_time_usec_ = controls.time_usec;
    stats_.armed = (controls.mode & kMavModeFlagSafetyArmed) != 0;
    ++stats_.actuator_messages;
    if (!lockstep_ && options_.config.lockstep()) {
      lockstep_ = true;
      stats_.lockstep_since_ns = now_ns_;
      Log("vehicle '" + options_.vehicle + "': PX4 in lockstep from t = " + SimTime(now_ns_) +
          " s");
    }
    if (exchange_ && controls.time_usec == exchange_time_usec_) answered_ = true;
  } else if (Decode(frame, &command)) {
    // PX4 asks for HIL_STATE_QUATERNION (115) with MAV_CMD_SET_MESSAGE_INTERVAL on connecting.
    if (command.command == kMavCmdSetMessageInterval &&
        static_cast<std::uint32_t>(command.param1) == HilStateQuaternion::kInfo.id) {
      state_interval_ns_ = command.param2 > 0
                               ? static_cast<TimeNs>(static_cast<double>(command.param2) * 1000.0)
                               : 0;
    }
  }
}

void Px4Autopilot::PaceToRealTime(TimeNs now_ns) {
  const Clock::time_point wall = Clock::now();
  if (!wall_anchor_ || now_ns < sim_anchor_ns_) {
    wall_anchor_ = wall;
    sim_anchor_ns_ = now_ns;
    return;
  }
  const Clock::time_point due = *wall_anchor_ + std::chrono::nanoseconds(now_ns - sim_anchor_ns_);
  if (due > wall) {
    std::this_thread::sleep_until(due);
  } else if (wall - due > std::chrono::seconds(1)) {  // far behind: do not race to catch up
    wall_anchor_ = wall;
    sim_anchor_ns_ = now_ns;
  }
}

void Px4Autopilot::Collect(Vehicle& vehicle) {
  if (!exchange_) return;
  const auto closed = [&] {
    return LinkError("PX4 closed its link (" + link_->Describe() + ") of vehicle '" +
                     options_.vehicle + "' at t = " + SimTime(now_ns_) + " s");
  };
  if (lockstep_) {
    const Clock::time_point deadline =
        Clock::now() +
        std::chrono::microseconds(static_cast<std::int64_t>(options_.config.timeout_s * 1e6));
    while (!answered_) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      if (!ReadFrames(static_cast<int>(left.count()))) throw closed();
    }
    if (answered_) {
      ++stats_.lockstep_steps;
    } else {
      ++stats_.timeouts;
      const std::string what = "PX4 did not answer HIL_SENSOR at t = " + SimTime(now_ns_) +
                               " s within " + FormatNumber(options_.config.timeout_s) +
                               " s of wall time";
      if (options_.config.on_timeout == OnTimeout::kStop) {
        throw LinkError("vehicle '" + options_.vehicle + "': " + what +
                        " (autopilot.on_timeout: stop; PX4 answers 1:1 only up to 250 Hz)");
      }
      Log("vehicle '" + options_.vehicle + "': " + what + "; going on with its last outputs");
    }
  } else {
    if (!ReadFrames(0)) throw closed();
    if (!lockstep_) PaceToRealTime(now_ns_);  // before lockstep (SITL start-up) and HIL
  }
  ApplyOutputs(vehicle);
}

void Px4Autopilot::ApplyOutputs(Vehicle& vehicle) {
  VehicleCommand command;
  command.mode = CommandMode::kMotors;
  for (int i = 0; i < options_.actuator_count; ++i) {
    double u = stats_.armed ? controls_[static_cast<std::size_t>(channel_of_[i])] : 0.0;
    if (i >= options_.motor_count) u = stats_.armed ? 0.5 * (u + 1.0) : 0.5;  // servo [-1, 1]
    command.motors[static_cast<std::size_t>(i)] = std::clamp(u, 0.0, 1.0);
  }
  vehicle.SetCommand(command);
}

void Px4Autopilot::SetMissionCommand(const VehicleCommand& command) {
  if (!mission_) {
    const AutopilotConfig& c = options_.config;
    Px4MissionLink::Options o;
    o.instance = c.instance;
    o.local_port = c.mission_local_port();
    o.remote_port = c.mission_remote_port();
    o.frame = options_.frame;
    o.arm_timeout_s = c.arm_timeout_s;
    mission_ = std::make_unique<Px4MissionLink>(o);
  }
  mission_->SetCommand(command);
}

bool Px4Autopilot::Estimate(RigidBodyState* state, bool* landed) const {
  return mission_ && mission_->Estimate(state, landed);
}

std::string Px4Autopilot::failure() const { return mission_ ? mission_->failure() : ""; }

}  // namespace airis::engine::mavlink
