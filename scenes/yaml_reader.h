#pragma once

// Generic YAML reader for every `*Config` struct with a `Visit(V&)` (engine/core/config.h). One
// list of fields drives reading, validation messages and documentation (schema.h). yaml-cpp appears
// only in scenes/.
//
// Errors are ConfigError with 1-based `file:line:col` and the full key path:
//   scenes/forest.yaml:42:7: vehicles[0].barometer.rate_hz: must be > 0 (got -5)
// Positions: an unknown key or a field that fails Validate() points at its key; a value of the
// wrong type or out of range points at the key too (the value is on the same line), a list element
// at the element.

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <charconv>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/error.h"

namespace airis::scenes {

namespace yaml_detail {

template <class T>
struct IsStdVector : std::false_type {};
template <class T, class A>
struct IsStdVector<std::vector<T, A>> : std::true_type {};

template <class T>
struct IsStdOptional : std::false_type {};
template <class T>
struct IsStdOptional<std::optional<T>> : std::true_type {};

template <class T>
struct IsFixedEigenVector : std::false_type {};
template <class S, int N, int Options, int MaxRows, int MaxCols>
struct IsFixedEigenVector<Eigen::Matrix<S, N, 1, Options, MaxRows, MaxCols>>
    : std::bool_constant<(N > 0)> {};

/// A visitor that does nothing, used only to detect whether a type has `Visit`.
struct NullVisitor {
  template <class T>
  void Field(const char*, T&, const char*) {}
  void Renamed(const char*, const char*) {}
};

template <class T>
concept HasVisit = requires(T& t, NullVisitor& v) {
  t.Visit(v);
};

template <class T>
concept HasValidate = requires(const T& t) {
  t.Validate();
};

/// A type that reads itself from a node (a registry-driven entry such as a sensor of any kind).
template <class T, class R>
concept ReadsItself = requires(T& t, const R& r, const YAML::Node& n, const YAML::Mark& m,
                               const std::string& k) {
  t.ReadFromYaml(r, n, m, k);
};

/// "a.b" from "a" and "b"; "b" when the prefix is empty.
inline std::string JoinKey(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

}  // namespace yaml_detail

/// Reads config structs and values from YAML nodes of one file, reporting every mistake as a
/// ConfigError that names the file, the 1-based line and column, and the key path. Missing keys
/// keep the struct's defaults; unknown keys are errors with the closest valid key suggested.
class YamlReader {
 public:
  /// @param file the file name printed in messages (as the user wrote it, or resolved).
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  /// 1-based location of a yaml-cpp mark (0-based) in this reader's file.
  engine::SourceLocation Where(const YAML::Mark& mark) const;

  /// Throws ConfigError at `mark` for the key `key_path`.
  [[noreturn]] void Fail(const YAML::Mark& mark, const std::string& key_path,
                         const std::string& problem) const;

  /// Reads `out` (a struct with Visit, a number, bool, string, enum, Eigen vector, std::vector or
  /// std::optional of those) from `node`, which is the value found at `key_path`. Throws
  /// ConfigError.
  template <class T>
  void Read(const YAML::Node& node, const std::string& key_path, T& out) const {
    ReadValue(node, node.Mark(), key_path, out);
  }

  /// As Read, reporting problems with the node as a whole at `mark` (the key's position).
  template <class T>
  void ReadValue(const YAML::Node& node, const YAML::Mark& mark, const std::string& key_path,
                 T& out) const;

  /// Reads the map `node` into the struct `out` through its Visit, rejects unknown keys and runs
  /// Validate(). `ignored_keys` are accepted without being read (the caller handles them).
  template <class T>
  void ReadStruct(const YAML::Node& node, const YAML::Mark& mark, const std::string& key_path,
                  T& out, const std::vector<std::string>& ignored_keys = {}) const;

  /// Calls out.Validate() and turns an InvalidField into a ConfigError located at the offending key
  /// inside `node` (or at `mark` when the key is absent, i.e. an invalid default).
  template <class T>
  void Validate(const YAML::Node& node, const YAML::Mark& mark, const std::string& key_path,
                const T& out) const {
    if constexpr (yaml_detail::HasValidate<T>) {
      try {
        out.Validate();
      } catch (const engine::InvalidField& e) {
        FailInvalidField(node, mark, key_path, e);
      }
    }
  }

