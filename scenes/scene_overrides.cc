#include "scenes/scene_overrides.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <iterator>
#include <optional>
#include <utility>

#include "scenes/scene_file.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

// One step of a key path: a map key, or a list index.
struct Step {
  std::string key;  // empty for an index
  std::size_t index = 0;
  bool is_index() const { return key.empty(); }
};

// "vehicles[0].start.position_ned_m" as steps; nullopt when it is not names joined by '.' with
// list entries as [N].
std::optional<std::vector<Step>> SplitKeyPath(const std::string& path) {
  std::vector<Step> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t end = i;
    while (end < path.size() &&
           (std::isalnum(static_cast<unsigned char>(path[end])) != 0 || path[end] == '_')) {
      ++end;
    }
    if (end == i) return std::nullopt;  // an empty name
    steps.push_back({path.substr(i, end - i), 0});
    i = end;
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return std::nullopt;
      const std::string digits = path.substr(i + 1, close - i - 1);
      if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
          digits.size() > 9) {
        return std::nullopt;
      }
      steps.push_back({"", static_cast<std::size_t>(std::stoul(digits))});
      i = close + 1;
    }
    if (i == path.size()) break;
    if (path[i] != '.' || i + 1 == path.size()) return std::nullopt;
    ++i;
  }
  if (steps.empty()) return std::nullopt;
  return steps;
}

std::string PathOf(const std::string& prefix, const Step& step) {
  return step.is_index() ? prefix + "[" + std::to_string(step.index) + "]"
                         : (prefix.empty() ? step.key : prefix + "." + step.key);
}

[[noreturn]] void Fail(const std::string& key_path, const std::string& problem) {
  throw ConfigError({}, key_path, problem);
}

// Puts `value` at `steps` below `node` (a handle into the document), `path` being node's key path.
// A null value removes the key, which the scene must set.
void SetNode(YAML::Node node, const std::vector<Step>& steps, std::size_t i,
             const YAML::Node& value, const std::string& path) {
  const Step& step = steps[i];
  const bool last = i + 1 == steps.size();
  const std::string here = PathOf(path, step);
  if (step.is_index()) {
    if (!node.IsSequence()) {
      Fail(path, "is not a list (it holds " + YamlReader::Describe(node) + "): no entry [" +
                     std::to_string(step.index) + "]");
    }
    if (step.index >= node.size()) {
      Fail(here, "no such entry (the list has " + std::to_string(node.size()) + ")");
    }
    if (!last) return SetNode(node[step.index], steps, i + 1, value, here);
    if (value.IsNull()) Fail(here, "a list entry cannot be removed (set the whole list instead)");
    node[step.index] = value;
    return;
  }
  const YAML::Node& read = node;  // const: looking a key up must not add it
  const bool present = node.IsMap() && read[step.key].IsDefined();
  if (value.IsNull() && !present) {
    Fail(here,
         "not set in the scene (null removes a key the scene sets, so that its default applies)");
  }
  if (!node.IsDefined() || node.IsNull()) {
    node = YAML::Node(YAML::NodeType::Map);  // `key:` with nothing after it means all defaults
  } else if (!node.IsMap()) {
    Fail(path, "holds " + YamlReader::Describe(node) + ", not a map of keys: it has no key '" +
                   step.key + "'");
  }
  if (!last) return SetNode(node[step.key], steps, i + 1, value, here);
  if (value.IsNull()) {
    node.remove(step.key);
  } else {
    node[step.key] = value;
  }
}

// A changed block or entry, read again (Validate included) once every override is in place, so that
// values valid only together (a larger area with a wider spacing) pass; and the overrides that
// changed it, in order.
struct PendingRead {
  const void* entry = nullptr;
  std::function<void()> read;
  std::vector<const SceneOverride*> overrides;
};
using PendingReads = std::vector<PendingRead>;

