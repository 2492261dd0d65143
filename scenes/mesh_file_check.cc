#include "scenes/mesh_file_check.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/limits.h"
#include "scenes/mesh_file_check_dae.h"
#include "scenes/mesh_file_check_fbx.h"
#include "scenes/mesh_file_check_obj.h"
#include "scenes/mesh_file_check_ply.h"
#include "scenes/mesh_loader.h"

namespace airis::scenes {

namespace fs = std::filesystem;
using engine::kMaxMeshTriangles;
using engine::kMaxMeshVertices;

namespace {

// The formats scenes accept (docs/scene-format.md); the importer reads many more, each with its own
// parser, which scenes have no use for.
constexpr const char* kMeshExtensions[] = {"obj", "gltf", "glb", "fbx", "ply", "stl", "dae"};
// Node trees of real models are a few levels deep.
constexpr std::size_t kMaxGltfNodeDepth = 256;

std::string Count(std::uint64_t n) { return std::to_string(n); }

[[noreturn]] void Refuse(const std::string& problem) { throw MeshLoadError(problem); }

std::string Lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string ReadBytes(const std::string& path, std::size_t offset, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  std::string out(count, '\0');
  in.read(out.data(), static_cast<std::streamsize>(count));
  out.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return out;
}

std::uint64_t LittleEndian(std::string_view bytes) {
  std::uint64_t v = 0;
  for (std::size_t i = bytes.size(); i > 0; --i) {
    v = (v << 8) | static_cast<unsigned char>(bytes[i - 1]);
  }
  return v;
}

void RequireCount(const char* what, std::uint64_t count, std::uint64_t limit) {
  if (count > limit) {
    Refuse("the file declares " + Count(count) + " " + what + ", more than the limit of " +
           Count(limit) + " (docs/limits.md)");
  }
}

/// ASCII STL, as a strict grammar (one statement a line): `solid [NAME]`, then facets of
/// `facet normal X Y Z`, `outer loop`, three `vertex X Y Z`, `endloop`, `endfacet`, then
/// `endsolid [NAME]`; several solids may follow each other. assimp 5.2.5 leaks the meshes it has
/// read when it gives up inside one (upstream issue #5946), and reads facets with fewer or more
/// vertices as it can: none of that reaches it.
void CheckAsciiStl(const std::string& text) {
  if (text.find('\0') != std::string::npos) Refuse("an ASCII STL file with a NUL byte");
  // What each line must start with, in order, within a solid; after the last, the next facet.
  static constexpr const char* kFacet[] = {"facet",  "outer",   "vertex",  "vertex",
                                           "vertex", "endloop", "endfacet"};
  std::size_t facets = 0;
  std::size_t step = 0;  // position in kFacet
  bool in_solid = false;
  std::size_t at = 0;
  for (std::size_t number = 1; at < text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::istringstream line(text.substr(at, end - at));
    at = end + 1;
    std::string word;
    if (!(line >> word)) continue;  // blank
    const std::string where = "ASCII STL line " + Count(number) + ": ";
    auto numbers = [&](int n) {
      for (int k = 0; k < n; ++k) {
        std::string value;
        line >> value;
        double v = 0;
        const auto r = std::from_chars(value.data(), value.data() + value.size(), v);
        if (value.empty() || r.ec != std::errc() || r.ptr != value.data() + value.size()) {
          Refuse(where + "expected " + Count(n) + " numbers after '" + word + "'");
        }
      }
    };
    auto nothing_more = [&] {
      std::string extra;
      if (line >> extra)
        Refuse(where + "unexpected " + engine::QuoteValue(extra) + " after '" + word + "'");
    };
    if (!in_solid) {
      if (word != "solid")
        Refuse(where + "expected 'solid' (got " + engine::QuoteValue(word) + ")");
      in_solid = true;
      continue;
    }
    if (step == 0 && word == "endsolid") {
      in_solid = false;
      continue;
    }
    if (word != kFacet[step]) {
      Refuse(where + "expected '" + kFacet[step] + "'" + (step == 0 ? " or 'endsolid'" : "") +
             " (got " + engine::QuoteValue(word) + ")");
    }
    if (word == "facet") {
      std::string normal;
      if (!(line >> normal) || normal != "normal") Refuse(where + "expected 'facet normal X Y Z'");
      numbers(3);
    } else if (word == "outer") {
      std::string loop;
      if (!(line >> loop) || loop != "loop") Refuse(where + "expected 'outer loop'");
    } else if (word == "vertex") {
      numbers(3);
    }
    nothing_more();
    step = (step + 1) % std::size(kFacet);
    if (step == 0) ++facets;
  }
  if (in_solid) Refuse("an ASCII STL file whose solid does not end ('endsolid' missing)");
  if (facets == 0) Refuse("an ASCII STL file without facets");
}

/// Binary STL: an 80-byte header, a triangle count, then 50 bytes per triangle, exactly (as assimp
/// tells the two apart); any other file must be ASCII STL, starting with 'solid'.
void CheckStl(const std::string& path, std::uintmax_t file_bytes) {
  const std::string head = ReadBytes(path, 0, 84);
  const std::uint64_t triangles =
      head.size() < 84 ? 0 : LittleEndian(std::string_view(head).substr(80, 4));
  if (head.size() == 84 && 84 + 50 * triangles == file_bytes) {
    RequireCount("triangles", triangles, kMaxMeshTriangles);
    if (triangles == 0) Refuse("a binary STL file of no triangles");
    return;
  }
  std::istringstream first(head);
  std::string word;
  if (first >> word && word.rfind("solid", 0) == 0) {
    CheckAsciiStl(ReadBytes(path, 0, file_bytes));
    return;
  }
  if (head.size() < 84) Refuse("too short for a binary STL file (84 bytes of header)");
  RequireCount("triangles", triangles, kMaxMeshTriangles);
  Refuse("the header declares " + Count(triangles) + " triangles (" + Count(84 + 50 * triangles) +
         " bytes) but the file has " + Count(file_bytes) +
         " (and it is no ASCII STL file, which starts with 'solid')");
}

/// Bytes of one element of a glTF accessor (glTF 2.0, 3.6.2).
std::uint64_t AccessorElementBytes(const nlohmann::json& accessor) {
  static const std::pair<const char*, std::uint64_t> kComponents[] = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
  std::uint64_t components = 1;
  const std::string type = accessor.value("type", std::string("SCALAR"));
  for (const auto& [name, n] : kComponents) {
    if (type == name) components = n;
  }
  const int component_type = accessor.value("componentType", 5126);
  const std::uint64_t component_bytes = (component_type == 5120 || component_type == 5121)   ? 1
                                        : (component_type == 5122 || component_type == 5123) ? 2
                                                                                             : 4;
  return components * component_bytes;
}

std::uint64_t Unsigned(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end()) return 0;
  if (!it->is_number_unsigned()) {
    if (it->is_number_integer() || it->is_number_float()) {
      Refuse("glTF '" + std::string(key) + "' must be a whole number >= 0");
    }
    return 0;
  }
  return it->get<std::uint64_t>();
}

/// glTF 2.0 JSON: every buffer holds the bytes it claims (from the GLB's binary chunk, a data URI
/// or a file beside it), every view lies within its buffer, every accessor within its view, and no
/// accessor (those without a view are zero-filled: nothing bounds them but their count) is larger
/// than the limits. Nodes form a forest, as the specification requires (a node shared by two
/// parents would be copied for each). The JSON declares glTF 2.0 (`asset.version` a string starting
/// with "2"): assimp 5.2.5 gives a .gltf or .glb file to its glTF 2.0 reader only then, and when no
/// glTF reader claims the file, it offers it to every reader by content, so that the OBJ reader,
/// say, would read a .gltf file that these checks never saw as OBJ.
void CheckGltfJson(const std::string& path, const std::string& text, std::uint64_t glb_bin_bytes) {
  const nlohmann::json gltf = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (gltf.is_discarded() || !gltf.is_object()) Refuse("its glTF JSON does not parse");
  const auto declares_2 = [&] {
    const auto asset = gltf.find("asset");
    if (asset == gltf.end() || !asset->is_object()) return false;
    const auto version = asset->find("version");
    return version != asset->end() && version->is_string() &&
           version->get_ref<const std::string&>().starts_with('2');
  };
  if (!declares_2()) {
    Refuse(
        "the glTF JSON does not declare glTF 2.0 (asset.version \"2.0\"), the only version read");
  }
  const nlohmann::json empty = nlohmann::json::array();
  auto list = [&](const char* key) -> const nlohmann::json& {
    const auto it = gltf.find(key);
    return it != gltf.end() && it->is_array() ? *it : empty;
  };
  std::vector<std::uint64_t> buffer_bytes;
  for (const auto& buffer : list("buffers")) {
    if (!buffer.is_object()) Refuse("a glTF buffer that is not an object");
    const std::uint64_t claimed = Unsigned(buffer, "byteLength");
    std::uint64_t available = glb_bin_bytes;
    if (const auto uri = buffer.find("uri"); uri != buffer.end() && uri->is_string()) {
      const std::string& u = uri->get_ref<const std::string&>();
      if (u.rfind("data:", 0) == 0) {
        const std::size_t comma = u.find(',');
        available = comma == std::string::npos ? 0 : (u.size() - comma - 1) / 4 * 3;
      } else {
        std::error_code ec;
        const fs::path file = fs::path(path).parent_path() / u;
        available = fs::is_regular_file(file, ec) ? fs::file_size(file, ec) : 0;
      }
    }
    if (claimed > available) {
      Refuse("glTF buffer " + Count(buffer_bytes.size()) + " claims " + Count(claimed) +
             " bytes but only " + Count(available) + " are there");
    }
    buffer_bytes.push_back(claimed);
  }
  std::vector<std::uint64_t> view_bytes;
  for (const auto& view : list("bufferViews")) {
    if (!view.is_object()) Refuse("a glTF buffer view that is not an object");
    const std::uint64_t buffer = Unsigned(view, "buffer");
    const std::uint64_t offset = Unsigned(view, "byteOffset");
    const std::uint64_t length = Unsigned(view, "byteLength");
    if (buffer >= buffer_bytes.size() || offset > buffer_bytes[buffer] ||
        length > buffer_bytes[buffer] - offset) {
      Refuse("glTF buffer view " + Count(view_bytes.size()) + " lies outside its buffer");
    }
    view_bytes.push_back(length);
  }
  std::size_t index = 0;
  for (const auto& accessor : list("accessors")) {
    if (!accessor.is_object()) Refuse("a glTF accessor that is not an object");
    const std::uint64_t count = Unsigned(accessor, "count");
    RequireCount("elements in one accessor", count, 3 * kMaxMeshTriangles);
    const std::uint64_t bytes = count * AccessorElementBytes(accessor);
    if (bytes > engine::kMaxMeshFileBytes) {
      Refuse("glTF accessor " + Count(index) + " is " + Count(bytes) +
             " bytes, more than the mesh file limit of " + Count(engine::kMaxMeshFileBytes));
    }
    if (accessor.contains("bufferView")) {
      const std::uint64_t view = Unsigned(accessor, "bufferView");
      const std::uint64_t offset = Unsigned(accessor, "byteOffset");
      if (view >= view_bytes.size() || offset > view_bytes[view] ||
          (count > 0 && AccessorElementBytes(accessor) > view_bytes[view] - offset)) {
        Refuse("glTF accessor " + Count(index) + " lies outside its buffer view");
      }
    }
    ++index;
  }
  const nlohmann::json& nodes = list("nodes");
  constexpr std::size_t kNoParent = SIZE_MAX;
  std::vector<std::size_t> parent(nodes.size(), kNoParent);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (!nodes[n].is_object()) continue;
    const auto children = nodes[n].find("children");
    if (children == nodes[n].end() || !children->is_array()) continue;
    for (const auto& child : *children) {
      if (!child.is_number_unsigned() || child.get<std::uint64_t>() >= nodes.size()) {
        Refuse("a glTF node names a child that does not exist");
      }
      std::size_t& p = parent[child.get<std::size_t>()];
      if (p != kNoParent) {
        Refuse("glTF node " + Count(child.get<std::uint64_t>()) +
               " is a child of two nodes (glTF 2.0 requires a tree)");
      }
      p = n;
    }
  }
  // Importers walk the tree recursively: a chain of a million nodes would exhaust the stack, and a
  // loop never ends.
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    std::size_t depth = 0;
    for (std::size_t at = n; parent[at] != kNoParent; at = parent[at]) {
      if (++depth > kMaxGltfNodeDepth) {
        Refuse("glTF node " + Count(n) + " is nested more than " + Count(kMaxGltfNodeDepth) +
               " levels deep (or in a loop)");
      }
    }
  }
}

