#include "engine/world/sensor.h"

namespace airis::engine {

Sensor::Sensor(std::string name, double rate_hz)
    : name_(std::move(name)), schedule_(rate_hz, 0, 1) {}

bool Sensor::SampleDue(const SensorContext& context) {
  if (schedule_.ConsumeDue(context.now_ns) == 0 || !enabled_) return false;
  if (gate_ && !gate_(context.now_ns)) return false;
  last_sample_ns_ = context.now_ns;
  Sample(context);
  return true;
}

void Sensor::NotifyListeners() const {
  for (const auto& listener : listeners_) listener(*this);
}

}  // namespace airis::engine
