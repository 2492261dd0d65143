#include "scenes/yaml_reader.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace airis::scenes {
namespace {

using engine::ConfigError;
using engine::InvalidField;

enum class Shape { kBox, kSphere, kCone };
constexpr engine::EnumName<Shape> kShapeNames[] = {
    {Shape::kBox, "box"}, {Shape::kSphere, "sphere"}, {Shape::kCone, "cone"}};
std::span<const engine::EnumName<Shape>> EnumNames(Shape) { return kShapeNames; }

struct MountTestConfig {
  double roll_deg = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  template <class V>
  void Visit(V& v) {
    v.Field("roll_deg", roll_deg, "roll (deg)");
    v.Field("position_m", position_m, "position (m)");
  }
  void Validate() const { engine::RequireInRange("roll_deg", roll_deg, -180.0, 180.0); }
};

struct BarometerTestConfig {
  double rate_hz = 50.0;
  std::uint8_t channel = 1;
  bool enabled = true;
  std::string name = "baro";
  Shape shape = Shape::kBox;
  MountTestConfig mount;
  std::optional<double> bias_pa;
  std::vector<double> taps;
  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per second (Hz)");
    v.Field("channel", channel, "bus channel");
    v.Field("enabled", enabled, "on or off");
    v.Field("name", name, "instance name");
    v.Field("shape", shape, "housing shape");
    v.Field("mount", mount, "mounting pose");
    v.Field("bias_pa", bias_pa, "fixed bias (Pa)");
    v.Field("taps", taps, "filter taps");
  }
  void Validate() const {
    engine::RequirePositive("rate_hz", rate_hz);
    // Re-checks the nested struct so its field comes back with the parent's prefix.
    try {
      mount.Validate();
    } catch (const InvalidField& e) {
      throw InvalidField("mount." + e.field(), e.problem());
    }
  }
};

struct VehicleTestConfig {
  std::string name;
  BarometerTestConfig barometer;
  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "vehicle name");
    v.Field("barometer", barometer, "the barometer");
  }
};

struct SceneTestConfig {
  std::uint64_t seed = 1;
  std::vector<VehicleTestConfig> vehicles;
  template <class V>
  void Visit(V& v) {
    v.Field("seed", seed, "random seed");
    v.Field("vehicles", vehicles, "vehicles");
  }
};

template <class T>
T ReadText(const std::string& text, const std::string& file = "scenes/test.yaml") {
  T out{};
  const YAML::Node root = LoadYamlString(text, file);
  YamlReader(file).ReadValue(root, root.Mark(), "", out);
  return out;
}

