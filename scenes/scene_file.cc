#include "scenes/scene_file.h"

#include <algorithm>
#include <filesystem>

namespace airis::scenes {

namespace fs = std::filesystem;

namespace {

/// Position of list entry `index` under top-level `key` of `root`.
YAML::Node EntryNode(const YAML::Node& root, const char* key, std::size_t index) {
  return root[key][index];
}

YAML::Mark KeyMark(const YAML::Node& root, const char* key) {
  for (const auto& entry : root) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) return entry.first.Mark();
  }
  return root.Mark();
}

template <class T>
void AppendEntries(const std::vector<T>& configs, const std::shared_ptr<const SourceFile>& file,
                   const char* key, std::vector<Sourced<T>>* out) {
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const YAML::Node node = EntryNode(file->root, key, i);
    out->push_back(Sourced<T>{configs[i], file, std::string(key) + "[" + std::to_string(i) + "]",
                              node, node.Mark(), static_cast<int>(i)});
  }
}

class DocumentReader {
 public:
  explicit DocumentReader(SceneDocument* doc)
      : doc_(doc), state_(std::make_shared<YamlReadState>(/*collect=*/true)) {}

  /// Reads one file (already parsed into `root`) and, first, everything it includes. Mistakes are
  /// collected; Finish() throws them.
  void Read(const std::string& path, const YAML::Node& root) {
    const std::string identity = Identity(path);
    stack_.push_back({path, identity});
    read_.push_back({identity, path});
    auto file = std::make_shared<SourceFile>(SourceFile{path, YAML::Node()});
    file->root.reset(root);
    doc_->files.push_back(file);

    SceneFileConfig config;
    const YamlReader reader(path, state_);
    const std::size_t errors_before = state_->errors().count();
    reader.Collect([&] { reader.ReadValue(root, root.Mark(), "", config); });
    // Includes of a file with mistakes could be misread (an entry left empty): read them once the
    // mistakes are fixed.
    if (state_->errors().count() == errors_before) {
      for (std::size_t i = 0; i < config.include.size(); ++i) {
        reader.Collect([&] { Include(reader, root, i, config.include[i]); });
      }
    }

    // Settings: the including file (read after its includes) overrides what they set.
    if (config.scene) {
      doc_->scene = Sourced<SceneSettingsConfig>{
          *config.scene, file, "scene", root["scene"], KeyMark(root, "scene"), 0};
    }
    if (config.ground) {
      doc_->ground = Sourced<GroundConfig>{*config.ground,          file, "ground", root["ground"],
                                           KeyMark(root, "ground"), 0};
    }
    if (config.terrain) {
      doc_->terrain = Sourced<TerrainConfig>{
          *config.terrain, file, "terrain", root["terrain"], KeyMark(root, "terrain"), 0};
    }
    if (config.physics) {
      doc_->physics = Sourced<engine::PhysicsConfig>{
          *config.physics, file, "physics", root["physics"], KeyMark(root, "physics"), 0};
    }
    AppendEntries(config.classes, file, "classes", &doc_->classes);
    AppendEntries(config.objects, file, "objects", &doc_->objects);
    AppendEntries(config.generators, file, "generators", &doc_->generators);
    AppendEntries(config.vehicles, file, "vehicles", &doc_->vehicles);
    stack_.pop_back();
  }

  /// Throws every mistake found in the files read.
  void Finish() const { state_->ThrowIfAny(); }

 private:
  struct Frame {
    std::string path;
    std::string identity;
  };

  /// Reads include `index` (`relative`) of the file `reader` reads: each file at most once (a file
  /// included twice would place its objects twice), within kMaxIncludeDepth and
  /// kMaxIncludedFiles.
  void Include(const YamlReader& reader, const YAML::Node& root, std::size_t index,
               const std::string& relative) {
    const YAML::Node node = root["include"][index];
    const std::string key = "include[" + std::to_string(index) + "]";
    const std::string child = ResolveRelative(reader.file(), relative);
    const std::string child_identity = Identity(child);
    for (std::size_t s = 0; s < stack_.size(); ++s) {
      if (stack_[s].identity != child_identity) continue;
      std::string chain;
      for (std::size_t k = s; k < stack_.size(); ++k) chain += stack_[k].path + " -> ";
      reader.Fail(node.Mark(), key, "include cycle: " + chain + child);
    }
    for (const auto& [identity, first_path] : read_) {
      if (identity == child_identity) {
        reader.Fail(node.Mark(), key,
                    "file " + child + " is already part of the scene (included before, as " +
                        first_path +
                        "); a file is included once, or its objects would be placed "
                        "twice");
      }
    }
    if (static_cast<int>(stack_.size()) >= engine::kMaxIncludeDepth) {
      reader.Fail(node.Mark(), key,
                  "includes nest deeper than the limit of " +
                      std::to_string(engine::kMaxIncludeDepth) + " files (docs/limits.md)");
    }
    if (read_.size() >= engine::kMaxIncludedFiles) {
      reader.Fail(node.Mark(), key,
                  "the scene includes more than the limit of " +
                      std::to_string(engine::kMaxIncludedFiles) + " files (docs/limits.md)");
    }
    if (!fs::exists(child)) reader.Fail(node.Mark(), key, "file not found: " + child);
    YAML::Node child_root;
    try {
      child_root = LoadYamlFile(child);
    } catch (const engine::ConfigError& e) {
      // A mistake inside the file is reported there; one with the file as a whole (a folder, too
      // large) where it is included.
      if (e.where().line > 0) throw;
      reader.Fail(node.Mark(), key, "cannot include " + child + ": " + e.problem());
    }
    Read(child, child_root);
  }

  static std::string Identity(const std::string& path) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    return ec ? fs::absolute(path).lexically_normal().string() : canonical.string();
  }

  SceneDocument* doc_;
  std::shared_ptr<YamlReadState> state_;
  std::vector<Frame> stack_;
  std::vector<std::pair<std::string, std::string>> read_;  // identity, path of every file read
};

}  // namespace

namespace {

// The keys a struct's Visit lists.
struct KeyNames {
  std::vector<std::string> names;
  template <class T>
  void Field(const char* key, T&, const char*) {
    names.emplace_back(key);
  }
  void Renamed(const char*, const char*) {}
};

}  // namespace

std::vector<std::string> SceneFileKeys() {
  KeyNames keys;
  SceneFileConfig{}.Visit(keys);
  return keys.names;
}

std::string ResolveRelative(const std::string& base_file, const std::string& relative) {
  const fs::path rel(relative);
  if (rel.is_absolute()) return rel.lexically_normal().string();
  return (fs::path(base_file).parent_path() / rel).lexically_normal().string();
}

void VehicleEntryConfig::Validate() const {
  engine::Require(!name.empty(), "name", "every vehicle needs a name");
  engine::RequireName("name", name);
  engine::Require(!preset.empty(), "preset", "every vehicle needs a preset");
  engine::Require(!overrides.IsDefined() || overrides.IsNull() || overrides.IsMap(), "overrides",
                  "expected a map of preset keys");
}

SceneDocument ReadSceneDocument(const std::string& path) {
  SceneDocument doc;
  doc.path = path;
  DocumentReader reader(&doc);
  reader.Read(path, LoadYamlFile(path));
  reader.Finish();
  return doc;
}

SceneDocument ReadSceneDocumentFromString(const std::string& text, const std::string& path) {
  SceneDocument doc;
  doc.path = path;
  DocumentReader reader(&doc);
  reader.Read(path, LoadYamlString(text, path));
  reader.Finish();
  return doc;
}

}  // namespace airis::scenes