  /// Finds `key` in map `node`: sets its value and its key's mark; false when absent.
  static bool FindKey(const YAML::Node& node, const std::string& key, YAML::Node* value,
                      YAML::Mark* mark);

  /// Short description of a node's kind for "got ..." ("a list", "a map", "nothing", "'text'").
  static std::string Describe(const YAML::Node& node);

  /// Parses a finite double from a scalar, or throws ConfigError.
  double ParseDouble(const YAML::Node& node, const YAML::Mark& mark,
                     const std::string& key_path) const;
  /// Parses an integer in [lo, hi] from a scalar, or throws ConfigError.
  std::int64_t ParseInteger(const YAML::Node& node, const YAML::Mark& mark,
                            const std::string& key_path, std::int64_t lo, std::int64_t hi) const;
  /// Parses an unsigned 64-bit integer from a scalar (seeds), or throws ConfigError.
  std::uint64_t ParseUnsigned64(const YAML::Node& node, const YAML::Mark& mark,
                                const std::string& key_path) const;
  /// Parses true/false, or throws ConfigError.
  bool ParseBool(const YAML::Node& node, const YAML::Mark& mark, const std::string& key_path) const;
  /// Returns the scalar text of `node`, or throws ConfigError ("expected <what>").
  const std::string& RequireScalar(const YAML::Node& node, const YAML::Mark& mark,
                                   const std::string& key_path, const char* what) const;
  /// Throws ConfigError unless `node` is a sequence ("expected <what>").
  void RequireSequence(const YAML::Node& node, const YAML::Mark& mark, const std::string& key_path,
                       const std::string& what) const;
  /// Throws ConfigError for an enum spelling that is not one of `choices` (with a suggestion).
  [[noreturn]] void FailEnum(const YAML::Mark& mark, const std::string& key_path,
                             const std::string& text,
                             const std::vector<std::string>& choices) const;

 private:
  /// Visitor that reads each field of a struct from a map node.
  class FieldReader;

  [[noreturn]] void FailInvalidField(const YAML::Node& node, const YAML::Mark& mark,
                                     const std::string& key_path,
                                     const engine::InvalidField& e) const;
  void RejectUnknownKeys(
      const YAML::Node& node, const std::string& key_path, const std::vector<std::string>& known,
      const std::vector<std::pair<std::string, std::string>>& renamed = {}) const;
  std::string file_;
};

class YamlReader::FieldReader {
 public:
  FieldReader(const YamlReader& reader, const YAML::Node& node, const std::string& key_path)
      : reader_(reader), node_(node), key_path_(key_path) {}

  template <class T>
  void Field(const char* key, T& member, const char* /*doc*/) {
    known_.emplace_back(key);
    YAML::Node value;
    YAML::Mark mark;
    if (FindKey(node_, key, &value, &mark)) {
      reader_.ReadValue(value, mark, yaml_detail::JoinKey(key_path_, key), member);
    }
  }

  /// An old spelling of a key (engine/core/config.h): reading it is an error naming the new one.
  void Renamed(const char* old_key, const char* new_key) {
    renamed_.emplace_back(old_key, new_key);
  }

  std::vector<std::string>& known() { return known_; }
  const std::vector<std::pair<std::string, std::string>>& renamed() const { return renamed_; }

