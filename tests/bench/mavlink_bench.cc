// ns per message of the MAVLink codec on the PX4 lockstep path: HIL_SENSOR goes out at 250 Hz and
// more per vehicle, HIL_ACTUATOR_CONTROLS comes back once per sensor step. Encode is a whole v2
// frame into a buffer (payload, truncation, header, CRC); decode is FrameParser::Next on a frame's
// bytes (start byte, header, CRC, zero-fill) plus Decode into the struct.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mavlink/crc.h"
#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/messages.h"

namespace airis::engine::mavlink {
namespace {

// Inputs cycle through a small table so the compiler cannot hoist the work out of the loop.
constexpr int kInputs = 64;

std::array<HilSensor, kInputs> Sensors() {
  std::array<HilSensor, kInputs> out{};
  for (int i = 0; i < kInputs; ++i) {
    HilSensor& m = out[i];
    m.time_usec = 4000u * (i + 1);
    m.xacc = 0.01f * i;
    m.yacc = -0.02f * i;
    m.zacc = -9.81f + 0.001f * i;
    m.xgyro = 0.001f * i;
    m.ygyro = -0.002f * i;
    m.zgyro = 0.003f * i;
    m.xmag = 0.21f;
    m.ymag = 0.05f;
    m.zmag = 0.43f;
    m.abs_pressure = 1013.25f - 0.01f * i;
    m.pressure_alt = 0.1f * i;
    m.temperature = 15.0f;
    m.fields_updated = 0x1FFF;
    m.id = 0;  // the id byte is truncated, as PX4 gets it
  }
  return out;
}

std::array<HilActuatorControls, kInputs> Controls() {
  std::array<HilActuatorControls, kInputs> out{};
  for (int i = 0; i < kInputs; ++i) {
    HilActuatorControls& m = out[i];
    m.time_usec = 4000u * (i + 1);
    m.flags = 1;  // lockstep
    for (int k = 0; k < 4; ++k) m.controls[k] = 0.58f + 0.001f * (i + k);
    m.mode = 129;  // armed, custom mode
  }
  return out;
}

template <class M>
void BM_Encode(benchmark::State& state, const std::array<M, kInputs>& messages) {
  FrameEncoder encoder(1, 200);
  FrameBuffer buffer;
  benchmark::DoNotOptimize(encoder.Encode(messages[0], buffer));
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(encoder.Encode(messages[i], buffer));
    benchmark::ClobberMemory();
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class M>
void BM_Decode(benchmark::State& state, const std::array<M, kInputs>& messages) {
  FrameEncoder encoder(1, 1);
  std::vector<FrameBuffer> frames(kInputs);
  std::vector<std::size_t> lengths(kInputs);
  for (int i = 0; i < kInputs; ++i) lengths[i] = encoder.Encode(messages[i], frames[i]);
  FrameParser parser;
  M out;
  int i = 0;
  for (auto _ : state) {
    std::span<const std::uint8_t> input(frames[i].data(), lengths[i]);
    const Frame* frame = parser.Next(input);
    benchmark::DoNotOptimize(frame != nullptr && Decode(*frame, &out));
    benchmark::DoNotOptimize(out);
    i = (i + 1) % kInputs;
  }
  if (parser.stats().frames_ok != static_cast<std::uint64_t>(state.iterations())) {
    state.SkipWithError("a frame did not parse");
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_EncodeHilSensor(benchmark::State& state) { BM_Encode(state, Sensors()); }
BENCHMARK(BM_EncodeHilSensor);

void BM_EncodeHilActuatorControls(benchmark::State& state) { BM_Encode(state, Controls()); }
BENCHMARK(BM_EncodeHilActuatorControls);

void BM_DecodeHilSensor(benchmark::State& state) { BM_Decode(state, Sensors()); }
BENCHMARK(BM_DecodeHilSensor);

void BM_DecodeHilActuatorControls(benchmark::State& state) { BM_Decode(state, Controls()); }
BENCHMARK(BM_DecodeHilActuatorControls);

// The CRC alone over a HIL_ACTUATOR_CONTROLS frame's 90 checked bytes: most of either direction's
// cost.
void BM_Crc90Bytes(benchmark::State& state) {
  std::array<std::uint8_t, 90> bytes{};
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i * 37);
  for (auto _ : state) {
    benchmark::DoNotOptimize(bytes);
    benchmark::DoNotOptimize(CrcAccumulate(bytes));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
}
BENCHMARK(BM_Crc90Bytes);

}  // namespace
}  // namespace airis::engine::mavlink
