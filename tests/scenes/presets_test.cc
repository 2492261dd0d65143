// vehicles/presets/*.yaml and the C++ airframe presets the scene loader uses must describe the same airframes.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "scenes/yaml_reader.h"
#include "vehicles/multirotor/airframe_presets.h"

namespace airis::scenes {
namespace {

// Flattens a config struct into "key=value" lines (numbers kept apart as doubles) through its Visit, so two
// configs compare field by field and a difference names the field.
class Flattener {
 public:
  template <class T>
  void Field(const char* key, T& value, const char*) {
    Add(prefix_ + key, value);
  }
  std::vector<std::string> lines;
  std::vector<std::pair<std::string, double>> numbers;

 private:
  template <class T>
  void Add(const std::string& key, T& value) {
    if constexpr (std::is_same_v<T, bool>) {
      lines.push_back(key + (value ? "=true" : "=false"));
    } else if constexpr (std::is_arithmetic_v<T>) {
      numbers.emplace_back(key, static_cast<double>(value));
    } else if constexpr (std::is_enum_v<T>) {
      lines.push_back(key + "=" + std::string(engine::ToString(value)));
    } else if constexpr (std::is_same_v<T, std::string>) {
      lines.push_back(key + "=" + value);
    } else if constexpr (yaml_detail::IsFixedEigenVector<T>::value) {
      for (int i = 0; i < T::RowsAtCompileTime; ++i) Add(key + "[" + std::to_string(i) + "]", value[i]);
    } else if constexpr (yaml_detail::IsStdOptional<T>::value) {
      if (value) {
        Add(key, *value);
      } else {
        lines.push_back(key + "=unset");
      }
    } else if constexpr (yaml_detail::IsStdVector<T>::value) {
      lines.push_back(key + ".size=" + std::to_string(value.size()));
      for (std::size_t i = 0; i < value.size(); ++i) Add(key + "[" + std::to_string(i) + "]", value[i]);
    } else {
      const std::string saved = prefix_;
      prefix_ = key + ".";
      value.Visit(*this);
      prefix_ = saved;
    }
  }
  std::string prefix_;
};

Flattener Flatten(vehicles::MultirotorConfig config) {
  Flattener f;
  config.Visit(f);
  return f;
}

TEST(PresetFilesTest, EveryPresetFileEqualsTheBuiltInPreset) {
  for (const auto& preset : EnumNames(vehicles::AirframePreset{})) {
    SCOPED_TRACE(preset.name);
    const auto from_file = ReadYamlFile<vehicles::MultirotorConfig>(std::string("vehicles/presets/") +
                                                                    preset.name + ".yaml");
    const Flattener file = Flatten(from_file);
    const Flattener built_in = Flatten(vehicles::MakeAirframe(preset.value));
    ASSERT_EQ(file.lines, built_in.lines);  // structure, enums, strings, unset optionals
    ASSERT_EQ(file.numbers.size(), built_in.numbers.size());
    for (std::size_t i = 0; i < file.numbers.size(); ++i) {
      const auto& [key, a] = file.numbers[i];
      const double b = built_in.numbers[i].second;
      ASSERT_EQ(key, built_in.numbers[i].first);
      // The files write rotor positions to a micrometre (6 decimals of metres) where the code uses exact
      // trigonometry: agreement to 1e-6 relative (absolute below 1) is agreement.
      EXPECT_NEAR(a, b, 1e-6 * std::max(1.0, std::abs(b))) << key;
    }
  }
}

}  // namespace
}  // namespace airis::scenes