/// GLB (glTF 2.0, 4.4): a 12-byte header with the total length, then a JSON chunk and an optional
/// binary chunk, each with its length. Lengths beyond the file are refused.
void CheckGlb(const std::string& path, std::uintmax_t file_bytes) {
  const std::string header = ReadBytes(path, 0, 20);
  if (header.size() < 20 || header.substr(0, 4) != "glTF") {
    Refuse("not a GLB file (it must start with 'glTF' and a 12-byte header)");
  }
  const std::uint64_t version = LittleEndian(std::string_view(header).substr(4, 4));
  const std::uint64_t length = LittleEndian(std::string_view(header).substr(8, 4));
  if (version != 2) Refuse("a GLB file of version " + Count(version) + " (only 2 is read)");
  if (length > file_bytes) {
    Refuse("the header declares " + Count(length) + " bytes but the file has " + Count(file_bytes));
  }
  if (length < 20) {
    Refuse("the header declares " + Count(length) +
           " bytes, fewer than the 20 of the GLB header and its first chunk's header");
  }
  const std::uint64_t json_bytes = LittleEndian(std::string_view(header).substr(12, 4));
  if (LittleEndian(std::string_view(header).substr(16, 4)) != 0x4E4F534Au) {
    Refuse("the first GLB chunk is not JSON");
  }
  if (json_bytes > length - 20) {
    Refuse("the JSON chunk declares " + Count(json_bytes) + " bytes, more than the file holds");
  }
  std::uint64_t bin_bytes = 0;
  const std::uint64_t bin_at = 20 + json_bytes;
  if (bin_at + 8 <= length) {
    const std::string bin = ReadBytes(path, bin_at, 8);
    bin_bytes = LittleEndian(std::string_view(bin).substr(0, 4));
    if (bin_bytes > length - bin_at - 8) {
      Refuse("the binary chunk declares " + Count(bin_bytes) + " bytes, more than the file holds");
    }
  }
  CheckGltfJson(path, ReadBytes(path, 20, json_bytes), bin_bytes);
}

}  // namespace

