// ns per call of the environment models: the atmosphere (called every physics tick), the magnetic
// models (called at magnetometer rates, and by the paper claimed too costly for a 1 kHz loop in the
// WMM's case), the geodetic conversions, gravity and the wind's per-tick advance.
#include <benchmark/benchmark.h>

#include <array>

#include "engine/core/geodetic.h"
#include "engine/environment/atmosphere.h"
#include "engine/environment/environment.h"
#include "engine/environment/gravity.h"
#include "engine/environment/tilted_dipole.h"
#include "engine/environment/wind.h"
#include "engine/environment/world_magnetic_model.h"

namespace airis::engine {
namespace {

// Inputs cycle through a small table so the compiler cannot hoist the call out of the loop.
constexpr int kInputs = 64;

std::array<double, kInputs> Altitudes(double lo_m, double hi_m) {
  std::array<double, kInputs> out;
  for (int i = 0; i < kInputs; ++i) out[i] = lo_m + (hi_m - lo_m) * i / (kInputs - 1);
  return out;
}

std::array<GeodeticPosition, kInputs> Positions() {
  std::array<GeodeticPosition, kInputs> out;
  for (int i = 0; i < kInputs; ++i) {
    out[i] = {DegToRad(-80.0 + 160.0 * i / (kInputs - 1)), DegToRad(-179.0 + 5.3 * i), 100.0 * i};
  }
  return out;
}

void BM_AtmosphereBelow86km(benchmark::State& state) {
  const auto altitudes = Altitudes(-500.0, 12000.0);
  benchmark::DoNotOptimize(ussa1976::Calc(altitudes[0]));
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ussa1976::Calc(altitudes[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AtmosphereBelow86km);

void BM_AtmosphereAllLowerLayers(benchmark::State& state) {
  const auto altitudes = Altitudes(-5000.0, 86000.0);
  benchmark::DoNotOptimize(ussa1976::Calc(altitudes[0]));
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ussa1976::Calc(altitudes[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AtmosphereAllLowerLayers);

void BM_AtmosphereAbove86km(benchmark::State& state) {
  const auto altitudes = Altitudes(86500.0, 1000000.0);
  benchmark::DoNotOptimize(ussa1976::Calc(altitudes[0]));  // builds the upper table once
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ussa1976::Calc(altitudes[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AtmosphereAbove86km);

void BM_AltitudeFromPressure(benchmark::State& state) {
  std::array<double, kInputs> pressures;
  for (int k = 0; k < kInputs; ++k) pressures[k] = 101325.0 - 1000.0 * k;
  benchmark::DoNotOptimize(ussa1976::CalcAltitudeFromPressure(pressures[0]));
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ussa1976::CalcAltitudeFromPressure(pressures[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AltitudeFromPressure);

void BM_GravityInverseSquare(benchmark::State& state) {
  const Gravity gravity;
  const auto altitudes = Altitudes(0.0, 10000.0);
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gravity.CalcAcceleration_m_s2(altitudes[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GravityInverseSquare);

void BM_TiltedDipole(benchmark::State& state) {
  const TiltedDipoleField dipole;
  const auto positions = Positions();
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(dipole.CalcField_nT(positions[i], 2026.0));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TiltedDipole);

void BM_Wmm2025(benchmark::State& state) {
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  const auto positions = Positions();
  benchmark::DoNotOptimize(wmm.CalcField_nT(positions[0], 2026.0));
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(wmm.CalcField_nT(positions[i], 2026.0));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Wmm2025);

void BM_GeodeticToEcef(benchmark::State& state) {
  const auto positions = Positions();
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(GeodeticToEcef(positions[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GeodeticToEcef);

void BM_EcefToGeodetic(benchmark::State& state) {
  const auto positions = Positions();
  std::array<Vec3, kInputs> points;
  for (int k = 0; k < kInputs; ++k) points[k] = GeodeticToEcef(positions[k]);
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(EcefToGeodetic(points[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EcefToGeodetic);

void BM_LocalNedToGeodetic(benchmark::State& state) {
  const LocalNedFrame frame({DegToRad(47.641468), DegToRad(-122.140165), 122.0});
  std::array<Vec3, kInputs> points;
  for (int k = 0; k < kInputs; ++k) points[k] = Vec3(37.0 * k, -21.0 * k, -3.0 * k);
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(frame.ToGeodetic(points[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LocalNedToGeodetic);

void BM_EnvironmentMagneticFieldWmm(benchmark::State& state) {
  // What a magnetometer pays per sample: world point -> geodetic -> WMM.
  const Environment env({}, {DegToRad(47.641468), DegToRad(-122.140165), 122.0}, RandomStream(1));
  std::array<Vec3, kInputs> points;
  for (int k = 0; k < kInputs; ++k) points[k] = Vec3(37.0 * k, -21.0 * k, -3.0 * k);
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(env.CalcMagneticField_nT(points[i]));
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EnvironmentMagneticFieldWmm);

void WindTick(benchmark::State& state, GustModel gust) {
  WindConfig config;
  config.mean_ned_m_s = Vec3(3.0, 4.0, 0.0);
  config.gust = gust;
  Wind wind(config, RandomStream(7));
  TimeNs now_ns = 0;
  const TimeNs step_ns = 1'000'000;  // 1 kHz tick
  wind.Advance(now_ns += step_ns);
  for (auto _ : state) {
    wind.Advance(now_ns += step_ns, 12.0);
    benchmark::DoNotOptimize(wind.CalcVelocity_W(Vec3::Zero()));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_WindSteady(benchmark::State& state) { WindTick(state, GustModel::kNone); }
BENCHMARK(BM_WindSteady);
void BM_WindGaussMarkov(benchmark::State& state) { WindTick(state, GustModel::kGaussMarkov); }
BENCHMARK(BM_WindGaussMarkov);
void BM_WindDryden(benchmark::State& state) { WindTick(state, GustModel::kDryden); }
BENCHMARK(BM_WindDryden);

}  // namespace
}  // namespace airis::engine
