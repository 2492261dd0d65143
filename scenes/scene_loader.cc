// LoadScene: a SceneDocument (scene_file.h) turned into a Scene (scene.h): classes, ground,
// objects, meshes through assimp, generators, vehicles, then the whole-scene checks.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "engine/core/limits.h"
#include "engine/core/random.h"
#include "engine/environment/sun.h"
#include "engine/render/texture_file.h"
#include "engine/scene/static_scene_builder.h"
#include "engine/world/image_sensor.h"
#include "scenes/builtin_classes.h"
#include "scenes/generators.h"
#include "scenes/mesh_loader.h"
#include "scenes/object_capacity.h"
#include "scenes/scene.h"
#include "scenes/scene_file.h"
#include "scenes/scene_overrides.h"
#include "scenes/terrain.h"
#include "scenes/vehicle_kinds.h"

namespace airis::scenes {

namespace fs = std::filesystem;
using engine::DegToRad;

namespace {

std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i > 0 ? ", " : "") + names[i];
  return out;
}

engine::Material ToMaterial(const MaterialConfig& c, const std::string& texture_path) {
  engine::Material m;
  m.base_color_rgb = c.color.cast<float>();
  m.texture_path = texture_path;
  m.roughness = static_cast<float>(c.roughness);
  m.metallic = static_cast<float>(c.metallic);
  m.pattern = c.pattern;
  m.pattern_size_m = c.pattern_size_m.cast<float>();
  m.restitution = static_cast<float>(c.restitution);
  m.friction = static_cast<float>(c.friction);
  return m;
}

// Folders of a dataset that no camera may be named after (docs/dataset-format.md).
constexpr const char* kReservedStreamNames[] = {"tartanair", "shards", "slurm"};

class SceneAssembler {
 public:
  SceneAssembler(SceneDocument doc, const SceneLoadOptions& options)
      : doc_(std::move(doc)), options_(options), capacity_(options.memory_limit_bytes) {
    builder_.LimitInstances(capacity_.max_instances());
  }

  Scene Assemble() {
    Scene s;
    s.path = doc_.path;
    for (const auto& f : doc_.files) s.files.push_back(f->path);
    SceneSettingsConfig settings;
    if (doc_.scene) settings = doc_.scene->config;
    s.name = settings.name;
    // The seed replaces the file's before anything draws from it (generators, then sensors).
    s.seed = options_.seed.value_or(settings.seed);
    s.origin = {DegToRad(settings.origin.latitude_deg), DegToRad(settings.origin.longitude_deg),
                settings.origin.altitude_m};
    s.environment = settings.environment;
    if (doc_.physics) s.physics = doc_.physics->config;

    // Independent entries are checked one by one and their mistakes reported together; objects
    // and generators name classes, so those come first.
    engine::ErrorCollector errors;
    for (const auto& c : doc_.classes) errors.Try([&] { DefineClass(c); });
    errors.ThrowIfAny();
    builder_.scene().lighting = MakeLighting(settings, s.origin.latitude_rad);
    s.sun = sun_;
    GroundConfig ground;
    if (doc_.ground) ground = doc_.ground->config;
    const engine::RandomStreams streams(s.seed);
    if (doc_.terrain) {
      // Terrain replaces the ground plane (its lowest point is at z = 0).
      if (doc_.ground && ground.enabled) {
        errors.Try([&] {
          doc_.ground->Fail("enabled",
                            "a scene with `terrain` has no ground plane (the terrain "
                            "is the ground); remove `ground` or set enabled: false");
        });
      }
      ground.enabled = false;
      errors.Try([&] { AddTerrainBlock(*doc_.terrain, streams, s.origin); });
      s.terrain_settings = DescribeTerrain(doc_.terrain->config);
    }
    s.has_ground = ground.enabled;
    if (ground.enabled) errors.Try([&] { AddGround(ground); });
    for (const auto& o : doc_.objects) errors.Try([&] { AddObjects(o); });
    for (const auto& g : doc_.generators) {
      errors.Try([&] { s.generated.push_back(Generate(g, streams)); });
    }
    for (const auto& v : doc_.vehicles) {
      errors.Try([&] { s.vehicles.push_back(AddVehicle(v, s.vehicles, ground.enabled)); });
    }
    errors.ThrowIfAny();
    CheckDatasetCameraNames(s.vehicles);
    // The vehicles' looks take the instance ids after every object's, in vehicle order.
    for (std::size_t i = 0; i < s.vehicles.size(); ++i)
      AddVehicleBody(doc_.vehicles[i], s.vehicles[i]);
    s.static_scene = std::make_shared<const engine::StaticScene>(builder_.Finish());
    s.files.insert(s.files.end(), inputs_.begin(), inputs_.end());
    return s;
  }

