#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"
#include "engine/core/clock.h"
#include "engine/core/config.h"
#include "engine/core/random.h"

namespace airis::engine {

/// What a real camera does to the light the renderer computes (docs/rendering.md, "Sensor
/// effects"): exposure, lens vignetting and sensor noise, applied to the RGB image only (depth,
/// normals and labels stay exact). Every effect is off by default, and then the RGB image is the
/// renderer's, byte for byte.
///
/// The renderer's linear colour (sRGB decoded) at exposure_ev 0 is the reference exposure: 1.0 is
/// a full pixel well. The signal of a pixel is that colour times 2^EV (EV = exposure_ev, plus the
/// automatic exposure when on) times the vignetting factor, clipped at the full well.
struct CameraEffectsConfig {
  double exposure_ev = 0.0;
  bool auto_exposure = false;
  double auto_exposure_target = 0.18;
  bool vignetting = false;
  bool noise = false;
  double full_well_e = 10000.0;
  double read_noise_e = 3.0;
  int adc_bits = 10;
  bool motion_blur = false;
  double exposure_time_s = 1.0 / 125.0;
  double rolling_shutter_readout_s = 0.0;

  template <class V>
  void Visit(V& v) {
    v.Field("exposure_ev", exposure_ev,
            "exposure relative to the renderer's (EV stops: the signal is multiplied by 2^EV); "
            "with auto_exposure, the compensation added to the metered exposure");
    v.Field("auto_exposure", auto_exposure,
            "meter each frame: choose the exposure that brings the mean linear luminance to "
            "auto_exposure_target");
    v.Field("auto_exposure_target", auto_exposure_target,
            "mean linear luminance (Rec. 709) auto exposure aims at, 0 to 1 (0.18: middle grey)");
    v.Field("vignetting", vignetting,
            "natural vignetting: irradiance falls as cos^4 of the angle between a pixel's ray and "
            "the optical axis");
    v.Field("noise", noise,
            "sensor noise: Poisson shot noise of the photo-electrons, Gaussian read noise and "
            "the ADC's quantisation");
    v.Field("full_well_e", full_well_e, "electrons of a full pixel well (linear colour 1.0)");
    v.Field("read_noise_e", read_noise_e, "read noise (electrons, 1 sigma)");
    v.Field("adc_bits", adc_bits,
            "ADC resolution (bits, 8 to 16): the full well maps to 2^bits - 1 digital numbers");
    v.Field("motion_blur", motion_blur,
            "blur the colour image by the camera's own motion during the exposure (the world "
            "taken as still; depth and labels stay sharp)");
    v.Field("exposure_time_s", exposure_time_s,
            "time the shutter is open (s), centred on the frame's time: the length of the motion "
            "blur and of the rain's streaks");
    v.Field("rolling_shutter_readout_s", rolling_shutter_readout_s,
            "time the sensor takes to read its rows out, top to bottom (s; 0: a global shutter): "
            "each row shows the scene at its own readout time, the middle row at the frame's "
            "(the camera's own motion, the world taken as still; depth and labels stay at the "
            "frame's time)");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
  /// True when some effect of CameraEffects::Apply changes the image (the rolling shutter and the
  /// motion blur, which need the depth and the camera's motion, are applied before it:
  /// ApplyRollingShutter, ApplyMotionBlur).
  bool any() const { return exposure_ev != 0.0 || auto_exposure || vignetting || noise; }
  /// True when the camera's motion changes the image (motion blur or a rolling shutter).
  bool motion() const { return motion_blur || rolling_shutter_readout_s > 0.0; }
};

/// Changes of one frame's effects (a dataset's domain randomization draws them).
struct CameraEffectsAdjustment {
  double exposure_ev_offset = 0.0;     ///< added to the exposure (EV stops)
  std::optional<double> read_noise_e;  ///< replaces the read noise and turns noise on
  std::optional<double> full_well_e;   ///< replaces the full well and turns noise on
};

/// Digital number of a pixel whose mean signal is `mean_e` electrons (EMVA 1288's linear camera
/// model): n ~ Poisson(mean_e) electrons (exact below 20 electrons, else the normal law of the
/// same mean and variance), plus N(0, read_noise_e^2), clipped to [0, full_well_e], times the
/// gain K = (2^adc_bits - 1) / full_well_e DN per electron, rounded. Mean K mean_e and variance
/// K^2 (mean_e + read_noise_e^2) + 1/12 (quantisation) away from the clips.
std::uint16_t SampleSensorDn(double mean_e, double full_well_e, double read_noise_e, int adc_bits,
                             RandomStream& rng);

/// cos^4 of the angle between pixel (u, v)'s ray (distortion inverted) and the optical axis:
/// the natural vignetting of a lens without pupil aberrations (irradiance falls as cos^4; e.g.
/// Ray, Applied Photographic Optics, ch. 4). 1 at the principal point.
double CalcVignetting(const CameraIntrinsics& k, double u, double v);

/// The effects of one camera: a vignetting map made once from its intrinsics, sRGB tables, and
/// noise seeded per frame from `seed` and the frame's time, so a frame's noise depends on nothing
/// else (not on the frames rendered before it: a dataset shard renders only some).
class CameraEffects {
 public:
  /// `config` must be valid.
  CameraEffects(const CameraEffectsConfig& config, const CameraIntrinsics& intrinsics,
                std::uint64_t seed);

  /// Applies the effects to `rgba` (sRGB, alpha untouched) of the frame at `time_ns`. Returns
  /// the exposure used (EV stops relative to the renderer's, metering and adjustment included).
  double Apply(Image<std::uint8_t>& rgba, TimeNs time_ns,
               const CameraEffectsAdjustment& adjustment = {}) const;
  /// True when Apply changes images (the config, or an adjustment, has an effect).
  bool active(const CameraEffectsAdjustment& adjustment = {}) const;

 private:
  double MeterEv(const Image<std::uint8_t>& rgba) const;

  CameraEffectsConfig config_;
  std::uint64_t seed_;
  std::vector<float> vignetting_;  // per pixel, empty without vignetting
};

}  // namespace airis::engine
