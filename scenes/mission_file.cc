#include "scenes/mission_file.h"

#include <algorithm>
#include <utility>

#include "scenes/mission_step_kinds.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {
namespace {

struct MissionHeader {
  std::string name;
  std::string vehicle;
  bool abort_on_collision = true;
  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "mission name, for logs");
    v.Field("vehicle", vehicle, "vehicle that flies it; empty = the scene's first");
    v.Field("abort_on_collision", abort_on_collision, "fail the mission on any collision");
  }
};

engine::Mission ReadMission(const YAML::Node& root, const std::string& file) {
  // Mistakes in different steps are reported together.
  const YamlReader reader(file, std::make_shared<YamlReadState>(/*collect=*/true));
  if (!root.IsMap()) {
    reader.Fail(root.Mark(), "",
                "a mission file must be a map with a 'steps' list (got " +
                    YamlReader::Describe(root) + ")");
  }
  MissionHeader header;
  reader.Collect([&] { reader.ReadStruct(root, root.Mark(), "", header, {"steps"}); });
  const YAML::Node steps = root["steps"];
  if (!steps) reader.Fail(root.Mark(), "steps", "missing: a mission needs a list of steps");
  reader.RequireSequence(steps, steps.Mark(), "steps", "a list of steps");
  if (steps.size() > engine::kMaxListEntries) {
    reader.Fail(steps.Mark(), "steps",
                "a list of " + std::to_string(steps.size()) +
                    " steps is longer than the limit of " +
                    std::to_string(engine::kMaxListEntries) + " (docs/limits.md)");
  }

  static const std::vector<std::string> kind_names = [] {
    std::vector<std::string> names;
    for (const MissionStepKind& k : MissionStepKinds()) names.emplace_back(k.name);
    return names;
  }();
  engine::Mission mission;
  mission.name = header.name;
  mission.vehicle = header.vehicle;
  mission.abort_on_collision = header.abort_on_collision;
  mission.file = file;
  mission.locate = [root, file](const std::string& key) {
    return YamlReader(file).Where(YamlReader::FindFieldMark(root, root.Mark(), key));
  };
  std::size_t i = 0;
  for (const YAML::Node& item : steps) {
    const std::string path = "steps[" + std::to_string(i++) + "]";
    reader.Collect([&] {
      if (!item.IsMap() || item.size() != 1) {
        reader.Fail(item.Mark(), path,
                    "each step is a map with one key naming its kind, e.g. '- goto: {...}' (got " +
                        YamlReader::Describe(item) + ")");
      }
      const auto entry = item.begin();
      const std::string& kind =
          reader.RequireScalar(entry->first, entry->first.Mark(), path, "a step kind as its key");
      const YAML::Mark mark = entry->first.Mark();
      const auto found = std::find(kind_names.begin(), kind_names.end(), kind);
      if (found == kind_names.end()) {
        std::string problem = "unknown step " + engine::QuoteValue(kind);
        if (const auto close = engine::ClosestMatch(kind.substr(0, 64), kind_names))
          problem += " (did you mean '" + *close + "'?)";
        std::string all;
        for (const auto& k : kind_names) all += (all.empty() ? "" : ", ") + k;
        reader.Fail(mark, path, problem + "; steps are " + all);
      }
      const auto index = static_cast<std::size_t>(found - kind_names.begin());
      mission.steps.push_back(
          MissionStepKinds()[index].read(reader, entry->second, mark, path + "." + kind));
    });
  }
  reader.state()->ThrowIfAny();
  if (mission.steps.empty())
    reader.Fail(steps.Mark(), "steps", "a mission needs at least one step");
  return mission;
}

}  // namespace

engine::Mission LoadMissionFile(const std::string& path) {
  return ReadMission(LoadYamlFile(path), path);
}

engine::Mission ParseMission(const std::string& text, const std::string& file) {
  return ReadMission(LoadYamlString(text, file), file);
}

}  // namespace airis::scenes