 private:
  void DefineClass(const Sourced<ClassConfig>& c) {
    // A second definition would silently win over the first.
    if (const auto it = defined_classes_.find(c.config.name); it != defined_classes_.end()) {
      c.Fail("name", "class '" + c.config.name + "' is already defined (" + Describe(*it->second) +
                         "); define each class once");
    }
    defined_classes_.emplace(c.config.name, &c);
    const Eigen::Vector3f color =
        c.config.color ? Eigen::Vector3f(c.config.color->cast<float>()) : Eigen::Vector3f::Zero();
    const bool* stuff = c.config.stuff ? &*c.config.stuff : nullptr;
    if (builder_.DefineClass(c.config.name, c.config.id, c.config.color ? &color : nullptr, stuff))
      return;
    for (const auto& known : builder_.scene().classes) {
      if (known.id == c.config.id) {
        c.Fail("id",
               "id " + std::to_string(c.config.id) + " is already class '" + known.name + "'");
      }
    }
    c.Fail("name", "no free class id left (255 classes at most)");
  }

  engine::SceneLighting MakeLighting(const SceneSettingsConfig& settings, double latitude_rad) {
    const LightingConfig& c = settings.lighting;
    engine::SceneLighting out;
    sun_.time_of_day_h = c.time_of_day_h;
    double azimuth_deg = c.sun_azimuth_deg.value_or(LightingConfig::kDefaultSunAzimuth_deg);
    double elevation_deg = c.sun_elevation_deg.value_or(LightingConfig::kDefaultSunElevation_deg);
    out.solar_place = {engine::RadToDeg(latitude_rad), settings.environment.date_decimal_year};
    if (c.time_of_day_h) {
      engine::CalcSolarAngles(out.solar_place.latitude_deg, out.solar_place.decimal_year,
                              *c.time_of_day_h, azimuth_deg, elevation_deg);
    }
    sun_.azimuth_rad = DegToRad(azimuth_deg);
    sun_.elevation_rad = DegToRad(elevation_deg);
    out.sun_direction_W = engine::CalcSunDirection_W(azimuth_deg, elevation_deg);
    out.sun_color_rgb = c.sun_color.cast<float>();
    out.sky_zenith_rgb = c.sky_zenith_color.cast<float>();
    out.sky_horizon_rgb = c.sky_horizon_color.cast<float>();
    out.ambient = static_cast<float>(c.ambient);
    out.fog_distance_m = static_cast<float>(c.CalcFogDistance_m());
    out.fog_height_m = static_cast<float>(c.fog_height_m);
    out.sky = c.sky;
    out.turbidity = static_cast<float>(c.turbidity);
    out.rain_mm_per_h = static_cast<float>(c.rain_mm_per_h);
    out.shadows.enabled = c.shadows.enabled;
    out.shadows.distance_m = static_cast<float>(c.shadows.distance_m);
    out.shadows.map_size_px = c.shadows.map_size_px;
    return out;
  }

  /// Id of class `name` named by `key` of `entry`, or a ConfigError listing the known classes.
  template <class T>
  std::uint8_t ClassOf(const Sourced<T>& entry, const std::string& key,
                       const std::string& name) const {
    const std::uint8_t id = builder_.ClassId(name);
    if (id != engine::kNoClass) return id;
    const std::vector<std::string> names = builder_.ClassNames();
    std::string problem = "unknown class '" + name + "'";
    if (const auto close = engine::ClosestMatch(name, names))
      problem += " (did you mean '" + *close + "'?)";
    problem += "; known classes: " + JoinNames(names) + "; add new ones under `classes:`";
    entry.Fail(key, problem);
  }

  /// Absolute path of a texture named by `key`, or a ConfigError with the resolved path.
  template <class T>
  std::string TexturePath(const Sourced<T>& entry, const std::string& key,
                          const std::string& texture) const {
    if (texture.empty()) return "";
    const std::string resolved = ResolveRelative(entry.file->path, texture);
    if (fs::is_directory(resolved)) {
      entry.Fail(key, "texture " + resolved + " is a folder, not an image file");
    }
    if (!fs::is_regular_file(resolved)) entry.Fail(key, "texture file not found: " + resolved);
    // Decoded once here, as the renderer will, so that `scene check` finds what a run would.
    if (NoteInput(resolved)) {
      const std::string problem = engine::CheckTextureFile(resolved);
      if (!problem.empty()) entry.Fail(key, "texture " + resolved + ": " + problem);
    }
    return fs::absolute(resolved).string();
  }