/// The ConfigError message thrown by reading `text`, or "" when none is thrown.
template <class T>
std::string ErrorOf(const std::string& text) {
  try {
    ReadText<T>(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlReaderTest, ReadsEveryFieldKind) {
  const auto c = ReadText<BarometerTestConfig>(
      "rate_hz: 25.5\n"
      "channel: 7\n"
      "enabled: false\n"
      "name: front\n"
      "shape: cone\n"
      "mount: {roll_deg: 90, position_m: [0.1, -0.2, 3]}\n"
      "bias_pa: -1.5\n"
      "taps: [1, 2, 3]\n");
  EXPECT_EQ(c.rate_hz, 25.5);
  EXPECT_EQ(c.channel, 7);
  EXPECT_FALSE(c.enabled);
  EXPECT_EQ(c.name, "front");
  EXPECT_EQ(c.shape, Shape::kCone);
  EXPECT_EQ(c.mount.roll_deg, 90.0);
  EXPECT_EQ(c.mount.position_m, Eigen::Vector3d(0.1, -0.2, 3.0));
  ASSERT_TRUE(c.bias_pa.has_value());
  EXPECT_EQ(*c.bias_pa, -1.5);
  EXPECT_EQ(c.taps, (std::vector<double>{1.0, 2.0, 3.0}));
}

TEST(YamlReaderTest, MissingKeysKeepDefaults) {
  const auto c = ReadText<BarometerTestConfig>("channel: 3\n");
  EXPECT_EQ(c.rate_hz, 50.0);
  EXPECT_TRUE(c.enabled);
  EXPECT_EQ(c.name, "baro");
  EXPECT_FALSE(c.bias_pa.has_value());
  EXPECT_TRUE(c.taps.empty());
  EXPECT_EQ(c.channel, 3);
}

TEST(YamlReaderTest, EmptyDocumentIsAllDefaults) {
  const auto c = ReadText<SceneTestConfig>("");
  EXPECT_EQ(c.seed, 1u);
  EXPECT_TRUE(c.vehicles.empty());
}

TEST(YamlReaderTest, ReadsFullUnsigned64Seeds) {
  EXPECT_EQ(ReadText<SceneTestConfig>("seed: 18446744073709551615\n").seed,
            18446744073709551615ull);
  EXPECT_EQ(
      ErrorOf<SceneTestConfig>("seed: -1\n"),
      "scenes/test.yaml:1:1: seed: out of range (got '-1'; expected 0 to 18446744073709551615)");
}

TEST(YamlReaderTest, UnknownKeySuggestsClosest) {
  EXPECT_EQ(ErrorOf<SceneTestConfig>("seed: 3\n"
                                     "vehicles:\n"
                                     "  - name: a\n"
                                     "    barometer:\n"
                                     "      rate_hx: 5\n"),
            "scenes/test.yaml:5:7: vehicles[0].barometer.rate_hx: unknown key 'rate_hx' "
            "(did you mean 'rate_hz'?)");
}

TEST(YamlReaderTest, UnknownKeyWithoutCloseMatchListsValidKeys) {
  EXPECT_EQ(
      ErrorOf<MountTestConfig>("colour: red\n"),
      "scenes/test.yaml:1:1: colour: unknown key 'colour' (valid keys: roll_deg, position_m)");
}

TEST(YamlReaderTest, DuplicateKeyIsAnError) {
  EXPECT_EQ(ErrorOf<MountTestConfig>("roll_deg: 1\nroll_deg: 2\n"),
            "scenes/test.yaml:2:1: roll_deg: duplicate key");
}

TEST(YamlReaderTest, ValidateErrorNamesFileLineColumnAndFullPath) {
  EXPECT_EQ(ErrorOf<SceneTestConfig>("vehicles:\n"
                                     "  - name: a\n"
                                     "  - name: b\n"
                                     "    barometer:\n"
                                     "      channel: 2\n"
                                     "      rate_hz: -5\n"),
            "scenes/test.yaml:6:7: vehicles[1].barometer.rate_hz: must be > 0 (got -5)");
}

TEST(YamlReaderTest, NestedValidateErrorPointsAtTheNestedKey) {
  // The nested struct's own Validate reports first, at its key.
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("mount:\n"
                                         "  position_m: [0, 0, 0]\n"
                                         "  roll_deg: 200\n"),
            "scenes/test.yaml:3:3: mount.roll_deg: must be between -180 and 180 (got 200)");
}

struct BadDefault {
  double gain = -1.0;
  template <class V>
  void Visit(V& v) {
    v.Field("gain", gain, "gain");
  }
  void Validate() const { engine::RequirePositive("gain", gain); }
};
struct Holder {
  BadDefault block;
  template <class V>
  void Visit(V& v) {
    v.Field("block", block, "block");
  }
};

TEST(YamlReaderTest, InvalidDefaultIsReportedAtTheStruct) {
  EXPECT_EQ(ErrorOf<Holder>("# comment\nblock: {}\n"),
            "scenes/test.yaml:2:1: block.gain: must be > 0 (got -1)");
}

TEST(YamlReaderTest, WrongTypesNameWhatWasExpected) {
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("rate_hz: fast\n"),
            "scenes/test.yaml:1:1: rate_hz: expected a number (got 'fast')");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("rate_hz: [1, 2]\n"),
            "scenes/test.yaml:1:1: rate_hz: expected a number (got a list)");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("enabled: maybe\n"),
            "scenes/test.yaml:1:1: enabled: expected true or false (got 'maybe')");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("channel: 2.5\n"),
            "scenes/test.yaml:1:1: channel: expected an integer (got '2.5')");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("name: {a: 1}\n"),
            "scenes/test.yaml:1:1: name: expected a string (got a map)");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("mount: 3\n"),
            "scenes/test.yaml:1:1: mount: expected a map of keys (got '3')");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("taps: 3\n"),
            "scenes/test.yaml:1:1: taps: expected a list (got '3')");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("rate_hz:\n"),
            "scenes/test.yaml:1:1: rate_hz: expected a number (got nothing)");
}

