#pragma once

// Documentation of config structs generated from their Visit (engine/core/config.h): every key with
// its type, default and doc string. docs/scene-format.md's tables are this output, checked by a
// test.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/config.h"

namespace airis::scenes {

/// One documented key of a config struct.
struct FieldDoc {
  std::string key;  ///< dotted path below the struct, lists as `objects[].name`
  std::string
      type;  ///< "number", "integer", "bool", "string", "one of a, b or c", "[x, y, z]", ...
  std::string default_value;  ///< the struct's default, as it would be written in YAML
  std::string doc;            ///< the doc string given to Field(), with its unit
};

namespace schema_detail {

template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};
template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsEigenVector : std::false_type {};
template <class S, int N, int O, int R, int C>
struct IsEigenVector<Eigen::Matrix<S, N, 1, O, R, C>> : std::bool_constant<(N > 0)> {};

struct Probe {
  template <class T>
  void Field(const char*, T&, const char*) {}
  void Renamed(const char*, const char*) {}
};
template <class T>
concept HasVisit = requires(T& t, Probe& p) {
  t.Visit(p);
};

}  // namespace schema_detail

/// Type of a field as shown in the docs.
template <class T>
std::string SchemaTypeName() {
  using namespace schema_detail;
  if constexpr (std::is_same_v<T, bool>) {
    return "bool";
  } else if constexpr (std::is_integral_v<T>) {
    return "integer";
  } else if constexpr (std::is_floating_point_v<T>) {
    return "number";
  } else if constexpr (std::is_same_v<T, std::string>) {
    return "string";
  } else if constexpr (std::is_enum_v<T>) {
    return "one of " + engine::EnumChoices<T>();
  } else if constexpr (IsEigenVector<T>::value) {
    return "list of " + std::to_string(T::RowsAtCompileTime) + " numbers";
  } else if constexpr (IsVector<T>::value) {
    return "list of " + SchemaTypeName<typename T::value_type>() + "s";
  } else if constexpr (IsOptional<T>::value) {
    return SchemaTypeName<typename T::value_type>() + ", optional";
  } else if constexpr (HasVisit<T>) {
    return "map";
  } else if constexpr (requires { T::kSchemaType; }) {
    return T::kSchemaType;
  } else {
    return "any YAML";
  }
}

/// Default of a field as it would be written in YAML.
template <class T>
std::string SchemaDefault(const T& value) {
  using namespace schema_detail;
  if constexpr (std::is_same_v<T, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_integral_v<T>) {
    return std::to_string(value);
  } else if constexpr (std::is_floating_point_v<T>) {
    return engine::FormatNumber(static_cast<double>(value));
  } else if constexpr (std::is_same_v<T, std::string>) {
    return value.empty() ? "\"\"" : "\"" + value + "\"";
  } else if constexpr (std::is_enum_v<T>) {
    return std::string(engine::ToString(value));
  } else if constexpr (IsEigenVector<T>::value) {
    std::string out = "[";
    for (int i = 0; i < T::RowsAtCompileTime; ++i) {
      if (i > 0) out += ", ";
      out += engine::FormatNumber(static_cast<double>(value[i]));
    }
    return out + "]";
  } else if constexpr (IsVector<T>::value) {
    if (value.empty()) return "[]";
    if constexpr (HasVisit<typename T::value_type>) {
      return "(" + std::to_string(value.size()) + " entries)";
    } else {
      std::string out = "[";
      for (std::size_t i = 0; i < value.size(); ++i)
        out += (i > 0 ? ", " : "") + SchemaDefault(value[i]);
      return out + "]";
    }
  } else if constexpr (IsOptional<T>::value) {
    return value ? SchemaDefault(*value) : "unset";
  } else {
    return "";
  }
}

/// Visitor that lists the fields of a struct, recursing into nested structs, lists and optionals of
/// structs (their keys as `parent.key`, `list[].key`).
class FieldLister {
 public:
  explicit FieldLister(std::vector<FieldDoc>* out, std::string prefix = "")
      : out_(out), prefix_(std::move(prefix)) {}

  void Renamed(const char*, const char*) {}  // old spellings are not documented keys

  template <class T>
  void Field(const char* key, T& member, const char* doc) {
    using namespace schema_detail;
    const std::string path = prefix_.empty() ? key : prefix_ + "." + key;
    out_->push_back({path, SchemaTypeName<T>(), SchemaDefault(member), doc});
    if constexpr (HasVisit<T>) {
      FieldLister nested(out_, path);
      member.Visit(nested);
    } else if constexpr (IsVector<T>::value) {
      if constexpr (HasVisit<typename T::value_type>) {
        typename T::value_type element{};
        FieldLister nested(out_, path + "[]");
        element.Visit(nested);
      }
    } else if constexpr (IsOptional<T>::value) {
      if constexpr (HasVisit<typename T::value_type>) {
        typename T::value_type element{};
        FieldLister nested(out_, path);
        element.Visit(nested);
      }
    }
  }

 private:
  std::vector<FieldDoc>* out_;
  std::string prefix_;
};

/// Every key of config struct T (with T's defaults), depth first in Visit order.
template <class T>
std::vector<FieldDoc> ListFields() {
  T defaults{};
  std::vector<FieldDoc> out;
  FieldLister lister(&out);
  defaults.Visit(lister);
  return out;
}

/// A Markdown table (key | type | default | meaning) of `fields`, each key prefixed with `prefix`.
std::string FieldTableMarkdown(std::span<const FieldDoc> fields, const std::string& prefix = "");

}  // namespace airis::scenes