  /// Model of a mesh file named by `key` (loaded once per file and axes).
  template <class T>
  std::uint32_t MeshModel(const Sourced<T>& entry, const std::string& key, const std::string& mesh,
                          MeshAxes axes) {
    const std::string resolved = ResolveRelative(entry.file->path, mesh);
    const auto cache_key = std::make_pair(resolved, static_cast<int>(axes));
    if (const auto it = mesh_models_.find(cache_key); it != mesh_models_.end()) return it->second;
    if (fs::is_directory(resolved)) {
      entry.Fail(key, "mesh " + resolved + " is a folder, not a mesh file");
    }
    if (!fs::is_regular_file(resolved)) entry.Fail(key, "mesh file not found: " + resolved);
    MeshFile file;
    try {
      file = LoadMeshFile(resolved, axes);
    } catch (const MeshLoadError& e) {
      entry.Fail(key, "cannot load mesh " + resolved + ": " + e.what());
    }
    NoteInput(resolved);
    for (const auto& m : file.materials) {
      if (!m.texture_path.empty() && file.images.count(m.texture_path) == 0) {
        NoteInput(m.texture_path);
      }
    }
    for (auto& [name, image] : file.images) {
      builder_.scene().embedded_images.emplace(name, std::move(image));
    }
    std::size_t triangles = 0;
    for (const auto& mesh : file.meshes) triangles += mesh.triangle_count();
    if (stored_triangles_ + triangles > engine::kMaxSceneTriangles) {
      entry.Fail(key, "mesh " + resolved + " adds " + std::to_string(triangles) +
                          " triangles to the scene's " + std::to_string(stored_triangles_) +
                          ", more than the limit of " + std::to_string(engine::kMaxSceneTriangles) +
                          " (docs/limits.md)");
    }
    stored_triangles_ += triangles;
    engine::Model model;
    model.name = resolved;
    std::vector<std::uint32_t> materials;
    for (const auto& m : file.materials) materials.push_back(builder_.Material(m));
    for (auto& part : file.parts) {
      model.parts.push_back({builder_.AddMesh(std::move(file.meshes[part.mesh])),
                             materials[part.material], Eigen::Affine3f::Identity()});
    }
    const std::uint32_t index = builder_.AddModel(std::move(model));
    mesh_models_.emplace(cache_key, index);
    return index;
  }

  void AddGround(const GroundConfig& g) {
    static const Sourced<GroundConfig> kDefault;
    const Sourced<GroundConfig>& entry = doc_.ground ? *doc_.ground : kDefault;
    const std::uint8_t cls =
        doc_.ground ? ClassOf(entry, "class", g.class_name) : builder_.ClassId(g.class_name);
    const std::string texture =
        doc_.ground ? TexturePath(entry, "material.texture", g.material.texture) : "";
    const auto material =
        static_cast<std::int32_t>(builder_.Material(ToMaterial(g.material, texture)));
    builder_.AddObject(
        builder_.PrimitiveModel(engine::Primitive::kPlane),
        engine::MakePose(Vec3::Zero(), 0, 0, 0, Vec3(g.size_m.x(), g.size_m.y(), 1.0)), cls,
        engine::CollisionShape::kAuto, "ground", material);
  }

  void AddTerrainBlock(const Sourced<TerrainConfig>& entry, const engine::RandomStreams& streams,
                       const engine::GeodeticPosition& origin) {
    const TerrainConfig& c = entry.config;
    const std::uint8_t cls = ClassOf(entry, "class", c.class_name);
    engine::RandomStream stream = streams.Stream("terrain");
    if (c.dem.empty() && entry.node["heights"]) {
      entry.Fail("heights",
                 "applies to a `dem` only (generated hills start at the origin's altitude)");
    }
    engine::Heightfield field = c.dem.empty() ? GenerateTerrain(c, stream) : LoadDem(entry, origin);
    // Each city stands on a terrace levelled under its area before the terrain is chunked.
    for (const auto& g : doc_.generators) {
      if (!g.config.city) continue;
      const CityConfig& city = *g.config.city;
      Eigen::Vector2d lo, hi;
      CalcAreaBounds(city.area, &lo, &hi);
      const TerraceResult terrace = LevelTerrain(lo, hi, &field);
      const double span_m = terrace.highest_m - terrace.lowest_m;
      if (span_m > city.max_level_change_m) {
        g.Fail("city.area", "the terrain under the city spans " + engine::FormatRounded(span_m) +
                                " m of height (" + engine::FormatRounded(terrace.lowest_m) +
                                " to " + engine::FormatRounded(terrace.highest_m) +
                                " m), more than city.max_level_change_m = " +
                                engine::FormatNumber(city.max_level_change_m) +
                                " m: the ground is too steep to level for it (move the city to "
                                "flatter ground, make it smaller or raise the limit)");
      }
      city_levels_m_[&g] = terrace.height_m;
    }
    const std::size_t triangles =
        2 * static_cast<std::size_t>(field.rows() - 1) * static_cast<std::size_t>(field.cols() - 1);
    if (stored_triangles_ + triangles > engine::kMaxSceneTriangles) {
      entry.Fail("resolution_m", "the terrain's " + std::to_string(triangles) +
                                     " triangles exceed the scene's limit of " +
                                     std::to_string(engine::kMaxSceneTriangles) +
                                     " (docs/limits.md)");
    }
    stored_triangles_ += triangles;
    if (!AddTerrain(c, std::move(field), cls, builder_)) {
      entry.Fail("", capacity_.DescribeFull("objects"));
    }
  }