// Sets the override in `entry`, whose key path as the user addresses it is `entry_path`, and
// queues the changed entry to be read again.
template <class T>
AppliedSceneOverrides::Applied SetIn(Sourced<T>& entry, const std::string& entry_path,
                                     const std::vector<Step>& steps, std::size_t first,
                                     const YAML::Node& value, const SceneOverride& o,
                                     PendingReads& pending) {
  if (first == steps.size()) {
    entry.node.reset(value);  // the whole block or entry
  } else {
    SetNode(entry.node, steps, first, value, entry_path);
  }
  auto it = std::find_if(pending.begin(), pending.end(),
                         [&](const PendingRead& p) { return p.entry == &entry; });
  if (it == pending.end()) {
    pending.push_back(
        {&entry,
         [&entry, entry_path] {
           T config;
           YamlReader(entry.file->path).ReadValue(entry.node, entry.mark, entry_path, config);
           entry.config = std::move(config);
         },
         {}});
    it = std::prev(pending.end());
  }
  it->overrides.push_back(&o);
  return {o, entry.file->path, entry.key_path + o.key_path.substr(entry_path.size())};
}

// A settings block (`scene`, `ground`, `physics`): the one that wins, or a new one in the scene's
// own file when no file has it.
template <class T>
AppliedSceneOverrides::Applied SetInSettings(SceneDocument& doc, std::optional<Sourced<T>>& block,
                                             const std::string& key, const std::vector<Step>& steps,
                                             const YAML::Node& value, const SceneOverride& o,
                                             PendingReads& pending) {
  if (steps.size() > 1 && steps[1].is_index()) {
    Fail(key, "is a map, not a list: no entry [" + std::to_string(steps[1].index) + "]");
  }
  if (steps.size() == 1 && value.IsNull()) {
    if (!block) Fail(key, "not set in the scene (null removes a key the scene sets)");
    const std::string file = block->file->path;
    block.reset();
    return {o, file, key};
  }
  if (!block) {
    const std::shared_ptr<const SourceFile>& file = doc.files.front();
    block = Sourced<T>{T{}, file, key, YAML::Node(YAML::NodeType::Map), file->root.Mark(), 0};
  }
  return SetIn(*block, key, steps, 1, value, o, pending);
}

// An entry of a list (`vehicles[2]`), by its index among all the document's entries.
template <class T>
AppliedSceneOverrides::Applied SetInList(std::vector<Sourced<T>>& list, const std::string& key,
                                         const std::vector<Step>& steps, const YAML::Node& value,
                                         const SceneOverride& o, PendingReads& pending) {
  if (steps.size() < 2 || !steps[1].is_index()) {
    Fail(key, "is a list: name an entry by its index, e.g. " + key + "[0]." +
                  (steps.size() > 1 ? steps[1].key : std::string("...")));
  }
  const std::size_t index = steps[1].index;
  const std::string entry_path = PathOf(key, steps[1]);
  if (index >= list.size()) {
    Fail(entry_path, "no such entry (the scene has " + std::to_string(list.size()) + " in '" + key +
                         "', includes first)");
  }
  if (steps.size() == 2 && value.IsNull()) {
    Fail(entry_path, "an entry cannot be removed by an override");
  }
  return SetIn(list[index], entry_path, steps, 2, value, o, pending);
}

AppliedSceneOverrides::Applied ApplyOne(SceneDocument& doc, const SceneOverride& o,
                                        PendingReads& pending) {
  const std::vector<Step> steps = *SplitKeyPath(o.key_path);  // checked by ParseSceneOverride
  const YAML::Node value = YAML::Load(o.value);
  const std::string& key = steps.front().key;
  if (key == "scene") return SetInSettings(doc, doc.scene, key, steps, value, o, pending);
  if (key == "ground") return SetInSettings(doc, doc.ground, key, steps, value, o, pending);
  if (key == "physics") return SetInSettings(doc, doc.physics, key, steps, value, o, pending);
  if (key == "terrain") return SetInSettings(doc, doc.terrain, key, steps, value, o, pending);
  if (key == "classes") return SetInList(doc.classes, key, steps, value, o, pending);
  if (key == "objects") return SetInList(doc.objects, key, steps, value, o, pending);
  if (key == "generators") return SetInList(doc.generators, key, steps, value, o, pending);
  if (key == "vehicles") return SetInList(doc.vehicles, key, steps, value, o, pending);
  if (key == "include") {
    Fail(key, "cannot be overridden: a scene's includes are read before its overrides apply");
  }
  const std::vector<std::string> top = SceneFileKeys();
  std::string problem = "unknown key '" + key + "'";
  if (const auto close = engine::ClosestMatch(key, top)) {
    problem += " (did you mean '" + *close + "'?)";
  }
  Fail(key, problem);
}