std::span<const char* const> MeshFileExtensions() { return kMeshExtensions; }

void CheckMeshFileBeforeImport(const std::string& path) {
  std::string extension = Lowercase(fs::path(path).extension().string());
  if (!extension.empty()) extension.erase(0, 1);
  const bool known = std::any_of(std::begin(kMeshExtensions), std::end(kMeshExtensions),
                                 [&](const char* e) { return extension == e; });
  if (!known) {
    Refuse("unsupported mesh format " + engine::QuoteValue(extension) +
           " (expected .obj, .gltf, .glb, .fbx, .ply, .stl or .dae)");
  }
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) Refuse("cannot read the file");
  if (bytes > engine::kMaxMeshFileBytes) {
    Refuse("the file has " + Count(bytes) + " bytes, more than the limit of " +
           Count(engine::kMaxMeshFileBytes) + " (docs/limits.md)");
  }
  if (extension == "ply") CheckPlyFile(path, bytes);
  if (extension == "stl") CheckStl(path, bytes);
  if (extension == "dae") CheckDaeText(ReadBytes(path, 0, bytes));
  if (extension == "obj") CheckObjFile(path, ReadBytes(path, 0, bytes));
  if (extension == "fbx") CheckFbx(path, bytes);
  // assimp reads a .glb file as binary glTF and a .gltf file as JSON, whatever the content; a file
  // of the other form would go to its readers by content (see CheckGltfJson).
  if (extension == "glb") CheckGlb(path, bytes);
  if (extension == "gltf") {
    if (ReadBytes(path, 0, 4) == "glTF") {
      Refuse("a binary glTF (GLB) file named .gltf (name it .glb)");
    }
    CheckGltfJson(path, ReadBytes(path, 0, bytes), 0);
  }
}

}  // namespace airis::scenes