  /// The heights of a `terrain` block with `dem` (docs/terrain.md, "Elevation models").
  engine::Heightfield LoadDem(const Sourced<TerrainConfig>& entry,
                              const engine::GeodeticPosition& origin) const {
    const TerrainConfig& c = entry.config;
    const auto given = [&](const char* key) { return static_cast<bool>(entry.node[key]); };
    for (const char* key : kGeneratedTerrainKeys) {
      if (given(key)) {
        entry.Fail(key, std::string("is a setting of generated hills, but this terrain's heights "
                                    "come from `dem`: remove one of the two"));
      }
    }
    if (given("center_ne_m") && !given("extent_ne_m")) {
      entry.Fail("center_ne_m",
                 "with `dem`, a centre crops only with `extent_ne_m` (without either the terrain "
                 "is all the DEM covers)");
    }
    DemSampling sampling;
    sampling.path = ResolveRelative(entry.file->path, c.dem);
    if (given("heights")) sampling.heights = c.heights;
    if (given("extent_ne_m")) sampling.extent_m = c.extent_m;
    sampling.center_m = c.center_m;
    if (given("resolution_m")) sampling.resolution_m = c.resolution_m;
    NoteInput(sampling.path);
    try {
      return LoadDemTerrain(sampling, engine::LocalNedFrame(origin));
    } catch (const engine::InvalidField& e) {
      entry.Fail(e.field(), e.problem());
    }
  }

  void AddObjects(const Sourced<ObjectConfig>& entry) {
    const ObjectConfig& c = entry.config;
    if (!c.name.empty()) {
      // Names given by hand identify an object (annotations, collision events): one each.
      const auto [it, added] = named_objects_.emplace(c.name, &entry);
      if (!added) {
        entry.Fail("name", "object name '" + c.name + "' is already used (" +
                               Describe(*it->second) + "); give each object its own name");
      }
    }
    const std::uint8_t cls = ClassOf(entry, "class", c.class_name);
    const engine::Heightfield* terrain = builder_.scene().terrain.heightfield.get();
    if (c.on_terrain && terrain == nullptr) {
      entry.Fail("on_terrain", "the scene has no `terrain` to place the object on");
    }
    const RepeatConfig& r = c.repeat;
    // Checked before anything is placed or reserved: how many copies, and where the last ones go.
    const std::uint64_t copies = static_cast<std::uint64_t>(r.count) * r.rows;
    if (const std::string shortfall =
            capacity_.DescribeShortfall(copies, builder_.scene().objects.size());
        !shortfall.empty()) {
      entry.Fail(r.count > 1 || r.rows > 1 ? "repeat" : "", shortfall);
    }
    for (const int row : {0, r.rows - 1}) {
      for (const int i : {0, r.count - 1}) {
        const Vec3 p = c.position_m + i * r.step_m + row * r.row_step_m;
        if (p.norm() > engine::kMaxCoordinate_m) {
          entry.Fail("repeat", "copy " + std::to_string(i) + " of row " + std::to_string(row) +
                                   " lands " + engine::FormatRounded(p.norm()) +
                                   " m from the origin, beyond the limit of " +
                                   engine::FormatNumber(engine::kMaxCoordinate_m) +
                                   " m (docs/limits.md)");
        }
      }
    }
    std::uint32_t model = 0;
    std::string base = c.name;
    if (!c.mesh.empty()) {
      model = MeshModel(entry, "mesh", c.mesh, c.mesh_axes);
      if (base.empty()) base = engine::SanitizeName(fs::path(c.mesh).stem().string());
    } else {
      model = builder_.PrimitiveModel(c.primitive);
      if (base.empty()) base = std::string(engine::ToString(c.primitive));
    }
    std::int32_t material = -1;
    if (c.material) {
      material = static_cast<std::int32_t>(builder_.Material(
          ToMaterial(*c.material, TexturePath(entry, "material.texture", c.material->texture))));
    }
    builder_.ReserveObjects(copies);
    for (int row = 0; row < r.rows; ++row) {
      for (int i = 0; i < r.count; ++i) {
        Vec3 p = c.position_m + i * r.step_m + row * r.row_step_m;
        if (c.on_terrain) p.z() -= terrain->CalcHeight_m(p.x(), p.y());
        std::string name = base;
        if (r.rows > 1) name += "_" + std::to_string(row);
        if (r.count > 1 || r.rows > 1) name += "_" + std::to_string(i);
        const Eigen::Affine3d T = engine::MakePose(p, DegToRad(c.yaw_deg), DegToRad(c.pitch_deg),
                                                   DegToRad(c.roll_deg), c.scale);
        AIRIS_DEMAND(builder_.AddObject(model, T, cls, c.collision, std::move(name), material));
      }
    }
  }