bool AtOrBelow(const std::string& key_path, const std::string& prefix) {
  return key_path.rfind(prefix, 0) == 0 &&
         (key_path.size() == prefix.size() || key_path[prefix.size()] == '.' ||
          key_path[prefix.size()] == '[');
}

}  // namespace

SceneOverride ParseSceneOverride(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos) {
    throw ConfigError(
        {}, "--set",
        "expected KEY.PATH=VALUE, e.g. scene.lighting.sun_elevation_deg=20 (got '" + text + "')");
  }
  SceneOverride o;
  o.key_path = text.substr(0, equals);
  const auto fail = [&](const std::string& problem) {
    throw ConfigError({"--set " + text, 0, 0}, "", problem);
  };
  if (!SplitKeyPath(o.key_path)) {
    fail("'" + o.key_path +
         "' is not a key path: names joined by '.', list entries as [N], e.g. "
         "vehicles[0].start.position_ned_m");
  }
  YAML::Node value;
  try {
    value = YAML::Load(text.substr(equals + 1));
  } catch (const YAML::Exception& e) {
    fail("the value is not valid YAML (" + e.msg + ")");
  }
  if (value.IsMap())
    fail("the value is a map: set its keys one by one (" + o.key_path + ".KEY=VALUE)");
  if (value.IsNull()) {
    o.value = "null";
  } else {
    YAML::Emitter out;
    out << YAML::Flow << value;
    o.value = out.c_str();
  }
  return o;
}

std::vector<SceneOverride> ParseSceneOverrides(const std::vector<std::string>& texts) {
  std::vector<SceneOverride> out;
  for (const std::string& t : texts) out.push_back(ParseSceneOverride(t));
  std::sort(out.begin(), out.end(),
            [](const SceneOverride& a, const SceneOverride& b) { return a.key_path < b.key_path; });
  for (const SceneOverride& a : out) {
    for (const SceneOverride& b : out) {
      if (&a == &b || !AtOrBelow(b.key_path, a.key_path)) continue;
      throw ConfigError(
          {"--set " + b.text(), 0, 0}, b.key_path,
          a.key_path == b.key_path ? "set twice" : "inside '" + a.key_path + "', which is set too");
    }
  }
  return out;
}

std::vector<std::string> SceneOverrideTexts(const std::vector<SceneOverride>& overrides) {
  std::vector<std::string> texts;
  for (const SceneOverride& o : overrides) texts.push_back(o.text());
  return texts;
}

void AppliedSceneOverrides::Rethrow(const engine::ConfigError& error) const {
  for (auto it = applied_.rbegin(); it != applied_.rend(); ++it) {
    if (error.where().file == it->file && AtOrBelow(error.key_path(), it->file_key_path)) {
      throw ConfigError({"--set " + it->override.text(), 0, 0},
                        it->override.key_path + error.key_path().substr(it->file_key_path.size()),
                        error.problem());
    }
  }
  throw error;
}

AppliedSceneOverrides ApplySceneOverrides(SceneDocument* doc,
                                          const std::vector<SceneOverride>& overrides) {
  AppliedSceneOverrides applied;
  PendingReads pending;
  // Removals first (a removed key is never looked up by a later override).
  for (const bool removals : {true, false}) {
    for (const SceneOverride& o : overrides) {
      if ((o.value == "null") != removals) continue;
      try {
        applied.Add(ApplyOne(*doc, o, pending));
      } catch (const ConfigError& e) {
        throw ConfigError({"--set " + o.text(), 0, 0}, e.key_path(), e.problem());
      }
    }
  }
  for (const PendingRead& p : pending) {
    try {
      p.read();
    } catch (const ConfigError& e) {
      // The file was valid before: whatever the changed block's reader finds is an override's,
      // the one at or above the key in error, else the last that changed the block.
      const SceneOverride* blamed = p.overrides.back();
      for (const SceneOverride* o : p.overrides) {
        if (AtOrBelow(e.key_path(), o->key_path)) blamed = o;
      }
      throw ConfigError({"--set " + blamed->text(), 0, 0}, e.key_path(), e.problem());
    }
  }
  return applied;
}

}  // namespace airis::scenes
