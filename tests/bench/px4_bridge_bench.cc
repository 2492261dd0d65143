// The PX4 bridge's whole cost per lockstep exchange: one HIL_SENSOR out, one HIL_ACTUATOR_CONTROLS
// back from a peer that answers at once over loopback TCP (tests/mavlink/px4/scripted_px4.h), with
// the four 1 kHz physics ticks between exchanges at 250 Hz. Target (issue: PX4 in the loop): at
// least 50x real time for one vehicle, so that PX4 itself, not airis, limits a SITL run.
// BM_FourTicksWithoutBridge is the same vehicle and sensors flown by nobody: the difference is the
// bridge.
#include <benchmark/benchmark.h>

#include <memory>

#include "engine/mavlink/px4/hil_sensor_feed.h"
#include "engine/mavlink/px4/px4_autopilot.h"
#include "tests/mavlink/px4/scripted_px4.h"
#include "tools/jobs/simulation_job.h"

namespace airis::engine::mavlink {
namespace {

constexpr const char* kScene = R"(
scene: {name: bridge_bench}
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -0.2]}
    sensors:
      - imu: {rate_hz: 1000}
      - barometer: {rate_hz: 50}
      - magnetometer: {rate_hz: 125}
      - gps: {rate_hz: 10}
)";

constexpr double kExchangeS = 0.004;  // 250 Hz

void BM_Px4LockstepExchange(benchmark::State& state) {
  tools::SimulationJob job({"bench.yaml", kScene, std::nullopt});
  Px4Autopilot::Options o;
  o.config.kind = AutopilotKind::kPx4;
  o.vehicle = "drone1";
  o.frame = &job.world().environment().frame();
  o.actuator_count = 4;
  o.motor_count = 4;
  o.tcp_port = 0;
  auto bridge = std::make_unique<Px4Autopilot>(o, job.world().sensors(0));
  Px4Autopilot* px4 = bridge.get();
  testing::ScriptedPx4Script script;
  script.port = bridge->tcp_port();
  script.first_reply_after = 0;
  script.armed = false;
  script.stop_after_sensors = 1 << 30;
  job.simulation().SetAutopilot(0, std::move(bridge));
  {
    testing::ScriptedPx4 peer(script);
    job.simulation().RunFor(0.1);  // connected and in lockstep
    for (auto _ : state) job.simulation().RunFor(kExchangeS);
    state.counters["x_realtime"] = benchmark::Counter(
        kExchangeS * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["timeouts"] = static_cast<double>(px4->stats().timeouts);
    job.simulation().SetAutopilot(0, nullptr);  // closes the link: the peer ends
  }
}
BENCHMARK(BM_Px4LockstepExchange)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_FourTicksWithoutBridge(benchmark::State& state) {
  tools::SimulationJob job({"bench.yaml", kScene, std::nullopt});
  for (auto _ : state) job.simulation().RunFor(kExchangeS);
  state.counters["x_realtime"] = benchmark::Counter(
      kExchangeS * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FourTicksWithoutBridge)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace airis::engine::mavlink