TEST(YamlReaderTest, ListElementErrorsPointAtTheElement) {
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("taps: [1, x, 3]\n"),
            "scenes/test.yaml:1:11: taps[1]: expected a number (got 'x')");
  EXPECT_EQ(ErrorOf<MountTestConfig>("position_m:\n  - 1\n  - .nan\n  - 3\n"),
            "scenes/test.yaml:3:5: position_m[1]: must be a finite number (got .nan)");
  EXPECT_EQ(ErrorOf<MountTestConfig>("position_m: [1, 2]\n"),
            "scenes/test.yaml:1:1: position_m: expected a list of 3 numbers (got a list of 2)");
}

TEST(YamlReaderTest, OutOfRangeIntegersAreRejected) {
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("channel: 300\n"),
            "scenes/test.yaml:1:1: channel: out of range (got '300'; expected 0 to 255)");
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("channel: -1\n"),
            "scenes/test.yaml:1:1: channel: out of range (got '-1'; expected 0 to 255)");
}

TEST(YamlReaderTest, UnknownEnumValueListsChoicesAndSuggests) {
  EXPECT_EQ(ErrorOf<BarometerTestConfig>("shape: spere\n"),
            "scenes/test.yaml:1:1: shape: unknown value 'spere' (expected box, sphere or cone; "
            "did you mean 'sphere'?)");
}

TEST(YamlReaderTest, SyntaxErrorsCarryTheLocation) {
  try {
    LoadYamlString("a: [1, 2\nb: 3\n", "scenes/broken.yaml");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where().file, "scenes/broken.yaml");
    EXPECT_GT(e.where().line, 0);
    EXPECT_NE(std::string(e.what()).find("invalid YAML"), std::string::npos);
  }
}

TEST(YamlReaderTest, AStrayCommaIsAnErrorNotEndlessDocuments) {
  // yaml-cpp 0.7's LoadAll yields an empty document at such a ',' for ever (gigabytes): the loader
  // must stop and point at it, at the start of a file and after a root in flow style alike.
  const std::pair<const char*, int> cases[] = {{",", 1}, {"# c\n, a: 1\n", 1}, {"[1, 2], [3]", 7}};
  for (const auto& [text, column] : cases) {
    try {
      LoadYamlString(text, "scenes/comma.yaml");
      ADD_FAILURE() << "expected ConfigError for " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.where().column, column) << text;
      EXPECT_NE(std::string(e.what()).find("a ',' outside a flow sequence or map"),
                std::string::npos)
          << e.what();
    }
  }
  // Commas inside flow collections and plain scalars stay what they are.
  EXPECT_EQ(LoadYamlString("a: [1, 2]\nb: x, y\n", "t.yaml")["b"].as<std::string>(), "x, y");
}

TEST(YamlReaderTest, UnreadableFileNamesThePath) {
  try {
    LoadYamlFile("/nonexistent/scene.yaml");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.yaml: file not found");
  }
}

TEST(YamlReaderTest, ErrorLeavesTheDocumentUnchanged) {
  // Locating a Validate error walks the tree; it must not rebind (and so overwrite) any node.
  const YAML::Node root = LoadYamlString("vehicles:\n  - barometer: {rate_hz: -1}\n", "t.yaml");
  SceneTestConfig c;
  EXPECT_THROW(YamlReader("t.yaml").Read(root, "", c), ConfigError);
  EXPECT_TRUE(root["vehicles"].IsSequence());
  EXPECT_EQ(root["vehicles"][0]["barometer"]["rate_hz"].Scalar(), "-1");
}

}  // namespace
}  // namespace airis::scenes
