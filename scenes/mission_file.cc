#include "scenes/mission_file.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "engine/core/limits.h"
#include "engine/mission/mission_barriers.h"
#include "scenes/mission_step_kinds.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {
namespace {

struct MissionHeader {
  std::string name;
  std::string vehicle;
  bool abort_on_collision = true;
  engine::DomainRandomizationConfig randomize;
  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "mission name, for logs");
    v.Field("vehicle", vehicle, "vehicle that flies `steps`; empty = the scene's first");
    v.Field("abort_on_collision", abort_on_collision, "fail the mission on any collision");
    v.Field("randomize", randomize,
            "domain randomization of a dataset: ranges of sun, fog, exposure and noise "
            "(docs/dataset-format.md)");
  }
};

// The keys of one entry of `vehicles:` besides its steps.
struct TrackHeader {
  std::optional<bool> abort_on_collision;
  template <class V>
  void Visit(V& v) {
    v.Field("abort_on_collision", abort_on_collision,
            "fail the mission on a collision of this vehicle (default: the mission's)");
  }
};

// The `steps` list of `parent` (a mission in the single-vehicle form or an entry of `vehicles`).
std::vector<engine::MissionStep> ReadSteps(const YamlReader& reader, const YAML::Node& parent,
                                           const std::string& prefix, const std::string& what) {
  static const std::vector<std::string> kind_names = [] {
    std::vector<std::string> names;
    for (const MissionStepKind& k : MissionStepKinds()) names.emplace_back(k.name);
    return names;
  }();
  const std::string steps_path = prefix + "steps";
  YAML::Node steps;
  YAML::Mark steps_mark;
  if (!YamlReader::FindKey(parent, "steps", &steps, &steps_mark)) {
    reader.Fail(parent.Mark(), steps_path, "missing: " + what);
  }
  reader.RequireSequence(steps, steps_mark, steps_path, "a list of steps");
  if (steps.size() > engine::kMaxListEntries) {
    reader.Fail(steps_mark, steps_path,
                "a list of " + std::to_string(steps.size()) +
                    " steps is longer than the limit of " +
                    std::to_string(engine::kMaxListEntries) + " (docs/limits.md)");
  }
  if (steps.size() == 0) reader.Fail(steps_mark, steps_path, "a track needs at least one step");
  std::vector<engine::MissionStep> out;
  std::size_t i = 0;
  for (const YAML::Node& item : steps) {
    const std::string path = steps_path + "[" + std::to_string(i++) + "]";
    // Mistakes in different steps are reported together.
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
        if (const auto close =
                engine::ClosestMatch(kind.substr(0, engine::kMaxNameLength), kind_names))
          problem += " (did you mean '" + *close + "'?)";
        std::string all;
        for (const auto& k : kind_names) all += (all.empty() ? "" : ", ") + k;
        reader.Fail(mark, path, problem + "; steps are " + all);
      }
      const auto index = static_cast<std::size_t>(found - kind_names.begin());
      out.push_back(MissionStepKinds()[index].read(reader, entry->second, mark, path + "." + kind));
    });
  }
  return out;
}

// `vehicles: {drone1: {steps: [...]}, ...}`: a track per vehicle, in file order.
std::vector<engine::MissionTrack> ReadTracks(const YamlReader& reader, const YAML::Node& vehicles,
                                             const YAML::Mark& mark, const MissionHeader& header) {
  if (!vehicles.IsMap() || vehicles.size() == 0) {
    reader.Fail(mark, "vehicles",
                "a map of vehicle names to their tracks, e.g. 'drone1: {steps: [...]}' (got " +
                    YamlReader::Describe(vehicles) + ")");
  }
  std::vector<engine::MissionTrack> tracks;
  for (const auto& entry : vehicles) {
    const YAML::Mark key_mark = entry.first.Mark();
    const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : "";
    const std::string path = "vehicles." + name;
    if (!engine::IsValidName(name)) {
      reader.Fail(
          key_mark, "vehicles",
          engine::QuoteValue(name) + " is no vehicle name (1 to 64 letters, digits, '_' or '-')");
    }
    for (const engine::MissionTrack& earlier : tracks) {
      if (earlier.vehicle == name) reader.Fail(key_mark, path, "a second track for this vehicle");
    }
    if (!entry.second.IsMap()) {
      reader.Fail(key_mark, path,
                  "a vehicle's track is a map with a 'steps' list (got " +
                      YamlReader::Describe(entry.second) + ")");
    }
    TrackHeader own;
    reader.ReadStruct(entry.second, key_mark, path, own, {"steps"});
    engine::MissionTrack track;
    track.vehicle = name;
    track.abort_on_collision = own.abort_on_collision.value_or(header.abort_on_collision);
    // Reported with the track's other mistakes (an unknown key that was meant to be 'steps').
    reader.Collect([&] {
      track.steps =
          ReadSteps(reader, entry.second, path + ".", "a vehicle's track needs its steps");
    });
    track.file = reader.Where(key_mark).file;
    track.key_path = path;
    track.where = reader.Where(key_mark);
    tracks.push_back(std::move(track));
  }
  return tracks;
}

engine::Mission ReadMission(const YAML::Node& root, const std::string& file) {
  // Independent mistakes (the header's keys, different steps) are reported together.
  const YamlReader reader(file, std::make_shared<YamlReadState>(/*collect=*/true));
  if (!root.IsMap()) {
    reader.Fail(root.Mark(), "",
                "a mission file must be a map with a 'steps' list (got " +
                    YamlReader::Describe(root) + ")");
  }
  MissionHeader header;
  reader.Collect([&] { reader.ReadStruct(root, root.Mark(), "", header, {"steps", "vehicles"}); });
  engine::Mission mission;
  mission.name = header.name;
  mission.file = file;
  mission.randomize = header.randomize;
  mission.locate = [root, file](const std::string& key) {
    return YamlReader(file).Where(YamlReader::FindFieldMark(root, root.Mark(), key));
  };
  YAML::Node vehicles;
  YAML::Mark vehicles_mark;
  if (YamlReader::FindKey(root, "vehicles", &vehicles, &vehicles_mark)) {
    // The per-vehicle form: nothing of the single-vehicle form beside it.
    for (const char* single : {"vehicle", "steps"}) {
      YAML::Node value;
      YAML::Mark mark;
      if (YamlReader::FindKey(root, single, &value, &mark)) {
        reader.Fail(mark, single,
                    "a mission gives either 'vehicle' and 'steps' (one vehicle) or 'vehicles' (a "
                    "track per vehicle), not both");
      }
    }
    mission.tracks = ReadTracks(reader, vehicles, vehicles_mark, header);
  } else {
    engine::MissionTrack track;
    track.vehicle = header.vehicle;
    track.abort_on_collision = header.abort_on_collision;
    // Reported with the header's mistakes (an unknown key that was meant to be 'steps').
    reader.Collect([&] {
      track.steps = ReadSteps(reader, root, "",
                              "a mission needs a list of steps (or 'vehicles': a track of steps "
                              "per vehicle)");
    });
    track.file = file;
    YAML::Node value;
    YAML::Mark mark = root.Mark();
    YamlReader::FindKey(root, "vehicle", &value, &mark);
    track.where = reader.Where(mark);
    mission.tracks.push_back(std::move(track));
  }
  reader.state()->ThrowIfAny();
  engine::CheckMissionBarriers(mission);
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