 private:
  const YamlReader& reader_;
  const YAML::Node& node_;
  const std::string& key_path_;
  std::vector<std::string> known_;
  std::vector<std::pair<std::string, std::string>> renamed_;
};

template <class T>
void YamlReader::ReadStruct(const YAML::Node& node, const YAML::Mark& mark,
                            const std::string& key_path, T& out,
                            const std::vector<std::string>& ignored_keys) const {
  // `key:` with nothing after it means "all defaults".
  if (!node.IsNull()) {
    if (!node.IsMap()) Fail(mark, key_path, "expected a map of keys (got " + Describe(node) + ")");
    FieldReader fields(*this, node, key_path);
    out.Visit(fields);
    std::vector<std::string>& known = fields.known();
    known.insert(known.end(), ignored_keys.begin(), ignored_keys.end());
    RejectUnknownKeys(node, key_path, known, fields.renamed());
  }
  Validate(node, mark, key_path, out);
}

template <class T>
void YamlReader::ReadValue(const YAML::Node& node, const YAML::Mark& mark,
                           const std::string& key_path, T& out) const {
  using yaml_detail::IsFixedEigenVector;
  using yaml_detail::IsStdOptional;
  using yaml_detail::IsStdVector;
  if constexpr (std::is_same_v<T, YAML::Node>) {
    out.reset(node);  // kept raw (reset rebinds; = would copy into the old tree)
  } else if constexpr (std::is_same_v<T, bool>) {
    out = ParseBool(node, mark, key_path);
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    out = ParseUnsigned64(node, mark, key_path);
  } else if constexpr (std::is_integral_v<T>) {
    out = static_cast<T>(ParseInteger(node, mark, key_path, std::numeric_limits<T>::min(),
                                      static_cast<std::int64_t>(std::numeric_limits<T>::max())));
  } else if constexpr (std::is_floating_point_v<T>) {
    const double v = ParseDouble(node, mark, key_path);
    if (std::abs(v) > static_cast<double>(std::numeric_limits<T>::max())) {
      Fail(mark, key_path, "out of range (got " + node.Scalar() + ")");
    }
    out = static_cast<T>(v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    out = RequireScalar(node, mark, key_path, "a string");
  } else if constexpr (std::is_enum_v<T>) {
    const std::string& text = RequireScalar(node, mark, key_path, "one of the names");
    const auto parsed = engine::ParseEnum<T>(text);
    if (!parsed) {
      std::vector<std::string> choices;
      for (const auto& n : EnumNames(T{})) choices.emplace_back(n.name);
      FailEnum(mark, key_path, text, choices);
    }
    out = *parsed;
  } else if constexpr (IsFixedEigenVector<T>::value) {
    constexpr int kN = T::RowsAtCompileTime;
    const std::string what = "a list of " + std::to_string(kN) + " numbers";
    RequireSequence(node, mark, key_path, what);
    if (static_cast<int>(node.size()) != kN) {
      Fail(mark, key_path,
           "expected " + what + " (got a list of " + std::to_string(node.size()) + ")");
    }
    for (int i = 0; i < kN; ++i) {
      const YAML::Node item = node[static_cast<std::size_t>(i)];
      out[i] = static_cast<typename T::Scalar>(
          ParseDouble(item, item.Mark(), key_path + "[" + std::to_string(i) + "]"));
    }
  } else if constexpr (IsStdVector<T>::value) {
    RequireSequence(node, mark, key_path, "a list");
    out.clear();
    out.resize(node.size());
    for (std::size_t i = 0; i < node.size(); ++i) {
      const YAML::Node item = node[i];
      ReadValue(item, item.Mark(), key_path + "[" + std::to_string(i) + "]", out[i]);
    }
  } else if constexpr (IsStdOptional<T>::value) {
    if (!out) out.emplace();
    ReadValue(node, mark, key_path, *out);
  } else if constexpr (yaml_detail::ReadsItself<T, YamlReader>) {
    out.ReadFromYaml(*this, node, mark, key_path);
  } else if constexpr (yaml_detail::HasVisit<T>) {
    ReadStruct(node, mark, key_path, out);
  } else {
    static_assert(sizeof(T) == 0, "YamlReader: unsupported field type");
  }
}

/// Loads a YAML file, turning yaml-cpp's parse errors into ConfigError with file:line:col. Throws
/// ConfigError naming the path when the file cannot be read.
YAML::Node LoadYamlFile(const std::string& path);

/// Parses YAML text (for tests and embedded documents); `file` names it in messages.
YAML::Node LoadYamlString(const std::string& text, const std::string& file);

/// Reads a whole YAML file into a config struct T (starting from T's defaults) and validates it.
template <class T>
T ReadYamlFile(const std::string& path) {
  T out{};
  const YAML::Node root = LoadYamlFile(path);
  YamlReader(path).ReadValue(root, root.Mark(), "", out);
  return out;
}

}  // namespace airis::scenes
