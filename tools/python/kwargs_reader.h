#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/error.h"

namespace airis::python {

/// Fills config structs from Python keyword arguments through their Visit (the one list of
/// fields, DESIGN principle 1): each visited field takes the keyword of its name, converted to the
/// field's type. Errors are ConfigErrors naming the keyword: a wrong type, a bad enum spelling,
/// and (Finish) a keyword no struct has, with the closest name suggested.
class KwargsReader {
 public:
  explicit KwargsReader(const pybind11::dict& kwargs) : kwargs_(kwargs) {}

  template <class Config>
  void Read(Config& config) {
    config.Visit(*this);
  }

  template <class T>
  void Field(const char* name, T& value, const char* /*doc*/) {
    known_.push_back(name);
    if (!kwargs_.contains(name)) return;
    used_.insert(name);
    const pybind11::handle item = kwargs_[name];
    try {
      Convert(item, value, name);
    } catch (const pybind11::cast_error&) {
      throw engine::ConfigError(
          {}, name,
          "wrong type (got " + std::string(pybind11::str(item.get_type().attr("__name__"))) + ")");
    }
  }

  /// Throws ConfigError for a keyword that no visited struct has.
  void Finish() const {
    for (const auto& item : kwargs_) {
      const std::string key = pybind11::str(item.first);
      if (used_.count(key)) continue;
      std::string problem = "unknown option";
      if (const auto close = engine::ClosestMatch(key, known_)) {
        problem += " (did you mean '" + *close + "'?)";
      }
      throw engine::ConfigError({}, key, problem);
    }
  }

 private:
  template <class T>
  static void Convert(pybind11::handle item, T& value, const char* name) {
    if constexpr (std::is_enum_v<T>) {
      const std::string text = pybind11::cast<std::string>(item);
      const std::optional<T> parsed = engine::ParseEnum<T>(text);
      if (!parsed) {
        throw engine::ConfigError({}, name,
                                  "expected " + engine::EnumChoices<T>() + " (got '" + text + "')");
      }
      value = *parsed;
    } else if constexpr (std::is_same_v<T, engine::Vec3>) {
      const auto v = pybind11::cast<std::vector<double>>(item);
      if (v.size() != 3) {
        throw engine::ConfigError({}, name,
                                  "expected 3 numbers (got " + std::to_string(v.size()) + ")");
      }
      value = engine::Vec3(v[0], v[1], v[2]);
    } else if constexpr (std::is_same_v<T, bool> || std::is_integral_v<T>) {
      // Python bools are ints: an int field refuses them, a bool field takes only them.
      if (std::is_same_v<T, bool> != pybind11::isinstance<pybind11::bool_>(item)) {
        throw pybind11::cast_error();
      }
      value = pybind11::cast<T>(item);
    } else {
      value = pybind11::cast<T>(item);
    }
  }

  const pybind11::dict& kwargs_;
  std::vector<std::string> known_;
  std::set<std::string> used_;
};

}  // namespace airis::python