  GeneratedSummary Generate(const Sourced<GeneratorConfig>& entry,
                            const engine::RandomStreams& streams) {
    const GeneratorConfig& g = entry.config;
    GeneratedSummary summary;
    summary.kind = g.city ? "city" : "forest";
    const std::string& given = g.city ? g.city->name : g.forest->name;
    summary.name = !given.empty() ? given
                                  : fs::path(entry.file->path).stem().string() + "/" +
                                        summary.kind + std::to_string(entry.index_in_file);
    // Two generators of one name would draw the same random stream and name their objects alike.
    if (const auto [it, added] = generator_names_.emplace(summary.name, &entry); !added) {
      entry.Fail(given.empty() ? summary.kind : summary.kind + ".name",
                 "generator name '" + summary.name + "' is already used (" + Describe(*it->second) +
                     "); name each generator differently");
    }
    engine::RandomStream stream = streams.Stream("generators/" + summary.name);
    GeneratorReport report;
    if (g.city) {
      const CityConfig& c = *g.city;
      CityResources r;
      r.building_class = ClassOf(entry, "city.building_class", c.building_class);
      r.road_class = ClassOf(entry, "city.road_class", c.road_class);
      r.sidewalk_class = ClassOf(entry, "city.sidewalk_class", c.sidewalk_class);
      r.lamp_class = ClassOf(entry, "city.lamp_class", c.lamp_class);
      r.car_class = ClassOf(entry, "city.car_class", c.car_class);
      if (!c.car_mesh.empty())
        r.car_model = MeshModel(entry, "city.car_mesh", c.car_mesh, c.car_mesh_axes);
      const std::size_t first = builder_.scene().objects.size();
      report = GenerateCity(c, r, summary.name, stream, builder_);
      // On terrain: up onto its terrace.
      if (const auto level = city_levels_m_.find(&entry); level != city_levels_m_.end()) {
        auto& objects = builder_.scene().objects;
        for (std::size_t i = first; i < objects.size(); ++i) {
          objects[i].T_WO.translation().z() -= level->second;
        }
      }
    } else {
      const ForestConfig& f = *g.forest;
      ForestResources r;
      r.tree_class = ClassOf(entry, "forest.tree_class", f.tree_class);
      r.bush_class = ClassOf(entry, "forest.ground_cover.class", f.ground_cover.class_name);
      r.terrain = builder_.scene().terrain.heightfield.get();
      report = GenerateForest(f, r, summary.name, stream, builder_);
    }
    if (report.out_of_instance_ids) {
      entry.Fail(summary.kind, capacity_.DescribeFull("objects"));
    }
    summary.objects = report.objects;
    summary.buildings = report.buildings;
    summary.trees = report.trees;
    summary.bushes = report.bushes;
    return summary;
  }

