#include "engine/mavlink/px4/px4_mission_link.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/core/frames.h"
#include "engine/mavlink/enums.h"
#include "engine/mavlink/link/socket_util.h"
#include "engine/mavlink/messages.h"

namespace airis::engine::mavlink {
namespace {

// PX4's custom_mode: main mode in bits 16-23, sub mode in bits 24-31 (px4_custom_mode.h).
constexpr std::uint32_t kMainModeAuto = 4;
constexpr std::uint32_t kMainModeOffboard = 6;
constexpr std::uint32_t kAutoSubModeLand = 6;
std::uint32_t MainMode(std::uint32_t custom_mode) { return (custom_mode >> 16) & 0xFF; }
std::uint32_t SubMode(std::uint32_t custom_mode) { return (custom_mode >> 24) & 0xFF; }

constexpr TimeNs kSetpointPeriodNs = 50'000'000;  // 20 Hz
constexpr TimeNs kSecondNs = 1'000'000'000;
constexpr double kDefaultSpeed_m_s = 3.0;  // when a command gives no speed limit

// Messages the mission needs from PX4, at these intervals (us).
constexpr std::array<std::pair<std::uint32_t, float>, 4> kStreams = {
    {{GlobalPositionInt::kInfo.id, 20'000.0f},
     {Attitude::kInfo.id, 20'000.0f},
     {ExtendedSysState::kInfo.id, 100'000.0f},
     {HomePosition::kInfo.id, 500'000.0f}}};

double DegE7ToRad(std::int32_t v) { return DegToRad(static_cast<double>(v) * 1e-7); }

}  // namespace

Px4MissionLink::Px4MissionLink(const Options& options)
    : options_(options),
      link_("127.0.0.1", options.local_port, ResolveIpv4("127.0.0.1", options.remote_port)),
      // A companion computer's ids: the system's own id, component MAV_COMP_ID_ONBOARD_COMPUTER.
      encoder_(static_cast<std::uint8_t>(options.instance + 1), 191) {
  AIRIS_DEMAND(options.frame != nullptr);
}

template <class M>
void Px4MissionLink::Send(const M& message) {
  FrameBuffer buffer;
  const std::size_t n = encoder_.Encode(message, buffer);
  link_.Send(std::span<const std::uint8_t>(buffer.data(), n));
}

void Px4MissionLink::SendCommand(std::uint16_t command, float p1, float p2, float p3) {
  CommandLong c;
  c.command = command;
  c.param1 = p1;
  c.param2 = p2;
  c.param3 = p3;
  c.target_system = static_cast<std::uint8_t>(options_.instance + 1);
  c.target_component = 1;
  Send(c);
}

void Px4MissionLink::Handle(const Frame& frame, TimeNs now_ns) {
  if (frame.sysid != options_.instance + 1 || frame.compid != 1) return;  // PX4's autopilot only
  Heartbeat hb;
  GlobalPositionInt gp;
  Attitude at;
  ExtendedSysState ex;
  HomePosition home;
  StatusText st;
  if (Decode(frame, &hb)) {
    heard_ = true;
    armed_ = (hb.base_mode & kMavModeFlagSafetyArmed) != 0;
    was_armed_ = was_armed_ || armed_;
    custom_mode_ = hb.custom_mode;
  } else if (Decode(frame, &gp)) {
    const GeodeticPosition g{DegE7ToRad(gp.lat), DegE7ToRad(gp.lon), gp.alt * 1e-3};
    estimate_.p_W = options_.frame->ToNed(g);
    estimate_.v_W = Vec3(gp.vx, gp.vy, gp.vz) * 0.01;
    have_global_ = true;
  } else if (Decode(frame, &at)) {
    estimate_.q_WB = QuatFromEuler({at.roll, at.pitch, at.yaw});
    estimate_.w_B = Vec3(at.rollspeed, at.pitchspeed, at.yawspeed);
    have_attitude_ = true;
  } else if (Decode(frame, &ex)) {
    landed_state_ = ex.landed_state;
  } else if (Decode(frame, &home)) {
    const GeodeticPosition g{DegE7ToRad(home.latitude), DegE7ToRad(home.longitude),
                             home.altitude * 1e-3};
    local_origin_W_ = options_.frame->ToNed(g) - Vec3(home.x, home.y, home.z);
    have_home_ = true;
  } else if (Decode(frame, &st)) {
    const auto end = std::find(st.text.begin(), st.text.end(), '\0');
    last_status_text_.assign(st.text.begin(), end);
  }
  (void)now_ns;
}

void Px4MissionLink::Update(TimeNs now_ns) {
  std::array<std::uint8_t, 2048> buffer;
  for (;;) {
    const std::ptrdiff_t n = link_.Receive(buffer, 0);
    if (n <= 0) break;
    std::span<const std::uint8_t> bytes(buffer.data(), static_cast<std::size_t>(n));
    while (const Frame* frame = parser_.Next(bytes)) Handle(*frame, now_ns);
  }
  const double dt_s = ToSeconds(now_ns - last_update_ns_);
  last_update_ns_ = now_ns;
  if (now_ns >= next_heartbeat_ns_) {
    Heartbeat hb;
    hb.type = kMavTypeOnboardController;
    hb.autopilot = kMavAutopilotInvalid;
    hb.system_status = kMavStateActive;
    Send(hb);
    next_heartbeat_ns_ = now_ns + kSecondNs;
  }
  if (heard_ && now_ns >= next_request_ns_ && !(have_global_ && have_attitude_ && have_home_)) {
    for (const auto& [id, interval_us] : kStreams) {
      SendCommand(kMavCmdSetMessageInterval, static_cast<float>(id), interval_us);
    }
    next_request_ns_ = now_ns + kSecondNs;
  }
  if (!failure_.empty() || !heard_ || !have_home_ || !have_global_) return;

  const CommandMode mode = command_.mode;
  const bool flying_mode = mode == CommandMode::kPosition || mode == CommandMode::kVelocity;
  if (flying_mode) {
    // The reference moves toward the command's target at its speed limit.
    if (!reference_started_) {
      reference_W_ = estimate_.p_W;
      reference_started_ = true;
    }
    if (mode == CommandMode::kPosition) {
      const double speed =
          command_.speed_limit_m_s > 0 ? command_.speed_limit_m_s : kDefaultSpeed_m_s;
      const Vec3 to_go = command_.position_W - reference_W_;
      const double step = speed * std::max(dt_s, 0.0);
      if (to_go.norm() <= step) {
        reference_W_ = command_.position_W;
        reference_v_W_ = command_.velocity_W;
      } else {
        reference_W_ += to_go.normalized() * step;
        reference_v_W_ = to_go.normalized() * speed;
      }
    } else {
      reference_W_ = estimate_.p_W;
      reference_v_W_ = command_.velocity_W;
    }
    if (now_ns >= next_setpoint_ns_) {
      SendSetpoint(now_ns);
      next_setpoint_ns_ = now_ns + kSetpointPeriodNs;
    }
    if (MainMode(custom_mode_) != kMainModeOffboard && now_ns >= next_mode_request_ns_) {
      SendCommand(kMavCmdDoSetMode, kMavModeFlagCustomModeEnabled,
                  static_cast<float>(kMainModeOffboard));
      next_mode_request_ns_ = now_ns + kSecondNs / 2;
    }
    if (!armed_ && !was_armed_) {
      if (arm_asked_ns_ < 0) arm_asked_ns_ = now_ns;
      if (MainMode(custom_mode_) == kMainModeOffboard && now_ns >= next_arm_request_ns_) {
        SendCommand(kMavCmdComponentArmDisarm, 1.0f);
        next_arm_request_ns_ = now_ns + kSecondNs;
      }
      if (ToSeconds(now_ns - arm_asked_ns_) > options_.arm_timeout_s) {
        failure_ = "PX4 did not arm within " + FormatNumber(options_.arm_timeout_s) +
                   " s of simulated time" +
                   (last_status_text_.empty() ? std::string(" (it sent no message)")
                                              : "; it said: '" + last_status_text_ + "'");
      }
    }
  } else if (mode == CommandMode::kLand) {
    const bool landing =
        MainMode(custom_mode_) == kMainModeAuto && SubMode(custom_mode_) == kAutoSubModeLand;
    if (armed_ && !landing && now_ns >= next_mode_request_ns_) {
      SendCommand(kMavCmdDoSetMode, kMavModeFlagCustomModeEnabled,
                  static_cast<float>(kMainModeAuto), static_cast<float>(kAutoSubModeLand));
      next_mode_request_ns_ = now_ns + kSecondNs / 2;
    }
  } else if (mode == CommandMode::kDisarmed) {
    if (armed_ && now_ns >= next_mode_request_ns_) {
      SendCommand(kMavCmdComponentArmDisarm, 0.0f);
      next_mode_request_ns_ = now_ns + kSecondNs;
    }
  } else {
    failure_ = std::string("the mission commands mode '") + std::string(ToString(mode)) +
               "', which airis does not fly through PX4 (position, velocity and land only)";
  }
}

void Px4MissionLink::SendSetpoint(TimeNs now_ns) {
  SetPositionTargetLocalNed sp;
  sp.time_boot_ms = static_cast<std::uint32_t>(now_ns / 1'000'000);
  sp.target_system = static_cast<std::uint8_t>(options_.instance + 1);
  sp.target_component = 1;
  sp.coordinate_frame = kMavFrameLocalNed;
  const Vec3 p_L = reference_W_ - local_origin_W_;
  sp.x = static_cast<float>(p_L.x());
  sp.y = static_cast<float>(p_L.y());
  sp.z = static_cast<float>(p_L.z());
  const bool velocity_only = command_.mode == CommandMode::kVelocity;
  const Vec3& v = reference_v_W_;
  sp.vx = static_cast<float>(v.x());
  sp.vy = static_cast<float>(v.y());
  sp.vz = static_cast<float>(v.z());
  sp.yaw = static_cast<float>(command_.yaw_rad);
  std::uint16_t mask = kPositionTargetTypemaskAxIgnore | kPositionTargetTypemaskAyIgnore |
                       kPositionTargetTypemaskAzIgnore | kPositionTargetTypemaskYawRateIgnore;
  if (velocity_only) {
    mask |= kPositionTargetTypemaskXIgnore | kPositionTargetTypemaskYIgnore |
            kPositionTargetTypemaskZIgnore;
  }
  sp.type_mask = mask;
  Send(sp);
}

bool Px4MissionLink::Estimate(RigidBodyState* state, bool* landed) const {
  if (!(heard_ && have_global_ && have_attitude_ && have_home_)) return false;
  *state = estimate_;
  *landed = was_armed_ && !armed_ && landed_state_ == kMavLandedStateOnGround;
  return true;
}

}  // namespace airis::engine::mavlink
