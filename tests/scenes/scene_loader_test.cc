#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "engine/environment/sun.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;
using engine::ConfigError;

/// A fresh folder under the test temp dir with files written into it.
class SceneFiles {
 public:
  explicit SceneFiles(const std::string& name)
      : dir_(airis::testing::TestTempDir() / ("airis_scene_" + name)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  std::string Write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

/// The message of the ConfigError that loading `path` throws ("" if none).
std::string LoadError(const std::string& path) {
  try {
    LoadScene(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

/// The message of the ConfigError that loading `path` and building its world (as `scene check`
/// does) throws ("" if none).
std::string BuildError(const std::string& path) {
  try {
    BuildWorldWithoutCameras(LoadScene(path));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

const char kCube[] =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

TEST(SceneLoaderTest, UnknownKeyInAnObjectNamesFileLineColumnAndSuggestion) {
  SceneFiles f("unknown_key");
  const std::string path = f.Write("s.yaml",
                                   "objects:\n"
                                   "  - primitive: box\n"
                                   "    positon_m: [0, 0, -1]\n");
  EXPECT_EQ(
      LoadError(path),
      path +
          ":3:5: objects[0].positon_m: unknown key 'positon_m' (did you mean 'position_ned_m'?)");
}

TEST(SceneLoaderTest, WrongTypeAndOutOfRangeNameTheKey) {
  SceneFiles f("types");
  const std::string a = f.Write("a.yaml", "scene:\n  seed: many\n");
  EXPECT_EQ(LoadError(a), a + ":2:3: scene.seed: expected an integer (got 'many')");
  const std::string b = f.Write("b.yaml",
                                "objects:\n"
                                "  - primitive: sphere\n"
                                "    material:\n"
                                "      restitution: 2\n");
  EXPECT_EQ(LoadError(b),
            b + ":4:7: objects[0].material.restitution: must be between 0 and 1 (got 2)");
  const std::string c = f.Write("c.yaml", "objects:\n  - primitive: box\n    scale: [1, 0, 1]\n");
  EXPECT_EQ(LoadError(c), c + ":3:16: objects[0].scale[1]: must be > 0 (got 0)");
  const std::string d = f.Write("d.yaml", "scene:\n  environment:\n    wind:\n      gust: drydn\n");
  EXPECT_EQ(LoadError(d),
            d + ":4:7: scene.environment.wind.gust: unknown value 'drydn' (expected none, "
                "gauss_markov or dryden; did you mean 'dryden'?)");
}

TEST(SceneLoaderTest, MaterialShadingKeysReachTheSceneAndBadOnesNameTheKey) {
  SceneFiles f("shading");
  const std::string good = f.Write(
      "good.yaml",
      "objects:\n"
      "  - primitive: box\n"
      "    material: {roughness: 0.25, metallic: 1, pattern: facade, pattern_size_m: [3.5, 2]}\n");
  const Scene s = LoadScene(good);
  const engine::StaticObject& box = s.static_scene->objects.back();
  ASSERT_GE(box.material_override, 0);
  const engine::Material& m = s.static_scene->materials[box.material_override];
  EXPECT_EQ(m.roughness, 0.25f);
  EXPECT_EQ(m.metallic, 1.0f);
  EXPECT_EQ(m.pattern, engine::SurfacePattern::kFacade);
  EXPECT_EQ(m.pattern_size_m, Eigen::Vector2f(3.5f, 2.0f));
  const std::string a =
      f.Write("a.yaml", "objects:\n  - primitive: box\n    material:\n      roughness: 0\n");
  EXPECT_EQ(LoadError(a),
            a + ":4:7: objects[0].material.roughness: must be between 0.02 and 1 (got 0)");
  const std::string b =
      f.Write("b.yaml", "objects:\n  - primitive: box\n    material:\n      pattern: facde\n");
  EXPECT_EQ(LoadError(b).rfind(b + ":4:7: objects[0].material.pattern: unknown value 'facde'", 0),
            0u)
      << LoadError(b);
  const std::string c = f.Write(
      "c.yaml", "objects:\n  - primitive: box\n    material:\n      pattern_size_m: [3, 0]\n");
  EXPECT_EQ(LoadError(c).rfind(c + ":4:", 0), 0u) << LoadError(c);
  EXPECT_NE(LoadError(c).find("objects[0].material.pattern_size_m[1]"), std::string::npos)
      << LoadError(c);
}

TEST(SceneLoaderTest, NestedGeneratorValidationPointsIntoTheList) {
  SceneFiles f("nested");
  const std::string path = f.Write("s.yaml",
                                   "generators:\n"
                                   "  - forest:\n"
                                   "      species:\n"
                                   "        - name: a\n"
                                   "        - name: b\n"
                                   "          height_m: [20, 10]\n");
  EXPECT_EQ(LoadError(path),
            path +
                ":6:11: generators[0].forest.species[1].height_m: expected [min, max] "
                "with min <= max (got [20, 10])");
  const std::string both = f.Write("both.yaml", "generators:\n  - {}\n");
  EXPECT_EQ(LoadError(both),
            both + ":2:5: generators[0].city: expected one generator: city or forest");
}

TEST(SceneLoaderTest, MissingMeshNamesTheResolvedPath) {
  SceneFiles f("missing_mesh");
  const std::string path = f.Write("sub/s.yaml", "objects:\n  - mesh: ../meshes/house.obj\n");
  EXPECT_EQ(LoadError(path),
            path + ":2:5: objects[0].mesh: mesh file not found: " + f.Path("meshes/house.obj"));
}

TEST(SceneLoaderTest, UnreadableAndEmptyMeshesGiveAssimpsReason) {
  SceneFiles f("bad_mesh");
  f.Write("empty.obj", "# nothing\n");
  f.Write("junk.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0\n");
  const std::string a = f.Write("a.yaml", "objects:\n  - mesh: empty.obj\n");
  const std::string a_error = LoadError(a);
  EXPECT_EQ(
      a_error.rfind(a + ":2:5: objects[0].mesh: cannot load mesh " + f.Path("empty.obj") + ": ", 0),
      0u)
      << a_error;
  const std::string b = f.Write("b.yaml", "objects:\n  - name: x\n    mesh: junk.stl\n");
  const std::string b_error = LoadError(b);
  EXPECT_EQ(
      b_error.rfind(b + ":3:5: objects[0].mesh: cannot load mesh " + f.Path("junk.stl") + ": ", 0),
      0u)
      << b_error;
  EXPECT_GT(b_error.size(),
            (b + ":3:5: objects[0].mesh: cannot load mesh " + f.Path("junk.stl") + ": ").size());
}

TEST(SceneLoaderTest, MissingTexturesNameTheResolvedPath) {
  SceneFiles f("texture");
  const std::string a = f.Write("a.yaml",
                                "objects:\n"
                                "  - primitive: box\n"
                                "    material: {texture: img/brick.png}\n");
  EXPECT_EQ(LoadError(a), a + ":3:16: objects[0].material.texture: texture file not found: " +
                              f.Path("img/brick.png"));
  // A texture named inside a mesh's material library resolves against the mesh file.
  f.Write("m/cube.mtl", "newmtl wall\nKd 1 0 0\nmap_Kd wall.png\n");
  f.Write("m/cube.obj", std::string("mtllib cube.mtl\nusemtl wall\n") + kCube);
  const std::string b = f.Write("b.yaml", "objects:\n  - mesh: m/cube.obj\n");
  const std::string error = LoadError(b);
  EXPECT_NE(error.find(b + ":2:5: objects[0].mesh: cannot load mesh"), std::string::npos) << error;
  EXPECT_NE(error.find("texture file not found: " + f.Path("m/wall.png")), std::string::npos)
      << error;
}

// A glTF 2.0 quad (two triangles, positions, normals and texture coordinates in quad.bin) whose
// material names a colour, a normal (of scale `normal_scale`, JSON) and a metallic-roughness
// texture.
std::string GltfQuad(const std::string& normal_png, const std::string& metallic_roughness_png,
                     const std::string& normal_scale = "1") {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                              "indices": 3, "material": 0}]}],
  "materials": [{"name": "panel",
                 "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                          "metallicRoughnessTexture": {"index": 2},
                                          "metallicFactor": 1, "roughnessFactor": 0.5},
                 "normalTexture": {"index": 1, "scale": )" +
         normal_scale + R"(}}],
  "textures": [{"source": 0}, {"source": 1}, {"source": 2}],
  "images": [{"uri": "colour.png"}, {"uri": ")" +
         normal_png + R"("}, {"uri": ")" + metallic_roughness_png + R"("}],
  "buffers": [{"byteLength": 140, "uri": "quad.bin"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                 "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
}

std::string QuadBuffer() {
  const float positions[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const float normals[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const float uvs[8] = {0, 1, 1, 1, 1, 0, 0, 0};
  const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::string b;
  b.append(reinterpret_cast<const char*>(positions), sizeof(positions));
  b.append(reinterpret_cast<const char*>(normals), sizeof(normals));
  b.append(reinterpret_cast<const char*>(uvs), sizeof(uvs));
  b.append(reinterpret_cast<const char*>(indices), sizeof(indices));
  return b;
}

// A 1 x 1 PNG (RGB 128, 128, 255).
const std::string kPixelPng(
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00\x00"
    "\x01\x08\x02\x00\x00\x00\x90\x77\x53\xde\x00\x00\x00\x0c\x49\x44\x41\x54\x78\x9c\x63\x68\x68"
    "\xf8\x0f\x00\x03\x83\x02\x00\x00\xa5\xfb\x89\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82",
    69);

TEST(SceneLoaderTest, GltfMaterialsBringTheirNormalAndMetallicRoughnessMaps) {
  SceneFiles f("gltf_maps");
  f.Write("m/quad.bin", QuadBuffer());
  for (const char* png : {"m/colour.png", "m/normal.png", "m/mr.png"}) f.Write(png, kPixelPng);
  f.Write("m/quad.gltf", GltfQuad("normal.png", "mr.png"));
  const std::string good = f.Write("good.yaml", "objects:\n  - mesh: m/quad.gltf\n");
  const Scene s = LoadScene(good);
  const engine::Model& model = s.static_scene->models[s.static_scene->objects.back().model];
  const engine::Material& m = s.static_scene->materials[model.parts.at(0).material];
  EXPECT_EQ(m.texture_path, f.Path("m/colour.png"));
  EXPECT_EQ(m.normal_texture_path, f.Path("m/normal.png"));
  EXPECT_EQ(m.metallic_roughness_texture_path, f.Path("m/mr.png"));
  EXPECT_EQ(m.metallic, 1.0f);
  EXPECT_EQ(m.roughness, 0.5f);
  EXPECT_EQ(m.normal_scale, 1.0f);
  // The normal map's scale is read
  f.Write("m/flatter.gltf", GltfQuad("normal.png", "mr.png", "0.25"));
  const Scene flatter = LoadScene(f.Write("flatter.yaml", "objects:\n  - mesh: m/flatter.gltf\n"));
  const engine::Model& flat_model =
      flatter.static_scene->models[flatter.static_scene->objects.back().model];
  EXPECT_EQ(flatter.static_scene->materials[flat_model.parts.at(0).material].normal_scale, 0.25f);
  f.Write("m/huge.gltf", GltfQuad("normal.png", "mr.png", "1e300"));
  const std::string huge_error =
      LoadError(f.Write("huge.yaml", "objects:\n  - mesh: m/huge.gltf\n"));
  EXPECT_NE(huge_error.find("normalTexture.scale of material 'panel' is not finite"),
            std::string::npos)
      << huge_error;
  // A missing map is an error naming the resolved path and the material
  f.Write("m/missing.gltf", GltfQuad("no_such_normal.png", "mr.png"));
  const std::string bad = f.Write("bad.yaml", "objects:\n  - mesh: m/missing.gltf\n");
  const std::string error = LoadError(bad);
  EXPECT_NE(error.find("texture file not found: " + f.Path("m/no_such_normal.png") +
                       " (named by material 'panel'"),
            std::string::npos)
      << error;
}

/// A GLB of the quad whose base colour texture is `png`, embedded in its binary chunk.
std::string GlbQuadWithEmbeddedTexture(const std::string& png) {
  std::string bin = QuadBuffer() + png;  // the quad's 140 bytes, then the image
  const std::size_t image_bytes = png.size();
  while (bin.size() % 4 != 0) bin.push_back('\0');
  std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                              "indices": 3, "material": 0}]}],
  "materials": [{"name": "decal", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"bufferView": 4, "mimeType": "image/png"}],
  "buffers": [{"byteLength": )" +
                     std::to_string(bin.size()) + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 128, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 140, "byteLength": )" +
                     std::to_string(image_bytes) + R"(}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                 "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
  while (json.size() % 4 != 0) json.push_back(' ');
  const auto u32 = [](std::uint32_t v) {
    return std::string(reinterpret_cast<const char*>(&v), 4);
  };
  return "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
         u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
         u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
}

// GIVEN a GLB whose base colour texture is a PNG embedded in the file (as most GLBs carry them)
// THEN its material names the image "PATH#*0" and the scene holds the image's bytes (it was
//      silently left out before); the image is no input file of the scene
// AND an embedded image that is no PNG or JPEG is an error naming the texture and the material
TEST(SceneLoaderTest, GlbTexturesEmbeddedInTheFileAreRead) {
  SceneFiles f("glb_embedded");
  f.Write("m/decal.glb", GlbQuadWithEmbeddedTexture(kPixelPng));
  const Scene s = LoadScene(f.Write("good.yaml", "objects:\n  - mesh: m/decal.glb\n"));
  const engine::Model& model = s.static_scene->models[s.static_scene->objects.back().model];
  const engine::Material& m = s.static_scene->materials[model.parts.at(0).material];
  const std::string name = f.Path("m/decal.glb") + "#*0";
  EXPECT_EQ(m.texture_path, name);
  ASSERT_EQ(s.static_scene->embedded_images.count(name), 1u);
  EXPECT_EQ(s.static_scene->embedded_images.at(name), kPixelPng);
  EXPECT_EQ(std::count(s.files.begin(), s.files.end(), name), 0);
  f.Write("m/bad.glb", GlbQuadWithEmbeddedTexture("GIF89a not an image we read"));
  const std::string error = LoadError(f.Write("bad.yaml", "objects:\n  - mesh: m/bad.glb\n"));
  EXPECT_NE(error.find("embedded texture *0 (named by material 'decal'): not a PNG or JPEG image"),
            std::string::npos)
      << error;
}

TEST(SceneLoaderTest, IncludeCycleNamesTheChain) {
  SceneFiles f("cycle");
  const std::string a = f.Write("a.yaml", "include: [b.yaml]\n");
  const std::string b = f.Write("b.yaml", "objects: []\ninclude:\n  - a.yaml\n");
  EXPECT_EQ(LoadError(a), b + ":3:5: include[0]: include cycle: " + a + " -> " + b + " -> " + a);
  const std::string self = f.Write("self.yaml", "include: [self.yaml]\n");
  EXPECT_EQ(LoadError(self), self + ":1:11: include[0]: include cycle: " + self + " -> " + self);
  const std::string missing = f.Write("m.yaml", "include: [nope.yaml]\n");
  EXPECT_EQ(LoadError(missing),
            missing + ":1:11: include[0]: file not found: " + f.Path("nope.yaml"));
}

TEST(SceneLoaderTest, UnknownClassSuggestsAndLists) {
  SceneFiles f("class");
  const std::string path = f.Write("s.yaml", "objects:\n  - primitive: box\n    class: buildng\n");
  const std::string error = LoadError(path);
  EXPECT_EQ(
      error.rfind(path +
                      ":3:5: objects[0].class: unknown class 'buildng' (did you mean 'building'?); "
                      "known classes: ground, road",
                  0),
      0u)
      << error;
}

TEST(SceneLoaderTest, VehicleInsideAnObjectNamesBoth) {
  SceneFiles f("inside");
  const std::string path =
      f.Write("s.yaml",
              "objects:\n"
              "  - {name: shed, primitive: box, position_ned_m: [10, 0, -2], scale: [4, 4, 4]}\n"
              "vehicles:\n"
              "  - name: drone1\n"
              "    preset: quad_x\n"
              "    start: {position_ned_m: [11, 1, -1]}\n");
  // Found by the vehicle's collision shape against the object's, once the world is built.
  const std::string error = BuildError(path);
  EXPECT_EQ(error.rfind(path + ":6:13: vehicles[0].start.position_ned_m: vehicle 'drone1' starts "
                               "overlapping object 'shed' by ",
                        0),
            0u)
      << error;
}

TEST(SceneLoaderTest, VehicleBelowGroundAndDuplicateNamesAreErrors) {
  SceneFiles f("vehicles");
  const std::string a = f.Write(
      "a.yaml", "vehicles:\n  - {name: d, preset: quad_x, start: {position_ned_m: [0, 0, 1]}}\n");
  EXPECT_EQ(
      LoadError(a),
      a + ":2:39: vehicles[0].start.position_ned_m: vehicle 'd' starts 1.02 m into the ground (its "
          "body box reaches z = 1.02 m; NED z is down, so heights are negative; or set "
          "start.on_ground)");
  const std::string b =
      f.Write("b.yaml",
              "vehicles:\n"
              "  - {name: d, preset: quad_x}\n"
              "  - {name: d, preset: quad_x, start: {position_ned_m: [5, 0, -1]}}\n");
  EXPECT_EQ(
      LoadError(b),
      b + ":3:6: vehicles[1].name: duplicate vehicle name 'd' (also vehicles[0] at " + b + ":2)");
  const std::string c = f.Write("c.yaml", "vehicles:\n  - {name: d}\n");
  EXPECT_EQ(LoadError(c), c + ":2:5: vehicles[0].preset: every vehicle needs a preset");
}

TEST(SceneLoaderTest, TooManyObjectsIsAnError) {
  SceneFiles f("many");
  const std::string path = f.Write("s.yaml",
                                   "objects:\n"
                                   "  - primitive: box\n"
                                   "    repeat: {count: 65535, step_ned_m: [1, 0, 0], rows: 257, "
                                   "row_step_ned_m: [0, 1, 0]}\n");
  EXPECT_EQ(LoadError(path),
            path +
                ":3:5: objects[0].repeat: places 16842495 objects where 16777214 instance ids are "
                "left (a scene holds at most 16777215 objects: instance ids are 24-bit; "
                "docs/limits.md)");
}

/// The error of loading `text` (anchored at mem.yaml) whose objects may take `memory_bytes`.
std::string LoadErrorWithMemory(const std::string& text, std::uint64_t memory_bytes) {
  SceneLoadOptions options;
  options.memory_limit_bytes = memory_bytes;
  try {
    LoadSceneFromString(text, "mem.yaml", options);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// GIVEN objects that may take 12 MiB: 13,981 objects at the least a built object takes (900 B)
// WHEN a repeat places 20,000 boxes, or a forest grows past that, or a repeat passes the ids too
// THEN the repeat is refused before anything is placed, naming what is left and why; the forest
//      stops at the limit and says so; the ids are checked first (the same words on any machine)
TEST(SceneLoaderTest, ObjectsBeyondTheMemoryLimitAreRefused) {
  const std::uint64_t limit = 12ull << 20;
  EXPECT_EQ(LoadErrorWithMemory("objects:\n"
                                "  - primitive: box\n"
                                "    repeat: {count: 100, step_ned_m: [2, 0, 0], rows: 200, "
                                "row_step_ned_m: [0, 2, 0]}\n",
                                limit),
            "mem.yaml:3:5: objects[0].repeat: places 20000 objects where 13980 more fit in memory "
            "(the memory limit of 12 MiB holds 13981 objects and vehicles of at least 900 bytes "
            "each once built; docs/limits.md)");
  EXPECT_EQ(
      LoadErrorWithMemory("generators:\n"
                          "  - forest: {area: {size_ne_m: [600, 600]}, density_per_ha: 400}\n",
                          limit),
      "mem.yaml:2:5: generators[0].forest: the scene exceeds the 13981 objects that the "
      "memory limit of 12 MiB holds (at least 900 bytes each once built; docs/limits.md)");
  EXPECT_NE(LoadErrorWithMemory("objects:\n"
                                "  - primitive: box\n"
                                "    repeat: {count: 65535, step_ned_m: [1, 0, 0], rows: 257, "
                                "row_step_ned_m: [0, 1, 0]}\n",
                                limit)
                .find("places 16842495 objects where 16777214 instance ids are left"),
            std::string::npos);
  // Within the limit: 10,000 boxes and the ground load.
  EXPECT_EQ(LoadErrorWithMemory("objects:\n"
                                "  - primitive: box\n"
                                "    repeat: {count: 100, step_ned_m: [2, 0, 0], rows: 100, "
                                "row_step_ned_m: [0, 2, 0]}\n",
                                limit),
            "");
}

TEST(SceneLoaderTest, MoreObjectsThan16BitIdsNumberLoadWithDistinctIds) {
  SceneFiles f("past16bit");
  const std::string path = f.Write("s.yaml",
                                   "objects:\n"
                                   "  - primitive: box\n"
                                   "    repeat: {count: 300, step_ned_m: [2, 0, 0], rows: 230, "
                                   "row_step_ned_m: [0, 2, 0]}\n");
  const Scene s = LoadScene(path);
  // 69,000 boxes and the ground: ids 1..69001 in order, so past 65,535 and none repeated.
  const auto& objects = s.static_scene->objects;
  ASSERT_EQ(objects.size(), 69'001u);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    ASSERT_EQ(objects[i].instance_id, i + 1) << i;
  }
}

TEST(SceneLoaderTest, ObjectsRepeatShareOneModelAndGetUniqueIds) {
  SceneFiles f("repeat");
  f.Write("cube.obj", kCube);
  const std::string path = f.Write(
      "s.yaml",
      "objects:\n"
      "  - {name: c, mesh: cube.obj, mesh_axes: ned, position_ned_m: [0, 0, -1],\n"
      "     repeat: {count: 3, step_ned_m: [2, 0, 0], rows: 2, row_step_ned_m: [0, 2, 0]}}\n"
      "  - {name: d, mesh: cube.obj, mesh_axes: ned, position_ned_m: [9, 9, -1]}\n"
      "  - {primitive: cone, position_ned_m: [20, 0, -1], material: {color: [1, 0, 0]}}\n");
  const Scene s = LoadScene(path);
  ASSERT_EQ(s.static_scene->objects.size(), 1u + 6u + 1u + 1u);  // ground, 6 copies, d, cone
  std::set<std::uint32_t> ids;
  for (const auto& o : s.static_scene->objects) ids.insert(o.instance_id);
  EXPECT_EQ(ids.size(), s.static_scene->objects.size());
  EXPECT_EQ(*ids.begin(), 1u);
  EXPECT_EQ(*ids.rbegin(), 9u);
  const auto& objects = s.static_scene->objects;
  EXPECT_EQ(objects[1].name, "c_0_0");
  EXPECT_EQ(objects[6].name, "c_1_2");
  EXPECT_TRUE(objects[6].T_WO.translation().isApprox(Eigen::Vector3d(4, 2, -1)));
  EXPECT_EQ(objects[1].model, objects[7].model);  // one mesh file, one model
  EXPECT_EQ(objects[8].name, "cone");
  EXPECT_GE(objects[8].material_override, 0);
  EXPECT_EQ(s.static_scene->materials[objects[8].material_override].base_color_rgb,
            Eigen::Vector3f(1, 0, 0));
}

TEST(SceneLoaderTest, IncludesConcatenateAndTheIncluderWins) {
  SceneFiles f("include");
  f.Write("tiles/a.yaml",
          "scene: {name: tile, seed: 5}\n"
          "ground: {size_ne_m: [10, 10]}\n"
          "objects: [{name: from_a, primitive: box, position_ned_m: [3, 0, -1]}]\n");
  f.Write("tiles/b.yaml",
          "objects: [{name: from_b, primitive: sphere, position_ned_m: [6, 0, -1]}]\n");
  const std::string top =
      f.Write("top.yaml",
              "include: [tiles/a.yaml, tiles/b.yaml]\n"
              "scene: {name: top}\n"
              "objects: [{name: own, primitive: box, position_ned_m: [9, 0, -1]}]\n");
  const Scene s = LoadScene(top);
  EXPECT_EQ(s.name, "top");
  EXPECT_EQ(s.seed, 1u);  // the includer's scene block replaces the tile's as a whole
  ASSERT_EQ(s.static_scene->objects.size(), 4u);
  EXPECT_EQ(s.static_scene->objects[0].T_WO.linear().col(0).norm(), 10.0);  // tile's ground kept
  EXPECT_EQ(s.static_scene->objects[1].name, "from_a");
  EXPECT_EQ(s.static_scene->objects[2].name, "from_b");
  EXPECT_EQ(s.static_scene->objects[3].name, "own");
  EXPECT_EQ(s.files.size(), 3u);
}

TEST(SceneLoaderTest, SameSceneLoadsIdentically) {
  const std::string text =
      "scene: {seed: 77}\n"
      "generators:\n"
      "  - forest: {area: {size_ne_m: [100, 100]}, density_per_ha: 200}\n";
  const Scene a = LoadSceneFromString(text, "mem.yaml");
  const Scene b = LoadSceneFromString(text, "mem.yaml");
  ASSERT_EQ(a.static_scene->objects.size(), b.static_scene->objects.size());
  for (std::size_t i = 0; i < a.static_scene->objects.size(); ++i) {
    EXPECT_EQ(a.static_scene->objects[i].instance_id, b.static_scene->objects[i].instance_id);
    EXPECT_EQ(a.static_scene->objects[i].name, b.static_scene->objects[i].name);
    EXPECT_TRUE(a.static_scene->objects[i].T_WO.matrix() ==
                b.static_scene->objects[i].T_WO.matrix());
  }
  ASSERT_EQ(a.generated.size(), 1u);
  EXPECT_EQ(a.generated[0].name, "mem/forest0");
}

TEST(SceneLoaderTest, CustomClassesGetIdsAndClashesAreErrors) {
  const Scene s = LoadSceneFromString(
      "classes: [{name: crate}, {name: drone_dock, id: 200, color: [0, 1, 0]}]\n"
      "objects: [{primitive: box, class: drone_dock, position_ned_m: [5, 5, -1]}]\n",
      "mem.yaml");
  EXPECT_EQ(s.static_scene->objects.back().class_id, 200);
  ASSERT_NE(s.static_scene->FindClass(200), nullptr);
  EXPECT_EQ(s.static_scene->FindClass(200)->name, "drone_dock");
  try {
    LoadSceneFromString("classes:\n  - {name: crate, id: 4}\n", "mem.yaml");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "mem.yaml:2:19: classes[0].id: id 4 is already class 'building'");
  }
}

TEST(SceneLoaderTest, SunFromTimeOfDayAtEquinoxNoon) {
  // Near the March equinox (declination ~0) at solar noon the sun stands 90 deg - latitude high,
  // due south. Cooper's declination is -0.4 deg on that day, so 0.5 deg bounds it.
  double azimuth = 0, elevation = 0;
  engine::CalcSolarAngles(47.0, 2026.0 + 79.0 / 365.0, 12.0, azimuth, elevation);
  EXPECT_NEAR(elevation, 43.0, 0.5);
  EXPECT_NEAR(std::abs(azimuth), 180.0, 1e-6);
  const Vec3 d = engine::CalcSunDirection_W(azimuth, elevation);
  EXPECT_NEAR(d.norm(), 1.0, 1e-12);
  EXPECT_GT(d.z(), 0.0);  // light travels down
  EXPECT_GT(d.x(), 0.0);  // and north, from a southern sun
}

TEST(SceneLoaderTest, FormatOneSpellingsAreErrorsNamingTheNewKey) {
  const auto error = [](const std::string& text) {
    try {
      LoadSceneFromString(text, "scenes/old.yaml");
    } catch (const engine::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("objects: [{primitive: box, position_m: [0, 0, -1]}]\n"),
            "scenes/old.yaml:1:28: objects[0].position_m: renamed to 'position_ned_m' in format 2 "
            "(names say their frame and unit: docs/architecture.md, \"Names\")");
  EXPECT_NE(error("vehicles:\n  - name: d\n    preset: quad_x\n"
                  "    sensors: [{imu: {mount: {position_m: [0, 0, 0]}}}]\n")
                .find("vehicles[0].sensors[0].imu.mount.position_m: renamed to 'position_frd_m'"),
            std::string::npos);
  EXPECT_NE(error("vehicles:\n  - name: d\n    preset: quad_x\n"
                  "    overrides: {rotors: [{thrust_direction: [0, 0, -1]}]}\n")
                .find("vehicles[0].overrides.rotors[0].thrust_direction: renamed to "
                      "'thrust_direction_frd'"),
            std::string::npos);
  // A typo of an old spelling suggests the new key.
  EXPECT_NE(error("objects: [{primitive: box, positon_m: [0, 0, -1]}]\n")
                .find("unknown key 'positon_m' (did you mean 'position_ned_m'?)"),
            std::string::npos);
}

}  // namespace
}  // namespace airis::scenes