  /// The names datasets give image streams (engine::CalcDatasetNamePrefixes: a name another
  /// vehicle also uses is prefixed with the vehicle's) are unique in the scene.
  void CheckDatasetCameraNames(const std::vector<VehicleDescription>& vehicles) const {
    struct Owner {
      std::size_t vehicle = 0;
      std::size_t sensor = 0;
    };
    std::vector<engine::ImageSensorNames> sensors;
    std::vector<Owner> owners;
    for (std::size_t v = 0; v < vehicles.size(); ++v) {
      for (std::size_t i = 0; i < vehicles[v].sensors.size(); ++i) {
        const SensorDescription& s = vehicles[v].sensors[i];
        std::vector<std::string> streams = s.spec->ImageStreamNames(s.name);
        if (streams.empty()) continue;
        sensors.push_back({vehicles[v].name, s.name, std::move(streams)});
        owners.push_back({v, i});
      }
    }
    const std::vector<std::string> prefixes = engine::CalcDatasetNamePrefixes(sensors);
    struct Taken {
      std::string name;    // in datasets
      std::string stream;  // on its vehicle
      std::size_t sensor;  // index in `sensors`
    };
    std::vector<Taken> taken;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
      for (const std::string& stream : sensors[k].streams) {
        const std::string name = prefixes[k] + stream;
        for (const Taken& t : taken) {
          if (t.name != name) continue;
          doc_.vehicles[owners[k].vehicle].Fail(
              "sensors[" + std::to_string(owners[k].sensor) + "].name",
              "camera '" + stream + "' and camera '" + t.stream + "' of vehicle '" +
                  sensors[t.sensor].vehicle + "' would share the dataset name '" + name +
                  "' (a camera name that several vehicles use becomes <vehicle>_<camera>); "
                  "rename one");
        }
        taken.push_back({name, stream, k});
      }
    }
  }

  VehicleDescription AddVehicle(const Sourced<VehicleEntryConfig>& entry,
                                const std::vector<VehicleDescription>& earlier,
                                bool has_ground) const {
    const VehicleEntryConfig& c = entry.config;
    for (const auto& other : earlier) {
      if (other.name == c.name) {
        entry.Fail("name", "duplicate vehicle name '" + c.name + "' (also " + other.key_path +
                               " at " + other.where.file + ":" + std::to_string(other.where.line) +
                               ")");
      }
    }
    VehicleDescription v;
    v.name = c.name;
    v.kind = c.kind;
    v.preset = c.preset;
    v.start.p_W = c.start.position_m;
    v.start.q_WB = engine::QuatFromEuler(
        {DegToRad(c.start.roll_deg), DegToRad(c.start.pitch_deg), DegToRad(c.start.yaw_deg)});
    v.start.v_W = c.start.velocity_ned_m_s;
    v.start.w_B = c.start.angular_velocity_frd_rad_s;
    v.on_ground = c.start.on_ground;
    v.where = entry.Where();
    v.key_path = entry.key_path;
    v.locate = [entry](const std::string& key) { return entry.Where(key); };
    v.spec = ReadVehicleSpec(entry);
    v.autopilot = c.autopilot;
    CheckAutopilot(entry, *v.spec, earlier);
    for (std::size_t i = 0; i < c.sensors.size(); ++i) {
      const SensorEntry& e = c.sensors[i];
      for (const auto& other : v.sensors) {
        if (other.name == e.name) {
          entry.Fail("sensors[" + std::to_string(i) + "]", "duplicate sensor name '" + e.name +
                                                               "' on vehicle '" + c.name +
                                                               "' (name one with `name:`)");
        }
      }
      v.sensors.push_back({e.name, e.spec});
      // Image streams become dataset folders: their names are unique on the vehicle and are none
      // of the dataset's own folders (CheckDatasetCameraNames: and unique in the scene).
      for (const std::string& stream : e.spec->ImageStreamNames(e.name)) {
        const std::string key = "sensors[" + std::to_string(i) + "].name";
        for (const char* reserved : kReservedStreamNames) {
          if (stream == reserved) {
            entry.Fail(key, "camera '" + stream + "' would share its folder with the dataset's '" +
                                reserved + "/' (name it otherwise)");
          }
        }
        for (const auto& s : v.sensors) {
          if (&s == &v.sensors.back()) break;
          for (const std::string& taken : s.spec->ImageStreamNames(s.name)) {
            if (taken == stream) {
              entry.Fail(key, "camera '" + stream + "' is also the name of an image of sensor '" +
                                  s.name + "' on vehicle '" + c.name + "'");
            }
          }
        }
      }
    }
    if (has_ground && !v.on_ground) {
      // The body box, not only its centre, must be above the ground (it may touch it).
      const engine::Vec3 half = 0.5 * v.spec->CalcRigidBodyConfig().box_size_m;
      const engine::Mat3 R = v.start.q_WB.toRotationMatrix();
      const double lowest_z = v.start.p_W.z() + R.row(2).cwiseAbs().dot(half);
      if (lowest_z > kStartTolerance_m) {
        entry.Fail(
            "start.position_ned_m",
            "vehicle '" + c.name + "' starts " + engine::FormatRounded(lowest_z) +
                " m into the ground (its body box reaches z = " + engine::FormatRounded(lowest_z) +
                " m; NED z is down, so heights are negative; or set start.on_ground)");
      }
    }
    if (const engine::Heightfield* terrain = builder_.scene().terrain.heightfield.get();
        terrain != nullptr && !v.on_ground) {
      // The body box's lowest corner against the terrain under the centre (the box is small
      // beside a cell of terrain).
      const engine::Vec3 half = 0.5 * v.spec->CalcRigidBodyConfig().box_size_m;
      const engine::Mat3 R = v.start.q_WB.toRotationMatrix();
      const double lowest_z = v.start.p_W.z() + R.row(2).cwiseAbs().dot(half);
      const double surface_z = -terrain->CalcHeight_m(v.start.p_W.x(), v.start.p_W.y());
      if (lowest_z > surface_z + kStartTolerance_m) {
        entry.Fail(
            "start.position_ned_m",
            "vehicle '" + c.name + "' starts " + engine::FormatRounded(lowest_z - surface_z) +
                " m into the terrain (its surface is at z = " + engine::FormatRounded(surface_z) +
                " m there; set start.on_ground to "
                "start on it)");
      }
    }
    const double speed = v.start.v_W.norm();
    if (speed >= physics_max_speed_m_s_) {
      entry.Fail("start.velocity_ned_m_s", "a start speed of " + engine::FormatNumber(speed) +
                                               " m/s is at or above physics.max_speed_m_s (" +
                                               engine::FormatNumber(physics_max_speed_m_s_) +
                                               " m/s), where the run stops");
    }
    return v;
  }

  /// The look of vehicle `v` (its `body` block): its mesh file, or a body generated from its
  /// airframe.
  void AddVehicleBody(const Sourced<VehicleEntryConfig>& entry, const VehicleDescription& v) {
    const BodyConfig& c = entry.config.body;
    const std::uint8_t cls = ClassOf(entry, "body.class", c.class_name);
    std::int32_t material = -1;
    std::uint32_t model = 0;
    if (!c.mesh.empty()) {
      model = MeshModel(entry, "body.mesh", c.mesh, c.mesh_axes);
      if (c.color) {
        engine::Material m;
        m.base_color_rgb = c.color->cast<float>();
        material = static_cast<std::int32_t>(builder_.Material(m));
      }
    } else {
      std::unique_ptr<engine::Vehicle> vehicle;
      try {
        vehicle = v.spec->Build(v.name);
      } catch (const engine::InvalidField& e) {
        entry.Fail(e.field(), e.problem());
      }
      model = GenerateBodyModel(*vehicle, c.color.value_or(kDefaultBodyColor),
                                c.rotor_color.value_or(kDefaultRotorColor), builder_);
    }
    if (!builder_.AddVehicleBody(model, c.CalcModelPose(), cls, v.name, material)) {
      entry.Fail("body", capacity_.DescribeFull("objects and vehicles"));
    }
  }

  /// An `autopilot:` block that fits its vehicle (a channel per actuator) and uses its own PX4
  /// instance (ports).
  void CheckAutopilot(const Sourced<VehicleEntryConfig>& entry, const VehicleSpec& spec,
                      const std::vector<VehicleDescription>& earlier) const {
    const engine::mavlink::AutopilotConfig& a = entry.config.autopilot;
    if (a.kind != engine::mavlink::AutopilotKind::kPx4) return;
    try {
      // HIL_SENSOR messages carry the sensors' samples: at most one per physics tick.
      engine::RequireRate("sensor_rate_hz", a.sensor_rate_hz, physics_rate_hz_);
    } catch (const engine::InvalidField& e) {
      entry.Fail("autopilot.sensor_rate_hz", e.problem());
    }
    const std::vector<int>& map = a.motor_map;
    if (!map.empty()) {
      const int actuators = spec.Build(entry.config.name)->actuator_count();
      if (static_cast<int>(map.size()) != actuators) {
        entry.Fail("autopilot.motor_map",
                   "has " + std::to_string(map.size()) + " channels but the vehicle has " +
                       std::to_string(actuators) + " actuators (one PX4 output per actuator)");
      }
      for (std::size_t i = 0; i < map.size(); ++i) {
        if (std::count(map.begin(), map.begin() + static_cast<std::ptrdiff_t>(i), map[i]) > 0) {
          entry.Fail("autopilot.motor_map[" + std::to_string(i) + "]",
                     "channel " + std::to_string(map[i]) + " drives two actuators");
        }
      }
    }
    for (const auto& other : earlier) {
      if (other.autopilot.kind == engine::mavlink::AutopilotKind::kPx4 &&
          other.autopilot.instance == a.instance) {
        entry.Fail("autopilot.instance", "PX4 instance " + std::to_string(a.instance) +
                                             " also flies vehicle '" + other.name +
                                             "' (each vehicle needs its own instance and ports)");
      }
    }
  }

  /// The kind's config: its preset with `overrides` read over it (only the keys given change).
  static std::shared_ptr<const VehicleSpec> ReadVehicleSpec(
      const Sourced<VehicleEntryConfig>& entry) {
    const VehicleEntryConfig& c = entry.config;
    const VehicleKind* kind = FindVehicleKind(c.kind);
    if (!kind) {
      std::vector<std::string> names;
      for (const VehicleKind& k : VehicleKinds()) names.emplace_back(k.name);
      std::string problem = "unknown vehicle kind '" + c.kind + "'";
      if (const auto close = engine::ClosestMatch(c.kind, names))
        problem += " (did you mean '" + *close + "'?)";
      entry.Fail("kind", problem + "; kinds: " + JoinNames(names));
    }
    const vehicles::PresetFile* preset = FindPreset(*kind, c.preset);
    if (!preset) {
      std::vector<std::string> names;
      for (const vehicles::PresetFile& p : kind->presets) names.emplace_back(p.name);
      std::string problem = "unknown preset '" + c.preset + "'";
      if (const auto close = engine::ClosestMatch(c.preset, names))
        problem += " (did you mean '" + *close + "'?)";
      entry.Fail("preset", problem + "; presets: " + JoinNames(names));
    }
    return kind->read(*preset, YamlReader(entry.file->path), c.overrides, entry.MarkOf("overrides"),
                      entry.PathOf("overrides"));
  }

  /// Records a mesh or texture file the scene reads (once, in the order of first use); true when it
  /// is new.
  bool NoteInput(const std::string& path) const {
    if (!input_set_.insert(path).second) return false;
    inputs_.push_back(path);
    return true;
  }

  /// "file:line" of an entry, for messages that point at two.
  template <class T>
  static std::string Describe(const Sourced<T>& entry) {
    const engine::SourceLocation w = entry.Where();
    return entry.key_path + " at " + w.file + ":" + std::to_string(w.line);
  }

  // A start may touch a surface; deeper than this into one is overlapping it.
  static constexpr double kStartTolerance_m = 1e-3;

  SceneDocument doc_;
  SceneLoadOptions options_;
  ObjectCapacity capacity_;
  double physics_max_speed_m_s_ =
      doc_.physics ? doc_.physics->config.max_speed_m_s : engine::PhysicsConfig{}.max_speed_m_s;
  double physics_rate_hz_ =
      doc_.physics ? doc_.physics->config.rate_hz : engine::PhysicsConfig{}.rate_hz;
  mutable std::vector<std::string> inputs_;  // mesh and texture files, for Scene::files
  mutable std::set<std::string> input_set_;
  std::map<std::string, const Sourced<ClassConfig>*> defined_classes_;
  std::map<std::string, const Sourced<ObjectConfig>*> named_objects_;
  std::map<std::string, const Sourced<GeneratorConfig>*> generator_names_;
  std::size_t stored_triangles_ = 0;
  std::map<const Sourced<GeneratorConfig>*, double> city_levels_m_;  // terraces on terrain (m, up)
  engine::StaticSceneBuilder builder_{BuiltInClasses()};
  std::map<std::pair<std::string, int>, std::uint32_t> mesh_models_;
  SunPosition sun_;  // set by MakeLighting
};

}  // namespace

namespace {

// The document with the options' overrides applied, assembled; an error that an override's value
// causes while assembling (a vehicle moved into a building) names the override.
Scene Load(SceneDocument doc, const SceneLoadOptions& options) {
  const AppliedSceneOverrides applied = ApplySceneOverrides(&doc, options.overrides);
  try {
    Scene s = SceneAssembler(std::move(doc), options).Assemble();
    s.overrides = options.overrides;
    s.applied_overrides = applied;
    return s;
  } catch (const engine::ConfigError& e) {
    applied.Rethrow(e);
  }
}

}  // namespace

Scene LoadScene(const std::string& path, const SceneLoadOptions& options) {
  return Load(ReadSceneDocument(path), options);
}

Scene LoadSceneFromString(const std::string& text, const std::string& path,
                          const SceneLoadOptions& options) {
  return Load(ReadSceneDocumentFromString(text, path), options);
}

}  // namespace airis::scenes
