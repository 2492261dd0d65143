#include "engine/render/camera_effects.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/standard_normal.h"
#include "engine/render/srgb.h"

namespace airis::engine {
namespace {

using srgb::DecodeTable;
using srgb::EncodeLinear;
using srgb::EncodeTable;
using srgb::kEncodeSteps;

// Metered exposure is kept within this many stops of the renderer's (a black frame does not ask
// for an infinite gain).
constexpr double kMaxMeteredEv = 16.0;
// Below this mean the Poisson law is sampled exactly; above it, its normal approximation (same
// mean and variance; skewness 1/sqrt(mean) < 0.23).
constexpr double kExactPoissonBelow_e = 20.0;

}  // namespace

void CameraEffectsConfig::Validate() const {
  RequireInRange("exposure_ev", exposure_ev, -20.0, 20.0);
  RequireInRange("auto_exposure_target", auto_exposure_target, 1e-3, 1.0);
  RequireInRange("full_well_e", full_well_e, 1.0, 1e7);
  RequireInRange("read_noise_e", read_noise_e, 0.0, full_well_e);
  RequireInRange("adc_bits", adc_bits, 8, 16);
  RequireInRange("exposure_time_s", exposure_time_s, 1e-6, 1.0);
  RequireInRange("rolling_shutter_readout_s", rolling_shutter_readout_s, 0.0, 1.0);
}

std::uint16_t SampleSensorDn(double mean_e, double full_well_e, double read_noise_e, int adc_bits,
                             RandomStream& rng) {
  double e;
  if (mean_e < kExactPoissonBelow_e) {
    // Knuth's method: count uniforms until their product falls below exp(-mean).
    const double limit = std::exp(-std::max(mean_e, 0.0));
    int n = 0;
    for (double p = rng.Uniform01(); p > limit; p *= rng.Uniform01()) ++n;
    e = n + read_noise_e * StandardNormal(rng);
  } else {
    e = mean_e + std::sqrt(mean_e + read_noise_e * read_noise_e) * StandardNormal(rng);
  }
  const double max_dn = std::ldexp(1.0, adc_bits) - 1.0;
  const double gain_dn_e = max_dn / full_well_e;
  return static_cast<std::uint16_t>(std::clamp(e, 0.0, full_well_e) * gain_dn_e + 0.5);
}

double CalcVignetting(const CameraIntrinsics& k, double u, double v) {
  const auto ray = k.CalcRay(Eigen::Vector2d(u, v));
  if (!ray) return 0.0;
  const double c = ray->z() / ray->norm();
  return c * c * c * c;
}

CameraEffects::CameraEffects(const CameraEffectsConfig& config, const CameraIntrinsics& intrinsics,
                             std::uint64_t seed)
    : config_(config), seed_(seed) {
  if (!config_.vignetting) return;
  vignetting_.resize(static_cast<std::size_t>(intrinsics.width_px) * intrinsics.height_px);
  for (int v = 0; v < intrinsics.height_px; ++v) {
    for (int u = 0; u < intrinsics.width_px; ++u) {
      vignetting_[static_cast<std::size_t>(v) * intrinsics.width_px + u] =
          static_cast<float>(CalcVignetting(intrinsics, u, v));
    }
  }
}

bool CameraEffects::active(const CameraEffectsAdjustment& adjustment) const {
  return config_.any() || adjustment.exposure_ev_offset != 0.0 || adjustment.read_noise_e ||
         adjustment.full_well_e;
}

double CameraEffects::MeterEv(const Image<std::uint8_t>& rgba) const {
  // Mean Rec. 709 luminance of the signal at the reference exposure, vignetting included (the
  // sensor meters what reaches it).
  const auto& decode = DecodeTable();
  double sum = 0.0;
  const std::size_t n = static_cast<std::size_t>(rgba.width) * rgba.height;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &rgba.pixels[4 * i];
    const double y = 0.2126 * decode[p[0]] + 0.7152 * decode[p[1]] + 0.0722 * decode[p[2]];
    sum += vignetting_.empty() ? y : y * vignetting_[i];
  }
  if (sum <= 0.0) return kMaxMeteredEv;
  return std::clamp(std::log2(config_.auto_exposure_target * double(n) / sum), -kMaxMeteredEv,
                    kMaxMeteredEv);
}

double CameraEffects::Apply(Image<std::uint8_t>& rgba, TimeNs time_ns,
                            const CameraEffectsAdjustment& adjustment) const {
  AIRIS_DEMAND(rgba.channels == 4);
  AIRIS_DEMAND(vignetting_.empty() || vignetting_.size() == rgba.pixels.size() / 4);
  double ev = config_.exposure_ev + adjustment.exposure_ev_offset;
  if (config_.auto_exposure) ev += MeterEv(rgba);
  const double scale = std::exp2(ev);
  const bool noise = config_.noise || adjustment.read_noise_e || adjustment.full_well_e;
  const auto& decode = DecodeTable();
  if (!noise && vignetting_.empty()) {
    // Exposure alone maps each code to one code.
    std::array<std::uint8_t, 256> map{};
    for (int i = 0; i < 256; ++i) map[i] = EncodeLinear(EncodeTable(), decode[i] * scale);
    for (std::size_t i = 0; i < rgba.pixels.size(); i += 4) {
      for (int c = 0; c < 3; ++c) rgba.pixels[i + c] = map[rgba.pixels[i + c]];
    }
    return ev;
  }
  const double full_well_e = adjustment.full_well_e.value_or(config_.full_well_e);
  const double read_e = adjustment.read_noise_e.value_or(config_.read_noise_e);
  const double dn_to_step = kEncodeSteps / (std::ldexp(1.0, config_.adc_bits) - 1.0);
  const auto& encode = EncodeTable();
  // One stream per row, from the frame's time and the row: a pixel's noise depends on nothing
  // but the seed, the time and where it is.
  const std::uint64_t frame_seed =
      RandomStream(seed_ ^ static_cast<std::uint64_t>(time_ns)).NextU64();
  for (int v = 0; v < rgba.height; ++v) {
    RandomStream rng(frame_seed + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(v));
    for (int u = 0; u < rgba.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * rgba.width + u;
      const double s = vignetting_.empty() ? scale : scale * vignetting_[i];
      std::uint8_t* p = &rgba.pixels[4 * i];
      for (int c = 0; c < 3; ++c) {
        const double linear = decode[p[c]] * s;
        if (noise) {
          const std::uint16_t dn =
              SampleSensorDn(linear * full_well_e, full_well_e, read_e, config_.adc_bits, rng);
          p[c] = encode[static_cast<std::size_t>(dn * dn_to_step + 0.5)];
        } else {
          p[c] = EncodeLinear(encode, linear);
        }
      }
    }
  }
  return ev;
}

}  // namespace airis::engine
